// g0 of Torquato 1995 [LIT] (docs/continuum-model.md §2.3): Carnahan-Starling below the freezing point
// nu_f = 0.49, then g_f (nu_max - nu_f)/(nu_max - nu) with g_f = CS(nu_f).
#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
constexpr double kFreeze = 0.49;
struct Torquato {
    template <class S> static S cs(S nu) {
        const S om = 1.0 - nu;
        return (2.0 - nu) / (2.0 * om * om * om);
    }
    template <class S> static S dcs(S nu) {
        const S om = 1.0 - nu;
        const S om2 = om * om;
        return (5.0 - 2.0 * nu) / (2.0 * om2 * om2);
    }
    template <class S> static S g(S nu, double numax) {
        if (value(nu) < kFreeze) return cs(nu);
        return cs(kFreeze) * (numax - kFreeze) / (numax - nu);
    }
    template <class S> static S dg(S nu, double numax) {
        if (value(nu) < kFreeze) return dcs(nu);
        const S d = numax - nu;
        return cs(kFreeze) * (numax - kFreeze) / (d * d);
    }
    static double cap(double numax) { return numax; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_torquato(double numax) {
    return std::make_unique<RadialDistributionOf<Torquato>>(numax);
}

}  // namespace granlub::continuum
