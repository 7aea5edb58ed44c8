// The random numbers of granlub's grain insertions (particles.cpp, ring_insertion.cpp).
#pragma once
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace granlub {

// Uniform doubles and normals from std::mt19937_64, whose output sequence the standard fixes;
// the std:: distributions are implementation-defined, so they are not used (determinism).
class Rng {
public:
    explicit Rng(std::uint64_t seed) : g_(seed) {}
    double uniform() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }  // [0, 1)
    std::uint64_t below(std::uint64_t n) { return static_cast<std::uint64_t>(uniform() * static_cast<double>(n)); }
    double normal() {  // Box-Muller, one value per call
        double u1 = uniform();
        while (u1 <= 0.0) u1 = uniform();
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

private:
    std::mt19937_64 g_;
};

}  // namespace granlub
