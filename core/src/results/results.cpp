// Result files: profile.csv and summary.json, written atomically; "complete and current" test.
#include "granlub/results/results.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>

#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/text.h"

namespace granlub {

namespace detail {
const char* version_string();  // generated at build time (cmake/WriteVersion.cmake)
}

std::string version() { return detail::version_string(); }

std::string utc_now() {
    std::time_t t = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[32];
    std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return buf;
}

// ---------------------------------------------------------------------------------------------
Summary& Summary::set(const std::string& name, double v, const std::string& unit, std::optional<double> se) {
    outputs[name] = Scalar{v, se, unit};
    return *this;
}

double Summary::value(const std::string& name) const {
    auto it = outputs.find(name);
    if (it == outputs.end()) {
        std::vector<std::string> names;
        for (const auto& [n, s] : outputs) names.push_back(n);
        throw Error(fmt::format("summary of {} {} has no output '{}' (outputs: {})", solver, point, name,
                                fmt::join(names, ", ")));
    }
    return it->second.value;
}

Summary make_summary(const Case& c, const OperatingPoint& p, const std::string& solver,
                     std::optional<std::uint64_t> seed) {
    Summary s;
    s.solver = solver;
    s.case_name = c.name;
    s.point = p.id;
    s.inputs = {{"speed", p.speed},
                {"control", to_string(p.control)},
                {"solid_fraction", p.solid_fraction},
                {"normal_stress", p.normal_stress},
                {"roughness_bottom", p.bottom.roughness},
                {"roughness_top", p.top.roughness},
                {"restitution_bottom", p.bottom.restitution},
                {"restitution_top", p.top.restitution},
                {"gap", c.cell.gap},
                {"diameter", c.grains.diameter}};
    s.provenance.version = version();
    s.provenance.case_file = c.file.string();
    s.provenance.case_hash = c.file_hash;
    s.provenance.inputs_hash = c.inputs_hash(solver);
    s.provenance.inputs = c.inputs(solver);
    s.provenance.seed = seed;
    s.provenance.run_id = run_id();
    s.provenance.settings = nlohmann::json::object();
    auto it = c.sections.find(solver);
    if (it != c.sections.end()) {
        for (const auto& kv : it->second.values()) {
            const std::string& key = kv.first;
            std::visit([&](const auto& x) { s.provenance.settings[key] = x; }, kv.second);
        }
    }
    return s;
}

Summary make_summary(const Case& c, const OperatingPoint& p, const SolverInfo& info, std::optional<std::uint64_t> seed) {
    Summary s = make_summary(c, p, std::string(info.name), seed);
    s.kind = to_string(info.kind);
    return s;
}

std::filesystem::path result_dir(const std::filesystem::path& root, const std::string& solver,
                                 const std::string& point) {
    return root / solver / point;
}

std::string profile_csv(const Profile& p, const std::vector<std::string>& comments, std::string_view run) {
    std::string out;
    for (const auto& c : comments) out += "# " + one_line(c) + "\n";
    out += "# " + one_line(run_id_comment(run)) + "\n";
    out += fmt::format("{}\n", fmt::join(p.names, ","));
    for (std::size_t r = 0; r < p.rows(); ++r) {
        for (std::size_t c = 0; c < p.columns.size(); ++c)
            out += fmt::format("{}{:.10g}", c ? "," : "", p.columns[c][r]);
        out += '\n';
    }
    return out;
}

namespace {
Profile checked_profile(Profile p, const std::string& source) {
    for (const char* col : kProfileColumns)
        if (!p.has(col))
            throw Error(fmt::format("{}: missing required column '{}' (has: {})", source, col, fmt::join(p.names, ", ")));
    if (p.rows() < 2) throw Error(fmt::format("{}: a profile needs at least 2 rows, has {}", source, p.rows()));
    return p;
}
}  // namespace

Profile parse_profile_csv(std::string_view text, const std::string& source) {
    return checked_profile(parse_table(text, source), source);
}

Profile read_profile(const std::filesystem::path& path) { return checked_profile(read_table(path), path.string()); }

nlohmann::json summary_json(const Summary& s) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [name, v] : s.outputs) {
        out[name] = {{"value", v.value}, {"unit", v.unit}};
        out[name]["stderr"] = v.stderr_ ? nlohmann::json(*v.stderr_) : nlohmann::json(nullptr);
        if (v.dt_error) out[name]["dt_error"] = *v.dt_error;
        if (v.block_stderr) out[name]["block_stderr"] = *v.block_stderr;
    }
    nlohmann::json prov = {{"granlub_version", s.provenance.version},
                           {"case_file", s.provenance.case_file},
                           {"case_hash", s.provenance.case_hash},
                           {"inputs_hash", s.provenance.inputs_hash},
                           {"inputs", s.provenance.inputs},
                           {"settings", s.provenance.settings},
                           {"utc_time", s.provenance.utc_time.empty() ? utc_now() : s.provenance.utc_time}};
    prov["seed"] = s.provenance.seed ? nlohmann::json(*s.provenance.seed) : nlohmann::json(nullptr);
    prov["run_id"] = s.provenance.run_id.empty() ? nlohmann::json(nullptr) : nlohmann::json(s.provenance.run_id);
    nlohmann::json j = {{"format", "granlub-summary-1"}, {"solver", s.solver}, {"case", s.case_name}, {"point", s.point},
                        {"inputs", s.inputs},            {"outputs", out},     {"run", s.run},        {"provenance", prov}};
    if (!s.kind.empty()) j["kind"] = s.kind;
    return j;
}

Summary summary_from_json(const nlohmann::json& j, const std::string& source) {
    try {
        if (!j.is_object() || j.value("format", "") != "granlub-summary-1")
            throw Error(fmt::format("{}: not a granlub summary (format is not granlub-summary-1)", source));
        Summary s;
        s.solver = j.at("solver").get<std::string>();
        s.kind = j.value("kind", "");
        s.case_name = j.at("case").get<std::string>();
        s.point = j.at("point").get<std::string>();
        s.inputs = j.at("inputs");
        s.run = j.value("run", nlohmann::json::object());
        for (const auto& [name, v] : j.at("outputs").items()) {
            Scalar sc;
            sc.value = v.at("value").get<double>();
            sc.unit = v.value("unit", "");
            if (v.contains("stderr") && !v.at("stderr").is_null()) sc.stderr_ = v.at("stderr").get<double>();
            if (v.contains("dt_error") && !v.at("dt_error").is_null()) sc.dt_error = v.at("dt_error").get<double>();
            if (v.contains("block_stderr") && !v.at("block_stderr").is_null())
                sc.block_stderr = v.at("block_stderr").get<double>();
            s.outputs[name] = sc;
        }
        const auto& p = j.at("provenance");
        s.provenance.version = p.at("granlub_version").get<std::string>();
        s.provenance.case_file = p.value("case_file", "");
        s.provenance.case_hash = p.at("case_hash").get<std::string>();
        s.provenance.inputs_hash = p.at("inputs_hash").get<std::string>();
        if (p.contains("inputs")) s.provenance.inputs = p.at("inputs").get<std::map<std::string, std::string>>();
        s.provenance.settings = p.value("settings", nlohmann::json::object());
        s.provenance.utc_time = p.value("utc_time", "");
        if (p.contains("seed") && !p.at("seed").is_null()) s.provenance.seed = p.at("seed").get<std::uint64_t>();
        if (p.contains("run_id") && !p.at("run_id").is_null()) s.provenance.run_id = p.at("run_id").get<std::string>();
        for (const char* name : kStandardOutputs)
            if (!s.outputs.count(name)) throw Error(fmt::format("{}: missing standard output '{}'", source, name));
        return s;
    } catch (const nlohmann::json::exception& e) {
        throw Error(fmt::format("{}: malformed summary: {}", source, e.what()));
    }
}

Summary read_summary(const std::filesystem::path& path) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(read_file(path));
    } catch (const nlohmann::json::exception& e) {  // parse_error, and out_of_range for 1e999
        throw Error(fmt::format("{}: not valid JSON: {}", path.string(), e.what()));
    }
    return summary_from_json(j, path.string());
}

void write_result(const std::filesystem::path& dir, const Profile& profile, const Summary& summary_in) {
    Summary summary = summary_in;  // both files name one run: this process's unless the summary names one
    if (summary.provenance.run_id.empty()) summary.provenance.run_id = run_id();
    for (const char* col : kProfileColumns)
        if (!profile.has(col))
            throw Error(fmt::format("internal: {} {}: profile lacks column '{}'", summary.solver, summary.point, col));
    for (std::size_t c = 0; c < profile.columns.size(); ++c)
        for (double v : profile.columns[c])
            if (!std::isfinite(v))
                throw SolverError(fmt::format("{} {}: profile column '{}' has a non-finite value; nothing written",
                                              summary.solver, summary.point, profile.names[c]));
    for (const char* name : kStandardOutputs)
        if (!summary.outputs.count(name))
            throw Error(fmt::format("internal: {} {}: summary lacks output '{}'", summary.solver, summary.point, name));
    for (const auto& [name, v] : summary.outputs) {
        if (!std::isfinite(v.value) || (v.stderr_ && !std::isfinite(*v.stderr_)) ||
            (v.dt_error && !(std::isfinite(*v.dt_error) && *v.dt_error >= 0)))
            throw SolverError(fmt::format("{} {}: output '{}' is not finite; nothing written", summary.solver,
                                          summary.point, name));
        if (v.stderr_ && *v.stderr_ < 0)
            throw SolverError(fmt::format("{} {}: output '{}' has a negative standard error ({}); nothing written",
                                          summary.solver, summary.point, name, *v.stderr_));
    }
    // The summary is the completion marker: remove a previous one first, so that a crash between
    // the two writes cannot pair a new profile with an old summary.
    std::error_code ec;
    std::filesystem::remove(dir / "summary.json", ec);
    write_file_atomic(dir / "profile.csv",
                      profile_csv(profile, {fmt::format("granlub {} profile: case {} point {}", summary.solver,
                                                        summary.case_name, summary.point),
                                            fmt::format("granlub {} inputs_hash {}", summary.provenance.version,
                                                        summary.provenance.inputs_hash),
                                            kProfileYDefinition},
                                  summary.provenance.run_id));
    write_file_atomic(dir / "summary.json", summary_json(summary).dump(2) + "\n");
}

namespace {
// Content checks beyond parsing (see load_result); "" when the result is sound.
std::string result_problem(const std::filesystem::path& dir, const Summary& s, const Profile& p,
                           const std::string& case_name) {
    const auto sp = (dir / "summary.json").string();
    const auto pp = (dir / "profile.csv").string();
    // a member of a set of seeds lies one folder deeper, in seed-<S> (results.h)
    const std::string folder = dir.filename().string();
    const bool member = folder.starts_with("seed-");
    const std::filesystem::path point_dir = member ? dir.parent_path() : dir;
    const std::string solver = point_dir.parent_path().filename().string();
    const std::string point = point_dir.filename().string();
    if (member && (!s.provenance.seed || folder != fmt::format("seed-{}", *s.provenance.seed)))
        return fmt::format("{}: says seed {} but lies in the \"{}\" folder", sp,
                           s.provenance.seed ? std::to_string(*s.provenance.seed) : "none", folder);
    if (s.solver != solver)
        return fmt::format("{}: says solver \"{}\" but lies in the \"{}\" results folder", sp, s.solver, solver);
    if (s.point != point) return fmt::format("{}: says point \"{}\" but lies in the \"{}\" folder", sp, s.point, point);
    if (!case_name.empty() && s.case_name != case_name)
        return fmt::format("{}: says case \"{}\", this case is \"{}\"", sp, s.case_name, case_name);
    for (const auto& [name, sc] : s.outputs) {
        if (!std::isfinite(sc.value)) return fmt::format("{}: output \"{}\" is not a finite number", sp, name);
        if (sc.stderr_ && !(*sc.stderr_ >= 0 && std::isfinite(*sc.stderr_)))
            return fmt::format("{}: output \"{}\" has stderr {} (allowed: finite, >= 0)", sp, name, *sc.stderr_);
        if (sc.dt_error && !(*sc.dt_error >= 0 && std::isfinite(*sc.dt_error)))
            return fmt::format("{}: output \"{}\" has dt_error {} (allowed: finite, >= 0)", sp, name, *sc.dt_error);
        if (sc.block_stderr && !(*sc.block_stderr >= 0 && std::isfinite(*sc.block_stderr)))
            return fmt::format("{}: output \"{}\" has block_stderr {} (allowed: finite, >= 0)", sp, name,
                               *sc.block_stderr);
    }
    if (!(s.value("max_solid_fraction") > 0))
        return fmt::format("{}: max_solid_fraction = {} (allowed: > 0)", sp, s.value("max_solid_fraction"));
    const auto& y = p.column("y_over_H");
    for (std::size_t i = 0; i < y.size(); ++i) {
        if (!(y[i] >= -1e-9 && y[i] <= 1 + 1e-9))
            return fmt::format("{}: row {}: y_over_H = {} (allowed: [0, 1])", pp, i + 1, y[i]);
        if (i > 0 && !(y[i] > y[i - 1]))
            return fmt::format("{}: row {}: y_over_H = {} does not increase (previous {})", pp, i + 1, y[i], y[i - 1]);
    }
    for (std::size_t k = 0; k < p.names.size(); ++k)
        for (std::size_t i = 0; i < p.columns[k].size(); ++i) {
            const double v = p.columns[k][i];
            if (!std::isfinite(v)) return fmt::format("{}: row {}: {} is not a finite number", pp, i + 1, p.names[k]);
            if (p.names[k].ends_with("_stderr") && v < 0)
                return fmt::format("{}: row {}: {} = {} (allowed: >= 0)", pp, i + 1, p.names[k], v);
        }
    return "";
}
}  // namespace

namespace {
// The tables a point's run may write beside profile.csv (results.h): the cross-section and the
// profile across the width (cross_section.h), the plate history (load_control.h), dem's final state
// (particles.h) and the coarser runs of its time-step check (kDtCheckDir, kDtHalfDir), the
// automaton's time series.
constexpr const char* kPointTables[] = {kSectionFile,     kWidthProfileFile, kGapFile,       "final_state.csv",
                                        "timeseries.csv", kDtCheckProfile,   kDtHalfProfile};

// "" when every file of the point names the summary's run (run_id.h), else which does not. Results
// written before run ids name none: they are corrupt, not trusted, because nothing shows that their
// files come from one run (issue 34), and a sweep recomputes them once.
std::string run_problem(const std::filesystem::path& dir, const Summary& s) {
    const auto sp = (dir / "summary.json").string();
    const std::string& run = s.provenance.run_id;
    if (run.empty())
        return fmt::format("{}: written before run ids (no provenance.run_id): nothing shows that the point's files "
                           "come from one run",
                           sp);
    std::vector<std::string> tables{"profile.csv"};
    tables.insert(tables.end(), std::begin(kPointTables), std::end(kPointTables));
    std::error_code ec;
    for (const auto& t : tables) {
        const auto file = dir / t;
        if (t != "profile.csv" && !std::filesystem::exists(file, ec)) continue;
        const auto id = read_table_run_id(file);
        if (!id) return fmt::format("{} names no run, {} names run {}: not one run's files", file.string(), sp, run);
        if (*id != run)
            return fmt::format("{} was written by run {}, {} by run {}: the point's files come from different runs",
                               file.string(), *id, sp, run);
    }
    return "";
}

// "[grains] density = 2500 -> 2600, [dem] time (new) = 0.2": what changed between two input sets.
std::string changed_keys(const std::map<std::string, std::string>& was, const std::map<std::string, std::string>& now) {
    std::vector<std::string> diffs;
    for (const auto& [k, v] : now) {
        const auto it = was.find(k);
        if (it == was.end()) diffs.push_back(fmt::format("{} = {} (not in the old inputs)", k, clipped(v)));
        else if (it->second != v) diffs.push_back(fmt::format("{} = {} -> {}", k, clipped(it->second), clipped(v)));
    }
    for (const auto& [k, v] : was)
        if (!now.count(k)) diffs.push_back(fmt::format("{} = {} (no longer set)", k, clipped(v)));
    if (diffs.size() > 4) {
        const auto more = diffs.size() - 3;
        diffs.resize(3);
        diffs.push_back(fmt::format("and {} more", more));
    }
    return fmt::format("{}", fmt::join(diffs, ", "));
}
}  // namespace

ResultKey result_key(const Case& c, const std::string& solver) {
    return {c.inputs_hash(solver), c.name, c.inputs(solver)};
}

LoadedResult load_result(const std::filesystem::path& dir, const ResultKey& key) {
    std::error_code ec;
    const auto sp = dir / "summary.json";
    const auto pp = dir / "profile.csv";
    LoadedResult r;
    if (!std::filesystem::exists(sp, ec)) {
        r.status = {ResultState::Missing, sp.string() + " does not exist"};
        return r;
    }
    if (!std::filesystem::is_regular_file(sp, ec) || !std::filesystem::is_regular_file(pp, ec)) {
        r.status = {ResultState::Corrupt, fmt::format("{} is not a regular file",
                                                      std::filesystem::is_regular_file(sp, ec) ? pp.string() : sp.string())};
        return r;
    }
    try {
        Summary s = read_summary(sp);
        Profile p = read_profile(pp);
        if (std::string why = result_problem(dir, s, p, key.case_name); !why.empty()) {
            r.status = {ResultState::Corrupt, why};
            return r;
        }
        if (std::string why = run_problem(dir, s); !why.empty()) {
            r.status = {ResultState::Corrupt, why};
            return r;
        }
        if (s.provenance.inputs_hash != key.inputs_hash) {
            // name the keys that changed where both sides are known (older results lack them)
            const std::string what = s.provenance.inputs.empty() || key.inputs.empty()
                                         ? std::string()
                                         : changed_keys(s.provenance.inputs, key.inputs);
            r.status = {ResultState::Stale,
                        what.empty() ? fmt::format("{}: computed for inputs {}, the case now gives {}", sp.string(),
                                                   s.provenance.inputs_hash, key.inputs_hash)
                                     : fmt::format("{}: computed before the case changed: {}", sp.string(), what)};
            return r;
        }
        r.summary = std::move(s);
        r.profile = std::move(p);
        r.status = {ResultState::Complete, ""};
    } catch (const std::exception& e) {  // anything unreadable is corrupt, never fatal to a sweep
        r.status = {ResultState::Corrupt, e.what()};
    }
    return r;
}

LoadedResult load_result(const std::filesystem::path& dir, const std::string& inputs_hash,
                         const std::string& case_name) {
    return load_result(dir, ResultKey{inputs_hash, case_name, {}});
}

ResultStatus result_status(const std::filesystem::path& dir, const std::string& inputs_hash,
                           const std::string& case_name) {
    return load_result(dir, inputs_hash, case_name).status;
}

void remove_point_tables(const std::filesystem::path& dir) {
    for (const char* t : kPointTables) std::filesystem::remove(dir / t);  // throws when it cannot: the sweep says so
}

}  // namespace granlub
