// Two sweeps side by side under one pipeline (granlub/run/pipeline.h), as `granlub run` runs DEM and
// YADE: a reader's point starts once the point it reads is done, not once the whole sweep is; the
// pipeline takes the locks once (its sweeps would otherwise lock each other out in one process) and
// keeps other runs out while it lives; a point that fails, or a sweep that stops, ends the waits.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "case_text.h"
#include "granlub/error.h"
#include "granlub/run/pipeline.h"
#include "granlub/run/run_lock.h"
#include "granlub/run/sweep.h"
#include "toy_sweep.h"

using namespace granlub;
using granlub::test::toy_result;
namespace fs = std::filesystem;

namespace {

// --no-wait: a sweep that meets a lock fails at once (ResultsInUse) instead of hanging the test.
RunOptions no_wait_results(const std::string& name) {
    RunOptions o = test::fresh_results(name);
    o.wait = false;
    return o;
}

// run_sweep's exit code; -2 when a lock kept it out.
int sweep(const Case& c, const std::string& solver, const RunOptions& o, const PointSolver& solve, int at_once,
          const std::vector<std::string>& reads = {}) {
    try {
        return run_sweep(c, solver, o, solve, at_once, reads);
    } catch (const ResultsInUse&) {
        return -2;
    }
}

// What happened, in order, across the threads.
struct Events {
    std::mutex m;
    std::vector<std::string> seen;
    void add(const std::string& e) {
        std::lock_guard lock(m);
        seen.push_back(e);
    }
    std::ptrdiff_t at(const std::string& e) {
        std::lock_guard lock(m);
        const auto it = std::find(seen.begin(), seen.end(), e);
        return it == seen.end() ? -1 : it - seen.begin();
    }
};

// Waits until `flag` is set, at most 10 s (a test that fails must not hang).
void wait_until(const std::atomic<bool>& flag) {
    const auto t0 = std::chrono::steady_clock::now();
    while (!flag && std::chrono::steady_clock::now() - t0 < std::chrono::seconds(10))
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_reader_point_starts_once_the_point_it_reads_is_done) {
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());  // points U1.0, U2.0
    const RunOptions o = no_wait_results("granlub_test_pipeline");
    const fs::path root = o.results_root;
    const ResultKey key_a = result_key(c, "a");
    Events ev;
    std::atomic<bool> reader_ran_u1{false};
    // "a"'s U2.0 is slow: it finishes only once "b" has run U1.0 (or after 10 s, if b never does)
    const auto solve_a = [&](const OperatingPoint& p, const fs::path&) {
        if (p.id == "U2.0") wait_until(reader_ran_u1);
        ev.add("a " + p.id);
        return toy_result(c, p, "a");
    };
    const auto solve_b = [&](const OperatingPoint& p, const fs::path&) {
        // what b reads is there: a's point is complete, written by its sweep (asserted in the
        // test's thread: Boost.Test's assertions are not for other threads)
        if (load_result(result_dir(root, "a", p.id), key_a).status.state != ResultState::Complete)
            ev.add("b found a incomplete at " + p.id);
        ev.add("b " + p.id);
        if (p.id == "U1.0") reader_ran_u1 = true;
        return toy_result(c, p, "b");
    };
    int rc_a = -1, rc_b = -1;
    {
        const SweepPipeline pipeline(c, o, {"a", "b"});
        // its locks keep other runs out; a second pipeline in the process is refused
        BOOST_CHECK_THROW(ResultsLock({{root, "a/U1.0", LockMode::Shared}}, false), ResultsInUse);
        BOOST_CHECK_THROW(ResultsLock({{root, "b/U2.0", LockMode::Exclusive}}, false), ResultsInUse);
        BOOST_CHECK_THROW(SweepPipeline(c, o, {"c"}), Error);
        std::jthread ta([&] { rc_a = sweep(c, "a", o, solve_a, 2); });
        std::jthread tb([&] { rc_b = sweep(c, "b", o, solve_b, 2, {"a"}); });
    }
    BOOST_TEST(rc_a == 0);
    BOOST_TEST(rc_b == 0);
    BOOST_TEST(ev.at("a U1.0") < ev.at("b U1.0"));
    BOOST_TEST(ev.at("b U1.0") < ev.at("a U2.0"));  // while a's sweep still ran
    BOOST_TEST(ev.at("a U2.0") < ev.at("b U2.0"));
    BOOST_TEST(ev.at("b U2.0") >= 0);
    BOOST_TEST(ev.at("b found a incomplete at U1.0") == -1);
    BOOST_TEST(ev.at("b found a incomplete at U2.0") == -1);
    // the pipeline's locks are gone with it
    BOOST_CHECK_NO_THROW(ResultsLock({{root, "a/U1.0", LockMode::Exclusive}, {root, "a/U2.0", LockMode::Exclusive},
                                      {root, "b/U1.0", LockMode::Exclusive}, {root, "b/U2.0", LockMode::Exclusive}},
                                     false));
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(a_failed_point_or_a_stopped_sweep_ends_the_wait) {
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());
    const RunOptions o = no_wait_results("granlub_test_pipeline_fail");
    Events ev;
    const auto fails_u1 = [&](const OperatingPoint& p, const fs::path&) -> PointResult {
        if (p.id == "U1.0") throw SolverError("U1.0: the toy failed");
        ev.add("a " + p.id);
        return toy_result(c, p, "a");
    };
    const auto reader = [&](const OperatingPoint& p, const fs::path&) {
        ev.add("b " + p.id);
        return toy_result(c, p, "b");
    };
    int rc_a = -1, rc_b = -1;
    {
        const SweepPipeline pipeline(c, o, {"a", "b"});
        std::jthread tb([&] { rc_b = sweep(c, "b", o, reader, 1, {"a"}); });  // the reader first
        std::jthread ta([&] { rc_a = sweep(c, "a", o, fails_u1, 1); });
    }
    BOOST_TEST(rc_a == 1);  // its failure is its own
    BOOST_TEST(rc_b == 0);  // the reader ran both points (what it does without a's result is its business)
    BOOST_TEST(ev.at("b U1.0") >= 0);
    BOOST_TEST(ev.at("a U2.0") < ev.at("b U2.0"));

    // a sweep that throws (bad input) before its points: its readers do not wait for it
    Events ev2;
    const auto reader2 = [&](const OperatingPoint& p, const fs::path&) {
        ev2.add("b " + p.id);
        return toy_result(c, p, "b");
    };
    RunOptions forced = o;
    forced.force = true;
    {
        const SweepPipeline pipeline(c, forced, {"a", "b"});
        std::jthread tb([&] { rc_b = sweep(c, "b", forced, reader2, 2, {"a"}); });
        std::jthread ta([&] {
            try {
                run_sweep(c, "a", forced, [&](const OperatingPoint&, const fs::path&) -> PointResult {
                    throw CaseError("t.toml: [a] bad = 3: allowed 1 or 2");
                });
            } catch (const CaseError&) {
            }
        });
    }
    BOOST_TEST(rc_b == 0);
    BOOST_TEST(ev2.at("b U1.0") >= 0);
    BOOST_TEST(ev2.at("b U2.0") >= 0);
    fs::remove_all(o.results_root);
}
