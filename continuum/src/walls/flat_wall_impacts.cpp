// Walton's flat-wall impact law, stick and slide, averaged over a slipping Maxwellian (walls/flat_wall_impacts.h
// has the equations and their source).
#include "granlub/continuum/walls/flat_wall_impacts.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <tuple>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub::continuum {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kGauss = 20;        // Gauss-Legendre points per panel
constexpr double kReach = 10.0;   // r within xi +- kReach: the Gaussian beyond is below e^{-50}
constexpr double kStep = 0.02;    // the table's step in asinh(xi)

// The kGauss-point Gauss-Legendre rule on [-1, 1] (Newton on P_n from Chebyshev guesses).
struct GaussLegendre {
    std::array<double, kGauss> x{}, w{};
    GaussLegendre() {
        for (int i = 0; i < kGauss; ++i) {
            double z = std::cos(kPi * (i + 0.75) / (kGauss + 0.5)), dp = 0;
            for (int it = 0; it < 100; ++it) {
                double p0 = 1, p1 = z;
                for (int k = 2; k <= kGauss; ++k) {
                    const double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                    p0 = p1, p1 = p2;
                }
                dp = kGauss * (z * p1 - p0) / (z * z - 1);
                const double dz = p1 / dp;
                z -= dz;
                if (std::abs(dz) < 1e-16) break;
            }
            x[static_cast<std::size_t>(i)] = z;
            w[static_cast<std::size_t>(i)] = 2 / ((1 - z * z) * dp * dp);
        }
    }
};
const GaussLegendre& gauss() {
    static const GaussLegendre g;
    return g;
}

// e^{-x} times I0(x), I1(x), I1(x)/x, I2(x)/x^2, I1(x) - I0(x), I2(x) - I1(x) for x >= 0: the power series below 25
// (positive terms), Hankel's asymptotic series above (its smallest term there ~ e^{-50}), where the differences are
// summed term by term: taken as differences of the functions they would lose ~log10(x) digits, all of them at the
// slips of a nearly sticking wall (Abramowitz & Stegun 9.6.10, 9.7.1).
struct ScaledBessel {
    double i0, i1, j1, j2, d10, d21;
};
ScaledBessel scaled_bessel(double x) {
    if (x < 25.0) {
        const double t = 0.25 * x * x;
        double a = 1, b = 1, c = 1, s0 = 1, s1 = 1, s2 = 1;
        for (int k = 1; k < 200; ++k) {
            a *= t / (double(k) * k), b *= t / (double(k) * (k + 1)), c *= t / (double(k) * (k + 2));
            s0 += a, s1 += b, s2 += c;
            if (a < 1e-17 * s0 && k > t) break;
        }
        const double ex = std::exp(-x), i0 = ex * s0, i1 = ex * 0.5 * x * s1, i2 = ex * 0.125 * x * x * s2;
        return {i0, i1, ex * 0.5 * s1, ex * 0.125 * s2, i1 - i0, i2 - i1};
    }
    // sum_k (-1)^k a_k(nu) / x^k for nu = 0, 1, 2 (the k = 0 terms, 1, left out of the differences)
    double t[3] = {1, 1, 1}, s[3] = {1, 1, 1}, d10 = 0, d21 = 0;
    for (int k = 1; k < 40; ++k) {
        double next[3];
        for (int nu = 0; nu < 3; ++nu)
            next[nu] = -t[nu] * (4.0 * nu * nu - (2.0 * k - 1) * (2.0 * k - 1)) / (8.0 * k * x);
        if (std::abs(next[2]) > std::abs(t[2]) || std::abs(next[2]) < 1e-18) break;
        for (int nu = 0; nu < 3; ++nu) t[nu] = next[nu], s[nu] += next[nu];
        d10 += t[1] - t[0], d21 += t[2] - t[1];
    }
    const double n = 1.0 / std::sqrt(2 * kPi * x);
    return {n * s[0], n * s[1], n * s[1] / x, n * s[2] / (x * x), n * d10, n * d21};
}

// Q2(x) = int_0^x c^2 e^{-c^2/2} dc and Q3(x) = int_0^x c^3 e^{-c^2/2} dc, to full relative precision at small x
// too (where the closed forms cancel and mu_w^2 Q3 would carry their rounding into the stick limit).
double q2(double x, double ex, double er) {
    if (x >= 1.0) return std::sqrt(kPi / 2) * er - x * ex;
    double term = x * x * x, sum = term / 3;  // sum_k (-1)^k x^{2k+3} / (2^k k! (2k + 3))
    for (int k = 1; k < 40 && std::abs(term) > 1e-18 * sum; ++k) {
        term *= -0.5 * x * x / k;
        sum += term / (2 * k + 3);
    }
    return sum;
}
double q3(double x, double ex) {
    const double y = 0.5 * x * x;  // Q3 = 2 e^{-y} (e^y - 1 - y)
    if (y >= 0.5) return 2.0 - (x * x + 2.0) * ex;
    double term = y * y / 2, sum = term;
    for (int k = 3; k < 40 && term > 1e-18 * sum; ++k) term *= y / k, sum += term;
    return 2.0 * ex * sum;
}

}  // namespace

FlatWallImpacts::FlatWallImpacts(double e_w, double mu_w, double beta0) : e_(e_w), mu_(mu_w), b0_(beta0) {
    if (!(e_w >= 0 && e_w < 1) || !(mu_w > 0) || !std::isfinite(mu_w) || !(beta0 >= -1 && beta0 <= 1))
        throw Error(fmt::format("flat wall impact law: e_w = {} (allowed [0, 1)), mu_w = {} (allowed > 0), beta0 = {} "
                                "(allowed [-1, 1])",
                                e_w, mu_w, beta0));
    a_ = (2.0 / 7.0) * (1.0 + b0_) / (mu_ * (1.0 + e_));
    xi_max_ = std::max(20.0, 8.0 + 8.0 / a_);
    const double s_max = std::asinh(xi_max_);
    const auto n = static_cast<std::size_t>(std::ceil(s_max / kStep));
    ds_ = s_max / static_cast<double>(n);
    table_.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) {
        const double s = ds_ * static_cast<double>(k), xi = std::sinh(s);
        Factors f = from(quadrature(xi), xi);
        f.dh *= std::cosh(s), f.dg *= std::cosh(s);  // d/d asinh(xi)
        table_[k] = f;
    }
}

double FlatWallImpacts::sigma_stick(double xi) const {
    return (2.0 / 7.0) * (1.0 + b0_) * std::sqrt(2.0 / kPi) * xi / (1.0 + e_);
}

double FlatWallImpacts::delta_stick(double xi) const {
    return std::sqrt(2.0 / kPi) / (1.0 + e_) * ((1.0 - e_ * e_) + (1.0 - b0_ * b0_) * (xi * xi + 2.0) / 7.0);
}

FlatWallImpacts::Moments FlatWallImpacts::quadrature(double xi) const {
    const GaussLegendre& gl = gauss();
    const double M = mu_ * (1.0 + e_), ft = (1.0 - b0_ * b0_) / 7.0, rp = std::sqrt(kPi / 2);
    const double lo = std::max(0.0, xi - kReach), hi = xi + kReach;
    // panels no wider than the stick/slide crossover's scale 1/a in r
    const int panels = static_cast<int>(std::ceil((hi - lo) / std::min(1.0, 1.0 / a_)));
    const double width = (hi - lo) / panels;
    double so = 0, dso = 0, tl = 0, dtl = 0;
    for (int p = 0; p < panels; ++p) {
        const double mid = lo + (p + 0.5) * width;
        for (int q = 0; q < kGauss; ++q) {
            const double r = mid + 0.5 * width * gl.x[static_cast<std::size_t>(q)];
            const double w = 0.5 * width * gl.w[static_cast<std::size_t>(q)] * std::exp(-0.5 * (r - xi) * (r - xi));
            const ScaledBessel b = scaled_bessel(r * xi);
            const double x = a_ * r, gx = std::exp(-0.5 * x * x), er = std::erf(x / std::sqrt(2.0));
            // E_c of the tangential loss at |g| = r: sliding below c_n = a r, sticking above
            const double loss = M * r * q2(x, gx, er) - 1.75 * M * M * q3(x, gx) + ft * r * r * gx;
            // d/dxi of e^{-(r^2 + xi^2)/2} I1(r xi)/xi and I0(r xi), in the forms that do not cancel (ScaledBessel)
            const double dj = r * xi < 25.0 ? xi * (r * r * b.j2 - b.j1) : (b.d21 + (r - xi) / r * b.i1) / xi;
            so += w * er * r * r * b.j1;
            dso += w * er * r * r * dj;
            tl += w * loss * r * b.i0;
            dtl += w * loss * r * ((r - xi) * b.i0 + r * b.d10);
        }
    }
    const double norm = (1.0 + e_) * rp;
    return {mu_ * so, mu_ * dso, ((1.0 - e_ * e_) + tl) / norm, dtl / norm};
}

FlatWallImpacts::Moments FlatWallImpacts::asymptote(double xi) const {
    const double c0 = std::sqrt(2.0 / kPi), x2 = xi * xi;
    const double sigma = mu_ * (1.0 - 0.5 / x2 - 0.375 / (x2 * x2));
    const double dsigma = mu_ * (1.0 / (x2 * xi) + 1.5 / (x2 * x2 * xi));
    const double delta =
        (1.0 - e_) * c0 + mu_ * (xi + 0.5 / xi + 0.125 / (x2 * xi)) - 3.5 * mu_ * mu_ * (1.0 + e_) * c0;
    return {sigma / xi, (dsigma * xi - sigma) / x2, delta, sigma};  // d delta/d xi = sigma to this order
}

FlatWallImpacts::Factors FlatWallImpacts::from(const Moments& m, double xi) const {
    const double ks = sigma_stick(1.0);  // sigma_s/xi
    const double ds = delta_stick(xi), dds = std::sqrt(2.0 / kPi) / (1.0 + e_) * (1.0 - b0_ * b0_) * 2.0 * xi / 7.0;
    return {m.sigma_over_xi / ks, m.d_sigma_over_xi / ks, m.delta / ds, (m.d_delta * ds - m.delta * dds) / (ds * ds)};
}

FlatWallImpacts::Factors FlatWallImpacts::factors(double xi) const {
    xi = std::abs(xi);
    if (xi >= xi_max_) return from(asymptote(xi), xi);
    // cubic Hermite in s = asinh(xi)
    const double s = std::asinh(xi) / ds_;
    const std::size_t k = std::min(static_cast<std::size_t>(s), table_.size() - 2);
    const double t = s - static_cast<double>(k), t2 = t * t, u = 1 - t;
    const Factors& a = table_[k];
    const Factors& b = table_[k + 1];
    const double h00 = (1 + 2 * t) * u * u, h10 = t * u * u * ds_, h01 = t2 * (3 - 2 * t), h11 = t2 * (t - 1) * ds_;
    const double d00 = 6 * t * (t - 1) / ds_, d10 = (3 * t - 1) * (t - 1), d01 = -d00, d11 = t * (3 * t - 2);
    const double dsdxi = 1.0 / std::sqrt(1.0 + xi * xi);
    return {h00 * a.h + h10 * a.dh + h01 * b.h + h11 * b.dh,
            (d00 * a.h + d10 * a.dh + d01 * b.h + d11 * b.dh) * dsdxi,
            h00 * a.g + h10 * a.dg + h01 * b.g + h11 * b.dg,
            (d00 * a.g + d10 * a.dg + d01 * b.g + d11 * b.dg) * dsdxi};
}

std::shared_ptr<const FlatWallImpacts> flat_wall_impacts(double e_w, double mu_w, double beta0) {
    // Kept for the process: a case has a wall law or two (friction is not swept), and its table costs more than a
    // 1-D point's solve.
    static std::mutex mutex;
    static std::map<std::tuple<double, double, double>, std::shared_ptr<const FlatWallImpacts>> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    auto& law = cache[{e_w, mu_w, beta0}];
    if (!law) law = std::make_shared<const FlatWallImpacts>(e_w, mu_w, beta0);
    return law;
}

}  // namespace granlub::continuum
