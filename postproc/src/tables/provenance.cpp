#include "tables/provenance.h"

#include <algorithm>
#include <map>
#include <set>

#include <fmt/format.h>

#include "formats/format.h"

namespace granlub::postproc {
namespace {

// "key" -> text of every leaf of a JSON object, nested keys joined by '.'.
void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
    if (j.is_object()) {
        for (const auto& [k, v] : j.items()) flatten(v, prefix.empty() ? k : prefix + "." + k, out);
        return;
    }
    out[prefix] = j.is_string() ? j.get<std::string>() : j.dump();
}

}  // namespace

void provenance_part(Report& rep, const Collection& col) {
    Table prov;
    prov.header = {"solver", "point", "granlub", "written (UTC)", "seed", "case hash", "inputs hash"};
    for (const OperatingPoint* p : col.points)
        for (const auto& s : col.solvers) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) continue;
            const Provenance& pv = r.summary->provenance;
            prov.rows.push_back({{s, ""},
                                 {p->id, ""},
                                 {pv.version, ""},
                                 {pv.utc_time, ""},
                                 {pv.seed ? std::to_string(*pv.seed) : "—", ""},
                                 {pv.case_hash, "code"},
                                 {pv.inputs_hash, "code"}});
        }
    rep.table(std::move(prov));
    rep.text("Each run's full record (inputs, settings, run diagnostics) is its summary.json: "
             "results/<solver>/<point>/summary.json.");
    for (const auto& s : col.solvers) {
        std::vector<std::pair<std::string, std::map<std::string, std::string>>> per_point;
        for (const OperatingPoint* p : col.points)
            if (const Run& r = col.run(s, p->id); r.usable()) {
                std::map<std::string, std::string> kv;
                flatten(r.summary->provenance.settings, "", kv);
                per_point.emplace_back(p->id, std::move(kv));
            }
        if (per_point.empty()) continue;
        std::set<std::string> keys;
        for (const auto& [id, kv] : per_point)
            for (const auto& [k, v] : kv) keys.insert(k);
        Table t;
        t.header = {"setting", "value"};
        for (const auto& k : keys) {
            auto value = [&](const std::map<std::string, std::string>& kv) {
                const auto it = kv.find(k);
                return it == kv.end() ? std::string("—") : it->second;
            };
            const std::string v0 = value(per_point.front().second);
            const bool same = std::all_of(per_point.begin(), per_point.end(),
                                          [&](const auto& pp) { return value(pp.second) == v0; });
            std::string v = v0;
            if (!same) {
                v.clear();
                for (const auto& [id, kv] : per_point) v += (v.empty() ? "" : "; ") + id + ": " + value(kv);
            }
            t.rows.push_back({{k, "code"}, {v, ""}});
        }
        rep.fold(fmt::format("Settings of {} ({} keys)", s, keys.size()));
        rep.table(std::move(t));
        rep.end_fold();
    }
}

}  // namespace granlub::postproc
