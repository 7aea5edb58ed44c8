// Every validation path of the case parser: each bad input must be rejected with a message that
// names the file, the place (line:column where there is one), the key, the bad value and what is
// allowed.
#include <filesystem>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/run/solver_info.h"

using namespace granlub;
using granlub::test::kValidCase;
using granlub::test::error_of;
using granlub::test::with;

namespace {

struct Bad {
    const char* what;
    std::string text;
    std::vector<std::string> expect;  // substrings the message must contain
};


}  // namespace

BOOST_AUTO_TEST_CASE(valid_case_parses) {
    Case c = parse_case(kValidCase, "good.toml", Schema::common());
    BOOST_TEST(c.points.size() == 2u);
    BOOST_TEST(c.grains.diameter == 1.0e-3);
    BOOST_TEST(c.section("grains").is_default("friction"));
    BOOST_TEST(!c.section("grains").is_default("diameter"));
}

BOOST_AUTO_TEST_CASE(bad_inputs_are_rejected_with_clear_messages) {
    const std::vector<Bad> cases = {
        {"TOML syntax error", with("density = 2500.0", "density = = 2500"), {"bad.toml:7:", "TOML syntax error"}},
        {"unterminated string", with("name = \"t\"", "name = \"t"), {"bad.toml:3:", "TOML syntax error"}},
        {"wrong type", with("diameter = 1.0e-3", "diameter = \"big\""),
         {"bad.toml:6:1", "[grains] diameter", "\"big\"", "expected number", "allowed: a number > 0 m"}},
        {"negative diameter", with("diameter = 1.0e-3", "diameter = -1.0e-3"),
         {"bad.toml:6:1", "diameter = -0.001", "out of range", "> 0"}},
        {"zero density", with("density = 2500.0", "density = 0.0"), {"bad.toml:7:11", "density = 0:", "> 0"}},
        {"e_p > 1", with("restitution = 0.9", "restitution = 1.2"), {"[grains] restitution = 1.2", "(0, 1]"}},
        {"e_p = 0", with("restitution = 0.9", "restitution = 0"), {"[grains] restitution = 0", "(0, 1]"}},
        {"e_w > 1", with("restitution = 0.8", "restitution = 1.01"), {"[walls] restitution = 1.01", "(0, 1]"}},
        {"R > 1", with("roughness = 0.5", "roughness = 1.5"), {"bad.toml:12:1", "[walls] roughness = 1.5", "[0, 1]"}},
        {"R < 0", with("roughness = 0.5", "roughness = -0.1"), {"[walls] roughness = -0.1", "[0, 1]"}},
        {"nu >= nu_max", with("solid_fraction = 0.5", "solid_fraction = 0.65"),
         {"bad.toml:23:1", "[operating] solid_fraction = 0.65", "below [cell] max_solid_fraction = 0.65"}},
        {"nu_max too high", with("max_solid_fraction = 0.65", "max_solid_fraction = 0.8"),
         {"[cell] max_solid_fraction = 0.8", "(0, 0.74048]"}},
        {"gap < 2 d", with("gap = 5.0e-3", "gap = 1.5e-3"), {"bad.toml:15:7", "[cell] gap = 0.0015", "gap >= 2 d = 0.002"}},
        {"length < 2 d", with("length = 20.0e-3", "length = 1.0e-3"), {"[cell] length = 0.001", "2 d"}},
        {"width neither 0 nor >= 2 d", with("width = 0.0", "width = 1.0e-3"), {"[cell] width = 0.001", "0 (periodic)"}},
        {"annulus inside the trough", with("width = 0.0", "width = 0.01\nannulus_radius = 0.004"),
         {"[cell] annulus_radius = 0.004", "half the width"}},
        {"slice_case without a ring", kValidCase + "\n[report]\nslice_case = \"../slice\"\n",
         {"[report] slice_case = \"../slice\"", "needs [cell] geometry = \"annulus\""}},
        {"unknown geometry", with("width = 0.0", "width = 0.0\ngeometry = \"torus\""),
         {"[cell] geometry = \"torus\"", "one of \"slice\", \"annulus\""}},
        {"ring without a radius", with("width = 0.0", "width = 0.01\ngeometry = \"annulus\""),
         {"[cell] geometry", "needs [cell] annulus_radius > 0"}},
        {"ring without side walls", with("width = 0.0", "width = 0.0\ngeometry = \"annulus\"\nannulus_radius = 0.05"),
         {"[cell] width = 0", "needs a trough: width > 0"}},
        {"ring radius inside the trough", with("width = 0.0", "width = 0.01\ngeometry = \"annulus\"\nannulus_radius = 0.005"),
         {"[cell] annulus_radius = 0.005", "half the width"}},
        {"ring too small for its grains",
         with("width = 0.0", "width = 0.01\ngeometry = \"annulus\"\nannulus_radius = 0.0075"),
         {"[cell] annulus_radius = 0.0075", "2.5 grain diameters from the axis", "at least 3 d = 0.003 m",
          "too small for its grains"}},
        {"unknown key with suggestion", with("density = 2500.0", "density = 2500.0\ndiamter = 1e-3"),
         {"bad.toml:8:1", "[grains] diamter: unknown key", "did you mean 'diameter'?", "allowed: diameter, density"}},
        {"unknown section", kValidCase + "\n[operatng]\nspeed = 3\n",
         {"bad.toml:26:1", "[operatng]: unknown section", "did you mean 'operating'?", "allowed: case, grains"}},
        {"section that is not a table", "body_forces = 3\n" + kValidCase, {"body_forces = 3", "must be a table"}},
        {"empty sweep", with("speed = [1.0, 2.0]", "speed = []"), {"[operating] speed = []", "empty list"}},
        {"duplicate sweep value", with("speed = [1.0, 2.0]", "speed = [1.0, 1.0]"), {"1 appears twice"}},
        {"negative speed in a sweep", with("speed = [1.0, 2.0]", "speed = [1.0, -2.0]"),
         {"bad.toml:21:15", "[operating] speed = -2:", "out of range", "[1e-09, 10000] m/s"}},
        {"string in a numeric sweep", with("speed = [1.0, 2.0]", "speed = [1.0, \"fast\"]"),
         {"[operating] speed = \"fast\"", "expected number or list of numbers"}},
        {"missing required key", with("diameter = 1.0e-3\n", ""), {"bad.toml:5:1", "[grains] diameter: required key is missing"}},
        {"missing section", with("[cell]\ngap = 5.0e-3\nlength = 20.0e-3\nwidth = 0.0\nmax_solid_fraction = 0.65\n", ""),
         {"[cell] gap: required key is missing"}},
        {"unknown choice", with("control = \"fill\"", "control = \"fil\""),
         {"[operating] control = \"fil\"", "did you mean 'fill'?", "one of \"fill\", \"load\""}},
        {"load without normal stress", with("normal_stress = 1000.0\n", "", with("control = \"fill\"", "control = \"load\"")),
         {"[operating] normal_stress", "control = \"load\" needs"}},
        {"fill without solid fraction", with("solid_fraction = 0.5\n", ""),
         {"[operating] solid_fraction", "control = \"fill\" needs"}},
        {"NaN", with("diameter = 1.0e-3", "diameter = nan"), {"[grains] diameter = nan", "not a finite number"}},
        {"infinity", with("gap = 5.0e-3", "gap = inf"), {"[cell] gap = inf", "not a finite number"}},
        {"boolean for a number", kValidCase + "\n[body_forces]\ngravity = true\n",
         {"[body_forces] gravity = true", "expected number"}},
        {"per-wall table that is not a table", with("roughness = 0.5", "roughness = 0.5\ntop = 3"),
         {"[walls] top = 3", "must be a table"}},
        {"per-wall out of range", kValidCase + "\n[walls.bottom]\nrestitution = 1.2\n",
         {"[walls.bottom] restitution = 1.2", "(0, 1]"}},
        {"per-wall unknown key", kValidCase + "\n[walls.top]\nrougness = 0.2\n",
         {"[walls.top] rougness: unknown key", "did you mean 'roughness'?"}},
        {"Poisson ratio at 0.5", with("density = 2500.0", "density = 2500.0\npoisson_ratio = 0.5"),
         {"[grains] poisson_ratio = 0.5", "(-1, 0.5)"}},
        {"negative friction", with("roughness = 0.5", "roughness = 0.5\nfriction = -0.3"),
         {"[walls] friction = -0.3", ">= 0"}},
        {"roughness sweep out of range", with("normal_stress = 1000.0", "normal_stress = 1000.0\nroughness = [0.5, 2]"),
         {"[operating] roughness = 2", "[0, 1]"}},
        {"top-level key outside any section", "stray = 1\n" + kValidCase, {"[stray]: unknown section"}},
    };
    BOOST_TEST(cases.size() >= 25u);
    for (const auto& b : cases) {
        BOOST_TEST_CONTEXT(b.what) {
            const std::string msg = error_of(b.text);
            BOOST_TEST(!msg.empty(), "accepted a bad input");
            BOOST_TEST(msg.find("bad.toml") != std::string::npos, "no file name in: " << msg);
            for (const auto& e : b.expect) BOOST_TEST(msg.find(e) != std::string::npos, "'" << e << "' not in: " << msg);
        }
    }
}

BOOST_AUTO_TEST_CASE(missing_file_and_directory) {
    const auto tmp = std::filesystem::temp_directory_path() / "granlub_test_no_case";
    std::filesystem::remove_all(tmp);
    try {
        load_case(tmp, Schema::common());
        BOOST_FAIL("no error for a missing case");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("no such case directory or file") != std::string::npos);
    }
    std::filesystem::create_directories(tmp);
    try {
        load_case(tmp, Schema::common());
        BOOST_FAIL("no error for a directory without case.toml");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("no case.toml in this directory") != std::string::npos);
    }
    std::filesystem::remove_all(tmp);
}

BOOST_AUTO_TEST_CASE(solver_sections_are_declared_by_modules) {
    // A module's section: one line per key, and its own cross-key check.
    SectionSpec s("toy", "a toy solver");
    s.integer("steps", 100, Range::at_least(1), "time steps");
    s.integer("average_from", 10, Range::at_least(0), "first averaged step");
    s.validate = [](const Section& sec) {
        if (sec.integer("average_from") >= sec.integer("steps")) sec.fail("average_from", "must be below steps");
    };
    Schema schema = Schema::common();
    schema.add(s);
    Case c = parse_case(kValidCase + "\n[toy]\nsteps = 50\n", "t.toml", schema);
    BOOST_TEST(c.section("toy").integer("steps") == 50);
    BOOST_TEST(c.section("toy").is_default("average_from"));
    try {
        parse_case(kValidCase + "\n[toy]\nsteps = 5\naverage_from = 7\n", "t.toml", schema);
        BOOST_FAIL("cross-key check not applied");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("t.toml:28:16: [toy] average_from = 7: must be below steps") !=
                   std::string::npos, e.what());
    }
    try {
        parse_case(kValidCase + "\n[toy]\nsteps = 2.5\n", "t.toml", schema);
        BOOST_FAIL("a real accepted for an integer key");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("expected an integer") != std::string::npos, e.what());
    }
}

BOOST_AUTO_TEST_CASE(a_solver_section_carries_its_declaration) {
    // What the report knows of a solver is its declaration, carried by its section and by every case
    // parsed with the schema (granlub/run/solver_info.h, cli case_schema()).
    static constexpr SolverInfo toy{.name = "toy", .description = "", .kind = SolverKind::Particles, .whole_ring = true};
    Schema schema = Schema::common();
    schema.add(SectionSpec("toy", "a toy solver")).declare_solver("toy", &toy);
    BOOST_TEST(schema.find("toy")->solver == &toy);
    BOOST_TEST(schema.find("grains")->solver == nullptr);
    const Case c = parse_case(kValidCase + "\n[toy]\n", "t.toml", schema);
    const auto declared = declared_solvers(*c.schema);
    BOOST_TEST_REQUIRE(declared.size() == 1u);
    BOOST_TEST(declared.front()->whole_ring);
    BOOST_CHECK_THROW(schema.declare_solver("nosuch", &toy), Error);
}
