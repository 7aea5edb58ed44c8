// The wall constants' part of `granlub continuum-fit` (rheology_fit.h): the model for the walls' columns of a
// bulk-rheology table (the DEM's slips and near-wall T next to cases/bulk_shear's bumpy walls) is the continuum's
// own 1-D load-controlled solve of the bulk case at each answer's point, with the fitted case's [continuum]
// closures and settings (problem_for, case_setup.h), read the way the table's reducer reads the DEM
// (near_wall_temperature, granlub/particles/bulk_rheology.h).
#pragma once
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/continuum/case_setup.h"
#include "granlub/particles/bulk_rheology.h"
#include "granlub/particles/bulk_rheology_table.h"

namespace granlub::continuum::detail {

// The [continuum] keys of the walls a fit may free.
bool is_wall_key(const std::string& key);

// Throws CaseError naming the walls' columns a table lacks (BulkRows::missing_wall_columns).
void check_wall_columns(const std::vector<std::string>& missing_columns, const std::vector<std::string>& wall_keys,
                        const std::string& source);

// The bulk case's point of each answer (by its id, with the table's U and P): throws CaseError for an answer whose
// point the bulk case lacks or holds at another U or P, an answer
// whose wall values cannot weight a fit, a case whose walls do not feel the key (R7 = 0 at both walls for
// slip_dissipation), a case that sets r5_bottom or r5_top (for r5), and a cross-section case (its walls are not the 1-D solve's).
std::vector<const OperatingPoint*> wall_points(const Settings& s, const Case& bulk, const std::vector<BulkRow>& answers,
                                               const std::vector<std::string>& wall_keys, const std::string& source);

// The R5 the case gives both walls of the bulk case at point p (the fit's start for r5); throws CaseError when the
// walls' differ.
double case_r5(const Case& bulk, const Settings& s, const OperatingPoint& p);

// The continuum's slips over U and near-wall T over U^2 of the bulk case at one point with the settings `s` (errors
// 0); throws SolverError when the point does not solve.
WallLayers wall_model(const Case& bulk, const Settings& s, const OperatingPoint& p);

// (model - table)/error of slip_bottom, slip_top, T_wall_bottom, T_wall_top.
inline constexpr std::size_t kWallResiduals = 4;
void wall_residuals(const WallLayers& m, const BulkRow& r, double* f);

}  // namespace granlub::continuum::detail
