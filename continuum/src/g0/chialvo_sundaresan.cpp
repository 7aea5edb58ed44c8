// g0 of Chialvo & Sundaresan 2013 (Phys. Fluids 25, 070603, Eq. 31) (docs/continuum-model.md §2.3):
// Carnahan-Starling plus a term that diverges at the jamming fraction nu_c = nu_max,
//   g0 = (1 - nu/2)/(1 - nu)^3 + a2 nu^2/(nu_c - nu)^{3/2},   a2 = 0.58
// [SRC: read in CFDEM-PRINCETON twoPhaseEulerFoamPU/kineticTheoryModels/radialModel/ChialvoSundaresan
// ("Eq. 31"); the paper itself not read]. nu_c depends on the grains' friction (Chialvo, Sun & Sundaresan
// 2012); it is [cell] max_solid_fraction, or [continuum] max_solid_fraction.
#include <cmath>

#include "granlub/continuum/g0/radial_distribution.h"

namespace granlub::continuum {
namespace {
constexpr double kA2 = 0.58;
struct ChialvoSundaresan {
    template <class S> static S g(S nu, double numax) {
        using std::sqrt;
        const S om = 1.0 - nu, d = numax - nu;
        return (1.0 - 0.5 * nu) / (om * om * om) + kA2 * nu * nu / (d * sqrt(d));
    }
    template <class S> static S dg(S nu, double numax) {
        using std::sqrt;
        const S om = 1.0 - nu, d = numax - nu;
        const S om2 = om * om;
        return (2.5 - nu) / (om2 * om2) + kA2 * (2.0 * nu / (d * sqrt(d)) + 1.5 * nu * nu / (d * d * sqrt(d)));
    }
    static double cap(double numax) { return numax; }
};
}  // namespace

std::unique_ptr<RadialDistribution> make_g0_chialvo_sundaresan(double numax) {
    return std::make_unique<RadialDistributionOf<ChialvoSundaresan>>(numax);
}

}  // namespace granlub::continuum
