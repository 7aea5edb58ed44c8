// The ring's frames and walls (annulus.h).
#include "granlub/particles/annulus.h"

#include <cmath>
#include <numbers>

#include "granlub/case/case.h"

namespace granlub {

namespace {
constexpr double kPi = std::numbers::pi;
}

double Annulus::area() const { return 2.0 * kPi * R * W; }

double Annulus::polar_moment() const {
    const double ri = inner(), ro = outer();
    return 2.0 * kPi * (ro * ro * ro - ri * ri * ri) / 3.0;
}

Annulus annulus(const Case& c) { return {c.cell.annulus_radius, c.cell.width}; }

ParticleBox ring_slice_box(const Case& c) {
    const Annulus a = annulus(c);
    return {2.0 * kPi * a.R, c.cell.gap, a.W, false};
}

void to_slice(const ParticleSet& ring, const Annulus& a, ParticleSet& s) {
    const std::size_t n = ring.size();
    s.clear();
    s.reserve(n);
    const double R = a.R, rm2 = R * R + 0.25 * a.W * a.W;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = ring.x[i], z = ring.z[i], vx = ring.vx[i], vz = ring.vz[i];
        const double r2 = x * x + z * z, r = std::sqrt(r2);
        double theta = std::atan2(-z, x);
        if (theta < 0) theta += 2.0 * kPi;
        const double v_theta = (vx * z - vz * x) / r;  // along e_theta = (-sin, 0, -cos) theta
        const double v_r = (vx * x + vz * z) / r;
        s.push_back(R * theta, ring.y[i], (rm2 - r2) / (2.0 * R), v_theta * R / r, ring.vy[i], -v_r * r / R,
                    ring.radius[i]);
    }
}

ParticleBox ring_contact_box(const Annulus& a, double gap, double d) {
    return {4.0 * (a.outer() + d), gap, 2.0 * (a.outer() + d), false};
}

WallForceSeries ring_wall_forces(const RingWallLoads& w, const Annulus& a) {
    const double L = 2.0 * kPi * a.R, k_disc = a.area() / a.polar_moment();
    auto scaled = [](const std::vector<double>& v, double k) {
        std::vector<double> o(v);
        for (double& x : o) x *= k;
        return o;
    };
    WallForceSeries f;
    f.step = w.step;
    // the grains push the floor down (-y) and the top up: the slice's normal forces as they are
    f.fy_bottom = w.fy_floor;
    f.fy_top = w.fy_top;
    // torques about +y oppose the floor's turning (< 0) and drag the top along (> 0): the slice's
    // drags along -x and +x
    f.fx_bottom = scaled(w.t_floor, k_disc);
    f.fx_top = scaled(w.t_top, k_disc);
    // fz_bottom, fz_top stay empty: the discs' radial loads cancel around the ring and are not recorded
    f.fx_side1 = scaled(w.t_outer, L / (2.0 * kPi * a.outer() * a.outer()));
    f.fx_side2 = scaled(w.t_inner, L / (2.0 * kPi * a.inner() * a.inner()));
    f.fy_side1 = w.fy_outer;
    f.fy_side2 = w.fy_inner;
    return f;
}

BlockEstimate ring_torque_balance(const RingWallLoads& w, std::size_t first, std::size_t blocks) {
    const std::size_t n = w.step.size(), from = std::min(first, n);
    std::vector<double> sum(n - from), top(n - from);
    for (std::size_t i = from; i < n; ++i) {
        sum[i - from] = w.t_floor[i] + w.t_top[i] + w.t_outer[i] + w.t_inner[i];
        top[i - from] = w.t_top[i];
    }
    const BlockEstimate s = block_average(sum, blocks), t = block_average(top, blocks);
    return {s.mean / t.mean, s.stderr_ / std::abs(t.mean)};
}

}  // namespace granlub
