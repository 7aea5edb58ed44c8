// One enduring Hertz-Mindlin contact in both engines (issue: YADE's wall shear stresses were ~30 %
// below LIGGGHTS' in the jammed sawyer2001 transient). A sphere on a wall, free along y only,
// pressed by F0, slides at V (loading the tangential spring below the Coulomb limit), stops, and
// its normal force then ramps to 2 F0: contact/one_contact.in (LIGGGHTS) and contact/one_contact.py
// (YADE, with the driver's wall material). Two findings, each a check that could fail:
//  1. At a constant normal force the two tangential springs are the same (the wall material that
//     maps YADE's box contact onto LIGGGHTS' wall; it once left YADE's kt 7 % low).
//  2. While the contact sticks and the overlap grows, LIGGGHTS' spring (total shear displacement
//     times the current kt = 8 G* sqrt(R delta), tangential_model_history.h) raises F_t by
//     (delta2/delta1)^(1/2) = (Fn2/Fn1)^(1/3) without any tangential motion; YADE's incremental
//     Mindlin spring (F_t += kt du) keeps it. Under fluctuating normal forces, as in a dense
//     sheared bed, LIGGGHTS therefore carries more tangential force per contact (docs/measurements/engines.md).
#define BOOST_TEST_MODULE one enduring contact in LIGGGHTS and YADE
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "granlub/run/process.h"
#include "granlub/results/results.h"
#include "granlub/results/table.h"
#include "yade_installed.h"

namespace fs = std::filesystem;
using namespace granlub;

namespace {

struct Run {
    std::vector<double> t, ft, fn;  // the wall's force on the sphere: tangential (x) and normal (y), N
};

constexpr double E = 1e9, nu = 0.23, d = 0.787e-3, rho = 2550.0, F0 = 0.25, V = 0.002;
constexpr int n_slide = 1200, n_hold = 200, n_ramp = 400;

double time_step() {  // 0.15 Rayleigh times, as both engines' hertz default
    const double r = 0.5 * d, G = E / (2 * (1 + nu));
    return 0.15 * std::numbers::pi * r * std::sqrt(rho / G) / (0.1631 * nu + 0.8766);
}

double resting_overlap() {  // Hertz, sphere on a wall of the same material: F0 = 4/3 Y* sqrt(r) delta^3/2
    const double Ystar = E / (2 * (1 - nu * nu));
    return std::pow(3 * F0 / (4 * Ystar * std::sqrt(0.5 * d)), 2.0 / 3.0);
}

Run read_run(const fs::path& file, double sign) {
    TableFormat f;
    f.separator = TableFormat::Separator::whitespace;
    f.header = false;
    f.names = {"t", "ft", "fn"};
    f.finite = true;
    const Table tab = read_table(file, f);
    Run r{tab.columns[0], tab.columns[1], tab.columns[2]};
    for (double& x : r.ft) x *= sign;  // the force against the sliding, positive
    return r;
}

const fs::path& scratch() {
    static const fs::path dir = [] {
        fs::path p = fs::temp_directory_path() / "granlub_test_enduring_contact";
        fs::remove_all(p);
        fs::create_directories(p);
        return p;
    }();
    return dir;
}

std::string number(double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    return buf;
}

const Run& liggghts() {
    static const Run run = [] {
        const fs::path src = fs::path(GRANLUB_SOURCE_DIR) / "tests" / "yade" / "contact" / "one_contact.in";
        std::vector<std::string> argv{GRANLUB_LIGGGHTS_DRIVER_PATH, "-in", src.string(), "-log", "none"};
        for (const auto& [k, v] : std::vector<std::pair<std::string, double>>{
                 {"E", E}, {"nu", nu}, {"d", d}, {"rho", rho}, {"F0", F0}, {"delta0", resting_overlap()},
                 {"V", V}, {"dt", time_step()}, {"n_slide", n_slide}, {"n_hold", n_hold}, {"n_ramp", n_ramp}})
            argv.insert(argv.end(), {"-var", k, number(v)});
        argv.insert(argv.end(), {"-var", "out", "liggghts.txt"});
        const ProcessResult r = run_process(argv, scratch(), scratch() / "liggghts.log", 300);
        BOOST_TEST_REQUIRE(r.exit_code == 0, r.describe() << "\n" << tail_lines(scratch() / "liggghts.log", 20));
        return read_run(scratch() / "liggghts.txt", -1.0);
    }();
    return run;
}

const Run& yade_run() {
    static const Run run = [] {
        const fs::path src = fs::path(GRANLUB_SOURCE_DIR) / "tests" / "yade" / "contact" / "one_contact.py";
        const nlohmann::json j{{"driver_dir", (fs::path(GRANLUB_SOURCE_DIR) / "plugins" / "yade").string()},
                               {"E", E}, {"nu", nu}, {"d", d}, {"rho", rho}, {"F0", F0},
                               {"delta0", resting_overlap()}, {"V", V}, {"dt", time_step()},
                               {"n_slide", n_slide}, {"n_hold", n_hold}, {"n_ramp", n_ramp}, {"out", "yade.txt"}};
        std::ofstream(scratch() / "params.json") << j.dump(1);
        const char* env = std::getenv("GRANLUB_YADE");
        const auto launcher = find_executable(env && *env ? env : "yade");
        BOOST_TEST_REQUIRE(launcher.has_value());
        const ProcessResult r =
            run_process({launcher->string(), "-n", "-j1", "-x", src.string(), "params.json"}, scratch(), scratch() / "yade.log", 300);
        BOOST_TEST_REQUIRE(r.exit_code == 0, r.describe() << "\n" << tail_lines(scratch() / "yade.log", 20));
        return read_run(scratch() / "yade.txt", -1.0);
    }();
    return run;
}

// The mean of a series over steps [from, to).
double mean(const std::vector<double>& v, std::size_t from, std::size_t to) {
    double s = 0;
    for (std::size_t i = from; i < to; ++i) s += v.at(i);
    return s / static_cast<double>(to - from);
}

}  // namespace

BOOST_AUTO_TEST_CASE(same_tangential_spring_at_constant_normal_force,
                     *boost::unit_test::precondition(granlub::yade::test::YadeInstalled())) {
    const Run& L = liggghts();
    const Run& Y = yade_run();
    // the end of the slide: displacement V n_slide dt, both at F0, below the Coulomb limit (0.5 F0)
    const std::size_t k = n_slide - 10;
    const double ft_l = mean(L.ft, k - 5, k + 5), ft_y = mean(Y.ft, k - 5, k + 5);
    BOOST_TEST_MESSAGE("F_t at the end of the slide: LIGGGHTS " << ft_l << " N, YADE " << ft_y << " N");
    BOOST_TEST(mean(L.fn, k - 5, k + 5) == F0, boost::test_tools::tolerance(1e-3));
    BOOST_TEST(mean(Y.fn, k - 5, k + 5) == F0, boost::test_tools::tolerance(1e-3));
    BOOST_TEST(ft_l < 0.5 * F0);  // sticking
    BOOST_TEST(ft_l > 0.2 * F0);  // and loaded
    BOOST_TEST(ft_y == ft_l, boost::test_tools::tolerance(0.01));
}

BOOST_AUTO_TEST_CASE(liggghts_tangential_force_follows_the_overlap_yade_keeps_it,
                     *boost::unit_test::precondition(granlub::yade::test::YadeInstalled())) {
    const Run& L = liggghts();
    const Run& Y = yade_run();
    const std::size_t stopped = n_slide + n_hold - 10, loaded = n_slide + 2 * n_hold + n_ramp - 10;
    for (const Run* r : {&L, &Y}) {
        BOOST_TEST_REQUIRE(r->fn.size() >= static_cast<std::size_t>(loaded + 5));
        BOOST_TEST(mean(r->fn, loaded - 5, loaded + 5) == 2 * F0, boost::test_tools::tolerance(5e-3));
    }
    const double grow_l = mean(L.ft, loaded - 5, loaded + 5) / mean(L.ft, stopped - 5, stopped + 5);
    const double grow_y = mean(Y.ft, loaded - 5, loaded + 5) / mean(Y.ft, stopped - 5, stopped + 5);
    BOOST_TEST_MESSAGE("F_t after doubling Fn without tangential motion: LIGGGHTS x" << grow_l << ", YADE x" << grow_y);
    BOOST_TEST(grow_l == std::cbrt(2.0), boost::test_tools::tolerance(0.01));  // kt ~ delta^1/2 ~ Fn^1/3
    BOOST_TEST(grow_y == 1.0, boost::test_tools::tolerance(0.01));
}
