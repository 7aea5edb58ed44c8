// Block averages and their standard errors (see block_average.h).
#include "granlub/statistics/block_average.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace granlub {

BlockEstimate mean_and_stderr(std::span<const double> v) {
    BlockEstimate e;
    if (v.empty()) return e;
    const auto n = static_cast<double>(v.size());
    double m = 0;
    for (double x : v) m += x;
    m /= n;
    e.mean = m;
    e.blocks = v.size();
    if (v.size() >= 2) {
        double s2 = 0;
        for (double x : v) s2 += (x - m) * (x - m);
        s2 /= n - 1.0;
        e.stderr_ = std::sqrt(s2 / n);
    }
    return e;
}

BlockEstimate block_average(std::span<const double> x, std::size_t blocks) {
    if (x.empty() || blocks == 0) return {};
    blocks = std::min(blocks, x.size());
    const std::size_t len = x.size() / blocks;
    std::vector<double> means(blocks, 0.0);
    for (std::size_t b = 0; b < blocks; ++b) {
        for (std::size_t i = 0; i < len; ++i) means[b] += x[b * len + i];
        means[b] /= static_cast<double>(len);
    }
    return mean_and_stderr(means);
}

}  // namespace granlub
