// A report as the main job writes it (four solvers at three points, the dem transient at one and
// dt-unconverged at another; dem and yade with a cross-section at every point) says no caption
// sentence more than twice and cuts no figure title: the twelve cross-section maps' shared
// sentence is said once, above them.
#include <boost/test/unit_test.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/postproc/command.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "report_checks.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(captions)

BOOST_AUTO_TEST_CASE(no_caption_sentence_more_than_twice_and_no_title_cut) {
    const auto s = test::main_job_results("captions");
    Profile t;  // 2 x 2 cells
    t.add("y_over_H", {0.25, 0.25, 0.75, 0.75}).add("z_over_W", {-0.25, 0.25, -0.25, 0.25});
    t.add("solid_fraction", {0.6, 0.55, 0.5, 0.45}).add("u_over_U", {0.9, 0.9, 0.2, 0.2});
    for (const char* solver : {"dem", "yade"})
        for (const OperatingPoint& p : s.c.points)
            write_file_atomic(result_dir(s.o.results_root, solver, p.id) / kSectionFile, profile_csv(t, {"synthetic"}));
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path rep = s.o.results_root / "report";
    const std::string html = test::slurp(rep / "index.html");
    BOOST_TEST_REQUIRE(test::count(html, "<figure id=\"cross_section_") == 12u);  // 2 solvers x 3 points x (ν, u/U)

    const auto repeated = test::repeated_caption_sentences(html);
    BOOST_TEST(repeated.empty(), fmt::format("{}", fmt::join(repeated, "\n")));
    BOOST_TEST(test::count(html, "cross-section, the flow out of the page") == 1u);  // said once, above the maps
    BOOST_TEST(test::count(html, "Figures below: The trough") == 1u);
    const auto cut = test::cut_titles(rep / "plots");
    BOOST_TEST(cut.empty(), fmt::format("{}", fmt::join(cut, "\n")));
}

BOOST_AUTO_TEST_SUITE_END()
