// `granlub continuum-fit CASE --table FILE` (command.h): the fit of rheology_fit.h on a table read by core's one
// reader, printed, and written as a TOML fragment with its provenance.
#include <cstdio>
#include <optional>

#include <fmt/format.h>

#include "granlub/continuum/command.h"
#include "granlub/continuum/rheology_fit.h"
#include "granlub/error.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"

namespace granlub::continuum {

namespace {

std::string command_line(const Case& c, const FitCommand& o) {
    std::string s = fmt::format("granlub continuum-fit {} --table {}", c.file.string(), o.table.string());
    if (!o.free.empty()) s += fmt::format(" --free {}", fmt::join(o.free, ","));
    if (o.temperature) s += " --temperature";
    if (!o.bulk_case.empty()) s += fmt::format(" --bulk-case {}", o.bulk_case.string());
    return s;
}

std::string closures_text(const Settings& s) {
    std::string t = fmt::format("closures {}, g0 {} (nu_max {}), correlation_length {}", s.closures_name, s.g0_name,
                                s.closures->numax(), s.correlation_length_name);
    t += s.contact.active() ? ", contact_stress johnson_jackson" : ", contact_stress none";
    return t;
}

// The bulk case of a wall fit: --bulk-case, else the path in the table's provenance line `case NAME (PATH), ...`.
std::filesystem::path bulk_case_path(const FitCommand& o, const BulkRows& table) {
    if (!o.bulk_case.empty()) return o.bulk_case;
    for (const auto& l : table.provenance) {
        const auto open = l.find(" ("), close = l.find(')');
        if (l.starts_with("case ") && open != std::string::npos && close != std::string::npos && close > open + 2)
            return l.substr(open + 2, close - open - 2);
    }
    throw CaseError(fmt::format("{}: no provenance line '# case NAME (PATH)' names the bulk case whose walls the table "
                                "measured, which a wall fit solves (allowed: --bulk-case DIR)",
                                o.table.string()));
}

bool frees_a_wall_key(const std::vector<std::string>& free) {
    for (const auto& k : free)
        if (k == "slip_dissipation") return true;
    return false;
}

}  // namespace

int run_fit(const Case& c, const FitCommand& o) {
    const Settings s = resolve_settings(c);
    std::string bytes;
    BulkRows table;
    try {  // the table is the user's input: its faults are bad input (exit 2), named by the reader
        bytes = read_file(o.table);
        table = parse_bulk_table(bytes, o.table.string());
    } catch (const CaseError&) {
        throw;
    } catch (const Error& e) {
        throw CaseError(e.what());
    }
    const std::vector<BulkRow> answers = table.answers();
    fmt::print("continuum-fit: case {} ({}), {}\n", c.name, c.file.string(), closures_text(s));
    fmt::print("table {}: {} row(s), {} answer(s) (status = steady and core_dt_check = converged)\n", o.table.string(),
               table.rows.size(), answers.size());
    for (const BulkRow& r : table.rows)
        if (!is_answer(r))
            fmt::print("  left out: {} (status {}, core_dt_check {}): a labelled measurement, not a point of the fit\n",
                       r.point, r.status, r.core_dt_check);
    std::fflush(stdout);
    FitOptions fo;
    fo.free = o.free;
    fo.temperature = o.temperature;
    fo.missing_wall_columns = table.missing_wall_columns;
    std::optional<Case> bulk;
    if (frees_a_wall_key(o.free) && table.missing_wall_columns.empty()) {
        const std::filesystem::path path = bulk_case_path(o, table);
        bulk = bulk_case_for(load_case(path, *c.schema), c);
        fmt::print("the wall constants' model: the bulk case {} ({}) solved in 1-D with this case's [continuum]\n",
                   bulk->name, path.string());
        std::fflush(stdout);  // before a refusal on stderr
        fo.bulk = &*bulk;
    }
    const FitResult r = fit_bulk_rheology(s, answers, fo, o.table.string());
    fmt::print("\n{}", fit_report(r));

    std::vector<std::string> ids;
    for (const BulkRow& a : answers) ids.push_back(a.point);
    std::vector<std::string> prov = {
        "The closures' constants fitted on a bulk-rheology table (continuum/README.md, \"Fitting the closures' "
        "constants\"):",
        "paste into the [continuum] section of a case with the same closures; its other constants as the case has them.",
        fmt::format("by granlub {}: {}", version(), command_line(c, o)),
        fmt::format("case {} ({}), case file hash {}; {}", c.name, c.file.string(), c.file_hash, closures_text(s)),
        fmt::format("table {}, hash {}, {} row(s), the {} answer(s) fitted: {}", o.table.string(), hash_hex(bytes),
                    table.rows.size(), answers.size(), fmt::join(ids, ", ")),
        fmt::format("fitted on {}{}, each residual in units of its row's error",
                    !r.core ? "" : o.temperature ? "mu, nu and T/(d gdot)^2" : "mu and nu (T/(d gdot)^2 not)",
                    !r.walls ? "" : fmt::format("{}the walls' slips and near-wall T of the bulk case {} (its 1-D solve)",
                                                r.core ? " and " : "", fo.bulk->file.string()))};
    for (const auto& l : table.provenance)
        if (l.starts_with("case ") || l.starts_with("written ") || l.starts_with("from "))
            prov.push_back("the table's " + l);
    const std::filesystem::path out = o.out.empty() ? c.dir / kFitFile : o.out;
    write_file_atomic(out, fit_fragment(r, prov));
    fmt::print("wrote {}\n", out.string());
    return 0;
}

}  // namespace granlub::continuum
