// The locks on a case's results (granlub/run/run_lock.h): what conflicts and what does not (one point,
// not its neighbours; a realisation, not its point's pooled files), the holder named when a run will
// not wait, a failed taking that keeps nothing, a holder killed with kill -9,
// and an engine started under a lock that does not hold it. A second open file description in this
// process conflicts with the first as another process's would (flock(2)), so most of this needs no
// second process.
#include <boost/test/unit_test.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "case_text.h"
#include "granlub/run/process.h"
#include "granlub/run/run_lock.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

fs::path lock_scratch(const std::string& name) {
    const auto dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / "core-scratch" / ("lock_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// What taking `locks` without waiting throws; "" when it does not throw (the locks are then
// released at once).
std::string refusal(std::vector<LockRequest> locks) {
    try {
        ResultsLock l(std::move(locks), false);
    } catch (const ResultsInUse& e) {
        return e.what();
    }
    return "";
}

}  // namespace

BOOST_AUTO_TEST_SUITE(results_locks)

BOOST_AUTO_TEST_CASE(the_lock_files_are_named_after_what_they_guard) {
    const fs::path root = "/r";
    BOOST_TEST(lock_file(root, point_lock(root, "dem", "U1.4", LockMode::Shared).name) == "/r/.locks/dem/U1.4.lock");
    BOOST_TEST(lock_file(root, seed_lock(root, "dem", "U1.4", 7, LockMode::Shared).name) ==
               "/r/.locks/dem/U1.4/seed-7.lock");
    BOOST_TEST(lock_file(root, "report") == "/r/.locks/report.lock");
}

BOOST_AUTO_TEST_CASE(a_writer_keeps_out_everyone_else_on_its_point_only) {
    const fs::path root = lock_scratch("writer"), other = lock_scratch("writer_other_case");
    const auto u1 = [&](LockMode m) { return point_lock(root, "automaton", "U1.0", m); };
    {
        const ResultsLock held({u1(LockMode::Exclusive)}, false);
        const std::string why = refusal({u1(LockMode::Exclusive)});
        BOOST_TEST(why.find("the automaton results in " + (root / "automaton" / "U1.0").string()) != std::string::npos,
                   why);
        BOOST_TEST(why.find(fmt::format("in use by pid {} on ", ::getpid())) != std::string::npos, why);
        BOOST_TEST(why.find("(writing): ") != std::string::npos, why);  // then the command line
        BOOST_TEST(why.find("--no-wait") != std::string::npos, why);
        BOOST_TEST(!refusal({u1(LockMode::Shared)}).empty());  // compare waits for a writer of what it reads
        BOOST_TEST(refusal({point_lock(root, "automaton", "U2.0", LockMode::Exclusive)}).empty());  // another point
        BOOST_TEST(refusal({point_lock(root, "continuum", "U1.0", LockMode::Exclusive)}).empty());  // another solver
        BOOST_TEST(refusal({{root, "report", LockMode::Exclusive}}).empty());
        BOOST_TEST(refusal({point_lock(other, "automaton", "U1.0", LockMode::Exclusive)}).empty());  // another case
        BOOST_TEST(lock_holder(lock_file(root, "automaton/U1.0")).starts_with(fmt::format("pid {} ", ::getpid())));
    }
    BOOST_TEST(refusal({u1(LockMode::Exclusive)}).empty());  // released with its holder
}

// A set of seeds: each realisation is written under its own lock; the point's lock guards only
// the pooled files, which a realisation's writer takes after its own (the files' order).
BOOST_AUTO_TEST_CASE(realisations_of_one_point_do_not_block_each_other_nor_the_pooled_files) {
    const fs::path root = lock_scratch("seeds");
    const ResultsLock seed1({seed_lock(root, "dem", "U1.4", 1, LockMode::Exclusive)}, false);
    BOOST_TEST(refusal({seed_lock(root, "dem", "U1.4", 2, LockMode::Exclusive)}).empty());
    const std::string why = refusal({seed_lock(root, "dem", "U1.4", 1, LockMode::Exclusive)});
    BOOST_TEST(why.find("the dem results in " + (root / "dem" / "U1.4" / "seed-1").string()) != std::string::npos, why);
    const ResultsLock pooling({point_lock(root, "dem", "U1.4", LockMode::Exclusive)}, false);  // held with seed1
    BOOST_TEST(!refusal({point_lock(root, "dem", "U1.4", LockMode::Shared)}).empty());  // compare waits
    // a yade realisation's warm start reads dem's same realisation, not its neighbours
    BOOST_TEST(refusal({seed_lock(root, "dem", "U1.4", 2, LockMode::Shared)}).empty());
    BOOST_TEST(!refusal({seed_lock(root, "dem", "U1.4", 1, LockMode::Shared)}).empty());
}

BOOST_AUTO_TEST_CASE(point_locks_are_each_point_or_each_realisation_of_each_point) {
    const Case c = parse_case(granlub::test::kValidCase, "t.toml", Schema::common());  // points U1.0, U2.0
    std::vector<std::string> names;
    for (const auto& l : point_locks("/r", "dem", c.select(""), LockMode::Shared)) names.push_back(l.name);
    BOOST_TEST(names == (std::vector<std::string>{"dem/U1.0", "dem/U2.0"}), boost::test_tools::per_element());
    names.clear();
    for (const auto& l : point_locks("/r", "dem", c.select("U2.0"), LockMode::Exclusive, {3, 5})) {
        names.push_back(l.name);
        BOOST_TEST((l.mode == LockMode::Exclusive));
    }
    BOOST_TEST(names == (std::vector<std::string>{"dem/U2.0/seed-3", "dem/U2.0/seed-5"}),
               boost::test_tools::per_element());
}

BOOST_AUTO_TEST_CASE(readers_share_and_keep_writers_out) {
    const fs::path root = lock_scratch("readers");
    const auto dem = [&](LockMode m) { return point_lock(root, "dem", "U1.0", m); };
    const ResultsLock compare({dem(LockMode::Shared)}, false);
    const ResultsLock warm_start({dem(LockMode::Shared)}, false);  // e.g. yade reading dem's states
    const std::string why = refusal({dem(LockMode::Exclusive)});
    BOOST_TEST(why.find("the dem results") != std::string::npos, why);
    BOOST_TEST(why.find("(reading)") != std::string::npos, why);
}

BOOST_AUTO_TEST_CASE(a_refused_run_keeps_none_of_its_locks) {
    const fs::path root = lock_scratch("partial");
    const auto lock = [&](const char* solver, LockMode m) { return point_lock(root, solver, "U1.0", m); };
    {
        const ResultsLock yade({lock("yade", LockMode::Exclusive)}, false);
        // dem's lock is taken first (the files' order), then yade's is refused: dem must be freed
        BOOST_TEST(!refusal({lock("yade", LockMode::Exclusive), lock("dem", LockMode::Shared)}).empty());
        BOOST_TEST(refusal({lock("dem", LockMode::Exclusive)}).empty());
    }
    // the same file asked for twice is taken once, in the stronger mode
    const ResultsLock both({lock("dem", LockMode::Shared), lock("dem", LockMode::Exclusive)}, false);
    BOOST_TEST(!refusal({lock("dem", LockMode::Shared)}).empty());
}

// kill -9 gives the holder no chance to clean up: the kernel drops its lock with its descriptors.
BOOST_AUTO_TEST_CASE(a_holder_killed_with_kill_9_leaves_no_lock) {
    const fs::path root = lock_scratch("killed");
    int ready[2];
    BOOST_TEST_REQUIRE(::pipe(ready) == 0);
    const pid_t child = ::fork();
    BOOST_TEST_REQUIRE(child >= 0);
    if (child == 0) {
        ::close(ready[0]);
        try {
            const ResultsLock held({{root, "dem/U1.0", LockMode::Exclusive}}, false);
            [[maybe_unused]] const auto n = ::write(ready[1], "x", 1);
            for (;;) ::pause();
        } catch (...) {
            ::_exit(1);  // never back into the test runner
        }
    }
    ::close(ready[1]);
    char c = 0;
    BOOST_TEST_REQUIRE(::read(ready[0], &c, 1) == 1);  // the child holds the lock
    ::close(ready[0]);
    const std::string why = refusal({{root, "dem/U1.0", LockMode::Exclusive}});
    BOOST_TEST(why.find(fmt::format("in use by pid {} ", child)) != std::string::npos, why);
    ::kill(child, SIGKILL);
    int status = 0;
    BOOST_TEST_REQUIRE(::waitpid(child, &status, 0) == child);
    BOOST_TEST(WIFSIGNALED(status));
    // its line is still in the file (nothing cleaned it up), and stops nobody
    BOOST_TEST(lock_holder(lock_file(root, "dem/U1.0")).starts_with(fmt::format("pid {} ", child)));
    BOOST_TEST(refusal({{root, "dem/U1.0", LockMode::Exclusive}}).empty());
    BOOST_TEST(lock_holder(lock_file(root, "dem/U1.0")).starts_with(fmt::format("pid {} ", ::getpid())));
}

// The engines (LIGGGHTS, YADE) are exec'd while the sweep holds its lock: they must not inherit
// the lock's descriptor, or an engine outliving granlub would keep the results locked.
BOOST_AUTO_TEST_CASE(an_engine_started_under_the_lock_does_not_hold_it) {
    const fs::path root = lock_scratch("engine");
    const ResultsLock held({{root, "dem/U1.0", LockMode::Exclusive}}, false);
    const ProcessResult r =
        run_process({"/bin/sh", "-c", "ls -l /proc/$$/fd > fds.txt"}, root, root / "engine.log", 30);
    BOOST_TEST_REQUIRE(r.exit_code == 0);
    std::ifstream in(root / "fds.txt");
    std::stringstream fds;
    fds << in.rdbuf();
    BOOST_TEST(fds.str().find("engine.log") != std::string::npos, fds.str());  // the listing is real
    BOOST_TEST(fds.str().find("U1.0.lock") == std::string::npos, fds.str());
}

BOOST_AUTO_TEST_SUITE_END()
