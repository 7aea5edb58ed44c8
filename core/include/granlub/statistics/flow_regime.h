// Which flow regime a particle result is in, from what the run measured: the coordination number
// and the contact persistence (contacts.h) decide ONE verdict; the inertial number is reported
// beside it as a class of its own. Every particle solver writes both into summary.json's run block
// as run.flow_regime; the thresholds live here only.
//
// The verdict: Sawyer & Tichy's two lubrication regimes (Sawyer & Tichy 2001, J. Tribol. 123:777):
// "granular contact lubrication", where the grains stay compacted in enduring
// contacts and a contact network carries the load, and "granular collision lubrication", where
// the surfaces have lifted off and binary collisions carry it. We call a network enduring when
//   Z >= kEnduringMinCoordination (4): the mean coordination number reaches the jamming value
//     z_c(mu), which runs from 6 (frictionless) down to 4 (mu -> infinity) (Silbert 2010, Soft
//     Matter 6:2918, fig. 1); below z_c the stresses are rate-dependent and fluid-like (Vescovi,
//     Berzi & di Prisco 2017, arXiv:1707.03322). Z >= 4 is thus the weakest condition for a network;
//   and persistence >= kEnduringMinPersistence (0.5) [ASSUMPTION, ours]: most contacts survive a
//     shear strain kPersistenceStrain [ASSUMPTION, ours]. Neighbours move apart at about
//     gamma_dot d, so after a strain of 0.1 a pair that only collided is ~0.1 d apart, ten times the
//     contact tolerance (contacts.h), while a pair in a network still touches.
// "contact lubrication" when both hold; "collision lubrication" when either fails (Z is checked
// first: below it no network can carry the load whatever the persistence); "undetermined" when
// what would decide was not measured (Z unknown, or Z >= 4 and the persistence unknown). The
// criterion that decided is written beside the verdict.
//
// The inertial class: I = gamma_dot d / sqrt(P / rho_p) (GDR MiDi 2004, Eur. Phys. J. E 14:341,
// eq. 1; da Cruz et al. 2005, Phys. Rev. E 72:021309, eq. 2), the ratio of the time a grain takes
// to fall into a hole under the pressure P to the shear time 1/gamma_dot. Both papers find
//   I < 1e-3          quasi-static (rate-independent friction),
//   1e-3 <= I <= 0.1  dense inertial flow (mu(I) rheology),
//   I > 0.1           rapid flow (GDR MiDi's "rapid, gaseous" regime; da Cruz's "collisional").
// We call the last class "rapid", never "collisional", so that the class cannot read as a second
// verdict on collisions: "contact lubrication, I rapid" says that a network endures at a high
// inertial number, which the two numbers measure separately.
#pragma once
#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/results/results.h"

namespace granlub {

inline constexpr double kQuasiStaticMaxInertialNumber = 1e-3;  // GDR MiDi 2004 eq. 1; da Cruz et al. 2005 eq. 2
inline constexpr double kRapidMinInertialNumber = 0.1;          // GDR MiDi 2004 eq. 1; da Cruz et al. 2005 eq. 2
inline constexpr double kEnduringMinCoordination = 4.0;         // Silbert 2010 fig. 1: z_c(mu -> infinity)
inline constexpr double kEnduringMinPersistence = 0.5;          // [ASSUMPTION] ours: most contacts survive
inline constexpr double kPersistenceStrain = 0.1;               // [ASSUMPTION] ours: strain U/H t between snapshots

// Contact persistence is measured alike in every particle engine: after the run, kPersistenceIntervals
// + 1 snapshots persistence_every_steps() apart, pooled over the intervals (particle_pipeline.h).
inline constexpr std::int64_t kPersistenceIntervals = 2;
// Steps of a shear strain kPersistenceStrain at U/H (`shear_rate`), at least 1 and at most
// 1/kPersistenceRunFraction of the run's `steps` (the two intervals then cost at most a tenth of
// the run; YADE's 8 ms runs at 2 m/s need 200 of 8000 steps, which a hundredth cut to a strain of 0.04).
inline constexpr std::int64_t kPersistenceRunFraction = 20;
std::int64_t persistence_every_steps(double shear_rate, double time_step, std::int64_t steps);

// I = gamma_dot d / sqrt(P / rho_p); |gamma_dot| is used. Nothing unless P, d and rho_p are > 0.
std::optional<double> inertial_number(double shear_rate, double diameter, double pressure, double density);

// |du/dy| at mid-gap: the least-squares slope of u(y) over the stations in the middle third of
// [0, gap] (at least the two stations nearest the middle). y and u of the same size >= 2.
double mid_gap_shear_rate(std::span<const double> y, std::span<const double> u, double gap);

// The inertial-number class (never the verdict).
enum class InertialClass { QuasiStatic, DenseInertial, Rapid };
std::string to_string(InertialClass c);  // "quasi-static", "dense-inertial", "rapid"
InertialClass inertial_class(double inertial_number);

// Enduring contacts: Z >= kEnduringMinCoordination and persistence >= kEnduringMinPersistence;
// false when either is unknown.
bool enduring_contacts(std::optional<double> coordination, std::optional<double> persistence);

// The one verdict and the criterion that decided it ("Z = 3.21 < 4 (...)").
enum class Lubrication { Contact, Collision, Undetermined };
std::string to_string(Lubrication l);  // "contact lubrication", "collision lubrication", "undetermined"
struct Verdict {
    Lubrication lubrication = Lubrication::Undetermined;
    std::string criterion;
};
Verdict lubrication_verdict(std::optional<double> coordination, std::optional<double> persistence);

// run.flow_regime: {"regime" (the verdict, to_string(Lubrication)), "criterion" (what decided it),
// "inertial_class" (to_string(InertialClass) of "inertial_number"; null without one),
// "enduring_contacts", "inertial_number" (the classified one, mid-gap when known, else nominal),
// "inertial_number_nominal" (gamma_dot = U/H), "inertial_number_mid_gap", "coordination_number",
// "contact_persistence", "reason" (one sentence: verdict, criterion, inertial class),
// "verdict_version" (2), "thresholds"}; unknown values are null. Summaries written before
// verdict_version 2 had "regime" = the inertial class (with "collisional" for I > 0.1) and no
// "criterion": read_flow_verdict reads both.
struct FlowDiagnostics {
    std::optional<double> inertial_nominal, inertial_mid_gap, coordination, persistence;
    std::optional<double> coordination_stderr = {};  // block error of Z: "coordination_number_stderr"
};
nlohmann::json flow_regime_json(const FlowDiagnostics& d);
// The diagnostics a run.flow_regime record was made from (its numbers; absent or null: unknown).
FlowDiagnostics read_flow_diagnostics(const nlohmann::json& flow_regime);

// A run.flow_regime record of any version as the verdict, its criterion and the inertial class
// ("" when unknown). An older record's verdict is recomputed from its coordination number and
// persistence with today's thresholds, and its criterion says so.
struct FlowVerdict {
    Lubrication lubrication = Lubrication::Undetermined;
    std::string criterion;
    std::string inertial_class;
    std::optional<double> inertial_nominal, inertial_mid_gap;
    std::string label() const;  // "contact lubrication (I dense-inertial)"
};
FlowVerdict read_flow_verdict(const nlohmann::json& flow_regime);

// Fills d's two inertial numbers from a coarse-grained profile (columns y_over_H, u_over_U) of a gap
// H sheared at U under the mean wall normal stress P (Pa).
void set_inertial_numbers(FlowDiagnostics& d, const Profile& profile, double U, double H, double P, double diameter,
                          double density);

}  // namespace granlub
