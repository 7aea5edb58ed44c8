// One quantity over a point's seeds (seeds.h): what the seeds' pool (seed_pool.h) and the bulk table's
// pooled cores (bulk_rheology.h) both take from their members.
#pragma once
#include <optional>
#include <vector>

namespace granlub {

struct SeedMean {
    double mean = 0;
    double seed_stderr = 0;               // the sample standard deviation over the members / sqrt(n); 0 for one
    std::optional<double> block_stderr;   // the members' own errors combined, sqrt(sum se_i^2) / n, when each has one
};

// values[i] and errors[i] of member i; values must not be empty.
SeedMean seed_mean(const std::vector<double>& values, const std::vector<std::optional<double>>& errors);

}  // namespace granlub
