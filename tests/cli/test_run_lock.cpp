// Issue 34: two runs on one case. Two `granlub automaton --force` with different seeds used to
// both exit 0 and leave points with one run's summary.json beside the other's profile.csv. Here
// the first run is held inside its locks by the test hook of granlub/run/run_lock.h (it reads a
// fifo to its end right after taking them), so what the second run does while the first holds the
// results is observed, not guessed at with sleeps: it waits (default) or fails with exit 2
// (--no-wait); a holder killed with kill -9 blocks nobody; another solver is not blocked.
// Issue 76: the locks are per point, so a run on another point of the same solver, and a compare
// of another point, go on beside the held run; the same point waits.
#define BOOST_TEST_MODULE granlub run lock
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <boost/test/unit_test.hpp>
#include <fmt/format.h>

#include "granlub/results/results.h"
#include "granlub/results/run_id.h"
#include "granlub/run/run_lock.h"
#include "run_command.h"

namespace fs = std::filesystem;

namespace {

const std::string kCase = std::string(GRANLUB_SOURCE_DIR) + "/tests/cli/tiny";
const char* const kPoints[] = {"U1.0", "U2.0"};

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("granlub_test_lock_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// Polls `done` every 20 ms for up to `seconds`: waiting for a state, not for a time.
bool within(double seconds, const std::function<bool()>& done) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (!done()) {
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

// `granlub args...` in the background, stdout and stderr into `out`; with `pause_fifo`, held
// inside its lock until release() (the test hook GRANLUB_TEST_LOCK_PAUSE).
struct Granlub {
    pid_t pid = -1;
    fs::path out;
    int status = 0;
    bool reaped = false;

    Granlub(const std::vector<std::string>& args, fs::path out_file, const fs::path& pause_fifo = {})
        : out(std::move(out_file)) {
        std::vector<std::string> argv{GRANLUB_EXE};
        argv.insert(argv.end(), args.begin(), args.end());
        const int fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);  // there for text() at once
        BOOST_TEST_REQUIRE(fd >= 0);
        pid = ::fork();
        BOOST_TEST_REQUIRE(pid >= 0);
        if (pid == 0) {
            if (::dup2(fd, 1) < 0 || ::dup2(fd, 2) < 0) ::_exit(126);
            if (pause_fifo.empty())
                ::unsetenv("GRANLUB_TEST_LOCK_PAUSE");
            else
                ::setenv("GRANLUB_TEST_LOCK_PAUSE", pause_fifo.c_str(), 1);
            std::vector<char*> a;
            for (auto& s : argv) a.push_back(s.data());
            a.push_back(nullptr);
            ::execv(a[0], a.data());
            ::_exit(127);
        }
        ::close(fd);
    }
    ~Granlub() {
        if (!reaped) {
            ::kill(pid, SIGKILL);
            ::waitpid(pid, nullptr, 0);
        }
    }
    bool running() {
        if (reaped) return false;
        if (::waitpid(pid, &status, WNOHANG) == pid) reaped = true;
        return !reaped;
    }
    // The exit code, or minus the signal that killed it; -1000 when it did not end in time.
    int finish(double seconds = 240) {
        if (!within(seconds, [&] { return !running(); })) return -1000;
        return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
    }
    std::string text() const { return granlub::read_file(out); }
};

fs::path pause_fifo(const fs::path& dir) {
    const fs::path f = dir / "pause.fifo";
    BOOST_TEST_REQUIRE(::mkfifo(f.c_str(), 0600) == 0);
    return f;
}

// Lets a run held by the hook go on: open the fifo's writing end (there is a reader once the run
// waits in the hook) and close it, which is the end of file the run reads to.
bool release(const fs::path& fifo) {
    return within(60, [&] {
        const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
        if (fd < 0) return false;  // ENXIO: the run has not opened it yet
        ::close(fd);
        return true;
    });
}

// The lock of the automaton's point U1.0 names `pid` as its holder (the run took its locks).
bool holds_automaton(const fs::path& root, pid_t pid) {
    return granlub::lock_holder(granlub::lock_file(root, "automaton/U1.0")).starts_with(fmt::format("pid {} ", pid));
}

std::vector<std::string> automaton(const fs::path& root, int seed, std::vector<std::string> more = {}) {
    std::vector<std::string> a{"automaton", kCase, "--results", root.string(), "--seed", std::to_string(seed),
                               "--force"};
    a.insert(a.end(), more.begin(), more.end());
    return a;
}

std::string command(const std::vector<std::string>& args) {
    std::string cmd = GRANLUB_EXE;
    for (const auto& a : args) cmd += " '" + a + "'";
    return cmd;
}

// Every automaton point of `root` is one run's: profile.csv names the run summary.json names, all
// points name the same run, with `seed`; and `granlub compare` finds every result complete.
void every_point_from_one_run(const fs::path& root, std::uint64_t seed) {
    std::set<std::string> runs;
    for (const char* point : kPoints) {
        const fs::path dir = granlub::result_dir(root, "automaton", point);
        BOOST_TEST_CONTEXT(dir) {
            const granlub::Summary s = granlub::read_summary(dir / "summary.json");
            BOOST_TEST(s.provenance.seed.value_or(0) == seed);
            BOOST_TEST(!s.provenance.run_id.empty());
            BOOST_TEST(granlub::read_table_run_id(dir / "profile.csv").value_or("") == s.provenance.run_id);
            runs.insert(s.provenance.run_id);
        }
    }
    BOOST_TEST(runs.size() == 1u);
#ifdef GRANLUB_HAVE_COMPARE
    const auto o = granlub::test::run(command({"compare", kCase, "--results", root.string(), "--no-wait"}));
    BOOST_TEST(o.rc == 0, o.text);  // 1 when a result is corrupt or stale
#endif
}

// A first `granlub automaton --seed 1 --force [more]` in a fresh results folder, held inside its locks.
struct FirstRunHeld {
    fs::path root;
    fs::path fifo;
    Granlub first;

    explicit FirstRunHeld(const std::string& name, const std::vector<std::string>& more = {})
        : root(scratch(name)), fifo(pause_fifo(root)), first(automaton(root, 1, more), root / "first.out", fifo) {
        BOOST_TEST_REQUIRE(within(60, [&] { return holds_automaton(root, first.pid); }), first.text());
    }
};

}  // namespace

BOOST_AUTO_TEST_CASE(a_second_sweep_waits_for_the_first_and_then_recomputes_every_point) {
    FirstRunHeld held("wait");
    auto& [root, fifo, first] = held;
    Granlub second(automaton(root, 2), root / "second.out");
    BOOST_TEST_REQUIRE(within(60, [&] { return second.text().find("granlub: waiting for the automaton results") !=
                                               std::string::npos; }),
                       second.text());
    const std::string waiting = second.text();
    BOOST_TEST(waiting.find(fmt::format("in use by pid {} on ", first.pid)) != std::string::npos, waiting);
    BOOST_TEST(waiting.find("(writing): ") != std::string::npos, waiting);  // since when, and the command
    BOOST_TEST(waiting.find("--seed 1 --force") != std::string::npos, waiting);
    BOOST_TEST(second.running());  // waiting, not writing: nothing of either run is there yet
    for (const char* point : kPoints)
        BOOST_TEST(!fs::exists(granlub::result_dir(root, "automaton", point) / "summary.json"));
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    BOOST_TEST(second.finish() == 0, second.text());
    BOOST_TEST(second.text().find("free after") != std::string::npos, second.text());
    // the second ran after the first, over all of it (a run that had not waited would have been
    // overwritten by the first, which wrote once released: seed 1)
    every_point_from_one_run(root, 2);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(with_no_wait_a_second_run_fails_at_once_with_exit_2_naming_the_holder) {
    FirstRunHeld held("no_wait");
    auto& [root, fifo, first] = held;
    const auto refused = granlub::test::run(command(automaton(root, 2, {"--no-wait"})));
    BOOST_TEST(refused.rc == 2, refused.text);
    BOOST_TEST(refused.text.find("error: the automaton results in " + (root / "automaton").string()) !=
                   std::string::npos,
               refused.text);
    BOOST_TEST(refused.text.find(fmt::format("in use by pid {} on ", first.pid)) != std::string::npos, refused.text);
    BOOST_TEST(refused.text.find("--seed 1 --force") != std::string::npos, refused.text);
#ifdef GRANLUB_HAVE_COMPARE
    // compare reads the automaton results: it does not read them while a run writes them
    const auto compare = granlub::test::run(command({"compare", kCase, "--results", root.string(), "--no-wait"}));
    BOOST_TEST(compare.rc == 2, compare.text);
    BOOST_TEST(compare.text.find("the automaton results") != std::string::npos, compare.text);
#endif
    BOOST_TEST(first.running());
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    every_point_from_one_run(root, 1);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(a_run_killed_with_kill_9_inside_its_lock_does_not_block_the_next) {
    FirstRunHeld held("killed");
    auto& [root, fifo, first] = held;
    ::kill(first.pid, SIGKILL);
    BOOST_TEST(first.finish() == -SIGKILL);
    const auto next = granlub::test::run(command(automaton(root, 2, {"--no-wait"})));
    BOOST_TEST(next.rc == 0, next.text);
    BOOST_TEST(next.text.find("in use") == std::string::npos, next.text);
    every_point_from_one_run(root, 2);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(runs_on_different_solvers_of_one_case_do_not_block_each_other) {
    FirstRunHeld held("solvers");
    auto& [root, fifo, first] = held;
    const auto continuum =
        granlub::test::run(command({"continuum", kCase, "--results", root.string(), "--no-wait"}));
    BOOST_TEST(continuum.rc == 0, continuum.text);
    BOOST_TEST(continuum.text.find("in use") == std::string::npos, continuum.text);
    BOOST_TEST(first.running());  // the automaton still holds its results
    for (const char* point : kPoints)
        BOOST_TEST(fs::exists(granlub::result_dir(root, "continuum", point) / "summary.json"));
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    every_point_from_one_run(root, 1);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(another_point_of_the_same_solver_runs_beside_a_held_run) {
    FirstRunHeld held("other_point", {"--point", "U1.0"});
    auto& [root, fifo, first] = held;
    const auto other = granlub::test::run(command(automaton(root, 2, {"--point", "U2.0", "--no-wait"})));
    BOOST_TEST(other.rc == 0, other.text);
    BOOST_TEST(other.text.find("in use") == std::string::npos, other.text);
    BOOST_TEST(first.running());  // still holding U1.0
    BOOST_TEST(!fs::exists(granlub::result_dir(root, "automaton", "U1.0") / "summary.json"));
    BOOST_TEST(granlub::read_summary(granlub::result_dir(root, "automaton", "U2.0") / "summary.json")
                   .provenance.seed.value_or(0) == 2u);
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    BOOST_TEST(granlub::read_summary(granlub::result_dir(root, "automaton", "U1.0") / "summary.json")
                   .provenance.seed.value_or(0) == 1u);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(the_same_point_twice_waits_naming_the_holder) {
    FirstRunHeld held("same_point", {"--point", "U1.0"});
    auto& [root, fifo, first] = held;
    Granlub second(automaton(root, 2, {"--point", "U1.0"}), root / "second.out");
    BOOST_TEST_REQUIRE(within(60, [&] { return second.text().find("granlub: waiting for the automaton results in " +
                                                                  (root / "automaton" / "U1.0").string()) !=
                                               std::string::npos; }),
                       second.text());
    BOOST_TEST(second.text().find(fmt::format("in use by pid {} on ", first.pid)) != std::string::npos, second.text());
    BOOST_TEST(second.text().find("--point U1.0") != std::string::npos, second.text());  // the holder's command
    BOOST_TEST(second.running());
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    BOOST_TEST(second.finish() == 0, second.text());
    BOOST_TEST(granlub::read_summary(granlub::result_dir(root, "automaton", "U1.0") / "summary.json")
                   .provenance.seed.value_or(0) == 2u);  // the second ran after the first
    fs::remove_all(root);
}

#ifdef GRANLUB_HAVE_COMPARE
BOOST_AUTO_TEST_CASE(compare_waits_only_for_a_point_it_reads) {
    FirstRunHeld held("compare_point", {"--point", "U1.0"});
    auto& [root, fifo, first] = held;
    const auto continuum = granlub::test::run(command({"continuum", kCase, "--results", root.string(), "--no-wait"}));
    BOOST_TEST_REQUIRE(continuum.rc == 0, continuum.text);
    const auto other = granlub::test::run(command({"compare", kCase, "--results", root.string(), "--point", "U2.0",
                                                   "--no-wait"}));
    BOOST_TEST(other.rc == 0, other.text);
    BOOST_TEST(fs::exists(root / "report" / "index.html"));
    const auto same = granlub::test::run(command({"compare", kCase, "--results", root.string(), "--point", "U1.0",
                                                  "--no-wait"}));
    BOOST_TEST(same.rc == 2, same.text);
    BOOST_TEST(same.text.find("the automaton results in " + (root / "automaton" / "U1.0").string()) !=
                   std::string::npos,
               same.text);
    BOOST_TEST(first.running());
    BOOST_TEST_REQUIRE(release(fifo));
    BOOST_TEST(first.finish() == 0, first.text());
    fs::remove_all(root);
}
#endif
