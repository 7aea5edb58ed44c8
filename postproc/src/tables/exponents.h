// The fitted wall-stress–speed exponents n (σ = c Uⁿ) per solver and speed group, from the
// metrics' "exponent" rows; a group never fittable (fewer than kMinFitPoints speeds) has no row.
#pragma once
#include <vector>

#include "formats/report.h"
#include "statistics/metrics.h"

namespace granlub::postproc {

Table exponent_table(const Collection& col, const std::vector<MetricRow>& metrics);

}  // namespace granlub::postproc
