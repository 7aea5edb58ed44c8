// From a resolved case to the dimensionless problem of one operating point, and from its
// solution back to the result files (dimensional SI in summary.json, dimensionless profile.csv).
#pragma once
#include <memory>
#include <optional>
#include <string>

#include "granlub/case/bound_keys.h"
#include "granlub/case/case.h"
#include "granlub/continuum/problem.h"
#include "granlub/run/sweep.h"

namespace granlub::continuum {

enum class Method { FiniteVolume, Shooting };

// The [continuum] section, resolved once per case.
struct Settings {
    Method method = Method::FiniteVolume;
    std::string g0_name, wall_name, closures_name, correlation_length_name;
    bool gap_from_inventory = false;  // [continuum] gap = "inventory"
    bool wall_at_bump_tops = false;   // [continuum] wall_plane = "bump_tops"
    bool roughness_from_bumps = false;  // [continuum] wall_roughness = "bumps" or "built"
    bool plane_walls_from_impact = false;  // [continuum] wall_roughness = "built": plane walls from their impact law
    double flat_wall_contact_slip = 0.5;   // [continuum] flat_wall_spin: torque_balance 1/2, none 1 (walls/flat_wall.h)
    bool plane_wall_impacts_slide = true;  // [continuum] flat_wall_impacts = "stick_and_slide" (false: "stick")
    double ordering_fraction = 0;     // crystallization criterion; 0 = none
    SolverSettings solver;
    std::shared_ptr<const Closures> closures;
    std::shared_ptr<const WallFamily> family;
    double slip_dissipation = 0;  // f_t
    // continuum-fit's trial R5 at both walls (rheology_fit.h, --free r5); never read from a case: unset, R5 is
    // [continuum] r5_<side>, r5 or the wall's roughness
    std::optional<double> r5_fit;
    // the e_eff formula the walls' dissipation takes ([continuum] wall_friction_restitution = "as_grains": the
    // grains' friction_restitution); "none": the walls' restitution as declared
    std::string wall_e_eff = "none";
    // [continuum] wall_energy resolved: the convention and where it came from (the key, or the closure family)
    WallEnergy wall_energy = WallEnergy::GklR8;
    std::string wall_energy_source;
    // [continuum] contact_stress resolved (coefficient = Fr in Pa; inactive = none)
    ContactStress contact;
    // [continuum] geometry = "cross_section" (cross_section_setup.h)
    bool cross_section = false;
    int cells_y = 40, cells_z = 100;
    double side_roughness = -1;  // < 0: not set
    bool body_forces = false;
};

// The [continuum] keys and the Settings fields the plain ones fill (src/section.cpp).
const BoundKeys<Settings>& continuum_keys();
// Throws CaseError naming the key for values the section spec cannot check alone.
Settings resolve_settings(const Case& c);
// The roughness R of one wall of a point for R5..R8: the declared one, or with wall_roughness = "bumps" (or
// "built") on a bumpy wall sin(theta) = l/(d_w + d) of the bump layer the particle solvers build (wall_bumps.h).
// A plane wall under "built" takes R5..R8 from its impact law instead (walls/flat_wall.h; plane_wall_params).
double wall_roughness(const Case& c, const Settings& s, const OperatingPoint& p, const Wall& w, const char* side);
// A plane wall's parameters from its impact law (wall_roughness = "built"; walls/flat_wall.h), before any
// explicit r<k> key: R5..R8 and f_t of the law's stick limit, its restitution, no e_eff (the law holds the
// friction), and with flat_wall_impacts = "stick_and_slide" the law at the wall's friction (flat_wall_impacts.h).
WallParams plane_wall_params(const Settings& s, const Wall& w);
// run.wall_roughness of a summary: where R5..R8 came from and each wall's R (R5 for a plane under "built").
nlohmann::json wall_roughness_record(const Case& c, const Settings& s, const OperatingPoint& p);
// The continuum's nodes, at eta = 0..1 across its own domain of height H_c whose floor lies `floor_offset`
// above the floor's wall plane (the bumps' protrusion with wall_plane = "bump_tops", else 0), as y/H on the
// one scale of every profile.csv (kProfileYDefinition, granlub/results/results.h): y from the floor's wall
// plane over the gap between the wall planes. Records where its own walls lie on that scale in the summary's
// run.wall_plane. With wall_plane = "bump_centres" the nodes are eta unchanged.
std::vector<double> profile_y_over_H(const std::vector<double>& eta, double floor_offset, double H_c, double gap,
                                     const Settings& s, Summary& m);
// Throws SolverError when the point cannot have a sheared steady state (e.g. R5 = 0).
Problem problem_for(const Case& c, const Settings& s, const OperatingPoint& p);
// What every solved point records in summary.json's run (the solve, the model's names, warnings, and the regime:
// steady, or ordered past ordering_fraction); throws SolverError on a non-finite output. Call after the outputs.
struct RunFacts {
    int iterations = 0;
    double residual = 0;
    int continuation_steps = 0;
    double seconds = 0;
    double nu_max_node = 0;
};
void record_run(Summary& m, const Settings& s, const RunFacts& f);
// Solves one point and fills profile.csv / summary.json contents.
PointResult solve_point(const Case& c, const OperatingPoint& p, const Settings& s);

}  // namespace granlub::continuum
