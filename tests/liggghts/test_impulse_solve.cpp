// fix impulse/solve (plugins/liggghts/doc/fix_impulse_solve.txt) on the tiny deck
// tests/liggghts/in.separate with `iterate on`: its page's examples run as written and correct
// the overlaps to the slop, exactly; every out-of-range value and every combination it cannot
// serve stops with the plugin's error naming the problem.
#define BOOST_TEST_MODULE liggghts_impulse_solve
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
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

const fs::path kPage = fs::path(GRANLUB_SOURCE_DIR) / "plugins" / "liggghts" / "doc" / "fix_impulse_solve.txt";
const fs::path kTinyDeck = fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "in.separate";
const std::string kFolder = "liggghts_impulse_solve";
const std::string kPair = "pair_style gran model impulse tangential impulse separate on";
const std::string kWall = "fix wall all wall/gran model impulse tangential impulse primitive type 2 zplane 0.0 separate on";

// `text` as the deck `name` in this test's folder
fs::path write_deck(const std::string& text, const std::string& name) {
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    fs::create_directories(dir);
    std::ofstream(dir / name) << text;
    return dir / name;
}

// in.separate with its pair_style and wall lines replaced and `fix_lines` after pair_coeff
fs::path deck(const std::string& pair, const std::string& wall, const std::string& fix_lines, const std::string& name) {
    std::string d = read_text(kTinyDeck);
    d = std::regex_replace(d, std::regex("pair_style [^\n]*"), pair);
    d = std::regex_replace(d, std::regex("fix wall [^\n]*"), wall);
    d = std::regex_replace(d, std::regex("pair_coeff \\* \\*\n"), "pair_coeff * *\n" + fix_lines);
    return write_deck(d, name);
}

fs::path iterated(const std::string& fix_lines, const std::string& name) {
    return deck(kPair + " iterate on", kWall + " iterate on", fix_lines, name);
}

void close(double a, double b) { BOOST_TEST(std::abs(a - b) <= 1e-12 * std::max(1.0, std::abs(b)), a << " vs " << b); }

void expect_error(const fs::path& d, const std::string& message) {
    BOOST_TEST_CONTEXT(d.filename().string()) {
        const auto run = run_driver(d.string(), "", 1, kFolder);
        BOOST_TEST(run.exit_code != 0);
        BOOST_TEST(run.output.find(message) != std::string::npos, run.output);
        BOOST_TEST(run.output.find("RESULT") == std::string::npos);
    }
}

}  // namespace

// A keyword's value on a fix line, or `def`.
double value_of(const std::string& line, const std::string& key, double def) {
    std::smatch m;
    return std::regex_search(line, m, std::regex(" " + key + " ([^ ]+)")) ? std::stod(m[1].str()) : def;
}

// The grain overlapping the wall z = 0 by 1 mm and the pair overlapping by 1 mm (d = 10 mm, at
// rest) are corrected in one step by `correction` of their overlap beyond the slop: by default
// all of it, down to the slop, 1e-4 of r (wall) and of r_i + r_j (pair).
BOOST_AUTO_TEST_CASE(page_examples_run_and_correct_the_overlaps_to_the_slop) {
    const auto lines = example_lines(kPage);
    BOOST_TEST_REQUIRE(lines.size() >= 2u);
    int k = 0;
    for (const std::string& line : lines) {
        BOOST_TEST_CONTEXT(line) {
            BOOST_TEST_REQUIRE(line.find(" impulse/solve") != std::string::npos);
            const auto run = run_driver(iterated(line + "\n", "in.example" + std::to_string(k++)).string(), "", 1, kFolder);
            BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
            const auto r = results(run.output);
            BOOST_TEST_REQUIRE(r.count("z1") == 1u);
            const double slop = value_of(line, "slop", 1e-4), corr = value_of(line, "correction", 1.0);
            close(r.at("z1"), 0.004 + corr * (0.001 - slop * 0.005));
            close(r.at("x2"), 0.05 - 0.5 * corr * (0.001 - slop * 0.01));
            close(r.at("x3"), 0.059 + 0.5 * corr * (0.001 - slop * 0.01));
        }
    }
}

BOOST_AUTO_TEST_CASE(with_no_slop_the_overlaps_are_removed_exactly) {
    const auto run = run_driver(iterated("fix solve all impulse/solve slop 0\n", "in.noslop").string(), "", 1, kFolder);
    BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
    const auto r = results(run.output);
    BOOST_TEST_REQUIRE(r.count("z1") == 1u);
    close(r.at("z1"), 0.005);   // touching the wall
    close(r.at("x2"), 0.0495);  // equal masses: each moves half of the 1 mm overlap
    close(r.at("x3"), 0.0595);
    // separate off: the solver leaves the overlaps alone
    const auto off = run_driver(deck(std::regex_replace(kPair, std::regex("separate on"), "separate off") + " iterate on",
                                     std::regex_replace(kWall, std::regex("separate on"), "separate off") + " iterate on",
                                     "fix solve all impulse/solve slop 0\n", "in.off")
                                    .string(),
                                "", 1, kFolder);
    BOOST_TEST_REQUIRE(off.exit_code == 0, off.output);
    const auto o = results(off.output);
    close(o.at("z1"), 0.004);
    close(o.at("x2"), 0.05);
}

// A mesh wall (tests/liggghts/in.meshwall): its per-element forces come from the solver. The mesh
// carries the resting grain's weight, to round-off, with either operator; the solved grain is at
// rest (the single pass leaves it bouncing at g dt).
BOOST_AUTO_TEST_CASE(a_mesh_wall_gets_the_solved_forces) {
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    fs::create_directories(dir);
    fs::copy_file(fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "floor.stl", dir / "floor.stl",
                  fs::copy_options::overwrite_existing);
    const std::string deck = (fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "in.meshwall").string();
    const double weight = 2500.0 * std::numbers::pi / 6.0 * 1e-6 * 9.81;  // d = 10 mm
    for (const int iterate : {0, 1}) {
        BOOST_TEST_CONTEXT("iterate " << iterate) {
            const auto run = run_driver(deck, "-var iterate " + std::to_string(iterate), 1, kFolder);
            BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
            const auto r = results(run.output);
            BOOST_TEST_REQUIRE(r.count("fz1") == 1u);
            BOOST_TEST(std::abs(r.at("fz1") + weight) <= 1e-12 * weight, r.at("fz1") << " vs " << -weight);
            if (iterate) BOOST_TEST(std::abs(r.at("vz2")) < 1e-15);
            else BOOST_TEST(std::abs(r.at("vz2")) > 1e-6);
        }
    }
}

BOOST_AUTO_TEST_CASE(values_out_of_range_stop_with_the_plugins_error) {
    struct Bad {
        std::string args, message;
    };
    const std::vector<Bad> bad = {
        {"tolerance 0", "tolerance must be a number in [1e-12, 0.5]; got '0'"},
        {"tolerance 0.7", "tolerance must be a number in [1e-12, 0.5]; got '0.7'"},
        {"tolerance tight", "tolerance must be a number in [1e-12, 0.5]; got 'tight'"},
        {"tolerance", "keyword 'tolerance' needs a value"},
        {"iterations 0", "iterations must be a whole number in [1, 100000]"},
        {"iterations 2.5", "iterations must be a whole number in [1, 100000]"},
        {"iterations 100001", "iterations must be a whole number in [1, 100000]"},
        {"warm_start maybe", "warm_start must be yes or no; got 'maybe'"},
        {"restitution some", "restitution must be new or all; got 'some'"},
        {"slop -1e-4", "slop must be a number in [0, 0.01]"},
        {"slop 0.05", "slop must be a number in [0, 0.01]"},
        {"correction 0", "correction must be a number in (0, 1]"},
        {"correction 1.5", "correction must be a number in (0, 1]"},
        {"rest_factor -1", "rest_factor must be a number in [0, 100]"},
        {"rest_factor 101", "rest_factor must be a number in [0, 100]"},
        {"active_set some", "active_set must be yes or no; got 'some'"},
        {"impact_tolerance -0.01", "impact_tolerance must be a number in [0, 0.5] (0: off); got '-0.01'"},
        {"impact_tolerance 0.6", "impact_tolerance must be a number in [0, 0.5] (0: off); got '0.6'"},
        {"tol 1e-3", "unknown keyword 'tol' (tolerance, iterations, warm_start, restitution, rest_factor, slop, correction, "
                     "velocity_tolerance, impact_tolerance, active_set, overlap_limit, overlaps)"},
    };
    int k = 0;
    for (const Bad& b : bad)
        expect_error(iterated("fix solve all impulse/solve " + b.args + "\n", "in.bad" + std::to_string(k++)),
                     "ERROR: fix impulse/solve: " + b.message);
}

BOOST_AUTO_TEST_CASE(what_it_cannot_serve_stops_with_the_plugins_error) {
    const std::string fix = "fix solve all impulse/solve\n";
    // iterate on (the default) with no solver on the pair: made there (test below); on a wall alone, with the
    // pair at iterate off, nothing makes one; a solver and a model with iterate off (pair, then a wall)
    expect_error(deck(kPair + " iterate off", kWall, "", "in.nofix"),
                 "ERROR: model impulse (fix wall/gran wall) iterates ('iterate on', the default) but the run has no fix "
                 "impulse/solve");
    // the same under a pair style with another model
    expect_error(deck("pair_style gran model hertz tangential history", kWall, "", "in.hertzpair"),
                 "with another pair model, or the pair style at 'iterate off', give every impulse wall 'iterate off' "
                 "too");
    expect_error(deck(kPair + " iterate off", kWall + " iterate off", fix, "in.pairoff"),
                 "ERROR: model impulse (pair_style gran) has 'iterate off', but fix impulse/solve solves every impulse "
                 "contact of the run");
    expect_error(deck(kPair, kWall + " iterate off", fix, "in.walloff"),
                 "ERROR: model impulse (fix wall/gran wall) has 'iterate off', but fix impulse/solve solves every");
    // a wall with another contact model
    expect_error(deck(kPair + " iterate on", "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0",
                      fix, "in.hertzwall"),
                 "ERROR: fix impulse/solve: fix wall/gran wall uses another contact model");
    // the same with the solver the pair made: the message says how to do without it
    expect_error(deck(kPair, "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0", "",
                      "in.hertzwall_made"),
                 "uses another contact model; with fix impulse/solve every granular wall must be 'model impulse ... "
                 "iterate on' (this fix was made by model impulse, whose default is 'iterate on'; 'iterate off' on the "
                 "pair style and every impulse wall gives Sawyer & Tichy's single pass");
    // the group, a second solver, per-contact force output
    expect_error(iterated("group one id 1\nfix solve one impulse/solve\n", "in.group"),
                 "ERROR: fix impulse/solve: acts on every contact of the impulse models: its group must be 'all'; got 'one'");
    expect_error(iterated(fix + "fix solve2 all impulse/solve\n", "in.two"),
                 "ERROR: fix impulse/solve: only one fix impulse/solve is allowed");
    expect_error(iterated(fix + "compute cpl all pair/gran/local pos force\n", "in.cpl"),
                 "ERROR: fix impulse/solve: per-contact pair forces (compute pair/gran/local, contact force storage) are "
                 "not available");
    // newton on: LIGGGHTS refuses the contact history the iterated models keep, before the fix says so
    std::string d = read_text(iterated(fix, "in.newton"));
    d = std::regex_replace(d, std::regex("newton off"), "newton on");
    expect_error(write_deck(d, "in.newton"), "requires newton pair off");
}

// The models' default is iterate on: a deck that names neither the setting nor the solver gets the
// solver with its defaults from pair_style gran, says so, and gives the numbers of the deck that
// writes both out.
BOOST_AUTO_TEST_CASE(the_default_iterates_with_the_solver_the_pair_style_makes) {
    const auto made = run_driver(deck(kPair, kWall, "", "in.default").string(), "", 1, kFolder);
    BOOST_TEST_REQUIRE(made.exit_code == 0, made.output);
    BOOST_TEST(made.output.find("model impulse: iterate on (the default): made 'fix granlub_impulse_solve all "
                                "impulse/solve' with its defaults") != std::string::npos, made.output);
    // written after the pair style, the deck's fix takes over from the one the pair style made there
    const auto written = run_driver(iterated("fix solve all impulse/solve\n", "in.written").string(), "", 1, kFolder);
    BOOST_TEST_REQUIRE(written.exit_code == 0, written.output);
    // written before it, none is made
    std::string d = read_text(iterated("", "in.written_first"));
    d = std::regex_replace(d, std::regex("\npair_style "), "\nfix solve all impulse/solve\npair_style ");
    const auto first = run_driver(write_deck(d, "in.written_first").string(), "", 1, kFolder);
    BOOST_TEST_REQUIRE(first.exit_code == 0, first.output);
    BOOST_TEST(first.output.find("granlub_impulse_solve") == std::string::npos);
    const auto a = results(made.output), b = results(written.output), c = results(first.output);
    BOOST_TEST_REQUIRE(a.size() >= 3u);
    BOOST_TEST_REQUIRE(a.size() == b.size());
    BOOST_TEST_REQUIRE(a.size() == c.size());
    for (const auto& [key, value] : a) BOOST_TEST_CONTEXT(key) {
            close(value, b.at(key));
            close(value, c.at(key));
        }
    // and the single pass, written out, makes none
    const auto single = run_driver(deck(kPair + " iterate off", kWall + " iterate off", "", "in.single").string(), "", 1,
                                   kFolder);
    BOOST_TEST_REQUIRE(single.exit_code == 0, single.output);
    BOOST_TEST(single.output.find("granlub_impulse_solve") == std::string::npos);
}

// An atom whose motion is prescribed (fix move) or that no fix integrates is a wall to the solver:
// infinite mass. In.separate's grain 2 meets grain 3 (overlapping by 1 mm) at 1 m/s with e = 0.5;
// against a grain 3 that is kinematic it bounces back at exactly -e v = -0.5 m/s and takes the
// whole overlap correction, and grain 3 does not move; against a free grain 3 the two share both
// (0.25 and 0.75 m/s).
BOOST_AUTO_TEST_CASE(prescribed_and_unintegrated_atoms_are_kinematic) {
    const std::string base = read_text(kTinyDeck);
    const auto variant = [&](const std::string& integration, const std::string& name) {
        std::string d = std::regex_replace(base, std::regex("fix integr all nve/sphere\n"),
                                           "set atom 2 vx 1.0\ngroup free id 1 2\ngroup three id 3\n" + integration);
        d = std::regex_replace(d, std::regex("run 1\n"), "run 2\n");
        d = std::regex_replace(d, std::regex("print \"RESULT ([^\"]*)\""),
                               "variable v2 equal vx[2]\nvariable v3 equal vx[3]\nprint \"RESULT $1 v2=${v2} v3=${v3}\"");
        const auto run = run_driver(write_deck(d, name).string(), "", 1, kFolder);
        BOOST_TEST_REQUIRE(run.exit_code == 0, run.output);
        return results(run.output);
    };
    const double slop = 1e-4 * 0.01;  // fix impulse/solve's default slop of r_i + r_j
    for (const auto& [integration, name] :
         {std::pair<std::string, std::string>{"fix integr free nve/sphere\nfix hold three move linear 0 0 0\n", "in.moved"},
          {"fix integr free nve/sphere\n", "in.unintegrated"}}) {
        BOOST_TEST_CONTEXT(name) {
            const auto r = variant(integration, name);
            close(r.at("v2"), -0.5);
            close(r.at("v3"), 0.0);
            close(r.at("x3"), 0.059);
            // step 1 moves it 1e-5 m further in at 1 m/s, the correction takes all of that overlap but the slop
            // back, step 2 moves it at -0.5 m/s
            close(r.at("x2"), 0.05 + 1e-5 - (0.001 + 1e-5 - slop) + 1e-5 * -0.5);
        }
    }
    const auto both = variant("fix integr all nve/sphere\n", "in.free");
    close(both.at("v2"), 0.25);
    close(both.at("v3"), 0.75);
}
