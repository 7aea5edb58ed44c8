// The report never passes off a transient: a DEM point that is not steady is named with its
// reason, greyed in the tables, drawn hollow in the plots, left out of the fits and of the
// differences; a failed point shows the solver's message; old summaries read as "status unknown".
#include <regex>

#include <boost/test/unit_test.hpp>

#include "granlub/results/failure_record.h"
#include "granlub/postproc/command.h"
#include "granlub/results/results.h"
#include "synthetic.h"
#include "xml_check.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

// The <tr> of an HTML table whose text contains `what`, the first one from `from` (empty when none).
std::string table_row(const std::string& html, const std::string& what, std::size_t from = 0) {
    const auto at = html.find(what, from);
    if (at == std::string::npos) return {};
    const auto begin = html.rfind("<tr>", at), end = html.find("</tr>", at);
    return html.substr(begin, end - begin);
}

constexpr const char* kReason = "no steady state detected in 0.1 s of simulated time: run longer (--full)";

}  // namespace

BOOST_AUTO_TEST_SUITE(status)

BOOST_AUTO_TEST_CASE(a_transient_dem_point_is_never_passed_off) {
    auto s = test::make_case("status_transient");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    const std::string p1 = s.c.points[0].id, p2 = s.c.points[1].id;  // U = 1, 2 m/s
    test::patch_run(s, "dem", p2, {{"status", "transient"}, {"status_reason", kReason}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path rep = s.o.results_root / "report";
    const std::string html = test::slurp(rep / "index.html");
    BOOST_TEST(test::xml_error(html).empty());

    // Status table and the reasons under it; key numbers greyed with a status column.
    BOOST_TEST(test::count(html, "<td class=\"transient\">transient</td>") == 3u);  // status grid, reasons, key numbers
    BOOST_TEST(html.find(kReason) != std::string::npos);
    BOOST_TEST(test::count(html, "<td class=\"ok\">steady</td>") >= 5u);
    const std::string key_row = table_row(html, "<td class=\"transient\">transient</td><td class=\"transient\">");
    BOOST_TEST(key_row.find(p2) != std::string::npos, key_row);

    // metrics.csv: the status of each run; no difference or z for the transient pair, one for a steady pair.
    const fs::path csv = rep / "metrics.csv";
    auto r2 = test::read_metrics_row(csv, "scalar", p2, "shear_stress_bottom", "continuum", "dem");
    BOOST_TEST_REQUIRE(!r2.empty());
    BOOST_TEST(r2["status_a"] == "steady");
    BOOST_TEST(r2["status_b"] == "transient");
    BOOST_TEST(r2["z"].empty());
    BOOST_TEST(r2["difference"].empty());
    BOOST_TEST(r2["significant"].empty());
    BOOST_TEST(r2["note"] == "not compared: dem is transient");
    BOOST_TEST(!r2["b"].empty());  // the value itself is listed, labelled
    auto r1 = test::read_metrics_row(csv, "scalar", p1, "shear_stress_bottom", "continuum", "dem");
    BOOST_TEST(r1["status_b"] == "steady");
    BOOST_TEST(!r1["z"].empty());
    BOOST_TEST(test::read_metrics_row(csv, "profile", p2, "u_over_U", "continuum", "dem")["rms_difference"].empty());

    // Differences tables: the transient pair's cells show no number and are never bold.
    const std::string pair = "continuum − dem (dem: transient)";
    const std::string prof_row = table_row(html, pair), scalar_row = table_row(html, pair, html.find(pair) + 1);
    BOOST_TEST(test::count(prof_row, "<td class=\"transient\">—, transient</td>") == 3u);    // every profile
    BOOST_TEST(test::count(scalar_row, "<td class=\"transient\">—, transient</td>") == 7u);  // every scalar
    for (const auto& row : {prof_row, scalar_row}) {
        BOOST_TEST(row.find("significant") == std::string::npos, row);
        BOOST_TEST(row.find("z =") == std::string::npos, row);
    }
    BOOST_TEST(test::count(html, "<td class=\"transient\">—, transient</td>") == 10u);
    // ... whereas the steady pair at U = 1 has bold cells (sigma ~ U^2 vs U^1.5 with 5 % errors).
    BOOST_TEST(table_row(html, "<td>continuum − dem</td>").find("significant") != std::string::npos);
    BOOST_TEST(test::slurp(rep / "report.md").find("_—, transient_") != std::string::npos);

    // Fits: the dem has 2 steady speeds left, fewer than 3: not fitted; the continuum still is.
    auto e = test::read_metrics_row(csv, "exponent", "all", "shear_stress_bottom", "dem", "");
    BOOST_TEST_REQUIRE(!e.empty());
    BOOST_TEST(e["a"].empty());
    BOOST_TEST(e["note"] == "not fitted: 2 steady points (needs 3); 1 point not steady, left out");
    BOOST_TEST(std::stod(test::read_metrics_row(csv, "exponent", "all", "shear_stress_bottom", "continuum", "")["a"]) ==
               2.0);
    BOOST_TEST(html.find("n = 1.50") == std::string::npos);  // no dem power law anywhere

    // The stress plot: dem (Okabe-Ito bluish green, triangles) has 2 filled markers + legend, and
    // the transient point hollow, dashed and faded + its legend entry, labelled as such.
    const std::string svg = test::slurp(rep / "plots" / "stress_shear_stress_bottom.svg");
    BOOST_TEST(test::xml_error(svg).empty());
    const std::regex filled("<polygon points=\"[^\"]+\" fill=\"#009E73\" stroke=\"#009E73\" stroke-width=\"1.4\"/>");
    const std::regex hollow("<polygon points=\"[^\"]+\" fill=\"#ffffff\" stroke=\"#009E73\" stroke-width=\"1.4\" "
                            "stroke-dasharray=\"2 1.5\" class=\"unsteady\" opacity=\"0.55\"/>");
    auto matches = [&](const std::regex& re) {
        return static_cast<std::size_t>(std::distance(std::sregex_iterator(svg.begin(), svg.end(), re), std::sregex_iterator()));
    };
    BOOST_TEST(matches(filled) == 3u);
    BOOST_TEST(matches(hollow) == 2u);
    BOOST_TEST(svg.find(">dem: transient</text>") != std::string::npos);
    BOOST_TEST(html.find("results that are NOT steady") != std::string::npos);  // the caption says so
    BOOST_TEST(html.find("No power law: dem has 2 steady points (a fit needs 3).") != std::string::npos);
    // The profile plot at U = 2: the dem line dotted and faded.
    const std::string prof = test::slurp(rep / "plots" / ("profile_u2-0_u.svg"));
    BOOST_TEST(prof.find("stroke-dasharray=\"1.5 3\" class=\"unsteady\"") != std::string::npos);
    // The gnuplot source draws it hollow and faded too (#80 alpha), titled as transient.
    const std::string gp = test::slurp(rep / "plots" / "stress_shear_stress_bottom.gp");
    BOOST_TEST(gp.find("pt 8 ps 1.1 lc rgb '#80009E73' title 'dem: transient'") != std::string::npos, gp);

    // `granlub run`'s closing table says it too.
    const std::string table = postproc::summary_table(s.c, s.o);
    BOOST_TEST(table.find("dem " + p2 + ": transient: " + kReason) != std::string::npos, table);
}

BOOST_AUTO_TEST_CASE(failed_unknown_and_dt_unconverged_points_say_why) {
    auto s = test::make_case("status_failed");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    const auto& pts = s.c.points;
    // continuum U4: failed (no result, failure.json); U1: an old summary without run.status;
    // dem U1: halving the time step moved the bottom shear stress by 9 % = 4 standard errors.
    const fs::path failed = result_dir(s.o.results_root, "continuum", pts[2].id);
    fs::remove(failed / "summary.json");
    const std::string msg = "point U4.0: Newton did not converge in 50 iterations (residual 3.2e-02): try more cells";
    write_failure(failed, "continuum", pts[2].id, msg);
    test::patch_run(s, "continuum", pts[0].id, {{"status", nullptr}, {"status_reason", nullptr}});
    test::patch_run(s, "dem", pts[0].id,
                    {{"dt_refinement",
                      {{"time_step_s", 5e-7},
                       {"mean_solid_fraction", {{"change", 0.001}}},
                       {"shear_stress_bottom", {{"relative_change", 0.09}, {"z", 4.0}}},
                       {"shear_stress_top", {{"relative_change", 0.01}, {"z", 0.5}}}}}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(test::count(html, "<td class=\"failed\">failed</td>") == 2u);  // status grid and reasons
    BOOST_TEST(html.find(msg) != std::string::npos);
    BOOST_TEST(html.find("<td class=\"unknown\">status unknown</td>") != std::string::npos);
    BOOST_TEST(html.find("<td class=\"transient\">dt-unconverged</td>") != std::string::npos);
    BOOST_TEST(html.find("moves shear_stress_bottom by +9.0 % (4.0 standard errors") != std::string::npos);
    // Both U1 results are not steady: the pair is not compared.
    auto r = test::read_metrics_row(s.o.results_root / "report" / "metrics.csv", "scalar", pts[0].id,
                                          "normal_stress_top", "continuum", "dem");
    BOOST_TEST(r["note"] == "not compared: continuum is status unknown, dem is dt-unconverged");
    BOOST_TEST(postproc::summary_table(s.c, s.o).find("continuum " + pts[2].id + ": failed: " + msg) != std::string::npos);
    // A later success removes the record: the point is then simply missing.
    remove_failure(failed);
    BOOST_TEST(!fs::exists(failed / kFailureFile));
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    BOOST_TEST(test::slurp(s.o.results_root / "report" / "index.html").find(msg) == std::string::npos);
    // A point the model has no answer for is said so, not shown as a failure.
    const std::string none = "point U4.0: granlub yade runs the slice only";
    fs::remove(result_dir(s.o.results_root, "dem", pts[2].id) / "summary.json");
    write_failure(result_dir(s.o.results_root, "dem", pts[2].id), "dem", pts[2].id, none, true);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string with_none = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(test::count(with_none, "<td class=\"noanswer\">no answer</td>") == 2u);  // status grid and reasons
    BOOST_TEST(with_none.find(none) != std::string::npos);
    BOOST_TEST(test::count(with_none, "<td class=\"failed\">") == 0u);
}

BOOST_AUTO_TEST_SUITE_END()

// Which error the statistics use (issue 76): one run's block error, with the measured factor by
// which other seeds scatter more and where it was measured; a result pooled over seeds, the seeds'
// standard error; an incomplete set is no answer.
BOOST_AUTO_TEST_CASE(the_report_says_which_error_it_uses) {
    auto s = test::make_case("status_error_used");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    std::string md = test::slurp(s.o.results_root / "report" / "report.md");  // the HTML escapes the apostrophes
    BOOST_TEST(md.find("The standard errors are each run's own") != std::string::npos);
    BOOST_TEST(md.find("3.5 times one run's block error in LIGGGHTS and 5.1 times in YADE") != std::string::npos);
    BOOST_TEST(md.find("cases/sawyer2001_rough_hertz/README.md") != std::string::npos);
    BOOST_TEST(md.find("a median 2.1 and up to 6.5 times") != std::string::npos);
    BOOST_TEST(md.find("docs/measurements/dt-error.md") != std::string::npos);
    BOOST_TEST(md.find("six seeds at 2.0 m/s there: 4–5 times in ν̄ and τ") != std::string::npos);
    BOOST_TEST(md.find("use the seeds' standard error") == std::string::npos);
    BOOST_TEST(test::slurp(s.o.results_root / "report" / "metrics.csv").find("a_stderr, b_stderr: a particle result "
                                                                           "pooled over seeds") != std::string::npos);

    // every dem point pooled over three seeds: the legend names the seeds' error alone
    for (const auto& p : s.c.points) test::patch_run(s, "dem", p.id, {{"seeds", {{"pooled", {1, 2, 3}}}}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    md = test::slurp(s.o.results_root / "report" / "report.md");
    BOOST_TEST(md.find("use the seeds' standard error") != std::string::npos);
    BOOST_TEST(md.find("The standard errors are each run's own") == std::string::npos);
    BOOST_TEST(md.find("3.5 times") == std::string::npos);

    // one point left with one run: both, the measured factor for that one
    test::patch_run(s, "dem", s.c.points[0].id, {{"seeds", nullptr}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    md = test::slurp(s.o.results_root / "report" / "report.md");
    BOOST_TEST(md.find("use the seeds' standard error") != std::string::npos);
    BOOST_TEST(md.find("The other statistical results' standard errors are each run's own") != std::string::npos);

    // an incomplete set is labelled and not compared
    test::patch_run(s, "dem", s.c.points[1].id,
                    {{"status", "incomplete"}, {"status_reason", "incomplete: 2 of 3 seeds; missing seed 3 (not run yet)"}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    md = test::slurp(s.o.results_root / "report" / "report.md");
    BOOST_TEST(md.find("incomplete: 2 of 3 seeds; missing seed 3 (not run yet)") != std::string::npos);
    const auto m = test::read_metrics_row(s.o.results_root / "report" / "metrics.csv", "scalar", s.c.points[1].id,
                                          "shear_stress_bottom", "continuum", "dem");
    BOOST_TEST(m.at("z").empty());
    BOOST_TEST(m.at("status_b") == "incomplete");
}
