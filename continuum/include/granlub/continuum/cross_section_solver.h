// Vertex-centred finite volumes + Newton on the trough's cross-section (cross_section_problem.h), the 1-D
// solver's method (fv_solver.h) in 2-D:
//   unknowns (u^, s) per node, nu = cap/(1 + e^-s); Inventory also ln Lambda with the mass constraint (bordered)
//   control volumes around the nodes (halves at walls, quarters at corners); face coefficients node averages;
//   a wall face of a control volume takes its flux from its own wall's condition at that node (wall_condition.h),
//   so a corner node carries two walls' conditions, one on each of its two wall faces
//   exact Jacobian: node closures in Dual<1>, the 5-point stencil (9-point with the contact shear, whose face
//   fluxes need the tangential gradient) (+ ln Lambda) in Dual<19>
//   linear algebra: Eigen SparseLU, pattern analysed once, the matrix values refilled in place
#pragma once
#include <string>

#include "granlub/continuum/cross_section_problem.h"
#include "granlub/continuum/fv_solver.h"

namespace granlub::continuum {

// Newton from `s` (on the settings' grid); `s` holds the last iterate.
NewtonReport newton_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st,
                                  CrossSectionSolution& s);

// Full solve: the 1-D solution of the same gap (solve_fv on the same nodes in y^) extended over z^ as the
// initial guess, Newton, and continuation in ln Lambda and ln Pi (as the 1-D solver) when Newton fails; with a contact
// stress the continuation in it (contact_continuation.h). With body forces, then Picard passes: the pressure field of
// their potential part from the last solution (the top wall's mean = the load), Newton at that pressure (with a
// contact stress pi_c = p_c/p and the cap nu_P at each node's p), until it moves < 1e-10; the solution keeps it
// (`pressure`). Throws granlub::SolverError.
CrossSectionSolution solve_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st);

// The largest relative difference between the exact Jacobian at `s` and central differences with steps `step`
// (Load mode; tests). Both functions take the pressure field of `p`, or else the solution's (`s.pressure`, fixed as
// in a Picard pass).
double cross_section_jacobian_defect(const CrossSectionProblem& p, const CrossSectionSolution& s, double step);

// Max-norm residual of a solution (tests).
double cross_section_residual(const CrossSectionProblem& p, const CrossSectionSolution& s);

}  // namespace granlub::continuum
