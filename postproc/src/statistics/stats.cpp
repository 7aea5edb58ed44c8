#include "statistics/stats.h"

#include <algorithm>
#include <cmath>

namespace granlub::postproc {

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq) {
    if (x.empty()) return 0;
    if (xq <= x.front()) return y.front();
    if (xq >= x.back()) return y.back();
    const auto it = std::upper_bound(x.begin(), x.end(), xq);
    const auto i = static_cast<std::size_t>(it - x.begin());
    const double t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + t * (y[i] - y[i - 1]);
}

ProfileDifference profile_difference(const std::vector<double>& ya, const std::vector<double>& a,
                                     const std::vector<double>& se_a, const std::vector<double>& yb,
                                     const std::vector<double>& b, const std::vector<double>& se_b) {
    ProfileDifference d;
    d.lo = std::max(ya.front(), yb.front());
    d.hi = std::min(ya.back(), yb.back());
    double sum2 = 0, noise2 = 0;
    const bool noisy = !se_a.empty() || !se_b.empty();
    for (int k = 0; k < kGridPoints; ++k) {
        const double y = d.lo + (d.hi - d.lo) * k / (kGridPoints - 1);
        const double diff = interpolate(ya, a, y) - interpolate(yb, b, y);
        sum2 += diff * diff;
        if (std::abs(diff) > d.max) d.max = std::abs(diff), d.y_at_max = y;
        if (noisy) {
            const double sa = se_a.empty() ? 0 : interpolate(ya, se_a, y);
            const double sb = se_b.empty() ? 0 : interpolate(yb, se_b, y);
            noise2 += sa * sa + sb * sb;
        }
    }
    d.rms = std::sqrt(sum2 / kGridPoints);
    if (noisy) d.noise_rms = std::sqrt(noise2 / kGridPoints);
    return d;
}

std::optional<double> combined_stderr(std::optional<double> a, std::optional<double> b) {
    if (!a && !b) return std::nullopt;
    const double sa = a.value_or(0), sb = b.value_or(0);
    return std::sqrt(sa * sa + sb * sb);
}

std::optional<PowerFit> power_fit(const std::vector<double>& x, const std::vector<double>& y,
                                  const std::vector<std::optional<double>>& se_y) {
    std::vector<double> lx, ly, w;
    bool weighted = true;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i]))) continue;
        lx.push_back(std::log(x[i]));
        ly.push_back(std::log(y[i]));
        const double rel = (i < se_y.size() && se_y[i]) ? *se_y[i] / y[i] : 0.0;  // se of log y
        if (!(rel > 0)) weighted = false;
        w.push_back(rel > 0 ? 1 / (rel * rel) : 1.0);
    }
    const std::size_t n = lx.size();
    if (n < 2) return std::nullopt;
    if (!weighted) std::fill(w.begin(), w.end(), 1.0);
    double s = 0, sx = 0, sy = 0;
    for (std::size_t i = 0; i < n; ++i) s += w[i], sx += w[i] * lx[i], sy += w[i] * ly[i];
    const double mx = sx / s, my = sy / s;
    double sxx = 0, sxy = 0;
    for (std::size_t i = 0; i < n; ++i) sxx += w[i] * (lx[i] - mx) * (lx[i] - mx), sxy += w[i] * (lx[i] - mx) * (ly[i] - my);
    if (!(sxx > 0)) return std::nullopt;  // all at one speed
    PowerFit f;
    f.points = static_cast<int>(n);
    f.weighted = weighted;
    f.exponent = sxy / sxx;
    f.prefactor = std::exp(my - f.exponent * mx);
    double chi2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double r = ly[i] - (my + f.exponent * (lx[i] - mx));
        chi2 += w[i] * r * r;
    }
    const double dof = static_cast<double>(n) - 2;
    if (weighted) {
        const double birge = dof > 0 ? std::max(1.0, chi2 / dof) : 1.0;
        f.exponent_stderr = std::sqrt(birge / sxx);
    } else if (dof > 0) {
        f.exponent_stderr = std::sqrt(chi2 / dof / sxx);
    }
    return f;
}

}  // namespace granlub::postproc
