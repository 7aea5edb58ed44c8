// g0 of Ma & Ahmadi 1986 [LIT] (docs/continuum-model.md §2.3):
//   g0 = (1 + 2.5 nu + 4.5904 nu^2 + 4.515439 nu^3) / [1 - (nu/nu_max)^3]^0.67802
#include <cmath>

#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
constexpr double kA = 0.67802;
struct MaAhmadi {
    template <class S> static S num(S nu) { return 1.0 + nu * (2.5 + nu * (4.5904 + nu * 4.515439)); }
    template <class S> static S dnum(S nu) { return 2.5 + nu * (2.0 * 4.5904 + nu * 3.0 * 4.515439); }
    template <class S> static S den(S nu, double numax) {
        const S x = nu / numax;
        return 1.0 - x * x * x;
    }
    template <class S> static S g(S nu, double numax) {
        using std::pow;
        return num(nu) / pow(den(nu, numax), kA);
    }
    // g0' = N'/D^a + N a 3 nu^2/nu_max^3 D^{-a-1}
    template <class S> static S dg(S nu, double numax) {
        using std::pow;
        const S d = den(nu, numax);
        return dnum(nu) / pow(d, kA) +
               num(nu) * kA * 3.0 * nu * nu / (numax * numax * numax) * pow(d, -kA - 1.0);
    }
    static double cap(double numax) { return numax; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_ma_ahmadi(double numax) {
    return std::make_unique<RadialDistributionOf<MaAhmadi>>(numax);
}

}  // namespace granlub::continuum
