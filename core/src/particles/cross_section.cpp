// The y x z cross-section of a particle run (see cross_section.h).
#include "granlub/particles/cross_section.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "granlub/statistics/block_average.h"
#include "granlub/particles/coarse_grain.h"
#include "granlub/error.h"

namespace granlub {

CrossSection::CrossSection(std::size_t ny, std::size_t nz, double gap, double width, double length)
    : ny_(ny), nz_(nz), gap_(gap), width_(width), length_(length) {
    if (ny_ == 0 || nz_ == 0 || !(gap_ > 0) || !(width_ > 0) || !(length_ > 0))
        throw Error(fmt::format("cross-section: need cells > 0 over a positive gap, width and length (got {} x {} "
                                "cells, gap {:g}, width {:g}, length {:g})",
                                ny_, nz_, gap_, width_, length_));
}

std::size_t CrossSection::cells_for_grains(double d, double extent) {
    return std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(extent / d)));
}

CrossSection CrossSection::for_grains(double d, double gap, double width, double length) {
    return CrossSection(cells_for_grains(d, gap), cells_for_grains(d, width), gap, width, length);
}

void CrossSection::add_snapshot(const ParticleSet& p, double time) {
    const std::size_t cells = ny_ * nz_, base = volume_.size();
    volume_.resize(base + cells, 0.0);
    momentum_.resize(base + cells, 0.0);
    times_.push_back(time);
    const double hy = gap_ / static_cast<double>(ny_), hz = width_ / static_cast<double>(nz_), z0 = -0.5 * width_;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double r = p.radius[i];
        const double V = 4.0 / 3.0 * std::numbers::pi * r * r * r;
        // the bands the grain reaches (clamped to the grid: a grain sticking out of the gap keeps
        // only its share inside)
        auto band = [r](double c, double lo, double h, std::size_t n) {
            const double a = std::floor((c - r - lo) / h), b = std::floor((c + r - lo) / h);
            const auto first = static_cast<std::size_t>(std::clamp(a, 0.0, static_cast<double>(n - 1)));
            const auto last = static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(n - 1)));
            return std::pair(first, last);
        };
        const auto [ya, yb] = band(p.y[i], 0.0, hy, ny_);
        const auto [za, zb] = band(p.z[i], z0, hz, nz_);
        for (std::size_t k = ya; k <= yb; ++k) {
            const double fy = sphere_slice_volume(p.y[i], r, hy * static_cast<double>(k), hy * static_cast<double>(k + 1)) / V;
            if (fy <= 0) continue;
            for (std::size_t m = za; m <= zb; ++m) {
                const double fz = sphere_slice_volume(p.z[i], r, z0 + hz * static_cast<double>(m), z0 + hz * static_cast<double>(m + 1)) / V;
                const double v = V * fy * fz;
                volume_[base + k * nz_ + m] += v;
                momentum_[base + k * nz_ + m] += v * p.vx[i];
            }
        }
    }
}

Profile CrossSection::table(double U, std::size_t first) const {
    const std::size_t cells = ny_ * nz_, n = snapshots();
    first = std::min(first, n);
    const double cell_volume = gap_ / static_cast<double>(ny_) * width_ / static_cast<double>(nz_) * length_;
    std::vector<double> y(cells), z(cells), nu(cells, 0.0), u(cells, 0.0);
    for (std::size_t k = 0; k < ny_; ++k)
        for (std::size_t m = 0; m < nz_; ++m) {
            const std::size_t c = k * nz_ + m;
            y[c] = (static_cast<double>(k) + 0.5) / static_cast<double>(ny_);
            z[c] = (static_cast<double>(m) + 0.5) / static_cast<double>(nz_) - 0.5;
            double V = 0, P = 0;
            for (std::size_t s = first; s < n; ++s) V += volume_[s * cells + c], P += momentum_[s * cells + c];
            if (n > first) nu[c] = V / (cell_volume * static_cast<double>(n - first));
            if (V > 0) u[c] = P / V / U;
        }
    Profile t;
    t.add("y_over_H", std::move(y)).add("z_over_W", std::move(z)).add("solid_fraction", std::move(nu));
    t.add("u_over_U", std::move(u));
    return t;
}

Profile CrossSection::width_profile(double U, std::size_t first, std::size_t blocks) const {
    const std::size_t cells = ny_ * nz_, n = snapshots();
    first = std::min(first, n);
    const double band_volume = gap_ * width_ / static_cast<double>(nz_) * length_;
    std::vector<double> z(nz_), nu(nz_, 0.0), nu_se(nz_, 0.0), u(nz_, 0.0), u_se(nz_, 0.0);
    std::vector<double> nu_s, u_s;  // per snapshot, reused
    for (std::size_t m = 0; m < nz_; ++m) {
        z[m] = (static_cast<double>(m) + 0.5) / static_cast<double>(nz_) - 0.5;
        nu_s.clear(), u_s.clear();
        double V_all = 0, P_all = 0;
        for (std::size_t s = first; s < n; ++s) {
            double V = 0, P = 0;
            for (std::size_t k = 0; k < ny_; ++k) V += volume_[s * cells + k * nz_ + m], P += momentum_[s * cells + k * nz_ + m];
            nu_s.push_back(V / band_volume);
            if (V > 0) u_s.push_back(P / V / U);
            V_all += V, P_all += P;
        }
        double sum = 0;
        for (double v : nu_s) sum += v;
        if (!nu_s.empty()) nu[m] = sum / static_cast<double>(nu_s.size());
        nu_se[m] = block_average(nu_s, blocks).stderr_;
        if (V_all > 0) u[m] = P_all / V_all / U;
        u_se[m] = block_average(u_s, blocks).stderr_;
    }
    Profile t;
    t.add("z_over_W", std::move(z)).add("solid_fraction", std::move(nu)).add("solid_fraction_stderr", std::move(nu_se));
    t.add("u_over_U", std::move(u)).add("u_over_U_stderr", std::move(u_se));
    return t;
}

}  // namespace granlub
