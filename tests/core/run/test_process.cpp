// The process runner: exit codes, signals, logs, timeouts, programs that cannot start, and the
// engine dying with the process that runs it (kill -9, Ctrl-C) without leaving anything behind.
#define BOOST_TEST_MODULE core_process
#include <boost/test/unit_test.hpp>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/run/process.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
    const auto dir = fs::path(GRANLUB_BINARY_DIR) / "tests" / "core-scratch" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::string read_text(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Fields of /proc/PID/stat after the command name: state, parent, process group. Empty if gone.
std::vector<std::string> stat_fields(pid_t pid) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(in, line)) return {};
    std::istringstream rest(line.substr(line.rfind(')') + 1));
    std::vector<std::string> f(3);
    rest >> f[0] >> f[1] >> f[2];
    return f;
}

// Running (a zombie nobody reaped counts as gone: it runs nothing and holds no file).
bool alive(pid_t pid) {
    const auto f = stat_fields(pid);
    return !f.empty() && f[0] != "Z";
}

pid_t group_of(pid_t pid) {
    const auto f = stat_fields(pid);
    return f.empty() ? -1 : static_cast<pid_t>(std::stol(f[2]));
}

bool all_gone_within(const std::vector<pid_t>& pids, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    for (;;) {
        bool any = false;
        for (const pid_t p : pids) any = any || alive(p);
        if (!any) return true;
        if (std::chrono::steady_clock::now() > end) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
}

// This process has no child left, running or zombie (the runner reaped the engine and the watchdog).
bool no_children() { return ::waitpid(-1, nullptr, WNOHANG) == -1 && errno == ECHILD; }

// A fake engine like mpirun: it has a child of its own, and says who they are in `pids`.
const std::vector<std::string> kEngine = {"/bin/sh", "-c", "sleep 60 & echo $$ $! > pids.tmp && mv pids.tmp pids; wait"};

// {engine, its child} once the fake engine in `dir` has started.
std::vector<pid_t> engine_pids(const fs::path& dir) {
    for (int i = 0; i < 200; ++i) {
        std::ifstream in(dir / "pids");
        pid_t engine = 0, child = 0;
        if (in >> engine >> child) return {engine, child};
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    throw std::runtime_error("the fake engine did not start in " + dir.string());
}

// A process that runs the fake engine through the runner, as `granlub` does; it leads its own
// process group, as a shell job in the terminal's foreground does.
pid_t start_runner(const fs::path& dir) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::setpgid(0, 0);
        ::signal(SIGINT, SIG_DFL);
        try {
            run_process(kEngine, dir, dir / "run.log", 120);
        } catch (...) {
        }
        ::_exit(0);
    }
    ::setpgid(pid, pid);
    return pid;
}

// Runs the fake engine in a runner, ends the runner with `signal` sent to `target` (the runner,
// or its group as a terminal does), and checks that the engine, its child and the watchdog go.
void runner_killed(const std::string& name, int signal, bool to_group) {
    const auto dir = scratch(name);
    const pid_t runner = start_runner(dir);
    const auto pids = engine_pids(dir);
    const pid_t watchdog = group_of(pids[0]);
    BOOST_TEST(watchdog != runner);  // the engine is not in the runner's (the terminal's) group
    BOOST_TEST(group_of(pids[1]) == watchdog);
    BOOST_TEST_REQUIRE(alive(watchdog));
    // the watchdog holds its socket and nothing else (no log, no terminal, no caller's pipe)
    const auto fds = std::distance(fs::directory_iterator(fmt::format("/proc/{}/fd", watchdog)), fs::directory_iterator{});
    BOOST_TEST(fds == 1);

    ::kill(to_group ? -runner : runner, signal);
    int status = 0;
    ::waitpid(runner, &status, 0);
    BOOST_TEST_REQUIRE(WIFSIGNALED(status));
    BOOST_TEST(WTERMSIG(status) == signal);
    BOOST_TEST(all_gone_within({pids[0], pids[1]}, 5.0), "engine " << pids[0] << " or its child " << pids[1]
                                                                     << " outlived the runner");
    BOOST_TEST(all_gone_within({watchdog}, 5.0), "the watchdog " << watchdog << " outlived its group");
    BOOST_TEST(no_children());
}

}  // namespace

BOOST_AUTO_TEST_CASE(finds_programs_on_the_path) {
    const auto sh = find_executable("sh");
    BOOST_TEST_REQUIRE(sh.has_value());
    BOOST_TEST(sh->is_absolute());
    BOOST_TEST(!find_executable("granlub-no-such-program").has_value());
    BOOST_TEST(!find_executable("/nonexistent/yade").has_value());
    BOOST_TEST(find_executable(sh->string()).has_value());
}

BOOST_AUTO_TEST_CASE(exit_code_and_log) {
    const auto dir = scratch("process-exit");
    const auto log = dir / "run.log";
    const ProcessResult r = run_process(
        {"/bin/sh", "-c", "echo to-stdout; echo to-stderr >&2; echo stdin=$(readlink /proc/$$/fd/0); pwd; exit 3"}, dir,
        log, 30);
    BOOST_TEST(r.exit_code == 3);
    BOOST_TEST(!r.timed_out);
    BOOST_TEST(r.signal == 0);
    BOOST_TEST(r.describe() == "exit code 3");
    const std::string text = read_text(log);
    BOOST_TEST(text.find("to-stdout") != std::string::npos);
    BOOST_TEST(text.find("to-stderr") != std::string::npos);
    BOOST_TEST(text.find("stdin=/dev/null") != std::string::npos);
    BOOST_TEST(text.find(dir.filename().string()) != std::string::npos);  // ran in `dir`
    BOOST_TEST(tail_lines(log, 1).find(dir.filename().string()) != std::string::npos);
    BOOST_TEST(no_children());
}

BOOST_AUTO_TEST_CASE(killed_by_a_signal) {
    const auto dir = scratch("process-signal");
    const ProcessResult r = run_process({"/bin/sh", "-c", "kill -TERM $$"}, dir, dir / "run.log", 30);
    BOOST_TEST(r.signal == SIGTERM);
    BOOST_TEST(!r.timed_out);
    BOOST_TEST(r.describe().find("killed by signal 15") != std::string::npos);
    BOOST_TEST(no_children());
}

BOOST_AUTO_TEST_CASE(timeout_kills_the_process_group) {
    const auto dir = scratch("process-timeout");
    int polls = 0;
    const ProcessResult r = run_process(kEngine, dir, dir / "run.log", 0.6, [&] { ++polls; });
    BOOST_TEST(r.timed_out);
    BOOST_TEST(r.seconds < 10.0);
    BOOST_TEST(polls > 0);
    BOOST_TEST(r.describe().find("timed out") != std::string::npos);
    const auto pids = engine_pids(dir);
    BOOST_TEST(!alive(pids[0]));
    BOOST_TEST(all_gone_within({pids[1]}, 1.0));  // the engine's child too
    BOOST_TEST(no_children());
}

BOOST_AUTO_TEST_CASE(a_failing_poll_stops_the_engine) {
    const auto dir = scratch("process-poll-throws");
    auto poll = [&] {
        if (fs::exists(dir / "pids")) throw std::runtime_error("progress display failed");
    };
    BOOST_CHECK_THROW(run_process(kEngine, dir, dir / "run.log", 60, poll), std::runtime_error);
    const auto pids = engine_pids(dir);
    BOOST_TEST(!alive(pids[0]));
    BOOST_TEST(all_gone_within({pids[1]}, 1.0));
    BOOST_TEST(no_children());
}

BOOST_AUTO_TEST_CASE(engine_dies_when_the_runner_is_killed) { runner_killed("process-kill9", SIGKILL, false); }

BOOST_AUTO_TEST_CASE(engine_dies_on_ctrl_c_of_the_runner) { runner_killed("process-sigint", SIGINT, true); }

BOOST_AUTO_TEST_CASE(missing_program_is_a_solver_error) {
    const auto dir = scratch("process-missing");
    try {
        run_process({"/nonexistent/yade", "-x"}, dir, dir / "run.log", 5);
        BOOST_FAIL("expected SolverError");
    } catch (const SolverError& e) {
        BOOST_TEST(std::string(e.what()).find("/nonexistent/yade") != std::string::npos);
    }
    BOOST_TEST(no_children());
}
