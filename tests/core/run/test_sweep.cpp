// The sweep driver every solver uses: skip complete points, recompute stale or forced ones,
// report failures per point without writing anything for them, and points a model has no answer
// for as such.
#include <filesystem>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/error.h"
#include "granlub/results/failure_record.h"
#include "granlub/results/run_id.h"
#include "granlub/run/sweep.h"
#include "toy_sweep.h"

using namespace granlub;
namespace fs = std::filesystem;

using granlub::test::fresh_results;
using granlub::test::toy_result;

BOOST_AUTO_TEST_CASE(skip_force_stale_and_failures) {
    RunOptions o = fresh_results("granlub_test_sweep");
    const fs::path root = o.results_root;
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());
    int calls = 0;
    auto solve = [&](const OperatingPoint& p, const fs::path& dir) {
        ++calls;
        BOOST_TEST(fs::is_directory(dir));
        return toy_result(c, p);
    };
    BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST(calls == 2);
    BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST(calls == 2);  // both complete: skipped
    o.force = true;
    o.point = "U2.0";
    BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST(calls == 3);  // forced, one point
    o = RunOptions{};
    o.results_root = root;
    const Case changed =
        parse_case(granlub::test::with("density = 2500.0", "density = 2600.0"), "t.toml", Schema::common());
    auto solve_changed = [&](const OperatingPoint& p, const fs::path&) {
        ++calls;
        return toy_result(changed, p);
    };
    BOOST_TEST(run_sweep(changed, "toy", o, solve_changed) == 0);
    BOOST_TEST(calls == 5);  // stale: both recomputed

    // --full and an explicit --seed change results without changing the case: not reused.
    o.full = true;
    BOOST_TEST(run_sweep(changed, "toy", o, solve_changed) == 0);
    BOOST_TEST(calls == 7);
    BOOST_TEST(run_sweep(changed, "toy", o, solve_changed) == 0);
    BOOST_TEST(calls == 7);  // same options: skipped
    o.seed = 11;
    auto seeded = [&](const OperatingPoint& p, const fs::path&) {
        ++calls;
        PointResult r = toy_result(changed, p);
        r.summary.provenance.seed = 11;
        return r;
    };
    BOOST_TEST(run_sweep(changed, "toy", o, seeded) == 0);
    BOOST_TEST(calls == 9);
    BOOST_TEST(run_sweep(changed, "toy", o, seeded) == 0);
    BOOST_TEST(calls == 9);  // same seed: skipped
    o = RunOptions{};
    o.results_root = root;

    // One point fails: the sweep goes on, returns 1, and leaves that point without a result.
    fs::remove_all(root);
    auto flaky = [&](const OperatingPoint& p, const fs::path&) -> PointResult {
        if (p.id == "U1.0") throw SolverError("U1.0: no convergence (residual 1e-3); try more cells");
        return toy_result(c, p);
    };
    BOOST_TEST(run_sweep(c, "toy", o, flaky) == 1);
    BOOST_TEST(!fs::exists(root / "toy" / "U1.0" / "summary.json"));
    BOOST_TEST(fs::exists(root / "toy" / "U2.0" / "summary.json"));
    BOOST_TEST_REQUIRE(read_failure(root / "toy" / "U1.0").has_value());
    BOOST_TEST(!read_failure(root / "toy" / "U1.0")->no_answer);

    // A point the model has no answer for: not a failure (returns 0), recorded as "no answer".
    fs::remove_all(root);
    auto partial = [&](const OperatingPoint& p, const fs::path&) -> PointResult {
        if (p.id == "U1.0") throw NoAnswer("point U1.0: the toy holds a fixed number of grains");
        return toy_result(c, p);
    };
    BOOST_TEST(run_sweep(c, "toy", o, partial) == 0);
    BOOST_TEST(!fs::exists(root / "toy" / "U1.0" / "summary.json"));
    const auto why = read_failure(root / "toy" / "U1.0");
    BOOST_TEST_REQUIRE(why.has_value());
    BOOST_TEST(why->no_answer);
    BOOST_TEST(why->message == "point U1.0: the toy holds a fixed number of grains");
    BOOST_TEST(fs::exists(root / "toy" / "U2.0" / "summary.json"));
    fs::remove_all(root);
}

// Issue 34: two runs on one case left a point whose summary.json came from one run and whose
// profile.csv from the other, and every check passed. Every file of a point now names its run: a
// point whose files name different runs (or none, written before run ids) is corrupt, says which
// files and runs, and the next sweep recomputes it.
BOOST_AUTO_TEST_CASE(a_point_from_two_runs_is_corrupt_and_recomputed) {
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());
    RunOptions o = fresh_results("granlub_test_sweep_runs");
    const fs::path root = o.results_root;
    int calls = 0;
    auto solve = [&](const OperatingPoint& p, const fs::path& dir) {  // writes a second table too
        PointResult r = toy_result(c, p);
        write_file_atomic(dir / "section.csv", profile_csv(r.profile, {"a table beside the profile"}));
        ++calls;
        return r;
    };
    BOOST_TEST_REQUIRE(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST_REQUIRE(calls == 2);
    const fs::path dir = result_dir(root, "toy", "U1.0");
    const ResultKey key = result_key(c, "toy");
    BOOST_TEST_REQUIRE((load_result(dir, key).status.state == ResultState::Complete));
    const std::string mine = read_summary(dir / "summary.json").provenance.run_id;
    BOOST_TEST(mine == run_id());
    BOOST_TEST(read_table_run_id(dir / "profile.csv").value_or("") == mine);
    BOOST_TEST(read_table_run_id(dir / "section.csv").value_or("") == mine);

    // A table written by another run: replace this run's id in it by another's.
    const std::string other = "20260101T000000Z-elsewhere-1-00000000";
    auto from_other_run = [&](const fs::path& f) {
        std::string text = read_file(f);
        const auto at = text.find(mine);
        BOOST_TEST_REQUIRE(at != std::string::npos);
        write_file_atomic(f, text.replace(at, mine.size(), other));
    };
    for (const char* table : {"profile.csv", "section.csv"}) {
        BOOST_TEST_CONTEXT(table) {
            from_other_run(dir / table);
            const ResultStatus st = load_result(dir, key).status;
            BOOST_TEST((st.state == ResultState::Corrupt));
            for (const std::string& named : {(dir / table).string(), (dir / "summary.json").string(), mine, other})
                BOOST_TEST(st.reason.find(named) != std::string::npos, st.reason << " lacks " << named);
            BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);  // recomputed, not skipped
            BOOST_TEST((load_result(dir, key).status.state == ResultState::Complete));
            BOOST_TEST(read_table_run_id(dir / table).value_or("") == mine);
        }
    }
    BOOST_TEST(calls == 4);

    // Results written before run ids name none: corrupt, so recomputed once.
    nlohmann::json old = nlohmann::json::parse(read_file(dir / "summary.json"));
    old["provenance"].erase("run_id");
    write_file_atomic(dir / "summary.json", old.dump(2));
    const ResultStatus before = load_result(dir, key).status;
    BOOST_TEST((before.state == ResultState::Corrupt));
    BOOST_TEST(before.reason.find("written before run ids") != std::string::npos, before.reason);
    BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST(calls == 5);
    BOOST_TEST((load_result(dir, key).status.state == ResultState::Complete));

    // A table an earlier run wrote and this one does not (gap.csv of a load-controlled run) does
    // not stay behind to make the new result corrupt: the sweep removes it before it recomputes.
    write_file_atomic(dir / "gap.csv", "# run_id " + other + "\ntime_s,gap_m\n0,1\n");
    BOOST_TEST((load_result(dir, key).status.state == ResultState::Corrupt));
    o.force = true;
    o.point = "U1.0";
    BOOST_TEST(run_sweep(c, "toy", o, solve) == 0);
    BOOST_TEST(!fs::exists(dir / "gap.csv"));
    BOOST_TEST((load_result(dir, key).status.state == ResultState::Complete));
    fs::remove_all(root);
}
