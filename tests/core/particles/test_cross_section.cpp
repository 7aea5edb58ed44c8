// The y x z cross-section (granlub/particles/cross_section.h): grains packed into one corner show up there,
// every grain's volume is kept, and the velocity is the volume-weighted mean.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>

#include "granlub/particles/cross_section.h"

using namespace granlub;

BOOST_AUTO_TEST_CASE(grains_in_a_corner_fill_that_corner_and_keep_their_volume) {
    // a 4 x 4 x 4 mm box (x, y, z in [-2, 2] mm across z), 1 mm cells; grains of d = 1 mm on a simple
    // cubic lattice in the lower (small y) corner at the -z wall, two layers of 2 x 2 along x
    const double d = 1e-3, r = 0.5 * d;
    CrossSection xs = CrossSection::for_grains(d, 4e-3, 4e-3, 4e-3);
    ParticleSet p;
    for (int ix = 0; ix < 4; ++ix)
        for (int iy = 0; iy < 2; ++iy)
            for (int iz = 0; iz < 2; ++iz)
                p.push_back((ix + 0.5) * d, (iy + 0.5) * d, -2e-3 + (iz + 0.5) * d, 2.0 * (iy + 1), 0, 0, r);
    xs.add_snapshot(p, 0.0);
    xs.add_snapshot(p, 1.0);
    const Profile t = xs.table(2.0, 0);
    BOOST_TEST_REQUIRE(t.rows() == 16u);  // 4 x 4 cells
    const auto& y = t.column("y_over_H");
    const auto& z = t.column("z_over_W");
    const auto& nu = t.column("solid_fraction");
    const auto& u = t.column("u_over_U");
    const double cell = 1e-3 * 1e-3 * 4e-3, V = std::numbers::pi / 6.0 * d * d * d;
    double total = 0;
    for (std::size_t c = 0; c < t.rows(); ++c) {
        total += nu[c] * cell;
        const bool corner = y[c] < 0.5 && z[c] < 0.0;
        if (corner) {
            // each cell holds one grain per x cell exactly: 4 grains of V in a 4 mm deep cell
            BOOST_TEST(nu[c] == 4 * V / cell, boost::test_tools::tolerance(1e-12));
            BOOST_TEST(u[c] == (y[c] < 0.25 ? 1.0 : 2.0), boost::test_tools::tolerance(1e-12));
        } else {
            BOOST_TEST(nu[c] == 0.0);
            BOOST_TEST(u[c] == 0.0);
        }
    }
    BOOST_TEST(total == 16 * V, boost::test_tools::tolerance(1e-12));  // every grain's volume kept
}

BOOST_AUTO_TEST_CASE(a_grain_across_cell_boundaries_is_split_and_kept) {
    CrossSection xs(2, 2, 2e-3, 2e-3, 1e-3);
    ParticleSet p;
    p.push_back(0.5e-3, 1.0e-3, 0.0, 1.0, 0, 0, 0.4e-3);  // centred on the corner of all four cells
    xs.add_snapshot(p, 0.0);
    const Profile t = xs.table(1.0, 0);
    const double V = 4.0 / 3.0 * std::numbers::pi * std::pow(0.4e-3, 3), cell = 1e-3 * 1e-3 * 1e-3;
    for (double nu : t.column("solid_fraction")) BOOST_TEST(nu * cell == V / 4.0, boost::test_tools::tolerance(1e-12));
    BOOST_CHECK_THROW(CrossSection(0, 2, 1.0, 1.0, 1.0), std::exception);
}
