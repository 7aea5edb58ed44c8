// The continuum's (U, P) map of a case (docs/continuum-model.md §6.4): the case's model and walls (its
// first operating point's) solved on a grid of wall speeds x normal loads, each point from scratch, for the
// report's continuous fields under the particle solvers' points.
//
// File results/continuum/map.csv (atomic): '#' lines (what, the case file's hash, granlub version,
// the closures), then a header row and one row per grid point, speed fastest:
//   speed_m_s, normal_stress_Pa, status, mean_solid_fraction, gap_m, stress_ratio_bottom, stress_ratio_top,
//   inertial_number, slip_bottom_m_s, slip_top_m_s, max_solid_fraction_node, lubrication
// status: steady | ordered (past [continuum] ordering_fraction: not to be drawn as a number) | failed
// (numbers empty); lubrication: contact | collision (the continuum's criterion, case_setup.cpp).
#pragma once
#include <filesystem>
#include <string>

#include "granlub/case/case.h"

namespace granlub::continuum {

struct MapGrid {
    double speed_min = 0.4, speed_max = 2.8;  // m/s, linear
    double load_min = 1000, load_max = 8000;  // Pa, logarithmic
    int speeds = 100, loads = 100;
};

struct MapStats {
    std::size_t points = 0, failed = 0, ordered = 0;
    double seconds = 0;
};

// The map's CSV text (a pure function of the case and grid, besides the provenance lines).
std::string continuum_map_csv(const Case& c, const MapGrid& g, MapStats* stats = nullptr);
// Writes <results_root>/continuum/map.csv atomically; returns its path.
std::filesystem::path write_continuum_map(const Case& c, const MapGrid& g, const std::filesystem::path& results_root,
                                          MapStats* stats = nullptr);

}  // namespace granlub::continuum
