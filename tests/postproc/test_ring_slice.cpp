// The report's "whole ring against its slice" part ([report] slice_case): granlub dem's results
// of a ring case beside a slice case's, quantity by quantity with z, the radial packing from the
// width profiles, figures that parse; a slice case that is missing or has no results is a note,
// and the rest of the report stands.
#include <fstream>
#include <regex>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/postproc/command.h"
#include "granlub/results/run_id.h"
#include "synthetic.h"
#include "xml_check.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

// The synthetic case as a trough of width 10 mm at R = 50 mm: the slice, or with `ring` the whole ring.
test::SyntheticCase trough_case(const std::string& name, bool ring, const std::string& report = "") {
    test::SyntheticCase s = test::make_case(name);
    const std::string text =
        std::regex_replace(test::slurp(s.dir / "case.toml"), std::regex("width = 0.0\n"),
                           std::string("width = 10.0e-3\nannulus_radius = 0.05\n") + (ring ? "geometry = \"annulus\"\n" : "")) +
        report;
    std::ofstream(s.dir / "case.toml") << text;
    s.c = load_case(s.dir, test::synthetic_schema());
    return s;
}

// width_profile.csv of every dem point: solid fraction a + b z/W (+- 0.002), u/U 0.8.
void write_width_profiles(const test::SyntheticCase& s, double a, double b) {
    for (const OperatingPoint& p : s.c.points) {
        std::ofstream f(result_dir(s.o.results_root, "dem", p.id) / "width_profile.csv");
        f << "# synthetic\n# " << run_id_comment()  // the run of the dem results beside it
          << "\nz_over_W,solid_fraction,solid_fraction_stderr,u_over_U,u_over_U_stderr\n";
        for (double z : {-0.375, -0.125, 0.125, 0.375}) f << z << ',' << a + b * z << ",0.002,0.8,0.01\n";
    }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(ring_slice)

BOOST_AUTO_TEST_CASE(ring_beside_its_slice) {
    const auto slice = trough_case("ring_slice_slice", false);
    test::write_solver(slice, "dem");
    write_width_profiles(slice, 0.5, -0.1);  // outer/inner half 1.05/0.95 = 1.1053 +- 0.0044
    const auto ring = trough_case("ring_slice_ring", true, "\n[report]\nslice_case = \"../ring_slice_slice\"\n");
    test::write_solver(ring, "dem");
    write_width_profiles(ring, 0.5, -0.4);  // outer/inner half 1.2/0.8 = 1.5 +- 0.0064

    BOOST_TEST(postproc::compare(ring.c, ring.o) == 0);
    const fs::path rep = ring.o.results_root / "report";
    const std::string html = test::slurp(rep / "index.html");
    const auto start = html.find("The whole ring against its slice</h2>");
    BOOST_TEST_REQUIRE(start != std::string::npos);
    const std::string sec = html.substr(start, html.find("<h2", start) - start);
    // every quantity the synthetic dem writes (7) and the radial packing, at every point; the same
    // results on both sides: no difference
    for (const OperatingPoint& p : ring.c.points) BOOST_TEST(test::count(sec, "<tr><td>" + p.id + "</td>") == 8u, p.id);
    BOOST_TEST(test::count(sec, "<td>0</td><td>0</td></tr>") == 21u);
    // a quantity neither run has (the synthetic dem writes no side walls) is left out
    BOOST_TEST(sec.find("<td>τ outer side wall (Pa)</td>") == std::string::npos);
    // the radial packing: difference 0.3947 over a combined standard error 0.0078: z = 51, bold
    BOOST_TEST(sec.find("<td>1.5 ± 0.0064</td><td>1.105 ± 0.0044</td><td>0.395</td><td class=\"significant\">51</td>") !=
                   std::string::npos,
               sec);
    // figures across the width and the gap, per point, well-formed
    for (const OperatingPoint& p : ring.c.points) {
        const std::string slug = std::regex_replace(std::regex_replace(p.id, std::regex("\\."), "-"), std::regex("U"), "u");
        for (const char* f : {"width_nu", "width_u", "gap_nu", "gap_u"}) {
            const fs::path svg = rep / "plots" / ("ring_slice_" + slug + "_" + f + ".svg");
            BOOST_TEST_REQUIRE(fs::exists(svg), svg);
            BOOST_TEST(test::xml_error(test::slurp(svg)).empty(), svg);
        }
    }
    // the ring's results do not depend on [report]: still current
    BOOST_TEST(html.find("<td class=\"stale\">") == std::string::npos);
}

BOOST_AUTO_TEST_CASE(missing_slice_case_is_a_note) {
    const auto ring = trough_case("ring_slice_alone", true, "\n[report]\nslice_case = \"../no_such_case\"\n");
    test::write_solver(ring, "dem");
    BOOST_TEST(postproc::compare(ring.c, ring.o) == 0);
    const std::string html = test::slurp(ring.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("[report] slice_case = &quot;../no_such_case&quot;: ") != std::string::npos);
    BOOST_TEST(html.find("no such case directory or file") != std::string::npos);
    BOOST_TEST(html.find("Key numbers") != std::string::npos);  // the rest of the report stands
}

BOOST_AUTO_TEST_CASE(slice_without_results_is_a_note) {
    trough_case("ring_slice_empty", false);
    const auto ring = trough_case("ring_slice_ring2", true, "\n[report]\nslice_case = \"../ring_slice_empty\"\n");
    test::write_solver(ring, "dem");
    BOOST_TEST(postproc::compare(ring.c, ring.o) == 0);
    const std::string html = test::slurp(ring.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("No granlub dem results in") != std::string::npos);
}

BOOST_AUTO_TEST_SUITE_END()
