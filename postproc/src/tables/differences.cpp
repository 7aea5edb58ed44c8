#include "tables/differences.h"

#include <fmt/format.h>

#include "formats/format.h"
#include "tables/metric_lookup.h"

namespace granlub::postproc {

void difference_tables(Report& rep, const Collection& col, const std::vector<MetricRow>& metrics) {
    bool first_fold = false;  // every point one click away: the summary says who differs
    for (const OperatingPoint* p : col.points) {
        const auto runs = col.usable(p->id);
        if (runs.size() < 2) continue;
        rep.fold(fmt::format("Point {}", p->id), first_fold);
        first_fold = false;
        Table prof;
        prof.header = {"solvers (a − b)"};
        for (const auto& q : kProfileQuantities) prof.header.push_back(std::string(q.short_label) + ": RMS (max at y/H; noise)");
        Table sc;
        sc.header = {"solvers (a − b)"};
        for (const auto& q : kScalarQuantities) sc.header.push_back(q.short_label);
        for (std::size_t i = 0; i < runs.size(); ++i) {
            for (std::size_t j = i + 1; j < runs.size(); ++j) {
                const auto& a = runs[i]->solver;
                const auto& b = runs[j]->solver;
                // A pair with a result that is not steady: no number, the reason instead.
                std::string pair = a + " − " + b, unsteady;
                for (const Run* r : {runs[i], runs[j]})
                    if (!r->steady()) {
                        pair += fmt::format(" ({}: {})", r->solver, r->state_name());
                        if (unsteady.empty()) unsteady = "—, " + r->state_name();
                    }
                std::vector<Cell> prow{{pair, ""}}, srow{{pair, ""}};
                for (const auto& q : kProfileQuantities) {
                    const MetricRow* r = find_row(metrics, "profile", p->id, q.key, a, b);
                    if (!r) {
                        prow.push_back({});
                        continue;
                    }
                    if (!unsteady.empty()) {
                        prow.push_back({unsteady, "transient"});
                        continue;
                    }
                    std::string t = fmt::format("{} (max {} at {}", num(*r->rms, 3), num(*r->max, 3), num(*r->y_at_max, 2));
                    t += r->noise_rms ? fmt::format("; noise {})", num(*r->noise_rms, 2)) : ")";
                    prow.push_back({t, r->noise_rms && *r->rms > 2 * *r->noise_rms ? "significant" : ""});
                }
                for (const auto& q : kScalarQuantities) {
                    const MetricRow* r = find_row(metrics, "scalar", p->id, q.key, a, b);
                    if (!r) {
                        srow.push_back({});
                        continue;
                    }
                    if (!unsteady.empty()) {
                        srow.push_back({unsteady, "transient"});
                        continue;
                    }
                    std::string t = value_pm(r->difference, r->combined_stderr, 3);
                    if (r->z) t += " (" + z_text(*r->z) + ")";
                    srow.push_back({t, r->significant() ? "significant" : ""});
                }
                prof.rows.push_back(std::move(prow));
                sc.rows.push_back(std::move(srow));
            }
        }
        rep.text("Normalised profiles: RMS and max |a − b| over the y/H range both solvers cover; noise = RMS of the "
                 "combined standard error (bold: RMS > 2 × noise).");
        rep.table(std::move(prof));
        rep.text("Scalars: a − b ± combined standard error, stresses in Pa (bold: |z| > 2). A pair with a result "
                 "that is not steady is not compared (“—, transient”): a transient's difference is not a model "
                 "difference.");
        rep.table(std::move(sc));
        rep.end_fold();
    }
}

}  // namespace granlub::postproc
