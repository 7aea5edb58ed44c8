// Bond-orientational order and layering (packing_order.h).
#include "granlub/packing_order.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

#include "granlub/contacts.h"

namespace granlub {

namespace {

constexpr int kL = 6;
using Harmonics = std::array<std::complex<double>, kL + 1>;  // m = 0..6; m < 0 by symmetry

// Y6m(theta, phi) for m = 0..6 of the unit vector (x, y, z), theta from +z. std::sph_legendre gives
// Y_l^m(theta, 0) with the Condon-Shortley phase; |q6m| does not depend on the phase convention.
void harmonics(double x, double y, double z, Harmonics& out) {
    const double r = std::sqrt(x * x + y * y + z * z);
    const double theta = std::acos(std::clamp(z / r, -1.0, 1.0)), phi = std::atan2(y, x);
    for (int m = 0; m <= kL; ++m)
        out[static_cast<std::size_t>(m)] = std::sph_legendre(kL, m, theta) * std::polar(1.0, m * phi);
}

// sqrt(4 pi / 13 sum_{m=-6..6} |q_m|^2) from q_0..q_6: |q_{-m}| = |q_m| for a real field's harmonics.
double invariant(const Harmonics& q) {
    double s = std::norm(q[0]);
    for (int m = 1; m <= kL; ++m) s += 2.0 * std::norm(q[static_cast<std::size_t>(m)]);
    return std::sqrt(4.0 * std::numbers::pi / (2 * kL + 1) * s);
}

}  // namespace

double local_q6(const std::vector<std::array<double, 3>>& bonds) {
    if (bonds.empty()) return 0.0;
    Harmonics sum{}, y{};
    for (const auto& b : bonds) {
        harmonics(b[0], b[1], b[2], y);
        for (std::size_t m = 0; m <= kL; ++m) sum[m] += y[m];
    }
    for (auto& v : sum) v /= static_cast<double>(bonds.size());
    return invariant(sum);
}

BondOrder bond_order(const ParticleSet& p, const ParticleBox& box) {
    BondOrder o;
    const std::size_t n = p.size();
    if (n < 2) return o;
    const ContactList bonds = touching_pairs(p, box, kOrderNeighbourCutoff - 1.0);
    std::vector<Harmonics> sum(n, Harmonics{});
    std::vector<std::size_t> count(n, 0);
    Harmonics global{}, y{};
    for (const auto& [i, j] : bonds) {
        double dx = p.x[j] - p.x[i], dz = p.z[j] - p.z[i];
        dx -= box.length * std::round(dx / box.length);
        if (box.periodic_z) dz -= box.width * std::round(dz / box.width);
        harmonics(dx, p.y[j] - p.y[i], dz, y);  // l = 6 is even: the bond j -> i gives the same
        for (std::size_t m = 0; m <= kL; ++m) sum[i][m] += y[m], sum[j][m] += y[m], global[m] += y[m];
        ++count[i], ++count[j];
    }
    double q6 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (count[i] < kOrderMinNeighbours) continue;
        for (auto& v : sum[i]) v /= static_cast<double>(count[i]);
        q6 += invariant(sum[i]);
        ++o.grains;
    }
    o.q6 = o.grains ? q6 / static_cast<double>(o.grains) : 0.0;
    if (!bonds.empty())
        for (auto& v : global) v /= static_cast<double>(bonds.size());
    o.Q6 = bonds.empty() ? 0.0 : invariant(global);
    o.neighbours = 2.0 * static_cast<double>(bonds.size()) / static_cast<double>(n);
    return o;
}

LayerOrder layer_order(const ParticleSet& p, double lo, double hi, double d) {
    LayerOrder best;
    constexpr int kSteps = 80;  // lambda resolved to 0.005 d: a peak of N grains is ~lambda / (N y) wide
    for (int k = 0; k <= kSteps; ++k) {
        const double lambda = d * (kLayerSpacingMin + (kLayerSpacingMax - kLayerSpacingMin) * k / kSteps);
        double c = 0, s = 0;
        std::size_t n = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            if (p.y[i] < lo || p.y[i] > hi) continue;
            const double phase = 2.0 * std::numbers::pi * p.y[i] / lambda;
            c += std::cos(phase), s += std::sin(phase), ++n;
        }
        if (n == 0) return best;
        const double a = std::hypot(c, s) / static_cast<double>(n);
        if (a > best.order) best = {a, lambda, n};
    }
    return best;
}

void OrderSeries::add(const ParticleSet& p, double time) {
    if (time < t_start_ - 1e-12) return;
    const BondOrder o = bond_order(p, box_);
    q6_.push_back(o.q6);
    Q6_.push_back(o.Q6);
    neighbours_.push_back(o.neighbours);
    const LayerOrder l = granlub::layer_order(p, lo_, hi_, d_);
    layer_.push_back(l.order);
    spacing_.push_back(l.spacing);
}

namespace {
double mean_of(const std::vector<double>& v) {
    double s = 0;
    for (double x : v) s += x;
    return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}
}  // namespace

double OrderSeries::mean_neighbours() const { return mean_of(neighbours_); }
double OrderSeries::mean_layer_spacing() const { return mean_of(spacing_); }

std::optional<double> layering_amplitude(const Profile& profile, double gap, double diameter) {
    const auto& y = profile.column("y_over_H");
    const auto& nu = profile.column("solid_fraction");
    std::vector<double> v;
    for (std::size_t k = 0; k < y.size(); ++k)
        if (y[k] * gap >= 0.5 * diameter && (1.0 - y[k]) * gap >= 0.5 * diameter) v.push_back(nu[k]);
    if (v.size() < 3) return std::nullopt;
    double mean = 0, var = 0;
    for (double x : v) mean += x;
    mean /= static_cast<double>(v.size());
    if (!(mean > 0)) return std::nullopt;
    for (double x : v) var += (x - mean) * (x - mean);
    return std::sqrt(var / static_cast<double>(v.size())) / mean;
}

}  // namespace granlub
