#include "tables/metric_lookup.h"

namespace granlub::postproc {

std::optional<double> scaled(const std::optional<double>& v, double factor) {
    return v ? std::optional(*v * factor) : std::nullopt;
}

const MetricRow* find_row(const std::vector<MetricRow>& rows, const std::string& kind, const std::string& point,
                          const std::string& quantity, const std::string& a, const std::string& b) {
    for (const auto& r : rows)
        if (r.kind == kind && r.point == point && r.quantity == quantity && r.solver_a == a && r.solver_b == b) return &r;
    return nullptr;
}

const char* short_label(const std::string& key) {
    for (const auto& q : kScalarQuantities)
        if (key == q.key) return q.short_label;
    for (const auto& q : kProfileQuantities)
        if (key == q.key) return q.short_label;
    return "";
}

}  // namespace granlub::postproc
