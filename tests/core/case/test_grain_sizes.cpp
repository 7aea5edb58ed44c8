// A size spread (grain_sizes.h): the drawn diameters, their insertion without overlaps, and the
// insertion's limits.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/case/grain_sizes.h"
#include "granlub/particles/particles.h"

using namespace granlub;
namespace tt = boost::test_tools;

namespace {
const double kD = 0.787e-3;
ParticleBox sawyer_box(double gap = 4e-3) { return {30e-3, gap, 19e-3, false}; }
}  // namespace

BOOST_AUTO_TEST_CASE(diameters_have_the_declared_mean_spread_and_bounds) {
    const GrainSizes g{kD, 0.1};
    BOOST_TEST(g.min() == kD * (1 - std::sqrt(0.03)), tt::tolerance(1e-12));
    BOOST_TEST(g.max() == kD * (1 + std::sqrt(0.03)), tt::tolerance(1e-12));
    const auto d = draw_diameters(g, 20000, 3);
    double m = 0, v = 0;
    for (double x : d) m += x;
    m /= static_cast<double>(d.size());
    for (double x : d) v += (x - m) * (x - m);
    const double sd = std::sqrt(v / static_cast<double>(d.size()));
    BOOST_TEST(m / kD == 1.0, tt::tolerance(0.003));   // 4 standard errors of the mean
    BOOST_TEST(sd / kD == 0.1, tt::tolerance(0.03));
    BOOST_TEST(*std::min_element(d.begin(), d.end()) >= g.min());
    BOOST_TEST(*std::max_element(d.begin(), d.end()) <= g.max());
    BOOST_TEST((draw_diameters(g, 100, 3) == draw_diameters(g, 100, 3)));   // same seed, same sizes
    BOOST_TEST((draw_diameters(g, 100, 3) != draw_diameters(g, 100, 4)));
    const auto equal = draw_diameters(GrainSizes{kD, 0.0}, 10, 3);
    BOOST_TEST(std::all_of(equal.begin(), equal.end(), [](double x) { return x == kD; }));
    // the mean volume counts the grains of a fill: <d^3> = d^3 (1 + 3 s^2) for the uniform law
    BOOST_TEST(g.mean_volume() == std::numbers::pi / 6 * std::pow(kD, 3) * 1.03, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(a_spread_is_inserted_without_overlaps_at_its_fill) {
    const ParticleBox box = sawyer_box(6e-3);
    const GrainSizes g{kD, 0.1};
    const std::size_t n = grains_for_fill(box, g, 0.35);
    InsertionOptions opt;
    opt.seed = 11;
    opt.wall_speed = 2.0;
    opt.size_spread = 0.1;
    const ParticleSet p = insert_grains(box, kD, n, opt);
    BOOST_TEST(p.size() == n);
    BOOST_TEST(min_gap(p, box) > 0.0);  // no overlap with a grain or a wall
    BOOST_TEST(solid_fraction(p, box) == 0.35, tt::tolerance(0.02));
    const auto [lo, hi] = std::minmax_element(p.radius.begin(), p.radius.end());
    BOOST_TEST(2 * *lo >= g.min());
    BOOST_TEST(2 * *hi <= g.max());
    BOOST_TEST(2 * *hi - 2 * *lo > 0.25 * kD);  // the sizes really differ
    // equal grains are placed as before the spread existed: the same sites, jitter and velocities
    opt.size_spread = 0.0;
    const ParticleSet a = insert_grains(box, kD, n, opt), b = insert_grains(box, kD, n, opt);
    BOOST_TEST((a.x == b.x && a.vx == b.vx));
    BOOST_TEST(std::all_of(a.radius.begin(), a.radius.end(), [](double r) { return r == 0.5 * kD; }));
}

BOOST_AUTO_TEST_CASE(a_spread_the_lattice_cannot_hold_names_the_largest_fill) {
    const ParticleBox box = sawyer_box();
    InsertionOptions opt;
    opt.size_spread = 0.1;
    const std::size_t n = grains_for_fill(box, GrainSizes{kD, 0.1}, 0.595);
    try {
        insert_grains(box, kD, n, opt);
        BOOST_FAIL("expected a CaseError");
    } catch (const CaseError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.find("spaced for the largest grain") != std::string::npos, m);
        BOOST_TEST(m.find("can be inserted") != std::string::npos, m);
    }
}
