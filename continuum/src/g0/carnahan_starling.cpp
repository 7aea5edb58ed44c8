// g0 of Carnahan & Starling 1969: g0 = (2 - nu)/(2 (1 - nu)^3) (docs/continuum-model.md §2.3). It has no nu_max
// singularity, so the logit map is capped at 0.95 and nu > nu_max is reported as unphysical
// (§6.1, §6.3). It overshoots nu_max for the S&T case (§7.2).
#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
struct CarnahanStarling {
    template <class S> static S g(S nu, double /*numax*/) {
        const S om = 1.0 - nu;
        return (2.0 - nu) / (2.0 * om * om * om);
    }
    // g0' = (5 - 2 nu)/(2 (1 - nu)^4)
    template <class S> static S dg(S nu, double /*numax*/) {
        const S om = 1.0 - nu;
        const S om2 = om * om;
        return (5.0 - 2.0 * nu) / (2.0 * om2 * om2);
    }
    static double cap(double /*numax*/) { return 0.95; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_carnahan_starling(double numax) {
    return std::make_unique<RadialDistributionOf<CarnahanStarling>>(numax);
}

}  // namespace granlub::continuum
