// The numbers behind the comparison: profile differences on a common grid, differences of
// scalars with combined standard errors, and the power-law fit stress ~ U^n.
#pragma once
#include <optional>
#include <vector>

namespace granlub::postproc {

// Linear interpolation of (x, y) at xq; x ascending. Outside [x.front(), x.back()] the end
// value is held (callers stay inside the overlap).
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double xq);

struct ProfileDifference {
    double rms = 0;        // sqrt(mean (a - b)^2) on the common grid
    double max = 0;        // max |a - b|
    double y_at_max = 0;   // where max occurs (y/H)
    std::optional<double> noise_rms;  // sqrt(mean (se_a^2 + se_b^2)): the difference expected from noise alone
    double lo = 0, hi = 0;  // the overlap of the two station ranges that was compared
};

// a and b sampled at their own stations ya, yb (ascending y/H); se_* empty when not statistical.
// Compared on kGridPoints evenly spaced points over the overlap of the two station ranges.
inline constexpr int kGridPoints = 101;
ProfileDifference profile_difference(const std::vector<double>& ya, const std::vector<double>& a,
                                     const std::vector<double>& se_a, const std::vector<double>& yb,
                                     const std::vector<double>& b, const std::vector<double>& se_b);

// sqrt(a^2 + b^2) of the standard errors present; absent when neither is present.
std::optional<double> combined_stderr(std::optional<double> a, std::optional<double> b);

struct PowerFit {
    double exponent = 0;               // n in y = c x^n
    double prefactor = 0;              // c
    std::optional<double> exponent_stderr;
    int points = 0;
    bool weighted = false;             // by the standard errors of y
};

// Least squares on log y = log c + n log x. Weighted by (se_y / y)^-2 when every point has a
// standard error, the slope error then scaled by sqrt(chi^2/dof) when that exceeds 1 (Birge
// ratio); otherwise ordinary least squares with the error from the residuals (none for 2 points).
// Needs >= 2 points with distinct x > 0 and y > 0; returns nothing otherwise.
std::optional<PowerFit> power_fit(const std::vector<double>& x, const std::vector<double>& y,
                                  const std::vector<std::optional<double>>& se_y);

}  // namespace granlub::postproc
