#include "granlub/continuum/simple_shear.h"

#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub::continuum {

SimpleShear simple_shear_at_nu(const Closures& c, double nu) {
    const auto s = c.state(nu);
    const double fp = s.fp.v, fmu = s.fmu.v, fgam = s.fgam.v;
    const ContactStress& cs = c.contact();  // its shear mu_c p_c adds to the kinetic one (§2.9)
    const double contact = cs.active() ? cs.friction * cs.ratio(nu) : 0.0;
    return {nu, std::sqrt(fgam / (fmu * fp)), std::sqrt(fmu * fgam) / fp + contact, fmu / fgam};
}

SimpleShear simple_shear_at_inertial(const Closures& c, double inertial) {
    // The maximum of I(nu) on a grid, then bisection on the dense side (I falls monotonically there).
    const double cap = c.cap(), top = cap * (1 - 1e-12);
    double lo = 0, best = -1;
    const int n = 200;
    for (int i = 1; i < n; ++i) {
        const double nu = cap * i / n;
        const double I = simple_shear_at_nu(c, nu).inertial;
        if (I > best) best = I, lo = nu;
    }
    if (!(inertial > 0) || inertial > best)
        throw SolverError(fmt::format("homogeneous shear: I = {} is outside the closures' dense branch (0, {:.4f}]",
                                      inertial, best));
    double hi = top;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
        const double mid = 0.5 * (lo + hi);
        (simple_shear_at_nu(c, mid).inertial > inertial ? lo : hi) = mid;
    }
    return simple_shear_at_nu(c, 0.5 * (lo + hi));
}

}  // namespace granlub::continuum
