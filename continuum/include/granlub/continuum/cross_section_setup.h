// From a case to the trough's cross-section problem of one point ([continuum] geometry = "cross_section"), and
// from its solution to the result files: summary.json with every wall's stress and slip, profile.csv at
// mid-width (the 1-D columns), section.csv over the cross-section (the particle solvers' format, cross_section.h).
#pragma once
#include <filesystem>

#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/cross_section_problem.h"

namespace granlub::continuum {

// The geometry keys of [continuum] into `s`; stops (CaseError) on a width of 0, a grid too coarse for the walls,
// or a choice the cross-section cannot take (shooting, fill control).
void resolve_cross_section_settings(const Case& c, Settings& s);
// Throws SolverError when the point has no sheared steady state (as problem_for).
CrossSectionProblem cross_section_problem_for(const Case& c, const Settings& s, const OperatingPoint& p);
// Solves one point; writes section.csv into `dir` (the sweep writes profile.csv and summary.json).
PointResult solve_cross_section_point(const Case& c, const OperatingPoint& p, const Settings& s,
                                      const std::filesystem::path& dir);

}  // namespace granlub::continuum
