// Which flow regime a particle result is in, from what the run measured: the inertial number,
// the coordination number and the contact persistence (contacts.h). Every particle solver writes
// the verdict into summary.json's run block as run.flow_regime; the thresholds live here only.
//
// Inertial number I = gamma_dot d / sqrt(P / rho_p) (GDR MiDi 2004, Eur. Phys. J. E 14:341, eq. 1;
// da Cruz et al. 2005, Phys. Rev. E 72:021309, eq. 2): the ratio of the time a grain takes to
// fall into a hole under the pressure P to the shear time 1/gamma_dot. Both papers find
//   I < 1e-3          quasi-static (rate-independent friction, enduring contacts),
//   1e-3 <= I <= 0.1  dense inertial flow (mu(I) rheology),
//   I > 0.1           collisional (rapid, kinetic-theory) flow.
// Enduring contacts: a contact network carries the stress when the mean coordination number Z
// reaches its jamming value z_c(mu), which runs from 6 (frictionless) down to 4 (mu -> infinity)
// (Silbert 2010, Soft Matter 6:2918, fig. 1); below z_c the stresses are rate-dependent and
// fluid-like (Vescovi, Berzi & di Prisco 2017, arXiv:1707.03322). Z >= 4 is thus the weakest
// condition for a network; we also ask that most contacts survive a short shear strain
// (persistence >= kEnduringMinPersistence after a strain kPersistenceStrain). Neighbours move
// apart at about gamma_dot d, so after a strain of 0.1 a pair that only collided is ~0.1 d apart,
// ten times the contact tolerance (contacts.h), while a pair in a network still touches.
#pragma once
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/results/results.h"

namespace granlub {

inline constexpr double kQuasiStaticMaxInertialNumber = 1e-3;  // GDR MiDi 2004; da Cruz et al. 2005
inline constexpr double kCollisionalMinInertialNumber = 0.1;   // GDR MiDi 2004; da Cruz et al. 2005
inline constexpr double kEnduringMinCoordination = 4.0;        // Silbert 2010: z_c(mu -> infinity)
inline constexpr double kEnduringMinPersistence = 0.5;         // ours: most contacts survive
inline constexpr double kPersistenceStrain = 0.1;              // ours: shear strain U/H t between snapshots

// I = gamma_dot d / sqrt(P / rho_p); |gamma_dot| is used. Nothing unless P, d and rho_p are > 0.
std::optional<double> inertial_number(double shear_rate, double diameter, double pressure, double density);

// |du/dy| at mid-gap: the least-squares slope of u(y) over the stations in the middle third of
// [0, gap] (at least the two stations nearest the middle). y and u of the same size >= 2.
double mid_gap_shear_rate(std::span<const double> y, std::span<const double> u, double gap);

enum class FlowRegime { QuasiStatic, DenseInertial, Collisional };
std::string to_string(FlowRegime r);  // "quasi-static", "dense-inertial", "collisional"
FlowRegime flow_regime(double inertial_number);

// Enduring contacts: Z >= kEnduringMinCoordination and persistence >= kEnduringMinPersistence;
// false when either is unknown.
bool enduring_contacts(std::optional<double> coordination, std::optional<double> persistence);

// run.flow_regime: {"regime", "enduring_contacts", "inertial_number" (the classified one, mid-gap
// when known, else nominal), "inertial_number_nominal" (gamma_dot = U/H), "inertial_number_mid_gap",
// "coordination_number", "contact_persistence", "reason", "thresholds"}; unknown values are null.
struct FlowDiagnostics {
    std::optional<double> inertial_nominal, inertial_mid_gap, coordination, persistence;
};
nlohmann::json flow_regime_json(const FlowDiagnostics& d);

// Fills d's two inertial numbers from a coarse-grained profile (columns y_over_H, u_over_U) of a gap
// H sheared at U under the mean wall normal stress P (Pa).
void set_inertial_numbers(FlowDiagnostics& d, const Profile& profile, double U, double H, double P, double diameter,
                          double density);

}  // namespace granlub
