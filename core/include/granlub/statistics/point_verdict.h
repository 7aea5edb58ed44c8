// One verdict per operating point from the flow-regime records of every particle engine that ran
// it (run.flow_regime, flow_regime.h): the report shows this, not one verdict per engine.
//
// Each engine's verdict is flow_regime.h's. The point's is
//   that verdict when every engine that decided agrees and none has its coordination number Z
//     within kTransitionSigmas block errors of kEnduringMinCoordination (a point pooled over seeds:
//     the seeds' standard errors, seed_pool.h);
//   "at the transition" when the engines disagree (one contact, one collision lubrication) or an
//     engine's Z lies within those errors of the threshold: the numbers sit on the boundary and
//     the criterion gives each engine's Z (± error) and persistence beside the thresholds;
//   "undetermined" when no engine decided.
//   "at the transition" also when an engine's time-step check (run.dt_refinement) has its own
//     record: when the run at twice the step falls on the other side, or when the answer's Z lies
//     closer to the threshold than the check moved it (|Z - 4| < |Z(2 dt) - Z(dt)|, the time
//     step's error estimate of Z, as dt_error is the stresses': the methods converge at first
//     order, so the dt -> 0 value may lie that far beyond the answer).
// kTransitionSigmas = 2 [ASSUMPTION] ours: a Z two block errors from 4 could as well lie on its
// other side in a rerun. The persistence has no error (two intervals after the run): only the
// engines' disagreement, or the step's, puts it at the transition.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace granlub {

inline constexpr double kTransitionSigmas = 2.0;

struct EngineRegime {
    std::string engine;       // "dem", "yade"
    nlohmann::json flow_regime;  // its run.flow_regime (any verdict_version)
    nlohmann::json coarser;   // the flow_regime of its time-step check's run at twice the step; null: none
};
// An engine's record from its summary's run block: run.flow_regime, and the time-step check's
// coarser run's (run.dt_refinement.half_step_run after a second halving, else full_step_run),
// when the check recorded one. The one reader of both for the report.
EngineRegime engine_regime(const std::string& engine, const nlohmann::json& run);

enum class PointRegime { Contact, Collision, Transition, Undetermined };
std::string to_string(PointRegime r);  // "contact lubrication", "collision lubrication", "at the transition",
                                       // "undetermined"

struct PointVerdict {
    PointRegime regime = PointRegime::Undetermined;
    std::string criterion;  // each engine's numbers and verdict, and why the point reads as it does
    std::string brief;      // the short form: "dem Z = 4.35 (contact), yade Z = 3.92 (collision)"
    bool engines_disagree = false;  // at the transition because the engines' verdicts differ
    bool step_moves = false;        // at the transition because the time step moves Z across, or as far
};
PointVerdict point_verdict(const std::vector<EngineRegime>& runs);

}  // namespace granlub
