// The regime part of the report (postproc regimes.h) end to end on synthetic results: a
// case that sweeps speed and load draws the map, the lift-off, mu(I) and tau(U) per load, says
// which criterion decided each point and draws a transient hollow; a one-point case and a
// speed-only sweep draw no map and say why.
#include <algorithm>
#include <cmath>
#include <fstream>

#include <boost/test/unit_test.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "granlub/statistics/flow_regime.h"
#include "granlub/postproc/command.h"
#include "granlub/results/run_status.h"
#include "granlub/results/results.h"
#include "case_text.h"
#include "report_checks.h"
#include "synthetic.h"
#include "xml_check.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

test::SyntheticCase grid_case(const std::string& name, const std::string& operating) {
    test::SyntheticCase s;
    s.dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / "postproc-tmp" / name;
    fs::remove_all(s.dir);
    fs::create_directories(s.dir);
    // the shared valid case under load, with this test's operating points
    std::ofstream(s.dir / "case.toml") << test::with(
        "[operating]\nspeed = [1.0, 2.0]\ncontrol = \"fill\"\nsolid_fraction = 0.5\nnormal_stress = 1000.0\n",
        "[operating]\ncontrol = \"load\"\nsolid_fraction = 0.55\n" + operating);
    s.c = load_case(s.dir, test::synthetic_schema());
    s.o.results_root = s.dir / "results";
    return s;
}

// dem: tau = 0.4 P (n = 0 at every load), a linear u(y); the grains lift off (Z = 3) at 500 Pa
// above 1 m/s; the point U2 at 2000 Pa is transient. continuum: tau = 50 U^2 (n = 2), no contacts.
// automaton: as the continuum, with a lattice occupancy of 0.9 (not a solid fraction).
void write_results(const test::SyntheticCase& s) {
    for (const OperatingPoint& p : s.c.points)
        for (const char* solver : {"dem", "continuum", "automaton"}) {
            const bool dem = solver == std::string("dem"), lattice = solver == std::string("automaton");
            const double P = p.normal_stress, U = p.speed;
            Summary sum = make_summary(s.c, p, solver, dem ? std::optional<std::uint64_t>(7) : std::nullopt);
            sum.kind = dem ? "particles" : lattice ? "lattice" : "continuum";
            const double tau = dem ? 0.4 * P : 50 * U * U;
            sum.set("normal_stress_bottom", P * 1.02, "Pa").set("normal_stress_top", P, "Pa");
            sum.set("shear_stress_bottom", tau, "Pa").set("shear_stress_top", tau, "Pa");
            sum.set("slip_bottom", 0.1 * U, "m/s").set("slip_top", 0.1 * U, "m/s");
            const bool lifted = dem && P < 1000 && U > 1.0;
            sum.set("mean_solid_fraction", lifted ? 0.42 : lattice ? 0.9 : 0.58, "").set("max_solid_fraction", 0.65, "");
            if (dem) sum.set("gap", lifted ? 6.5e-3 : 5.0e-3, "m");
            std::vector<double> y, u, nu, T;
            for (int k = 0; k < 20; ++k) y.push_back((k + 0.5) / 20.0);
            for (double v : y) u.push_back(1.0 - v), nu.push_back(0.6), T.push_back(0.01);
            Profile prof;
            prof.add("y_over_H", y).add("u_over_U", u).add("solid_fraction", nu).add("temperature_over_U2", T);
            sum.run = {{"steps", 1000}, {"wall_clock_s", 0.5}};
            const bool transient = dem && P > 1000 && U > 1.5;
            set_regime(sum.run, transient ? RegimeStatus::Transient : RegimeStatus::Steady, transient ? "too short" : "");
            if (dem) {
                FlowDiagnostics d{0.05 * U, 0.04 * U, lifted ? 3.0 : 4.8, 0.9};
                sum.run["flow_regime"] = flow_regime_json(d);
            }
            if (solver == std::string("continuum")) {  // its own label, as the continuum writes it
                const double im = 0.15 * U;            // I/nu: collision above U = 4/3 m/s
                sum.run["lubrication"] = {{"verdict", im > 0.2 ? "collision lubrication" : "contact lubrication"},
                                          {"criterion", "I/nu against I0 = 0.2 (Chialvo & Sundaresan 2013, Eq. 35)"},
                                          {"inertial_number", 0.6 * im},
                                          {"inertial_number_over_solid_fraction", im}};
            }
            write_result(result_dir(s.o.results_root, solver, p.id), prof, sum);
        }
}

// Markers drawn open (white fill) that are not results marked unsteady: the per-load figures keep
// open markers for results that are not steady (svg_plot.cpp draws those with class "unsteady").
int open_steady_markers(const std::string& svg) {
    int n = 0;
    for (auto at = svg.find("fill=\"#ffffff\" stroke"); at != std::string::npos;
         at = svg.find("fill=\"#ffffff\" stroke", at + 1)) {
        const auto end = svg.find('>', at);
        if (svg.substr(at, end - at).find("class=\"unsteady\"") == std::string::npos) ++n;
    }
    return n;
}

std::string regime_part(const std::string& html) {
    const auto start = html.find("Regimes over speed and load</h2>");
    BOOST_TEST_REQUIRE(start != std::string::npos);
    const auto end = html.find("<h2", start);
    return html.substr(start, end - start);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(regime_report)

BOOST_AUTO_TEST_CASE(a_speed_by_load_sweep_draws_the_map_and_says_what_decided) {
    auto s = grid_case("regime_grid", "speed = [0.5, 1.0, 2.0]\nnormal_stress = [500.0, 2000.0]\n");
    BOOST_TEST_REQUIRE(s.c.points.size() == 6u);
    write_results(s);
    // one steady point (U = 1 m/s at 2000 Pa, Z = 4.8) whose Δt check's run at twice the step has
    // Z = 3.5: the step turns its verdict, so the map and the table put it at the transition
    const auto at = std::find_if(s.c.points.begin(), s.c.points.end(),
                                 [](const OperatingPoint& p) { return p.speed == 1.0 && p.normal_stress == 2000.0; });
    BOOST_TEST_REQUIRE((at != s.c.points.end()));
    const OperatingPoint& turned = *at;
    FlowDiagnostics coarse{0.05, 0.04, 3.5, 0.9};
    const nlohmann::json small = {{"relative_change", -0.01}, {"z", -0.5}};
    test::patch_run(s, "dem", turned.id,
                    {{"dt_refinement",
                      {{"mean_solid_fraction", {{"change", -0.001}}},
                       {"shear_stress_bottom", small},
                       {"shear_stress_top", small},
                       {"full_step_run", {{"status", "steady"}, {"flow_regime", flow_regime_json(coarse)}}}}}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path rep = s.o.results_root / "report";
    const std::string sec = regime_part(test::slurp(rep / "index.html"));
    BOOST_TEST(test::count(sec, "Z within its time-step error of 4") == 1u);
    BOOST_TEST(sec.find("at twice the step Z = 3.5, collision") != std::string::npos);
    BOOST_TEST(test::slurp(rep / "plots" / "regime_map_dem.svg").find("at the transition") != std::string::npos);
    for (const char* f : {"regime_map_dem", "regime_liftoff_gap_dem", "regime_liftoff_nu_dem", "regime_liftoff_nu_continuum",
                          "regime_mu_of_i_mid_gap",
                          "regime_mu_of_i_nominal", "regime_nu_of_i", "regime_tau_of_u_bottom_dem", "regime_tau_of_u_top_dem",
                          "regime_tau_of_u_top_continuum"}) {
        BOOST_TEST(fs::exists(rep / "plots" / (std::string(f) + ".svg")), f);
        if (fs::exists(rep / "plots" / (std::string(f) + ".svg"))) {
            const std::string err = test::xml_error(test::slurp(rep / "plots" / (std::string(f) + ".svg")));
            BOOST_TEST(err.empty(), f << ": " << err);
        }
    }
    BOOST_TEST(!fs::exists(rep / "plots" / "regime_map_continuum.svg"));  // no contacts, no verdict
    // lift-off: one figure per solver; none for a solver without a gap, nor for the lattice (named)
    BOOST_TEST(!fs::exists(rep / "plots" / "regime_liftoff_gap_continuum.svg"));
    BOOST_TEST(!fs::exists(rep / "plots" / "regime_liftoff_nu_automaton.svg"));
    BOOST_TEST(!fs::exists(rep / "plots" / "regime_tau_of_u_top_automaton.svg"));
    for (const char* f : {"regime_liftoff_gap_dem", "regime_liftoff_nu_dem", "regime_tau_of_u_top_dem",
                          "regime_tau_of_u_bottom_continuum"}) {
        const fs::path svg = rep / "plots" / (std::string(f) + ".svg");
        if (fs::exists(svg)) BOOST_TEST(open_steady_markers(test::slurp(svg)) == 0, f);
    }
    BOOST_TEST(sec.find("Not drawn: automaton") != std::string::npos);
    // every verdict with the criterion that decided it; no contradictory label anywhere
    BOOST_TEST(sec.find("collision lubrication") != std::string::npos);
    BOOST_TEST(sec.find("contact lubrication") != std::string::npos);
    BOOST_TEST(sec.find("Z = 3 &lt; 4") != std::string::npos);
    BOOST_TEST(sec.find(", enduring contacts") == std::string::npos);  // the old contradictory label
    // the continuum's own label, named as its own criterion; "—" only for the automaton, which has none
    BOOST_TEST(sec.find("continuum&#39;s own criterion, I/ν = 0.3: I/nu against I0 = 0.2") != std::string::npos);
    BOOST_TEST(sec.find("continuum&#39;s own criterion, I/ν = 0.075:") != std::string::npos);
    BOOST_TEST(test::count(sec, "own criterion") == 6u);  // the continuum at each of the six points
    BOOST_TEST(test::count(sec, "no regime label of its own") == 6u);  // the automaton at each
    // a reader meets no caption sentence more than twice and no title cut at its figure's edge
    const auto repeated = test::repeated_caption_sentences(test::slurp(rep / "index.html"));
    BOOST_TEST(repeated.empty(), fmt::format("{}", fmt::join(repeated, "\n")));
    const auto cut = test::cut_titles(rep / "plots");
    BOOST_TEST(cut.empty(), fmt::format("{}", fmt::join(cut, "\n")));
    // the transient point's own row keeps its run's verdict (marked); the point gets none from it
    BOOST_TEST(sec.find("no run here is a result") != std::string::npos);
    BOOST_TEST(test::count(sec, ">no verdict<") == 1u);
    // the experiment's critical shear rate at U = 100 1/s x 5 mm = 0.5 m/s
    const std::string map = test::slurp(rep / "plots" / "regime_map_dem.svg");
    BOOST_TEST(map.find("Sawyer") != std::string::npos);
    BOOST_TEST(sec.find("= 0.5 m/s") != std::string::npos);
    // the transient point drawn as one, and left out of the fits: dem has 2 steady speeds at 2000 Pa
    BOOST_TEST(map.find("transient") != std::string::npos);
    BOOST_TEST(sec.find("not fitted: 2 steady points") != std::string::npos);
    // the fits: dem n = 0 at 500 Pa (quasi-static), continuum n = 2 (Bagnold)
    BOOST_TEST(sec.find("quasi-static") != std::string::npos);
    BOOST_TEST(sec.find("Bagnold (collisional)") != std::string::npos);
    // the reference law is drawn and cited
    const std::string mu = test::slurp(rep / "plots" / "regime_mu_of_i_mid_gap.svg");
    BOOST_TEST(mu.find("Jop et al. 2006") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_one_point_case_and_a_speed_only_sweep_draw_no_map_and_say_why) {
    auto one = grid_case("regime_one", "speed = 1.0\nnormal_stress = 1000.0\n");
    write_results(one);
    BOOST_TEST(postproc::compare(one.c, one.o) == 0);
    std::string sec = regime_part(test::slurp(one.o.results_root / "report" / "index.html"));
    BOOST_TEST(sec.find("No regime map: the case has one operating point") != std::string::npos);
    BOOST_TEST(!fs::exists(one.o.results_root / "report" / "plots" / "regime_map_dem.svg"));

    auto speeds = grid_case("regime_speeds", "speed = [0.5, 1.0, 2.0]\nnormal_stress = 1000.0\n");
    write_results(speeds);
    BOOST_TEST(postproc::compare(speeds.c, speeds.o) == 0);
    sec = regime_part(test::slurp(speeds.o.results_root / "report" / "index.html"));
    BOOST_TEST(sec.find("No regime map: one load (P = 1000 Pa)") != std::string::npos);
    BOOST_TEST(!fs::exists(speeds.o.results_root / "report" / "plots" / "regime_map_dem.svg"));
}

BOOST_AUTO_TEST_CASE(a_hole_in_the_grid_is_drawn_as_one) {
    auto s = grid_case("regime_hole", "speed = [0.5, 1.0, 2.0]\nnormal_stress = [500.0, 2000.0]\n");
    write_results(s);
    // the solver could not run one point: no result there, the rest drawn
    fs::remove_all(result_dir(s.o.results_root, "dem", s.c.points.front().id));
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string map = test::slurp(s.o.results_root / "report" / "plots" / "regime_map_dem.svg");
    BOOST_TEST(map.find("no usable result") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
