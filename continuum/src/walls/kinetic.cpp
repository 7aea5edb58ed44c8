// Wall family K: kinetic, P-based, Jenkins-Richman-structured (docs/continuum-model.md §4.2) [ASSUMPTION; DERIVED].
// A Maxwellian at the wall with the wall normal stress equal to P (the Jenkins & Richman 1986
// device) gives the collision rate; a fraction R5 of collisions is diffuse (Hui et al. 1984).
//   b5 = sqrt(2/pi) f_p / ((1 + e_w) f_mu)                 traction / (mu u_s)
//   b6 = sqrt(2/pi) (1 - e_w) f_p / G                       normal-collision dissipation
//   b7 = f_t sqrt(2/pi) f_p^2 / ((1 + e_w) G)               slip dissipation (f_t = 0 default)
//   b8 = f_mu f_p / G                                       slip work (= b4)
// The default: it reproduces J&H's dilute walls and S&T's equal slip/U. Its structure is that of a bumpy wall
// (Jenkins & Richman 1986; Richman 1988 as Jenkins & Berzi 2010 use it): traction/P proportional to R u_s/sqrt(T),
// dissipation to R (1 - e_w) P sqrt(T), the flux into the flow slip work minus that (wall_energy = "slip_work");
// Richman's own C(theta), D(theta) could not be read, R stands in for them [ASSUMPTION].
#include <cmath>
#include <numbers>

#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {
namespace {
class Kinetic final : public WallFamily {
public:
    WallCoefficients coefficients(const ClosureState<D1>& s, const WallParams& w, double /*numax*/) const override {
        const double c = std::sqrt(2.0 / std::numbers::pi);
        const double ew = w.restitution;
        // The collision rate sees the kinetic pressure (fpk); with a contact stress (§2.9) T = P/(rho_p fp), so
        // the T-powers bring fp: b5 = c fpk/((1+e_w) f_mu), b6 = c (1-e_w) fpk/G, b7 ~ fpk fp/G, b8 = f_mu fp/G
        // (fpk = fp without one).
        return {c * s.fpk / ((1.0 + ew) * s.fmu), c * (1.0 - w.dissipation_e()) * s.fpk / s.G,
                w.slip_dissipation * c * s.fpk * s.fp / ((1.0 + ew) * s.G), s.fmu * s.fp / s.G, wall_xi_per_slip(s)};
    }
};
}  // namespace

std::unique_ptr<WallFamily> make_wall_kinetic() { return std::make_unique<Kinetic>(); }

}  // namespace granlub::continuum
