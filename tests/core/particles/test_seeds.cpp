// Seeds pooled into one answer (granlub/particles/seeds.h, seed_pool.h): the key and the flag with
// their bad inputs, the set a run computes, the sweep over the members of a set and the pooled
// files (mean, the seeds' standard error, the status from every seed, incomplete sets labelled),
// the same bytes in any order of completion.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/error.h"
#include "granlub/particles/seed_pool.h"
#include "granlub/particles/seeds.h"
#include "granlub/results/file_io.h"
#include "granlub/results/run_status.h"
#include "granlub/run/sweep.h"
#include "granlub/statistics/flow_regime.h"

using namespace granlub;
namespace fs = std::filesystem;
using granlub::test::error_of;
using granlub::test::kValidCase;
using granlub::test::TmpDir;

namespace {

std::string with_particles(const std::string& lines) { return kValidCase + "\n[particles]\n" + lines + "\n"; }

Case case_with(const std::string& lines) { return parse_case(with_particles(lines), "t.toml", Schema::common()); }

// The CaseError message of seed_set for the case lines and options; "" when none.
std::string set_error(const std::string& lines, const RunOptions& o) {
    try {
        seed_set(case_with(lines), o);
    } catch (const CaseError& e) {
        return e.what();
    }
    return "";
}

RunOptions flags(const std::string& seeds, std::optional<std::uint64_t> seed = std::nullopt) {
    RunOptions o;
    o.seeds = seeds;
    o.seed = seed;
    return o;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// A member's result: its values move with the seed, its provenance fixed (time, run id, wall clock),
// so that two sweeps computing the same seeds write the same member files.
PointResult member_result(const Case& c, const OperatingPoint& p, std::uint64_t seed, bool steady = true) {
    PointResult r;
    const double k = static_cast<double>(seed);
    r.profile.add("y_over_H", {0.25, 0.75})
        .add("u_over_U", {0.8 + 0.01 * k, 0.2 - 0.01 * k})
        .add("solid_fraction", {0.55, 0.56 + 0.001 * k})
        .add("temperature_over_U2", {0.01, 0.02})
        .add("u_over_U_stderr", {0.001, 0.002})
        .add("solid_fraction_stderr", {0.0001, 0.0001})
        .add("temperature_over_U2_stderr", {0.0003, 0.0004})
        .add("v_over_U", {0.001 * k, 0.0});
    r.summary = make_summary(c, p, "dem", seed);
    for (const char* name : kStandardOutputs) r.summary.set(name, p.speed, "");
    r.summary.set("shear_stress_bottom", 1000 + 10 * k, "Pa", 2.0);
    r.summary.set("mean_solid_fraction", 0.58 + 0.001 * k, "", 0.0001);
    r.summary.set("max_solid_fraction", 0.65, "");
    r.summary.set("layering", 0.1 * k, "");
    r.summary.set("q6", 0.40 + 0.01 * k, "", 0.002);
    r.summary.provenance.utc_time = "2026-12-06T10:00:0" + std::to_string(seed % 10) + "Z";
    r.summary.provenance.run_id = "run-of-seed-" + std::to_string(seed);
    r.summary.run["wall_clock_s"] = 60.0 + k;
    // the run facts as the particle pipeline writes them: Z 3.9, 4.1, 4.3 for seeds 1, 2, 3 (collision
    // lubrication below Z = 4, contact above), a constant persistence without an error
    FlowDiagnostics d;
    d.coordination = 3.7 + 0.2 * k;
    d.coordination_stderr = 0.03;
    d.persistence = 0.8;
    d.inertial_nominal = 0.05 + 0.001 * k;
    d.inertial_mid_gap = 0.06 + 0.001 * k;
    r.summary.run["flow_regime"] = flow_regime_json(d);
    r.summary.run["flow_regime"]["coordination_number_core"] = 4.5 + 0.1 * k;
    r.summary.run["flow_regime"]["coordination_number_core_stderr"] = nullptr;  // too few blocks
    r.summary.run["flow_regime"]["coordination_snapshots"] = 40 + seed;         // a count: the lowest seed's
    r.summary.run["order"] = {{"q6", 0.40 + 0.01 * k}, {"q6_stderr", 0.002},   {"Q6", 0.1},
                              {"Q6_stderr", 0.01},      {"layering", 0.1 * k}, {"neighbour_cutoff", 1.2},
                              {"snapshots", 40 + seed}};
    set_regime(r.summary.run, steady ? RegimeStatus::Steady : RegimeStatus::Transient,
               steady ? "" : "no steady state detected in 0.3 s of simulated time");
    r.line = "ok";
    return r;
}

// Runs the toy particle sweep on `c` into `root` with --seed `seed` (none: every member).
int sweep(const Case& c, const fs::path& root, std::optional<std::uint64_t> seed, int* calls = nullptr,
          std::uint64_t transient_seed = 0) {
    RunOptions o;
    o.results_root = root;
    o.seed = seed;
    o.point = "U1.0";
    return run_particle_sweep(c, "dem", o, [&](const OperatingPoint& p, const RunOptions& ro, const fs::path& dir) {
        if (calls) ++*calls;
        BOOST_TEST(dir.filename().string() == "seed-" + std::to_string(ro.seed.value()));
        return member_result(c, p, *ro.seed, *ro.seed != transient_seed);
    });
}

}  // namespace

BOOST_AUTO_TEST_CASE(bad_seeds_keys_name_the_key_and_what_is_allowed) {
    const std::string allowed = "allowed: an integer [1, 1000], or a non-empty list of distinct integers >= 0";
    for (const auto& [text, why] : std::vector<std::pair<std::string, std::string>>{
             {"seeds = 0", "out of range"},
             {"seeds = -2", "out of range"},
             {"seeds = 1001", "out of range"},
             {"seeds = 2.5", "expected an integer"},
             {"seeds = \"3\"", "expected an integer"},
             {"seeds = []", "empty list"},
             {"seeds = [1, 2, 1]", "seeds = [ 1, 2, 1 ]: 1 appears twice in the list"},  // toml++'s spelling
             {"seeds = [1, 2.5]", "seeds = [ 1, 2.5 ]: 2.5 is not an integer"},
             {"seeds = [1, -3]", "seeds = [ 1, -3 ]: -3 is out of range"}}) {
        const std::string e = error_of(with_particles(text));
        BOOST_TEST_INFO(text << " -> " << e);
        BOOST_TEST(contains(e, "bad.toml:"));
        BOOST_TEST(contains(e, "[particles] seeds"));
        BOOST_TEST(contains(e, why));
        BOOST_TEST(contains(e, allowed));
    }
}

BOOST_AUTO_TEST_CASE(the_set_from_a_count_or_a_list) {
    BOOST_TEST(seed_set(case_with("seed = 5"), {}).seeds == std::vector<std::uint64_t>{5});
    BOOST_TEST(!seed_set(case_with("seed = 5"), {}).pooled());
    const SeedSet three = seed_set(case_with("seed = 5\nseeds = 3"), {});
    BOOST_TEST(three.seeds == (std::vector<std::uint64_t>{5, 6, 7}));
    BOOST_TEST(three.run == three.seeds);
    BOOST_TEST(three.pooled());
    const SeedSet list = seed_set(case_with("seeds = [7, 1, 2]"), {});
    BOOST_TEST(list.seeds == (std::vector<std::uint64_t>{1, 2, 7}));  // ascending: the pooling order
    // --seeds overrides the key; --seed picks one member
    BOOST_TEST(seed_set(case_with("seeds = 3"), flags("2,9")).seeds == (std::vector<std::uint64_t>{2, 9}));
    BOOST_TEST(seed_set(case_with(""), flags("4")).seeds == (std::vector<std::uint64_t>{1, 2, 3, 4}));
    BOOST_TEST(seed_set(case_with("seeds = 4"), flags("", 3)).run == std::vector<std::uint64_t>{3});
    // one seed: --seed is that seed, as before the key existed
    BOOST_TEST(seed_set(case_with("seeds = 1"), flags("", 42)).seeds == std::vector<std::uint64_t>{42});
    BOOST_TEST(seed_set(case_with(""), flags("1", 42)).run == std::vector<std::uint64_t>{42});
}

BOOST_AUTO_TEST_CASE(bad_seeds_flags_and_a_seed_outside_the_set_stop) {
    for (const auto& [text, why] : std::vector<std::pair<std::string, std::string>>{{"0", "out of range"},
                                                                                    {"1001", "out of range"},
                                                                                    {"-1", "not a whole number"},
                                                                                    {"2.5", "not a whole number"},
                                                                                    {"three", "not a whole number"},
                                                                                    {"1,2,1", "1 appears twice"},
                                                                                    {"1,,2", "'' is not a whole number"},
                                                                                    {"1, 2", "' 2' is not a whole number"},
                                                                                    {"1,-2", "'-2' is not"}}) {
        const std::string e = set_error("", flags(text));
        BOOST_TEST_INFO("--seeds " << text << " -> " << e);
        BOOST_TEST(contains(e, "--seeds"));
        BOOST_TEST(contains(e, why));
        BOOST_TEST(contains(e, "allowed: a whole number of seeds from 1 to 1000, or a comma-separated list"));
    }
    const std::string e = set_error("seeds = 3", flags("", 9));
    BOOST_TEST(contains(e, "--seed 9: not one of the seeds [1, 2, 3]"));
    BOOST_TEST(contains(e, "[particles] seeds"));
    BOOST_TEST(contains(set_error("seeds = [1, 2]", flags("5,6", 1)), "--seed 1: not one of the seeds [5, 6] (--seeds"));
    BOOST_TEST(set_error("seeds = [1, 2]", flags("", 2)).empty());
}

BOOST_AUTO_TEST_CASE(one_seed_runs_in_the_point_folder_as_before) {
    const TmpDir tmp("seeds_one");
    for (const auto& [lines, seed] : std::vector<std::pair<std::string, std::uint64_t>>{{"seed = 3", 3}, {"seeds = [7]", 7}}) {
        const Case c = case_with(lines);
        RunOptions o;
        o.results_root = tmp.path / std::to_string(seed);
        o.point = "U1.0";
        std::optional<std::uint64_t> given;
        BOOST_TEST(run_particle_sweep(c, "dem", o, [&](const OperatingPoint& p, const RunOptions& ro, const fs::path& dir) {
            given = ro.seed;
            BOOST_TEST(dir.filename().string() == "U1.0");
            return member_result(c, p, ro.seed.value_or(3));
        }) == 0);
        // the default: the options untouched (the case's seed); a list of one: its seed
        BOOST_TEST((seed == 3 ? !given.has_value() : given == std::optional<std::uint64_t>(7)));
        BOOST_TEST(!fs::exists(o.results_root / "dem" / "U1.0" / ("seed-" + std::to_string(seed))));
        const Summary s = read_summary(o.results_root / "dem" / "U1.0" / "summary.json");
        BOOST_TEST((s.provenance.seed == seed));
        BOOST_TEST(!s.run.contains("seeds"));  // never pooled: the run's own facts
        BOOST_TEST(s.run.at("flow_regime").dump() == member_result(c, c.points[0], seed).summary.run.at("flow_regime").dump());
    }
}

BOOST_AUTO_TEST_CASE(seeds_are_no_input_of_a_result) {
    // a member's result does not depend on which other seeds the set holds: adding seeds reuses it
    Schema schema = Schema::common();
    SectionSpec engine("dem", "a particle engine: reads [particles]");
    engine.uses = {kParticlesSection};
    schema.add(engine);
    const auto hash = [&](const std::string& lines) {
        return parse_case(with_particles(lines), "t.toml", schema).inputs_hash("dem");
    };
    const std::string h = hash("");
    BOOST_TEST(hash("seeds = 4") == h);
    BOOST_TEST(hash("seeds = [3, 4]") == h);
    BOOST_TEST(hash("seed = 2") != h);  // the seed itself is one
}

BOOST_AUTO_TEST_CASE(a_set_is_run_member_by_member_and_pooled) {
    const TmpDir tmp("seeds_sweep");
    const Case c = case_with("seeds = 3");
    int calls = 0;
    BOOST_TEST(sweep(c, tmp.path, std::nullopt, &calls) == 0);
    BOOST_TEST(calls == 3);
    const fs::path point = tmp.path / "dem" / "U1.0";
    for (int s : {1, 2, 3}) BOOST_TEST(fs::exists(point / ("seed-" + std::to_string(s)) / "summary.json"));
    const LoadedResult pooled = load_result(point, result_key(c, "dem"));
    BOOST_TEST_REQUIRE((pooled.status.state == ResultState::Complete), pooled.status.reason);
    const Summary& s = *pooled.summary;
    BOOST_TEST(to_string(read_regime(s.run).status) == "steady");
    BOOST_TEST(!s.provenance.seed.has_value());
    BOOST_TEST(s.run.at("seeds").at("pooled") == nlohmann::json({1, 2, 3}));
    // mean 1020 Pa, the seeds' standard error sd / sqrt(3) = 10 / sqrt(3); the block errors beside it
    const Scalar& tau = s.outputs.at("shear_stress_bottom");
    BOOST_TEST(tau.value == 1020.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(*tau.stderr_ == 10.0 / std::sqrt(3.0), boost::test_tools::tolerance(1e-12));
    BOOST_TEST(*tau.block_stderr == std::sqrt(3 * 4.0) / 3, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!s.outputs.at("max_solid_fraction").stderr_.has_value());  // the same in every seed
    BOOST_TEST(*s.outputs.at("layering").stderr_ == 0.1 / std::sqrt(3.0), boost::test_tools::tolerance(1e-9));
    BOOST_TEST(s.run.at("wall_clock_s").get<double>() == 61.0 + 62.0 + 63.0);  // the members' cost
    const Profile& p = *pooled.profile;
    BOOST_TEST(p.column("u_over_U")[0] == 0.82, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(p.column("u_over_U_stderr")[0] == 0.01 / std::sqrt(3.0), boost::test_tools::tolerance(1e-9));
    BOOST_TEST(p.column("u_over_U_block_stderr")[1] == 0.002 / std::sqrt(3.0), boost::test_tools::tolerance(1e-9));
    BOOST_TEST(p.has("v_over_U_stderr"));  // a column without a block error gains the seeds'
    // the run facts with an error pool as the outputs: Z's mean 4.1, the seeds' error 0.2 / sqrt(3),
    // the block errors 0.03 each combined beside it
    const nlohmann::json& fr = s.run.at("flow_regime");
    BOOST_TEST(fr.at("coordination_number").get<double>() == 4.1, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(fr.at("coordination_number_stderr").get<double>() == 0.2 / std::sqrt(3.0),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(fr.at("coordination_number_block_stderr").get<double>() == std::sqrt(3 * 0.03 * 0.03) / 3,
               boost::test_tools::tolerance(1e-12));
    // the core's Z without block errors: the seeds' error, no block error to keep
    BOOST_TEST(fr.at("coordination_number_core").get<double>() == 4.7, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(fr.at("coordination_number_core_stderr").get<double>() == 0.1 / std::sqrt(3.0),
               boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!fr.contains("coordination_number_core_block_stderr"));
    // a measured mean without an error: pooled, the same in every seed so without a seeds' error
    BOOST_TEST(fr.at("contact_persistence").get<double>() == 0.8, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!fr.contains("contact_persistence_stderr"));
    BOOST_TEST(fr.at("inertial_number_mid_gap").get<double>() == 0.062, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(fr.at("inertial_number").get<double>() == 0.062, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(fr.at("coordination_snapshots").get<int>() == 41);  // a count: the lowest seed's
    // the verdict is the pooled Z's (4.1: contact), not the lowest seed's (3.9: collision), made by the
    // function that made each seed's
    const nlohmann::json lowest = read_summary(point / "seed-1" / "summary.json").run.at("flow_regime");
    BOOST_TEST(lowest.at("regime").get<std::string>() == "collision lubrication");
    BOOST_TEST(fr.at("regime").get<std::string>() == "contact lubrication");
    BOOST_TEST((read_flow_verdict(fr).lubrication == Lubrication::Contact));
    BOOST_TEST(contains(fr.at("criterion").get<std::string>(), "Z = 4.1 >= 4"));
    BOOST_TEST(contains(fr.at("reason").get<std::string>(), "contact lubrication: Z = 4.1"));
    BOOST_TEST(fr.at("enduring_contacts").get<bool>());
    // run.order: q6 as its output, layering as its output (which has no error of its own)
    const nlohmann::json& order = s.run.at("order");
    BOOST_TEST(order.at("q6").get<double>() == s.outputs.at("q6").value, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(order.at("q6_stderr").get<double>() == *s.outputs.at("q6").stderr_, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(order.at("q6_block_stderr").get<double>() == *s.outputs.at("q6").block_stderr,
               boost::test_tools::tolerance(1e-15));
    BOOST_TEST(order.at("layering").get<double>() == s.outputs.at("layering").value, boost::test_tools::tolerance(1e-15));
    BOOST_TEST(order.at("layering_stderr").get<double>() == *s.outputs.at("layering").stderr_,
               boost::test_tools::tolerance(1e-15));
    BOOST_TEST(order.at("Q6_stderr").get<double>() < 1e-15);  // the same Q6 in every seed: no scatter
    BOOST_TEST(order.at("snapshots").get<int>() == 41);
    // run_facts_from names each pooled, recomputed and lowest-seed fact
    const nlohmann::json& from = s.run.at("seeds").at("run_facts_from");
    const auto names = [&](const char* k) { return from.at(k).get<std::vector<std::string>>(); };
    const auto has = [](const std::vector<std::string>& v, const std::string& x) {
        return std::find(v.begin(), v.end(), x) != v.end();
    };
    BOOST_TEST(has(names("pooled"), "flow_regime.coordination_number"));
    BOOST_TEST(has(names("pooled"), "flow_regime.contact_persistence"));
    BOOST_TEST(has(names("pooled"), "order.layering"));
    BOOST_TEST(!has(names("pooled"), "order.snapshots"));
    BOOST_TEST(has(names("recomputed"), "flow_regime.regime"));
    BOOST_TEST(has(names("from_lowest_seed"), "flow_regime.coordination_snapshots"));
    BOOST_TEST(has(names("from_lowest_seed"), "order.neighbour_cutoff"));
    BOOST_TEST(!has(names("from_lowest_seed"), "flow_regime.coordination_number_stderr"));
    BOOST_TEST(from.at("lowest_seed").get<std::string>() == "seed-1");
    // a second sweep finds every member complete
    BOOST_TEST(sweep(c, tmp.path, std::nullopt, &calls) == 0);
    BOOST_TEST(calls == 3);
    // back to one seed: the pooled files are no single run's answer, and it is recomputed beside the seeds
    const Case one = case_with("");
    RunOptions o;
    o.results_root = tmp.path;
    o.point = "U1.0";
    BOOST_TEST(run_particle_sweep(one, "dem", o, [&](const OperatingPoint& q, const RunOptions&, const fs::path& dir) {
        ++calls;
        BOOST_TEST((dir == point));
        return member_result(one, q, 1);
    }) == 0);
    BOOST_TEST(calls == 4);
    BOOST_TEST(!read_summary(point / "summary.json").run.contains("seeds"));
    BOOST_TEST(fs::exists(point / "seed-2" / "summary.json"));  // the members stay, for a set again
}

// A run fact one seed did not measure is no pooled fact: null, named, and the verdict says Z is missing.
BOOST_AUTO_TEST_CASE(a_run_fact_missing_in_one_seed_is_null_in_the_pool) {
    const TmpDir tmp("seeds_fact_missing");
    const Case c = case_with("seeds = 2");
    RunOptions o;
    o.results_root = tmp.path;
    o.point = "U1.0";
    BOOST_TEST(run_particle_sweep(c, "dem", o, [&](const OperatingPoint& p, const RunOptions& ro, const fs::path&) {
        PointResult r = member_result(c, p, *ro.seed);
        if (*ro.seed == 2) r.summary.run["flow_regime"]["coordination_number"] = nullptr;
        return r;
    }) == 0);
    const Summary s = read_summary(tmp.path / "dem" / "U1.0" / "summary.json");
    const nlohmann::json& fr = s.run.at("flow_regime");
    BOOST_TEST(fr.at("coordination_number").is_null());
    BOOST_TEST(fr.at("coordination_number_stderr").is_null());
    BOOST_TEST(fr.at("regime").get<std::string>() == "undetermined");
    BOOST_TEST(s.run.at("seeds").at("run_facts_from").at("not_in_every_seed") ==
               nlohmann::json({"flow_regime.coordination_number"}));
    BOOST_TEST(fr.at("coordination_number_core").get<double>() == 4.65, boost::test_tools::tolerance(1e-12));
}

BOOST_AUTO_TEST_CASE(an_incomplete_or_unsteady_set_is_no_answer) {
    const TmpDir tmp("seeds_incomplete");
    const Case c = case_with("seeds = [4, 8, 9]");
    const fs::path point = tmp.path / "dem" / "U1.0";
    BOOST_TEST(sweep(c, tmp.path, 8, nullptr, 9) == 0);
    Summary s = read_summary(point / "summary.json");
    BOOST_TEST(to_string(read_regime(s.run).status) == "incomplete");
    BOOST_TEST(contains(s.run.at("status_reason").get<std::string>(), "incomplete: 1 of 3 seeds"));
    BOOST_TEST(contains(s.run.at("status_reason").get<std::string>(), "seed 4 (not run yet)"));
    BOOST_TEST(s.run.at("seeds").at("missing").size() == 2u);
    BOOST_TEST(*s.outputs.at("shear_stress_bottom").stderr_ == 2.0);  // one seed: its own block error
    const Summary only = read_summary(point / "seed-8" / "summary.json");  // and its own run facts
    BOOST_TEST(s.run.at("flow_regime").dump() == only.run.at("flow_regime").dump());
    BOOST_TEST(s.run.at("order").dump() == only.run.at("order").dump());
    BOOST_TEST(s.run.at("seeds").at("run_facts_from").at("pooled").empty());
    BOOST_TEST(sweep(c, tmp.path, 4, nullptr, 9) == 0);
    BOOST_TEST(sweep(c, tmp.path, 9, nullptr, 9) == 0);  // seed 9 is transient
    s = read_summary(point / "summary.json");
    const Regime r = read_regime(s.run);
    BOOST_TEST(to_string(r.status) == "transient");
    BOOST_TEST(contains(r.reason, "1 of 3 seeds not steady: seed 9 transient: no steady state"));
}

BOOST_AUTO_TEST_CASE(the_same_seeds_give_the_same_bytes_in_any_order_of_completion) {
    const TmpDir a("seeds_order_a"), b("seeds_order_b");
    const Case c = case_with("seeds = 3");
    for (std::uint64_t s : {1, 2, 3}) BOOST_TEST(sweep(c, a.path, s) == 0);
    for (std::uint64_t s : {3, 1, 2}) BOOST_TEST(sweep(c, b.path, s) == 0);
    for (const char* f : {"summary.json", "profile.csv"}) {
        const std::string x = read_file(a.path / "dem" / "U1.0" / f), y = read_file(b.path / "dem" / "U1.0" / f);
        BOOST_TEST(x == y, f << " differs between the orders");
        BOOST_TEST(!x.empty());
    }
    // the bytes compared hold the pooled run facts and the verdict recomputed from them
    const Summary s = read_summary(b.path / "dem" / "U1.0" / "summary.json");
    BOOST_TEST(s.run.at("flow_regime").contains("coordination_number_block_stderr"));
    BOOST_TEST(s.run.at("flow_regime").at("regime").get<std::string>() == "contact lubrication");
    // and pooling again changes nothing
    const std::string before = read_file(a.path / "dem" / "U1.0" / "summary.json");
    pool_seeds(a.path / "dem" / "U1.0", {3, 2, 1}, result_key(c, "dem"));
    BOOST_TEST(read_file(a.path / "dem" / "U1.0" / "summary.json") == before);
}

BOOST_AUTO_TEST_CASE(a_member_in_the_wrong_folder_is_corrupt) {
    const TmpDir tmp("seeds_folder");
    const Case c = case_with("seeds = 2");
    BOOST_TEST(sweep(c, tmp.path, std::nullopt) == 0);
    const fs::path point = tmp.path / "dem" / "U1.0";
    fs::rename(point / "seed-2", point / "seed-5");
    const LoadedResult r = load_result(point / "seed-5", result_key(c, "dem"));
    BOOST_TEST((r.status.state == ResultState::Corrupt));
    BOOST_TEST(contains(r.status.reason, "says seed 2 but lies in the \"seed-5\" folder"));
}

BOOST_AUTO_TEST_CASE(a_members_lines_name_its_seed) {
    BOOST_TEST(point_label("U2.0", "/r/dem/U2.0") == "U2.0");  // one seed: as always
    BOOST_TEST(point_label("U2.0", "/r/dem/U2.0/dt_full") == "U2.0");
    BOOST_TEST(point_label("U2.0", "/r/dem/U2.0/seed-3") == "U2.0/seed-3");
    BOOST_TEST(point_label("U2.0", "/r/dem/U2.0/seed-3/dt_full") == "U2.0/seed-3");
}
