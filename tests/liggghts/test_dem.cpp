// `granlub dem` end to end on a small shear cell (a few hundred grains, a few thousand steps):
// complete result files with finite stresses, momentum balance across the gap, determinism,
// the Hertz reference, 2 MPI ranks, clear errors for bad inputs, and the readers of LIGGGHTS'
// line-oriented outputs.
#define BOOST_TEST_MODULE liggghts_dem
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <regex>
#include <utility>

#include <fmt/format.h>

#include "granlub/case/case.h"
#include "granlub/dem/command.h"
#include "granlub/error.h"
#include "granlub/particles/particles.h"
#include "granlub/results/run_status.h"
#include "granlub/results/results.h"
#include "granlub/run/sweep.h"
#include "deck.h"
#include "outputs.h"
#include "run_driver.h"
#include "settings.h"
#include "tiny_cell.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

const std::string kCase = test::tiny_cell("tiny", "", "time = 0.02\nsample_every = 20\nsnapshots = 10\nstations = 6\n");

Schema schema() { return test::dem_schema(); }
using test::edit;
fs::path scratch(const std::string& name) { return test::scratch("liggghts_dem", name); }

struct Run {
    int code = 1;
    fs::path dir;
};

Run run(const std::string& text, const std::string& name, int np = 1) {
    const Case c = parse_case(text, "tiny.toml", schema());
    RunOptions o;
    o.results_root = scratch(name);
    o.np = np;
    Run r;
    r.code = dem::run(c, o);
    r.dir = result_dir(o.results_root, "dem", c.points.front().id);
    return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(short_shear_cell_writes_complete_finite_results) {
    const Run r = run(kCase, "basic");
    BOOST_TEST_REQUIRE(r.code == 0);
    const Case c = parse_case(kCase, "tiny.toml", schema());
    BOOST_TEST((result_status(r.dir, c.inputs_hash("dem")).state == ResultState::Complete));
    const Summary s = read_summary(r.dir / "summary.json");
    for (const char* name : kStandardOutputs) {
        BOOST_TEST_REQUIRE(s.outputs.count(name) == 1u, name);
        BOOST_TEST(std::isfinite(s.value(name)));
    }
    for (const char* name : {"normal_stress_bottom", "normal_stress_top", "shear_stress_bottom", "shear_stress_top"}) {
        BOOST_TEST(s.value(name) > 0.0, name);
        BOOST_TEST(s.outputs.at(name).stderr_.value_or(-1) > 0.0, name);
    }
    BOOST_TEST(std::abs(s.value("mean_solid_fraction") - 0.4) < 2e-3);
    const double dt = s.run.at("time_step_s").get<double>();
    BOOST_TEST(s.run.at("steps").get<long>() == std::lround(std::ceil(0.02 / dt - 1e-9)));
    BOOST_TEST(s.run.at("atom_steps_per_s").get<double>() > 0.0);
    const Profile p = read_profile(r.dir / "profile.csv");
    BOOST_TEST(p.rows() == 6u);
    for (const char* col : kProfileColumns) BOOST_TEST(p.has(col), col);
    BOOST_TEST(p.has("u_over_U_stderr"));
    // sheared: faster near the moving wall than near the fixed one
    BOOST_TEST(p.column("u_over_U").front() > p.column("u_over_U").back());
    // the readable deck and the initial configuration stay for reruns
    std::ifstream deck(r.dir / "in.granlub");
    std::stringstream ss;
    ss << deck.rdbuf();
    BOOST_TEST(ss.str().find("pair_style      gran model impulse tangential impulse") != std::string::npos);
    // the case's single pass is written out on the pair style and every wall (the models' default is
    // iterate on), and no solver
    const std::string text = ss.str();
    const std::regex iterate_off(" iterate off\n");
    BOOST_TEST(std::distance(std::sregex_iterator(text.begin(), text.end(), iterate_off), std::sregex_iterator()) == 5);
    BOOST_TEST(text.find("impulse/solve") == std::string::npos);
    BOOST_TEST(fs::exists(r.dir.parent_path().parent_path() / "initial" / "U1.0" / "particles.csv"));
    BOOST_TEST(!fs::exists(r.dir / "snapshots.txt"));
}

BOOST_AUTO_TEST_CASE(wall_stresses_carry_the_weight_of_the_grains) {
    // periodic across z (no side walls): in the mean, bottom minus top normal force = weight
    const std::string text = edit(edit(kCase, "width = 6.0e-3", "width = 0.0"), "time = 0.02", "time = 0.06");
    const Run r = run(edit(text, "\\[dem\\]", "[particles]\nperiodic_depth = 6.0e-3\n[dem]"), "weight");
    BOOST_TEST_REQUIRE(r.code == 0);
    const Summary s = read_summary(r.dir / "summary.json");
    const double n = static_cast<double>(s.run.at("atoms").get<long>());
    const double m = 2500.0 * std::numbers::pi / 6.0 * 1e-9;
    const double weight_stress = n * m * 9.81 / (8e-3 * 6e-3);
    const double diff = s.value("normal_stress_bottom") - s.value("normal_stress_top");
    const double se = std::hypot(*s.outputs.at("normal_stress_bottom").stderr_, *s.outputs.at("normal_stress_top").stderr_);
    BOOST_TEST_MESSAGE("weight " << weight_stress << " Pa, P_bot - P_top " << diff << " +- " << se);
    BOOST_TEST(std::abs(diff - weight_stress) < 4.0 * se + 0.05 * weight_stress);
}

BOOST_AUTO_TEST_CASE(same_seed_same_numbers) {
    const Run a = run(kCase, "seed_a");
    const Run b = run(kCase, "seed_b");
    BOOST_TEST_REQUIRE(a.code == 0);
    BOOST_TEST_REQUIRE(b.code == 0);
    const Summary sa = read_summary(a.dir / "summary.json"), sb = read_summary(b.dir / "summary.json");
    BOOST_TEST(sa.value("normal_stress_top") == sb.value("normal_stress_top"));
    BOOST_TEST(sa.value("shear_stress_bottom") == sb.value("shear_stress_bottom"));
}

// How many points run at once: a last round that would leave cores idle is folded into the first
// (single-rank points, no --threads), never with MPI ranks or an explicit --threads.
BOOST_AUTO_TEST_CASE(points_at_once_leaves_no_idle_last_round) {
    RunOptions o;  // all cores, one rank per point
    BOOST_TEST(points_at_once(o, 1, 2) == 1);
    BOOST_TEST(points_at_once(o, 2, 2) == 2);
    BOOST_TEST(points_at_once(o, 3, 2) == 3);  // 1.5 rounds shared, not 2 rounds
    BOOST_TEST(points_at_once(o, 4, 2) == 2);  // two full rounds
    BOOST_TEST(points_at_once(o, 7, 4) == 7);
    BOOST_TEST(points_at_once(o, 8, 4) == 4);
    RunOptions ranks;
    ranks.np = 2;
    BOOST_TEST(points_at_once(ranks, 3, 2) == 1);
    RunOptions capped;
    capped.threads = 2;
    BOOST_TEST(points_at_once(capped, 3, 8) == 2);
}

// Points run side by side (one LIGGGHTS process each) give exactly what they give one at a time.
BOOST_AUTO_TEST_CASE(points_side_by_side_give_the_same_numbers) {
    const Case c = parse_case(edit(kCase, "speed = \\[1.0\\]", "speed = [1.0, 1.5, 2.0]"), "tiny.toml", schema());
    RunOptions four;
    four.threads = 4;
    BOOST_TEST_REQUIRE(points_at_once(four, 3) == 3);
    std::map<int, fs::path> roots;
    for (const int threads : {1, 3}) {
        RunOptions o;
        o.threads = threads;
        o.results_root = scratch("side_by_side_" + std::to_string(threads));
        BOOST_TEST_REQUIRE(dem::run(c, o) == 0);
        roots[threads] = o.results_root;
    }
    for (const auto& p : c.points) {
        const Summary a = read_summary(result_dir(roots[1], "dem", p.id) / "summary.json");
        const Summary b = read_summary(result_dir(roots[3], "dem", p.id) / "summary.json");
        for (const char* name : kStandardOutputs) BOOST_TEST(a.value(name) == b.value(name), p.id << " " << name);
        BOOST_TEST(test::read_text(result_dir(roots[1], "dem", p.id) / "profile.csv") ==
                   test::read_text(result_dir(roots[3], "dem", p.id) / "profile.csv"));
    }
}

BOOST_AUTO_TEST_CASE(hertz_reference_runs_with_the_grains_elastic_constants) {
    const Run r = run(edit(kCase, "time = 0.02", "time = 0.002\nmodel = \"hertz\""), "hertz");
    BOOST_TEST_REQUIRE(r.code == 0);
    const Summary s = read_summary(r.dir / "summary.json");
    BOOST_TEST(s.value("normal_stress_bottom") > 0.0);
    BOOST_TEST(s.run.at("model").get<std::string>() == "hertz");
    // glass (E = 63 GPa, nu = 0.23) at d = 1 mm: time step 0.15 Rayleigh times, ~1e-7 s
    BOOST_TEST(s.run.at("time_step_s").get<double>() < 2e-7);
    std::ifstream deck(r.dir / "in.granlub");
    std::stringstream ss;
    ss << deck.rdbuf();
    BOOST_TEST(ss.str().find("model hertz tangential history") != std::string::npos);
    BOOST_TEST(ss.str().find("youngsModulus peratomtype 63000000000") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(two_mpi_ranks_complete) {
    const Run r = run(kCase, "np2", 2);
    BOOST_TEST_REQUIRE(r.code == 0);
    const Summary s = read_summary(r.dir / "summary.json");
    BOOST_TEST(s.run.at("ranks").get<int>() == 2);
    BOOST_TEST(s.value("normal_stress_bottom") > 0.0);
}

// contact_solve = "iterated": the deck sets `iterate on` on the pair style and every wall and adds
// the solver fix with the case's tolerance and cap; the same seed gives the same numbers, and it
// runs on 2 ranks.
BOOST_AUTO_TEST_CASE(iterated_contact_solve_writes_the_solver_and_runs) {
    const std::string text = edit(kCase, "\\[dem\\]", "[dem]\ncontact_solve = \"iterated\"\nsolve_tolerance = 1e-5\nsolve_iterations = 300");
    const Run a = run(text, "iterated_a"), b = run(text, "iterated_b"), two = run(text, "iterated_np2", 2);
    BOOST_TEST_REQUIRE(a.code == 0);
    BOOST_TEST_REQUIRE(b.code == 0);
    BOOST_TEST_REQUIRE(two.code == 0);
    const std::string deck = test::read_text(a.dir / "in.granlub");
    BOOST_TEST(deck.find("fix solve all impulse/solve tolerance 1e-05 iterations 300 impact_tolerance 0\n") != std::string::npos);
    // pair style, bottom, top and the two side walls
    const std::regex iterate_on(" iterate on\n");
    BOOST_TEST(std::distance(std::sregex_iterator(deck.begin(), deck.end(), iterate_on), std::sregex_iterator()) == 5);
    const Summary sa = read_summary(a.dir / "summary.json"), sb = read_summary(b.dir / "summary.json");
    BOOST_TEST(sa.run.at("contact_solve").get<std::string>() == "iterated");
    BOOST_TEST(sa.provenance.settings.at("resolved").at("solve_tolerance").get<double>() == 1e-5);
    for (const char* name : kStandardOutputs) BOOST_TEST(sa.value(name) == sb.value(name), name);
    const Summary s2 = read_summary(two.dir / "summary.json");
    BOOST_TEST(s2.run.at("ranks").get<int>() == 2);
    // rough walls made of bumps: atoms moved by fix move (the floor's) or by no fix (the plate's), which
    // the solver treats as kinematic (test_impulse_solve.cpp checks that exactly)
    const Run rough = run(edit(text, "roughness = 0.5\n", "roughness = 0.5\nsurface = \"bumps\"\n"), "iterated_bumps");
    BOOST_TEST_REQUIRE(rough.code == 0);
    const std::string rough_deck = test::read_text(rough.dir / "in.granlub");
    BOOST_TEST(rough_deck.find("fix bmove bbump move linear") != std::string::npos);
    BOOST_TEST(rough_deck.find("fix solve all impulse/solve") != std::string::npos);
    BOOST_TEST(read_summary(rough.dir / "summary.json").value("shear_stress_bottom") > 0.0);
    BOOST_TEST(s2.value("normal_stress_bottom") > 0.0);
}

BOOST_AUTO_TEST_CASE(bad_inputs_give_clear_errors) {
    try {  // unknown model name
        parse_case(edit(kCase, "\\[dem\\]", "[dem]\nmodel = \"hooke\""), "tiny.toml", schema());
        BOOST_FAIL("expected a CaseError");
    } catch (const CaseError& e) {
        const std::string w = e.what();
        BOOST_TEST(w.find("model") != std::string::npos);
        BOOST_TEST(w.find("impulse") != std::string::npos);
    }
    try {  // missing restitution
        parse_case(edit(kCase, "restitution = 0.9\n", ""), "tiny.toml", schema());
        BOOST_FAIL("expected a CaseError");
    } catch (const CaseError& e) {
        BOOST_TEST(std::string(e.what()).find("restitution") != std::string::npos);
    }
    {  // a fill too dense to insert: the point fails, no result is written
        const std::string dense = edit(edit(kCase, "solid_fraction = 0.4", "solid_fraction = 0.72"), "annulus_radius = 0.05",
                                       "annulus_radius = 0.05\nmax_solid_fraction = 0.74");
        const Case c = parse_case(dense, "tiny.toml", schema());
        try {
            initial_particles(c, c.points.front(), scratch("dense_direct"), {});
            BOOST_FAIL("expected a CaseError");
        } catch (const CaseError& e) {
            const std::string w = e.what();
            BOOST_TEST(w.find("solid_fraction") != std::string::npos);
            BOOST_TEST(w.find("at most") != std::string::npos);
        }
        // bad input: `granlub check` finds it without running (exit 2), and so does a run
        BOOST_CHECK_THROW(dem::check(c, RunOptions{}), CaseError);
        BOOST_CHECK_THROW(run(dense, "dense"), CaseError);
        BOOST_TEST(!fs::exists(result_dir(scratch("dense"), "dem", c.points.front().id) / "summary.json"));
    }
    for (const char* bad : {"solve_tolerance = 0.0", "solve_tolerance = 0.6", "solve_iterations = 0",
                            "contact_solve = \"twice\""}) {  // the solver's settings out of range
        try {
            parse_case(edit(kCase, "\\[dem\\]", std::string("[dem]\n") + bad), "tiny.toml", schema());
            BOOST_FAIL("expected a CaseError for " << bad);
        } catch (const CaseError& e) {
            const std::string key = std::string(bad).substr(0, std::string(bad).find(' '));
            BOOST_TEST(std::string(e.what()).find(key) != std::string::npos, e.what());
        }
    }
    {  // the iterated solve with the Hertz model: nothing to solve
        const Case c = parse_case(edit(kCase, "\\[dem\\]", "[dem]\nmodel = \"hertz\"\ncontact_solve = \"iterated\""),
                                  "tiny.toml", schema());
        try {
            dem::resolve_settings(c, c.points.front(), RunOptions{});
            BOOST_FAIL("expected a CaseError");
        } catch (const CaseError& e) {
            BOOST_TEST(std::string(e.what()).find("contact_solve") != std::string::npos, e.what());
        }
    }
    // impact_time: an option of the single pass only; speculative: of the impulse model without impact_time
    for (const auto& [combo, key] : {std::pair{"contact_solve = \"iterated\"\nimpact_time = true", "impact_time"},
                                     std::pair{"model = \"hertz\"\nimpact_time = true", "impact_time"},
                                     std::pair{"model = \"hertz\"\nspeculative = true", "speculative"},
                                     std::pair{"impact_time = true\nspeculative = true", "speculative"}}) {
        const Case c = parse_case(edit(kCase, "\\[dem\\]", std::string("[dem]\n") + combo), "tiny.toml", schema());
        try {
            dem::resolve_settings(c, c.points.front(), RunOptions{});
            BOOST_FAIL("expected a CaseError for " << combo);
        } catch (const CaseError& e) {
            const std::string w = e.what();
            BOOST_TEST(w.find(key) != std::string::npos, w);
            BOOST_TEST(w.find("allowed") != std::string::npos, w);
        }
    }
    {  // speculative with the iterated solve: accepted, and the deck says so
        const Case c = parse_case(edit(kCase, "\\[dem\\]", "[dem]\ncontact_solve = \"iterated\"\nspeculative = true"),
                                  "tiny.toml", schema());
        const auto s = dem::resolve_settings(c, c.points.front(), RunOptions{});
        BOOST_TEST(s.iterated);
        BOOST_TEST(s.speculative);
    }
    {  // a time step that lets grains tunnel
        const Case c = parse_case(edit(kCase, "\\[dem\\]", "[dem]\ntime_step = 1e-4"), "tiny.toml", schema());
        try {
            dem::resolve_settings(c, c.points.front(), RunOptions{});
            BOOST_FAIL("expected a CaseError");
        } catch (const CaseError& e) {
            BOOST_TEST(std::string(e.what()).find("time_step") != std::string::npos);
        }
    }
}

// [dem] boundary_pairs: "pass_start" writes model impulse's boundary_start on (the single pass's
// boundary pairs from the positions as the pass began); "sequential", the default, leaves the deck,
// the provenance and the inputs hash as they were before the key existed.
BOOST_AUTO_TEST_CASE(boundary_pairs_pass_start_is_a_switch_of_the_single_pass) {
    const Case base = parse_case(kCase, "tiny.toml", schema());
    auto with = [](const std::string& keys) {
        return parse_case(edit(kCase, "\\[dem\\]", "[dem]\n" + keys), "tiny.toml", schema());
    };
    const Case sequential = with("boundary_pairs = \"sequential\"");
    const Case pass_start = with("boundary_pairs = \"pass_start\"");
    BOOST_TEST(sequential.inputs_hash("dem") == base.inputs_hash("dem"));  // neutral: no result stale
    BOOST_TEST(pass_start.inputs_hash("dem") != base.inputs_hash("dem"));
    const auto s0 = dem::resolve_settings(base, base.points.front(), RunOptions{});
    const auto s1 = dem::resolve_settings(pass_start, pass_start.points.front(), RunOptions{});
    BOOST_TEST(!s0.boundary_start);
    BOOST_TEST(s1.boundary_start);
    BOOST_TEST(dem::model_text(s0).settings == " beta0 0 separate on iterate off");  // as before the key
    BOOST_TEST(dem::model_text(s1).settings == " beta0 0 separate on iterate off boundary_start on");
    BOOST_TEST(!s0.to_json().contains("boundary_pairs"));
    BOOST_TEST(s1.to_json().at("boundary_pairs") == "pass_start");
    // refused where nothing moves in a single pass: another law, the iterated solve, no overlap removal
    for (const char* combo : {"model = \"hertz\"", "contact_solve = \"iterated\"", "separate_overlaps = false"}) {
        const Case c = with(std::string(combo) + "\nboundary_pairs = \"pass_start\"");
        try {
            dem::resolve_settings(c, c.points.front(), RunOptions{});
            BOOST_FAIL("expected a CaseError for " << combo);
        } catch (const CaseError& e) {
            const std::string w = e.what();
            BOOST_TEST(w.find("boundary_pairs") != std::string::npos, w);
            BOOST_TEST(w.find("allowed") != std::string::npos, w);
        }
    }
    // impact_time moves grains in the pass too: accepted without overlap removal
    const Case timed = with("separate_overlaps = false\nimpact_time = true\nboundary_pairs = \"pass_start\"");
    BOOST_TEST(dem::resolve_settings(timed, timed.points.front(), RunOptions{}).boundary_start);
}

// [dem] strain: a run length in shear strain U t / H, never below `time`, capped by strain_time_max.
BOOST_AUTO_TEST_CASE(run_length_in_shear_strain_with_a_cap) {
    const Case base = parse_case(kCase, "tiny.toml", schema());
    const double H = base.cell.gap, U = base.points.front().speed;
    const double t0 = dem::resolve_settings(base, base.points.front(), RunOptions{}).time;
    auto time_with = [&](const std::string& keys) {
        const Case c = parse_case(edit(kCase, "\\[dem\\]", "[dem]\n" + keys), "tiny.toml", schema());
        return dem::resolve_settings(c, c.points.front(), RunOptions{}).time;
    };
    const double two = 2 * t0 * U / H;  // the strain of twice `time`
    BOOST_TEST(std::abs(time_with(fmt::format("strain = {:.17g}", two)) - 2 * t0) < 1e-12 * t0);
    BOOST_TEST(std::abs(time_with(fmt::format("strain = {:.17g}\nstrain_time_max = {:.17g}", two, 1.5 * t0)) -
                        1.5 * t0) < 1e-12 * t0);
    BOOST_TEST(time_with(fmt::format("strain = {:.17g}", 0.5 * two)) == t0);  // never below `time`
    BOOST_TEST(time_with("strain = 0") == t0);                                // off
}

// [dem] neighbor_skin: the deck's neighbour skin in grain diameters; the old name skin reads the same,
// with a warning.
BOOST_AUTO_TEST_CASE(neighbor_skin_in_diameters_and_its_old_name) {
    auto resolved = [](const std::string& key) {
        const Case c = parse_case(edit(kCase, "\\[dem\\]", "[dem]\n" + key + " = 0.5"), "tiny.toml", schema());
        return std::pair{dem::resolve_settings(c, c.points.front(), RunOptions{}).skin_m, c.warnings};
    };
    const auto [now, now_warnings] = resolved("neighbor_skin");
    const auto [old, old_warnings] = resolved("skin");
    const Case base = parse_case(kCase, "tiny.toml", schema());
    BOOST_TEST(now == 0.5 * base.grains.diameter);
    BOOST_TEST(old == now);
    BOOST_TEST(now_warnings.empty());
    BOOST_REQUIRE_EQUAL(old_warnings.size(), 1u);
    BOOST_TEST(old_warnings[0].find("[dem] skin is the old name of neighbor_skin") != std::string::npos, old_warnings[0]);
}

// The wall-force and plate-position readers: comments and blank lines skipped, rows parsed, and a
// bad line named by file and line number.
BOOST_AUTO_TEST_CASE(output_readers_parse_rows_and_name_bad_lines) {
    const fs::path dir = scratch("readers");
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    };
    auto error_of = [](auto read) -> std::string {
        try {
            read();
        } catch (const SolverError& e) {
            return e.what();
        }
        return "";
    };
    const auto w = dem::read_wall_series(write("wall.txt", "# Time-averaged data\n# TimeStep a b\n\n100 1 2\n200 3 4\n"));
    BOOST_TEST(w.step == (std::vector<double>{100, 200}));
    BOOST_REQUIRE(w.columns.size() == 2u);
    BOOST_TEST(w.columns[1] == (std::vector<double>{2, 4}));
    BOOST_TEST(error_of([&] { dem::read_wall_series(write("w2.txt", "100 1 2\n200 3\n")); })
                   .find("w2.txt:2: 2 values, expected 3 as on line 1") != std::string::npos);
    // LIGGGHTS prints a blown-up run's forces as nan / -nan / inf.
    BOOST_TEST(error_of([&] { dem::read_wall_series(write("w3.txt", "100 1 2\n200 -nan 4\n")); })
                   .find("w3.txt:2: non-finite") != std::string::npos);
    BOOST_TEST(error_of([&] { dem::read_wall_series(write("w4.txt", "100 1 x2\n")); })
                   .find("w4.txt:1: 'x2' is not a number") != std::string::npos);
    BOOST_TEST(error_of([&] { dem::read_wall_series(dir / "missing.txt"); }).find("wrote no wall-force file") !=
               std::string::npos);
    // The initial position (step 0) and repeated steps are dropped.
    const auto p = dem::read_plate_series(write("plate.txt", "# plate\n0 5e-3\n100 4.9e-3\n100 4.9e-3\n200 4.8e-3\n"));
    BOOST_TEST(p.step == (std::vector<double>{100, 200}));
    BOOST_TEST(p.gap == (std::vector<double>{4.9e-3, 4.8e-3}));
    BOOST_TEST(error_of([&] { dem::read_plate_series(write("p2.txt", "100 4.9e-3\n200\n")); })
                   .find("p2.txt:2: 1 values, expected 2: step gap") != std::string::npos);
    BOOST_TEST(error_of([&] { dem::read_plate_series(dir / "missing.txt"); }).find("wrote no plate-position file") !=
               std::string::npos);
}

BOOST_AUTO_TEST_CASE(every_result_carries_its_flow_regime_and_refine_dt_reruns_at_half_the_step) {
    const Run r = run(kCase + "refine_dt = true\nrefine_time = 0.01\n", "refine_dt");
    BOOST_TEST_REQUIRE(r.code == 0);
    const Summary s = read_summary(r.dir / "summary.json");
    const auto& fr = s.run.at("flow_regime");
    for (const char* key : {"inertial_number", "inertial_number_nominal", "inertial_number_mid_gap",
                            "coordination_number", "contact_persistence"})
        BOOST_TEST((fr.at(key).is_number() && std::isfinite(fr.at(key).get<double>())), key);
    BOOST_TEST(fr.at("regime").is_string());
    BOOST_TEST(fr.at("contact_persistence").get<double>() >= 0.0);
    BOOST_TEST(fr.at("contact_persistence").get<double>() <= 1.0);
    BOOST_TEST(fr.at("persistence_snapshots").get<int>() == 3);
    BOOST_TEST(!fs::exists(r.dir / "contacts.txt"));  // read and removed
    // the check: the full-step run in dt_full/, the point's answer at half the step (warm-started for
    // refine_time), a record read_regime accepts, and every output's time-step error
    const auto& rec = s.run.at("dt_refinement");
    const double dt = s.run.at("time_step_s").get<double>();
    const auto& full = rec.at("full_step_run");
    BOOST_TEST(full.at("time_step_s").get<double>() == 2 * dt);
    BOOST_TEST(rec.at("time_step_s").get<double>() == dt);
    BOOST_TEST(full.at("flow_regime").at("persistence_interval_s").get<double>() ==
               fr.at("persistence_interval_s").get<double>());
    BOOST_TEST(rec.at("start").get<std::string>().starts_with("warm"));
    BOOST_CHECK_NO_THROW(dt_unconverged_reason(rec));
    BOOST_TEST((read_regime(s.run).status != RegimeStatus::Unknown));
    BOOST_TEST((read_regime(s.run).status == (s.run.at("status") == "transient" ? RegimeStatus::Transient
                                              : dt_unconverged_reason(rec).empty() ? RegimeStatus::Steady
                                                                                   : RegimeStatus::DtUnconverged)));
    BOOST_TEST(read_profile(r.dir / "dt_full" / "profile.csv").rows() == 6u);
    const Scalar& tau = s.outputs.at("shear_stress_bottom");
    BOOST_TEST_REQUIRE(tau.dt_error.has_value());
    BOOST_TEST(*tau.dt_error == std::abs(full.at("outputs").at("shear_stress_bottom").at("value").get<double>() -
                                         tau.value));
    // the full-step run is the plain run: the same grains, deck and numbers
    const Run plain = run(kCase, "refine_dt_off");
    BOOST_TEST_REQUIRE(plain.code == 0);
    const Summary p = read_summary(plain.dir / "summary.json");
    BOOST_TEST(p.value("shear_stress_bottom") == full.at("outputs").at("shear_stress_bottom").at("value").get<double>());
    BOOST_TEST(!p.run.contains("dt_refinement"));
    BOOST_TEST(!p.outputs.at("shear_stress_bottom").dt_error.has_value());
    BOOST_TEST(!fs::exists(plain.dir / "dt_full"));
    // the default check is cold: the half-step run starts from the initial grains for the whole time
    const Run cold = run(kCase + "refine_dt = true\n", "refine_dt_cold");
    BOOST_TEST_REQUIRE(cold.code == 0);
    const Summary c = read_summary(cold.dir / "summary.json");
    const auto& crec = c.run.at("dt_refinement");
    BOOST_TEST(crec.at("start").get<std::string>().starts_with("cold"));
    BOOST_TEST(c.run.at("steps").get<long>() == 2 * crec.at("full_step_run").at("steps").get<long>());
    BOOST_TEST(crec.at("full_step_run").at("outputs").at("shear_stress_bottom").at("value").get<double>() ==
               p.value("shear_stress_bottom"));
}
