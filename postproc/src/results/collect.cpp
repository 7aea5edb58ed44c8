#include "results/collect.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub::postproc {
namespace {

// Profile column behind a compared quantity, and whether it is divided by nu_max.
std::pair<const char*, bool> source_column(const std::string& quantity) {
    if (quantity == "u_over_U") return {"u_over_U", false};
    if (quantity == "nu_over_numax") return {"solid_fraction", true};
    if (quantity == "T_over_U2") return {"temperature_over_U2", false};
    throw Error("internal: unknown profile quantity '" + quantity + "'");
}

}  // namespace

std::vector<double> Run::column(const std::string& quantity) const {
    const auto [name, per_max] = source_column(quantity);
    std::vector<double> v = profile->column(name);
    if (per_max)
        for (double& x : v) x /= nu_max();
    return v;
}

std::vector<double> Run::column_stderr(const std::string& quantity) const {
    const auto [name, per_max] = source_column(quantity);
    const std::string se = std::string(name) + "_stderr";
    if (!profile->has(se)) return {};
    std::vector<double> v = profile->column(se);
    if (per_max)
        for (double& x : v) x /= nu_max();
    return v;
}

std::optional<double> Run::scalar(const std::string& name) const {
    if (!usable()) return std::nullopt;
    if (name == "nu_bar_over_numax") return summary->value("mean_solid_fraction") / nu_max();
    if (name == "slip_bottom_over_U" || name == "slip_top_over_U") {
        const auto base = name.substr(0, name.size() - 7);
        return point->speed > 0 ? std::optional(summary->value(base) / point->speed) : std::nullopt;
    }
    const auto it = summary->outputs.find(name);
    return it == summary->outputs.end() ? std::nullopt : std::optional(it->second.value);
}

std::string Run::wall_surface(bool bottom) const {
    if (!usable()) return "";
    const auto& run = summary->run;
    const char* side = bottom ? "bottom" : "top";
    if (!run.is_object() || !run.contains("walls") || !run["walls"].contains(side)) return "";
    return run["walls"][side].value("surface", std::string());
}

std::optional<double> Run::wall_roughness(bool bottom) const {
    const std::string surface = wall_surface(bottom);
    if (surface == "plane") return std::nullopt;
    if (surface == "bumps") return summary->run["walls"][bottom ? "bottom" : "top"].value("roughness_built", 0.0);
    return bottom ? point->bottom.roughness : point->top.roughness;
}

std::optional<double> Run::scalar_stderr(const std::string& name) const {
    return scaled_error(name, [](const Scalar& s) { return s.stderr_; });
}

std::optional<double> Run::scalar_dt_error(const std::string& name) const {
    return scaled_error(name, [](const Scalar& s) { return s.dt_error; });
}

std::optional<double> Run::scaled_error(const std::string& name,
                                        const std::function<std::optional<double>(const Scalar&)>& error) const {
    if (!usable()) return std::nullopt;
    auto se = [&](const std::string& n) -> std::optional<double> {
        const auto it = summary->outputs.find(n);
        return it == summary->outputs.end() ? std::nullopt : error(it->second);
    };
    if (name == "nu_bar_over_numax") {
        const auto s = se("mean_solid_fraction");
        return s ? std::optional(*s / nu_max()) : std::nullopt;
    }
    if (name == "slip_bottom_over_U" || name == "slip_top_over_U") {
        const auto s = se(name.substr(0, name.size() - 7));
        return s && point->speed > 0 ? std::optional(*s / point->speed) : std::nullopt;
    }
    return se(name);
}

Run load_run(const Case& c, const std::filesystem::path& root, const std::string& solver, const OperatingPoint& p) {
    Run r;
    r.solver = solver;
    r.point = &p;
    r.dir = result_dir(root, solver, p.id);
    LoadedResult loaded = load_result(r.dir, result_key(c, solver));  // the solvers' definition too
    r.status = std::move(loaded.status);
    r.summary = std::move(loaded.summary);
    r.profile = std::move(loaded.profile);
    if (r.summary) r.regime = read_regime(r.summary->run);
    try {
        r.failure = read_failure(r.dir);
    } catch (const Error& e) {
        r.failure_error = e.what();
    }
    return r;
}

std::size_t Run::seeds_pooled() const {
    if (!usable() || !summary->run.is_object()) return 0;
    const auto it = summary->run.find("seeds");
    if (it == summary->run.end() || !it->is_object() || !it->contains("pooled") || !it->at("pooled").is_array()) return 0;
    return it->at("pooled").size();
}

std::string Run::state_name() const {
    if (usable()) return regime.status == RegimeStatus::Unknown ? "status unknown" : to_string(regime.status);
    if (failure) return failure->no_answer ? "no answer" : "failed";
    switch (status.state) {
        case ResultState::Missing: return "missing";
        case ResultState::Stale: return "stale";
        case ResultState::Corrupt: return "corrupt";
        case ResultState::Complete: break;
    }
    return "corrupt";
}

std::string Run::state_reason() const {
    std::string why;
    if (usable()) {
        why = regime.reason;
        // A later attempt failed but left this (still current) result in place.
        if (failure && failure->utc_time > summary->provenance.utc_time)
            why += fmt::format("{}a later run failed ({}): {}", why.empty() ? "" : "; ", failure->utc_time,
                               failure->message);
    } else if (failure) {
        why = failure->message;
        if (status.state != ResultState::Missing) why += fmt::format(" (the result left in place is {}: {})",
                                                                     status.state == ResultState::Stale ? "stale" : "corrupt",
                                                                     status.reason);
    } else {
        why = status.state == ResultState::Missing ? std::string() : status.reason;
    }
    if (!failure_error.empty()) why += (why.empty() ? "" : "; ") + failure_error;
    return why;
}

std::string Run::state_class() const {
    if (usable()) {
        switch (regime.status) {
            case RegimeStatus::Steady: return "ok";
            case RegimeStatus::Unknown: return "unknown";
            default: return "transient";
        }
    }
    if (failure) return failure->no_answer ? "noanswer" : "failed";
    return status.state == ResultState::Stale ? "stale" : status.state == ResultState::Corrupt ? "corrupt" : "missing";
}

const Run& Collection::run(const std::string& solver, const std::string& point) const {
    return runs.at({solver, point});
}

std::vector<const Run*> Collection::usable(const std::string& point) const {
    std::vector<const Run*> out;
    for (const auto& s : solvers) {
        const Run& r = run(s, point);
        if (r.usable()) out.push_back(&r);
    }
    return out;
}

bool Collection::any_usable(const std::string& solver) const {
    return std::any_of(points.begin(), points.end(), [&](const OperatingPoint* p) { return run(solver, p->id).usable(); });
}

std::optional<SolverKind> Run::kind() const {
    if (!summary) return std::nullopt;
    if (!summary->kind.empty()) {
        for (const SolverKind k : {SolverKind::Continuum, SolverKind::Lattice, SolverKind::Particles})
            if (summary->kind == to_string(k)) return k;
        return std::nullopt;
    }
    const auto& run = summary->run;
    if (run.is_object() && run.contains("simulated_time_s")) return SolverKind::Particles;
    if (run.is_object() && run.contains("lattice")) return SolverKind::Lattice;
    return SolverKind::Continuum;
}

std::optional<SolverKind> Collection::kind(const std::string& solver) const {
    for (const OperatingPoint* p : points)
        if (const auto k = run(solver, p->id).kind()) return k;
    return std::nullopt;
}

std::size_t Collection::count(ResultState state) const {
    return static_cast<std::size_t>(
        std::count_if(runs.begin(), runs.end(), [&](const auto& kv) { return kv.second.status.state == state; }));
}

std::vector<std::string> known_solvers(const Case& c) {
    std::vector<std::string> known;
    if (!c.schema) return known;
    const Schema common = Schema::common();
    for (const SectionSpec& s : c.schema->sections())
        if (!common.find(s.name)) known.push_back(s.name);
    return known;
}

std::vector<std::string> result_solvers(const std::vector<std::string>& known, const std::filesystem::path& root,
                                        std::vector<std::string>* missing) {
    std::vector<std::string> solvers, others;
    std::error_code ec;
    for (const auto& s : known) {
        if (std::filesystem::is_directory(root / s, ec))
            solvers.emplace_back(s);
        else if (missing)
            missing->emplace_back(s);
    }
    if (std::filesystem::is_directory(root, ec)) {
        for (const auto& e : std::filesystem::directory_iterator(root, ec)) {
            const std::string name = e.path().filename().string();
            if (!e.is_directory() || name == "report" || name == "initial" || name == kSlurmDir || name.starts_with(".") ||
                name.find(".partial") != std::string::npos ||
                std::find(known.begin(), known.end(), name) != known.end())
                continue;
            others.push_back(name);
        }
    }
    std::sort(others.begin(), others.end());
    solvers.insert(solvers.end(), others.begin(), others.end());
    return solvers;
}

Collection collect(const Case& c, const RunOptions& o) {
    Collection col;
    col.root = results_root(c, o);
    col.points = c.select(o.point);
    col.known = known_solvers(c);
    col.solvers = result_solvers(col.known, col.root, &col.missing_solvers);
    for (const auto& s : col.solvers)
        for (const OperatingPoint* p : col.points) col.runs.emplace(std::pair(s, p->id), load_run(c, col.root, s, *p));
    return col;
}

}  // namespace granlub::postproc
