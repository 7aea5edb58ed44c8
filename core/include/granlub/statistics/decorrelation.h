// How long a series stays correlated, and how many blocks its standard error may then use: the
// block error of block_average.h holds only for blocks much longer than the series' decorrelation
// time (Flyvbjerg & Petersen 1989, J. Chem. Phys. 91:461). Shared by both particle engines'
// reduction (particle_reduction.h), so that their wall-stress errors are comparable.
//
// The decorrelation time is the integrated autocorrelation time tau_int = 1 + 2 sum_k rho(k), in
// samples: the variance of the mean of n samples is var(x) tau_int / n. It is summed over lags
// k <= M with Sokal's automatic window, the smallest M >= kSokalWindow tau_int(M) (Sokal 1997,
// "Monte Carlo methods in statistical mechanics", in Functional Integration, Plenum, sec. 3;
// Madras & Sokal 1988, J. Stat. Phys. 50:109).
#pragma once
#include <cstddef>
#include <span>

namespace granlub {

inline constexpr double kSokalWindow = 5.0;  // Sokal 1997 sec. 3: c ~ 4-6 for near-exponential decay
// A block is at least this many decorrelation times long [ASSUMPTION] ours: measured on AR(1)
// series (tests/core/test_decorrelation.cpp, 2026-11-27), blocks of one tau_int leave the block
// error 15-40 % low on windows of 6-20 tau_int; three keep it within about 5 % of the scatter of
// independent runs.
inline constexpr double kBlockDecorrelationTimes = 3.0;
inline constexpr std::size_t kMinBlocks = 2;  // a standard error needs two blocks

// tau_int in samples (>= 1; 1 for a series shorter than 4 samples or without variance).
double integrated_autocorrelation_time(std::span<const double> series);

// The blocks a series of n samples with decorrelation time tau (samples) is cut into: at most
// `requested`, each at least kBlockDecorrelationTimes tau long, never fewer than kMinBlocks (then
// the blocks are shorter than that and `decorrelated` is false: the error is a lower bound).
struct BlockChoice {
    std::size_t blocks = 0;
    double tau_samples = 1;
    bool decorrelated = true;
};
BlockChoice decorrelated_blocks(std::size_t n, double tau_samples, std::size_t requested);

}  // namespace granlub
