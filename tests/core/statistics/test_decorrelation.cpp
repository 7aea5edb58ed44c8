// The decorrelation time and the blocks it allows (granlub/statistics/decorrelation.h), on AR(1)
// series x_i = phi x_(i-1) + e_i, whose integrated autocorrelation time is (1 + phi)/(1 - phi)
// exactly: the block error of one run must agree with the scatter of the means of independent runs.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "granlub/statistics/block_average.h"
#include "granlub/statistics/decorrelation.h"

using namespace granlub;

namespace {

std::vector<double> ar1(double phi, std::size_t n, std::mt19937_64& rng) {
    std::normal_distribution<double> e(0.0, 1.0);
    std::vector<double> x(n);
    double v = e(rng) / std::sqrt(1.0 - phi * phi);  // start in the stationary distribution
    for (double& xi : x) xi = v = phi * v + e(rng);
    return x;
}

double tau_ar1(double phi) { return (1.0 + phi) / (1.0 - phi); }

}  // namespace

BOOST_AUTO_TEST_SUITE(decorrelation)

BOOST_AUTO_TEST_CASE(integrated_autocorrelation_time_of_ar1) {
    std::mt19937_64 rng(7);
    for (double phi : {0.0, 0.5, 0.9, 0.97}) {
        const double tau = integrated_autocorrelation_time(ar1(phi, 200000, rng));
        BOOST_TEST_MESSAGE("phi " << phi << ": tau_int " << tau << " (exact " << tau_ar1(phi) << ")");
        BOOST_TEST(std::abs(tau - tau_ar1(phi)) < 0.1 * tau_ar1(phi) + 0.05, phi << ": " << tau);
    }
    // anticorrelated and degenerate series: never below one sample
    BOOST_TEST(integrated_autocorrelation_time(std::vector<double>{1, -1, 1, -1, 1, -1, 1, -1}) == 1.0);
    BOOST_TEST(integrated_autocorrelation_time(std::vector<double>(50, 3.0)) == 1.0);
    BOOST_TEST(integrated_autocorrelation_time(std::vector<double>{1, 2}) == 1.0);
}

BOOST_AUTO_TEST_CASE(blocks_are_at_least_the_decorrelation_times_long) {
    BlockChoice b = decorrelated_blocks(1000, 10.0, 10);  // blocks of 100 >= 30: as requested
    BOOST_TEST(b.blocks == 10u);
    BOOST_TEST(b.decorrelated);
    b = decorrelated_blocks(1000, 50.0, 10);  // at least 150 samples a block: 6
    BOOST_TEST(b.blocks == 6u);
    BOOST_TEST(b.decorrelated);
    b = decorrelated_blocks(100, 50.0, 10);  // a window of two decorrelation times: two short blocks
    BOOST_TEST(b.blocks == kMinBlocks);
    BOOST_TEST(!b.decorrelated);
}

// The test of item 3 of issue 50: 400 independent runs of an AR(1) series 15 decorrelation times
// long (tau_int = 39 samples, a wall-stress series of the length and memory measured on YADE's
// warm starts). The block error of each run, with the blocks decorrelation.h allows, must agree
// with the standard deviation of the runs' means within 15 % (the sampling error of both over 400
// runs is about 4 %); with ten blocks of 1.5 tau_int, the rule before, it was low.
BOOST_AUTO_TEST_CASE(block_error_agrees_with_the_scatter_of_independent_runs) {
    const double phi = 0.95;
    const std::size_t n = 600, runs = 400;
    std::mt19937_64 rng(11);
    double sum = 0, sum2 = 0, se2_new = 0, se2_old = 0;
    std::size_t blocks_new = 0;
    for (std::size_t r = 0; r < runs; ++r) {
        const std::vector<double> x = ar1(phi, n, rng);
        const BlockChoice b = decorrelated_blocks(n, integrated_autocorrelation_time(x), 10);
        const BlockEstimate e = block_average(x, b.blocks), old = block_average(x, 10);
        sum += e.mean, sum2 += e.mean * e.mean;
        se2_new += e.stderr_ * e.stderr_, se2_old += old.stderr_ * old.stderr_;
        blocks_new += b.blocks;
    }
    const double m = sum / runs;
    const double scatter = std::sqrt((sum2 / runs - m * m) * runs / (runs - 1.0));
    const double ratio_new = std::sqrt(se2_new / runs) / scatter, ratio_old = std::sqrt(se2_old / runs) / scatter;
    BOOST_TEST_MESSAGE("block error / scatter of 400 runs: " << ratio_new << " with "
                                                             << static_cast<double>(blocks_new) / runs
                                                             << " blocks on average, " << ratio_old
                                                             << " with 10 blocks");
    BOOST_TEST(std::abs(ratio_new - 1.0) < 0.15, ratio_new);
    BOOST_TEST(ratio_old < ratio_new);
}

BOOST_AUTO_TEST_SUITE_END()
