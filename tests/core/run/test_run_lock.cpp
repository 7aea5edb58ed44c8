// The locks on a case's results (granlub/run/run_lock.h): what conflicts and what does not, the holder
// named when a run will not wait, a failed taking that keeps nothing, a holder killed with kill -9,
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

BOOST_AUTO_TEST_CASE(a_writer_keeps_out_everyone_else_on_its_results_only) {
    const fs::path root = lock_scratch("writer"), other = lock_scratch("writer_other_case");
    {
        const ResultsLock held({{root, "automaton", LockMode::Exclusive}}, false);
        const std::string why = refusal({{root, "automaton", LockMode::Exclusive}});
        BOOST_TEST(why.find("the automaton results in " + (root / "automaton").string()) != std::string::npos, why);
        BOOST_TEST(why.find(fmt::format("in use by pid {} on ", ::getpid())) != std::string::npos, why);
        BOOST_TEST(why.find("(writing): ") != std::string::npos, why);  // then the command line
        BOOST_TEST(why.find("--no-wait") != std::string::npos, why);
        BOOST_TEST(!refusal({{root, "automaton", LockMode::Shared}}).empty());  // compare waits for a writer
        BOOST_TEST(refusal({{root, "continuum", LockMode::Exclusive}}).empty());  // another solver
        BOOST_TEST(refusal({{root, "report", LockMode::Exclusive}}).empty());
        BOOST_TEST(refusal({{other, "automaton", LockMode::Exclusive}}).empty());  // another case
        BOOST_TEST(lock_holder(lock_file(root, "automaton")).starts_with(fmt::format("pid {} ", ::getpid())));
    }
    BOOST_TEST(refusal({{root, "automaton", LockMode::Exclusive}}).empty());  // released with its holder
}

BOOST_AUTO_TEST_CASE(readers_share_and_keep_writers_out) {
    const fs::path root = lock_scratch("readers");
    const ResultsLock compare({{root, "dem", LockMode::Shared}}, false);
    const ResultsLock warm_start({{root, "dem", LockMode::Shared}}, false);  // e.g. yade reading dem's states
    const std::string why = refusal({{root, "dem", LockMode::Exclusive}});
    BOOST_TEST(why.find("the dem results") != std::string::npos, why);
    BOOST_TEST(why.find("(reading)") != std::string::npos, why);
}

BOOST_AUTO_TEST_CASE(a_refused_run_keeps_none_of_its_locks) {
    const fs::path root = lock_scratch("partial");
    {
        const ResultsLock yade({{root, "yade", LockMode::Exclusive}}, false);
        // dem's lock is taken first (the files' order), then yade's is refused: dem must be freed
        BOOST_TEST(!refusal({{root, "yade", LockMode::Exclusive}, {root, "dem", LockMode::Shared}}).empty());
        BOOST_TEST(refusal({{root, "dem", LockMode::Exclusive}}).empty());
    }
    // the same file asked for twice is taken once, in the stronger mode
    const ResultsLock both({{root, "dem", LockMode::Shared}, {root, "dem", LockMode::Exclusive}}, false);
    BOOST_TEST(!refusal({{root, "dem", LockMode::Shared}}).empty());
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
            const ResultsLock held({{root, "dem", LockMode::Exclusive}}, false);
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
    const std::string why = refusal({{root, "dem", LockMode::Exclusive}});
    BOOST_TEST(why.find(fmt::format("in use by pid {} ", child)) != std::string::npos, why);
    ::kill(child, SIGKILL);
    int status = 0;
    BOOST_TEST_REQUIRE(::waitpid(child, &status, 0) == child);
    BOOST_TEST(WIFSIGNALED(status));
    // its line is still in the file (nothing cleaned it up), and stops nobody
    BOOST_TEST(lock_holder(lock_file(root, "dem")).starts_with(fmt::format("pid {} ", child)));
    BOOST_TEST(refusal({{root, "dem", LockMode::Exclusive}}).empty());
    BOOST_TEST(lock_holder(lock_file(root, "dem")).starts_with(fmt::format("pid {} ", ::getpid())));
}

// The engines (LIGGGHTS, YADE) are exec'd while the sweep holds its lock: they must not inherit
// the lock's descriptor, or an engine outliving granlub would keep the results locked.
BOOST_AUTO_TEST_CASE(an_engine_started_under_the_lock_does_not_hold_it) {
    const fs::path root = lock_scratch("engine");
    const ResultsLock held({{root, "dem", LockMode::Exclusive}}, false);
    const ProcessResult r =
        run_process({"/bin/sh", "-c", "ls -l /proc/$$/fd > fds.txt"}, root, root / "engine.log", 30);
    BOOST_TEST_REQUIRE(r.exit_code == 0);
    std::ifstream in(root / "fds.txt");
    std::stringstream fds;
    fds << in.rdbuf();
    BOOST_TEST(fds.str().find("engine.log") != std::string::npos, fds.str());  // the listing is real
    BOOST_TEST(fds.str().find("dem.lock") == std::string::npos, fds.str());
}

BOOST_AUTO_TEST_SUITE_END()
