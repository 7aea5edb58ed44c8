#include "tables/wall_layer_table.h"

#include <fmt/format.h>

#include "formats/format.h"
#include "results/scope.h"

namespace granlub::postproc {

namespace {

std::optional<double> field(const nlohmann::json& w, const char* key) {
    return w.contains(key) && w[key].is_number() ? std::optional<double>(w[key].get<double>()) : std::nullopt;
}

// "0.26 ± 0.003" of a record's value and its _stderr sibling.
std::string with_error(const nlohmann::json& w, const std::string& key) {
    return value_pm(field(w, key.c_str()), field(w, (key + "_stderr").c_str()), 3);
}

}  // namespace

Table wall_layer_table(const Collection& col) {
    Table t;
    t.header = {"solver", "point", "wall", "grains touching", "slip / U", "carried back by spin / U",
                "contact-point slip / U", "rolling share", "contacts rolling"};
    bool any = false;
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            const nlohmann::json* rec = r.usable() ? run_object(r, "wall_layer") : nullptr;
            if (!rec) continue;
            const std::string cls = r.steady() ? "" : r.state_class();
            for (const auto& [key, label] : {std::pair{"bottom", "floor"}, std::pair{"top", "top"}}) {
                std::vector<Cell> row{{s, ""}, {p->id, ""}, {label, ""}};
                const nlohmann::json* w = rec->contains(key) ? &(*rec)[key] : nullptr;
                const std::string why = w && w->contains("not_measured") ? (*w)["not_measured"].get<std::string>()
                                        : !w && rec->contains("not_measured") ? (*rec)["not_measured"].get<std::string>()
                                                                              : "";
                if (!w || !why.empty()) {
                    row.push_back({fmt::format("not measured ({})", why.empty() ? "no record" : why), cls});
                    row.resize(t.header.size(), {"", cls});
                } else {
                    any = true;
                    row.push_back({num(field(*w, "grains"), 4), cls});
                    row.push_back({with_error(*w, "slip_over_U"), cls});
                    row.push_back({with_error(*w, "rolling_over_U"), cls});
                    row.push_back({with_error(*w, "contact_slip_over_U"), cls});
                    row.push_back({num(field(*w, "rolling_share"), 2), cls});
                    row.push_back({num(field(*w, "rolling_fraction"), 2), cls});
                }
                t.rows.push_back(std::move(row));
            }
        }
    if (!any) t.rows.clear();
    return t;
}

}  // namespace granlub::postproc
