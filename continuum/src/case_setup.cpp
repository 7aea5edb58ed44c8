#include "granlub/continuum/case_setup.h"

#include <chrono>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "granlub/case/particle_box.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/continuum/walls/flat_wall.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"
#include "granlub/continuum/closures/effective_restitution.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/cross_section_setup.h"
#include "granlub/continuum/fv_solver.h"
#include "granlub/continuum/shooting_solver.h"
#include "granlub/continuum/simple_shear.h"
#include "granlub/error.h"
#include "granlub/results/run_status.h"

namespace granlub::continuum {

namespace {
// [continuum] wall_energy (docs/continuum-model.md §4.5): S&T's R8-weighted slip work stays the seed's own model
// (lun84); every other closure family takes the slip work whole, as the wall conditions' sources write it.
void resolve_wall_energy(const Section& sec, Settings& s) {
    const std::string& we = sec.string("wall_energy");
    const bool gkl = we == "gkl_r8" || (we == "by_closures" && s.closures_name == "lun84");
    s.wall_energy = gkl ? WallEnergy::GklR8 : WallEnergy::SlipWork;
    s.wall_energy_source = we == "by_closures" ? fmt::format("closures = {}", s.closures_name) : "[continuum] wall_energy";
    if (gkl) return;
    for (const std::string k : {"r8", "r8_bottom", "r8_top"})
        if (sec.has(k))
            sec.fail(k, fmt::format("{} weights the slip work in the GKL energy condition (wall_energy = \"gkl_r8\"), "
                                    "but the slip work enters whole here (wall_energy = \"slip_work\", from {}); "
                                    "allowed: remove {}, or wall_energy = \"gkl_r8\"",
                                    k, s.wall_energy_source, k));
}

// A choice that needs each point's load: refuse fill control, naming the key, the point and the alternative.
void refuse_fill_control(const Case& c, const Section& sec, const char* key, const std::string& why,
                         const std::string& alternative) {
    for (const OperatingPoint& p : c.points)
        if (p.control != Control::Load)
            sec.fail(key, fmt::format("{}, but point {} has [operating] control = fill (allowed: control = \"load\", "
                                      "or {})",
                                      why, p.id, alternative));
}

// [continuum] contact_stress (docs/continuum-model.md §2.9): every constant required with it and refused without
// it; its nu_c is g0's nu_max. Fr stays in Pa here; problem_for divides it by each point's P_y.
void resolve_contact_stress(const Case& c, const Section& sec, Settings& s, double numax) {
    static const std::vector<std::pair<const char*, const char*>> keys = {
        {"contact_coefficient", "Fr, Pa"},
        {"contact_onset_fraction", "nu_min"},
        {"contact_exponent_onset", "n"},
        {"contact_exponent_jamming", "m"},
        {"contact_friction", "mu_c"}};
    const std::string& model = sec.string("contact_stress");
    if (model == "none") {
        for (const auto& [k, what] : keys)
            if (sec.has(k))
                sec.fail(k, fmt::format("{} is a constant ({}) of contact_stress = \"johnson_jackson\", but "
                                        "contact_stress = \"none\" (allowed: remove it, or contact_stress = "
                                        "\"johnson_jackson\")",
                                        k, what));
        return;
    }
    for (const auto& [k, what] : keys)
        if (!sec.has(k))
            sec.fail("contact_stress", fmt::format("contact_stress = \"{}\" needs its constant {} ({}); it has no "
                                                   "default (to be fitted on a bulk-rheology table): set {}",
                                                   model, k, what, k));
    ContactStress& cs = s.contact;  // its constants read with the plain keys (section.cpp)
    cs.jamming = numax;
    if (!(cs.onset < numax))
        sec.fail("contact_onset_fraction",
                 fmt::format("contact_onset_fraction = {} is not below nu_c = {} (g0's nu_max, [continuum] "
                             "max_solid_fraction or [cell] max_solid_fraction); allowed: below it",
                             cs.onset, numax));
    if (s.method == Method::Shooting)
        sec.fail("method", "method = \"shooting\" has no contact stress (contact_stress); allowed: \"fv\"");
    refuse_fill_control(c, sec, "contact_stress", "contact_stress needs each point's load (its pressure over P_y)",
                        "contact_stress = \"none\"");
}

// [continuum] flat_wall_impacts: whether a plane wall's impacts (wall_roughness = "built") may slide, which needs
// the wall's friction; the cross-section's plane side walls take the floor's ([walls] sides = "plane"). An elastic
// plane (e_w = 1) is refused under "built": its impacts' R6 = 1 + (2/7)/(1 - e_w^2) diverges (walls/flat_wall.h).
void resolve_flat_wall_impacts(const Case& c, const Section& sec, Settings& s) {
    s.plane_wall_impacts_slide = sec.string("flat_wall_impacts") == "stick_and_slide";
    if (!s.plane_walls_from_impact) {
        if (!sec.is_default("flat_wall_impacts"))
            sec.fail("flat_wall_impacts", "flat_wall_impacts chooses the impact law of plane walls under "
                                          "wall_roughness = \"built\" (allowed: remove it, or wall_roughness = "
                                          "\"built\")");
        return;
    }
    const bool plane_sides = s.cross_section && c.side_walls == SideWalls::Plane;
    for (const auto& [w, side] : {std::pair{&c.bottom, "bottom"}, {&c.top, "top"}}) {
        const bool plane = w->surface != WallSurface::Bumps || (w == &c.bottom && plane_sides);
        if (!plane) continue;
        const Section& ws = c.section(fmt::format("walls.{}", side));
        const auto wall_key = [&](const char* key) -> const Section& { return ws.has(key) ? ws : c.section("walls"); };
        if (!(w->restitution < 1))
            wall_key("restitution")
                .fail("restitution", fmt::format("the {} wall is a plane whose conditions come from its impact law "
                                                 "([continuum] wall_roughness = \"built\"), which has no elastic "
                                                 "limit (R6 = 1 + (2/7)/(1 - e_w^2)); allowed: restitution < 1",
                                                 side));
        if (!s.plane_wall_impacts_slide || w->friction > 0) continue;
        wall_key("friction")
            .fail("friction", fmt::format("the {} wall{} is a plane whose impacts stick and slide ([continuum] "
                                          "wall_roughness = \"built\", flat_wall_impacts = \"stick_and_slide\"), "
                                          "which needs its friction; allowed: friction > 0, or flat_wall_impacts = "
                                          "\"stick\" (every impact sticking)",
                                          side, w == &c.bottom && plane_sides ? " (and the side walls)" : ""));
    }
}
}  // namespace

Settings resolve_settings(const Case& c) {
    const Section& sec = c.section(kSolver.name);
    Settings s;
    continuum_keys().read(s, sec);  // the plain keys (section.cpp)
    s.method = sec.string("method") == "shooting" ? Method::Shooting : Method::FiniteVolume;
    s.g0_name = sec.string("g0");
    s.wall_name = sec.string("wall_model");
    s.closures_name = sec.string("closures");
    // The closures' own parameters: the Closures object built below holds them, not Settings.
    ClosureParams lp;
    lp.restitution = c.grains.restitution;
    lp.alpha = sec.real("viscosity_alpha");
    lp.dufour = sec.boolean("dufour");
    const std::string fr = sec.string("friction_restitution");
    if (fr != "none") lp.dissipation_restitution = closures::e_eff(fr, lp.restitution, c.grains.friction);
    if (sec.string("wall_friction_restitution") == "as_grains") {
        if (fr == "none")
            sec.fail("wall_friction_restitution",
                     "\"as_grains\" applies the grains' friction_restitution to the walls, and friction_restitution = "
                     "\"none\" (allowed: \"none\", or \"as_grains\" with friction_restitution = \"jenkins_zhang\" or "
                     "\"chialvo_sundaresan\")");
        s.wall_e_eff = fr;
        // every wall of every point, as the grains' e_eff below: outside [0, 1) it is no restitution
        for (const OperatingPoint& p : c.points)
            for (const auto& [w, side] : {std::pair{&p.bottom, "bottom"}, std::pair{&p.top, "top"}}) {
                const double e = closures::e_eff(fr, w->restitution, w->friction);
                if (!(e >= 0 && e < 1))
                    sec.fail("wall_friction_restitution",
                             fmt::format("as_grains gives the {} wall of point {} e_eff = {:.4f} for its restitution {} "
                                         "and friction {}; it must lie in [0, 1) (allowed: \"none\", or walls whose "
                                         "e_eff does)",
                                         side, p.id, e, w->restitution, w->friction));
            }
    }
    if (fr != "none" && !(lp.dissipation_restitution >= 0 && lp.dissipation_restitution < 1))
        sec.fail("friction_restitution", fmt::format("{} gives e_eff = {:.4f} for e_p = {} and [grains] friction = {}; "
                                                     "it must lie in [0, 1)",
                                                     fr, lp.dissipation_restitution, lp.restitution, c.grains.friction));
    const std::string& cl = s.correlation_length_name = sec.string("correlation_length");
    lp.correlation_length = cl == "jenkins2007"     ? CorrelationLength::Jenkins2007
                            : cl == "jenkins_berzi" ? CorrelationLength::JenkinsBerzi
                                                    : CorrelationLength::None;
    const std::optional<double> cc = sec.maybe_real("correlation_constant");
    if (lp.correlation_length == CorrelationLength::JenkinsBerzi && !cc)
        sec.fail("correlation_constant", "correlation_length = \"jenkins_berzi\" needs its constant c (order one, "
                                         "fitted to simulations): set correlation_constant");
    if (lp.correlation_length != CorrelationLength::JenkinsBerzi && cc)
        sec.fail("correlation_constant", fmt::format("correlation_constant = {} is the constant of correlation_length "
                                                     "= \"jenkins_berzi\", but correlation_length = \"{}\" (allowed: "
                                                     "remove it, or correlation_length = \"jenkins_berzi\")",
                                                     *cc, cl));
    if (cc) lp.correlation_constant = *cc;
    const double numax = sec.maybe_real("max_solid_fraction").value_or(c.cell.max_solid_fraction);
    // Each registry's failure against its own key.
    std::shared_ptr<const ClosureFamily> family;
    std::shared_ptr<const RadialDistribution> g0;
    const auto on_key = [&](const char* key, const auto& make) {
        try {
            make();
        } catch (const CaseError&) {
            throw;
        } catch (const Error& e) {
            sec.fail(key, e.what());
        }
    };
    on_key("closures", [&] { family = make_closure_family(s.closures_name); });
    on_key("g0", [&] { g0 = make_g0(s.g0_name, numax); });
    on_key("wall_model", [&] { s.family = make_wall_family(s.wall_name); });
    if (!family->uses_lsjc_knobs() && lp.alpha != 1.0)
        sec.fail("viscosity_alpha", fmt::format("viscosity_alpha = {} is a factor of the Lun et al. 1984 viscosity; "
                                                "closures = \"{}\" has none (allowed: 1, or closures = \"lun84\")",
                                                lp.alpha, s.closures_name));
    s.closures = std::make_shared<Closures>(lp, g0, family);
    resolve_wall_energy(sec, s);
    resolve_contact_stress(c, sec, s, numax);
    s.gap_from_inventory = sec.string("gap") == "inventory";
    if (s.gap_from_inventory) {
        refuse_fill_control(c, sec, "gap", "gap = \"inventory\" solves the gap under a given load", "gap = \"fixed\"");
        if (s.method == Method::Shooting)
            sec.fail("method", "method = \"shooting\" cannot solve for the gap (gap = \"inventory\"); allowed: \"fv\"");
    }
    s.wall_at_bump_tops = sec.string("wall_plane") == "bump_tops";
    if (s.wall_at_bump_tops && c.bottom.surface != WallSurface::Bumps && c.top.surface != WallSurface::Bumps)
        sec.fail("wall_plane", "wall_plane = \"bump_tops\" needs bumps on the walls ([walls] surface = \"bumps\"); "
                               "with plane walls allowed: \"bump_centres\"");
    const std::string roughness = sec.string("wall_roughness");
    s.roughness_from_bumps = roughness == "bumps" || roughness == "built";
    s.plane_walls_from_impact = roughness == "built";
    if (roughness == "bumps" && c.bottom.surface != WallSurface::Bumps && c.top.surface != WallSurface::Bumps)
        sec.fail("wall_roughness", "wall_roughness = \"bumps\" needs bumps on the walls ([walls] surface = \"bumps\"); "
                                   "with plane walls allowed: \"declared\", \"built\"");
    s.flat_wall_contact_slip = sec.string("flat_wall_spin") == "none" ? 1.0 : kFlatWallTorqueBalanceShare;
    if (!s.plane_walls_from_impact && !sec.is_default("flat_wall_spin"))
        sec.fail("flat_wall_spin", "flat_wall_spin is the spin of the grains beside a plane wall whose factors come "
                                   "from its impact law; allowed with wall_roughness = \"built\" only");
    // The impact law gives family K's factors with the whole slip work returned (walls/flat_wall.h).
    if (s.plane_walls_from_impact && s.wall_name != "kinetic")
        sec.fail("wall_roughness", fmt::format("wall_roughness = \"built\" gives a plane wall family K's factors "
                                               "(Walton's impact law); wall_model = \"{}\" has other terms (allowed "
                                               "with it: \"declared\", \"bumps\"; or wall_model = \"kinetic\")",
                                               s.wall_name));
    if (s.plane_walls_from_impact && s.wall_energy != WallEnergy::SlipWork)
        sec.fail("wall_roughness", fmt::format("wall_roughness = \"built\": a plane wall's flux into the flow is "
                                               "slip work minus its impacts' dissipation, but the slip work is "
                                               "weighted by R8 here ({}); allowed: wall_energy = \"slip_work\"",
                                               s.wall_energy_source));
    resolve_cross_section_settings(c, s);
    resolve_flat_wall_impacts(c, sec, s);
    // A plane wall under "built" has its friction in its impact law: with no bumpy wall the key would change nothing.
    if (s.plane_walls_from_impact && s.wall_e_eff != "none" && c.bottom.surface != WallSurface::Bumps &&
        c.top.surface != WallSurface::Bumps)
        sec.fail("wall_friction_restitution",
                 "every wall here is a plane whose friction is already in its impact law (wall_roughness = \"built\"), "
                 "so as_grains would change nothing; allowed: \"none\" (or wall_roughness = \"declared\")");
    return s;
}

namespace {
// The continuum's contact/collision criterion: Chialvo & Sundaresan 2013 (Phys. Fluids 25, 070603, Eq. 35 and
// Table 2) blend their quasi-static and inertial stresses with chi = 1/[(I0/I_m)^{3/2} + 1], I_m = I/nu,
// I0 = 0.2 [SRC: read in CFDEM-PRINCETON kineticTheoryModel.C]; the collisional part dominates (chi > 1/2)
// for I/nu > I0. I_m is local (their Eq. 35: the local I over the local nu), so the label takes I and nu at the
// same place, mid-gap. Here it only labels the point ("contact" below I0, "collision" above).
constexpr double kTransitionIm = 0.2;
nlohmann::json lubrication_record(double inertial, double nu_local) {
    const double Im = inertial / nu_local;
    return {{"verdict", Im > kTransitionIm ? "collision lubrication" : "contact lubrication"},
            {"criterion", "I/nu at mid-gap against I0 = 0.2 (Chialvo & Sundaresan 2013, Eq. 35)"},
            {"inertial_number", inertial},
            {"solid_fraction", nu_local},
            {"inertial_number_over_solid_fraction", Im}};
}

// The bulk rheology of the same closures at the solution's mid-gap I (simple_shear.h): what the walls add to mu or
// take from it is the solution's top-wall mu over this one.
nlohmann::json homogeneous_record(const Closures& c, double inertial, double mu_top) {
    try {
        const SimpleShear h = simple_shear_at_inertial(c, inertial);
        return {{"inertial_number", inertial},
                {"solid_fraction", h.nu},
                {"stress_ratio", h.stress_ratio},
                {"top_over_homogeneous", mu_top / h.stress_ratio}};
    } catch (const SolverError& e) {
        return {{"inertial_number", inertial}, {"note", e.what()}};
    }
}

// R_k at one wall: [continuum] r<k>_<side>, else r<k>, else the point's wall roughness.
double roughness_factor(const Section& sec, const std::string& rk, const char* side, double wall_r) {
    if (auto v = sec.maybe_real(rk + "_" + side)) return *v;
    if (auto v = sec.maybe_real(rk)) return *v;
    return wall_r;
}
}  // namespace

namespace {
// How much narrower the continuum's domain is than the gap between the bumps' centres, m.
double bump_offset(const Case& c, const Settings& s, const OperatingPoint& p) {
    return s.wall_at_bump_tops ? bump_protrusion(c, p.bottom) + bump_protrusion(c, p.top) : 0.0;
}
}  // namespace

std::vector<double> profile_y_over_H(const std::vector<double>& eta, double floor_offset, double H_c, double gap,
                                     const Settings& s, Summary& m) {
    m.run["wall_plane"] = {{"plane", s.wall_at_bump_tops ? "bump_tops" : "bump_centres"},
                           {"floor_y_over_H", floor_offset / gap},
                           {"top_y_over_H", (floor_offset + H_c) / gap}};
    if (!s.wall_at_bump_tops) return eta;  // the domain is the gap between the planes: bit for bit as before
    std::vector<double> y(eta);
    for (double& v : y) v = (floor_offset + v * H_c) / gap;
    return y;
}

nlohmann::json wall_roughness_record(const Case& c, const Settings& s, const OperatingPoint& p) {
    nlohmann::json r = {{"source", s.plane_walls_from_impact ? "built" : s.roughness_from_bumps ? "bumps" : "declared"},
                        {"bottom", wall_roughness(c, s, p, p.bottom, "bottom")},
                        {"top", wall_roughness(c, s, p, p.top, "top")}};
    if (s.plane_walls_from_impact) {
        const FlatWallFactors f = flat_wall_from_impact_law(p.bottom.restitution, s.flat_wall_contact_slip);
        r["plane_walls"] = {{"law", s.plane_wall_impacts_slide
                                        ? "Walton's impact law, impacts sticking and sliding at the wall's friction "
                                          "(traction and collisional terms times h(xi), g(xi) at the contact points' "
                                          "slip) (docs/continuum-model.md 4.3b)"
                                        : "Walton's impact law, every impact sticking (docs/continuum-model.md 4.3b)"},
                            {"contact_slip_share", s.flat_wall_contact_slip},
                            {"impacts", s.plane_wall_impacts_slide ? "stick_and_slide" : "stick"},
                            {"friction_bottom", p.bottom.friction}, {"friction_top", p.top.friction},
                            {"beta0", kFlatWallBeta0}, {"r5", f.r5}, {"r6_at_floor_restitution", f.r6},
                            {"slip_dissipation", f.slip_dissipation}};
    }
    return r;
}

double wall_roughness(const Case& c, const Settings& s, const OperatingPoint& p, const Wall& w, const char* side) {
    if (s.plane_walls_from_impact && w.surface != WallSurface::Bumps)
        return flat_wall_from_impact_law(w.restitution, s.flat_wall_contact_slip).r5;  // R5 of its impact law
    if (!s.roughness_from_bumps) return w.roughness;
    // sin(theta) = l/(d_w + d) of the layer the particle solvers build (Jenkins & Richman 1986; wall_bumps.h):
    // the bumps' diameter and spacing give the continuum's R, where the declared R only asked for them.
    const std::optional<BumpLayer> b = wall_bumps(c, p, w, side, particle_box(c));
    return b ? b->roughness : w.roughness;
}

WallParams plane_wall_params(const Settings& s, const Wall& w) {
    // Walton's impact law (walls/flat_wall.h) already holds the wall's friction: no e_eff on top of it.
    const FlatWallFactors f = flat_wall_from_impact_law(w.restitution, s.flat_wall_contact_slip);
    WallParams params;
    params.restitution = w.restitution;
    params.r5 = f.r5, params.r6 = f.r6, params.r7 = f.r7, params.r8 = f.r8;
    params.slip_dissipation = f.slip_dissipation;
    params.energy = s.wall_energy;
    if (s.plane_wall_impacts_slide) {
        params.impacts = flat_wall_impacts(w.restitution, w.friction, kFlatWallBeta0);
        params.contact_slip_share = s.flat_wall_contact_slip;  // the law at the contact points' slip
    }
    return params;
}

Problem problem_for(const Case& c, const Settings& s, const OperatingPoint& p) {
    const Section& sec = c.section(kSolver.name);
    Problem q;
    q.closures = s.closures;
    if (s.contact.active()) {  // pi_c = p_c/P_y at this point's load (§2.9)
        ContactStress cs = s.contact;
        cs.coefficient /= p.normal_stress;
        q.closures = std::make_shared<Closures>(s.closures->with_contact(cs));
    }
    q.Lambda = (c.cell.gap - bump_offset(c, s, p)) / c.grains.diameter;  // the continuum's own domain
    q.mode = p.control == Control::Load ? (s.gap_from_inventory ? Mode::Inventory : Mode::Load) : Mode::Fill;
    // the grains the particle solvers insert: solid_fraction over the gap between the bumps' centres
    q.inventory = p.solid_fraction * c.cell.gap / c.grains.diameter;
    q.Pi = q.mode != Mode::Fill ? c.grains.density * p.speed * p.speed / p.normal_stress : 0.0;
    // fill: the same grains in the continuum's domain (narrower than the gap with wall_plane = "bump_tops")
    const double offset = bump_offset(c, s, p);
    q.nu_mean = offset > 0 ? p.solid_fraction * c.cell.gap / (c.cell.gap - offset) : p.solid_fraction;
    const auto wall = [&](const Wall& w, const char* side) {
        WallBC bc;
        bc.family = s.family;
        if (s.plane_walls_from_impact && w.surface != WallSurface::Bumps) {
            bc.params = plane_wall_params(s, w);
            for (auto [k, v] : {std::pair{"r5", &bc.params.r5}, {"r6", &bc.params.r6}, {"r7", &bc.params.r7},
                                {"r8", &bc.params.r8}})
                *v = roughness_factor(sec, k, side, *v);  // an explicit r<k> still overrides
            if (s.r5_fit) bc.params.r5 = *s.r5_fit;
        } else {
            bc.params.restitution = w.restitution;
            // [ASSUMPTION] a wall's impacts lose energy to its friction as the grains' do: the grains' e_eff formula
            // at the wall's restitution and friction, in the dissipation only (as in the bulk)
            if (s.wall_e_eff != "none")
                bc.params.dissipation_restitution = closures::e_eff(s.wall_e_eff, w.restitution, w.friction);
            const double r = wall_roughness(c, s, p, w, side);
            bc.params.r5 = s.r5_fit ? *s.r5_fit : roughness_factor(sec, "r5", side, r);
            // Johnson & Jackson's dissipation carries no specularity: with the slip work whole it is theirs (R6 = 1).
            const bool r6_is_r = s.wall_energy == WallEnergy::GklR8 || s.family->dissipation_scales_with_roughness();
            bc.params.r6 = roughness_factor(sec, "r6", side, r6_is_r ? r : 1.0);
            bc.params.r7 = roughness_factor(sec, "r7", side, r);
            bc.params.r8 = roughness_factor(sec, "r8", side, r);
            bc.params.slip_dissipation = s.slip_dissipation;
        }
        bc.params.energy = s.wall_energy;
        if (!(bc.params.r5 > 0))
            throw SolverError(fmt::format(
                "R5 = 0 at the {} wall (from [continuum] r5_{}, r5, or the wall roughness {}): a smooth wall exerts "
                "no traction, so the GKL model has no sheared steady state (plug flow, T -> 0); set [continuum] "
                "r5_{} > 0 or use a rough wall",
                side, side, w.roughness, side));
        return bc;
    };
    q.bottom = wall(p.bottom, "bottom");
    q.top = wall(p.top, "top");
    // Elastic grains: Lun et al. (1984) collisional dissipation vanishes (gamma ~ 1 - e_p^2), the
    // solver's start (homogeneous shear, where production balances that dissipation) has no finite
    // temperature, and Newton's matrix is singular there. Said up front instead of "try more cells".
    if (c.grains.restitution >= 1.0)
        throw SolverError(fmt::format(
            "[grains] restitution = {}: perfectly elastic grains dissipate nothing in collisions (Lun et al. 1984, "
            "gamma ~ 1 - e_p^2), so the solver's homogeneous-shear start has no finite temperature; it needs "
            "e_p < 1 (results approach a limit: sawyer2001 at 2 m/s gives P = 159, 190, 194 kPa at e_p = 0.999, "
            "0.9999, 0.99999)",
            c.grains.restitution));
    if (q.mode == Mode::Fill && !(q.nu_mean < s.closures->cap()))
        throw SolverError(fmt::format("solid_fraction = {} in the continuum's domain{} is not below the closures' "
                                      "limit {} (g0 = {}); lower [operating] solid_fraction or raise [continuum] "
                                      "max_solid_fraction (default [cell] max_solid_fraction)",
                                      q.nu_mean, offset > 0 ? " (narrowed to the bumps' tops)" : "",
                                      s.closures->cap(), s.g0_name));
    return q;
}

void record_run(Summary& m, const Settings& s, const RunFacts& f) {
    m.run["iterations"] = f.iterations;
    m.run["final_residual"] = f.residual;
    m.run["continuation_steps"] = f.continuation_steps;
    m.run["solve_time_s"] = f.seconds;
    m.run["method"] = s.method == Method::Shooting ? "shooting" : "fv";
    m.run["g0"] = s.g0_name;
    m.run["wall_model"] = s.wall_name;
    if (s.wall_e_eff != "none") m.run["wall_friction_restitution"] = "as_grains";  // absent: none, as before
    if (s.contact.active())
        m.run["contact_stress"] = {{"model", "johnson_jackson"}, {"coefficient_Pa", s.contact.coefficient},
                                   {"onset_fraction", s.contact.onset}, {"jamming_fraction", s.contact.jamming},
                                   {"exponent_onset", s.contact.n}, {"exponent_jamming", s.contact.m},
                                   {"friction", s.contact.friction}};
    else
        m.run["contact_stress"] = "none";
    m.run["wall_energy"] = {{"convention", s.wall_energy == WallEnergy::GklR8 ? "gkl_r8" : "slip_work"},
                            {"source", s.wall_energy_source}};
    m.run["closures"] = s.closures_name;
    m.run["dissipation_restitution"] = s.closures->params().e_eff();
    const ClosureParams& cp = s.closures->params();
    m.run["correlation_length"] = cp.correlation_length == CorrelationLength::JenkinsBerzi
                                      ? fmt::format("{}, c = {}", s.correlation_length_name, cp.correlation_constant)
                                      : s.correlation_length_name;
    nlohmann::json warnings = nlohmann::json::array();
    if (f.nu_max_node > s.closures->numax())
        warnings.push_back(fmt::format("solid fraction {:.4f} exceeds nu_max = {} (g0 = {} has no nu_max limit)",
                                       f.nu_max_node, s.closures->numax(), s.g0_name));
    m.run["warnings"] = warnings;
    // Steady by construction: the continuum solves the steady boundary-value problem (no time
    // derivatives), and only a converged Newton solve reaches this point; a failed one throws and
    // writes no result.
    // A solution the theory itself calls ordered (the crystallization criterion) is labelled, not a number.
    if (s.ordering_fraction > 0 && f.nu_max_node > s.ordering_fraction)
        set_regime(m.run, RegimeStatus::Ordered,
                   fmt::format("the largest solid fraction {:.4f} exceeds [continuum] ordering_fraction = {}: the "
                               "grains would order (crystallization criterion), where kinetic theory does not hold",
                               f.nu_max_node, s.ordering_fraction));
    else
        set_regime(m.run, RegimeStatus::Steady);
    for (const auto& [name, v] : m.outputs)
        if (!std::isfinite(v.value))
            throw SolverError(fmt::format("the solution has a non-finite {} (residual {:.3g}); try more cells", name,
                                          f.residual));
}

PointResult solve_point(const Case& c, const OperatingPoint& p, const Settings& s) {
    const Problem q = problem_for(c, s, p);
    const auto t0 = std::chrono::steady_clock::now();
    Solution sol = s.method == Method::Shooting ? solve_shooting(q, s.solver) : solve_fv(q, s.solver);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const Observables o = observe(q, sol);

    const double U = p.speed, rho = c.grains.density;
    const double P = rho * U * U / sol.Pi;  // = normal_stress in Load mode
    const double T_scale = P / rho;         // T = (P/rho) / f_p
    const double tau_b = P * o.tau_bottom, tau_t = P * o.tau_top;
    // Gap and mean nu between the planes through the bumps' centres, as the particle solvers report them
    // (the continuum's own domain is narrower by the offset with wall_plane = "bump_tops").
    const double offset = bump_offset(c, s, p), d = c.grains.diameter;
    const double H_c = solved_problem(q, sol).Lambda * d, gap = H_c + offset;
    const double nu_mean = offset > 0 ? o.nu_mean * H_c / gap : o.nu_mean;
    // Inertial number at mid-gap, I = gamma_dot d / sqrt(P/rho_p) (GDR MiDi 2004, eq. 1), as the particle
    // solvers report it.
    const std::size_t n = sol.nodes(), ic = (n - 1) / 2;
    const double du_c = std::abs(sol.u[ic + 1] - sol.u[ic - 1]) / (sol.y[ic + 1] - sol.y[ic - 1]);
    const double inertial = (U * du_c / H_c) * d / std::sqrt(P / rho);

    PointResult r;
    std::vector<double> T_over_U2(sol.nodes());
    // q's closures: with a contact stress T = (P - p_c)/(rho_p f_p), its f_p the effective one (§2.9)
    for (std::size_t i = 0; i < sol.nodes(); ++i) T_over_U2[i] = 1.0 / (sol.Pi * q.closures->state(sol.nu[i]).fp.v);
    Summary& m = r.summary;
    m = make_summary(c, p, kSolver);
    const double floor_offset = s.wall_at_bump_tops ? bump_protrusion(c, p.bottom) : 0.0;
    r.profile.add("y_over_H", profile_y_over_H(sol.y, floor_offset, H_c, gap, s, m))
        .add("u_over_U", sol.u).add("solid_fraction", sol.nu).add("temperature_over_U2", T_over_U2);
    m.set("normal_stress_bottom", P, "Pa").set("normal_stress_top", P, "Pa");
    m.set("shear_stress_bottom", tau_b, "Pa").set("shear_stress_top", tau_t, "Pa");
    m.set("slip_bottom", U * o.slip_bottom, "m/s").set("slip_top", U * o.slip_top, "m/s");
    m.set("mean_solid_fraction", nu_mean, "").set("max_solid_fraction", s.closures->numax(), "");
    m.set("solid_fraction_centre", o.nu_centre, "").set("solid_fraction_bottom", o.nu_bottom, "")
        .set("solid_fraction_top", o.nu_top, "");
    m.set("temperature_bottom", T_scale * o.T_bottom, "m^2/s^2").set("temperature_top", T_scale * o.T_top, "m^2/s^2")
        .set("temperature_centre", T_scale * o.T_centre, "m^2/s^2");
    m.set("stress_ratio", o.tau_bottom, "").set("pi_number", sol.Pi, "");
    m.set("inertial_number", inertial, "");
    if (s.gap_from_inventory) m.set("gap", gap, "m");
    m.run["wall_roughness"] = wall_roughness_record(c, s, p);
    m.run["lubrication"] = lubrication_record(inertial, sol.nu[ic]);  // I and nu at the same node, mid-gap
    m.run["homogeneous_shear"] = homogeneous_record(*q.closures, inertial, o.tau_top);  // with the contact stress
    const EnergyBudget eb = energy_budget(q, sol);
    m.run["energy_budget"] = {{"wall_work_W_m2", P * U * eb.wall_work},
                              {"bulk_dissipation_W_m2", P * U * eb.bulk_dissipation},
                              {"wall_dissipation_W_m2", P * U * eb.wall_dissipation},
                              {"wall_collisional_W_m2", P * U * eb.wall_collisional},
                              {"wall_unreturned_slip_work_W_m2", P * U * eb.wall_unreturned_slip_work},
                              {"contact_dissipation_W_m2", P * U * eb.contact_dissipation},
                              {"relative_defect", eb.relative_defect()}};
    m.run["cells"] = s.solver.cells;
    m.run["body_forces"] = "not modelled: GKL has p_yy uniform across the gap (S&T 2001 Eq. 6b)";
    record_run(m, s, {sol.iterations, sol.residual, sol.continuation_steps, secs, o.nu_max_node});

    r.line = fmt::format("nu={:.4f} P={:.4g} Pa tau={:.4g} Pa slip={:.3f}/{:.3f} m/s it={}", nu_mean, P, tau_b,
                         U * o.slip_bottom, U * o.slip_top, sol.iterations);
    if (s.gap_from_inventory) r.line += fmt::format(" gap={:.3f} mm mu={:.3f} I={:.3f}", 1e3 * gap, o.tau_top, inertial);
    if (s.ordering_fraction > 0 && o.nu_max_node > s.ordering_fraction) r.line += " ORDERED";
    return r;
}

}  // namespace granlub::continuum
