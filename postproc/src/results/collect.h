// Finding and loading every solver's results for the case's operating points. Reads result
// files only, through core's load_result: the same definition of "complete" the solvers use, so
// a result compare calls corrupt is one the next solver run recomputes.
#pragma once
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"

namespace granlub::postproc {

// The solvers the case's schema declares: the sections `granlub` adds to the common ones, one per
// solver compiled in, in `granlub run` order (the generated solvers.h, cmake/GranlubSolverList.cmake). The report's order and colours, and
// the solvers whose missing results it names; any other folder under results/ (except report/ and
// initial/) is treated as a solver too and listed after these.
std::vector<std::string> known_solvers(const Case& c);

struct Run {
    std::string solver;
    const OperatingPoint* point = nullptr;
    std::filesystem::path dir;
    ResultStatus status;             // Complete only when both files load and pass the checks
    std::optional<Profile> profile;  // present when Complete
    std::optional<Summary> summary;
    Regime regime;                        // from the summary's run block; Unknown when not usable
    std::optional<FailureRecord> failure;  // the point folder's failure.json, when present
    std::string failure_error;            // why failure.json could not be read

    bool usable() const { return status.state == ResultState::Complete && profile && summary; }
    // A usable result that is a steady state: the only kind fitted, compared with z or bold.
    bool steady() const { return usable() && regime.steady(); }
    // What the report calls the run: "steady", "transient", "dt-unconverged", "status unknown"
    // (usable), "failed" (no usable result, failure.json present), "no answer" (the same, of kind "no
    // answer": the model cannot answer the point), "missing", "stale", "corrupt".
    std::string state_name() const;
    std::string state_reason() const;  // why; empty for a plain steady result
    std::string state_class() const;   // report cell class: ok, transient, unknown, failed, noanswer, missing, ...
    // Normalised profile columns: y/H ascending, u/U, nu/nu_max (nu_max from this run's
    // summary), T/U^2, and their standard errors (empty when the solver gives none).
    const std::vector<double>& y() const { return profile->column("y_over_H"); }
    std::vector<double> column(const std::string& quantity) const;         // "u_over_U", "nu_over_numax", ...
    std::vector<double> column_stderr(const std::string& quantity) const;  // empty when absent
    double nu_max() const { return summary->value("max_solid_fraction"); }
    // A summary output; "nu_bar_over_numax" and "slip_bottom_over_U"/"slip_top_over_U" derived.
    std::optional<double> scalar(const std::string& name) const;
    std::optional<double> scalar_stderr(const std::string& name) const;
    // The time-step error estimate |value(dt) - value(dt/2)| of a value checked at half the step
    // (the value is the dt/2 run's), scaled as scalar() scales it; nothing when not checked.
    std::optional<double> scalar_dt_error(const std::string& name) const;
    // The roughness of the wall this run's solver had (core wall_bumps.h): the R its bumps built
    // (run.walls.<side>), nothing for a particle solver's plane (a frictional plane has no R), else
    // the point's R (the continuum's and the automaton's walls are R itself).
    std::optional<double> wall_roughness(bool bottom) const;
    // run.walls.<side>.surface of a particle solver ("plane", "bumps"); "" for the others.
    std::string wall_surface(bool bottom) const;
    // What the results are (granlub/run/solver_info.h): the summary's "kind"; in a summary written
    // before it was recorded, read from its run block (a particle engine's simulated time, a
    // lattice's lattice, else a continuum's); nothing without a summary or with a kind not known.
    std::optional<SolverKind> kind() const;
    // How many seeds a particle result pools (run.seeds.pooled, granlub/particles/seed_pool.h): its
    // standard errors are then the seeds' standard error; 0 for one run, whose are its own block errors.
    std::size_t seeds_pooled() const;

private:
    std::optional<double> scaled_error(const std::string& name,
                                       const std::function<std::optional<double>(const Scalar&)>& error) const;
};

struct Collection {
    std::filesystem::path root;                  // results root
    std::vector<const OperatingPoint*> points;   // compared points, case order
    std::vector<std::string> known;              // known_solvers(case)
    std::vector<std::string> solvers;            // with a results folder, report order
    std::vector<std::string> missing_solvers;    // known solvers without a results folder
    std::map<std::pair<std::string, std::string>, Run> runs;  // (solver, point id) -> run, every solver x point

    const Run& run(const std::string& solver, const std::string& point) const;
    std::vector<const Run*> usable(const std::string& point) const;  // solvers order
    bool any_usable(const std::string& solver) const;
    std::optional<SolverKind> kind(const std::string& solver) const;  // the first of its runs that says
    std::size_t count(ResultState state) const;
};

Collection collect(const Case& c, const RunOptions& o);

// The solvers with a results folder under `root`, in report order (the known ones, then any other
// folder but report/, initial/, slurm/ (kSlurmDir) and hidden ones); the known solvers without one go to `missing`.
std::vector<std::string> result_solvers(const std::vector<std::string>& known, const std::filesystem::path& root,
                                        std::vector<std::string>* missing = nullptr);

// One run's status without loading it into a collection (for summary_table).
Run load_run(const Case& c, const std::filesystem::path& root, const std::string& solver, const OperatingPoint& p);

// The quantities compared, in report order.
struct Quantity {
    const char* key;    // column/derived-output name
    const char* label;  // axis label with unit
    const char* short_label;
};
inline constexpr Quantity kProfileQuantities[] = {
    {"u_over_U", "u/U", "u/U"}, {"nu_over_numax", "ν/ν_max", "ν/ν_max"}, {"T_over_U2", "T/U²", "T/U²"}};
inline constexpr Quantity kScalarQuantities[] = {
    {"normal_stress_bottom", "normal stress, moving wall (Pa)", "σ_yy bottom"},
    {"normal_stress_top", "normal stress, stationary wall (Pa)", "σ_yy top"},
    {"shear_stress_bottom", "shear stress, moving wall (Pa)", "τ_xy bottom"},
    {"shear_stress_top", "shear stress, stationary wall (Pa)", "τ_xy top"},
    {"slip_bottom_over_U", "slip at the moving wall / U", "slip bottom / U"},
    {"slip_top_over_U", "slip at the stationary wall / U", "slip top / U"},
    {"nu_bar_over_numax", "mean ν / ν_max", "ν̄/ν_max"}};

}  // namespace granlub::postproc
