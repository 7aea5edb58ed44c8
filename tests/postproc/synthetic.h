// Synthetic result sets with known answers: analytic profiles and power-law stresses written
// through core's write_result, so the tests exercise the real file formats.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub::test {

// A fresh directory under the build tree holding case.toml (speeds 1, 2, 4 m/s, nu_max 0.65).
struct SyntheticCase {
    std::filesystem::path dir;
    Case c;
    RunOptions o;  // results_root = dir/results
};
SyntheticCase make_case(const std::string& name, const std::string& extra_toml = "");
// The common sections and one empty section per solver, in `granlub run` order (continuum,
// automaton, dem, yade): the solvers the report knows (postproc known_solvers).
Schema synthetic_schema();
// make_case with `from` replaced by `to` in its case.toml (e.g. "width = 0.0" by "width = 0.01").
SyntheticCase edited_case(const std::string& name, const std::string& from, const std::string& to);

// continuum: 41 stations on [0, 1], deterministic; u/U = 0.9 - 0.8 y, nu/nu_max = 0.8 + 0.1 y,
//   T/U^2 = 0.01; sigma_b = 1000 U^2, sigma_t = 900 U^2, tau = 400 U^2, slip = 0.1 U, nu_bar 0.55.
// dem: 20 bin centres, stderr 0.01 on every profile; u/U offset +0.05, same nu, T/U^2 = 0.012;
//   sigma_b = 1100 U^1.5 +- 5 %, sigma_t = 1000 U^1.5 +- 5 %, tau = 450 U^1.5 +- 5 %, slip 0.12 U +- 0.01 U,
//   nu_bar 0.56 +- 0.005.
// automaton: 10 cell centres, lattice occupancy with max_solid_fraction = 1: nu = 0.8 + 0.1 y (so
//   nu/nu_max equals the continuum's), u/U as the continuum, T/U^2 = 0.01; stresses 0.9 x continuum.
void write_solver(const SyntheticCase& s, const std::string& solver);

// Results shaped like the main job's: the four solvers at the three points, the dem transient at
// the last point and dt-unconverged at the first.
SyntheticCase main_job_results(const std::string& name);

// Edits the written summary.json of (solver, point): merges `run` into its run block (e.g. a
// regime status or a dt_refinement record), or removes the keys whose value is null.
void patch_run(const SyntheticCase& s, const std::string& solver, const std::string& point, const nlohmann::json& run);

std::map<std::string, std::string> read_metrics_row(const std::filesystem::path& csv, const std::string& kind,
                                                    const std::string& point, const std::string& quantity,
                                                    const std::string& a, const std::string& b);

std::string slurp(const std::filesystem::path& p);

// How often `what` occurs in `text` (overlapping occurrences counted).
std::size_t count(const std::string& text, const std::string& what);

}  // namespace granlub::test
