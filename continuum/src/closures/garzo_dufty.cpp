// Closure family garzo_dufty: the transport coefficients of Garzo & Dufty 1999 as extended kinetic
// theory uses them (Jenkins & Berzi 2010; Berzi & Vescovi 2015): LSJC's pressure and dissipation,
// GD's viscosity and conductivity (closures/garzo_dufty.h), no grad-nu heat flux
// (docs/continuum-model.md §2.5).
#include "granlub/continuum/closures/garzo_dufty.h"
#include "granlub/continuum/closures/lun84.h"

namespace granlub::continuum {
namespace {
class GarzoDufty final : public ClosureFamily {
public:
    ClosureState<D1> state(const ClosureParams& p, D1 nu, D1 g, D1 dg) const override {
        ClosureState<D1> s = lsjc_pressure_and_dissipation(p, nu, g, dg);
        s.fmu = closures::f_mu_gd(nu, g, p.restitution);
        s.fk = closures::f_kappa_gd(nu, g, p.restitution);
        s.fphi = D1(0.0);
        return s;
    }
};
}  // namespace

std::unique_ptr<ClosureFamily> make_closures_garzo_dufty() { return std::make_unique<GarzoDufty>(); }

}  // namespace granlub::continuum
