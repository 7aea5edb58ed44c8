// Touching pairs, coordination number and contact persistence (contacts.h).
#include "granlub/particles/contacts.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {

// One axis of the cell list: n cells of size h >= the contact range from lo; periodic axes wrap.
struct Axis {
    double lo = 0, h = 1;
    long n = 1;
    bool periodic = false;
    double period = 0;
    Axis(double lo_, double extent, double range, bool periodic_) : lo(lo_), periodic(periodic_), period(extent) {
        n = std::max(1L, static_cast<long>(std::floor(extent / range)));
        h = extent > 0 ? extent / static_cast<double>(n) : 1.0;
    }
    long cell(double v) const {
        const long k = static_cast<long>(std::floor((v - lo) / h));
        return periodic ? ((k % n) + n) % n : std::clamp(k, 0L, n - 1);
    }
    double image(double d) const { return periodic ? d - period * std::round(d / period) : d; }
};

}  // namespace

ContactList touching_pairs(const ParticleSet& p, const ParticleBox& box, double tolerance) {
    ContactList out;
    const std::size_t n = p.size();
    if (n < 2) return out;
    if (!(box.length > 0) || (box.periodic_z && !(box.width > 0)) || !(tolerance >= 0))
        throw Error(fmt::format("contacts: need a positive periodic length (and width when periodic in z) and a "
                                "non-negative tolerance (got L = {:g}, W = {:g}, tolerance {:g})",
                                box.length, box.width, tolerance));
    const double rmax = *std::max_element(p.radius.begin(), p.radius.end());
    const double range = 2.0 * rmax * (1.0 + tolerance);
    const auto [ylo, yhi] = std::minmax_element(p.y.begin(), p.y.end());
    const auto [zlo, zhi] = std::minmax_element(p.z.begin(), p.z.end());
    const Axis ax(0.0, box.length, range, true);
    const Axis ay(*ylo, *yhi - *ylo, range, false);
    const Axis az = box.periodic_z ? Axis(-0.5 * box.width, box.width, range, true)
                                   : Axis(*zlo, *zhi - *zlo, range, false);
    const auto index = [&](long i, long j, long k) { return static_cast<std::size_t>((i * ay.n + j) * az.n + k); };
    std::vector<std::vector<std::uint32_t>> cells(static_cast<std::size_t>(ax.n * ay.n * az.n));
    std::vector<long> cx(n), cy(n), cz(n);
    for (std::size_t a = 0; a < n; ++a) {
        cx[a] = ax.cell(p.x[a]);
        cy[a] = ay.cell(p.y[a]);
        cz[a] = az.cell(p.z[a]);
        cells[index(cx[a], cy[a], cz[a])].push_back(static_cast<std::uint32_t>(a));
    }
    // Per axis and cell, the distinct cells c-1, c, c+1 (with few cells the wraps coincide): made
    // once, so the pair loop allocates nothing.
    auto neighbours = [](const Axis& ax_) {
        std::vector<std::vector<long>> all(static_cast<std::size_t>(ax_.n));
        for (long c = 0; c < ax_.n; ++c) {
            auto& v = all[static_cast<std::size_t>(c)];
            for (long d = -1; d <= 1; ++d) {
                long k = c + d;
                if (ax_.periodic) k = ((k % ax_.n) + ax_.n) % ax_.n;
                else if (k < 0 || k >= ax_.n) continue;
                if (std::find(v.begin(), v.end(), k) == v.end()) v.push_back(k);
            }
        }
        return all;
    };
    const auto nx = neighbours(ax), ny = neighbours(ay), nz = neighbours(az);
    for (std::size_t a = 0; a < n; ++a)
        for (long i : nx[static_cast<std::size_t>(cx[a])])
            for (long j : ny[static_cast<std::size_t>(cy[a])])
                for (long k : nz[static_cast<std::size_t>(cz[a])])
                    for (std::uint32_t b : cells[index(i, j, k)]) {
                        if (b <= a) continue;
                        const double dx = ax.image(p.x[b] - p.x[a]), dy = p.y[b] - p.y[a];
                        const double dz = az.image(p.z[b] - p.z[a]);
                        const double reach = (p.radius[a] + p.radius[b]) * (1.0 + tolerance);
                        if (dx * dx + dy * dy + dz * dz <= reach * reach)
                            out.emplace_back(static_cast<std::uint32_t>(a), b);
                    }
    std::sort(out.begin(), out.end());
    return out;
}

OverlapStats overlaps(const ParticleSet& p, const ParticleBox& box, const ContactList& pairs) {
    // the minimum images of touching_pairs(): x always periodic, z when the box says so
    const auto image = [](double d, double period) { return d - period * std::round(d / period); };
    OverlapStats o;
    double sum = 0;
    for (const auto& [a, b] : pairs) {
        const double dx = image(p.x[b] - p.x[a], box.length), dy = p.y[b] - p.y[a];
        const double dz = box.periodic_z ? image(p.z[b] - p.z[a], box.width) : p.z[b] - p.z[a];
        const double reach = p.radius[a] + p.radius[b];
        const double rel = (reach - std::sqrt(dx * dx + dy * dy + dz * dz)) / reach;
        if (rel <= 0) continue;
        ++o.overlapping;
        sum += rel;
        o.max = std::max(o.max, rel);
    }
    if (o.overlapping) o.mean = sum / static_cast<double>(o.overlapping);
    return o;
}

double coordination_number(const ContactList& pairs, std::size_t grains) {
    return grains > 0 ? 2.0 * static_cast<double>(pairs.size()) / static_cast<double>(grains) : 0.0;
}

std::optional<double> band_coordination(const ParticleSet& p, const ContactList& pairs, Band band) {
    const auto in = [&](std::uint32_t i) { return p.y[i] >= band.lo && p.y[i] <= band.hi; };
    std::size_t grains = 0, ends = 0;
    for (std::size_t i = 0; i < p.size(); ++i) grains += in(static_cast<std::uint32_t>(i));
    if (grains == 0) return std::nullopt;
    for (const auto& [a, b] : pairs) ends += static_cast<std::size_t>(in(a)) + static_cast<std::size_t>(in(b));
    return static_cast<double>(ends) / static_cast<double>(grains);
}

std::optional<double> contact_persistence(const ContactList& before, const ContactList& after) {
    if (before.empty()) return std::nullopt;
    std::size_t kept = 0;
    for (auto a = before.begin(), b = after.begin(); a != before.end() && b != after.end();) {
        if (*a < *b) ++a;
        else if (*b < *a) ++b;
        else ++kept, ++a, ++b;
    }
    return static_cast<double>(kept) / static_cast<double>(before.size());
}

void ContactSeries::add(const ParticleSet& p, double time) {
    if (time < t_start_ - 1e-12) return;
    const auto t0 = std::chrono::steady_clock::now();
    const ContactList pairs = touching_pairs(p, box_);
    z_.push_back(coordination_number(pairs, p.size()));
    if (core_)
        if (const auto zc = band_coordination(p, pairs, *core_)) z_core_.push_back(*zc);
    const OverlapStats o = overlaps(p, box_, pairs);
    max_overlap_ = std::max(max_overlap_, o.max);
    overlap_sum_ += o.mean * static_cast<double>(o.overlapping);
    overlapping_ += o.overlapping;
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace granlub
