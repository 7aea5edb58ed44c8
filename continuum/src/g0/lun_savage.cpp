// g0 of Lun & Savage 1986 (Acta Mech. 63:15) [LIT]: g0 = (1 - nu/nu_max)^{-2.5 nu_max}
// (docs/continuum-model.md §2.3; OpenFOAM radialModel `LunSavage`). The first alternative to the default.
#include <cmath>

#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
struct LunSavage {
    template <class S> static S g(S nu, double numax) {
        using std::pow;
        return pow(1.0 - nu / numax, -2.5 * numax);
    }
    // g0' = 2.5 (1 - nu/nu_max)^{-2.5 nu_max - 1}
    template <class S> static S dg(S nu, double numax) {
        using std::pow;
        return 2.5 * pow(1.0 - nu / numax, -2.5 * numax - 1.0);
    }
    static double cap(double numax) { return numax; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_lun_savage(double numax) {
    return std::make_unique<RadialDistributionOf<LunSavage>>(numax);
}

}  // namespace granlub::continuum
