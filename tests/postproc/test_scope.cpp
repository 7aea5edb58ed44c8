// What each solver's numbers mean, on the page: the scope table (body forces, what the wall
// stresses are, run length), the automaton's lattice stresses marked wherever they appear, and
// under load control the gap and P_top / target in the key numbers with the controlled normal
// stresses never fitted.
#include <fstream>
#include <regex>

#include <boost/test/unit_test.hpp>

#include "granlub/postproc/command.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

// The Markdown table row that starts with `| first | second |`, the first after `heading`.
std::string md_row(const std::string& md, const std::string& heading, const std::string& first,
                   const std::string& second = "") {
    const std::string start = "| " + first + " |" + (second.empty() ? "" : " " + second + " |");
    const auto at = md.find(start, md.find(heading));
    return at == std::string::npos ? std::string() : md.substr(at, md.find('\n', at) - at);
}

constexpr const char* kScope = "### What each solver's numbers mean";
constexpr const char* kKey = "### Key numbers";

}  // namespace

BOOST_AUTO_TEST_SUITE(scope)

BOOST_AUTO_TEST_CASE(each_solver_says_what_its_numbers_mean) {
    auto s = test::make_case("scope_fill");
    for (const char* solver : {"continuum", "automaton", "dem"}) test::write_solver(s, solver);
    for (const OperatingPoint& p : s.c.points) {
        test::patch_run(s, "continuum", p.id, {{"body_forces", "not modelled: p_yy uniform"}, {"iterations", 4}});
        test::patch_run(s, "automaton", p.id, {{"ignored", "gravity: no body force"}, {"steps", 10000}});
        test::patch_run(s, "dem", p.id,
                        {{"simulated_time_s", p.speed == 1.0 ? 0.25 : 0.5},
                         {"steps", 20000},
                         {"start", "warm, from a state"},
                         {"plate", "a loaded plate"},
                         {"model", "impulse"},
                         {"contact_solve", p.speed == 1.0 ? "single_pass" : "iterated"},
                         {"steady_state",
                          {{"allowed_relative_drift", {{"wall_stress", 0.035}, {"gap", 0.004}}}, {"sigmas", 3.0}}}});
    }
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string md = test::slurp(s.o.results_root / "report" / "report.md");

    const std::string continuum = md_row(md, kScope, "continuum");
    BOOST_TEST(continuum.find("gravity not modelled: p_yy uniform") != std::string::npos, continuum);
    BOOST_TEST(md_row(md, kScope, "automaton").find("ignores gravity: no body force") != std::string::npos);
    BOOST_TEST(md_row(md, kScope, "automaton").find("lattice analogues") != std::string::npos);
    // DEM: the case's gravity (9.81 by default) and its weight per area rho nu g H = 2500 * 0.52 * 9.81 * 5e-3 = 64 Pa
    // (the synthetic DEM's nu_bar is 0.56: 69 Pa); its run length from simulated_time_s over the points.
    const std::string dem = md_row(md, kScope, "dem");
    BOOST_TEST(dem.find("P_bot − P_top includes their weight") != std::string::npos, dem);
    BOOST_TEST(dem.find("≈ 69 Pa") != std::string::npos, dem);
    // Measured: the synthetic DEM's sigma_b - sigma_t = 100 U^1.5 over U = 1, 2, 4 -> 100 to 800 Pa.
    BOOST_TEST(dem.find("(measured P_bot − P_top: 100–800 Pa") != std::string::npos, dem);
    BOOST_TEST(dem.find("side walls") == std::string::npos, dem);  // not recorded: not mentioned
    BOOST_TEST(dem.find("0.25–0.5 s simulated") != std::string::npos, dem);
    BOOST_TEST(dem.find("(20000 steps)") != std::string::npos, dem);
    // how the run got there, as its summary says
    BOOST_TEST(dem.find("start: warm, from a state; load: a loaded plate") != std::string::npos, dem);
    BOOST_TEST(md_row(md, kScope, "continuum").find("start:") == std::string::npos);
    // how the steady window was found, from the run's own record
    BOOST_TEST(dem.find("within 3 combined standard errors or within 3.5 % (wall stresses) and 0.4 % (gap)") !=
                   std::string::npos,
               dem);

    // which contact operator made the DEM numbers (the first usable point's: U = 1, the single pass)
    BOOST_TEST(dem.find("Sawyer & Tichy's impulse operator, one pass over the contacts per step") != std::string::npos,
               dem);
    BOOST_TEST(continuum.find("contacts:") == std::string::npos);

    // The automaton's stresses are marked in every key-number cell and named in the stress captions.
    const std::string key = md_row(md, kKey, "automaton", "U1.0");
    BOOST_TEST(std::regex_search(key, std::regex(R"(\| 900 \(lattice\) \| 360 \(lattice\) \|)")), key);
    BOOST_TEST(md_row(md, kKey, "continuum", "U1.0").find("(lattice)") == std::string::npos);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("automaton (lattice analogue)") != std::string::npos);
    BOOST_TEST(html.find("stresses are lattice analogues") != std::string::npos);
}

// A point answered at a quarter step ([dem] refine_halvings = 2) is named with the verdict that sent
// it there; the run length compares with the runs the answers were checked against.
BOOST_AUTO_TEST_CASE(a_point_answered_at_a_quarter_step_says_why) {
    auto s = test::make_case("scope_quarter");
    test::write_solver(s, "dem");
    const std::string why = "halving the time step moves shear_stress_bottom by -9.1 % (-11.1 standard errors)";
    for (const OperatingPoint& p : s.c.points) {
        const bool quarter = &p == &s.c.points.front();
        nlohmann::json rec = {{"time_step_s", quarter ? 2.5e-7 : 5e-7},
                              {"start", "cold: from the initial grains, the whole run at dt/2"},
                              {"mean_solid_fraction", {{"change", 0.001}}},
                              {"shear_stress_bottom", {{"relative_change", 0.003}, {"z", 0.2}}},
                              {"shear_stress_top", {{"relative_change", 0.01}, {"z", 0.5}}},
                              {"full_step_run", {{"status", "steady"}, {"steps", 1000}, {"time_step_s", 1e-6}}}};
        if (quarter) {
            rec["halvings"] = 2;
            rec["half_step_run"] = {{"status", "steady"}, {"steps", 2000}, {"time_step_s", 5e-7}};
            rec["first_check"] = {{"verdict", why}};
        }
        test::patch_run(s, "dem", p.id, {{"simulated_time_s", 0.001}, {"dt_refinement", rec}});
    }
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string dem = md_row(test::slurp(s.o.results_root / "report" / "report.md"), kScope, "dem");
    BOOST_TEST(dem.find("checked against a run of 0.001 s at twice the step") != std::string::npos, dem);
    BOOST_TEST(dem.find(s.c.points.front().id + ": at a quarter of the step (cold, the whole run), checked against "
                        "the half step, because the half step failed its check against the full step (" + why + ")") !=
                   std::string::npos,
               dem);
    BOOST_TEST(dem.find(s.c.points.back().id + ": at a quarter") == std::string::npos, dem);
}

// A dense point ([dem] dense_inertial_number) ran at half the case's step: the run length names it,
// with its nominal inertial number and the threshold; a point above the threshold is not named.
BOOST_AUTO_TEST_CASE(a_dense_point_at_half_the_step_is_named) {
    auto s = test::make_case("scope_dense");
    test::write_solver(s, "dem");
    const OperatingPoint& dense = s.c.points.front();
    test::patch_run(s, "dem", dense.id,
                    {{"simulated_time_s", 0.001},
                     {"dense_step",
                      {{"inertial_number_nominal", 0.1837}, {"dense_inertial_number", 0.2}, {"case_time_step_s", 1e-6}}}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string dem = md_row(test::slurp(s.o.results_root / "report" / "report.md"), kScope, "dem");
    BOOST_TEST(dem.find("dense points, whose nominal inertial number U d/(H √(P/ρ)) is below 0.2 ([dem] "
                        "dense_inertial_number), run at half the case's step, and so do their checks: " +
                        dense.id + " (nominal I 0.18)") != std::string::npos,
               dem);
    BOOST_TEST(dem.find(s.c.points.back().id + " (nominal I") == std::string::npos, dem);
}

// [dem] quarter_step_inertial_number: a point below it ran at a quarter of the case's step (dense_step
// halvings 2): the run length names it in its own clause, with that threshold, and not among the half-step
// points; the [Δt x] note adds the eighth-against-a-quarter sentence only then.
BOOST_AUTO_TEST_CASE(a_dense_point_at_a_quarter_of_the_step_is_named_apart) {
    auto s = test::make_case("scope_dense_quarter");
    test::write_solver(s, "dem");
    const OperatingPoint& quarter = s.c.points.front();
    const OperatingPoint& half = s.c.points.back();
    BOOST_TEST_REQUIRE(quarter.id != half.id);
    test::patch_run(s, "dem", quarter.id,
                    {{"simulated_time_s", 0.001},
                     {"dense_step",
                      {{"inertial_number_nominal", 0.0841}, {"dense_inertial_number", 0.2}, {"halvings", 2},
                       {"quarter_step_inertial_number", 0.1}, {"case_time_step_s", 4e-6}}}});
    test::patch_run(s, "dem", half.id,
                    {{"simulated_time_s", 0.001},
                     {"dense_step",
                      {{"inertial_number_nominal", 0.1837}, {"dense_inertial_number", 0.2}, {"halvings", 1},
                       {"case_time_step_s", 2e-6}}}});
    const auto file = result_dir(s.o.results_root, "dem", quarter.id) / "summary.json";
    auto j = nlohmann::json::parse(test::slurp(file));
    j["outputs"]["shear_stress_bottom"]["dt_error"] = 5.0;  // a checked value: the [Δt x] note is written
    write_file_atomic(file, j.dump(2));
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string md = test::slurp(s.o.results_root / "report" / "report.md");
    const std::string dem = md_row(md, kScope, "dem");
    BOOST_TEST(dem.find("run at half the case's step, and so do their checks: " + half.id + " (nominal I 0.18)") !=
                   std::string::npos,
               dem);
    BOOST_TEST(dem.find("; dense points whose nominal inertial number is below 0.1 ([dem] "
                        "quarter_step_inertial_number) run at a quarter of the case's step, and so do their checks: " +
                        quarter.id + " (nominal I 0.084)") != std::string::npos,
               dem);
    BOOST_TEST(dem.find(quarter.id + " (nominal I 0.084), ") == std::string::npos, dem);  // named once
    BOOST_TEST(md.find("below [dem] quarter_step_inertial_number Δt is a quarter of the case's step, the value comes "
                       "from an eighth, checked against a quarter") != std::string::npos);
}

// The [Δt x] note says that a dense point's Δt is half the case's step, only when there is one.
BOOST_AUTO_TEST_CASE(the_dt_note_names_the_dense_step_only_with_a_dense_point) {
    const std::string clause = "For a dense point ([dem] dense_inertial_number) Δt is itself half the case's step";
    for (const bool dense : {false, true}) {
        auto s = test::make_case(dense ? "dt_note_dense" : "dt_note_plain");
        test::write_solver(s, "dem");
        const OperatingPoint& p = s.c.points.front();
        // a checked value (the note is written only then)
        const auto file = result_dir(s.o.results_root, "dem", p.id) / "summary.json";
        auto j = nlohmann::json::parse(test::slurp(file));
        j["outputs"]["shear_stress_bottom"]["dt_error"] = 5.0;
        write_file_atomic(file, j.dump(2));
        if (dense)
            test::patch_run(s, "dem", p.id,
                            {{"dense_step",
                              {{"inertial_number_nominal", 0.1837}, {"dense_inertial_number", 0.2}, {"case_time_step_s", 1e-6}}}});
        BOOST_TEST(postproc::compare(s.c, s.o) == 0);
        const std::string md = test::slurp(s.o.results_root / "report" / "report.md");
        BOOST_TEST(md.find("[Δt x]: the value comes from the run at half the time step") != std::string::npos);
        BOOST_TEST((md.find(clause) != std::string::npos) == dense, dense);
        BOOST_TEST(md.find("quarter_step_inertial_number") == std::string::npos);  // no point at a quarter
    }
}

BOOST_AUTO_TEST_CASE(load_control_shows_gap_and_load_and_fits_no_normal_stress) {
    auto s = test::edited_case("scope_load", "control = \"fill\"", "control = \"load\"");  // target 1000 Pa
    test::write_solver(s, "continuum");
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string md = test::slurp(s.o.results_root / "report" / "report.md");
    BOOST_TEST(md.find("| ν̄/ν_max | gap (mm) | P_top / target |") != std::string::npos);
    // The synthetic continuum: sigma_top = 900 U^2 against the 1000 Pa target; its gap is the case's (5 mm).
    const std::string u1 = md_row(md, kKey, "continuum", "U1.0");
    BOOST_TEST(u1.find("| 5 (fixed) | 0.9 |") != std::string::npos, u1);
    BOOST_TEST(md_row(md, kKey, "continuum", "U2.0").find("| 5 (fixed) | 3.6 |") != std::string::npos);

    // The normal stresses follow the load: no exponent, the reason instead; the shear stresses are fitted (n = 2).
    const auto metrics = s.o.results_root / "report" / "metrics.csv";
    for (const char* q : {"normal_stress_top", "normal_stress_bottom"}) {
        const auto row = test::read_metrics_row(metrics, "exponent", "all", q, "continuum", "");
        BOOST_TEST(row.at("a").empty(), q);
        BOOST_TEST(row.at("note").find("load control") != std::string::npos, row.at("note"));
    }
    // The target drawn in the top-wall figure, said in its caption.
    const std::string top = test::slurp(s.o.results_root / "report" / "plots" / "stress_normal_stress_top.svg");
    BOOST_TEST(top.find(">load target</text>") != std::string::npos);
    BOOST_TEST(md.find("Black dashed: the load target of the case.") != std::string::npos);
    const auto tau = test::read_metrics_row(metrics, "exponent", "all", "shear_stress_bottom", "continuum", "");
    BOOST_TEST(std::stod(tau.at("a")) == 2.0, boost::test_tools::tolerance(1e-9));
}

// Two speeds can never give a fit: one sentence says so, no per-solver list, no exponent table.
BOOST_AUTO_TEST_CASE(too_few_speeds_say_so_once) {
    auto s = test::edited_case("scope_two_speeds", "speed = [1.0, 2.0, 4.0]", "speed = [1.0, 2.0]");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string md = test::slurp(s.o.results_root / "report" / "report.md");
    BOOST_TEST(md.find("No power law: no group of points that differ only in speed has 3 speeds.") !=
               std::string::npos);
    BOOST_TEST(md.find("has 2 steady points (a fit needs 3)") == std::string::npos);
    BOOST_TEST(md.find("| solver | speed group |") == std::string::npos);
    BOOST_TEST(md.find("No stress–speed exponent") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
