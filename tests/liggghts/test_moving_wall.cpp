// fix wall/gran/moving and the torque of compute wall/gran/force (plugins/liggghts/doc) through the
// driver and tests/liggghts/in.moving: a turning primitive floor moves two grains exactly as
// LIGGGHTS' turning mesh of the same plane does, and its torque is the mesh's; a floor moved along
// its normal moves them as the mesh moved by fix move/mesh; a grain started at
// rest on it rolls at 2/7 of the floor's speed; a turning cylinder drags along its surface and its
// torque is taken at the contact points on the cylinder, not at the grains' centres; bad input
// stops with a message. Single pass and the iterated solve.
#define BOOST_TEST_MODULE liggghts_moving_wall
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>
#include <vector>

#include "run_driver.h"

namespace fs = std::filesystem;
using granlub::test::read_text;
using granlub::test::results;
using granlub::test::run_driver;

namespace {

const fs::path kDeck = fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "in.moving";
const std::string kFolder = "liggghts_moving_wall";

std::map<std::string, double> run(const std::string& wall, int iterate, int lift = 0) {
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    fs::create_directories(dir);
    fs::copy_file(fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "floor.stl", dir / "floor.stl",
                  fs::copy_options::overwrite_existing);
    const auto r = run_driver(kDeck.string(),
                              "-var wall " + wall + " -var iterate " + std::to_string(iterate) + " -var lift " +
                                  std::to_string(lift),
                              1, kFolder);
    BOOST_TEST_REQUIRE(r.exit_code == 0, r.output);
    const auto v = results(r.output);
    BOOST_TEST_REQUIRE(v.count("tqref1") == 1u, r.output);
    return v;
}

bool close(double a, double b, double tol) { return std::abs(a - b) <= tol * std::max(1e-3, std::abs(b)); }

}  // namespace

BOOST_AUTO_TEST_CASE(a_turning_floor_moves_the_grains_as_the_turning_mesh) {
    for (int iterate : {0, 1}) {
        const auto plane = run("plane", iterate), mesh = run("mesh", iterate);
        for (const auto& [key, value] : mesh)
            BOOST_TEST(close(plane.at(key), value, 1e-12), "iterate " << iterate << " " << key << ": " << plane.at(key)
                                                                        << " vs the mesh's " << value);
        // the comparison means something: the floor carries the weight and drags the grains round
        BOOST_TEST(plane.at("fz1") > 0.0);
        BOOST_TEST(std::abs(plane.at("tq1")) > 1e-5);
        // grain 1 (at rest, 30 mm from the axis, after its bounces) rolls without slipping at 2/7 of
        // the floor's speed there, Omega r = 0.3 m/s along -y
        BOOST_TEST(close(plane.at("vy1"), -2.0 / 7.0 * 10.0 * 0.03, 1e-6), "vy1 " << plane.at("vy1"));
    }
}

// The floor rises at 0.05 m/s, then sinks at 0.02 m/s (normal_velocity, a variable changed between
// two runs) as LIGGGHTS' fix move/mesh moves the mesh: the resting grain is thrown up by the
// restitution and lands again on the sinking floor, to the last digits of the mesh's motion.
BOOST_AUTO_TEST_CASE(a_plane_moving_along_its_normal_moves_as_the_moved_mesh) {
    for (int iterate : {0, 1}) {
        const auto plane = run("plane", iterate, 1), mesh = run("mesh", iterate, 1);
        for (const auto& [key, value] : mesh)
            BOOST_TEST(close(plane.at(key), value, 1e-12), "iterate " << iterate << " " << key << ": " << plane.at(key)
                                                                        << " vs the mesh's " << value);
        // the floor moved: grain 2, resting on it at z = 4.9 mm, ends 0.3 mm higher and sinking with it
        BOOST_TEST(plane.at("z2") > 0.0052);
        BOOST_TEST(close(plane.at("vz2"), -0.02, 0.01), "vz2 " << plane.at("vz2"));
    }
}

BOOST_AUTO_TEST_CASE(a_turning_cylinder_drags_at_its_surface) {
    for (int iterate : {0, 1}) {
        const auto c = run("cylinder", iterate);
        // the torque summed by the compute is the one taken by hand at the contact points (40 mm
        // from the axis; at the grains' centres, 35 mm, it would be an eighth less)
        BOOST_TEST(close(c.at("tq1"), c.at("tqref1"), 1e-12), c.at("tq1") << " vs " << c.at("tqref1"));
        // grain 1, pressed against the cylinder at angle 0, is dragged along +y (the surface moves
        // at Omega R = 0.4 m/s there) and slides: friction gives it at most mu g t = 0.05 m/s
        BOOST_TEST(c.at("vy1") > 0.04);
        BOOST_TEST(c.at("vy1") < 0.4);
        BOOST_TEST(c.at("tq1") > 0.0);
    }
}

BOOST_AUTO_TEST_CASE(bad_input_stops_with_a_message) {
    struct Case {
        std::string from, to, message;
    };
    const std::string plane = "zplane 0.0 store_force yes iterate ${it} ${turn}";
    const std::vector<Case> cases = {
        {plane, "zplane 0.0 store_force yes iterate ${it}", "'surface_ang_vel origin ox oy oz axis ax ay az omega w'"},
        {plane, "zplane 0.0 store_force yes iterate ${it} surface_ang_vel origin 0 0 0 axis 0 0 1",
         "'surface_ang_vel origin ox oy oz axis ax ay az omega w'"},
        {plane, "zplane 0.0 store_force yes iterate ${it} surface_ang_vel origin 0 0 0 axis 0 0 0 omega 1",
         "the axis must not be the zero vector"},
        {plane, "zplane 0.0 shear x 1 store_force yes iterate ${it} ${turn}", "'shear' and this fix's motions exclude each other"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_velocity vz", "normal_velocity takes one equal-style"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_velocity v_nosuch",
         "normal_velocity needs an equal-style variable nosuch"},
        {"zcylinder 0.04 0.05 0.05 store_force yes ${turn}", "zcylinder 0.04 0.05 0.05 store_force yes normal_velocity v_vz",
         "normal_velocity and normal_load move a plane (xplane, yplane, zplane) only"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_load -1 0 -0.01 0.01", "needs M > 0 and lo < hi"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_load -1 1 0.01 -0.01", "needs M > 0 and lo < hi"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_load -1 1 0.001 0.01", "starts outside [lo, hi]"},
        {plane, "zplane 0.0 iterate ${it} normal_load -1 1 -0.01 0.01", "normal_load needs store_force yes"},
        {plane, "zplane 0.0 store_force yes iterate ${it} carry all", "carry belongs to normal_load"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_load -1 1 -0.01 0.01 normal_velocity v_vz",
         "normal_velocity takes one equal-style variable, v_name, and excludes normal_load"},
        {plane, "zplane 0.0 store_force yes iterate ${it} normal_load -1 1 -0.01 0.01 carry nosuch",
         "carry takes one existing group-ID"},
        {"torque 0.05 0.05 0 0 0 1", "torque 0.05 0.05 0 0 1", "[torque ox oy oz ax ay az]"},
        {"torque 0.05 0.05 0 0 0 1", "torque 0 0 0 0 0 0", "the torque axis must not be the zero vector"},
    };
    const fs::path dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / kFolder;
    fs::create_directories(dir);
    for (const Case& c : cases) {
        std::string d = read_text(kDeck);
        const auto at = d.find(c.from);
        BOOST_TEST_REQUIRE(at != std::string::npos, c.from);
        d.replace(at, c.from.size(), c.to);
        std::ofstream(dir / "in.bad") << d;
        const bool cylinder = c.from.find("zcylinder") != std::string::npos;
        const auto r = run_driver((dir / "in.bad").string(), cylinder ? "-var wall cylinder" : "-var wall plane", 1, kFolder);
        BOOST_TEST(r.exit_code != 0, c.to);
        BOOST_TEST(r.output.find(c.message) != std::string::npos, c.to << "\n" << r.output);
        BOOST_TEST(r.output.find("RESULT") == std::string::npos, c.to);
    }
    // a mesh wall has no primitive contact geometry: neither turning nor a torque by this compute
    std::string d = read_text(kDeck);
    d = std::regex_replace(d, std::regex("variable tqref equal v_tq\n"),
                           "variable tqref equal v_tq\ncompute bad all wall/gran/force floor torque 0 0 0 0 0 1\n");
    std::ofstream(dir / "in.bad") << d;
    fs::copy_file(fs::path(GRANLUB_SOURCE_DIR) / "tests" / "liggghts" / "floor.stl", dir / "floor.stl",
                  fs::copy_options::overwrite_existing);
    auto r = run_driver((dir / "in.bad").string(), "-var wall mesh", 1, kFolder);
    BOOST_TEST(r.exit_code != 0);
    BOOST_TEST(r.output.find("wall floor is a mesh; torque needs primitive walls") != std::string::npos, r.output);
    d = std::regex_replace(read_text(kDeck), std::regex("wall/gran \\$\\{model\\} mesh n_meshes 1 meshes floormesh"),
                           "wall/gran/moving ${model} mesh n_meshes 1 meshes floormesh ${turn}");
    std::ofstream(dir / "in.bad") << d;
    r = run_driver((dir / "in.bad").string(), "-var wall mesh", 1, kFolder);
    BOOST_TEST(r.exit_code != 0);
    BOOST_TEST(r.output.find("a primitive wall only") != std::string::npos, r.output);
}
