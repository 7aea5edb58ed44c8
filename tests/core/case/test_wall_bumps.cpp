// Rough walls (wall_bumps.h): the layout and the roughness it builds, and the cases it refuses.
#include <cmath>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/case/case.h"
#include "granlub/particles/particles.h"
#include "granlub/case/wall_bumps.h"

using namespace granlub;
using granlub::test::error_of;
using granlub::test::kValidCase;
using granlub::test::with;
namespace tt = boost::test_tools;

namespace {
// kValidCase (d = 1 mm, L = 20 mm, H = 5 mm, periodic width) with rough walls
std::string rough(const std::string& walls, const std::string& text = kValidCase) {
    return with("roughness = 0.5", walls, text);
}
}  // namespace

BOOST_AUTO_TEST_CASE(touching_bumps_of_the_grains_size_give_one_half) {
    const Case c = parse_case(rough("roughness = 0.5\nsurface = \"bumps\""), "r.toml", Schema::common());
    const OperatingPoint& p = c.points.front();
    const ParticleBox box = particle_box(c);
    const auto b = wall_bumps(c, p, p.bottom, "bottom", box);
    BOOST_TEST_REQUIRE(b.has_value());
    BOOST_TEST(b->diameter == 1e-3);
    BOOST_TEST(b->count_x == 20u);                 // 20 mm / 1 mm
    BOOST_TEST(b->roughness == 0.5, tt::tolerance(1e-12));  // sin 30 degrees
    BOOST_TEST(b->rows == 10u);                    // 10 mm / 0.866 mm = 11.5: the even count below, stretched
    BOOST_TEST(b->size() == b->count_x * b->rows);
    // no two bumps overlap (the closest touch), the layer fills the periodic width
    double closest = 1e9;
    for (std::size_t i = 0; i < b->size(); ++i)
        for (std::size_t j = i + 1; j < b->size(); ++j) {
            double dx = b->x[j] - b->x[i], dz = b->across[j] - b->across[i];
            dx -= box.length * std::round(dx / box.length);
            dz -= box.width * std::round(dz / box.width);
            closest = std::min(closest, std::hypot(dx, dz));
        }
    BOOST_TEST(closest >= b->diameter * (1 - 1e-9));
    BOOST_TEST(closest <= b->diameter * 1.2);
    // a plane wall has none; R = 0 is the plane too
    const Case plane = parse_case(kValidCase, "s.toml", Schema::common());
    BOOST_TEST(!wall_bumps(plane, plane.points.front(), plane.points.front().top, "top", box));
    OperatingPoint smooth = p;
    smooth.bottom.roughness = 0;
    BOOST_TEST(!wall_bumps(c, smooth, smooth.bottom, "bottom", box));
}

BOOST_AUTO_TEST_CASE(rougher_walls_space_the_bumps_and_smoother_shrink_them) {
    // R = 0.75 with bumps of the grains' size: 1.5 mm apart, 13.33 -> 13 in a row, R built 0.769
    // is too far; R = 0.8 gives 1.6 mm, 12.5 -> ... so take R = 0.625: 1.25 mm, 16 bumps exactly
    Case c = parse_case(rough("roughness = 0.625\nsurface = \"bumps\""), "r.toml", Schema::common());
    auto b = wall_bumps(c, c.points.front(), c.points.front().bottom, "bottom", particle_box(c));
    BOOST_TEST(b->count_x == 16u);
    BOOST_TEST(b->diameter == 1e-3);
    BOOST_TEST(b->roughness == 0.625, tt::tolerance(1e-12));
    // R = 0.2 below one half: touching bumps of R d / (1 - R) = 0.25 mm, 80 in a row
    c = parse_case(rough("roughness = 0.2\nsurface = \"bumps\""), "r.toml", Schema::common());
    b = wall_bumps(c, c.points.front(), c.points.front().bottom, "bottom", particle_box(c));
    BOOST_TEST(b->diameter == 0.25e-3, tt::tolerance(1e-12));
    BOOST_TEST(b->count_x == 80u);
    BOOST_TEST(b->spacing == b->diameter, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(walls_that_cannot_be_built_are_refused_with_the_key_and_what_is_allowed) {
    // bumps too large for the roughness asked
    std::string m = error_of(rough("roughness = 0.3\nsurface = \"bumps\"\nbump_diameter = 1e-3"));
    BOOST_TEST(m.find("[walls] roughness = 0.3") != std::string::npos, m);
    BOOST_TEST(m.find("touch at R = 0.5") != std::string::npos, m);
    BOOST_TEST(m.find("at most 0.000428571 m") != std::string::npos, m);
    // a periodic length without a whole number of bumps near R: 20 mm / 1.2 mm = 16.7
    m = error_of(rough("roughness = 0.6\nsurface = \"bumps\""));
    BOOST_TEST(m.find("holds 16 bumps (R = 0.625) or 17 bumps (R = 0.5882)") != std::string::npos, m);
    BOOST_TEST(m.find("[cell] length = 0.02") != std::string::npos, m);
    // bumps that leave no room for the grains: 4 mm bumps on both walls of a 5 mm gap
    m = error_of(rough("roughness = 1\nsurface = \"bumps\"\nbump_diameter = 4e-3"));
    BOOST_TEST(m.find("bump_diameter = 0.004") != std::string::npos, m);
    BOOST_TEST(m.find("at least two grain diameters") != std::string::npos, m);
    // a sweep of R reports the point that fails
    m = error_of(rough("roughness = 0.5\nsurface = \"bumps\"",
                       with("normal_stress = 1000.0", "normal_stress = 1000.0\nroughness = [0.5, 0.6]")));
    BOOST_TEST(m.find("[operating] roughness = 0.6") != std::string::npos, m);
    // the ring has no rough walls (yet)
    m = error_of(rough("roughness = 0.5\nsurface = \"bumps\"",
                       with("width = 0.0", "width = 0.01\nannulus_radius = 0.02\ngeometry = \"annulus\"")));
    BOOST_TEST(m.find("in a slice only") != std::string::npos, m);
    // a layer of more bumps than any cell holds (an absurd length: found by the case fuzzer as a cast of 2e67 to
    // an integer) is refused before it is counted, naming the length
    m = error_of(rough("roughness = 0.5\nsurface = \"bumps\"", with("length = 20.0e-3", "length = 1.5e64")));
    BOOST_TEST(m.find("[walls] roughness = 0.5") != std::string::npos, m);
    BOOST_TEST(m.find("[cell] length 1.5e+64 m") != std::string::npos, m);
    BOOST_TEST(m.find("more than 1e+07 in one layer") != std::string::npos, m);
    // a spread beyond what the insertion handles
    m = error_of(with("restitution = 0.9", "restitution = 0.9\nsize_spread = 0.3"));
    BOOST_TEST(m.find("[grains] size_spread = 0.3") != std::string::npos, m);
}

BOOST_AUTO_TEST_CASE(side_walls_as_the_bottom_carry_its_bumps_up_to_the_top) {
    // a 10 mm trough with the floor's touching 1 mm bumps on both side walls
    const std::string text = with("width = 0.0", "width = 0.01", kValidCase);
    const Case c =
        parse_case(rough("roughness = 0.5\nsurface = \"bumps\"\nsides = \"as_bottom\"", text), "r.toml", Schema::common());
    const OperatingPoint& p = c.points.front();
    const ParticleBox box = particle_box(c);
    const auto floor = wall_bumps(c, p, p.bottom, "bottom", box);
    const auto side = side_bumps(c, p, box, 6e-3);
    BOOST_TEST_REQUIRE(side.has_value());
    BOOST_TEST(side->diameter == floor->diameter);
    BOOST_TEST(side->count_x == floor->count_x);
    BOOST_TEST(side->roughness == floor->roughness);
    BOOST_TEST(side->rows == 6u);  // rows 0.866 mm apart from one row above the floor to 6 mm: 6.93 -> 6
    BOOST_TEST(side->size() == side->rows * side->count_x);
    double lowest = 1e9, highest = 0, closest = 1e9;
    for (std::size_t i = 0; i < side->size(); ++i) {
        lowest = std::min(lowest, side->across[i]);
        highest = std::max(highest, side->across[i]);
        for (std::size_t j = i + 1; j < side->size(); ++j) {
            double dx = side->x[j] - side->x[i];
            dx -= box.length * std::round(dx / box.length);
            closest = std::min(closest, std::hypot(dx, side->across[j] - side->across[i]));
        }
    }
    BOOST_TEST(lowest == side->row_spacing, tt::tolerance(1e-12));
    BOOST_TEST(highest <= 6e-3);
    BOOST_TEST(closest >= side->diameter * (1 - 1e-9));  // touching, never overlapping
    // plane sides (the default), or a plane floor: none
    const Case plain = parse_case(rough("roughness = 0.5\nsurface = \"bumps\"", text), "r.toml", Schema::common());
    BOOST_TEST(!side_bumps(plain, plain.points.front(), box, 6e-3));
    const Case flat = parse_case(rough("roughness = 0.5\nsides = \"as_bottom\"", text), "r.toml", Schema::common());
    BOOST_TEST(!side_bumps(flat, flat.points.front(), box, 6e-3));
    // a periodic width has no side walls to roughen
    const std::string m = error_of(rough("roughness = 0.5\nsurface = \"bumps\"\nsides = \"as_bottom\""));
    BOOST_TEST(m.find("[walls] sides") != std::string::npos, m);
    BOOST_TEST(m.find("needs side walls") != std::string::npos, m);
}

// A layer moved along x stays in the period: the shift wraps as the layout does, a whole number of
// periods changes nothing, and the layout's other fields stay (what a run from a state starts).
BOOST_AUTO_TEST_CASE(moved_bumps_wrap_into_the_period) {
    BumpLayer b;
    b.diameter = 1.0, b.spacing = 2.0, b.count_x = 4, b.rows = 1;
    b.x = {0.0, 2.0, 4.0, 6.0}, b.across = {0.1, 0.2, 0.3, 0.4};
    const double L = 8.0;
    const BumpLayer m = moved_bumps(b, 3.0 * L + 2.5, L);
    const std::vector<double> want{2.5, 4.5, 6.5, 0.5};
    for (std::size_t k = 0; k < 4; ++k) BOOST_TEST(m.x[k] == want[k], tt::tolerance(1e-12));
    BOOST_TEST(m.across == b.across, tt::per_element());
    BOOST_TEST(m.diameter == b.diameter);
    BOOST_TEST(moved_bumps(b, 5.0 * L, L).x == b.x, tt::per_element());
    for (double x : moved_bumps(b, -0.5, L).x) BOOST_TEST((x >= 0.0 && x < L), x);
    for (double x : moved_bumps(b, L - 1e-17, L).x) BOOST_TEST((x >= 0.0 && x < L), x);
}
