// Grain sizes (grain_sizes.h).
#include "granlub/grain_sizes.h"

#include <cmath>
#include <numbers>

#include "rng.h"

namespace granlub {

double GrainSizes::half_width() const { return std::sqrt(3.0) * spread; }
double GrainSizes::min() const { return mean * (1.0 - half_width()); }
double GrainSizes::max() const { return mean * (1.0 + half_width()); }
double GrainSizes::mean_volume() const {
    return std::numbers::pi * mean * mean * mean * (1.0 + 3.0 * spread * spread) / 6.0;  // E[(1 + a u)^3], u ~ U(-1, 1)
}

std::vector<double> draw_diameters(const GrainSizes& g, std::size_t n, std::uint64_t seed) {
    std::vector<double> d(n, g.mean);
    if (g.equal()) return d;
    // a stream apart from the insertion's (seed): the golden-ratio constant decorrelates the two
    Rng rng(seed ^ 0x9E3779B97F4A7C15ULL);
    const double a = g.half_width();
    for (double& v : d) v = g.mean * (1.0 + a * (2.0 * rng.uniform() - 1.0));
    return d;
}

}  // namespace granlub
