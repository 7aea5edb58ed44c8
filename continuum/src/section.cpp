// The [continuum] case section: one line per key (type, default, range, unit, doc) and, for a plain
// key, the Settings field it fills (granlub/case/bound_keys.h; resolve_settings() reads them in one
// loop).
#include "granlub/case/bound_keys.h"
#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/closures/family.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/g0/radial_distribution.h"
#include "granlub/continuum/walls/wall_family.h"

namespace granlub::continuum {

namespace {

BoundKeys<Settings> declare() {
    BoundKeys<Settings> k(
        SectionSpec(kSolver.name, "GKL continuum solver (Sawyer & Tichy 2001; closures of Lun et al. 1984)"));
    // Keys declared on s are read by hand (case_setup.cpp, cross_section_setup.cpp): their values resolve to
    // registry objects or enums, take a default from another section, go into the closures' parameters or a
    // wall's per-point roughness, or are checked against other keys.
    SectionSpec& s = k.spec;
    s.choice("method", "fv", {"fv", "shooting"},
             "fv: finite volumes + Newton (default); shooting: GSL shooting cross-check (small gaps only)");
    s.choice("closures", "lun84", closure_names(),
             "closure family: lun84 (Lun et al. 1984) or garzo_dufty (Garzo & Dufty 1999 viscosity and "
             "conductivity, as extended kinetic theory uses them)");
    s.choice("friction_restitution", "none", {"none", "jenkins_zhang", "chialvo_sundaresan"},
             "grain friction ([grains] friction) through an effective restitution in the dissipation: "
             "Jenkins & Zhang 2002 or Chialvo & Sundaresan 2013; none = frictionless");
    s.choice("wall_friction_restitution", "none", {"none", "as_grains"},
             "the walls' friction ([walls] friction) in their collisional dissipation: as_grains = friction_restitution's "
             "e_eff at the wall's restitution and friction (an assumption: a wall's impacts lose energy to friction as "
             "the grains' do); none = the wall's restitution as declared");
    s.choice("correlation_length", "none", {"none", "jenkins2007", "jenkins_berzi"},
             "correlation length L dividing the dissipation (extended kinetic theory): Jenkins 2007, or "
             "jenkins_berzi (Jenkins & Berzi 2010, at its homogeneous-shear value, constant correlation_constant); "
             "none = L = d");
    s.real_optional("correlation_constant", Range::closed(0.01, 10.0), "",
                    "c of correlation_length = jenkins_berzi (order one, fitted to simulations); needed by it, "
                    "allowed with it only");
    s.real_optional("max_solid_fraction", Range::closed(0.3, 0.75), "",
                    "nu_max where g0 diverges (random close packing); default [cell] max_solid_fraction");
    s.choice("gap", "fixed", {"fixed", "inventory"},
             "fixed: the gap is [cell] gap; inventory (control = load): the gap is solved to hold the grains the "
             "particle solvers insert ([operating] solid_fraction x [cell] gap per wall area)");
    s.choice("wall_plane", "bump_centres", {"bump_centres", "bump_tops"},
             "where the continuum meets a bumpy wall ([walls] surface = bumps): the plane through the bumps' "
             "centres, or their tops (the room the bumps leave); gap, mean nu and profile.csv's y/H are reported "
             "between the centres' planes either way");
    s.choice("wall_roughness", "declared", {"declared", "bumps", "built"},
             "R5..R8 of the walls: declared = the declared roughness; bumps = on a bumpy wall ([walls] surface = bumps) "
             "sin(theta) = l/(d_w + d) of the bumps the particle solvers build from it (their diameter and spacing, "
             "whole bumps in the periodic length); built = that on bumpy walls and, on plane walls (side walls too), "
             "the factors of their impact law (Walton's; in its stick limit without spin R5 = R7 = 2/7, R6 = 1 + "
             "(2/7)/(1 - e_w^2), f_t = 1/2; the grains' spin: flat_wall_spin; whether impacts slide: "
             "flat_wall_impacts; wall_model = kinetic, the slip work returned whole)");
    s.choice("flat_wall_spin", "torque_balance", {"torque_balance", "none"},
             "wall_roughness = built, plane walls: the spin of the grains beside them; torque_balance = their contact "
             "points slip at half the grains' slip (the torques of the wall's and the upper grains' impacts balance: "
             "an assumption), none = no spin (the grains' slip in the impact law)");
    s.choice("flat_wall_impacts", "stick_and_slide", {"stick_and_slide", "stick"},
             "plane walls under wall_roughness = built: stick_and_slide = Walton's law whole, an impact sliding where "
             "its tangential impulse would exceed [walls] friction x its normal one (friction > 0 needed): traction "
             "and dissipation fall below the stick limit's as the contact points' slip grows against sqrt(T) "
             "(Jenkins 1992); stick = every impact sticking (infinite friction): traction linear in the slip");
    k.real_optional("ordering_fraction", &Settings::ordering_fraction, Range::closed(0.3, 0.75), "",
                    "crystallization criterion: a solution whose largest nu exceeds it is labelled ordered, not "
                    "drawn as a number; default: no criterion");
    // Values are named as their files (src/g0/lun_savage.cpp); the short names they had are still read.
    s.choice("g0", "ogawa", g0_names(), "radial distribution g0(nu); nu_max is [cell] max_solid_fraction")
        .old_spellings(g0_old_names());
    s.choice("wall_model", "kinetic", wall_names(),
             "wall-condition family for B5..B8: kinetic (P-based, Jenkins-Richman-structured) or johnson_jackson")
        .old_spellings(wall_old_names());
    s.choice("wall_energy", "by_closures", {"by_closures", "gkl_r8", "slip_work"},
             "what the energy wall condition returns of the slip work: gkl_r8 the fraction R8, the rest a wall sink "
             "whatever e_w (Sawyer & Tichy's GKL form, the seed's own model); slip_work all of it, the flux into the "
             "flow being slip work minus a collisional dissipation that vanishes at e_w = 1 (Johnson & Jackson 1987, "
             "Jenkins & Richman 1986); by_closures: gkl_r8 with closures = lun84, slip_work otherwise");
    // The rate-independent contact stress (docs/continuum-model.md §2.9): no default constants, to be fitted on a
    // bulk-rheology table.
    s.choice("contact_stress", "none", {"none", "johnson_jackson"},
             "rate-independent contact stress beside the kinetic one: johnson_jackson (Johnson & Jackson 1987: "
             "p_c = Fr (nu - nu_min)^n/(nu_c - nu)^m, shear mu_c p_c, nu_c = g0's nu_max), needs every contact_* "
             "constant; none = kinetic stresses only");
    const auto contact = [](double ContactStress::*member) { return part(&Settings::contact, member); };
    k.real_optional("contact_coefficient", contact(&ContactStress::coefficient), Range::positive(), "Pa",
                    "Fr of contact_stress = johnson_jackson");
    k.real_optional("contact_onset_fraction", contact(&ContactStress::onset), Range::closed(0.3, 0.75), "",
                    "nu_min of contact_stress = johnson_jackson: no contact pressure below it");
    k.real_optional("contact_exponent_onset", contact(&ContactStress::n), Range::closed(0.0, 10.0), "",
                    "n of contact_stress = johnson_jackson");
    k.real_optional("contact_exponent_jamming", contact(&ContactStress::m), Range::closed(0.1, 10.0), "",
                    "m of contact_stress = johnson_jackson (the divergence at nu_c)");
    k.real_optional("contact_friction", contact(&ContactStress::friction), Range::closed(0.0, 2.0), "",
                    "mu_c of contact_stress = johnson_jackson: its shear over its pressure (sin phi)");
    s.real("viscosity_alpha", 1.0, Range::closed(0.0, 4.0), "",
           "LSJC viscosity factor (2 + alpha)/3; 1 = original theory, 1.6 = MFiX");
    s.boolean("dufour", true, "include the grad-nu heat-flux term of LSJC (sign uncertain, effect < 1e-4)");
    k.real("slip_dissipation", &Settings::slip_dissipation, 0.0, Range::unit(), "", "fraction f_t of slip work dissipated at the wall (R7 term)");
    for (const char* r : {"r5", "r6", "r7", "r8"}) {
        const std::string n(r);
        s.real_optional(n, Range::unit(), "", "roughness factor " + n + " at both walls; default: the wall's roughness");
        for (const char* side : {"bottom", "top"})
            s.real_optional(n + "_" + side, Range::unit(), "", "roughness factor " + n + " at the " + side +
                                                               " wall; default: " + n + ", else the wall's roughness");
    }
    // The trough's cross-section (continuum/README.md "The trough's cross-section"; cross_section_setup.cpp).
    s.choice("geometry", "gap", {"gap", "cross_section"},
             "gap: the 1-D gap between floor and top (the seed's model); cross_section: fully developed flow over the "
             "trough's cross-section H x W ([cell] width > 0), floor and side walls moving, the top still");
    k.integer("cross_section_cells_y", &Settings::cells_y, 40, Range::closed(2, 1e4),
              "geometry = cross_section: cells across the gap; at least 4 per grain diameter (4 H/d)");
    k.integer("cross_section_cells_z", &Settings::cells_z, 100, Range::closed(2, 1e5),
              "geometry = cross_section: cells across the width; at least 4 per grain diameter (4 W/d)");
    s.choice("body_forces", "off", {"off", "on"},
             "geometry = cross_section: off = the pressure uniform (the load); on = gravity ([body_forces] gravity) and "
             "the centripetal force ([cell] annulus_radius) through the potential part of their pressure field");
    k.real_optional("side_roughness", &Settings::side_roughness, Range::unit(), "",
                    "geometry = cross_section: R5..R8 of both side walls; default: [walls] sides = plane: the wall "
                    "roughness as declared, as_bottom: the floor's R5..R8");
    const auto solver = [](auto SolverSettings::*member) { return part(&Settings::solver, member); };
    k.integer("cells", solver(&SolverSettings::cells), 200, Range::closed(100, 1e6),
              "finite-volume cells across the gap (profile has cells + 1 rows)");
    k.real("tolerance", solver(&SolverSettings::tolerance), 1e-10, Range::positive(), "",
           "Newton tolerance on the max-norm flux-balance residual");
    k.integer("max_iterations", solver(&SolverSettings::max_iterations), 50, Range::closed(1, 1e4),
              "Newton iterations per solve");
    k.integer("max_continuation_steps", solver(&SolverSettings::max_continuation_steps), 200, Range::closed(1, 1e5),
              "continuation steps when the direct solve fails");
    return k;
}

}  // namespace

const BoundKeys<Settings>& continuum_keys() { return keys_once<Settings, declare>(); }

SectionSpec section() { return continuum_keys().spec; }

}  // namespace granlub::continuum
