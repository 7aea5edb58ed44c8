// When a particle run is steady, and from where: shared by `granlub dem` and `granlub yade`.
//
// Two steps, because one alone was measured to fail both ways on cases/sawyer2001 (2026-11-23,
// 0.3 s at 5.5 kPa): MSER-5 alone called U = 2.8 m/s steady from 0.055 s while its plate was
// still compacting (gap 4.24 -> 4.09 mm until ~0.2 s, bottom shear stress drifting, Geweke
// z = -3.3), and called U = 2.0 m/s a transient because a 0.5 % bump of the gap at 0.12 s moved its
// truncation point past half the run.
//  1. Start of the initial transient: MSER-5 (White 1997, Simulation 69:323; White, Cobb &
//     Spratt 2000) on each series, its truncation point searched in the first half of the run only;
//     the latest start of the series.
//  2. No drift left: from that start on, each series' first and second half of the window must
//     agree, either within 3 combined standard errors (block means; a Geweke 1992-style
//     diagnostic) when those errors are small enough to see a 25 % drift, or within a drift
//     that cannot matter (kStressDrift, kGapDrift). If a series
//     fails, the start moves on by one MSER batch until all pass. Steady = they all pass from a
//     start in the first half of the run (MSER's own rule of thumb: at least half the run is kept).
// The drift allowances are ours (the papers leave "steady" open): half of the Δt-convergence
// targets the project holds particle results to (shear stress within 7 %, |Δν̄| <= 0.005).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace granlub {

// A wall stress may drift by this fraction of its mean across the window and still be steady.
inline constexpr double kStressDrift = 0.035;
// The plate position (gap) likewise: 0.4 % of the gap is a drift of 0.0025 in ν̄ at ν̄ ≈ 0.6.
inline constexpr double kGapDrift = 0.004;
// Standard errors of each half of the window: block means of this many blocks.
inline constexpr std::size_t kDriftBlocks = 5;
// Combined standard errors a half-to-half difference may reach and still count as noise ...
inline constexpr double kDriftSigmas = 3.0;
// ... provided the check could see a drift of this fraction of the mean at kDriftSigmas: a window
// too noisy for that (YADE's 1.5 ms quick runs: wall-stress errors of 30-40 % of the mean) says
// nothing about drift and is not called steady on noise alone.
inline constexpr double kDriftResolution = 0.25;

// MSER-5 truncation point on a series of samples, in samples. `steady` is false when the best
// truncation lies beyond half of the series (no steady state detected yet). `max_cut` bounds the
// search (fraction of the series that may be cut; MSER's customary search keeps a quarter).
struct SteadyState {
    std::size_t start = 0;
    bool steady = false;
};
SteadyState detect_steady_state(std::span<const double> series, std::size_t batch = 5, double max_cut = 0.75);

// Half-to-half drift of a series over a window: second half's mean minus the first's.
struct DriftCheck {
    std::string name;
    double change = 0;      // mean(second half) - mean(first half)
    double relative = 0;    // change / |mean of the window|
    double z = 0;           // change / combined block standard error (0 if that is 0)
    double allowed = 0;     // the relative drift that passes regardless of z
    bool resolvable = true; // kDriftSigmas combined errors are below kDriftResolution of the mean
    bool pass = true;
};
DriftCheck drift_check(const std::string& name, std::span<const double> window, double allowed);

// A series to test, indexed like the wall-force blocks.
struct NamedSeries {
    std::string name;
    std::span<const double> values;
    double allowed_drift;  // relative
};

// The plate position (gap, m) at the end of each servo window (the initial position dropped).
struct PlateSeries {
    std::vector<double> step;
    std::vector<double> gap;
};

// The steady window: indices into the wall-block and plate series, its start in s, the verdict
// and the drift checks that decided it.
struct SteadyWindow {
    std::size_t wall_start = 0;
    std::size_t plate_start = 0;
    double t_start = 0;  // s
    bool steady = true;
    std::vector<DriftCheck> checks;
    nlohmann::json to_json() const;  // run.steady_state: method, allowances, checks
};

// `wall_step`: the step at the end of each wall block of sample_every steps; `plate` (load
// control, else null) is tested too, with kGapDrift.
SteadyWindow steady_window(const std::vector<NamedSeries>& wall_series, std::span<const double> wall_step,
                           std::int64_t sample_every, double time_step, const PlateSeries* plate,
                           std::int64_t servo_every);

}  // namespace granlub
