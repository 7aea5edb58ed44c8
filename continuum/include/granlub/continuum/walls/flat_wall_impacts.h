// A flat frictional wall's traction and dissipation from Walton's impact law with impacts that stick AND slide
// (docs/continuum-model.md §4.3b; walls/flat_wall.h has the stick limit this corrects) [DERIVED, ours].
//
// Jenkins (1992, J. Appl. Mech. 59, 120)'s construction, the grains' spin left out as in flat_wall.h: a Maxwellian
// at T (each velocity component of variance T) with mean slip u_s along the wall hits it at the flux-weighted rate
// (c_n of density c_n exp(-c_n^2/2T)/T), the contact-point slip g = (u_s + C_x, C_z). Per impact (mass m)
//   J_n = (1 + e_w) m c_n,   J_t = min(mu_w J_n, (2/7)(1 + beta0) m |g|) against g,
//   lost: (1/2) m (1 - e_w^2) c_n^2 and, sticking, (1/7)(1 - beta0^2) m |g|^2, sliding, J_t |g| - (7/4) J_t^2/m.
// With xi = u_s/sqrt(T), N the wall's normal stress (family K: P) and Z = N/E[J_n] the impacts per area and time,
//   sigma(xi) = S/N = E[J_t g_x/|g|]/E[J_n],   delta(xi) = D/(N sqrt T) = E[loss]/(E[J_n] sqrt T),
// and in the stick limit (mu_w -> infinity; flat_wall.h)
//   sigma_s = (2/7)(1 + beta0) sqrt(2/pi) xi/(1 + e_w),
//   delta_s = sqrt(2/pi)/(1 + e_w) [(1 - e_w^2) + (1/7)(1 - beta0^2)(xi^2 + 2)].
// The wall condition (wall_condition.h) multiplies family K's traction by h = sigma/sigma_s and its collisional
// terms (R6, R7) by g = delta/delta_s; both are 1 in the stick limit and fall as 1/xi once impacts slide.
//
// Reduction (T = m = 1, a = (2/7)(1 + beta0)/(mu_w (1 + e_w)): an impact sticks where c_n >= a|g|). The c_n-integral
// is closed: E_c[J_t] = mu_w (1 + e_w) sqrt(pi/2) erf(a|g|/sqrt 2) (the two branches' boundary terms cancel), and
// E_c[tangential loss] = M r Q2(a r) - (7/4) M^2 Q3(a r) + (1/7)(1 - beta0^2) r^2 exp(-a^2 r^2/2), r = |g|,
// M = mu_w (1 + e_w), Q2(x) = int_0^x c^2 e^{-c^2/2} dc, Q3(x) = int_0^x c^3 e^{-c^2/2} dc. The angle of g is
// closed by Bessel functions (g is a 2-D Gaussian about (xi, 0), |g| Rice-distributed):
//   sigma = mu_w int_0^inf erf(a r/sqrt 2) r e^{-(r^2 + xi^2)/2} I1(r xi) dr,
//   delta = [(1 - e_w^2) + int_0^inf E_c[tangential loss](r) r e^{-(r^2 + xi^2)/2} I0(r xi) dr]/((1 + e_w) sqrt(pi/2)),
// left to a composite Gauss-Legendre rule in r. For xi -> infinity every impact slides:
//   sigma -> mu_w (1 - 1/(2 xi^2) - 3/(8 xi^4)),
//   delta -> (1 - e_w) sqrt(2/pi) + mu_w (xi + 1/(2 xi) + 1/(8 xi^3)) - (7/2) mu_w^2 (1 + e_w) sqrt(2/pi)
// (E|g| = xi + 1/(2 xi) + 1/(8 xi^3) + ...), exponentially close once a xi >> 1.
//
// At the experiment's walls (e_w = 0.9, mu_w = 0.5, beta0 = 0): sigma = 0.1118, 0.2148, 0.3023, 0.3710, 0.4538,
// 0.4860 and delta = 0.2526, 0.4169, 0.6770, 1.0153, 1.8509, 2.7966 at xi = 1, 2, 3, 4, 6, 8; h = 0.944, 0.880,
// 0.814, 0.752 and g = 0.983, 0.939, 0.900, 0.863 at xi = 0, 2.3, 3.4, 4.3.
// Measured 2026-12-06 on commit 3b1d174 (this law against the stick limit, both spin-free; the extended closures
// of the rough cases' fit): the periodic poly twin's walls go from xi 3.1-3.4 to 3.8-4.3, mu = tau/P from
// 0.377/0.396/0.404 to 0.360/0.377/0.388 at 1.4/2.0/2.8 m/s (DEM 0.243/0.259/0.270), slips from 0.255-0.260 U to
// 0.287-0.299 U (DEM 0.31 U); the troughs' plane side walls: on _rough the side share's excess over the DEM's from
// +4.2/+3.5/+3.7 to +3.4/+2.8/+3.0 points; on _poly (plane floor and top too) tau from +37..+46 % to +30..+39 % of
// the DEM's. With the grains' spin (flat_wall_spin = "torque_balance": the law at the contact points' xi, half the
// grains'; measured 2026-12-06 on commit f370f5a, against the spin's stick limit): the poly twin's mu from
// 0.270/0.282/0.289 to 0.256/0.267/0.274 (all three within 7 % of the DEM's), its slips from 0.355-0.362 U to
// 0.369-0.377 U (0.06 U above the DEM's: none within 0.05 U); the _rough trough 7 of 7 targets at every speed either
// way, the _poly trough 5, 5, 5 of 7 (the stick limit 5, 5, 6), tau there from -2..+3 % to -8..-3 % of the DEM's.
//
// Evaluation: h and g are tabulated once per law on a grid uniform in asinh(xi) (values and exact xi-derivatives
// from the quadrature, cubic Hermite between nodes), up to xi_max >= 20, where a (xi_max - 8) >= 8 and the
// asymptotes hold to < 3e-8; beyond it the asymptotes. The table agrees with the quadrature to ~1e-8 (tested to
// 1e-6); a table costs ~8 ms, an evaluation ~30 ns.
#pragma once
#include <memory>
#include <vector>

namespace granlub::continuum {

class FlatWallImpacts {
public:
    // e_w in [0, 1), mu_w > 0, beta0 in [-1, 1]; throws granlub::Error otherwise.
    FlatWallImpacts(double e_w, double mu_w, double beta0);

    double restitution() const { return e_; }
    double friction() const { return mu_; }
    double beta0() const { return b0_; }
    double xi_max() const { return xi_max_; }

    struct Factors {
        double h, dh;  // sigma/sigma_s and d/dxi
        double g, dg;  // delta/delta_s and d/dxi
    };
    // At xi >= 0 (|xi| otherwise): the table, the asymptotes beyond xi_max. No allocation.
    Factors factors(double xi) const;

    double sigma_stick(double xi) const;
    double delta_stick(double xi) const;
    double sigma(double xi) const { return factors(xi).h * sigma_stick(xi); }
    double delta(double xi) const { return factors(xi).g * delta_stick(xi); }

    // sigma/xi and delta with their xi-derivatives: by the quadrature (the table's nodes) or the asymptotes.
    struct Moments {
        double sigma_over_xi, d_sigma_over_xi, delta, d_delta;
    };
    Moments quadrature(double xi) const;
    Moments asymptote(double xi) const;

private:
    Factors from(const Moments& m, double xi) const;

    double e_, mu_, b0_;
    double a_;          // an impact sticks where c_n >= a |g|
    double xi_max_, ds_;
    std::vector<Factors> table_;  // at asinh(xi) = k ds, derivatives in asinh(xi)
};

// The law at (e_w, mu_w, beta0), tabulated once per process (thread-safe).
std::shared_ptr<const FlatWallImpacts> flat_wall_impacts(double e_w, double mu_w, double beta0);

}  // namespace granlub::continuum
