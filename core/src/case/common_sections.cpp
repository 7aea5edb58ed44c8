// The sections every case shares. One line per key: type, default, range, unit, doc.
// Solver sections are declared by their modules (e.g. continuum/src/section.cpp).
#include <fmt/format.h>

#include "granlub/case/grain_sizes.h"

#include "common_sections.h"
#include "granlub/case/case.h"

namespace granlub {

std::vector<SectionSpec> common_sections() {
    std::vector<SectionSpec> s;

    SectionSpec c("case", "identification");
    c.string("name", "", "short name; default: the case directory's name");
    c.string("title", "", "one-line description");
    c.string("base", "",
             "the case this one is a variant of: a case directory or file, relative to this file; its keys are read "
             "first and this file's merged over them key by key (a table not given is the base's; [case] is never "
             "inherited); \"\" = none");
    c.keys.back().input = false;  // the values it brings are the inputs, not where they were written
    s.push_back(c);

    SectionSpec g("grains", "the granular material");
    g.real_required("diameter", Range::positive(), "m",
                    "grain diameter d (with size_spread: the particle solvers' mean diameter; the continuum and the "
                    "automaton use d)");
    g.real_required("density", Range::positive(), "kg/m^3", "grain material density rho_p");
    g.real_required("restitution", Range::open_closed(0, 1), "", "grain-grain normal restitution e_p");
    g.real("friction", 0.5, Range::non_negative(), "", "grain-grain Coulomb friction coefficient (particle solvers)");
    g.real("youngs_modulus", 63e9, Range::positive(), "Pa", "Young's modulus (soft-sphere models; glass)");
    g.real("poisson_ratio", 0.23, Range{-1.0, 0.5, true, true}, "", "Poisson's ratio (soft-sphere models; glass)");
    g.real("size_spread", 0.0, Range::closed(0, kMaxSizeSpread), "",
           "particle solvers: standard deviation of the diameters over their mean d; diameters uniform in "
           "d (1 +- sqrt(3) size_spread); 0 = equal grains");
    s.push_back(g);

    SectionSpec w("walls", "both walls; [walls.bottom] and [walls.top] override per wall");
    w.real_required("restitution", Range::open_closed(0, 1), "", "grain-wall normal restitution e_w");
    w.real("friction", 0.5, Range::non_negative(), "", "grain-wall Coulomb friction coefficient");
    w.real_required("roughness", Range::unit(), "", "wall roughness R: 0 smooth, 1 rough");
    w.choice("surface", "plane", {"plane", "bumps"},
             "particle solvers: plane = a smooth frictional plane (R then applies to the continuum and the automaton "
             "only); bumps = a monolayer of fixed spheres on the plane, hexagonal, spaced so that R = sin(theta) = "
             "spacing / (bump_diameter + d) (Jenkins & Richman 1986); R = 0: the plane alone");
    w.real("bump_diameter", 0.0, Range::non_negative(), "m",
           "surface = bumps: the bumps' diameter; 0 = the largest that give R: min(d, R d / (1 - R))");
    w.choice("sides", "plane", {"plane", "as_bottom"},
             "particle solvers' side walls (a slice with width > 0; they move with the bottom wall): plane = smooth "
             "frictional planes; as_bottom = the bottom wall's surface, its bumps laid out on each side wall "
             "[ASSUMPTION: plane by default; Sawyer & Tichy 2001 do not say which surfaces their rough runs covered]").neutral_default();
    w.subtables = {"bottom", "top"};
    s.push_back(w);
    for (const char* side : {"bottom", "top"}) {
        SectionSpec ws(fmt::format("walls.{}", side),
                       fmt::format("the {} wall; keys not given take [walls]'s values", side));
        ws.real_optional("restitution", Range::open_closed(0, 1), "", "grain-wall normal restitution e_w");
        ws.real_optional("friction", Range::non_negative(), "", "grain-wall Coulomb friction coefficient");
        ws.real_optional("roughness", Range::unit(), "", "wall roughness R");
        ws.choice("surface", "", {"", "plane", "bumps"}, "particle solvers' wall: plane or bumps; \"\" = as [walls]");
        ws.real_optional("bump_diameter", Range::non_negative(), "m", "surface = bumps: the bumps' diameter");
        s.push_back(ws);
    }

    SectionSpec cell("cell", "the shear cell");
    cell.choice("geometry", "slice", {"slice", "annulus"},
                "slice: a periodic stretch of the trough of length `length`, curvature as a centripetal body force; "
                "annulus: granlub dem runs the whole ring of mean radius annulus_radius (the other solvers: the slice)");
    cell.real_required("gap", Range::positive(), "m", "gap H between the walls");
    cell.real_required("length", Range::positive(), "m",
                       "periodic length along the flow (the slice; with geometry = annulus, the solvers that run a slice)");
    cell.real("width", 0.0, Range::non_negative(), "m", "trough width between side walls; 0 = periodic");
    cell.real("annulus_radius", 0.0, Range::non_negative(), "m",
              "mean radius of the annulus: the slice's centripetal body force (0 = none), the ring's radius with "
              "geometry = annulus");
    cell.real("max_solid_fraction", 0.65, Range::open_closed(0, 0.74048), "",
              "maximum solid fraction nu_max of the continuum closures");
    s.push_back(cell);

    SectionSpec op("operating", "operating points; list-valued keys are swept (Cartesian product)");
    // Bounded: the stresses scale as U^2, which underflows to exactly 0 below ~1e-150 m/s.
    op.sweep("speed", std::nullopt, Range::closed(1e-9, 1e4), "m/s", "sliding speed U of the bottom wall");
    op.keys.back().optional_key = false;  // required
    op.choice("control", "fill", {"fill", "load"},
              "fill: mean solid fraction given, stresses out; load: normal stress given");
    op.sweep("solid_fraction", std::nullopt, Range::open(0, 1), "", "mean solid fraction (control = fill)");
    op.sweep("normal_stress", std::nullopt, Range::positive(), "Pa", "normal stress on the walls (control = load)");
    op.sweep("roughness", std::nullopt, Range::unit(), "", "roughness of both walls, overriding [walls]");
    s.push_back(op);

    SectionSpec bf("body_forces", "body forces");
    bf.real("gravity", 9.81, Range::non_negative(), "m/s^2", "gravity along -y (toward the moving wall); 0 = none");
    s.push_back(bf);

    SectionSpec rep("report", "what `granlub compare` shows besides this case's own results (no solver reads it)");
    rep.solver_input = false;
    rep.string("slice_case", "",
               "with [cell] geometry = \"annulus\": a case directory (relative to this case's) whose granlub dem "
               "results at the same point ids the report sets beside this ring's, the slice against the whole ring; "
               "\"\" = none");
    s.push_back(rep);
    return s;
}

SectionSpec particles_section() {
    SectionSpec s(kParticlesSection, "what both particle engines (dem, yade) share: the initial grains and the cell's depth");
    s.integer("seed", 1, Range::at_least(0), "seed of the initial configuration (--seed overrides)");
    s.integer_or_list("seeds", 1, Range::closed(1, kMaxIntegerList), Range::at_least(0),
                      "independent realisations of every point, pooled into one answer: N = the seeds seed, seed + 1, "
                      "... seed + N - 1, or the list of seeds itself; each its own size draw, insertion and packing, "
                      "in <point>/seed-<S>/, the point's files their mean ± the seeds' standard error (--seeds "
                      "overrides; 1 = one run, as before)");
    s.keys.back().input = false;  // which realisations run, not what any one of them is
    s.real("velocity_noise", 0.1, Range::non_negative(), "",
           "initial velocity noise per component, standard deviation / U, on the linear Couette profile");
    s.real("periodic_depth", 0.0, Range::non_negative(), "m",
           "depth across z when [cell] width = 0 (periodic); 0 = 10 grain diameters");
    return s;
}

Schema Schema::common() {
    Schema s;
    for (auto& sec : common_sections()) s.sections_.push_back(std::move(sec));
    s.sections_.push_back(particles_section());  // not common: only solvers that `use` it hash it
    return s;
}

}  // namespace granlub
