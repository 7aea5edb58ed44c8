// Enduring contacts under the impulse model: plugins/liggghts/examples/in.resting_bed (324 grains
// poured onto a floor, 1 s) with and without `separate on`. Prints the overlap statistics the doc
// page and README quote (run with --log_level=message) and checks what the page claims: with
// separate on no overlap exceeds one step of travel (0.02 d at the deck's step), without it the
// bed sinks into itself.
#define BOOST_TEST_MODULE liggghts_resting_bed
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_driver.h"

namespace fs = std::filesystem;

namespace {

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/plugins/liggghts/examples/in.resting_bed";
const std::string kFolder = "liggghts_resting_bed";
constexpr double kPeriod = 0.008;  // the deck's periodic x and y

struct Grain {
    double x, y, z, r;
};

struct Overlaps {
    size_t grains = 0, contacts = 0, floor_contacts = 0;
    double max = 0, median = 0;  // grain-grain, relative to r_i + r_j
    double floor_max = 0;        // grain-floor, relative to r
    double top = 0;              // highest centre
};

std::vector<Grain> last_frame(const fs::path& dump) {
    const std::string text = granlub::test::read_text(dump);
    std::istringstream in(text.substr(text.rfind("ITEM: ATOMS")));
    std::string header;
    std::getline(in, header);
    std::vector<Grain> g;
    long id;
    Grain a;
    while (in >> id >> a.x >> a.y >> a.z >> a.r) g.push_back(a);
    return g;
}

Overlaps measure(const std::vector<Grain>& g) {
    Overlaps o;
    o.grains = g.size();
    std::vector<double> rel;
    for (size_t i = 0; i < g.size(); ++i) {
        o.top = std::max(o.top, g[i].z);
        if (g[i].z < g[i].r) {
            ++o.floor_contacts;
            o.floor_max = std::max(o.floor_max, (g[i].r - g[i].z) / g[i].r);
        }
        for (size_t j = i + 1; j < g.size(); ++j) {
            double dx = g[i].x - g[j].x, dy = g[i].y - g[j].y;
            dx -= kPeriod * std::round(dx / kPeriod);
            dy -= kPeriod * std::round(dy / kPeriod);
            const double dz = g[i].z - g[j].z, sum = g[i].r + g[j].r;
            const double d = std::sqrt(dx * dx + dy * dy + dz * dz);
            if (d < sum) rel.push_back((sum - d) / sum);
        }
    }
    o.contacts = rel.size();
    if (!rel.empty()) {
        std::sort(rel.begin(), rel.end());
        o.max = rel.back();
        o.median = rel.size() % 2 ? rel[rel.size() / 2] : 0.5 * (rel[rel.size() / 2 - 1] + rel[rel.size() / 2]);
    }
    return o;
}

Overlaps run_bed(const std::string& separate) {
    const auto run = granlub::test::run_driver(kDeck, "-var separate " + separate, 1, kFolder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    const Overlaps o = measure(last_frame(fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder /
                                          ("resting_bed_" + separate + ".dump")));
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
