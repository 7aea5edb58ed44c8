// Error paths without YADE: a missing launcher, a failing or silent run (fake launchers), bad
// inputs rejected before anything starts, malformed driver output; and the reduction of known
// driver output (signs, areas, profiles) to the result files.
#define BOOST_TEST_MODULE yade_errors
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>

#include "granlub/error.h"
#include "granlub/results/failure_record.h"
#include "granlub/particles/particles.h"
#include "granlub/results/results.h"
#include "granlub/yade/driver.h"
#include "granlub/yade/reduce.h"
#include "granlub/yade/settings.h"
#include "yade_test_case.h"

using namespace granlub;
using namespace granlub::yade;
using namespace granlub::yade::test;
namespace fs = std::filesystem;

namespace {

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// An executable shell script standing in for the yade launcher.
fs::path fake_launcher(const fs::path& dir, const std::string& body) {
    const fs::path f = dir / "fake-yade";
    std::ofstream(f) << "#!/bin/sh\n" << body << "\n";
    ::chmod(f.c_str(), 0755);
    return f;
}

// Runs the driver of the tiny case's first point through a fake launcher doing `body`; returns
// the SolverError's message ("" when nothing was thrown).
std::string driver_error(const fs::path& dir, const std::string& body, double timeout_s) {
    ScopedEnv env("GRANLUB_YADE", fake_launcher(dir, body).string());
    const Case c = tiny_case();
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    try {
        run_driver(locate_driver(), dir / "point", collision_params(c, c.points.at(0), s, 1.0), "U2.0", timeout_s);
    } catch (const SolverError& e) {
        return e.what();
    }
    return "";
}

RunOptions options(const fs::path& root) {
    RunOptions o;
    o.results_root = root;
    return o;
}

}  // namespace

BOOST_AUTO_TEST_CASE(missing_yade_is_a_clear_error) {
    ScopedEnv env("GRANLUB_YADE", "/nonexistent/yade");
    try {
        locate_driver();
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        const std::string m = e.what();
        BOOST_TEST(has(m, "YADE not found"));
        BOOST_TEST(has(m, "/nonexistent/yade"));
        BOOST_TEST(has(m, "apt-get install"));
    }
    ScopedEnv env2("GRANLUB_YADE", "granlub-no-such-yade");
    try {
        locate_driver();
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        BOOST_TEST(has(e.what(), "not on PATH"));
    }
    // the command reports the point as failed and writes no result
    const auto root = scratch("missing-yade");
    const Case c = tiny_case();
    BOOST_TEST(run(c, options(root)) == 1);
    BOOST_TEST(!fs::exists(root / "yade" / "U2.0" / "summary.json"));
}

BOOST_AUTO_TEST_CASE(failing_run_names_exit_code_and_log) {
    const auto dir = scratch("failing-run");
    const std::string m = driver_error(dir, "echo 'Traceback: boom' >&2; exit 1", 30);
    BOOST_TEST(has(m, "point U2.0"));
    BOOST_TEST(has(m, "exit code 1"));
    BOOST_TEST(has(m, "yade.log"));
    BOOST_TEST(has(m, "boom"));
    BOOST_TEST(fs::exists(dir / "point" / "yade.log"));         // log kept
    BOOST_TEST(fs::exists(dir / "point" / "params.json"));      // rerunnable by hand
    BOOST_TEST(fs::exists(dir / "point" / "granlub_yade.py"));  // with the driver that ran
}

BOOST_AUTO_TEST_CASE(rejected_parameters_are_named) {
    BOOST_TEST(has(driver_error(scratch("rejected"), "echo 'bad parameters: x' >&2; exit 2", 30),
                   "rejected its parameters"));
}

BOOST_AUTO_TEST_CASE(hanging_run_times_out) {
    BOOST_TEST(has(driver_error(scratch("hanging"), "sleep 30", 0.5), "timed out"));
}

BOOST_AUTO_TEST_CASE(silent_run_writes_no_result) {
    const auto dir = scratch("silent");
    ScopedEnv env("GRANLUB_YADE", fake_launcher(dir, "exit 0").string());
    const auto root = dir / "results";
    const Case c = tiny_case();
    BOOST_TEST(run(c, options(root)) == 1);
    BOOST_TEST(!fs::exists(root / "yade" / "U2.0" / "summary.json"));
    BOOST_TEST(!fs::exists(root / "yade" / "U2.0" / "profile.csv"));
}

BOOST_AUTO_TEST_CASE(bad_inputs_are_rejected_before_yade_starts) {
    const auto dir = scratch("before-start");
    const fs::path marker = dir / "yade-started";
    ScopedEnv env("GRANLUB_YADE", fake_launcher(dir, "touch '" + marker.string() + "'; exit 0").string());
    const auto root = dir / "results";
    // a time step too large for the contact, more grains than fit, too few plate updates under load
    const Case c1 = tiny_case("", "", "time_step = 5e-6\n");
    const Case c2 = tiny_case_edits({{"annulus_radius = 0.0762", "annulus_radius = 0.0762\nmax_solid_fraction = 0.74"},
                                     {"solid_fraction = 0.5", "solid_fraction = 0.73"}},
                                    "");
    const Case c3 = tiny_case("control = \"fill\"", "control = \"load\"\nnormal_stress = 5e3", "servo_every = 1000\n");
    for (const Case* c : {&c1, &c2, &c3}) {
        BOOST_TEST(run(*c, options(root)) == 1);
        BOOST_TEST(!fs::exists(marker));
        BOOST_TEST(!fs::exists(root / "yade" / "U2.0" / "params.json"));
    }
}

// The whole ring is granlub dem's: YADE answers "no answer" (not a failure) before it starts.
BOOST_AUTO_TEST_CASE(the_whole_ring_has_no_answer_here) {
    const auto dir = scratch("ring");
    const fs::path marker = dir / "yade-started";
    ScopedEnv env("GRANLUB_YADE", fake_launcher(dir, "touch '" + marker.string() + "'; exit 0").string());
    const Case c = tiny_case_edits({{"annulus_radius = 0.0762", "annulus_radius = 0.0762\ngeometry = \"annulus\""}}, "");
    BOOST_CHECK_EXCEPTION(check(c, options(dir / "results")), NoAnswer, [](const NoAnswer& e) {
        return has(e.what(), "granlub yade runs the slice only") && has(e.what(), "geometry = \"annulus\"");
    });
    BOOST_TEST(run(c, options(dir / "results")) == 0);
    BOOST_TEST(!fs::exists(marker));
    const auto why = read_failure(dir / "results" / "yade" / "U2.0");
    BOOST_TEST_REQUIRE(why.has_value());
    BOOST_TEST(why->no_answer);
}

// start = "warm" without granlub dem's final state, or with one from another case: the point fails
// before YADE starts, saying what to run.
BOOST_AUTO_TEST_CASE(warm_start_needs_the_dem_state_of_this_case) {
    const auto dir = scratch("warm-start");
    const fs::path marker = dir / "yade-started";
    ScopedEnv env("GRANLUB_YADE", fake_launcher(dir, "touch '" + marker.string() + "'; exit 0").string());
    const auto root = dir / "results";
    const Case c = tiny_case("", "", "start = \"warm\"\n");
    BOOST_TEST(run(c, options(root)) == 1);
    BOOST_TEST(!fs::exists(marker));
    auto failure = read_failure(root / "yade" / "U2.0");
    BOOST_TEST_REQUIRE(failure.has_value());
    BOOST_TEST(has(failure->message, "run `granlub dem`"), failure->message);
    BOOST_TEST(has(failure->message, "final_state.csv"), failure->message);
    // a state of 3 grains is not this case's
    ParticleState st;
    for (int i = 0; i < 3; ++i) st.particles.push_back(0.001 * i, 0.001, 0.0, 0, 0, 0, 0.5 * c.grains.diameter);
    st.gap = c.cell.gap;
    write_particle_state(final_state_path(root, "dem", "U2.0"), st);
    BOOST_TEST(run(c, options(root)) == 1);
    BOOST_TEST(!fs::exists(marker));
    failure = read_failure(root / "yade" / "U2.0");
    BOOST_TEST_REQUIRE(failure.has_value());
    BOOST_TEST(has(failure->message, "holds 3 grains"), failure->message);
}

BOOST_AUTO_TEST_CASE(malformed_wall_forces_name_the_line) {
    const auto dir = scratch("malformed");
    std::ofstream(dir / "wallforce.csv") << "# c\nstep,fx_bottom,fy_bottom,fz_bottom,fx_top,fy_top,fz_top,fx_side1,"
                                            "fx_side2\n50,1,2,3,4,5,6,7,8\n100,1,2,nan,4,5,6,7,8\n";
    try {
        read_wall_forces(dir / "wallforce.csv");
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        BOOST_TEST(has(e.what(), "wallforce.csv:4"));
    }
    std::ofstream(dir / "short.csv") << "step,fx_bottom,fy_bottom,fz_bottom,fx_top,fy_top,fz_top,fx_side1,fx_side2\n1,2\n";
    BOOST_CHECK_THROW(read_wall_forces(dir / "short.csv"), SolverError);
    BOOST_CHECK_THROW(read_wall_forces(dir / "none.csv"), SolverError);
}

// Known driver output: every grain at the same height with the same velocity, constant wall
// forces. The stresses are the forces over the areas with granlub dem's signs, with zero error.
BOOST_AUTO_TEST_CASE(reduction_of_known_output) {
    const auto dir = scratch("reduce");
    const Case c = tiny_case();
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    const ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    const std::size_t n = 10;
    const double r = 0.5 * c.grains.diameter;
    const std::vector<double> radius(n, r);
    const auto rows = static_cast<std::size_t>(s.steps / s.sample_every);
    const auto snaps = static_cast<std::size_t>(s.steps / s.snapshot_every);
    {
        std::ofstream w(dir / "wallforce.csv");
        w << "step,fx_bottom,fy_bottom,fz_bottom,fx_top,fy_top,fz_top,fx_side1,fx_side2\n";
        for (std::size_t i = 1; i <= rows; ++i)
            w << i * static_cast<std::size_t>(s.sample_every) << ",-2,-10,0,1.5,8,0,-0.25,-0.75\n";
        std::ofstream b(dir / "samples.bin", std::ios::binary);
        const double y = 0.5 * c.cell.gap;
        for (std::size_t k = 0; k < snaps * n; ++k) {  // x, y, z, vx, vy, vz; the grains spread along x
            const double x = static_cast<double>(k % n) * c.cell.length / static_cast<double>(n);
            const double row[6] = {x, y, 0.0, 0.3 * p.speed, 0.0, 0.0};
            b.write(reinterpret_cast<const char*>(row), sizeof row);
        }
        nlohmann::json d = {{"grains", n},     {"snapshots", snaps},          {"dt", s.time_step},
                            {"steps", s.steps}, {"simulated_time", 0.0015},    {"max_overlap_over_d", 0.0},
                            {"wall_clock_s", 1.0}, {"wall_clock_run_s", 0.5}, {"yade_version", "test"}};
        std::ofstream(dir / "driver_summary.json") << d.dump();
    }
    const PointResult res = reduce_point(c, p, s, box, radius, dir, make_summary(c, p, "yade", 1));
    const double A = c.cell.length * c.cell.width;
    const auto& out = res.summary.outputs;
    BOOST_TEST(out.at("normal_stress_bottom").value == 10.0 / A, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("normal_stress_top").value == 8.0 / A, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("shear_stress_bottom").value == 2.0 / A, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("shear_stress_top").value == 1.5 / A, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("shear_stress_side").value == 0.5 / (c.cell.length * c.cell.gap),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(out.at("normal_stress_top").stderr_.value() < 1e-9 * out.at("normal_stress_top").value);
    // grains fill only the middle slabs: the whole volume is there, the mean velocity is 0.3 U
    const double vg = n * 4.0 / 3.0 * 3.141592653589793 * r * r * r;
    BOOST_TEST(out.at("mean_solid_fraction").value == vg / (A * c.cell.gap), boost::test_tools::tolerance(1e-9));
    const auto& u = res.profile.column("u_over_U");
    const auto& nu = res.profile.column("solid_fraction");
    BOOST_TEST(u[u.size() / 2] == 0.3, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(nu.front() == 0.0);
    BOOST_TEST(res.summary.run.at("grains").get<std::size_t>() == n);
    // positions along the flow are recorded: the contacts are counted
    BOOST_TEST(res.summary.run.at("flow_regime").at("coordination_number").is_number());
    BOOST_TEST(!res.summary.run.at("flow_regime").contains("contacts_not_measured"));
    // the cross-section holds the same volume, at the middle of the gap and the width
    {
        std::ifstream in(dir / "section.csv");
        std::stringstream text;
        text << in.rdbuf();
        const Profile sec = parse_table(text.str(), "section.csv");
        const auto& snu = sec.column("solid_fraction");
        const auto& sz = sec.column("z_over_W");
        std::size_t ny = 0;
        for (double z : sz) ny += z == sz.front();
        const double cell = c.cell.gap / static_cast<double>(ny) * c.cell.width /
                            static_cast<double>(sec.rows() / ny) * c.cell.length;
        double total = 0;
        for (std::size_t k = 0; k < sec.rows(); ++k) total += snu[k] * cell;
        BOOST_TEST(total == vg, boost::test_tools::tolerance(1e-9));
    }
    // and the result files can be written and read back
    write_result(dir / "result", res.profile, res.summary);
    BOOST_TEST(read_summary(dir / "result" / "summary.json").value("shear_stress_top") == 1.5 / A,
               boost::test_tools::tolerance(1e-12));
    // a driver that wrote fewer snapshots than it claims is caught
    fs::resize_file(dir / "samples.bin", fs::file_size(dir / "samples.bin") - 8);
    BOOST_CHECK_THROW(reduce_point(c, p, s, box, radius, dir, make_summary(c, p, "yade", 1)), SolverError);
}
