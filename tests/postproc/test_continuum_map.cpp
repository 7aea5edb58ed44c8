// The continuum map's figures (postproc/src/continuum_map.h) on a known map file: the rows read back,
// a contour line where the field crosses its level (log-interpolated in P), the contact/collision
// boundary, and no figures without a map.
#include <cmath>
#include <filesystem>

#include <boost/test/unit_test.hpp>

#include "figures/continuum_map.h"
#include "granlub/error.h"
#include <fmt/format.h>

#include "granlub/results/file_io.h"
#include "synthetic.h"

using namespace granlub;
using namespace granlub::postproc;

BOOST_AUTO_TEST_SUITE(continuum_map)

BOOST_AUTO_TEST_CASE(map_rows_contours_and_boundary) {
    const auto s = test::make_case("continuum_map");
    Collection col;
    col.root = s.dir / "results";
    BOOST_TEST(continuum_map_figures(s.c, col).empty());  // no map: nothing drawn
    // 3 speeds x 3 loads: mu_top = 0.2 + 0.1 j (load index j), nu = 0.5 - 0.01 j, collision above the
    // second load; one failed point
    std::string csv = "# a map\nspeed_m_s,normal_stress_Pa,status,mean_solid_fraction,gap_m,stress_ratio_bottom,"
                      "stress_ratio_top,inertial_number,slip_bottom_m_s,slip_top_m_s,max_solid_fraction_node,"
                      "lubrication\n";
    const double loads[] = {1000, 2000, 4000};
    for (int j = 0; j < 3; ++j)
        for (double U : {0.5, 1.0, 2.0}) {
            if (U == 2.0 && j == 2) {
                csv += "2,4000,failed,,,,,,,,,\n";
                continue;
            }
            csv += fmt::format("{},{},steady,{},5e-3,{},{},{},0.1,0.1,0.55,{}\n", U, loads[j], 0.5 - 0.01 * j,
                               0.2 + 0.1 * j, 0.2 + 0.1 * j, 0.05 * U, j >= 1 ? "collision" : "contact");
        }
    std::filesystem::create_directories(col.root / "continuum");
    write_file_atomic(col.root / "continuum" / "map.csv", csv);
    const auto rows = read_continuum_map(col.root / "continuum" / "map.csv");
    BOOST_REQUIRE(rows.size() == 9u);
    BOOST_TEST(rows[8].status == "failed");
    BOOST_TEST(std::abs(rows[3].mu_top - 0.3) < 1e-12);
    BOOST_TEST(rows[3].collision);
    const auto figs = continuum_map_figures(s.c, col);
    BOOST_REQUIRE(figs.size() == 3u);
    // mu = 0.25 between the first two loads, at their geometric mean, at every speed
    const Series* c25 = nullptr;
    const Series* edge = nullptr;
    for (const auto& ser : figs[0].series) {
        if (ser.label == "μ (top wall) = 0.25") c25 = &ser;
        if (ser.label == "contact | collision") edge = &ser;
    }
    BOOST_REQUIRE(c25);
    BOOST_TEST(c25->x.size() == 3u);
    for (double P : c25->y) BOOST_TEST(std::abs(P - std::sqrt(1000.0 * 2000.0)) < 1e-9);
    BOOST_REQUIRE(edge);  // between the first and second load
    for (double P : edge->y) BOOST_TEST(std::abs(P - std::sqrt(1000.0 * 2000.0)) < 1e-9);
    // a malformed row names the file and line
    write_file_atomic(col.root / "continuum" / "map.csv", csv + "1,2,steady,x\n");
    BOOST_CHECK_THROW(read_continuum_map(col.root / "continuum" / "map.csv"), Error);
}

BOOST_AUTO_TEST_SUITE_END()
