// The report's figures, built from the collected results (what to plot; svg_plot.h and
// gnuplot.h decide how).
#pragma once
#include <string>
#include <vector>

#include "formats/figure_model.h"
#include "results/collect.h"

namespace granlub::postproc {

// One colour/dash/marker per solver, the same in every figure: known solvers by their fixed
// order, others after them.
int solver_style(const Collection& col, const std::string& solver);

// u/U, nu/nu_max and T/U^2 against y/H at one point; every usable solver overlaid, +-1 standard
// error bands for the statistical ones.
std::vector<Figure> profile_figures(const Collection& col, std::size_t point_index);
// Wall normal and shear stress against U on log-log axes, one figure per stress output, with the
// fitted power law per solver and speed group.
std::vector<Figure> stress_figures(const Collection& col);
// Slip / U at each wall against that wall's roughness (against U when the case has one roughness).
std::vector<Figure> slip_figures(const Collection& col);
// Mean solid fraction / nu_max per solver and point (and the fill target).
Figure solid_fraction_figure(const Collection& col, double case_nu_max);

std::string point_slug(const OperatingPoint& p);  // "U2.0_R0.25" -> "u2-0_r0-25"
std::string name_slug(const std::string& s);      // a file-name part: "my Solver" -> "my-solver"

}  // namespace granlub::postproc
