// Enduring contacts under the impulse model: plugins/liggghts/examples/in.resting_bed (324 grains
// poured onto a floor, 1 s) with and without `separate on`. Prints the overlap statistics the doc
// page and README quote (run with --log_level=message) and checks what the page claims: with
// separate on no overlap exceeds one step of travel (0.02 d at the deck's step), without it the
// bed sinks into itself.
#define BOOST_TEST_MODULE liggghts_resting_bed
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>

#include "overlaps.h"

namespace fs = std::filesystem;

namespace {

using granlub::test::Overlaps;

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/plugins/liggghts/examples/in.resting_bed";
const std::string kFolder = "liggghts_resting_bed";
constexpr double kPeriod = 0.008;  // the deck's periodic x and y

Overlaps run_bed(const std::string& separate) {
    const auto run = granlub::test::run_driver(kDeck, "-var separate " + separate, 1, kFolder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    const Overlaps o = granlub::test::measure(
        granlub::test::last_frame(fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder / ("resting_bed_" + separate + ".dump")),
        {kPeriod, kPeriod, 0.0}, true);
    BOOST_TEST_MESSAGE("separate " << separate << ": " << o.grains << " grains, " << o.contacts
                                   << " contacts, overlap/(r_i+r_j) median " << o.median << " max " << o.max
                                   << "; floor: " << o.floor_contacts << " grains, max overlap/r " << o.floor_max
                                   << "; highest centre " << o.top << " m");
    return o;
}

}  // namespace

BOOST_AUTO_TEST_CASE(separate_on_holds_a_resting_bed_separate_off_lets_it_sink) {
    const Overlaps off = run_bed("off");
    const Overlaps on = run_bed("on");
    BOOST_TEST(off.grains == 324u);
    BOOST_TEST(on.grains == 324u);
    BOOST_TEST(on.contacts > 0u);
    BOOST_TEST(on.max < 0.02);  // within one step of travel at the deck's step (0.02 d)
    BOOST_TEST(on.floor_contacts == 0u);
    BOOST_TEST(off.median > 10 * on.median);
    // 324 grains of 1 mm at solid fraction 0.6 fill 4.4 mm of the 8 x 8 mm column: without
    // separate the top sinks below that, with it the bed keeps at least that height
    BOOST_TEST(off.top < 0.0039);
    BOOST_TEST(on.top > 0.0039);
}
