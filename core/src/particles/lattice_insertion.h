// The steps both lattice insertions share (particles.cpp: the slice's FCC sites;
// ring_insertion.cpp: the ring's circles): the largest site spacing that still gives n sites, a
// random subset of the sites, and the jitter of each grain about its site. Same seed, same grains.
#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

#include "rng.h"

namespace granlub {

// The largest spacing a in [d, 1000 d] with count(a) >= n, by bisection: count(a) does not
// increase with a. count(d) >= n is the caller's to check.
template <class Count>
double largest_spacing(double d, std::size_t n, Count count) {
    double lo = d, hi = 2.0 * d;
    while (count(hi) >= n && hi < 1e3 * d) hi *= 2.0;
    for (int it = 0; it < 100; ++it) {
        const double mid = 0.5 * (lo + hi);
        (count(mid) >= n ? lo : hi) = mid;
    }
    return lo;
}

// n of the sites 0 .. count-1 at random (the first n of a Fisher-Yates shuffle), sorted for a
// tidy file.
inline std::vector<std::size_t> random_sites(Rng& rng, std::size_t count, std::size_t n) {
    std::vector<std::size_t> sites(count);
    for (std::size_t s = 0; s < sites.size(); ++s) sites[s] = s;
    for (std::size_t s = 0; s < n; ++s) std::swap(sites[s], sites[s + rng.below(sites.size() - s)]);
    sites.resize(n);
    std::sort(sites.begin(), sites.end());
    return sites;
}

// A displacement uniform in the ball of radius r (rejection sampling).
inline void ball_jitter(Rng& rng, double r, double& dx, double& dy, double& dz) {
    do {
        dx = 2.0 * rng.uniform() - 1.0;
        dy = 2.0 * rng.uniform() - 1.0;
        dz = 2.0 * rng.uniform() - 1.0;
    } while (dx * dx + dy * dy + dz * dz > 1.0);
    dx *= r, dy *= r, dz *= r;
}

}  // namespace granlub
