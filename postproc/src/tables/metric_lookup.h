// Small lookups the report's tables share: a metric row by its key, a quantity's short label, an
// optional value scaled.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "statistics/metrics.h"

namespace granlub::postproc {

const MetricRow* find_row(const std::vector<MetricRow>& rows, const std::string& kind, const std::string& point,
                          const std::string& quantity, const std::string& a, const std::string& b);
const char* short_label(const std::string& key);
std::optional<double> scaled(const std::optional<double>& v, double factor);

}  // namespace granlub::postproc
