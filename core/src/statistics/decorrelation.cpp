// The decorrelation time of a series and the blocks it allows (see decorrelation.h).
#include "granlub/statistics/decorrelation.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace granlub {

double integrated_autocorrelation_time(std::span<const double> x) {
    const std::size_t n = x.size();
    if (n < 4) return 1.0;
    double mean = 0;
    for (double v : x) mean += v;
    mean /= static_cast<double>(n);
    std::vector<double> d(n);
    for (std::size_t i = 0; i < n; ++i) d[i] = x[i] - mean;
    auto autocov = [&](std::size_t k) {
        double s = 0;
        for (std::size_t i = 0; i + k < n; ++i) s += d[i] * d[i + k];
        return s / static_cast<double>(n);  // the biased estimator: smaller variance at large lags
    };
    const double c0 = autocov(0);
    if (!(c0 > 0)) return 1.0;
    double tau = 1.0;
    for (std::size_t m = 1; m < n; ++m) {
        tau += 2.0 * autocov(m) / c0;
        if (static_cast<double>(m) >= kSokalWindow * tau) break;
    }
    return std::max(1.0, tau);
}

BlockChoice decorrelated_blocks(std::size_t n, double tau, std::size_t requested) {
    BlockChoice c;
    c.tau_samples = tau;
    const double min_len = kBlockDecorrelationTimes * tau;
    const auto fit = static_cast<std::size_t>(std::floor(static_cast<double>(n) / min_len));
    c.blocks = std::min(requested, fit);
    if (c.blocks < kMinBlocks) {
        c.blocks = std::min(requested, kMinBlocks);
        c.decorrelated = false;
    }
    return c;
}

}  // namespace granlub
