// Coarse-graining across the gap: slice volumes and profiles (see coarse_grain.h).
#include "granlub/particles/coarse_grain.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

double sphere_slice_volume(double yc, double r, double a, double b) {
    const double lo = std::max(a, yc - r) - yc;
    const double hi = std::min(b, yc + r) - yc;
    if (!(hi > lo)) return 0.0;
    // pi * integral_lo^hi (r^2 - t^2) dt
    return std::numbers::pi * (r * r * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3.0);
}

SliceCoarseGrainer::SliceCoarseGrainer(Stations s, double cross_area) : st_(s), area_(cross_area) {
    if (st_.n == 0 || !(st_.hi > st_.lo) || !(area_ > 0))
        throw Error(fmt::format("coarse-graining: need stations > 0 across [lo, hi] with hi > lo and a positive area "
                                "(got {} stations over [{:g}, {:g}], area {:g})",
                                st_.n, st_.lo, st_.hi, area_));
}

void SliceCoarseGrainer::add_snapshot(const ParticleSet& p, double time) {
    const std::size_t base = sums_.size();
    sums_.resize(base + st_.n * kSums, 0.0);
    double* s = sums_.data() + base;
    const double w = st_.width();
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double yc = p.y[i], r = p.radius[i];
        const double vx = p.vx[i], vy = p.vy[i], vz = p.vz[i];
        // only the slabs the sphere touches
        const double f0 = std::floor((yc - r - st_.lo) / w);
        const double f1 = std::floor((yc + r - st_.lo) / w);
        const auto k0 = static_cast<std::ptrdiff_t>(std::max(0.0, f0));
        const auto k1 = static_cast<std::ptrdiff_t>(std::min(static_cast<double>(st_.n) - 1.0, f1));
        for (std::ptrdiff_t k = k0; k <= k1; ++k) {
            const double a = st_.lo + static_cast<double>(k) * w;
            const double v = sphere_slice_volume(yc, r, a, a + w);
            if (v <= 0) continue;
            double* q = s + static_cast<std::size_t>(k) * kSums;
            q[0] += v;
            q[1] += v * vx;
            q[2] += v * vy;
            q[3] += v * vz;
            q[4] += v * vx * vx;
            q[5] += v * vy * vy;
            q[6] += v * vz * vz;
        }
    }
    times_.push_back(time);
}

SliceCoarseGrainer::Fields SliceCoarseGrainer::fields(std::size_t first, std::size_t last) const {
    last = std::min(last, snapshots());
    Fields f;
    const std::size_t n = st_.n;
    for (auto* v : {&f.nu, &f.ux, &f.uy, &f.uz, &f.T}) v->assign(n, 0.0);
    if (last <= first) return f;
    std::vector<double> acc(n * kSums, 0.0);
    for (std::size_t t = first; t < last; ++t) {
        const double* s = sums_.data() + t * n * kSums;
        for (std::size_t j = 0; j < n * kSums; ++j) acc[j] += s[j];
    }
    const double slab = st_.width() * area_ * static_cast<double>(last - first);
    for (std::size_t k = 0; k < n; ++k) {
        const double* q = acc.data() + k * kSums;
        f.nu[k] = q[0] / slab;
        if (q[0] > 0) {  // an empty station keeps u = T = 0 (no grain ever touched it)
            f.ux[k] = q[1] / q[0];
            f.uy[k] = q[2] / q[0];
            f.uz[k] = q[3] / q[0];
            const double c2 = (q[4] / q[0] - f.ux[k] * f.ux[k]) + (q[5] / q[0] - f.uy[k] * f.uy[k]) +
                              (q[6] / q[0] - f.uz[k] * f.uz[k]);
            f.T[k] = std::max(0.0, c2 / 3.0);
        }
    }
    return f;
}

double SliceCoarseGrainer::mean_solid_fraction(std::size_t first, std::size_t last) const {
    const auto f = fields(first, last);
    double m = 0;
    for (double v : f.nu) m += v;
    return m / static_cast<double>(st_.n);
}

Profile SliceCoarseGrainer::profile(double U, std::size_t first, std::size_t blocks) const {
    if (!(U > 0)) throw Error(fmt::format("coarse-graining: the velocity scale U = {:g} must be positive", U));
    const std::size_t n = st_.n, last = snapshots();
    if (first >= last)
        throw Error(fmt::format("coarse-graining: no snapshots to average (first {} of {})", first, last));
    const Fields all = fields(first, last);
    const std::size_t count = last - first;
    const std::size_t nb = std::min(blocks, count);
    std::vector<Fields> per;
    if (nb >= 2) {
        const std::size_t len = count / nb;
        for (std::size_t b = 0; b < nb; ++b) per.push_back(fields(first + b * len, first + (b + 1) * len));
    }
    auto stderr_of = [&](std::vector<double> Fields::*member, double scale) {
        std::vector<double> e(n, 0.0), values(per.size());
        if (per.size() < 2) return e;
        for (std::size_t k = 0; k < n; ++k) {
            for (std::size_t b = 0; b < per.size(); ++b) values[b] = (per[b].*member)[k];
            e[k] = mean_and_stderr(values).stderr_ / scale;
        }
        return e;
    };
    auto scaled = [&](const std::vector<double>& v, double scale) {
        std::vector<double> o(v);
        for (double& x : o) x /= scale;
        return o;
    };
    const double H = st_.hi;
    std::vector<double> y(n);
    for (std::size_t k = 0; k < n; ++k) y[k] = st_.centre(k) / H;
    Profile p;
    p.add("y_over_H", y);
    p.add("u_over_U", scaled(all.ux, U));
    p.add("solid_fraction", all.nu);
    p.add("temperature_over_U2", scaled(all.T, U * U));
    p.add("u_over_U_stderr", stderr_of(&Fields::ux, U));
    p.add("solid_fraction_stderr", stderr_of(&Fields::nu, 1.0));
    p.add("temperature_over_U2_stderr", stderr_of(&Fields::T, U * U));
    p.add("v_over_U", scaled(all.uy, U));
    p.add("w_over_U", scaled(all.uz, U));
    return p;
}

}  // namespace granlub
