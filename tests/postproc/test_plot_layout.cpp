// Plots that read: the legend never covers a marker (a free corner, else below the frame) and
// category labels that would touch are staggered onto two rows.
#include <regex>

#include <boost/test/unit_test.hpp>

#include "formats/svg_plot.h"

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

BOOST_AUTO_TEST_SUITE_END()
