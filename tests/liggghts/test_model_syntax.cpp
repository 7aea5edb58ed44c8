// The LIGGGHTS doc pages of the impulse model cannot drift from what LIGGGHTS 3.8 accepts: every
// line of their [Examples:] blocks runs on the tiny deck in.separate (and its separate setting
// really acts); the combinations the plugin does not register stop with a message naming them.
#define BOOST_TEST_MODULE liggghts_model_syntax
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "run_driver.h"

namespace fs = std::filesystem;
using granlub::test::example_lines;
using granlub::test::read_text;
using granlub::test::results;
using granlub::test::run_driver;

namespace {

const fs::path kPlugin = fs::path(GRANLUB_SOURCE_DIR) / "plugins" / "liggghts";
const fs::path kTinyDeck = fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "in.separate";
const std::string kFolder = "liggghts_syntax";

// in.separate with its pair_style line or its wall line replaced by `line`; y fixed too, so
// yplane walls are allowed. A line with `iterate off` gets the other impulse model set to iterate
// off too, as that setting requires; otherwise both iterate (the default) with the fix impulse/solve
// that pair_style gran makes.
fs::path deck_with(const std::string& line, const std::string& name) {
    std::string deck = read_text(kTinyDeck);
    deck = std::regex_replace(deck, std::regex("boundary p p f"), "boundary p f f");
    const bool pair = line.rfind("pair_style", 0) == 0;
    if (line.find("iterate off") != std::string::npos)
        deck = std::regex_replace(deck, std::regex(pair ? "(fix wall [^\n]*)" : "(pair_style [^\n]*)"), "$1 iterate off");
    deck = std::regex_replace(deck, std::regex(pair ? "pair_style [^\n]*" : "fix wall [^\n]*"), line);
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    fs::create_directories(dir);
    std::ofstream(dir / name) << deck;
    return dir / name;
}

void close(double a, double b) { BOOST_TEST(std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)), a << " vs " << b); }

void check_examples(const fs::path& page) {
    const auto lines = example_lines(page);
    BOOST_TEST_REQUIRE(lines.size() >= 2u, page << ": no [Examples:] block");
    int k = 0;
    for (const std::string& line : lines) {
        BOOST_TEST_CONTEXT(page.filename().string() << ": " << line) {
            const bool pair = line.rfind("pair_style gran", 0) == 0;
            BOOST_TEST_REQUIRE((pair || line.find(" wall/gran ") != std::string::npos));
            const auto run = run_driver(deck_with(line, "in.example" + std::to_string(k++)).string(), "", 1, kFolder);
            BOOST_TEST(run.exit_code == 0, run.output);
            const auto r = results(run.output);
            BOOST_TEST_REQUIRE(r.count("x2") == 1u);
            const bool separate = line.find("separate off") == std::string::npos;  // on by default
            // iterate on (the default) corrects the overlaps to fix impulse/solve's slop: 1e-4 of r_i + r_j
            // (wall: r); the single pass removes them
            const double slop = line.find("iterate off") == std::string::npos ? 1e-4 : 0.0;
            if (pair) {
                close(r.at("x2"), separate ? 0.0495 + 0.5 * slop * 0.01 : 0.05);  // the pair overlapping by 1 mm, at rest
            } else if (line.find("zplane 0.0") != std::string::npos) {
                close(r.at("z1"), separate ? 0.005 - slop * 0.005 : 0.004);  // the grain overlapping the floor by 1 mm
            }
        }
    }
}

}  // namespace

BOOST_AUTO_TEST_CASE(model_impulse_page_examples_run_as_written) {
    check_examples(kPlugin / "doc" / "gran_model_impulse.txt");
}

BOOST_AUTO_TEST_CASE(tangential_impulse_page_examples_run_as_written) {
    check_examples(kPlugin / "doc" / "gran_tangential_impulse.txt");
}

BOOST_AUTO_TEST_CASE(a_setting_before_the_tangential_keyword_is_rejected_by_liggghts) {
    // the order the page warns about: settings come after all model keywords
    const auto run = run_driver(deck_with("pair_style gran model impulse separate on tangential impulse", "in.order")
                                    .string(), "", 1, kFolder);
    BOOST_TEST(run.exit_code != 0);
    BOOST_TEST(run.output.find("wrong keyword order: 'tangential'") != std::string::npos, run.output);
}

BOOST_AUTO_TEST_CASE(unsupported_combinations_name_the_real_problem) {
    struct Case {
        std::string line, got, what;
    };
    const std::string wall = "fix wall all wall/gran ", plane = " primitive type 2 zplane 0.0";
    const std::vector<Case> cases = {
        {"pair_style gran model impulse tangential history", "model impulse tangential history", "model impulse"},
        {"pair_style gran model impulse tangential impulse rolling_friction cdt",
         "model impulse tangential impulse rolling_friction cdt", "model impulse"},
        {"pair_style gran model impulse tangential impulse cohesion sjkr", "model impulse tangential impulse cohesion sjkr",
         "model impulse"},
        {"pair_style gran model hertz tangential impulse", "model hertz tangential impulse", "tangential impulse"},
        {wall + "model impulse tangential history" + plane, "model impulse tangential history", "model impulse"},
        {wall + "model impulse tangential impulse rolling_friction epsd2" + plane,
         "model impulse tangential impulse rolling_friction epsd2", "model impulse"},
        {wall + "model hooke tangential impulse" + plane, "model hooke tangential impulse", "tangential impulse"},
    };
    int k = 0;
    for (const Case& c : cases) {
        BOOST_TEST_CONTEXT(c.line) {
            const auto run = run_driver(deck_with(c.line, "in.unsupported" + std::to_string(k++)).string(), "", 1, kFolder);
            BOOST_TEST(run.exit_code != 0);
            const std::string expected = "ERROR: " + c.what + " combines only as 'model impulse', 'model impulse "
                                         "tangential impulse'";
            BOOST_TEST(run.output.find(expected) != std::string::npos, run.output);
            BOOST_TEST(run.output.find("got '" + c.got + "'") != std::string::npos, run.output);
            BOOST_TEST(run.output.find("Unknown normal model") == std::string::npos);
            BOOST_TEST(run.output.find("RESULT") == std::string::npos);
        }
    }
}
