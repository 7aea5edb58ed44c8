// The closures' free constants fitted on the bulk rheology measured apart (issue 73 items 1-2; continuum/README.md
// "Fitting the closures' constants"): weighted nonlinear least squares of the homogeneous simple shear of the
// closures (simple_shear.h) at each answer row's I and P against the row's mu and nu (and optionally
// T/(d gamma_dot)^2), each residual in units of the row's own standard error, by GSL's gsl_multifit_nlinear
// (trust region, Levenberg-Marquardt). What `granlub continuum-fit` runs.
#pragma once
#include <string>
#include <vector>

#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/simple_shear.h"
#include "granlub/particles/bulk_rheology_table.h"

namespace granlub::continuum {

// The [continuum] keys a fit may free: correlation_constant (correlation_length = "jenkins_berzi"), the five
// contact_* constants (contact_stress = "johnson_jackson") and max_solid_fraction (g0's nu_max, also the contact
// stress's nu_c).
const std::vector<std::string>& fittable_keys();
// The default free set of a case: the constants of the branches it chooses (not max_solid_fraction).
std::vector<std::string> default_free_keys(const Settings& s);

struct FitOptions {
    std::vector<std::string> free;  // keys of fittable_keys(); empty = default_free_keys(s)
    bool temperature = false;       // fit T/(d gamma_dot)^2 as well (default: mu and nu; T printed)
};

struct FitConstant {
    std::string key;
    double start = 0, value = 0;
    double error = 0;         // one standard error from the covariance, the table's errors taken as given
    bool determined = true;   // false: its Jacobian column depends on the others (GSL's covar drops it)
    bool no_effect = false;   // its Jacobian column is zero: no row depends on it there (e.g. L* = 1 at every row)
    bool moved_inside = false;  // the case's value sat on the edge of the allowed range; the fit started just inside
    double low = 0, high = 0;   // the range the fit keeps it in (the key's declared range)
};

struct FitRow {
    BulkRow row;
    SimpleShear model;         // the closures' homogeneous shear at the row's I and P with the fitted constants
    double mu = 0, nu = 0, T = 0;  // (model - table)/error; T's only when the error is > 0
};

struct FitResult {
    std::vector<FitConstant> constants;
    std::vector<std::vector<double>> correlation;  // of the constants, from the covariance
    std::vector<FitRow> rows;
    bool temperature = false;  // whether T was fitted
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
