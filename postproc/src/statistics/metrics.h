// The comparison metrics: for each pair of solvers and each point, RMS and max difference of each
// normalised profile and the difference of each scalar with its combined standard error; for
// each solver, the fitted wall-stress-speed exponent. Written as results/report/metrics.csv.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "results/collect.h"
#include "statistics/stats.h"

namespace granlub::postproc {

struct MetricRow {
    std::string kind;      // "profile", "scalar" or "exponent"
    std::string point;     // point id; for "exponent" the speed group ("all" when one group)
    std::string quantity;  // u_over_U, nu_over_numax, T_over_U2, a summary output or derived ratio
    std::string solver_a, solver_b;  // solver_b empty for "exponent"
    std::optional<double> a, a_stderr, b, b_stderr;  // scalar values; for "exponent" a = n
    std::optional<double> difference, combined_stderr, z;  // a - b, sqrt(se_a^2 + se_b^2), diff/se
    std::optional<double> rms, max, y_at_max, noise_rms;   // profiles
    std::optional<int> fit_points;                          // exponents
    std::string status_a, status_b;  // Run::state_name() of each; for "exponent" the fit's ("steady" or empty)
    std::string note;                // why a number is absent ("not compared: dem is transient", "not fitted: ...")
    bool significant() const { return z && std::abs(*z) > 2; }
};

// Points that differ only in speed, for the stress-speed fits; and points that differ only in
// roughness, for the slip plots. label is empty when all points form one group.
struct PointGroup {
    std::string label;
    std::vector<const OperatingPoint*> points;
};
std::vector<PointGroup> speed_groups(const std::vector<const OperatingPoint*>& points);
std::vector<PointGroup> roughness_groups(const std::vector<const OperatingPoint*>& points);

inline constexpr const char* kStressOutputs[] = {"normal_stress_bottom", "normal_stress_top", "shear_stress_bottom",
                                                 "shear_stress_top"};

// The stress-speed fit of one solver over one speed group: steady points only, at least
// kMinFitPoints of them (transients are shown, never fitted).
inline constexpr int kMinFitPoints = 3;
struct StressFit {
    std::optional<PowerFit> fit;
    int steady_points = 0, other_points = 0;  // usable points in the group: steady, and not steady
    std::string why_not;                      // when no fit: "not fitted: 2 steady points (needs 3)"
};
// Under load control the normal stresses are the control variable (the top one is held at the
// target): they are never fitted.
bool controlled_stress(const PointGroup& group, const std::string& q);
StressFit stress_fit(const Collection& col, const PointGroup& group, const std::string& solver, const std::string& q);

std::vector<MetricRow> compute_metrics(const Collection& col);
std::string metrics_csv(const std::vector<MetricRow>& rows);
inline constexpr const char* kMetricsHeader =
    "kind,point,quantity,solver_a,solver_b,a,a_stderr,b,b_stderr,difference,combined_stderr,z,significant,"
    "rms_difference,max_difference,y_over_H_at_max,noise_rms,fit_points,status_a,status_b,note";

}  // namespace granlub::postproc
