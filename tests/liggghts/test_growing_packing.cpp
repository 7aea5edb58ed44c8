// The model's defaults hold a packing made by growing the grains (plugins/liggghts/examples/
// in.growing_packing: 343 grains grown with fix adapt to solid fraction 0.55 in a periodic box, as
// LIGGGHTS' packing tutorials do, then at rest), and `separate off` does not: every contact there
// is an enduring one, made by growth rather than by a collision.
#define BOOST_TEST_MODULE liggghts_growing_packing
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>

#include "overlaps.h"

namespace fs = std::filesystem;

namespace {

using granlub::test::Overlaps;

const std::string kDeck = std::string(GRANLUB_SOURCE_DIR) + "/plugins/liggghts/examples/in.growing_packing";
const std::string kFolder = "liggghts_growing_packing";
constexpr double kBox = 0.0084;  // the deck's periodic box

// `settings` after "tangential impulse" ("" = the model's defaults), written to growing_packing_<tag>.dump
Overlaps run_packing(const std::string& settings, const std::string& tag) {
    const std::string vars = (settings.empty() ? std::string() : "-var settings " + settings + " ") + "-var tag " + tag;
    const auto run = granlub::test::run_driver(kDeck, vars, 1, kFolder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    const Overlaps o = granlub::test::measure(
        granlub::test::last_frame(fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder / ("growing_packing_" + tag + ".dump")),
        {kBox, kBox, kBox}, false);
    BOOST_TEST_MESSAGE(tag << ": " << o.grains << " grains, " << o.touching << " pairs within 1 % of touching, "
                           << o.contacts << " overlapping, overlap/(r_i+r_j) median " << o.median << " max " << o.max);
    return o;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_default_model_holds_a_grown_packing_separate_off_does_not) {
    const Overlaps def = run_packing("", "default");
    const Overlaps off = run_packing("'separate off'", "off");
    BOOST_TEST(def.grains == 343u);
    BOOST_TEST(off.grains == 343u);
    BOOST_TEST(def.touching > def.grains);  // over 2 near-contacts per grain: a packing, not a gas
    // the last growth step adds (1.22 - 0.6) mm / 20000 * 10 = 3e-4 mm to a diameter; the
    // default removes each overlap as it forms, so none may exceed a small fraction of it
    BOOST_TEST(def.max < 1e-3);
    BOOST_TEST(off.median > 0.01);  // without it overlaps grow with the grains (measured median 0.07, max 0.25)
}
