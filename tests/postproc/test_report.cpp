// The report end to end on synthetic results: every file exists and parses (index.html and every
// SVG as XML via expat, the gnuplot scripts by running gnuplot, the ParaView files as XML with
// their blocks); partial, stale and corrupt results are stated, not plotted.
#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <regex>

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include "granlub/error.h"
#include "granlub/postproc/command.h"
#include "granlub/results/results.h"
#include "synthetic.h"
#include "xml_check.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

std::vector<fs::path> files_with(const fs::path& dir, const std::string& ext) {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().extension() == ext) out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

void expect_well_formed(const fs::path& p) {
    const std::string err = test::xml_error(test::slurp(p));
    BOOST_TEST(err.empty(), p.string() << ": not well-formed XML: " << err);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(report)

BOOST_AUTO_TEST_CASE(full_report_exists_and_parses) {
    auto s = test::make_case("report_full");
    for (const char* solver : {"continuum", "automaton", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path rep = s.o.results_root / "report";
    for (const char* f : {"index.html", "report.md", "metrics.csv"}) BOOST_TEST(fs::exists(rep / f), f);

    const std::string html = test::slurp(rep / "index.html");
    expect_well_formed(rep / "index.html");
    // 3 points x 3 profiles + 4 stresses + 2 slips + 1 solid fraction.
    const auto svgs = files_with(rep / "plots", ".svg");
    BOOST_TEST(svgs.size() == 16u);
    BOOST_TEST(test::count(html, "<svg ") == 16u);
    for (const auto& svg : svgs) {
        expect_well_formed(svg);
        const auto stem = svg.stem().string();
        BOOST_TEST(fs::exists(rep / "plots" / (stem + ".dat")), stem);
        BOOST_TEST(fs::exists(rep / "plots" / (stem + ".gp")), stem);
        BOOST_TEST(fs::exists(rep / "plots" / (stem + ".pdf")), stem);  // the figure as PDF (rsvg-convert)
        BOOST_TEST(html.find("<a href=\"plots/" + stem + ".pdf\">PDF</a>") != std::string::npos, stem);
        BOOST_TEST(test::slurp(rep / "plots" / (stem + ".pdf")).starts_with("%PDF"), stem);
    }
    BOOST_TEST(html.find("solvers compared: continuum, automaton, dem; missing (no usable results): yade.") !=
               std::string::npos);
    BOOST_TEST(html.find("n = 1.50 ± 0.05") != std::string::npos);  // the dem's fitted exponent in a legend
    BOOST_TEST(!std::regex_search(html, std::regex("[^A-Za-z](nan|inf)[^A-Za-z]", std::regex::icase)));
    const std::string md = test::slurp(rep / "report.md");
    BOOST_TEST(md.find("![Shear stress on the moving wall](plots/stress_shear_stress_bottom.svg)") != std::string::npos);

    // ParaView: one .vtm per point, one block per solver, each a .vtp that exists and parses.
    const auto vtms = files_with(rep / "paraview", ".vtm");
    BOOST_TEST(vtms.size() == 3u);
    for (const auto& vtm : vtms) {
        expect_well_formed(vtm);
        const std::string text = test::slurp(vtm);
        const std::regex file_attr("file=\"([^\"]+)\"");
        std::size_t blocks = 0;
        for (auto it = std::sregex_iterator(text.begin(), text.end(), file_attr); it != std::sregex_iterator(); ++it) {
            const fs::path vtp = vtm.parent_path() / (*it)[1].str();
            BOOST_TEST(fs::exists(vtp), vtp.string());
            if (fs::exists(vtp)) {
                expect_well_formed(vtp);
                BOOST_TEST(test::slurp(vtp).find("Name=\"nu_over_numax\"") != std::string::npos);
            }
            ++blocks;
        }
        BOOST_TEST(blocks == 3u);
        for (const char* name : {"name=\"continuum\"", "name=\"automaton\"", "name=\"dem\""})
            BOOST_TEST(text.find(name) != std::string::npos, vtm.string() << " lacks block " << name);
    }
    // The staging and old folders are gone.
    for (const auto& e : fs::directory_iterator(s.o.results_root))
        BOOST_TEST(e.path().filename().string().find(".report") == std::string::npos, e.path().string());
}

BOOST_AUTO_TEST_CASE(gnuplot_sources_render) {
    BOOST_TEST_REQUIRE(fs::exists("/usr/bin/gnuplot"), "gnuplot (gnuplot-nox, .ci/packages) is needed");
    auto s = test::make_case("report_gnuplot");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path plots = s.o.results_root / "report" / "plots";
    for (const auto& gp : files_with(plots, ".gp")) {
        const std::string cmd = "cd '" + plots.string() + "' && gnuplot '" + gp.filename().string() + "' 2>/dev/null";
        BOOST_TEST(std::system(cmd.c_str()) == 0, gp.string());
        const fs::path out = plots / (gp.stem().string() + ".gnuplot.svg");
        BOOST_TEST_REQUIRE(fs::exists(out), out.string());
        expect_well_formed(out);
    }
}

BOOST_AUTO_TEST_CASE(partial_results_state_missing_solvers) {
    auto s = test::make_case("report_partial");
    test::write_solver(s, "continuum");
    // Only the first point of the continuum survives.
    for (std::size_t i = 1; i < s.c.points.size(); ++i) fs::remove_all(result_dir(s.o.results_root, "continuum", s.c.points[i].id));
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    expect_well_formed(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("solvers compared: continuum; missing (no usable results): automaton, dem, yade.") != std::string::npos);
    BOOST_TEST(html.find("No point has results from two solvers") != std::string::npos);
    BOOST_TEST(test::count(html, "<td class=\"missing\">missing</td>") == 2u);  // continuum's other two points
    const std::string table = postproc::summary_table(s.c, s.o);
    BOOST_TEST(table.find("dem") != std::string::npos);
    BOOST_TEST(table.find("no results") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(stale_results_are_named_and_left_out) {
    auto s = test::make_case("report_stale");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    const std::string p2 = s.c.points[1].id;
    const fs::path summary = result_dir(s.o.results_root, "dem", p2) / "summary.json";
    auto j = nlohmann::json::parse(test::slurp(summary));
    j["provenance"]["inputs_hash"] = "0000000000000000";
    write_file_atomic(summary, j.dump(2));
    BOOST_TEST(postproc::compare(s.c, s.o) == 1);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("<td class=\"stale\">stale</td>") != std::string::npos);
    BOOST_TEST(html.find(summary.string()) != std::string::npos);  // the reason names the file
    const auto row = test::read_metrics_row(s.o.results_root / "report" / "metrics.csv", "scalar", p2,
                                            "shear_stress_bottom", "continuum", "dem");
    BOOST_TEST(row.empty());  // not compared
    // A changed case makes every result stale: nothing to compare is an error naming the cause.
    auto changed = test::make_case("report_stale_all");
    test::write_solver(changed, "continuum");
    std::ofstream(changed.dir / "case.toml", std::ios::app) << "\n[body_forces]\ngravity = 1.5\n";
    const Case c2 = load_case(changed.dir, test::synthetic_schema());
    BOOST_CHECK_EXCEPTION(postproc::compare(c2, changed.o), Error, [](const Error& e) {
        return std::string(e.what()).find("no usable results") != std::string::npos;
    });
}

BOOST_AUTO_TEST_CASE(malformed_results_give_clear_reasons) {
    auto s = test::make_case("report_corrupt");
    for (const char* solver : {"continuum", "dem", "automaton"}) test::write_solver(s, solver);
    const auto& pts = s.c.points;
    // 1: a profile with a non-number; 2: a summary filed under the wrong solver; 3: stations out of order.
    const fs::path bad_csv = result_dir(s.o.results_root, "dem", pts[0].id) / "profile.csv";
    write_file_atomic(bad_csv, "y_over_H,u_over_U,solid_fraction,temperature_over_U2\n0,abc,0.5,0.01\n1,0,0.5,0.01\n");
    const fs::path moved = result_dir(s.o.results_root, "automaton", pts[1].id) / "summary.json";
    auto j = nlohmann::json::parse(test::slurp(moved));
    j["solver"] = "yade";
    write_file_atomic(moved, j.dump(2));
    const fs::path unordered = result_dir(s.o.results_root, "continuum", pts[2].id) / "profile.csv";
    std::string text = test::slurp(unordered);
    text.replace(text.find("\n0.5,"), 5, "\n0.001,");  // y/H = 0.5 -> 0.001 breaks the order
    write_file_atomic(unordered, text);

    BOOST_TEST(postproc::compare(s.c, s.o) == 1);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    expect_well_formed(s.o.results_root / "report" / "index.html");
    BOOST_TEST(test::count(html, "<td class=\"corrupt\">corrupt</td>") == 6u);  // status table and the list of reasons
    BOOST_TEST(html.find("&#39;abc&#39; is not a number") != std::string::npos);
    BOOST_TEST(html.find("says solver &quot;yade&quot; but lies in the &quot;automaton&quot; results folder") !=
               std::string::npos);
    BOOST_TEST(html.find("y_over_H = 0.001 does not increase") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(no_results_is_an_error) {
    auto s = test::make_case("report_none");
    BOOST_CHECK_EXCEPTION(postproc::compare(s.c, s.o), Error, [](const Error& e) {
        return std::string(e.what()).find("no usable results") != std::string::npos;
    });
    BOOST_TEST(!fs::exists(s.o.results_root / "report"));
}

BOOST_AUTO_TEST_CASE(a_second_compare_replaces_the_report_whole) {
    auto s = test::make_case("report_twice");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    write_file_atomic(s.o.results_root / "report" / "plots" / "leftover.svg", "<svg/>");
    fs::remove_all(s.o.results_root / "dem");
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    BOOST_TEST(!fs::exists(s.o.results_root / "report" / "plots" / "leftover.svg"));
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("solvers compared: continuum; missing (no usable results): automaton, dem, yade.") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(any_other_results_folder_is_a_solver) {
    auto s = test::make_case("report_other_solver");
    test::write_solver(s, "continuum");
    test::write_solver(s, "mysolver");  // written like the automaton (occupancy, nu_max = 1)
    fs::create_directories(s.o.results_root / "initial" / "U1.0");  // shared initial states: not a solver
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("solvers compared: continuum, mysolver; missing") != std::string::npos);
    BOOST_TEST(html.find(">initial<") == std::string::npos);
    const auto row = test::read_metrics_row(s.o.results_root / "report" / "metrics.csv", "profile", s.c.points[0].id,
                                            "nu_over_numax", "continuum", "mysolver");
    BOOST_TEST_REQUIRE(!row.empty());
    BOOST_TEST(std::stod(row.at("rms_difference")) < 1e-12);  // each solver's own nu_max
}

BOOST_AUTO_TEST_SUITE_END()

// The cross-section maps (section.csv of a particle run): two heat maps per run that has one, in
// the point's part, marked when the run is a transient; none for runs without the file.
BOOST_AUTO_TEST_CASE(cross_section_maps_where_a_particle_run_has_one) {
    auto s = test::make_case("report_cross_section");
    {  // a trough 10 mm wide (the synthetic case is periodic across z), for the ParaView image
        std::string text = test::slurp(s.dir / "case.toml");
        text.replace(text.find("width = 0.0"), 11, "width = 0.01");
        std::ofstream(s.dir / "case.toml") << text;
        s.c = load_case(s.dir, test::synthetic_schema());
    }
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    // 3 x 4 cells, grains packed toward the floor and the outer wall (z/W = -1/2)
    Profile t;
    std::vector<double> y, z, nu, u;
    for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 4; ++m) {
            y.push_back((k + 0.5) / 3.0), z.push_back((m + 0.5) / 4.0 - 0.5);
            nu.push_back(0.6 - 0.1 * k - 0.05 * m), u.push_back(1.0 - 0.3 * k);
        }
    t.add("y_over_H", y).add("z_over_W", z).add("solid_fraction", nu).add("u_over_U", u);
    const OperatingPoint& p0 = s.c.points[0];
    const OperatingPoint& p1 = s.c.points[1];
    for (const OperatingPoint* p : {&p0, &p1})
        write_file_atomic(result_dir(s.o.results_root, "dem", p->id) / "section.csv", profile_csv(t, {"synthetic"}));
    test::patch_run(s, "dem", p1.id, {{"status", "transient"}, {"status_reason", "no steady state (test)"}});
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path rep = s.o.results_root / "report";
    const std::string html = test::slurp(rep / "index.html");
    expect_well_formed(rep / "index.html");
    const auto maps = files_with(rep / "plots", ".svg");
    const auto n = std::count_if(maps.begin(), maps.end(),
                                 [](const fs::path& f) { return f.stem().string().starts_with("cross_section_dem_"); });
    BOOST_TEST(n == 4);  // nu and u/U at the two points with a section.csv, none at the third
    for (const auto& f : maps)
        if (f.stem().string().starts_with("cross_section_dem_")) {
            expect_well_formed(f);
            BOOST_TEST(fs::exists(f.parent_path() / (f.stem().string().substr(0, f.stem().string().rfind('_')) + ".csv")));
        }
    BOOST_TEST(html.find("dem " + p0.id + ": solid fraction ν") != std::string::npos);
    BOOST_TEST(html.find("dem " + p0.id + ": streamwise velocity u/U") != std::string::npos);
    BOOST_TEST(html.find("z/W across the width") != std::string::npos);
    // the transient point's maps say so; the steady one's do not
    BOOST_TEST(html.find("dem " + p1.id + ": solid fraction ν (transient)") != std::string::npos);
    BOOST_TEST(test::count(html, "TRANSIENT — not a result") == 2u);
    // ParaView: the point's multiblock file has the cross-section as an image block
    const std::string vtm = test::slurp(rep / "paraview" / "u1-0.vtm");
    BOOST_TEST(vtm.find("name=\"dem cross-section\"") != std::string::npos, vtm);
    const auto vtis = files_with(rep / "paraview" / "u1-0", ".vti");
    BOOST_TEST_REQUIRE(vtis.size() == 1u);
    const std::string vti = test::slurp(vtis.front());
    BOOST_TEST(vti.find("Name=\"solid_fraction\"") != std::string::npos);
    BOOST_TEST(vti.find("WholeExtent=\"0 1 0 3 0 4\"") != std::string::npos, vti.substr(0, 400));
    expect_well_formed(vtis.front());
}
