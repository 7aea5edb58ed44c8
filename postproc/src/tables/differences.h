// The differences between solvers, per point and pair (a − b): profiles' RMS and max with the
// noise level, scalars with combined standard errors and z; a pair with a result that is not
// steady is not compared. The first point unfolded, the others one click away.
#pragma once
#include <vector>

#include "formats/report.h"
#include "statistics/metrics.h"

namespace granlub::postproc {

void difference_tables(Report& rep, const Collection& col, const std::vector<MetricRow>& metrics);

}  // namespace granlub::postproc
