// Wall family JJ: Johnson & Jackson 1987 in GKL form (docs/continuum-model.md §4.3). Traction and dissipation are
// JJ's [SRC: MFiX bc_theta.f]; mapping them onto the GKL R-scaled terms is our [ASSUMPTION]:
//   b5 = (pi sqrt3/(6 nu_max)) nu g0 / f_mu                 (R5 = specularity phi')
//   b6 = (pi sqrt3/(4 nu_max)) (1 - e_w^2) nu g0 / G
//   b7 = f_t (pi sqrt3/(6 nu_max)) nu g0 f_p / G            (f_t = 0 default)
//   b8 = f_mu f_p / G
// With R5 = phi' and R6 = R8 = 1 this is exactly JJ: the slip work phi' pi sqrt3 rho nu g0 sqrt(T) u_s^2/(6 nu_max)
// enters the flow whole and the dissipation carries no specularity [SRC: OpenFOAM/mousse
// JohnsonJacksonParticleTheta, the same bc_theta.f terms]. wall_energy = "slip_work" gives exactly that (R6
// defaults to 1 there, dissipation_scales_with_roughness); GKL's R-scaling of every term is wall_energy = "gkl_r8".
#include <cmath>
#include <numbers>

#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {
namespace {
class JohnsonJackson final : public WallFamily {
public:
    WallCoefficients coefficients(const ClosureState<D1>& s, const WallParams& w, double numax) const override {
        const double a = std::numbers::pi * std::sqrt(3.0) / (6.0 * numax);
        const D1 ng = s.nu * s.g;
        const double ed = w.dissipation_e();
        return {a * ng / s.fmu, 1.5 * a * (1.0 - ed * ed) * ng / s.G, w.slip_dissipation * a * ng * s.fp / s.G,
                s.fmu * s.fp / s.G, wall_xi_per_slip(s)};
    }
    bool dissipation_scales_with_roughness() const override { return false; }
};
}  // namespace

std::unique_ptr<WallFamily> make_wall_johnson_jackson() { return std::make_unique<JohnsonJackson>(); }

}  // namespace granlub::continuum
