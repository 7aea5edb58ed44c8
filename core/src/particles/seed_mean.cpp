// One quantity over a point's seeds (seed_mean.h).
#include "granlub/particles/seed_mean.h"

#include <algorithm>
#include <cmath>

namespace granlub {

SeedMean seed_mean(const std::vector<double>& v, const std::vector<std::optional<double>>& se) {
    const auto n = static_cast<double>(v.size());
    SeedMean p;
    for (double x : v) p.mean += x;
    p.mean /= n;
    double ss = 0;
    for (double x : v) ss += (x - p.mean) * (x - p.mean);
    if (v.size() > 1) p.seed_stderr = std::sqrt(ss / (n - 1) / n);
    if (std::all_of(se.begin(), se.end(), [](const auto& e) { return e.has_value(); })) {
        double s2 = 0;
        for (const auto& e : se) s2 += *e * *e;
        p.block_stderr = std::sqrt(s2) / n;
    }
    return p;
}

}  // namespace granlub
