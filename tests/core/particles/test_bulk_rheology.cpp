// The core reduction of a wide plane-shear cell (bulk_rheology.h) on synthetic profiles whose answer
// is known: a straight u(y) in the core gives its slope whatever the profile does near the walls; a
// curved core shows in the halves' slopes and in the shear rate's error. And the table
// (bulk_rheology_table.h) from synthetic results on disk.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "case_text.h"
#include "granlub/error.h"
#include "granlub/particles/bulk_rheology.h"
#include "granlub/particles/bulk_rheology_table.h"
#include "granlub/particles/seed_pool.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"

using namespace granlub;
namespace tt = boost::test_tools;

namespace {

constexpr double kD = 0.787e-3, kRho = 2550.0, kU = 3.0, kH = 0.024, kP = 2250.0;

// n stations across the gap; u/U, nu, T/U^2 from the functions, constant standard errors
Profile synthetic(std::size_t n, const std::function<double(double)>& u, double nu, double T_over_U2) {
    std::vector<double> y(n), uu(n), ue(n, 1e-3), v(n, nu), ve(n, 2e-3), T(n, T_over_U2), Te(n, 1e-6);
    for (std::size_t k = 0; k < n; ++k) {
        y[k] = (static_cast<double>(k) + 0.5) / static_cast<double>(n);
        uu[k] = u(y[k]);
    }
    Profile p;
    p.add("y_over_H", y).add("u_over_U", uu).add("u_over_U_stderr", ue).add("solid_fraction", v);
    p.add("solid_fraction_stderr", ve).add("temperature_over_U2", T).add("temperature_over_U2_stderr", Te);
    return p;
}

CoreRun run_of(const Profile& p, double tau_bottom = 900.0, double tau_top = 900.0, double P_top = kP) {
    CoreRun r;
    r.profile = &p;
    r.speed = kU;
    r.gap = kH;
    r.normal_bottom = {kP, 10.0};
    r.normal_top = {P_top, 10.0};
    r.shear_bottom = {tau_bottom, 5.0};
    r.shear_top = {tau_top, 5.0};
    r.z_bulk = Measured{3.9, 0.01};
    return r;
}

// A complete, steady DEM result of point p at dir: u/U = 0.9 - slope y over the gap (the answer's slope, then its
// Delta-t check's in dt_full/), walls 1000 Pa and 400 Pa (the check's 380 Pa), the check's nu-bar change dnu; with a
// seed, the result of that member of a set of seeds.
void write_checked_point(const std::filesystem::path& dir, const Case& c, const OperatingPoint& p, double slope,
                         double check_slope, double dnu, std::optional<std::uint64_t> seed = std::nullopt) {
    std::filesystem::create_directories(dir / kDtCheckDir);
    const auto linear = [](double k) { return [k](double y) { return 0.9 - k * y; }; };
    write_file_atomic(dir / kDtCheckProfile, profile_csv(synthetic(61, linear(check_slope), 0.577, 4e-4)));
    Summary s = make_summary(c, p, "dem", seed);
    s.set("normal_stress_bottom", 1000.0, "Pa", 10.0).set("normal_stress_top", 1000.0, "Pa", 10.0);
    s.set("shear_stress_bottom", 400.0, "Pa", 4.0).set("shear_stress_top", 400.0, "Pa", 4.0);
    s.set("slip_bottom", 0.1, "m/s", 0.0).set("slip_top", 0.1, "m/s", 0.0).set("gap", 5.0e-3, "m", 1e-6);
    s.set("mean_solid_fraction", 0.58, "").set("max_solid_fraction", 0.65, "");
    const nlohmann::json check_outputs = {{"normal_stress_bottom", {{"value", 1000.0}, {"stderr", 10.0}}},
                                          {"normal_stress_top", {{"value", 1000.0}, {"stderr", 10.0}}},
                                          {"shear_stress_bottom", {{"value", 380.0}, {"stderr", 4.0}}},
                                          {"shear_stress_top", {{"value", 380.0}, {"stderr", 4.0}}},
                                          {"gap", {{"value", 5.0e-3}}}};
    s.run = {{"time_step_s", 1e-6},
             {"atoms", 1234},
             {"flow_regime", {{"coordination_number", 3.5}, {"coordination_number_core", 4.1}}},
             {"dt_refinement",
              {{"mean_solid_fraction", {{"change", dnu}}},
               {"shear_stress_bottom", {{"relative_change", 0.05}, {"z", 3.0}}},
               {"shear_stress_top", {{"relative_change", 0.05}, {"z", 3.0}}},
               {"full_step_run",
                {{"time_step_s", 2e-6},
                 {"status", "steady"},
                 {"outputs", check_outputs},
                 {"flow_regime", {{"coordination_number", 3.6}, {"coordination_number_core", 4.3}}}}}}}};
    set_regime(s.run, RegimeStatus::Steady);
    write_result(dir, synthetic(61, linear(slope), 0.58, 4e-4), s);
}

// A load-controlled test case, its first point (U = 1 m/s, 1000 Pa; gap 5 mm, d = 1 mm, rho = 2500) and where the
// DEM's result of that point lies in a fresh results folder.
struct TableCase {
    test::TmpDir tmp;
    Case c;
    OperatingPoint p;
    std::filesystem::path dir;
    explicit TableCase(const std::string& name)
        : tmp(name),
          c(parse_case(test::with("control = \"fill\"", "control = \"load\""), "t.toml", Schema::common())),
          p(c.points.front()),
          dir(result_dir(tmp.path, "dem", p.id)) {}
};

// The one row of a table's text, by its header's names (the comment lines skipped).
std::map<std::string, std::string> only_row(const std::string& csv) {
    std::istringstream in(csv);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line))
        if (line.rfind('#', 0) != 0) lines.push_back(line);
    BOOST_REQUIRE(lines.size() == 2u);
    const auto split = [](const std::string& s) {
        std::vector<std::string> out;
        std::stringstream ss(s);
        for (std::string cell; std::getline(ss, cell, ',');) out.push_back(cell);
        if (!s.empty() && s.back() == ',') out.emplace_back();
        return out;
    };
    const auto h = split(lines[0]), v = split(lines[1]);
    BOOST_REQUIRE(h.size() == v.size());
    std::map<std::string, std::string> m;
    for (std::size_t i = 0; i < h.size(); ++i) m[h[i]] = v[i];
    return m;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_straight_core_gives_its_slope_whatever_the_walls_do) {
    // u/U = 0.9 - 0.8 y/H in the core, and boundary layers (a steep fall) within 0.3 H of each wall
    const auto u = [](double y) {
        const double line = 0.9 - 0.8 * y;
        if (y < 0.3) return line + 0.5 * (0.3 - y);
        if (y > 0.7) return line - 0.5 * (y - 0.7);
        return line;
    };
    const Profile p = synthetic(61, u, 0.58, 4e-4);
    const CoreRheology r = core_rheology(run_of(p), kD, kRho);
    const double gamma = 0.8 * kU / kH;  // 100 1/s
    BOOST_TEST(r.stations == 21u);       // centres in [1/3, 2/3] of 61 slabs
    BOOST_TEST(r.shear_rate.value == gamma, tt::tolerance(1e-9));
    BOOST_TEST(std::abs(r.shear_rate_halves) < 1e-9);
    BOOST_TEST(r.inertial_number.value == gamma * kD / std::sqrt(kP / kRho), tt::tolerance(1e-9));
    BOOST_TEST(r.friction.value == 0.4, tt::tolerance(1e-12));
    BOOST_TEST(r.friction.error > 0.0);
    BOOST_TEST(r.solid_fraction.value == 0.58, tt::tolerance(1e-12));
    BOOST_TEST(r.solid_fraction.error == 2e-3, tt::tolerance(1e-9));  // the correlated bound: no 1/sqrt(n)
    const double Ts = 4e-4 * kU * kU / std::pow(kD * gamma, 2);
    BOOST_TEST(r.temperature_scaled.value == Ts, tt::tolerance(1e-9));
    BOOST_TEST(!r.coordination_core);
    BOOST_TEST(r.coordination->value == 3.9);
    // the slope's error is the propagated one for points on the line: 1e-3 / sqrt(sum (y - ybar)^2)
    double ybar = 0, sxx = 0;
    std::vector<double> yc;
    for (std::size_t k = 0; k < 61; ++k)
        if (const double y = (static_cast<double>(k) + 0.5) / 61.0; y >= 1.0 / 3 && y <= 2.0 / 3) yc.push_back(y), ybar += y;
    ybar /= static_cast<double>(yc.size());
    for (double y : yc) sxx += (y - ybar) * (y - ybar);
    BOOST_TEST(r.shear_rate.error == 1e-3 / std::sqrt(sxx) * kU / kH, tt::tolerance(1e-6));
}

// A continuum's profile has no _stderr columns: it reads with zero errors (exact means, an unweighted line whose
// error is its scatter: 0 on a straight one), and core_run takes the stresses, gap and slips from its outputs.
BOOST_AUTO_TEST_CASE(a_profile_without_errors_reads_exact) {
    std::vector<double> y, u, nu, T;
    for (int k = 0; k <= 40; ++k) {
        y.push_back(k / 40.0), u.push_back(0.9 - 0.8 * y.back()), nu.push_back(0.57), T.push_back(4e-4);
    }
    Profile p;
    p.add("y_over_H", y).add("u_over_U", u).add("solid_fraction", nu).add("temperature_over_U2", T);
    const std::map<std::string, Scalar> outs = {
        {"normal_stress_bottom", {kP, std::nullopt, "Pa"}}, {"normal_stress_top", {kP, std::nullopt, "Pa"}},
        {"shear_stress_bottom", {900.0, std::nullopt, "Pa"}}, {"shear_stress_top", {900.0, std::nullopt, "Pa"}},
        {"slip_bottom", {0.3, std::nullopt, "m/s"}},          {"slip_top", {0.3, std::nullopt, "m/s"}},
        {"gap", {kH, std::nullopt, "m"}}};
    const CoreRun run = core_run(p, kU, outs, nlohmann::json::object(), 0.02, 0.0, 0.0, "continuum summary");
    BOOST_TEST(run.gap == kH);  // the solved gap, not the case's 0.02
    BOOST_TEST(!run.z_core.has_value());
    const CoreRheology r = core_rheology(run, kD, kRho);
    BOOST_TEST(r.shear_rate.value == 0.8 * kU / kH, tt::tolerance(1e-9));
    BOOST_TEST(r.shear_rate.error == 0.0, tt::tolerance(1e-9));
    BOOST_TEST(r.friction.value == 0.4, tt::tolerance(1e-12));
    BOOST_TEST(r.friction.error == 0.0);
    BOOST_TEST(r.solid_fraction.error == 0.0);
    BOOST_TEST(r.walls.has_value());  // both slips given
    auto fixed_gap = outs;  // a solver that keeps the gap fixed writes none: the case's
    fixed_gap.erase("gap");
    BOOST_TEST(core_run(p, kU, fixed_gap, nlohmann::json::object(), 0.02, 0, 0, "x").gap == 0.02);
    BOOST_CHECK_THROW(core_run(p, kU, {}, nlohmann::json::object(), kH, 0, 0, "empty summary"), Error);
}

BOOST_AUTO_TEST_CASE(a_curved_core_shows_in_the_halves_and_the_error) {
    // u/U = 1 - y^2: the slope steepens upward (-2 y), so the upper half shears faster
    const Profile p = synthetic(61, [](double y) { return 1.0 - y * y; }, 0.55, 4e-4);
    const CoreRheology r = core_rheology(run_of(p), kD, kRho);
    BOOST_TEST(r.shear_rate.value == 1.0 * kU / kH, tt::tolerance(1e-6));  // the mean slope over [1/3, 2/3]
    BOOST_TEST(r.shear_rate_halves > 0.25);                                   // -2(0.583) vs -2(0.417): 1/3 of -1
    BOOST_TEST(r.shear_rate_halves < 0.40);
    // the residuals (~1e-3 of u/U) dominate the block errors (1e-3 each): the error grows with them
    const CoreRheology straight = core_rheology(run_of(synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4)), kD, kRho);
    BOOST_TEST(r.shear_rate.error >= straight.shear_rate.error);
}

BOOST_AUTO_TEST_CASE(walls_that_disagree_are_reported_not_hidden) {
    const Profile p = synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    const CoreRheology r = core_rheology(run_of(p, 800.0, 1000.0), kD, kRho);
    BOOST_TEST(r.friction.value == 0.4, tt::tolerance(1e-12));  // the mean of the walls
    BOOST_TEST(r.wall_shear_imbalance == 200.0 / 900.0, tt::tolerance(1e-12));  // over their mean
    BOOST_TEST(r.wall_normal_imbalance == 0.0);
}

BOOST_AUTO_TEST_CASE(walls_pressed_unequally_are_reported_and_averaged) {
    const Profile p = synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    const CoreRheology r = core_rheology(run_of(p, 900.0, 900.0, 2150.0), kD, kRho);
    BOOST_TEST(r.pressure.value == 2200.0, tt::tolerance(1e-12));
    BOOST_TEST(r.wall_normal_imbalance == -100.0 / 2200.0, tt::tolerance(1e-12));
    BOOST_TEST(r.friction.value == 900.0 / 2200.0, tt::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(the_core_z_is_preferred_and_bad_input_fails) {
    const Profile p = synthetic(61, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    CoreRun run = run_of(p);
    run.z_core = Measured{4.2, 0.02};
    const CoreRheology r = core_rheology(run, kD, kRho);
    BOOST_TEST(r.coordination_core);
    BOOST_TEST(r.coordination->value == 4.2);
    // too few stations in the core to fit two halves
    const Profile coarse = synthetic(12, [](double y) { return 1.0 - y; }, 0.55, 4e-4);
    BOOST_CHECK_THROW(core_rheology(run_of(coarse), kD, kRho), Error);
    // a core that does not flow (u constant)
    const Profile plug = synthetic(61, [](double) { return 0.5; }, 0.55, 4e-4);
    BOOST_CHECK_THROW(core_rheology(run_of(plug), kD, kRho), Error);
}

BOOST_AUTO_TEST_CASE(a_line_fit_weights_by_the_errors) {
    // two precise points on y = 2x and one imprecise far off: the fit follows the precise ones
    const LineFit f = fit_line({0.0, 1.0, 2.0}, {0.0, 2.0, 10.0}, {1e-3, 1e-3, 1e3});
    BOOST_TEST(f.slope == 2.0, tt::tolerance(1e-5));
    BOOST_CHECK_THROW(fit_line({0.0, 1.0}, {0.0, 1.0}, {1.0, 1.0}), Error);
    BOOST_CHECK_THROW(fit_line({1.0, 1.0, 1.0}, {0.0, 1.0, 2.0}, {1.0, 1.0, 1.0}), Error);
}

// The table from results on disk: a point with its Delta-t check (the check run's profile sheared
// less, its walls' stresses different) is a row whose *_dt_change are the answer minus the check; a
// point without results is left out and named; a check that moved nu beyond the rule labels the row.
BOOST_AUTO_TEST_CASE(the_table_reads_each_point_and_its_check) {
    namespace fs = std::filesystem;
    const TableCase t_("bulk_table");
    const auto& [tmp, c, p, dir] = t_;
    const auto write = [&](double dnu) { write_checked_point(dir, c, p, 0.8, 0.7, dnu); };
    const auto row = [&]() {
        const BulkTable t = bulk_rheology_table(c, tmp.path, "dem");
        BOOST_TEST(t.rows == 1u);
        BOOST_TEST(t.notes.size() == 1u);  // the second point has no result
        BOOST_TEST(t.csv.find("# point U2.0 left out: no result") != std::string::npos, t.csv);
        BOOST_TEST(t.csv.find(std::string("# format ") + kBulkTableFormat) == 0u);
        const std::map<std::string, std::string> m = only_row(t.csv);
        // the one reader (read_bulk_table) takes what the writer wrote
        const BulkRows back = parse_bulk_table(t.csv, "written");
        BOOST_REQUIRE(back.rows.size() == 1u);
        BOOST_TEST(back.rows[0].point == m.at("point"));
        BOOST_TEST(back.rows[0].core_dt_check == m.at("core_dt_check"));
        BOOST_TEST(back.rows[0].friction.value == std::stod(m.at("mu")));
        BOOST_TEST(back.rows[0].solid_fraction.error == std::stod(m.at("nu_err")));
        BOOST_TEST(back.missing_wall_columns.empty());
        BOOST_TEST(back.rows[0].slip_top.value == std::stod(m.at("slip_top_over_U")));
        BOOST_TEST(back.rows[0].T_wall_bottom.error == std::stod(m.at("T_wall_bottom_err")));
        return m;
    };
    write(0.001);
    auto m = row();
    const double sqrtPrho = std::sqrt(1000.0 / 2500.0), d = 1e-3, H = 5e-3;
    BOOST_TEST(m.at("point") == p.id);
    BOOST_TEST(m.at("status") == "steady");
    BOOST_TEST(m.at("dt_check") == "converged");
    BOOST_TEST(std::stod(m.at("shear_rate_1_s")) == 0.8 / H, tt::tolerance(1e-5));
    BOOST_TEST(std::stod(m.at("I_dt_change")) == 0.1 / H * d / sqrtPrho, tt::tolerance(1e-5));
    BOOST_TEST(std::stod(m.at("mu")) == 0.4, tt::tolerance(1e-5));
    BOOST_TEST(std::stod(m.at("mu_dt_change")) == 0.02, tt::tolerance(1e-4));
    BOOST_TEST(std::stod(m.at("nu_dt_change")) == 0.003, tt::tolerance(1e-3));
    BOOST_TEST(m.at("core_dt_check") == "unconverged:I");  // the core sheared 0.8/0.7 as fast: I moved 14 %
    BOOST_TEST(std::stod(m.at("Z")) == 4.1, tt::tolerance(1e-6));
    BOOST_TEST(std::stod(m.at("Z_dt_change")) == -0.2, tt::tolerance(1e-4));
    BOOST_TEST(m.at("Z_source") == "core");
    BOOST_TEST(m.at("grains") == "1234");
    BOOST_TEST(std::stod(m.at("slip_bottom_over_U")) == 0.1, tt::tolerance(1e-5));  // 0.1 m/s at U = 1 m/s
    BOOST_TEST(std::stod(m.at("slip_bottom_err")) == 0.0);
    BOOST_TEST(std::stod(m.at("T_wall_top_over_U2")) == 4e-4, tt::tolerance(1e-5));  // T/U^2 is 4e-4 everywhere
    BOOST_TEST(std::stod(m.at("T_wall_top_err")) == 1e-6, tt::tolerance(1e-5));
    write(0.006);  // the check moved nu-bar by more than the rule's 0.005: a labelled row, not an answer
    m = row();
    BOOST_TEST(m.at("status") == "dt-unconverged");
    BOOST_TEST(m.at("dt_check") == "unconverged");
}

// A point answered by several seeds: each member's core and its check's are reduced alone and then pooled, so the
// row's error sees how the seeds scatter; the pooled point's own files (seed_pool.h) hold no check to reduce.
BOOST_AUTO_TEST_CASE(a_point_of_several_seeds_pools_each_seeds_core) {
    namespace fs = std::filesystem;
    const TableCase t_("bulk_table_seeds");
    const auto& [tmp, c, p, dir] = t_;
    write_checked_point(dir / "seed-1", c, p, 0.8, 0.7, 0.001, 1);
    write_checked_point(dir / "seed-2", c, p, 1.0, 0.9, 0.001, 2);
    pool_seeds(dir, {1, 2}, result_key(c, "dem"));
    BOOST_REQUIRE(!fs::exists(dir / kDtCheckProfile));  // what the single-seed reading would need
    const BulkTable t = bulk_rheology_table(c, tmp.path, "dem");
    BOOST_TEST(t.csv.find("# point U1.0: the cores of seeds 1, 2 each reduced") != std::string::npos, t.csv);
    const auto m = only_row(t.csv);
    const double H = 5e-3, I_per_slope = 1e-3 / H / std::sqrt(1000.0 / 2500.0);  // I of a core slope of 1 (u/U per y/H)
    BOOST_TEST(m.at("seeds") == "2");
    BOOST_TEST(std::stod(m.at("I")) == 0.9 * I_per_slope, tt::tolerance(1e-5));
    // two seeds 0.2 apart in slope: their standard error, 0.1, is far above their own (1e-3 per station)
    BOOST_TEST(std::stod(m.at("I_err")) == 0.1 * I_per_slope, tt::tolerance(1e-3));
    BOOST_TEST(std::stod(m.at("I_dt_change")) == 0.1 * I_per_slope, tt::tolerance(1e-5));
    // each seed's I moved 11-13 % with the step, but by 0.7 of the combined errors the seeds' scatter sets: converged
    BOOST_TEST(m.at("core_dt_check") == "converged");
    BOOST_TEST(m.at("status") == "steady");
    BOOST_TEST(m.at("dt_check") == "converged");
    BOOST_TEST(std::stod(m.at("mu")) == 0.4, tt::tolerance(1e-5));
    BOOST_TEST(std::stod(m.at("mu_err")) > 0.0);  // the members' own errors combined when they agree
    // a set of three with one member done: a pool of one, read through its member, labelled incomplete (no answer)
    fs::remove_all(dir / "seed-2");
    pool_seeds(dir, {1, 2, 3}, result_key(c, "dem"));
    const auto one = only_row(bulk_rheology_table(c, tmp.path, "dem").csv);
    BOOST_TEST(one.at("seeds") == "1");
    BOOST_TEST(one.at("status") == "incomplete");
    BOOST_TEST(std::stod(one.at("I")) == 0.8 * I_per_slope, tt::tolerance(1e-5));
    BOOST_TEST(one.at("core_dt_check") == "unconverged:I");  // seed 1 alone: 0.8 against 0.7, its own errors
}

// The pooled error: the larger of the seeds' scatter and the members' own errors combined.
BOOST_AUTO_TEST_CASE(a_pooled_core_keeps_the_larger_error) {
    CoreRheology a, b;
    a.stations = b.stations = 20;
    a.friction = {0.40, 0.010};
    b.friction = {0.41, 0.010};  // scatter 0.005 < own errors combined 0.0071
    a.inertial_number = {0.03, 0.0005};
    b.inertial_number = {0.05, 0.0005};  // scatter 0.01 > own 0.00035
    const CoreRheology pooled = pool_core_rheology({a, b});
    BOOST_TEST(pooled.friction.value == 0.405, tt::tolerance(1e-12));
    BOOST_TEST(pooled.friction.error == std::sqrt(2.0) * 0.01 / 2, tt::tolerance(1e-12));
    BOOST_TEST(pooled.inertial_number.value == 0.04, tt::tolerance(1e-12));
    BOOST_TEST(pooled.inertial_number.error == 0.01, tt::tolerance(1e-12));
    BOOST_TEST(!pooled.coordination.has_value());
    b.stations = 19;
    BOOST_CHECK_THROW(pool_core_rheology({a, b}), Error);
    BOOST_CHECK_THROW(pool_core_rheology({}), Error);
}

// The walls' layers: the mean T/U^2 over the stations within 2 d of each wall's bump tops (d_w/2 inside the planes),
// and the slips over U, from a profile whose T steps at known heights: a station outside a band would change the mean.
BOOST_AUTO_TEST_CASE(the_walls_layers_are_the_stations_within_two_diameters_of_the_bump_tops) {
    // H = 24 mm = 30.5 d, bumps of diameter d: the floor's band y/H in [0.5 d, 2.5 d]/H = [0.0164, 0.0820], the
    // top's [0.9180, 0.9836]; T/U^2 = 1e-3 (floor's band), 2e-3 (top's band), 5e-4 elsewhere, with errors 1e-5 /
    // 3e-5 / 0
    const double dw = kD, lo = 0.5 * dw / kH, hi = 2.5 * dw / kH;
    Profile p = synthetic(61, [](double y) { return 0.9 - 0.8 * y; }, 0.58, 5e-4);
    auto& y = p.columns[0];
    std::vector<double> T(y.size(), 5e-4), Te(y.size(), 0.0);
    std::size_t nb = 0, nt = 0;
    for (std::size_t k = 0; k < y.size(); ++k) {
        if (y[k] >= lo && y[k] <= hi) T[k] = 1e-3, Te[k] = 1e-5, ++nb;
        if (y[k] >= 1 - hi && y[k] <= 1 - lo) T[k] = 2e-3, Te[k] = 3e-5, ++nt;
    }
    BOOST_REQUIRE(nb == 4u);  // stations 1..4 of 61 (centres 0.0246 .. 0.0738)
    BOOST_REQUIRE(nt == 4u);
    Profile q;
    q.add("y_over_H", y).add("temperature_over_U2", T).add("temperature_over_U2_stderr", Te);
    const NearWallTemperature w = near_wall_temperature(q, kH, kD, 0.5 * dw, 0.5 * dw);
    BOOST_TEST(w.stations_bottom == 4u);
    BOOST_TEST(w.stations_top == 4u);
    BOOST_TEST(w.bottom.value == 1e-3, tt::tolerance(1e-12));
    BOOST_TEST(w.bottom.error == 1e-5, tt::tolerance(1e-12));
    BOOST_TEST(w.top.value == 2e-3, tt::tolerance(1e-12));
    BOOST_TEST(w.top.error == 3e-5, tt::tolerance(1e-12));
    // plane walls (no protrusion): the floor's band starts at its plane, [0, 2 d]/H = [0, 0.0656]: stations 0..3,
    // station 0 (T/U^2 5e-4) in, station 4 (0.0738) out
    const NearWallTemperature plane = near_wall_temperature(q, kH, kD, 0, 0);
    BOOST_TEST(plane.stations_bottom == 4u);
    BOOST_TEST(plane.bottom.value == (5e-4 + 3 * 1e-3) / 4, tt::tolerance(1e-12));
    // a profile without an error column (the continuum's): errors 0
    Profile r;
    r.add("y_over_H", y).add("temperature_over_U2", T);
    BOOST_TEST(near_wall_temperature(r, kH, kD, 0.5 * dw, 0.5 * dw).top.error == 0.0);
    // a continuum's nodes: the band's mean of the lines between them. T/U^2 = a + b y/H is linear: the mean is its
    // value at the band's middle, wherever the nodes lie (here 2 in each band)
    const std::vector<double> yn = {0, 0.03, 0.06, 0.1, 0.3, 0.5, 0.7, 0.9, 0.94, 0.97, 1.0};
    std::vector<double> Tn;
    for (double v : yn) Tn.push_back(1e-3 + 2e-3 * v);
    Profile lin;
    lin.add("y_over_H", yn).add("temperature_over_U2", Tn);
    const NearWallTemperature li = near_wall_temperature(lin, kH, kD, 0.5 * dw, 0.5 * dw, BandMean::Interpolated);
    BOOST_TEST(li.bottom.value == 1e-3 + 2e-3 * 0.5 * (lo + hi), tt::tolerance(1e-12));
    BOOST_TEST(li.bottom.error == 0.0);
    BOOST_TEST(li.top.value == 1e-3 + 2e-3 * (1 - 0.5 * (lo + hi)), tt::tolerance(1e-12));
    // the stations' mean of the same nodes is not that (it is the mean of the two nodes inside)
    BOOST_TEST(std::abs(near_wall_temperature(lin, kH, kD, 0.5 * dw, 0.5 * dw).bottom.value - li.bottom.value) > 1e-6);
    // too coarse a profile for the band: named
    Profile coarse;
    coarse.add("y_over_H", {0.25, 0.75}).add("temperature_over_U2", {1e-3, 1e-3});
    BOOST_CHECK_EXCEPTION(near_wall_temperature(coarse, kH, kD, 0.5 * dw, 0.5 * dw), Error, [](const Error& e) {
        return std::string(e.what()).find("no profile station lies in y/H [0.0164, 0.0820]") != std::string::npos;
    });
    // the reduction: with both slips recorded it gives the layers, over U; without, none
    p.columns[5] = T, p.columns[6] = Te;  // temperature_over_U2 and its stderr (synthetic()'s column order)
    CoreRun run = run_of(p);
    run.protrusion_bottom = run.protrusion_top = 0.5 * dw;
    BOOST_TEST(!core_rheology(run, kD, kRho).walls.has_value());
    run.slip_bottom = Measured{0.3, 0.006};
    run.slip_top = Measured{0.6, 0.003};
    const CoreRheology c = core_rheology(run, kD, kRho);
    BOOST_REQUIRE(c.walls.has_value());
    BOOST_TEST(c.walls->slip_bottom.value == 0.1, tt::tolerance(1e-12));  // 0.3 / U = 3 m/s
    BOOST_TEST(c.walls->slip_bottom.error == 0.002, tt::tolerance(1e-12));
    BOOST_TEST(c.walls->slip_top.value == 0.2, tt::tolerance(1e-12));
    BOOST_TEST(c.walls->T_bottom.value == 1e-3, tt::tolerance(1e-12));
    BOOST_TEST(c.walls->T_top.error == 3e-5, tt::tolerance(1e-12));
}

// The core's Delta-t rule: nu by 0.005; mu and I by 7 %, unless within 2 combined standard errors.
BOOST_AUTO_TEST_CASE(the_core_is_judged_by_the_pipelines_thresholds) {
    CoreRheology a, b;
    a.inertial_number = {0.100, 0.001}, b.inertial_number = {0.100, 0.001};
    a.friction = {0.40, 0.01}, b.friction = {0.40, 0.01};
    a.solid_fraction = {0.580, 0.002}, b.solid_fraction = {0.580, 0.002};
    BOOST_TEST(core_dt_unconverged(a, b).empty());
    b.inertial_number = {0.110, 0.001};  // 9 %, 7 errors: moved
    b.friction = {0.44, 0.02};           // 9 %, but within 2 combined errors (0.045): not moved
    b.solid_fraction = {0.586, 0.002};   // 0.006 > 0.005: moved
    const auto moved = core_dt_unconverged(a, b);
    BOOST_TEST(moved == (std::vector<std::string>{"I", "nu"}), tt::per_element());
}
