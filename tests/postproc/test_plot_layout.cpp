// Plots that read: the legend never covers a marker (a free corner, else below the frame),
// category labels that would touch are staggered onto two rows, and a title too wide for the
// figure wraps instead of running past its edge.
#include <regex>

#include <boost/test/unit_test.hpp>

#include "figures/cross_section_map.h"
#include "formats/svg_plot.h"
#include "formats/svg_title.h"
#include "report_checks.h"

using namespace granlub::postproc;

namespace {

Series points(std::string label, std::vector<double> x, std::vector<double> y) {
    Series s;
    s.label = std::move(label);
    s.mark = Mark::Points;
    s.x = std::move(x);
    s.y = std::move(y);
    return s;
}

double svg_height(const std::string& svg) {
    std::smatch m;
    BOOST_TEST_REQUIRE(std::regex_search(svg, m, std::regex(R"re(<svg [^>]*height="([0-9.]+)")re")));
    return std::stod(m[1]);
}

// The y of the tick label `text` (text-anchor middle: the x-axis labels).
double label_y(const std::string& svg, const std::string& text) {
    std::smatch m;
    BOOST_TEST_REQUIRE(std::regex_search(svg, m, std::regex(R"re(y="([0-9.]+)" text-anchor="middle">)re" + text + "<")));
    return std::stod(m[1]);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(plot_layout)

BOOST_AUTO_TEST_CASE(the_legend_takes_a_free_corner) {
    Figure f;
    f.name = "free";
    // Data along the bottom, and one point at the top in the middle: the top right corner is free.
    f.series.push_back(points("a solver", {0, 1, 2, 3, 4}, {0, 0.1, 0, 0.1, 0}));
    f.series.push_back(points("another", {2}, {1}));
    BOOST_TEST(layout(f).legend_corner == 0);
    BOOST_TEST(svg_height(render_svg(f)) == 380.0);
}

BOOST_AUTO_TEST_CASE(the_legend_goes_below_when_every_corner_holds_data) {
    Figure f;
    f.name = "crowded";
    // A marker in each of the four corners of the frame.
    f.series.push_back(points("corners", {0, 0, 10, 10}, {0, 10, 0, 10}));
    f.series.push_back(points("middle", {5}, {5}));
    BOOST_TEST(layout(f).legend_corner == kLegendBelow);
    const std::string svg = render_svg(f);
    BOOST_TEST(svg_height(svg) > 380.0);  // grown for the legend rows
    // The legend's text sits below the frame (y > 380 - 52), not over the data.
    std::smatch m;
    BOOST_TEST_REQUIRE(std::regex_search(svg, m, std::regex(R"re(<text x="[0-9.]+" y="([0-9.]+)">corners</text>)re")));
    BOOST_TEST(std::stod(m[1]) > 380.0);
}

BOOST_AUTO_TEST_CASE(touching_category_labels_are_staggered) {
    Figure f;
    f.name = "categories";
    for (int i = 0; i < 6; ++i) f.x.categories.emplace_back(i, "U2.0_R0.65_long" + std::to_string(i));
    f.series.push_back(points("", {0, 5}, {0, 1}));
    const std::string svg = render_svg(f);
    BOOST_TEST(label_y(svg, "U2.0_R0.65_long1") - label_y(svg, "U2.0_R0.65_long0") >= 14.0);  // one row lower
    // Three short labels fit side by side: one row.
    Figure g;
    g.name = "few";
    for (int i = 0; i < 3; ++i) g.x.categories.emplace_back(i, "U" + std::to_string(i));
    g.series.push_back(points("", {0, 2}, {0, 1}));
    const std::string few = render_svg(g);
    BOOST_TEST(label_y(few, "U0") == label_y(few, "U1"));
}

// The width estimate is the font's: DejaVu Sans Bold's advances (H 1714, i 702 of 2048 units per
// em), nothing for a combining mark, an em for a character outside ASCII.
BOOST_AUTO_TEST_CASE(title_widths_are_the_fonts_advances) {
    BOOST_TEST(bold_text_width("Hi", 14) == (1714 + 702) / 2048.0 * 14, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(bold_text_width("ν̄", 14) == 14.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(bold_text_width("", 14) == 0.0);
    BOOST_TEST(bold_text_width("WWW", 14) > bold_text_width("iii", 14) * 2);
}

// A title as long as the rough regimes case's (cut at 1400 px before) and one far longer: each
// wraps into lines that fit the figure, and the figure grows by a line for each extra one; a title
// that fits stays one line and the figure its size.
BOOST_AUTO_TEST_CASE(a_title_too_wide_for_the_figure_wraps) {
    Figure f;
    f.series.push_back(points("a", {1, 2, 3}, {1, 2, 3}));
    f.title = "Short";
    const double one_line = svg_height(render_svg(f));
    BOOST_TEST(granlub::test::cut_title_lines(render_svg(f)).empty());
    for (const std::string title :
         {"Shear stress on the stationary wall against U, per load: continuum",
          "Lift-off: mean solid fraction against speed, per load: continuum and every other solver the case could "
          "name, with a title far longer than any the report writes today, ν̄ and σ included"}) {
        f.title = title;
        const std::string svg = render_svg(f);
        BOOST_TEST(granlub::test::cut_title_lines(svg).empty(), title);
        const auto lines = title_lines(title, title_room(301, 540));
        BOOST_TEST(lines.size() >= 2u, title);
        BOOST_TEST(svg_height(svg) == one_line + kTitleLineHeight * static_cast<double>(lines.size() - 1));
        std::string joined;
        for (const auto& l : lines) joined += (joined.empty() ? "" : " ") + l;
        BOOST_TEST(joined == title);  // wrapped between words, nothing lost
    }
    // one word wider than the figure: squeezed to the room, not cut
    f.title = std::string(80, 'W');
    const std::string svg = render_svg(f);
    BOOST_TEST(svg.find("lengthAdjust=\"spacingAndGlyphs\"") != std::string::npos);
    BOOST_TEST(granlub::test::cut_title_lines(svg).empty());
    // the cross-section maps wrap theirs the same way
    const CrossSectionMap m{2, 2, {0.25, 0.25, 0.75, 0.75}, {-0.25, 0.25, -0.25, 0.25}, {0.5, 0.6, 0.4, 0.3}, {1, 1, 0, 0}};
    const std::string map = render_cross_section_svg(
        m, m.nu, "yade U2.8_P5550: solid fraction ν (dt-unconverged), a title as long as a sentence can make it", "ν", "");
    BOOST_TEST(granlub::test::cut_title_lines(map).empty());
    BOOST_TEST(svg_height(map) > 380);
}

BOOST_AUTO_TEST_SUITE_END()
