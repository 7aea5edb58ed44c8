// The closures' free constants fitted on the bulk rheology measured apart (issue 73 items 1-2; continuum/README.md
// "Fitting the closures' constants"): weighted nonlinear least squares of the homogeneous simple shear of the
// closures (simple_shear.h) at each answer row's I and P against the row's mu and nu (and optionally
// T/(d gamma_dot)^2), each residual in units of the row's own standard error, by GSL's gsl_multifit_nlinear
// (trust region, Levenberg-Marquardt). What `granlub continuum-fit` runs.
// The wall constant slip_dissipation (f_t) is fitted on the table's walls' columns (the DEM's slips and T next to the
// bulk case's bumpy walls) against the continuum's own 1-D load-controlled solve of the bulk case at each answer's
// point with the fitted case's [continuum] (src/wall_fit.h), alone or jointly with the closures' constants.
#pragma once
#include <string>
#include <vector>

#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/simple_shear.h"
#include "granlub/particles/bulk_rheology_table.h"

namespace granlub::continuum {

// The [continuum] keys a fit may free: correlation_constant (correlation_length = "jenkins_berzi"), the five
// contact_* constants (contact_stress = "johnson_jackson") and max_solid_fraction (g0's nu_max, also the contact
// stress's nu_c), and the wall constants slip_dissipation (f_t) and r5 (R5 at both walls), fitted on the walls'
// columns.
const std::vector<std::string>& fittable_keys();
// The default free set of a case: the constants of the branches it chooses (not max_solid_fraction).
std::vector<std::string> default_free_keys(const Settings& s);

struct FitOptions {
    std::vector<std::string> free;  // keys of fittable_keys(); empty = default_free_keys(s)
    bool temperature = false;       // fit T/(d gamma_dot)^2 as well (default: mu and nu; T printed)
    // For a wall key in `free`: the bulk case whose walls the table measured, with the fitted case's [continuum]
    // section (bulk_case_for), and the table's missing wall columns (BulkRows::missing_wall_columns).
    const Case* bulk = nullptr;
    std::vector<std::string> missing_wall_columns;
};

// The bulk case `bulk` with the [continuum] section of `fitted`: the closures, wall conditions and settings of the
// case being fitted applied to the bulk case's geometry, walls and points. The section's declarations are
// `fitted`'s (its schema): `fitted` must outlive the result.
Case bulk_case_for(const Case& bulk, const Case& fitted);

struct FitConstant {
    std::string key;
    double start = 0, value = 0;
    double error = 0;         // one standard error from the covariance, the table's errors taken as given
    bool determined = true;   // false: its Jacobian column depends on the others (GSL's covar drops it)
    bool no_effect = false;   // its Jacobian column is zero: no row depends on it there (e.g. L* = 1 at every row)
    bool moved_inside = false;  // the case's value sat on the edge of the allowed range; the fit started inside
    double fit_start = 0;       // where the fit started (start, or inside the range when moved_inside)
    double low = 0, high = 0;   // the range the fit keeps it in (the key's declared range)
};

struct FitRow {
    BulkRow row;
    SimpleShear model;         // the closures' homogeneous shear at the row's I and P with the fitted constants
    double mu = 0, nu = 0, T = 0;  // (model - table)/error; T's only when the error is > 0; NaN: not reached
    // with a wall key free: the bulk case's 1-D solve at the row's point, and its (model - table)/error
    WallLayers walls;
    double slip_bottom = 0, slip_top = 0, T_bottom = 0, T_top = 0;
};

struct FitResult {
    std::vector<FitConstant> constants;
    std::vector<std::vector<double>> correlation;  // of the constants, from the covariance
    std::vector<FitRow> rows;
    bool temperature = false;  // whether T was fitted
    bool core = true;          // whether the core's mu, nu (T) were fitted (a closure constant free)
    bool walls = false;        // whether the walls' slips and T were fitted (a wall key free)
    double chi2 = 0;
    std::size_t residuals = 0, dof = 0;
    double p_value = 0;  // P(chi2 >= the fit's) for dof degrees of freedom, the errors taken as given
    std::size_t iterations = 0;
    std::string stop;  // why the iteration stopped
};

// Throws CaseError for what the user can change: a key that cannot be freed in this case (naming the keys that
// can), fewer answers than free constants (how many are needed), an answer whose error is not > 0, a row whose I
// the closures cannot reach at the case's constants (naming the row and the range they cover); SolverError when
// the iteration does not converge.
FitResult fit_bulk_rheology(const Settings& s, const std::vector<BulkRow>& answers, const FitOptions& o,
                            const std::string& source);

// What the command prints: the constants with their errors and correlations, every row's residuals, chi2/dof.
std::string fit_report(const FitResult& r);
// The TOML fragment: the fitted constants under [continuum], `provenance` as comment lines above them.
std::string fit_fragment(const FitResult& r, const std::vector<std::string>& provenance);

}  // namespace granlub::continuum
