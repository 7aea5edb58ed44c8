// The summary first: per quantity and point who agrees within the combined errors, the largest
// disagreement with its size, and the numbers that are not answers; one line when all agree. The
// regime as one verdict, "at the transition" where the particle engines straddle Z = 4.
#include <filesystem>

#include <boost/test/unit_test.hpp>

#include "granlub/postproc/command.h"
#include "granlub/results/file_io.h"
#include "figures/cross_section_map.h"
#include "report/summary.h"
#include "results/collect.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(summary)

BOOST_AUTO_TEST_CASE(who_agrees_and_what_is_not_an_answer) {
    auto s = test::make_case("summary");
    for (const char* solver : {"continuum", "automaton", "dem"}) test::write_solver(s, solver);
    test::patch_run(s, "dem", s.c.points.back().id, {{"status", "transient"}, {"status_reason", "not steady"}});
    const auto col = postproc::collect(s.c, s.o);
    const auto sum = postproc::case_summary(col);
    BOOST_TEST(!sum.all_agree);
    // U = 1 m/s: τ_bottom continuum 400 Pa, dem 450 ± 22.5 Pa: z = 2.2, they differ (+13 %).
    const auto& header = sum.table.header;
    BOOST_TEST_REQUIRE(header.size() == 4u);
    const auto row = std::find_if(sum.table.rows.begin(), sum.table.rows.end(),
                                  [](const auto& r) { return r[0].text == "τ moving wall"; });
    BOOST_TEST_REQUIRE((row != sum.table.rows.end()));
    BOOST_TEST((*row)[1].text == "dem +12\u00a0% (z = 2.2) vs continuum", (*row)[1].text);
    // The automaton's stresses are no answer (lattice analogues), and the transient dem point is named.
    std::string all;
    for (const auto& t : sum.sentences) all += t + "\n";
    BOOST_TEST(all.find("automaton's wall stresses (lattice analogues)") != std::string::npos, all);
    BOOST_TEST(all.find("dem at U4.0 (transient: it ended before a steady state)") != std::string::npos, all);
    BOOST_TEST(all.find("Largest disagreement:") != std::string::npos, all);
}

BOOST_AUTO_TEST_CASE(one_line_when_everything_agrees) {
    auto s = test::make_case("summary_agree");
    test::write_solver(s, "continuum");
    fs::copy(s.o.results_root / "continuum", s.o.results_root / "copy", fs::copy_options::recursive);
    for (const auto& p : s.c.points) {  // the copy names its own solver
        const auto file = s.o.results_root / "copy" / p.id / "summary.json";
        auto j = nlohmann::json::parse(test::slurp(file));
        j["solver"] = "copy";
        j["provenance"]["inputs_hash"] = s.c.inputs_hash("copy");  // a solver without a section of its own
        write_file_atomic(file, j.dump(2));
    }
    const auto sum = postproc::case_summary(postproc::collect(s.c, s.o));
    BOOST_TEST(sum.all_agree);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("<p>All 2 solvers (continuum, copy) agree within their combined errors on every quantity at every point.</p>") !=
               std::string::npos);
}

// Engines on either side of Z = 4 give one short verdict, "at the transition", with each engine's
// Z and reading (the regime table has the thresholds and persistence): it has to fit the summary.
BOOST_AUTO_TEST_CASE(engines_on_either_side_read_at_the_transition) {
    auto s = test::make_case("summary_transition");
    for (const char* solver : {"dem", "yade"}) test::write_solver(s, solver);
    const std::string id = s.c.points.front().id;
    auto regime = [](const char* verdict, double z) {
        return nlohmann::json{{"verdict_version", 2}, {"regime", verdict}, {"criterion", "test"},
                              {"coordination_number", z}, {"coordination_number_stderr", 0.02},
                              {"contact_persistence", 0.8}};
    };
    test::patch_run(s, "dem", id, {{"flow_regime", regime("contact lubrication", 4.35)}});
    test::patch_run(s, "yade", id, {{"flow_regime", regime("collision lubrication", 3.92)}});
    const auto r = postproc::regime_reading(postproc::collect(s.c, s.o), id);
    BOOST_TEST_REQUIRE(r.has_value());
    BOOST_TEST(r->uncertain);
    BOOST_TEST(r->text == "at the transition (engines disagree): dem Z = 4.35 (contact), yade Z = 3.92 (collision)",
               r->text);
}

// A verdict the time step turns: collision at the answer's step, contact in its Δt check's run at
// twice the step. The summary says so with both numbers; the regime table's criterion has them too.
BOOST_AUTO_TEST_CASE(a_verdict_the_time_step_turns_reads_at_the_transition) {
    auto s = test::make_case("summary_step_transition");
    test::write_solver(s, "dem");
    const std::string id = s.c.points.front().id;
    auto regime = [](const char* verdict, double z) {
        return nlohmann::json{{"verdict_version", 2}, {"regime", verdict}, {"criterion", "test"},
                              {"coordination_number", z}, {"coordination_number_stderr", 0.02},
                              {"contact_persistence", 0.8}};
    };
    const nlohmann::json small = {{"relative_change", -0.01}, {"z", -0.5}};
    const nlohmann::json check = {{"mean_solid_fraction", {{"change", -0.001}}},
                                  {"shear_stress_bottom", small},
                                  {"shear_stress_top", small},
                                  {"full_step_run", {{"status", "steady"}, {"flow_regime", regime("contact lubrication", 4.12)}}}};
    test::patch_run(s, "dem", id, {{"flow_regime", regime("collision lubrication", 3.93)}, {"dt_refinement", check}});
    const auto col = postproc::collect(s.c, s.o);
    const auto r = postproc::regime_reading(col, id);
    BOOST_TEST_REQUIRE(r.has_value());
    BOOST_TEST(r->uncertain);
    BOOST_TEST(r->text == "at the transition (Z within its time-step error of 4): dem Z = 3.93 (collision; 4.12 at "
                          "twice the step)",
               r->text);
    // the other point has no check: its verdict stands
    const auto other = postproc::regime_reading(col, s.c.points.back().id);
    BOOST_TEST((!other || other->text.find("twice the step") == std::string::npos));
}

// Each state named as what it is: a dt-unconverged run's cross-section is not stamped "TRANSIENT".
BOOST_AUTO_TEST_CASE(cross_section_stamps_name_the_state) {
    auto s = test::make_case("stamps");
    test::write_solver(s, "dem");
    const auto& p = s.c.points;
    test::patch_run(s, "dem", p[1].id, {{"status", "transient"}, {"status_reason", "not steady"}});
    test::patch_run(s, "dem", p[2].id, {{"status", "dt-unconverged"}, {"status_reason", "halving dt moved tau by 9 %"}});
    const auto col = postproc::collect(s.c, s.o);
    BOOST_TEST(postproc::cross_section_stamp(col.run("dem", p[0].id)) == "");
    BOOST_TEST(postproc::cross_section_stamp(col.run("dem", p[1].id)) == "TRANSIENT — not a result");
    BOOST_TEST(postproc::cross_section_stamp(col.run("dem", p[2].id)) == "DT-UNCONVERGED — Δt changes it");
    const std::string svg = postproc::render_cross_section_svg({1, 1, {0.5}, {0}, {0.6}, {0.5}}, {0.6}, "t", "ν",
                                                         postproc::cross_section_stamp(col.run("dem", p[2].id)));
    BOOST_TEST(svg.find(">DT-UNCONVERGED — Δt changes it</text>") != std::string::npos);
    BOOST_TEST(svg.find("TRANSIENT") == std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
