// g0 of the 1/3-power form, g0 = 1/(1 - (nu/nu_max)^{1/3}) (docs/continuum-model.md §2.3). Ogawa et al. 1980 /
// Bagnold; often labelled "Lun et al. 1984" (ANSYS Fluent "lun-et-al") [LIT].
// The default: it fits S&T's mean nu best (RMS 0.016, §7.2).
#include <cmath>

#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
struct Ogawa {
    template <class S> static S g(S nu, double numax) {
        using std::cbrt;
        return 1.0 / (1.0 - cbrt(nu / numax));
    }
    // g0' = x / (3 nu (1 - x)^2), x = (nu/nu_max)^{1/3}
    template <class S> static S dg(S nu, double numax) {
        using std::cbrt;
        const S x = cbrt(nu / numax);
        const S om = 1.0 - x;
        return x / (3.0 * nu * om * om);
    }
    static double cap(double numax) { return numax; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_ogawa(double numax) {
    return std::make_unique<RadialDistributionOf<Ogawa>>(numax);
}

}  // namespace granlub::continuum
