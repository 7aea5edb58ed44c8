// The one value +- standard error of granlub's statistical solvers, by block averaging
// (Flyvbjerg & Petersen 1989, J. Chem. Phys. 91:461): a series is cut into contiguous blocks
// long enough to be independent, and the standard error of the mean is the standard deviation of
// the block values (n - 1 in the denominator) over sqrt(number of blocks).
#pragma once
#include <cstddef>
#include <span>

namespace granlub {

struct BlockEstimate {
    double mean = 0;
    double stderr_ = 0;  // 0 for fewer than 2 blocks
    std::size_t blocks = 0;
};

// Mean and standard error of the mean of independent block values.
BlockEstimate mean_and_stderr(std::span<const double> block_values);

// Mean and standard error of a series from `blocks` contiguous blocks (the last samples that do
// not fill a block are dropped).
BlockEstimate block_average(std::span<const double> series, std::size_t blocks);

}  // namespace granlub
