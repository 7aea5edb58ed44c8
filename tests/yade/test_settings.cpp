// [yade] settings: defaults, derived steps, and bad inputs rejected with the key named.
#define BOOST_TEST_MODULE yade_settings
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "granlub/error.h"
#include "granlub/yade/driver.h"
#include "granlub/yade/settings.h"
#include "yade_test_case.h"

using namespace granlub;
using namespace granlub::yade;
using granlub::yade::test::tiny_case;
using granlub::yade::test::tiny_case_edits;

namespace {
template <class F>
std::string error_of(F&& f) {
    try {
        f();
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }
}  // namespace

BOOST_AUTO_TEST_CASE(viscel_time_step_and_run_length) {
    const Case c = tiny_case();
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(std::string(s.law->name) == "viscel");
    BOOST_TEST(s.time_step == 1e-5 / 20, boost::test_tools::tolerance(1e-12));
    // time = 1.5e-3 s, 50-step wall blocks, 30 snapshots: 3000 steps, a snapshot every 100
    BOOST_TEST(s.steps == 3000);
    BOOST_TEST(s.sample_every == 50);
    BOOST_TEST(s.snapshot_every == 100);
    BOOST_TEST(s.steps % s.sample_every == 0);
    BOOST_TEST(s.steps % s.snapshot_every == 0);
    BOOST_TEST(s.insertion.wall_speed == 2.0);
    BOOST_TEST(s.insertion.seed == 1u);
}

BOOST_AUTO_TEST_CASE(full_run_and_seed_override) {
    const Case c = tiny_case("", "", "time_full = 3e-3\n");
    RunOptions o;
    o.full = true;
    o.seed = 77;
    const Settings s = resolve_settings(c, c.points.at(0), o);
    BOOST_TEST(s.steps == 6000);
    BOOST_TEST(s.insertion.seed == 77u);
}

BOOST_AUTO_TEST_CASE(hertz_time_step_is_a_rayleigh_fraction) {
    const Case c = tiny_case("", "", "model = \"hertz\"\n");
    // t_R = pi r sqrt(rho/G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)), glass
    const double G = 63e9 / (2 * 1.23);
    const double tr = std::numbers::pi * 0.3935e-3 * std::sqrt(2550.0 / G) / (0.1631 * 0.23 + 0.8766);
    BOOST_TEST(c.grains.rayleigh_time() == tr, boost::test_tools::tolerance(1e-12));
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(std::string(s.law->name) == "hertz");
    BOOST_TEST(s.time_step == 0.15 * tr, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(too_large_time_step_is_rejected) {
    const Case c = tiny_case("", "", "time_step = 2e-6\n");
    const std::string e = error_of([&] { resolve_settings(c, c.points.at(0), RunOptions{}); });
    BOOST_TEST(has(e, "[yade] time_step"));
    BOOST_TEST(has(e, "contact_time"));
    BOOST_TEST(has(e, "case.toml"));
}

BOOST_AUTO_TEST_CASE(too_short_run_is_rejected) {
    const Case c = tiny_case("time = 1.5e-3", "time = 1e-4");
    const std::string e = error_of([&] { resolve_settings(c, c.points.at(0), RunOptions{}); });
    BOOST_TEST(has(e, "[yade] time"));
    BOOST_TEST(has(e, "blocks"));
}

// control = "load": the servo of granlub dem, its keys declared once (granlub/particles/servo.h) in [yade].
const char* kFill = "control = \"fill\"";
const char* kLoad = "control = \"load\"\nnormal_stress = 5e3";

BOOST_AUTO_TEST_CASE(load_control_settings) {
    const Case c = tiny_case(kFill, kLoad, "servo_every = 100\n");
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(s.servo.load);
    BOOST_TEST(s.servo.target_stress == 5e3);
    BOOST_TEST(s.servo.servo_every == 100);
    BOOST_TEST(s.servo.servo_gain == 0.05);
    BOOST_TEST(s.servo.servo_max_error == kServoMaxError);
    BOOST_TEST(s.servo.gap_max == 1.5 * c.cell.gap);
    BOOST_TEST(s.servo.gap_min == 0.5 * c.cell.gap / kClosestPacking);  // the point's solid_fraction
    BOOST_TEST(s.servo.insert_fill_key == "[operating] solid_fraction");
    BOOST_TEST(s.steps == 3000);  // 30 plate updates
    // servo_every = 0 is sample_every; without solid_fraction the grains fill to fill_for_load
    const Case d = tiny_case("control = \"fill\"\nsolid_fraction = 0.5", kLoad);
    const Settings sd = resolve_settings(d, d.points.at(0), RunOptions{});
    BOOST_TEST(sd.servo.servo_every == 50);
    BOOST_TEST(sd.servo.insert_fill == 0.55);
    BOOST_TEST(sd.servo.insert_fill_key == "[yade] fill_for_load (default)");
    // the driver gets the servo, lengths in m
    const ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    const auto j = couette_params(c, c.points.at(0), s, box, "/tmp/particles.csv");
    BOOST_TEST(j.at("servo").at("every").get<long long>() == 100);
    // the window servo's step: servo_gain d capped at one grain-plate overlap at the load (issue 50)
    BOOST_TEST(j.at("servo").at("step").get<double>() == s.plate_gain * c.grains.diameter);
    BOOST_TEST(s.plate_gain < 0.05);
    BOOST_TEST(j.at("servo").at("gap_max").get<double>() == s.servo.gap_max);
    const Case f = tiny_case();
    BOOST_TEST(!couette_params(f, f.points.at(0), resolve_settings(f, f.points.at(0), RunOptions{}), box, "/tmp/p.csv")
                    .contains("servo"));
}

// servo_plate = "weight": the driver gets the plate kind and its mass ratio; start = "warm" is
// a setting (the state itself is checked when the point runs).
BOOST_AUTO_TEST_CASE(weight_plate_and_warm_start_settings) {
    const Case c = tiny_case(kFill, kLoad, "servo_plate = \"weight\"\nplate_mass = 2.5\nstart = \"warm\"\n");
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(s.servo.weight_plate);
    BOOST_TEST(s.warm_start);
    BOOST_TEST(s.servo.plate_mass == 2.5);
    const ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    const auto j = couette_params(c, c.points.at(0), s, box, "/tmp/particles.csv");
    BOOST_TEST(j.at("servo").at("plate").get<std::string>() == "weight");
    BOOST_TEST(j.at("servo").at("plate_mass_ratio").get<double>() == 2.5);
    const Case d = tiny_case(kFill, kLoad);  // the default: a weight plate (issue 50)
    const Settings sd = resolve_settings(d, d.points.at(0), RunOptions{});
    BOOST_TEST(sd.servo.weight_plate);
    BOOST_TEST(!sd.warm_start);
    const Case w = tiny_case(kFill, kLoad, "servo_plate = \"window\"\n");
    const Settings sw = resolve_settings(w, w.points.at(0), RunOptions{});
    BOOST_TEST(!sw.servo.weight_plate);
    BOOST_TEST(couette_params(w, w.points.at(0), sw, box, "/tmp/p.csv").at("servo").at("plate").get<std::string>() ==
               "window");
    BOOST_TEST(has(error_of([] { tiny_case("", "", "servo_plate = \"spring\"\n"); }), "servo_plate"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "plate_mass = 0\n"); }), "plate_mass"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "start = \"hot\"\n"); }), "start"));
}

// The window servo (issue 50): its gain capped from the contact stiffness as granlub dem's (one
// grain-plate overlap at the load per unit error, servo.h), refused by name where a window is
// shorter than the contacts' response (it would ram); a weight plate may carry a rough top's bumps.
BOOST_AUTO_TEST_CASE(window_servo_capped_and_refused_where_it_would_ram) {
    const Case c = tiny_case(kFill, kLoad);
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    // viscel, t_c = 10 us, e = 0.9 at a wall of 1000 kg: k_n = m* (pi^2 + ln^2 e) / t_c^2, overlap P d^2 / k_n
    const double m = c.grains.mass(), ms = m * 1e3 / (m + 1e3), ln = std::log(0.9), d = c.grains.diameter;
    const double kn = ms * (std::numbers::pi * std::numbers::pi + ln * ln) / 1e-10;
    BOOST_TEST(s.plate_overlap == 5e3 * d * d / kn, boost::test_tools::tolerance(1e-9));
    BOOST_TEST(s.plate_gain == s.plate_overlap / d, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.plate_gain < 2e-3 * s.servo.servo_gain);  // 0.05 d would be ~800 overlaps
    const ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    BOOST_TEST(couette_params(c, c.points.at(0), s, box, "/tmp/p.csv").at("servo").at("step").get<double>() ==
               s.plate_gain * d, boost::test_tools::tolerance(1e-12));
    // Hertz: granlub dem's cap, the same function
    const Case h = tiny_case(kFill, kLoad, "model = \"hertz\"\n");
    const Settings sh = resolve_settings(h, h.points.at(0), RunOptions{});
    BOOST_TEST(sh.plate_overlap == hertz_plate_overlap(h.grains, 5e3));
    // windows of 10 steps of 0.5 us are shorter than the contacts' response (~t_c = 20 steps)
    const std::string e = error_of([] {
        const Case r = tiny_case_edits({{kFill, kLoad}, {"sample_every = 50", "sample_every = 10"}},
                                       "servo_every = 10\nservo_plate = \"window\"\n");
        resolve_settings(r, r.points.at(0), RunOptions{});
    });
    BOOST_TEST_MESSAGE(e);
    for (const char* w : {"[yade] servo_every", "ram", "allowed: servo_every >= 20", "servo_plate = \"weight\""})
        BOOST_TEST(has(e, w), w << " in: " << e);
    // ... which a weight plate does not have
    const Case wt = tiny_case_edits({{kFill, kLoad}, {"sample_every = 50", "sample_every = 10"}},
                                    "servo_every = 10\nservo_plate = \"weight\"\n");
    BOOST_TEST(resolve_settings(wt, wt.points.at(0), RunOptions{}).servo.weight_plate);
    // a weight plate on a rough top: allowed, the bumps go to the driver
    const Case rough = tiny_case_edits({{kFill, kLoad}, {"roughness = 0.5", "roughness = 0.5\nsurface = \"bumps\""}},
                                       "servo_plate = \"weight\"\nservo_max_gap = 1.75\n");
    const Settings sr = resolve_settings(rough, rough.points.at(0), RunOptions{});
    BOOST_TEST(sr.servo.weight_plate);
    BOOST_TEST(sr.bumps_top.has_value());
}

// neighbor_skin reaches the driver's collider (its verletDist in smallest radii, the same number); outside
// (0, 5] it is refused by name; the old names verlet_distance and dt still read, with a warning each.
BOOST_AUTO_TEST_CASE(collider_neighbor_skin) {
    const ParticleBox box{0.03, 0.004, 0.019, false};
    const Case d = tiny_case();
    const Settings sd = resolve_settings(d, d.points.at(0), RunOptions{});
    BOOST_TEST(couette_params(d, d.points.at(0), sd, box, "/tmp/p.csv").at("run").at("verlet_distance").get<double>() ==
               0.2);
    const Case c = tiny_case("", "", "neighbor_skin = 0.5\n");
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(couette_params(c, c.points.at(0), s, box, "/tmp/p.csv").at("run").at("verlet_distance").get<double>() ==
               0.5);
    BOOST_TEST(has(error_of([] { tiny_case("", "", "neighbor_skin = 0\n"); }), "neighbor_skin"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "neighbor_skin = 6\n"); }), "neighbor_skin"));
    const Case old = tiny_case("", "", "verlet_distance = 0.5\ndt = 5e-7\n");
    const Settings so = resolve_settings(old, old.points.at(0), RunOptions{});
    BOOST_TEST(so.neighbor_skin == 0.5);
    BOOST_TEST(so.time_step == 5e-7);
    BOOST_REQUIRE_EQUAL(old.warnings.size(), 2u);
    BOOST_TEST(has(old.warnings[0] + old.warnings[1], "[yade] verlet_distance is the old name of neighbor_skin"));
    BOOST_TEST(has(old.warnings[0] + old.warnings[1], "[yade] dt is the old name of time_step"));
}

BOOST_AUTO_TEST_CASE(load_control_runs_whole_servo_windows_and_snapshot_intervals) {
    // 1.52e-3 s: 61 blocks of 50 steps = 3050 steps, rounded up to 31 windows of 100
    const Case c = tiny_case_edits({{kFill, kLoad}, {"time = 1.5e-3", "time = 1.52e-3"}}, "servo_every = 100\n");
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(s.steps == 3100);
    BOOST_TEST(s.snapshot_every == 100);
    // 46 windows and 4 snapshots: a snapshot every 11 windows, the run rounded up to 55 windows
    const Case d = tiny_case_edits(
        {{kFill, kLoad}, {"time = 1.5e-3", "time = 2.3e-3"}, {"snapshots = 30", "snapshots = 4"}}, "servo_every = 100\n");
    const Settings sd = resolve_settings(d, d.points.at(0), RunOptions{});
    BOOST_TEST(sd.snapshot_every == 1100);
    BOOST_TEST(sd.steps == 5500);
    BOOST_TEST(sd.steps % sd.servo.servo_every == 0);
}

BOOST_AUTO_TEST_CASE(bad_servo_settings_give_clear_errors) {
    auto error = [](const std::string& extra) {
        return error_of([&] {
            const Case c = tiny_case(kFill, kLoad, extra);
            resolve_settings(c, c.points.at(0), RunOptions{});
        });
    };
    for (const auto& [extra, words] : std::vector<std::pair<std::string, std::vector<std::string>>>{
             {"servo_gain = 0.5\n", {"case.toml", "[yade] servo_gain", "0.5", "allowed", "(0, 0.1]"}},
             {"servo_gain = 0.0\n", {"[yade] servo_gain"}},
             {"servo_max_gap = 5.0\n", {"[yade] servo_max_gap", "5", "allowed", "(1, 4]"}},
             {"fill_for_load = 0.8\n", {"[yade] fill_for_load", "0.8"}},
             {"servo_every = 75\n", {"case.toml", "[yade] servo_every", "75", "multiple of sample_every = 50"}},
             {"servo_every = 1000\n", {"[yade] servo_every", "3 plate updates", "at least 20"}}}) {
        const std::string e = error(extra);
        BOOST_TEST_MESSAGE(e);
        for (const auto& w : words) BOOST_TEST(has(e, w), w << " in: " << e);
    }
}

BOOST_AUTO_TEST_CASE(bad_keys_are_rejected_by_the_schema) {
    BOOST_TEST(has(error_of([] { tiny_case("", "", "model = \"dem\"\n"); }), "model"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "tangential_restitution = 0\n"); }), "tangential_restitution"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "snapshots = 1\n"); }), "snapshots"));
    BOOST_TEST(has(error_of([] { tiny_case("", "", "contact_tme = 1e-5\n"); }), "contact_tme"));
}

BOOST_AUTO_TEST_CASE(parameter_file_carries_the_case) {
    const Case c = tiny_case("[walls]\nrestitution = 0.9\nfriction = 0.5\nroughness = 0.5\n",
                             "[walls]\nrestitution = 0.7\nfriction = 0.5\nroughness = 0.5\n[walls.top]\nrestitution = 0.8\n");
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    const auto j = couette_params(c, p, s, box, "/tmp/particles.csv");
    BOOST_TEST(j.at("format").get<std::string>() == kParamsFormat);
    BOOST_TEST(j.at("task").get<std::string>() == "couette");
    BOOST_TEST(j.at("model").get<std::string>() == "viscel");
    BOOST_TEST(j.at("materials").at("grain").at("restitution").get<double>() == 0.9);
    BOOST_TEST(j.at("materials").at("bottom").at("restitution").get<double>() == 0.7);
    BOOST_TEST(j.at("materials").at("top").at("restitution").get<double>() == 0.8);
    // side walls slide with the bottom wall and take its material, as in granlub dem
    BOOST_TEST(j.at("materials").at("side").at("restitution").get<double>() == 0.7);
    BOOST_TEST(j.at("wall_speed").get<double>() == 2.0);
    BOOST_TEST(j.at("gravity").get<double>() == 9.81);
    BOOST_TEST(j.at("annulus_radius").get<double>() == 0.0762);
    BOOST_TEST(j.at("cell").at("width").get<double>() == c.cell.width);
    BOOST_TEST(j.at("run").at("steps").get<long long>() == s.steps);
    BOOST_TEST(j.at("contact").at("dt").get<double>() == s.time_step);
    const auto k = collision_params(c, p, s, 1.5);
    BOOST_TEST(k.at("task").get<std::string>() == "collision");
    BOOST_TEST(k.at("impact_speed").get<double>() == 1.5);
}

// A run from a state of time t (a warm start from granlub dem's, a continued piece) gets the floor's
// and the side walls' bumps moved U t along from their layout, wrapped into the period (wall_bumps.h
// moved_bumps), the top's at their layout, and start_time, from which the driver's final state
// counts on (particles.h ParticleState::time); a cold start gets the layout and 0.
BOOST_AUTO_TEST_CASE(a_start_from_a_state_moves_the_floors_bumps) {
    const Case c = tiny_case("roughness = 0.5", "roughness = 0.5\nsurface = \"bumps\"\nsides = \"as_bottom\"");
    const OperatingPoint& p = c.points.at(0);
    const Settings s = resolve_settings(c, p, RunOptions{});
    BOOST_TEST_REQUIRE((s.bumps_bottom && s.bumps_top && s.bumps_side));
    const ParticleBox box{c.cell.length, c.cell.gap, c.cell.width, false};
    const double t = 0.30028, L = box.length;  // U t = 76.3 periods of the cell
    const auto cold = couette_params(c, p, s, box, "/tmp/p.csv");
    const auto warm = couette_params(c, p, s, box, "/tmp/p.csv", kStartOverlap, t);
    BOOST_TEST(cold.at("start_time").get<double>() == 0.0);
    BOOST_TEST(warm.at("start_time").get<double>() == t);
    const auto x0 = cold.at("bumps").at("bottom").at("x").get<std::vector<double>>();
    const auto x = warm.at("bumps").at("bottom").at("x").get<std::vector<double>>();
    BOOST_TEST(x0 == s.bumps_bottom->x, boost::test_tools::per_element());
    BOOST_TEST_REQUIRE(x.size() == x0.size());
    for (std::size_t k = 0; k < x.size(); ++k) {
        BOOST_TEST(x[k] == std::fmod(x0[k] + p.speed * t, L), boost::test_tools::tolerance(1e-12));
        BOOST_TEST((x[k] >= 0.0 && x[k] < L));
    }
    BOOST_TEST(warm.at("bumps").at("bottom").at("z") == cold.at("bumps").at("bottom").at("z"));
    BOOST_TEST(warm.at("bumps").at("sides").at("x").at(0).get<double>() ==
                   std::fmod(s.bumps_side->x[0] + p.speed * t, L), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(warm.at("bumps").at("top") == cold.at("bumps").at("top"));
}

// Both engines start from [particles] (declared once in core), not from each other's sections.
BOOST_AUTO_TEST_CASE(initial_grains_come_from_the_shared_particles_section) {
    const Case c = tiny_case("[yade]", "[particles]\nseed = 5\nvelocity_noise = 0.2\n\n[yade]");
    const Settings s = resolve_settings(c, c.points.at(0), RunOptions{});
    BOOST_TEST(s.insertion.seed == 5u);
    BOOST_TEST(s.insertion.velocity_noise == 0.2);
    RunOptions o;
    o.seed = 9;
    BOOST_TEST(resolve_settings(c, c.points.at(0), o).insertion.seed == 9u);
    // the keys are no longer the engines' own
    BOOST_TEST(has(error_of([] { tiny_case("", "", "seed = 5\n"); }), "seed"));
    // a change in [particles] makes the particle results stale, not those of other solvers
    const Case d = tiny_case();
    BOOST_TEST(c.inputs_hash("yade") != d.inputs_hash("yade"));
    BOOST_TEST(c.inputs_hash("continuum") == d.inputs_hash("continuum"));
    BOOST_TEST(c.inputs("yade").at("[particles] seed") == "5");
}
