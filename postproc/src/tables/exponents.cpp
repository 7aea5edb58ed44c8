#include "tables/exponents.h"

#include <fmt/format.h>

#include "formats/format.h"
#include "tables/metric_lookup.h"

namespace granlub::postproc {

Table exponent_table(const Collection& col, const std::vector<MetricRow>& metrics) {
    Table ex;
    ex.header = {"solver", "speed group"};
    for (const char* q : kStressOutputs) ex.header.push_back(std::string("n, ") + short_label(q));
    for (const auto& group : speed_groups(col.points)) {
        if (group.points.size() < static_cast<std::size_t>(kMinFitPoints)) continue;  // never fittable
        const std::string g = group.label.empty() ? "all" : group.label;
        for (const auto& s : col.solvers) {
            std::vector<Cell> row{{s, ""}, {g, ""}};
            bool any = false;
            for (const char* q : kStressOutputs) {
                const MetricRow* r = find_row(metrics, "exponent", g, q, s, "");
                any = any || r;
                if (!r)
                    row.push_back({});
                else if (!r->a)
                    row.push_back({r->note, "transient"});
                else
                    row.push_back({fmt::format("{} ({} steady speeds)", value_pm(r->a, r->a_stderr, 3), *r->fit_points), ""});
            }
            if (any) ex.rows.push_back(std::move(row));
        }
    }
    return ex;
}

}  // namespace granlub::postproc
