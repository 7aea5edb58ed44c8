// A result's regime status: is a solver's result the steady state it is meant to be?
// Every solver writes it into summary.json's run block; the report reads it and never shows a
// transient as a result.
//
//   run.status         "steady" | "transient" | "dt-unconverged" | "ordered" | "incomplete"
//   run.status_reason  one sentence: why (empty for a plain steady result)
//   run.dt_refinement  optional: the same point rerun at half the time step, see below
//
// A summary without run.status (written before the field existed) reads as Unknown: steadiness
// is not invented. A steady result whose dt_refinement record shows that halving the time step
// moves the answer (dt_unconverged_reason) reads as DtUnconverged.
#pragma once
#include <map>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "granlub/results/results.h"

namespace granlub {

enum class RegimeStatus {
    Steady,         // a steady state was reached (or the solver is steady by construction)
    Transient,      // the run ended before a steady state was detected
    DtUnconverged,  // steady, but halving the time step changes the answer
    Ordered,        // a continuum solution its own theory calls ordered (crystallization criterion):
                    // outside the theory's validity, labelled, never drawn as a number
    Incomplete,     // a point pooled over seeds (seed_pool.h) that some of its seeds are still missing
                    // from: not an answer until every one is there
    Unknown,        // the summary does not say (older summaries)
};

std::string to_string(RegimeStatus s);  // "steady", "transient", "dt-unconverged", "ordered", "incomplete", "unknown"
// The written names only ("unknown" is never written); nothing for any other text.
std::optional<RegimeStatus> regime_status_from_string(std::string_view s);

struct Regime {
    RegimeStatus status = RegimeStatus::Unknown;
    std::string reason;
    bool steady() const { return status == RegimeStatus::Steady; }
};

// Writes run.status and run.status_reason (run must be a JSON object or null).
void set_regime(nlohmann::json& run, RegimeStatus status, const std::string& reason = "");

// Reads a summary's run block: Unknown when run.status is absent, and also (with the reason
// saying why) when it is not one of the written names or the dt_refinement record is malformed.
Regime read_regime(const nlohmann::json& run);

// The half-time-step record a solver may add as run.dt_refinement, all changes "refined minus
// original" (the answer minus the run at twice its step; after a second halving, [dem]
// refine_halvings = 2, that run is "half_step_run" and the failed first pair is "first_check"):
//   {"time_step_s": <refined step>,
//    "mean_solid_fraction": {"change": <absolute change of the mean solid fraction>},
//    "shear_stress_bottom": {"relative_change": <change / original>, "z": <change / combined stderr>},
//    "shear_stress_top":    {"relative_change": ..., "z": ...}}
// Thresholds (ours): the point is not converged in the time step when |change of nu_bar| >
// kDtMaxSolidFractionChange, or a wall shear stress moves by more than kDtMaxRelativeStressChange
// AND by more than kDtMaxStressZ combined standard errors (a change within the noise is no change).
inline constexpr double kDtMaxSolidFractionChange = 0.005;
inline constexpr double kDtMaxRelativeStressChange = 0.07;
inline constexpr double kDtMaxStressZ = 2.0;
// Empty when the record shows convergence; otherwise the reason. Throws Error naming the key when
// the record is malformed.
std::string dt_unconverged_reason(const nlohmann::json& dt_refinement);

// The run the answer was checked against, from a run.dt_refinement record: its "half_step_run"
// after a second halving ([dem] refine_halvings = 2), else its "full_step_run"; run is null when
// that record is absent or not an object (or dt_refinement is not an object).
struct DtCheckRun {
    const nlohmann::json* run = nullptr;
    bool second_halving = false;  // the answer is the quarter-step run, checked against the half step
};
DtCheckRun dt_check_run(const nlohmann::json& dt_refinement);

// Whether a Delta-t check should be repeated one halving finer ([dem] refine_halvings = 2), from the
// two runs' own run blocks and their record (dt_refinement_record): nullopt when the finer run is
// not steady (it is the answer: a transient, to be run longer, not refined); "" when the pair is
// converged; otherwise why not: the rule's reason, or that the coarser run never reached a steady
// state (no check against it is possible, while the finer run can still be checked one step finer).
std::optional<std::string> dt_check_failure(const nlohmann::json& coarse_run, const nlohmann::json& fine_run,
                                            const nlohmann::json& record);

// Writes the record above from the outputs of the original run and of the rerun at
// refined_time_step: mean_solid_fraction {"change", "original", "refined"}, and for each of the
// stresses and slips present in both, {"relative_change", "z", "original", "refined",
// "original_stderr", "refined_stderr"}. z = change / sqrt(se_o^2 + se_r^2); without any standard
// error a change counts as 1e300 standard errors (JSON has no infinity). Throws Error when the
// mean solid fraction or a wall shear stress is missing.
nlohmann::json dt_refinement_record(double refined_time_step, const std::map<std::string, Scalar>& original,
                                    const std::map<std::string, Scalar>& refined);

}  // namespace granlub
