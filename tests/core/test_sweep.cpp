// The sweep driver every solver uses: skip complete points, recompute stale or forced ones,
// report failures per point without writing anything for them, and points a model has no answer
// for as such.
#include <filesystem>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/error.h"
#include "granlub/failure_record.h"
#include "granlub/sweep.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

PointResult toy_result(const Case& c, const OperatingPoint& p) {
    PointResult r;
    r.profile.add("y_over_H", {0, 1}).add("u_over_U", {1, 0}).add("solid_fraction", {0.5, 0.5}).add(
        "temperature_over_U2", {0.01, 0.01});
    r.summary = make_summary(c, p, "toy");
    for (const char* name : kStandardOutputs) r.summary.set(name, p.speed, "");
    r.line = "ok";
    return r;
}

}  // namespace

BOOST_AUTO_TEST_CASE(skip_force_stale_and_failures) {
    const fs::path root = fs::temp_directory_path() / "granlub_test_sweep";
    fs::remove_all(root);
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());
    RunOptions o;
    o.results_root = root;
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
