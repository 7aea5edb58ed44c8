// Overlap-free grains in the ring trough (annulus.h, insert_ring_grains).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "granlub/annulus.h"
#include "granlub/error.h"
#include "granlub/grain_sizes.h"
#include "lattice_insertion.h"

namespace granlub {

namespace {

constexpr double kPi = std::numbers::pi;

// Sites a apart: layers along y, circles across the width, on each circle as many sites as
// chords of length >= a allow. Sites on one circle are a chord apart, on neighbouring circles
// at least the circles' radial distance a, in neighbouring layers at least a along y.
struct RingLattice {
    std::vector<double> r;            // circle radii
    std::vector<std::size_t> per;     // sites on each circle
    std::vector<std::size_t> first;   // index of each circle's first site within a layer
    std::size_t per_layer = 0, layers = 0;
    double y0 = 0, ay = 0, jitter = 0;
    std::size_t count() const { return per_layer * layers; }
};

RingLattice make_ring_lattice(const Annulus& an, double h, double d, double a, double sag) {
    RingLattice l;
    l.jitter = 0.5 * (a - d);
    const double margin = l.jitter + 1e-9 * d;
    const double hy = h - d - 2.0 * margin;
    l.layers = hy < 0 ? 0 : static_cast<std::size_t>(std::floor(hy / a)) + 1;
    l.ay = l.layers > 1 ? hy / static_cast<double>(l.layers - 1) : 0.0;
    l.y0 = 0.5 * d + margin;
    const double r0 = an.inner() + 0.5 * d + margin + sag, r1 = an.outer() - 0.5 * d - margin - sag;
    if (r1 < r0) return l;
    const std::size_t circles = static_cast<std::size_t>(std::floor((r1 - r0) / a)) + 1;
    const double ar = circles > 1 ? (r1 - r0) / static_cast<double>(circles - 1) : 0.0;
    for (std::size_t j = 0; j < circles; ++j) {
        const double r = r0 + static_cast<double>(j) * ar;
        // m sites: chord 2 r sin(pi/m) >= a
        const double s = 0.5 * a / r;
        const std::size_t m = s >= 1 ? 0 : static_cast<std::size_t>(std::floor(kPi / std::asin(s) * (1 - 1e-12)));
        if (m < 2) continue;
        l.r.push_back(r);
        l.first.push_back(l.per_layer);
        l.per.push_back(m);
        l.per_layer += m;
    }
    return l;
}

void ring_site(const RingLattice& l, std::size_t s, double& x, double& y, double& z) {
    const std::size_t k = s / l.per_layer, in_layer = s % l.per_layer;
    const std::size_t j = static_cast<std::size_t>(std::upper_bound(l.first.begin(), l.first.end(), in_layer) -
                                                   l.first.begin()) - 1;
    const std::size_t i = in_layer - l.first[j];
    // half a site's turn on every other circle and layer: no radial rows of sites
    const double shift = 0.5 * static_cast<double>((j + k) % 2);
    const double theta = 2.0 * kPi * (static_cast<double>(i) + shift) / static_cast<double>(l.per[j]);
    x = l.r[j] * std::cos(theta);
    z = -l.r[j] * std::sin(theta);
    y = l.y0 + static_cast<double>(k) * l.ay;
}

}  // namespace

std::size_t ring_capacity(const Annulus& a, double h, double d, double sag) {
    return make_ring_lattice(a, h, d, d, sag).count();
}

ParticleSet insert_ring_grains(const Annulus& an, double h, double d_mean, std::size_t n, const InsertionOptions& opt,
                               double sag) {
    const GrainSizes g{d_mean, opt.size_spread};
    const double d = g.max();  // sites and wall margins for the largest grain
    if (!(d > 0) || !(h > 0) || !(an.W > 0) || !(an.inner() > 0))
        throw CaseError(fmt::format("ring insertion: grain diameter {:g} m, height {:g} m, width {:g} m and inner "
                                    "radius {:g} m must be positive",
                                    d, h, an.W, an.inner()));
    const std::size_t most = ring_capacity(an, h, d, sag);
    if (most < n) {
        const double vg = g.mean_volume();
        throw CaseError(fmt::format("ring insertion: {} grains (solid fraction {:.4f} below the height {:g} m) do "
                                    "not fit on the ring's insertion lattice; at most {} (solid fraction {:.4f})",
                                    n, static_cast<double>(n) * vg / (an.area() * h), h, most,
                                    static_cast<double>(most) * vg / (an.area() * h)));
    }
    const double a = largest_spacing(d, n, [&](double s) { return make_ring_lattice(an, h, d, s, sag).count(); });
    const RingLattice l = make_ring_lattice(an, h, d, a, sag);
    const std::vector<double> diameters = draw_diameters(g, n, opt.seed);
    Rng rng(opt.seed);
    const std::vector<std::size_t> sites = random_sites(rng, l.count(), n);

    ParticleSet p;
    p.reserve(n);
    const double omega = opt.wall_speed / an.R, sigma = opt.velocity_noise * std::abs(opt.wall_speed);
    for (std::size_t k = 0; k < n; ++k) {
        double x, y, z;
        ring_site(l, sites[k], x, y, z);
        double dx, dy, dz;
        ball_jitter(rng, g.equal() ? l.jitter : 0.5 * (a - diameters[k]), dx, dy, dz);
        x += dx, y += dy, z += dz;
        // (0, w, 0) x (x, y, z) = (w z, 0, -w x): turning with the floor, slower toward the top
        const double w = omega * (1.0 - y / h);
        p.push_back(x, y, z, w * z + sigma * rng.normal(), sigma * rng.normal(), -w * x + sigma * rng.normal(),
                    0.5 * diameters[k]);
    }
    return p;
}

}  // namespace granlub
