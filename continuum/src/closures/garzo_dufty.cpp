// Closure family garzo_dufty: the transport coefficients of Garzo & Dufty 1999 as extended kinetic
// theory uses them (Jenkins & Berzi 2010; Berzi & Vescovi 2015): LSJC's pressure and dissipation,
// GD's viscosity and conductivity (closures/garzo_dufty.h), no grad-nu heat flux
// (docs/continuum-model.md §2.5).
#include "granlub/continuum/closures/dissipation.h"
#include "granlub/continuum/closures/family.h"
#include "granlub/continuum/closures/garzo_dufty.h"
#include "granlub/continuum/closures/pressure.h"

namespace granlub::continuum {
namespace {
class GarzoDufty final : public ClosureFamily {
public:
    ClosureState<D1> state(const ClosureParams& p, D1 nu, D1 g, D1 dg) const override {
        namespace c = closures;
        const double e = p.restitution, eta = p.eta();
        ClosureState<D1> s{};
        s.nu = nu;
        s.g = g;
        s.dg = dg;
        s.fp = c::f_p(nu, g, eta);
        s.dfp = c::df_p(nu, g, dg, eta);
        s.fmu = c::f_mu_gd(nu, g, e);
        s.fk = c::f_kappa_gd(nu, g, e);
        s.fphi = D1(0.0);
        s.fgam = c::f_gamma(nu, g, eta);
        return s;
    }
};
}  // namespace

std::unique_ptr<ClosureFamily> make_closures_garzo_dufty() { return std::make_unique<GarzoDufty>(); }

}  // namespace granlub::continuum
