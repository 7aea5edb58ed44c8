// The results model: results/<solver>/<point>/{profile.csv, summary.json}.
// Contract: docs/architecture.md ("Results").
//
// profile.csv: '#' comment lines (provenance), a header row, one row per station across the gap.
//   Required columns: y_over_H, u_over_U, solid_fraction, temperature_over_U2; statistical
//   solvers add <column>_stderr; solvers may add further columns. y_over_H has one meaning in
//   every solver's file (kProfileYDefinition, written as a comment line), so that profiles
//   overlay without knowing any solver's conventions.
// summary.json: {"format", "solver", "case", "point", "inputs", "outputs", "run", "provenance"}.
//   outputs: name -> {"value", "stderr" (null when not statistical), "unit"[, "dt_error"]}.
//   Standard outputs (see kStandardOutputs): normal and shear stress on each wall (Pa, positive
//   magnitudes), slip at each wall (m/s: U - u(0) at the bottom, u(H) at the top),
//   mean_solid_fraction, max_solid_fraction.
// A point pooled over several seeds (granlub/particles/seeds.h) holds its members' results one
// folder deeper, <solver>/<point>/seed-<S>/, each a point result of its own.
// summary.json is written last and is the completion marker: a run that dies leaves at most a
// profile.csv without a current summary, which counts as incomplete.
// Every file of a point names the run that wrote it (run_id.h): summary.json's provenance.run_id
// and a "# run_id <id>" line in profile.csv and in each of the point's other tables (section.csv,
// width_profile.csv, gap.csv, final_state.csv, timeseries.csv, dt_full/profile.csv, dt_half/profile.csv); a point
// whose files name different runs is corrupt.
#pragma once
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/results/file_io.h"
#include "granlub/results/run_id.h"
#include "granlub/results/table.h"
#include "granlub/run/solver_info.h"

namespace granlub {

// A particle point checked in its time step ([dem] refine_dt) keeps the full-step run it was checked
// against in this folder beside its files; its profile is one of the point's tables.
inline constexpr const char* kDtCheckDir = "dt_full";
inline constexpr const char* kDtCheckProfile = "dt_full/profile.csv";
// Where that check failed and the step was halved once more ([dem] refine_halvings = 2), the run at
// half the step moves here, and the point's answer (at a quarter) is checked against it.
inline constexpr const char* kDtHalfDir = "dt_half";
inline constexpr const char* kDtHalfProfile = "dt_half/profile.csv";

// The folder of a results folder where `granlub slurm` writes its job scripts and their logs: not
// a solver's results.
inline constexpr const char* kSlurmDir = "slurm";

struct Case;
struct OperatingPoint;

// A profile is a table (table.h) with the columns kProfileColumns at least.
using Profile = Table;

struct Scalar {
    double value = 0;
    std::optional<double> stderr_;  // standard error, for statistical solvers
    std::string unit;
    // the time-step error estimate of a value checked at half the time step: |value(dt) - value(dt/2)|,
    // the value being the dt/2 run's (the error of a first-order method at dt/2)
    std::optional<double> dt_error = std::nullopt;
    // a point pooled over seeds (seed_pool.h): stderr is the seeds' standard error, and this the
    // members' own block errors combined, sqrt(sum se_i^2) / n, what they alone would claim
    std::optional<double> block_stderr = std::nullopt;
};

// The tables a point's run may write beside profile.csv, named here so that the results model
// (which checks that all of a point's files come from one run) needs nothing of the writers:
// kSectionFile holds the cross-section (cross_section.h) and is named after its file, section.csv,
// a format of its own (docs/architecture.md, "Results").
inline constexpr const char* kSectionFile = "section.csv";
inline constexpr const char* kWidthProfileFile = "width_profile.csv";  // CrossSection::width_profile
inline constexpr const char* kGapFile = "gap.csv";                     // the plate history (load_control.h)

inline constexpr const char* kStandardOutputs[] = {
    "normal_stress_bottom", "normal_stress_top", "shear_stress_bottom", "shear_stress_top",
    "slip_bottom",          "slip_top",          "mean_solid_fraction", "max_solid_fraction"};
inline constexpr const char* kProfileColumns[] = {"y_over_H", "u_over_U", "solid_fraction",
                                                  "temperature_over_U2"};
// What y_over_H is in every profile.csv: the walls' planes are the case's ([cell] gap apart when
// the gap is fixed), with bumps the planes through the bumps' centres (granlub/case/wall_bumps.h);
// a solver whose own domain ends elsewhere (the continuum's wall_plane = "bump_tops") writes its
// rows on this scale all the same, its first and last rows then off 0 and 1.
inline constexpr const char* kProfileYDefinition =
    "y_over_H = y / H: y from the floor's wall plane, H the gap between the two walls' planes (with bumps the "
    "planes through their centres; under a load the solver's own gap)";

struct Provenance {
    std::string version;      // granlub version (git describe)
    std::string case_file;    // path of case.toml
    std::string case_hash;    // hash of the case file's bytes
    std::string inputs_hash;  // Case::inputs_hash(solver): what the results depend on
    std::map<std::string, std::string> inputs;  // Case::inputs(solver); empty in older results
    nlohmann::json settings;  // the solver's resolved settings
    std::optional<std::uint64_t> seed;
    std::string utc_time;     // ISO 8601, filled at write time when empty
    std::string run_id;       // the run that wrote the point (run_id.h); "" in results written before
};

struct Summary {
    std::string solver;
    std::string kind;  // what the results are: to_string(SolverKind) (run/solver_info.h); "" in older results
    std::string case_name;
    std::string point;
    nlohmann::json inputs;  // the point's inputs (filled by make_summary)
    std::map<std::string, Scalar> outputs;
    nlohmann::json run;     // steps or iterations, wall_clock_s, solver-specific counters
    Provenance provenance;

    Summary& set(const std::string& name, double value, const std::string& unit,
                 std::optional<double> stderr_ = std::nullopt);
    double value(const std::string& name) const;  // throws naming the outputs
};

// A summary with solver, case, point, inputs and provenance (this process's run id included)
// filled in.
Summary make_summary(const Case& c, const OperatingPoint& p, const std::string& solver,
                     std::optional<std::uint64_t> seed = std::nullopt);
// The same for a solver's declaration: solver info.name, kind its kind.
Summary make_summary(const Case& c, const OperatingPoint& p, const SolverInfo& info,
                     std::optional<std::uint64_t> seed = std::nullopt);

std::filesystem::path result_dir(const std::filesystem::path& results_root, const std::string& solver,
                                 const std::string& point);


// The table as CSV: the comments, then a comment naming the run `run` (run_id.h), the header row
// and the rows.
std::string profile_csv(const Profile& p, const std::vector<std::string>& comments = {},
                        std::string_view run = run_id());
Profile parse_profile_csv(std::string_view text, const std::string& source);  // + required columns
Profile read_profile(const std::filesystem::path& path);

nlohmann::json summary_json(const Summary& s);
Summary summary_from_json(const nlohmann::json& j, const std::string& source);
Summary read_summary(const std::filesystem::path& path);

// Writes profile.csv then summary.json (the completion marker), both atomically, profile.csv
// naming the summary's run. Refuses NaN or infinite numbers and a profile without the required
// columns.
void write_result(const std::filesystem::path& dir, const Profile& profile, const Summary& summary);

enum class ResultState { Missing, Complete, Stale, Corrupt };
struct ResultStatus {
    ResultState state = ResultState::Missing;
    std::string reason;
};
struct LoadedResult {
    ResultStatus status;
    std::optional<Summary> summary;  // present when Complete
    std::optional<Profile> profile;
};
// The one definition of "complete and current", used by the solvers (skip or recompute) and by
// `granlub compare` (plot or name as corrupt) alike. Corrupt: a file is missing or unreadable, a
// number is not finite, a standard error is negative, y_over_H is not increasing within [0, 1],
// max_solid_fraction is not positive, or the summary names another solver, point (both taken
// from the folder, <root>/<solver>/<point>, or <root>/<solver>/<point>/seed-<S> for a member of a
// set of seeds, whose summary must name seed S) or case (when `case_name` is given), or the point's
// files do not all name the summary's run (a table from another run, or results written before
// run ids: recomputing them is the safe side, see load_result). Stale: all that
// holds but the summary's inputs_hash differs from the key's. Never throws for bad files.
struct ResultKey {
    std::string inputs_hash;                    // Case::inputs_hash(solver)
    std::string case_name;                      // "" = not checked
    std::map<std::string, std::string> inputs;  // Case::inputs(solver): a stale reason names the changed keys
};
ResultKey result_key(const Case& c, const std::string& solver);  // computed once per sweep
LoadedResult load_result(const std::filesystem::path& dir, const ResultKey& key);
LoadedResult load_result(const std::filesystem::path& dir, const std::string& inputs_hash,
                         const std::string& case_name = "");
ResultStatus result_status(const std::filesystem::path& dir, const std::string& inputs_hash,
                           const std::string& case_name = "");

// Removes the tables a point's run may write beside profile.csv (the list in the header comment):
// a sweep calls it before it recomputes the point, so that a table this run does not write (gap.csv
// after a change from load to fill control) cannot stay behind naming an earlier run.
void remove_point_tables(const std::filesystem::path& dir);

std::string version();   // project version + git describe --dirty, taken at build time
std::string utc_now();   // ISO 8601

}  // namespace granlub
