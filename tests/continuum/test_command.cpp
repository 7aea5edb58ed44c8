// `granlub continuum` end to end on small in-memory cases: result files, resume, --point,
// determinism, the shooting method key, and the bad-input paths (clear CaseError/SolverError).
#define BOOST_TEST_MODULE continuum_command
#include <cmath>
#include <numbers>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include <boost/test/unit_test.hpp>

#include "granlub/case/case.h"
#include "granlub/case/particle_box.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/continuum/case_setup.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/cross_section_setup.h"
#include "granlub/continuum/map.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"
#include "granlub/error.h"
#include "granlub/results/results.h"
#include "temp_dir.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

const char* kCase = R"(
[case]
name = "st_load"
[grains]
diameter = 0.787e-3
density = 2550.0
restitution = 0.9
[walls]
restitution = 0.9
roughness = 0.5
[cell]
gap = 4.0e-3
length = 30.0e-3
max_solid_fraction = 0.65
[operating]
speed = [1.4, 2.0, 2.8]
control = "load"
normal_stress = 5.5e3
)";

Schema schema() {
    Schema s = Schema::common();
    s.add(continuum::section());
    return s;
}

Case parse(const std::string& extra, const std::string& base = kCase) {
    return parse_case(base + extra, "test.toml", schema());
}

std::string case_error(const std::string& extra) {
    try {
        parse(extra);
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

using continuum::testing::TempDir;

// The error resolve_settings raises for the case with `extra` appended, or "".
std::string settings_error(const std::string& extra, const std::string& base = kCase) {
    try {
        continuum::resolve_settings(parse(extra, base));
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

// The default case with one point under fill control.
std::string fill_case() {
    const std::string base(kCase);
    return base.substr(0, base.find("[operating]")) + "[operating]\nspeed = 2.0\ncontrol = \"fill\"\nsolid_fraction = 0.5\n";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// Options that write into `tmp`, every point or only `point`.
RunOptions into(const TempDir& tmp, const std::string& point = "") {
    RunOptions o;
    o.results_root = tmp.path;
    o.point = point;
    return o;
}

}  // namespace

BOOST_AUTO_TEST_CASE(run_writes_complete_results_and_resumes) {
    TempDir tmp;
    const Case c = parse("");
    RunOptions o = into(tmp);
    BOOST_TEST(continuum::run(c, o) == 0);
    const double expect_nu[3] = {0.61039, 0.57768, 0.53034};
    const double expect_tau[3] = {1512.30, 1506.21, 1496.09};
    int k = 0;
    for (const char* id : {"U1.4", "U2.0", "U2.8"}) {
        BOOST_TEST_CONTEXT("point " << id) {
            const fs::path dir = tmp.path / "continuum" / id;
            const Profile p = read_profile(dir / "profile.csv");
            BOOST_TEST(p.rows() >= 101u);
            for (const char* col : kProfileColumns) BOOST_TEST(p.has(col));
            BOOST_TEST(p.column("y_over_H").front() == 0.0);
            BOOST_TEST(p.column("y_over_H").back() == 1.0);
            const Summary s = read_summary(dir / "summary.json");
            for (const char* name : kStandardOutputs) BOOST_TEST(std::isfinite(s.value(name)));
            BOOST_TEST(std::abs(s.value("mean_solid_fraction") - expect_nu[k]) < 2e-5);
            BOOST_TEST(std::abs(s.value("shear_stress_bottom") - expect_tau[k]) / expect_tau[k] < 1e-4);
            BOOST_TEST(s.value("normal_stress_bottom") == 5.5e3);
            BOOST_TEST(s.value("normal_stress_top") == 5.5e3);
            BOOST_TEST(std::abs(s.value("slip_bottom") - s.value("slip_top")) < 1e-9);
            BOOST_TEST(s.value("solid_fraction_centre") > s.value("solid_fraction_bottom"));
            BOOST_TEST(s.value("temperature_bottom") > s.value("temperature_centre"));
            BOOST_TEST(s.run.at("iterations").get<int>() >= 1);
            BOOST_TEST(s.run.at("final_residual").get<double>() < 1e-10);
            BOOST_TEST((result_status(dir, c.inputs_hash("continuum")).state == ResultState::Complete));
        }
        ++k;
    }
    // resume: complete points are skipped (the files are not rewritten)
    const auto stamp = fs::last_write_time(tmp.path / "continuum" / "U2.0" / "summary.json");
    BOOST_TEST(continuum::run(c, o) == 0);
    BOOST_TEST((fs::last_write_time(tmp.path / "continuum" / "U2.0" / "summary.json") == stamp));
}

BOOST_AUTO_TEST_CASE(point_selection_and_determinism) {
    TempDir tmp;
    const Case c = parse("");
    RunOptions o = into(tmp, "U2.0");
    BOOST_TEST(continuum::run(c, o) == 0);
    BOOST_TEST(!fs::exists(tmp.path / "continuum" / "U1.4"));
    const Summary a = read_summary(tmp.path / "continuum" / "U2.0" / "summary.json");
    o.force = true;
    BOOST_TEST(continuum::run(c, o) == 0);
    const Summary b = read_summary(tmp.path / "continuum" / "U2.0" / "summary.json");
    for (const auto& [name, v] : a.outputs) BOOST_TEST(v.value == b.value(name), name);
    o.point = "U9.9";
    BOOST_CHECK_THROW(continuum::run(c, o), Error);
}

BOOST_AUTO_TEST_CASE(fill_control_and_shooting_method_agree_with_fv) {
    const std::string fill = R"(
[operating]
speed = [1.4, 2.8]
control = "fill"
solid_fraction = 0.595
)";
    std::string base(kCase);
    base = base.substr(0, base.find("[operating]"));
    const Case fv = parse_case(base + fill, "test.toml", schema());
    const Case sh = parse_case(base + fill + "[continuum]\nmethod = \"shooting\"\n", "test.toml", schema());
    const auto sfv = continuum::resolve_settings(fv);
    const auto ssh = continuum::resolve_settings(sh);
    for (std::size_t i = 0; i < fv.points.size(); ++i) {
        const auto a = continuum::solve_point(fv, fv.points[i], sfv);
        const auto b = continuum::solve_point(sh, sh.points[i], ssh);
        BOOST_TEST(std::abs(a.summary.value("mean_solid_fraction") - 0.595) < 1e-9);
        BOOST_TEST(std::abs(b.summary.value("mean_solid_fraction") - 0.595) < 1e-5);
        for (const char* q : {"normal_stress_bottom", "shear_stress_bottom", "slip_bottom"})
            BOOST_TEST(std::abs(a.summary.value(q) / b.summary.value(q) - 1) < 1e-5, q);
        BOOST_TEST(b.summary.run.at("method").get<std::string>() == "shooting");
        // docs/continuum-model.md §7.5: P = 3761 Pa at U = 1.4 and 15044 Pa at U = 2.8
        const double P = fv.points[i].speed < 2 ? 3761 : 15044;
        BOOST_TEST(std::abs(a.summary.value("normal_stress_bottom") - P) < 1.0);
    }
}

BOOST_AUTO_TEST_CASE(per_wall_roughness_factors_override_the_case_roughness) {
    const Case c = parse("[continuum]\nr6 = 0.2\nr5_top = 0.8\n");
    const auto s = continuum::resolve_settings(c);
    const auto p = continuum::problem_for(c, s, c.points[0]);
    BOOST_TEST(p.bottom.params.r5 == 0.5);
    BOOST_TEST(p.top.params.r5 == 0.8);
    BOOST_TEST(p.bottom.params.r6 == 0.2);
    BOOST_TEST(p.top.params.r6 == 0.2);
    BOOST_TEST(p.top.params.r8 == 0.5);
    const auto r = continuum::solve_point(c, c.points[0], s);
    BOOST_TEST(r.summary.value("slip_top") < r.summary.value("slip_bottom"));  // rougher top wall slips less
    BOOST_TEST(std::abs(r.summary.value("shear_stress_top") / r.summary.value("shear_stress_bottom") - 1) < 1e-9);
}

// [continuum] wall_friction_restitution = "as_grains": the wall's collisional dissipation takes the grains' e_eff
// formula at the wall's own restitution and friction (here 0.8 and 0.3, unlike the grains' 0.9 and 0.5), its traction
// keeps e_w; the wall then removes more of the slip work, so the flow is cooler and slips less. "none" (the default)
// leaves the wall as declared; "as_grains" without a friction_restitution is refused.
BOOST_AUTO_TEST_CASE(wall_friction_restitution_takes_the_walls_friction_into_their_dissipation) {
    std::string base = kCase;
    base.replace(base.find("restitution = 0.9\n[walls]"), 17, "restitution = 0.9\nfriction = 0.5");
    base.replace(base.find("[walls]\nrestitution = 0.9"), 25, "[walls]\nrestitution = 0.8\nfriction = 0.3");
    const std::string fr = "[continuum]\nfriction_restitution = \"chialvo_sundaresan\"\n";
    const Case off = parse(fr, base), on = parse(fr + "wall_friction_restitution = \"as_grains\"\n", base);
    const auto so = continuum::resolve_settings(off), sn = continuum::resolve_settings(on);
    const auto po = continuum::problem_for(off, so, off.points[0]), pn = continuum::problem_for(on, sn, on.points[0]);
    BOOST_TEST(po.bottom.params.dissipation_e() == 0.8);
    for (const auto* w : {&pn.bottom.params, &pn.top.params}) {
        BOOST_TEST(w->restitution == 0.8);  // the traction's e_w
        BOOST_TEST(w->dissipation_e() == 0.8 - 1.5 * 0.3 * std::exp(-0.9), boost::test_tools::tolerance(1e-15));
    }
    const auto a = continuum::solve_point(off, off.points[0], so).summary;
    const auto b = continuum::solve_point(on, on.points[0], sn).summary;
    BOOST_TEST(b.value("temperature_bottom") < a.value("temperature_bottom"));
    BOOST_TEST(b.value("slip_bottom") < a.value("slip_bottom"));
    std::string e;
    try {
        continuum::resolve_settings(parse("[continuum]\nwall_friction_restitution = \"as_grains\"\n"));
    } catch (const CaseError& x) {
        e = x.what();
    }
    BOOST_TEST(contains(e, "wall_friction_restitution"), e);
    BOOST_TEST(contains(e, "friction_restitution = \"none\""), e);
    // a wall whose e_eff falls below 0 (e_w = 0.05, mu_w = 0.3: -0.133) is refused, naming the wall and point
    std::string low = base;
    low.replace(low.find("[walls]\nrestitution = 0.8"), 25, "[walls]\nrestitution = 0.05");
    e.clear();
    try {
        continuum::resolve_settings(parse(fr + "wall_friction_restitution = \"as_grains\"\n", low));
    } catch (const CaseError& x) {
        e = x.what();
    }
    BOOST_TEST(contains(e, "wall_friction_restitution"), e);
    BOOST_TEST(contains(e, "bottom wall of point"), e);
    BOOST_TEST(contains(e, "[0, 1)"), e);
}

BOOST_AUTO_TEST_CASE(bad_keys_are_rejected_with_the_key_and_what_is_allowed) {
    std::string e = case_error("[continuum]\ng0 = \"bogus\"\n");
    BOOST_TEST(contains(e, "g0"));
    BOOST_TEST(contains(e, "ogawa"));
    e = case_error("[continuum]\ncells = 10\n");
    BOOST_TEST(contains(e, "cells"));
    BOOST_TEST(contains(e, "100"));
    e = case_error("[continuum]\nwall_model = \"smooth\"\n");
    BOOST_TEST(contains(e, "wall_model"));
    BOOST_TEST(contains(e, "johnson_jackson"));
    e = case_error("[continuum]\nr5 = 1.5\n");
    BOOST_TEST(contains(e, "r5"));
    e = case_error("[continuum]\ncels = 200\n");
    BOOST_TEST(contains(e, "cels"));
    e = case_error("[continuum]\ntolerance = -1\n");
    BOOST_TEST(contains(e, "tolerance"));
}

BOOST_AUTO_TEST_CASE(old_spellings_are_read_as_the_new_names_with_a_warning) {
    const Case c = parse("[continuum]\ng0 = \"ls\"\nwall_model = \"jj\"\n");
    BOOST_TEST(c.section("continuum").string("g0") == "lun_savage");
    BOOST_TEST(c.section("continuum").string("wall_model") == "johnson_jackson");
    BOOST_REQUIRE(c.warnings.size() == 2u);
    BOOST_TEST(contains(c.warnings[0], "test.toml:20:6: [continuum] g0 = \"ls\" is the old spelling of \"lun_savage\""),
               c.warnings[0]);
    // the same inputs as the new spelling: results stay current when a case is updated
    const Case n = parse("[continuum]\ng0 = \"lun_savage\"\nwall_model = \"johnson_jackson\"\n");
    BOOST_TEST(n.warnings.empty());
    BOOST_TEST(c.inputs_hash("continuum") == n.inputs_hash("continuum"));
}

BOOST_AUTO_TEST_CASE(impossible_points_fail_cleanly_and_write_nothing) {
    TempDir tmp;
    // smooth walls: no traction, no sheared steady state
    const Case c = parse("[continuum]\nr5 = 0.0\n");
    RunOptions o = into(tmp, "U2.0");
    BOOST_TEST(continuum::run(c, o) == 1);
    BOOST_TEST(!fs::exists(tmp.path / "continuum" / "U2.0" / "summary.json"));
    BOOST_TEST(!fs::exists(tmp.path / "continuum" / "U2.0" / "profile.csv"));
    const auto s = continuum::resolve_settings(c);
    try {
        continuum::solve_point(c, c.points[1], s);
        BOOST_FAIL("R5 = 0 accepted");
    } catch (const SolverError& e) {
        BOOST_TEST(contains(e.what(), "R5 = 0"));
        BOOST_TEST(contains(e.what(), "r5_bottom"));
    }
    // a fill fraction at or above the closures' limit
    std::string base(kCase);
    base = base.substr(0, base.find("[operating]"));
    try {
        parse_case(base + "[operating]\nspeed = 2.0\ncontrol = \"fill\"\nsolid_fraction = 0.7\n", "test.toml", schema());
        BOOST_FAIL("solid_fraction above nu_max accepted");
    } catch (const CaseError& e) {
        BOOST_TEST(contains(e.what(), "solid_fraction"));
        BOOST_TEST(contains(e.what(), "max_solid_fraction"));
    }
    // Newton that cannot converge names the residual and what to try
    const Case tight = parse("[continuum]\nmax_iterations = 1\nmax_continuation_steps = 1\n");
    try {
        continuum::solve_point(tight, tight.points[0], continuum::resolve_settings(tight));
        BOOST_FAIL("one Newton iteration should not converge");
    } catch (const SolverError& e) {
        BOOST_TEST(contains(e.what(), "residual"));
        BOOST_TEST(contains(e.what(), "try"));
    }
}

// Choices that cannot go together stop before anything runs (exit 2 from the command line), naming the key.
BOOST_AUTO_TEST_CASE(incompatible_choices_name_the_key) {
    std::string e = settings_error("[continuum]\nclosures = \"garzo_dufty\"\nviscosity_alpha = 1.6\n");
    BOOST_TEST(contains(e, "viscosity_alpha"), e);
    BOOST_TEST(contains(e, "lun84"), e);
    e = settings_error("[continuum]\ngap = \"inventory\"\nmethod = \"shooting\"\n");
    BOOST_TEST(contains(e, "method"), e);
    e = settings_error("[continuum]\nwall_plane = \"bump_tops\"\n");
    BOOST_TEST(contains(e, "wall_plane"), e);
    BOOST_TEST(contains(e, "bumps"), e);
    // the Jenkins-Berzi correlation length needs its constant, and the constant needs it
    e = settings_error("[continuum]\ncorrelation_length = \"jenkins_berzi\"\n");
    BOOST_TEST(contains(e, "correlation_constant"), e);
    e = settings_error("[continuum]\ncorrelation_length = \"jenkins2007\"\ncorrelation_constant = 0.5\n");
    BOOST_TEST(contains(e, "correlation_constant"), e);
    BOOST_TEST(contains(e, "jenkins_berzi"), e);
    BOOST_TEST(settings_error("[continuum]\ncorrelation_length = \"jenkins_berzi\"\ncorrelation_constant = 0.5\n").empty());
    const std::string fill = fill_case();
    e = settings_error("[continuum]\ngap = \"inventory\"\n", fill);
    BOOST_TEST(contains(e, "gap"), e);
    BOOST_TEST(contains(e, "control"), e);
    // and the command's answer to them
    TempDir tmp;
    BOOST_CHECK_THROW(continuum::run(parse("[continuum]\nclosures = \"garzo_dufty\"\nviscosity_alpha = 1.6\n"), into(tmp)),
                      CaseError);
}

// [continuum] wall_energy (docs/continuum-model.md §4.1): by default GKL's R8-weighted slip work with lun84 (the
// seed's own model) and the slip work whole with any other closure family; the summary names the convention and
// where it came from; r8 is refused where it weights nothing; Johnson & Jackson's dissipation carries no
// specularity (R6 = 1) once the slip work is whole.
BOOST_AUTO_TEST_CASE(wall_energy_convention_by_closures_or_explicit) {
    const auto convention = [](const Case& c) {
        const auto s = continuum::resolve_settings(c);
        return continuum::solve_point(c, c.points[0], s).summary.run.at("wall_energy");
    };
    auto w = convention(parse(""));
    BOOST_TEST(w.at("convention") == "gkl_r8");
    BOOST_TEST(w.at("source") == "closures = lun84");
    w = convention(parse("[continuum]\nclosures = \"garzo_dufty\"\n"));
    BOOST_TEST(w.at("convention") == "slip_work");
    w = convention(parse("[continuum]\nwall_energy = \"slip_work\"\n"));
    BOOST_TEST(w.at("convention") == "slip_work");
    BOOST_TEST(w.at("source") == "[continuum] wall_energy");
    w = convention(parse("[continuum]\nclosures = \"garzo_dufty\"\nwall_energy = \"gkl_r8\"\n"));
    BOOST_TEST(w.at("convention") == "gkl_r8");
    // the slip work returned whole heats the walls: denser centre against the walls than with GKL's sink
    const Case gkl = parse(""), whole = parse("[continuum]\nwall_energy = \"slip_work\"\n");
    const auto a = continuum::solve_point(gkl, gkl.points[0], continuum::resolve_settings(gkl));
    const auto b = continuum::solve_point(whole, whole.points[0], continuum::resolve_settings(whole));
    BOOST_TEST(b.summary.value("temperature_bottom") > a.summary.value("temperature_bottom"));
    BOOST_TEST(b.summary.run.at("energy_budget").at("wall_unreturned_slip_work_W_m2").get<double>() == 0.0);
    BOOST_TEST(a.summary.run.at("energy_budget").at("wall_unreturned_slip_work_W_m2").get<double>() > 0.0);
    // bad input names the key and what is allowed
    std::string e = case_error("[continuum]\nwall_energy = \"r8\"\n");
    BOOST_TEST(contains(e, "wall_energy"), e);
    BOOST_TEST(contains(e, "slip_work"), e);
    for (const char* k : {"r8", "r8_top"}) {
        try {
            continuum::resolve_settings(parse(fmt::format("[continuum]\nwall_energy = \"slip_work\"\n{} = 0.4\n", k)));
            BOOST_FAIL("r8 accepted with the slip work whole");
        } catch (const CaseError& x) {
            BOOST_TEST(contains(x.what(), k), x.what());
            BOOST_TEST(contains(x.what(), "gkl_r8"), x.what());
        }
    }
    // Johnson & Jackson: R6 = 1 with the slip work whole, R with GKL's convention; an explicit r6 wins
    for (const auto& [extra, r6] : {std::pair<std::string, double>{"wall_energy = \"slip_work\"\n", 1.0},
                                    {"wall_energy = \"gkl_r8\"\n", 0.5},
                                    {"wall_energy = \"slip_work\"\nr6 = 0.3\n", 0.3}}) {
        const Case c = parse("[continuum]\nwall_model = \"johnson_jackson\"\n" + extra);
        const auto p = continuum::problem_for(c, continuum::resolve_settings(c), c.points[0]);
        BOOST_TEST(p.bottom.params.r6 == r6);
        BOOST_TEST(p.top.params.r6 == r6);
    }
}

// The contact/collision label (run.lubrication): Chialvo & Sundaresan 2013's I_m = I/nu is local (Eq. 35), so it
// takes the mid-gap I over the mid-gap nu, not over the gap's mean nu (lower: the walls are dilute).
BOOST_AUTO_TEST_CASE(lubrication_label_uses_the_local_solid_fraction) {
    const Case c = parse("");
    const auto s = continuum::resolve_settings(c);
    for (const OperatingPoint& p : c.points) {
        const auto m = continuum::solve_point(c, p, s).summary;
        const auto& l = m.run.at("lubrication");
        const double nu_c = m.value("solid_fraction_centre"), I = m.value("inertial_number");
        BOOST_TEST(l.at("solid_fraction").get<double>() == nu_c);  // N = 200: the centre is a node
        BOOST_TEST(nu_c > m.value("mean_solid_fraction"));
        BOOST_TEST(l.at("inertial_number_over_solid_fraction").get<double>() == I / nu_c);
        BOOST_TEST(l.at("verdict") == (I / nu_c > 0.2 ? "collision lubrication" : "contact lubrication"));
    }
}

// profile.csv's y_over_H on the one scale of every solver (kProfileYDefinition): from the floor's wall plane over the
// gap between the planes through the bumps' centres. With wall_plane = "bump_tops" the continuum's own domain is
// narrower by the bumps' protrusion at each wall: its nodes then run from prot/gap to 1 - prot/gap, evenly, and the
// summary says where its walls lie; with the wall at the centres' planes the nodes span 0..1.
BOOST_AUTO_TEST_CASE(profile_y_is_on_the_wall_planes_scale) {
    std::string bumpy(kCase);
    bumpy.replace(bumpy.find("roughness = 0.5\n"), 16, "roughness = 0.5\nsurface = \"bumps\"\n");
    bumpy.replace(bumpy.find("normal_stress = 5.5e3"), 21, "normal_stress = 5.5e3\nsolid_fraction = 0.595");
    for (const bool tops : {false, true}) {
        const Case c = parse(fmt::format("[continuum]\ngap = \"inventory\"\nwall_plane = \"{}\"\n",
                                         tops ? "bump_tops" : "bump_centres"),
                             bumpy);
        const OperatingPoint& p = c.points[0];
        const auto r = continuum::solve_point(c, p, continuum::resolve_settings(c));
        const auto& y = r.profile.column("y_over_H");
        const double gap = r.summary.value("gap"), prot = bump_protrusion(c, p.bottom);
        BOOST_TEST(prot > 0.3e-3);  // bumps of the grains' size: d/2 above the plane
        const double lo = tops ? prot / gap : 0.0, hi = tops ? 1 - prot / gap : 1.0;
        BOOST_TEST(std::abs(y.front() - lo) < 1e-12, y.front());
        BOOST_TEST(std::abs(y.back() - hi) < 1e-12, y.back());
        const double step = (hi - lo) / static_cast<double>(y.size() - 1);
        for (std::size_t i = 1; i < y.size(); ++i) BOOST_TEST(std::abs(y[i] - y[i - 1] - step) < 1e-9);
        const auto& w = r.summary.run.at("wall_plane");
        BOOST_TEST(w.at("plane") == (tops ? "bump_tops" : "bump_centres"));
        BOOST_TEST(std::abs(w.at("floor_y_over_H").get<double>() - lo) < 1e-12);
        BOOST_TEST(std::abs(w.at("top_y_over_H").get<double>() - hi) < 1e-12);
    }
}

// wall_roughness = "bumps": a bumpy wall's R5..R8 are sin(theta) = l/(d_w + d) of the layer the particle
// solvers build (whole bumps in the periodic length: 38 of 0.789 mm over 30 mm, R = 0.5016), not the declared
// R = 0.5 that asked for them; the summary says which. Plane walls refuse it, naming the key.
BOOST_AUTO_TEST_CASE(wall_roughness_from_the_bumps) {
    std::string bumpy(kCase);
    bumpy.replace(bumpy.find("roughness = 0.5\n"), 16, "roughness = 0.5\nsurface = \"bumps\"\n");
    const Case c = parse("[continuum]\nwall_roughness = \"bumps\"\n", bumpy);
    const continuum::Settings s = continuum::resolve_settings(c);
    const OperatingPoint& p = c.points.front();
    const double built = wall_bumps(c, p, p.bottom, "bottom", particle_box(c))->roughness;
    BOOST_TEST(continuum::wall_roughness(c, s, p, p.bottom, "bottom") == built);
    BOOST_TEST(continuum::wall_roughness(c, s, p, p.top, "top") == built);
    BOOST_TEST(std::abs(built - 0.5) > 1e-4);  // the rounding to whole bumps: the test can tell them apart
    BOOST_TEST(std::abs(built - 0.5) <= kBumpRoughnessTolerance);
    const Case declared = parse("", bumpy);
    BOOST_TEST(continuum::wall_roughness(declared, continuum::resolve_settings(declared), p, p.bottom, "bottom") ==
               0.5);
    TempDir tmp;
    BOOST_TEST(continuum::run(c, into(tmp, "U1.4")) == 0);
    const auto sum = read_summary(tmp.path / "continuum" / "U1.4" / "summary.json");
    BOOST_TEST(sum.run.at("wall_roughness").at("source") == "bumps");
    BOOST_TEST(sum.run.at("wall_roughness").at("top").get<double>() == built);
    BOOST_TEST(sum.run.at("correlation_length") == "none");
    try {
        continuum::resolve_settings(parse("[continuum]\nwall_roughness = \"bumps\"\n"));
        BOOST_FAIL("plane walls accepted wall_roughness = bumps");
    } catch (const CaseError& e) {
        BOOST_TEST(contains(e.what(), "wall_roughness"), e.what());
    }
}

// wall_roughness = "built" on plane walls: Walton's impact law (walls/flat_wall.h, walls/flat_wall_impacts.h), the
// contact points slipping at a share phi of the grains' slip u_s (flat_wall_spin: torque_balance 1/2, none 1). The
// solution's wall traction and wall dissipation are the law's, computed here from the solution's own slip and T at
// each wall (the contact points' xi = phi u_s/sqrt T): S = sigma(xi) P and D = delta(xi) P sqrt(T), in the stick
// limit (flat_wall_impacts = "stick", or stick_and_slide at a huge friction) sigma = (2/7) sqrt(2/pi) xi/(1 + e_w)
// and delta = sqrt(2/pi)/(1 + e_w) [(1 - e_w^2) + (xi^2 + 2)/7], with sliding (the default, friction 0.5) sigma and
// delta by the law's quadrature; e_eff is not added (the law holds the friction); plane side walls of the
// cross-section take the law too; it refuses the walls' families, conventions and frictions it does not fit.
BOOST_AUTO_TEST_CASE(built_plane_walls_follow_waltons_impact_law) {
    const std::string keys = "[continuum]\nclosures = \"garzo_dufty\"\nwall_roughness = \"built\"\n"
                             "friction_restitution = \"chialvo_sundaresan\"\n";
    const auto with_wall_friction = [](const std::string& mu) {
        std::string c(kCase);
        c.replace(c.find("[walls]\n"), 8, "[walls]\nfriction = " + mu + "\n");
        c.replace(c.find("[grains]\n"), 9, "[grains]\nfriction = 0.5\n");
        return c;
    };
    const std::string frictional = with_wall_friction("0.5");
    const double P = 5.5e3, e = 0.9, c0 = std::sqrt(2.0 / std::numbers::pi);
    // The U1.4 point's walls against sigma(xi), delta(xi) at the contact points' xi; returns the top's traction and
    // the mean slip.
    const auto check = [&](const Case& c, double phi, const auto& sigma, const auto& delta) {
        TempDir tmp;
        BOOST_TEST(continuum::run(c, into(tmp, "U1.4")) == 0);
        const Summary m = read_summary(tmp.path / "continuum" / "U1.4" / "summary.json");
        BOOST_TEST(m.run.at("wall_roughness").at("source") == "built");
        BOOST_TEST(m.run.at("wall_roughness").at("plane_walls").at("contact_slip_share").get<double>() == phi);
        double sink = 0, slip = 0;
        for (const char* side : {"bottom", "top"}) {
            const double us = m.value(std::string("slip_") + side), T = m.value(std::string("temperature_") + side);
            const double tau = m.value(std::string("shear_stress_") + side), xi = phi * us / std::sqrt(T);
            BOOST_CHECK_CLOSE_FRACTION(std::abs(tau), sigma(xi) * P, 1e-6);
            sink += delta(xi) * P * std::sqrt(T);
            slip += 0.5 * us;
        }
        BOOST_CHECK_CLOSE_FRACTION(m.run.at("energy_budget").at("wall_collisional_W_m2").get<double>(), sink, 1e-6);
        BOOST_TEST(m.run.at("energy_budget").at("wall_unreturned_slip_work_W_m2").get<double>() == 0.0);
        return std::pair{std::abs(m.value("shear_stress_top")), slip};
    };
    const auto sigma_s = [&](double xi) { return (2.0 / 7.0) * c0 * xi / (1 + e); };
    const auto delta_s = [&](double xi) { return c0 / (1 + e) * ((1 - e * e) + (xi * xi + 2) / 7.0); };
    const continuum::FlatWallImpacts law(e, 0.5, 0.0);
    const auto sigma = [&](double xi) { return law.quadrature(xi).sigma_over_xi * xi; };
    const auto delta = [&](double xi) { return law.quadrature(xi).delta; };

    double tau_spin = 0, tau_none = 0;
    for (const auto& [spin, phi] : {std::pair{"", 0.5}, {"flat_wall_spin = \"none\"\n", 1.0}}) {
        BOOST_TEST_CONTEXT("contact slip share " << phi) {
            // the stick limit: the key, or a friction no impact reaches
            const Case stick = parse(keys + spin + "flat_wall_impacts = \"stick\"\n", frictional);
            const continuum::Problem q = continuum::problem_for(stick, continuum::resolve_settings(stick),
                                                                stick.points.front());
            for (const auto* w : {&q.bottom.params, &q.top.params}) {
                BOOST_TEST(w->r5 == (2.0 / 7.0) * phi);
                BOOST_TEST(w->r7 == (2.0 / 7.0) * phi);
                BOOST_CHECK_CLOSE_FRACTION(w->r6, 1.0 + (2.0 / 7.0) / (1.0 - e * e), 1e-14);
                BOOST_TEST(w->slip_dissipation == 0.5 * phi);
                BOOST_TEST(w->dissipation_e() == e);  // no e_eff on top of the law
                BOOST_TEST(!w->impacts);
            }
            const auto [tau, slip_stick] = check(stick, phi, sigma_s, delta_s);
            (phi < 1 ? tau_spin : tau_none) = tau;
            check(parse(keys + spin, with_wall_friction("1.0e6")), phi, sigma_s, delta_s);

            // impacts that slide (the default) at friction 0.5: less traction for the same slip, so more slip
            const Case slide = parse(keys + spin, frictional);
            const continuum::Problem qs =
                continuum::problem_for(slide, continuum::resolve_settings(slide), slide.points.front());
            BOOST_TEST(qs.bottom.params.impacts != nullptr);
            BOOST_TEST(qs.bottom.params.impacts->friction() == 0.5);
            BOOST_TEST(qs.bottom.params.impacts == qs.top.params.impacts);
            BOOST_TEST(qs.bottom.params.contact_slip_share == phi);
            const double slip_slide = check(slide, phi, sigma, delta).second;
            BOOST_TEST_MESSAGE("share " << phi << ", U1.4 mean slip: " << slip_stick << " m/s with impacts sticking, "
                                        << slip_slide << " m/s sticking and sliding");
            BOOST_TEST(slip_slide > slip_stick);
        }
    }
    BOOST_TEST(tau_spin < 0.9 * tau_none);  // rolling grains grip less

    std::string trough(frictional);
    trough.replace(trough.find("length = 30.0e-3"), 16, "length = 30.0e-3\nwidth = 19.0e-3");
    const Case x = parse(keys + "geometry = \"cross_section\"\n", trough);
    const auto xq = continuum::cross_section_problem_for(x, continuum::resolve_settings(x), x.points.front());
    BOOST_TEST(xq.outer.params.r5 == 1.0 / 7.0);
    BOOST_TEST(xq.inner.params.slip_dissipation == 0.25);
    BOOST_TEST(xq.outer.params.impacts != nullptr);
    BOOST_TEST(xq.outer.params.contact_slip_share == 0.5);
    // bumpy floor and top with their impacts as_grains: the plane side walls keep the law's e_w (no e_eff on top)
    std::string bumpy(trough);
    bumpy.replace(bumpy.find("roughness = 0.5\n"), 16, "roughness = 0.5\nsurface = \"bumps\"\n");
    const Case xb = parse(keys + "geometry = \"cross_section\"\nwall_friction_restitution = \"as_grains\"\n", bumpy);
    const auto xbq = continuum::cross_section_problem_for(xb, continuum::resolve_settings(xb), xb.points.front());
    BOOST_TEST(xbq.gap.bottom.params.dissipation_e() < 0.8);  // e_eff(0.9, 0.5) = 0.733 on the bumps
    BOOST_TEST(xbq.outer.params.dissipation_e() == 0.9);
    BOOST_TEST(xbq.outer.params.r5 == 1.0 / 7.0);

    std::string err = settings_error("[continuum]\nwall_roughness = \"built\"\n");  // lun84: the R8 convention
    BOOST_TEST(contains(err, "wall_roughness"), err);
    BOOST_TEST(contains(err, "slip_work"), err);
    err = settings_error(keys + "wall_model = \"johnson_jackson\"\n", frictional);
    BOOST_TEST(contains(err, "wall_roughness"), err);
    BOOST_TEST(contains(err, "kinetic"), err);
    // all walls plane: as_grains would change nothing (the law holds the friction), refused naming the key
    err = settings_error(keys + "wall_friction_restitution = \"as_grains\"\n", frictional);
    BOOST_TEST(contains(err, "wall_friction_restitution"), err);
    BOOST_TEST(contains(err, "change nothing"), err);
    err = settings_error("[continuum]\nflat_wall_spin = \"none\"\n");
    BOOST_TEST(contains(err, "flat_wall_spin"), err);
    BOOST_TEST(contains(err, "built"), err);
    // sliding needs the wall's friction; the stick limit does not
    err = settings_error(keys, with_wall_friction("0.0"));
    BOOST_TEST(contains(err, "[walls] friction"), err);
    BOOST_TEST(contains(err, "flat_wall_impacts = \"stick\""), err);
    BOOST_TEST(settings_error(keys + "flat_wall_impacts = \"stick\"\n", with_wall_friction("0.0")).empty());
    err = settings_error("[continuum]\nflat_wall_impacts = \"stick\"\n");
    BOOST_TEST(contains(err, "flat_wall_impacts"), err);
    BOOST_TEST(contains(err, "wall_roughness = \"built\""), err);
    // an elastic plane has no impact-law conditions (R6 diverges), sticking or sliding
    std::string elastic(frictional);
    elastic.replace(elastic.find("restitution = 0.9\nroughness"), 17, "restitution = 1.0");
    for (const char* impacts : {"", "flat_wall_impacts = \"stick\"\n"}) {
        err = settings_error(keys + impacts, elastic);
        BOOST_TEST(contains(err, "[walls] restitution"), err);
        BOOST_TEST(contains(err, "restitution < 1"), err);
    }
}

// gap = "inventory": the gap under the load from the grains the particle solvers insert, with the gap
// in the summary; a solution past the crystallization criterion is labelled ordered, not a steady number.
BOOST_AUTO_TEST_CASE(inventory_gap_and_the_ordered_label) {
    TempDir tmp;
    const std::string ekt = "[continuum]\nclosures = \"garzo_dufty\"\ng0 = \"torquato\"\nmax_solid_fraction = 0.636\n"
                            "correlation_length = \"jenkins2007\"\ngap = \"inventory\"\n";
    const std::string base = std::string(kCase).substr(0, std::string(kCase).find("[operating]")) +
                             "[operating]\nspeed = [0.4, 2.8]\ncontrol = \"load\"\nnormal_stress = 5.5e3\n"
                             "solid_fraction = 0.5\n";
    const Case c = parse(ekt, base);
    BOOST_TEST(continuum::run(c, into(tmp)) == 0);
    for (const char* id : {"U0.4", "U2.8"}) {
        const auto s = read_summary(tmp.path / "continuum" / id / "summary.json");
        const double gap = s.outputs.at("gap").value, nu = s.outputs.at("mean_solid_fraction").value;
        BOOST_TEST(gap * nu == 0.5 * 4.0e-3, boost::test_tools::tolerance(1e-9));  // holds the grains
        BOOST_TEST(s.run.at("status") == "steady");
        BOOST_TEST(std::abs(s.run.at("energy_budget").at("relative_defect").get<double>()) < 1e-3);
    }
    // slower is denser: the criterion at 0.5 labels the slow point ordered and leaves the fast one
    const auto slow = read_summary(tmp.path / "continuum" / "U0.4" / "summary.json");
    const auto fast = read_summary(tmp.path / "continuum" / "U2.8" / "summary.json");
    BOOST_TEST(slow.outputs.at("gap").value < fast.outputs.at("gap").value);
    TempDir tmp2;
    const double cut = 0.5 * (slow.outputs.at("solid_fraction_centre").value + fast.outputs.at("solid_fraction_centre").value);
    const Case o = parse(ekt + fmt::format("ordering_fraction = {}\n", cut), base);
    BOOST_TEST(continuum::run(o, into(tmp2)) == 0);
    const auto so = read_summary(tmp2.path / "continuum" / "U0.4" / "summary.json");
    BOOST_TEST(so.run.at("status") == "ordered");
    BOOST_TEST(contains(so.run.at("status_reason").get<std::string>(), "ordering_fraction"));
    BOOST_TEST(read_summary(tmp2.path / "continuum" / "U2.8" / "summary.json").run.at("status") == "steady");
}

// [continuum] contact_stress (docs/continuum-model.md §2.9): no default constants, each one required with the branch
// and refused without it, out-of-range values and the unsupported fill control / shooting method refused naming the
// key; with its constants the summary records them and the contacts' share of the work.
BOOST_AUTO_TEST_CASE(contact_stress_needs_its_constants_and_says_what_is_allowed) {
    const std::string all = "contact_coefficient = 0.05\ncontact_onset_fraction = 0.5\ncontact_exponent_onset = 2\n"
                            "contact_exponent_jamming = 5\ncontact_friction = 0.2\n";
    const std::string branch = "[continuum]\ncontact_stress = \"johnson_jackson\"\n";
    BOOST_TEST(settings_error(branch + all).empty());
    for (const char* k : {"contact_coefficient", "contact_onset_fraction", "contact_exponent_onset",
                          "contact_exponent_jamming", "contact_friction"}) {
        std::string without = all;
        without.erase(without.find(k), without.find('\n', without.find(k)) - without.find(k) + 1);
        const std::string e = settings_error(branch + without);
        BOOST_TEST(contains(e, "contact_stress"), e);
        BOOST_TEST(contains(e, k), e);
        // and a constant without the branch
        const std::string line = all.substr(all.find(k), all.find('\n', all.find(k)) - all.find(k) + 1);
        const std::string f = settings_error("[continuum]\n" + line);
        BOOST_TEST(contains(f, k), f);
        BOOST_TEST(contains(f, "johnson_jackson"), f);
    }
    // out of range or unknown: the key and what is allowed
    for (const auto& [line, key, allowed] : {std::tuple{"contact_coefficient = -1", "contact_coefficient", "> 0"},
                                             {"contact_exponent_jamming = 0", "contact_exponent_jamming", "0.1"},
                                             {"contact_friction = 3", "contact_friction", "2"},
                                             {"contact_stress = \"schaeffer\"", "contact_stress", "johnson_jackson"}}) {
        const std::string x = case_error(fmt::format("[continuum]\n{}\n", line));
        BOOST_TEST(contains(x, key), x);
        BOOST_TEST(contains(x, allowed), x);
    }
    std::string e;
    // nu_min must lie below nu_c (max_solid_fraction = 0.65 here)
    std::string high = all;
    high.replace(high.find("contact_onset_fraction = 0.5"), 28, "contact_onset_fraction = 0.7");
    e = settings_error(branch + high);
    BOOST_TEST(contains(e, "contact_onset_fraction"), e);
    BOOST_TEST(contains(e, "0.65"), e);
    e = settings_error(branch + all + "method = \"shooting\"\n");
    BOOST_TEST(contains(e, "method"), e);
    const std::string fill = fill_case();
    e = settings_error(branch + all, fill);
    BOOST_TEST(contains(e, "control"), e);
    BOOST_TEST(contains(e, "contact_stress"), e);
    // the summary names the branch and its constants, and books the contacts' dissipation
    const Case c = parse(branch + all);
    const auto r = continuum::solve_point(c, c.points[0], continuum::resolve_settings(c));
    BOOST_TEST(r.summary.run.at("contact_stress").at("model") == "johnson_jackson");
    BOOST_TEST(r.summary.run.at("contact_stress").at("friction").get<double>() == 0.2);
    BOOST_TEST(r.summary.run.at("energy_budget").at("contact_dissipation_W_m2").get<double>() > 0.0);
    // T = (P - p_c)/(rho_p f_p) with the kinetic f_p (docs/continuum-model.md §2.9), at mid-gap
    const double nu = r.summary.value("solid_fraction_centre"), P = 5.5e3;
    const double pc = 0.05 * std::pow(nu - 0.5, 2) / std::pow(0.65 - nu, 5);
    const double fp = continuum::resolve_settings(parse("")).closures->state(nu).fp.v;
    BOOST_TEST(pc > 0.1 * P);
    BOOST_CHECK_CLOSE_FRACTION(r.summary.value("temperature_centre"), (P - pc) / (2550.0 * fp), 1e-12);
    const Case none = parse("");
    const auto n = continuum::solve_point(none, none.points[0], continuum::resolve_settings(none));
    BOOST_TEST(n.summary.run.at("contact_stress") == "none");
}

// geometry = "cross_section": a width of 0, a grid too coarse for the walls and the 1-D-only choices stop with the
// key and what is allowed; a run writes every wall's stress and slip, the mid-width profile and section.csv in the
// particle solvers' columns.
BOOST_AUTO_TEST_CASE(cross_section_geometry_keys_and_outputs) {
    std::string e = settings_error("[continuum]\ngeometry = \"cross_section\"\n");  // kCase has no width
    BOOST_TEST(contains(e, "geometry"), e);
    BOOST_TEST(contains(e, "width > 0"), e);
    std::string trough(kCase);
    trough.replace(trough.find("length = 30.0e-3"), 16, "length = 30.0e-3\nwidth = 19.0e-3");
    e = settings_error("[continuum]\ngeometry = \"cross_section\"\ncross_section_cells_z = 50\n", trough);
    BOOST_TEST(contains(e, "cross_section_cells_z"), e);
    BOOST_TEST(contains(e, ">= 97"), e);
    e = settings_error("[continuum]\ngeometry = \"cross_section\"\ncross_section_cells_y = 12\n", trough);
    BOOST_TEST(contains(e, "cross_section_cells_y"), e);
    BOOST_TEST(contains(e, ">= 21"), e);
    e = settings_error("[continuum]\ngeometry = \"cross_section\"\nmethod = \"shooting\"\n", trough);
    BOOST_TEST(contains(e, "method"), e);
    // the contact stress (§2.9) on the cross-section: its constants checked as on the gap, with or without body forces
    const std::string contact = "[continuum]\ngeometry = \"cross_section\"\ncontact_stress = \"johnson_jackson\"\n"
                                "contact_coefficient = 0.05\ncontact_onset_fraction = 0.5\ncontact_exponent_onset = 2\n"
                                "contact_exponent_jamming = 5\ncontact_friction = 0.2\n";
    BOOST_TEST(settings_error(contact, trough).empty());
    BOOST_TEST(settings_error(contact + "body_forces = \"on\"\n", trough).empty());
    std::string high = contact;
    high.replace(high.find("contact_onset_fraction = 0.5"), 28, "contact_onset_fraction = 0.7");
    e = settings_error(high, trough);
    BOOST_TEST(contains(e, "contact_onset_fraction"), e);
    BOOST_TEST(contains(e, "0.65"), e);
    std::string without = contact;
    without.erase(without.find("contact_friction"));
    e = settings_error(without, trough);
    BOOST_TEST(contains(e, "contact_friction"), e);
    for (const auto& [line, key, allowed] : {std::tuple{"contact_coefficient = -1", "contact_coefficient", "> 0"},
                                             {"contact_friction = 3", "contact_friction", "2"}}) {
        std::string bad = contact;
        const std::string k = std::string(key) + " = ";
        const auto at = bad.find(k);
        bad.replace(at, bad.find('\n', at) - at, line);
        const std::string x = case_error(bad);  // the case's key ranges, whatever the geometry
        BOOST_TEST(contains(x, key), x);
        BOOST_TEST(contains(x, allowed), x);
    }
    e = settings_error("[continuum]\nside_roughness = 0.3\n", trough);
    BOOST_TEST(contains(e, "side_roughness"), e);
    e = settings_error("[continuum]\nbody_forces = \"on\"\n", trough);
    BOOST_TEST(contains(e, "body_forces"), e);
    BOOST_TEST(settings_error("[continuum]\ngeometry = \"cross_section\"\n", trough).empty());

    TempDir tmp;
    const Case c = parse("[continuum]\ngeometry = \"cross_section\"\ncross_section_cells_y = 24\n", trough);
    try {  // the (U, P) map is the 1-D gap's
        continuum::continuum_map_csv(c, continuum::MapGrid{});
        BOOST_FAIL("the map ran with geometry = cross_section");
    } catch (const CaseError& err) {
        BOOST_TEST(contains(err.what(), "geometry"), err.what());
    }
    BOOST_TEST(continuum::run(c, into(tmp, "U2.0")) == 0);
    const fs::path dir = tmp.path / "continuum" / "U2.0";
    const Summary s = read_summary(dir / "summary.json");
    for (const char* name : kStandardOutputs) BOOST_TEST(std::isfinite(s.value(name)));
    for (const char* w : {"outer", "inner"}) {
        BOOST_TEST(s.value(std::string("shear_stress_") + w) > 0);
        BOOST_TEST(s.value(std::string("slip_over_U_") + w) > 0);
    }
    // the top holds what the floor and the sides drag
    const double W = 19e-3, H = 4e-3;
    const double floor = s.value("shear_stress_bottom") * W, sides = 2 * s.value("shear_stress_side") * H;
    BOOST_TEST(std::abs(floor + sides - s.value("shear_stress_top") * W) < 1e-6 * floor);
    BOOST_TEST(std::abs(s.value("side_wall_drag_share") - sides / (s.value("shear_stress_top") * W)) < 1e-9);
    BOOST_TEST((result_status(dir, c.inputs_hash("continuum")).state == ResultState::Complete));
    const Profile mid = read_profile(dir / "profile.csv");
    BOOST_TEST(mid.rows() == 25u);
    const Profile map = read_table(dir / kSectionFile);  // the reader the report draws the maps from
    // the particle solvers' cells: about one grain diameter, 5 across the gap, 24 across the width
    BOOST_TEST(map.rows() == 5u * 24u);
    for (const char* col : {"y_over_H", "z_over_W", "solid_fraction", "u_over_U"}) BOOST_TEST(map.has(col));
    BOOST_TEST(std::abs(map.column("z_over_W").front() - (0.5 / 24 - 0.5)) < 1e-9);
    // and the grains in them are the solution's
    double grains = 0;
    for (double nu : map.column("solid_fraction")) grains += nu / static_cast<double>(map.rows());
    BOOST_TEST(std::abs(grains - s.value("mean_solid_fraction")) < 1e-3);
    // with the contact stress a point solves and books the contacts' dissipation; T = (P - p_c)/(rho_p f_p) with the
    // kinetic f_p (§2.9) at mid-width and mid-gap
    TempDir tc;
    const Case cc = parse(contact + "cross_section_cells_y = 24\n", trough);
    BOOST_TEST(continuum::run(cc, into(tc, "U2.0")) == 0);
    const Summary sc = read_summary(tc.path / "continuum" / "U2.0" / "summary.json");
    BOOST_TEST(sc.run.at("contact_stress").at("model") == "johnson_jackson");
    BOOST_TEST(sc.run.at("energy_budget").at("contact_dissipation_W_m").get<double>() > 0.0);
    const double nu = sc.value("solid_fraction_centre"), P = 5.5e3;
    const double pc = 0.05 * std::pow(nu - 0.5, 2) / std::pow(0.65 - nu, 5);
    const double fp = continuum::resolve_settings(parse("")).closures->state(nu).fp.v;
    BOOST_TEST(pc > 0.01 * P);  // 3 %: T without it would miss by that much
    BOOST_CHECK_CLOSE_FRACTION(sc.value("temperature_centre"), (P - pc) / (2550.0 * fp), 1e-9);
    // and with the body forces (gravity, S&T's annulus): the outer wall carries more than the inner one
    std::string annulus = trough;
    annulus.replace(annulus.find("width = 19.0e-3"), 15, "width = 19.0e-3\nannulus_radius = 0.0762");
    TempDir tb;
    const Case cb = parse(contact + "cross_section_cells_y = 24\nbody_forces = \"on\"\n", annulus);
    BOOST_TEST(continuum::run(cb, into(tb, "U2.0")) == 0);
    const Summary sb = read_summary(tb.path / "continuum" / "U2.0" / "summary.json");
    BOOST_TEST(sb.run.at("energy_budget").at("contact_dissipation_W_m").get<double>() > 0.0);
    BOOST_TEST(sb.value("normal_stress_outer") > sb.value("normal_stress_inner"));
    BOOST_TEST(std::abs(sb.run.at("energy_budget").at("relative_defect").get<double>()) < 0.01);
}

// The side walls from [walls] sides: plane = the declared roughness (side_roughness overrides it), as_bottom = the
// floor's condition, and with the wall at the bumps' tops bumpy side walls narrow the width as the floor's narrow the
// gap; the inventory is the grains per length over the narrower width.
BOOST_AUTO_TEST_CASE(cross_section_side_walls_from_the_case) {
    std::string trough(kCase);
    trough.replace(trough.find("length = 30.0e-3"), 16, "length = 30.0e-3\nwidth = 19.0e-3");
    trough.replace(trough.find("roughness = 0.5\n"), 16, "roughness = 0.5\nsurface = \"bumps\"\n");
    const std::string xs = "[continuum]\ngeometry = \"cross_section\"\ngap = \"inventory\"\nwall_plane = \"bump_tops\"\n";
    std::string as_bottom = trough;
    as_bottom.replace(as_bottom.find("surface = \"bumps\"\n"), 18, "surface = \"bumps\"\nsides = \"as_bottom\"\n");
    const double d = 0.787e-3, W = 19e-3;
    {
        const Case c = parse(xs, trough);
        const continuum::Settings s = continuum::resolve_settings(c);
        const OperatingPoint& p = c.points.front();
        const auto q = continuum::cross_section_problem_for(c, s, p);
        BOOST_TEST(q.outer.params.r5 == 0.5);
        BOOST_TEST(std::abs(q.width - W / d) < 1e-12);  // plane sides: the full width
        const auto r = continuum::cross_section_problem_for(c, continuum::resolve_settings(
                                                                  parse(xs + "side_roughness = 0.2\n", trough)), p);
        BOOST_TEST(r.inner.params.r8 == 0.2);
        BOOST_TEST(r.gap.bottom.params.r8 == 0.5);
    }
    {
        const Case c = parse(xs, as_bottom);
        const continuum::Settings s = continuum::resolve_settings(c);
        const OperatingPoint& p = c.points.front();
        const auto q = continuum::cross_section_problem_for(c, s, p);
        const double prot = bump_protrusion(c, p.bottom);
        BOOST_TEST(prot > 0);
        BOOST_TEST(std::abs(q.width - (W - 2 * prot) / d) < 1e-9);
        BOOST_TEST(std::abs(q.gap.inventory - p.solid_fraction * c.cell.gap * W / (d * (W - 2 * prot))) < 1e-9);
        BOOST_TEST(q.outer.params.r5 == q.gap.bottom.params.r5);
        BOOST_TEST(q.outer.params.restitution == q.gap.bottom.params.restitution);
    }
}
