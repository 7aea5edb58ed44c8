// The results of a load-controlled particle run (granlub/servo.h), shared by `granlub dem` and
// `granlub yade`: the steady window of the wall stresses and the plate, the mean gap, the plate
// history file gap.csv, and what summary.json gets (gap, mean_solid_fraction, run.load_control).
// Inputs are engine-independent series: wall-force blocks of sample_every steps (the step at the
// end of each block) and the plate position at the end of each servo window.
#pragma once
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/block_average.h"
#include "granlub/results.h"
#include "granlub/servo.h"
#include "granlub/steady_state.h"

namespace granlub {

inline constexpr const char* kGapFile = "gap.csv";  // the plate history, granlub's format

// Mean gap (m) and its block standard error over the steady part of the plate history.
BlockEstimate mean_gap(const PlateSeries& plate, const SteadyWindow& w, std::size_t blocks);

// The top-wall normal stress (Pa) averaged over each servo window of the plate history (the
// wall-force blocks inside it; -1 for a window without blocks). `top_stress` per wall block.
std::vector<double> window_stresses(const ServoSettings& s, std::span<const double> wall_step,
                                    std::span<const double> top_stress, const PlateSeries& plate);

// gap.csv: time_s, gap_m, normal_stress_top_Pa (the top-wall stress averaged over each servo window).
std::string gap_csv(const ServoSettings& s, double time_step, std::span<const double> wall_step,
                    std::span<const double> top_stress, const PlateSeries& plate, const std::string& comment);

// Under load: sets outputs "gap" (m, the mean plate position) and "mean_solid_fraction" = N V_grain
// / (A gap) (exact for the grain count; slabs ending at the mean gap would miss grains while the
// plate is above it), reads outputs "normal_stress_top", and returns run.load_control (target,
// P_top / target, gap statistics, updates at a plate limit or with a clamped error, gap_file).
// `line` gets the one-line summary suffix (" gap=... (P_top/P=...)").
struct LoadSummaryInputs {
    const ServoSettings& servo;
    double initial_gap;                // m, the case's H (the plate's start)
    std::span<const double> wall_step;
    std::span<const double> top_stress;
    const PlateSeries& plate;
    const SteadyWindow& window;
    std::size_t blocks;
    std::size_t grains;
    double solids_volume;              // m^3, the grains' volume (particles.h, solids_volume)
    double area;                       // m^2, the wall area L W
};
nlohmann::json load_summary(const LoadSummaryInputs& in, std::map<std::string, Scalar>& outputs, std::string& line);

}  // namespace granlub
