// The bulk-rheology table (bulk_rheology_table.h).
#include "granlub/particles/bulk_rheology_table.h"

#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "granlub/error.h"
#include "granlub/particles/bulk_rheology.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"

namespace granlub {

namespace fs = std::filesystem;

namespace {

// the outputs of a check run's record in run.dt_refinement: name -> {value, stderr}
std::map<std::string, Scalar> record_outputs(const nlohmann::json& run) {
    std::map<std::string, Scalar> outs;
    for (const auto& [name, v] : run.at("outputs").items()) {
        Scalar s{v.at("value").get<double>(), std::nullopt, ""};
        if (v.contains("stderr") && v.at("stderr").is_number()) s.stderr_ = v.at("stderr").get<double>();
        outs[name] = s;
    }
    return outs;
}

// Delta-t verdict of a point, from its status and its record
std::string dt_check(const Summary& s) {
    if (!s.run.contains("dt_refinement")) return "not-checked";
    switch (read_regime(s.run).status) {
    case RegimeStatus::Steady: return "converged";
    case RegimeStatus::DtUnconverged: return "unconverged";
    default: return "no-verdict";
    }
}

// the core's own Delta-t verdict (core_dt_unconverged): "converged", or "unconverged:" and what moved
std::string core_dt_check(const CoreRheology& answer, const CoreRheology& check) {
    const auto moved = core_dt_unconverged(answer, check);
    return moved.empty() ? "converged" : fmt::format("unconverged:{}", fmt::join(moved, ";"));
}

// A run's core and its Delta-t check's core, reduced alike (core_run, core_rheology): the check's profile is the
// run's dt_full/ (dt_half/ after a second halving) profile, its outputs its record in run.dt_refinement.
struct PointCores {
    CoreRheology answer;
    std::optional<CoreRheology> check;
    double check_dt = 0;
};

std::string src_of(const fs::path& dir) { return (dir / "summary.json").string(); }

PointCores point_cores(const fs::path& dir, const Summary& s, const Profile& profile, const Case& c,
                       const OperatingPoint& p) {
    const std::string src = src_of(dir);
    PointCores pc;
    pc.answer = run_core(c, p, profile, s.outputs, s.run, src);
    if (s.run.contains("dt_refinement")) {
        const DtCheckRun chk = dt_check_run(s.run.at("dt_refinement"));
        if (!chk.run) throw Error(fmt::format("{}: run.dt_refinement names no check run", src));
        const Profile cp = read_profile(dir / (chk.second_halving ? kDtHalfProfile : kDtCheckProfile));
        pc.check = run_core(c, p, cp, record_outputs(*chk.run), *chk.run, src);
        pc.check_dt = chk.run->at("time_step_s").get<double>();
    }
    return pc;
}

// The seeds a point's files pool (run.seeds.pooled, seed_pool.h), nullopt for a point run with one seed (its own
// files). A pool may hold one member while the set's others are missing (status "incomplete").
std::optional<std::vector<std::uint64_t>> pooled_seeds(const Summary& s) {
    if (!s.run.contains("seeds") || !s.run.at("seeds").contains("pooled")) return std::nullopt;
    return s.run.at("seeds").at("pooled").get<std::vector<std::uint64_t>>();
}

std::string num(double v) { return fmt::format("{:.6g}", v); }
std::string opt_num(const std::optional<double>& v) { return v ? num(*v) : std::string(); }

const char* kColumns[] = {
    "point", "speed_m_s", "load_Pa", "status", "dt_check", "core_dt_check", "time_step_s", "check_time_step_s", "gap_m", "grains",
    "core_from_y_over_H", "core_to_y_over_H", "core_stations", "shear_rate_1_s", "shear_rate_err",
    "shear_rate_halves", "pressure_Pa", "pressure_err", "shear_stress_Pa", "shear_stress_err",
    "wall_shear_imbalance", "wall_normal_imbalance", "I", "I_err", "I_dt_change", "mu", "mu_err", "mu_dt_change", "nu", "nu_err",
    "nu_dt_change", "T_scaled", "T_scaled_err", "T_scaled_dt_change", "Z", "Z_err", "Z_dt_change", "Z_source"};

}  // namespace

BulkTable bulk_rheology_table(const Case& c, const fs::path& results_root, const std::string& solver) {
    BulkTable t;
    const ResultKey key = result_key(c, solver);
    std::string rows;
    for (const auto& p : c.points) {
        const fs::path dir = result_dir(results_root, solver, p.id);
        const LoadedResult res = load_result(dir, key);
        if (res.status.state != ResultState::Complete) {
            t.notes.push_back(fmt::format("point {} left out: {}{}", p.id,
                                          res.status.state == ResultState::Missing ? "no result"
                                          : res.status.state == ResultState::Stale ? "stale result"
                                                                                   : "corrupt result",
                                          res.status.reason.empty() ? "" : " (" + res.status.reason + ")"));
            continue;
        }
        const Summary& s = *res.summary;
        const std::optional<std::vector<std::uint64_t>> seeds = pooled_seeds(s);
        PointCores pc;
        std::string dt_verdict;
        if (!seeds || seeds->empty()) {
            pc = point_cores(dir, s, *res.profile, c, p);
            dt_verdict = dt_check(s);
        } else {  // each member reduced alone, then pooled (pool_core_rheology): the pool's own files hold no check
            std::vector<CoreRheology> answers, checks;
            for (const std::uint64_t seed : *seeds) {
                const fs::path mdir = dir / realisation_folder(seed);
                const LoadedResult m = load_result(mdir, key);
                if (m.status.state != ResultState::Complete)
                    throw Error(fmt::format("{}: pooled seed {} is no longer complete at {}", src_of(dir), seed,
                                            mdir.string()));
                const PointCores one = point_cores(mdir, *m.summary, *m.profile, c, p);
                answers.push_back(one.answer);
                if (one.check) checks.push_back(*one.check);
                pc.check_dt = one.check_dt;
                const std::string v = dt_check(*m.summary);
                if (dt_verdict.empty() || dt_verdict == "converged") dt_verdict = v;
            }
            pc.answer = pool_core_rheology(answers);
            if (checks.size() == answers.size()) pc.check = pool_core_rheology(checks);
            t.notes.push_back(fmt::format("point {}: the cores of seeds {} each reduced, then pooled (errors: the larger "
                                          "of the seeds' standard error and their own combined)",
                                          p.id, fmt::join(*seeds, ", ")));
        }
        const CoreRheology& a = pc.answer;
        const std::optional<CoreRheology>& b = pc.check;
        const double check_dt = pc.check_dt;
        const auto change = [&](auto field) -> std::optional<double> {
            if (!b) return std::nullopt;
            return field(a) - field(*b);
        };
        const double gap = s.outputs.count("gap") ? s.outputs.at("gap").value : c.cell.gap;
        std::vector<std::string> v = {
            p.id, num(p.speed), num(p.normal_stress), to_string(read_regime(s.run).status), dt_verdict,
            b ? core_dt_check(a, *b) : std::string("not-checked"),
            num(s.run.value("time_step_s", 0.0)), b ? num(check_dt) : std::string(), num(gap),
            std::to_string(s.run.value("atoms", std::size_t{0})), num(a.core_from), num(a.core_to),
            std::to_string(a.stations), num(a.shear_rate.value), num(a.shear_rate.error), num(a.shear_rate_halves),
            num(a.pressure.value), num(a.pressure.error), num(a.shear_stress.value), num(a.shear_stress.error),
            num(a.wall_shear_imbalance), num(a.wall_normal_imbalance), num(a.inertial_number.value), num(a.inertial_number.error),
            opt_num(change([](const CoreRheology& r) { return r.inertial_number.value; })), num(a.friction.value),
            num(a.friction.error), opt_num(change([](const CoreRheology& r) { return r.friction.value; })),
            num(a.solid_fraction.value), num(a.solid_fraction.error),
            opt_num(change([](const CoreRheology& r) { return r.solid_fraction.value; })),
            num(a.temperature_scaled.value), num(a.temperature_scaled.error),
            opt_num(change([](const CoreRheology& r) { return r.temperature_scaled.value; })),
            a.coordination ? num(a.coordination->value) : std::string(),
            a.coordination ? num(a.coordination->error) : std::string(),
            b && a.coordination && b->coordination && a.coordination_core == b->coordination_core
                ? num(a.coordination->value - b->coordination->value)
                : std::string(),
            a.coordination ? (a.coordination_core ? "core" : "bulk") : "none"};
        if (a.walls)  // kWallColumns' order
            for (const Measured& m : {a.walls->slip_bottom, a.walls->slip_top, a.walls->T_bottom, a.walls->T_top})
                v.push_back(num(m.value)), v.push_back(num(m.error));
        else
            v.insert(v.end(), std::size(kWallColumns), std::string());
        v.push_back(seeds && !seeds->empty() ? std::to_string(seeds->size()) : std::string("1"));
        rows += fmt::format("{}\n", fmt::join(v, ","));
        ++t.rows;
    }
    std::string head = fmt::format("# format {}\n# case {} ({}), case file hash {}\n# written {} by granlub {}\n",
                                   kBulkTableFormat, c.name, c.file.string(), c.file_hash, utc_now(), version());
    head += fmt::format("# from {}; columns, units and method: cases/bulk_shear/README.md\n",
                        (results_root / solver).string());
    for (const auto& n : t.notes) head += "# " + n + "\n";
    t.csv = head + fmt::format("{},{},seeds\n", fmt::join(kColumns, ","), fmt::join(kWallColumns, ",")) + rows;
    return t;
}

}  // namespace granlub
