#include "granlub/run/process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <fstream>
#include <thread>

#include <fmt/format.h>

#include "granlub/error.h"
#include "watchdog.h"

namespace granlub {

std::string ProcessResult::describe() const {
    if (timed_out) return fmt::format("timed out after {:.0f} s and was killed", seconds);
    if (signal) return fmt::format("killed by signal {} ({})", signal, strsignal(signal));
    return fmt::format("exit code {}", exit_code);
}

std::optional<std::filesystem::path> find_executable(const std::string& name) {
    namespace fs = std::filesystem;
    auto usable = [](const fs::path& p) {
        std::error_code ec;
        return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
    };
    if (name.empty()) return std::nullopt;
    if (name.find('/') != std::string::npos) {
        if (usable(name)) return fs::path(name);
        return std::nullopt;
    }
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/local/bin:/usr/bin:/bin";
    std::size_t start = 0;
    while (start <= dirs.size()) {
        const std::size_t end = std::min(dirs.find(':', start), dirs.size());
        const std::string dir = dirs.substr(start, end - start);
        const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
        if (usable(candidate)) return candidate;
        start = end + 1;
    }
    return std::nullopt;
}

namespace {

// Stops the engine's group: SIGTERM, up to 2 s for the engine to go, then SIGKILL for what is
// left (the watchdog included: it leads the group). Returns the engine's wait status.
int stop_group(pid_t group, pid_t engine) {
    int status = 0;
    ::kill(-group, SIGTERM);
    for (int i = 0; i < 40; ++i) {
        if (::waitpid(engine, &status, WNOHANG) == engine) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    ::kill(-group, SIGKILL);
    while (::waitpid(engine, &status, 0) < 0 && errno == EINTR) {}
    return status;
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& workdir,
                          const std::filesystem::path& log, double timeout_s, const std::function<void()>& poll) {
    if (argv.empty()) throw SolverError("run_process: no program given");
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) throw SolverError(fmt::format("cannot open the log file {}: {}", log.string(), std::strerror(errno)));
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);

    // A pipe closed on exec tells the parent whether exec failed, and why.
    int err_pipe[2];
    if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
        ::close(fd);
        throw SolverError(fmt::format("cannot start {}: pipe: {}", argv[0], std::strerror(errno)));
    }
    const auto close_all = [&] {
        ::close(fd);
        ::close(err_pipe[0]);
        ::close(err_pipe[1]);
    };
    // Before the engine: whenever granlub dies after this line, the watchdog stops the group.
    std::optional<Watchdog> dog;
    try {
        dog.emplace();
    } catch (...) {
        close_all();
        throw;
    }
    const pid_t group = dog->group();
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        close_all();
        throw SolverError(fmt::format("cannot start {}: fork: {}", argv[0], std::strerror(e)));
    }
    if (pid == 0) {  // child: the watchdog's group, log, stdin from /dev/null, exec
        const auto fail = [&] {
            const int e = errno;
            [[maybe_unused]] const auto n = ::write(err_pipe[1], &e, sizeof e);
            ::_exit(127);
        };
        if (::setpgid(0, group) != 0) fail();
        const int devnull = ::open("/dev/null", O_RDONLY);
        if (devnull < 0 || ::dup2(devnull, STDIN_FILENO) < 0) fail();
        if (::dup2(fd, STDOUT_FILENO) < 0 || ::dup2(fd, STDERR_FILENO) < 0) fail();
        if (::chdir(workdir.c_str()) != 0) fail();
        ::execv(args[0], args.data());
        fail();
    }
    ::setpgid(pid, group);  // also here, so that the group is set whichever process runs first
    ::close(fd);
    ::close(err_pipe[1]);
    int exec_errno = 0;
    ssize_t got;
    do got = ::read(err_pipe[0], &exec_errno, sizeof exec_errno);
    while (got < 0 && errno == EINTR);
    ::close(err_pipe[0]);
    if (got == static_cast<ssize_t>(sizeof exec_errno)) {
        int st = 0;
        ::waitpid(pid, &st, 0);
        throw SolverError(fmt::format("cannot start {} in {}: {}", argv[0], workdir.string(), std::strerror(exec_errno)));
    }

    ProcessResult r;
    int status = 0;
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    try {
        for (;;) {
            const pid_t w = ::waitpid(pid, &status, WNOHANG);
            if (w == pid) break;
            if (w < 0 && errno != EINTR)
                throw SolverError(fmt::format("waiting for {}: {}", argv[0], std::strerror(errno)));
            if (timeout_s > 0 && elapsed() > timeout_s) {
                r.timed_out = true;
                status = stop_group(group, pid);
                break;
            }
            if (poll) poll();
            std::this_thread::sleep_for(std::chrono::milliseconds(poll ? 200 : 20));
        }
    } catch (...) {  // a failing progress display must not leave the engine running
        stop_group(group, pid);
        throw;
    }
    r.seconds = elapsed();
    dog->dismiss();
    if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    return r;
}

std::string tail_lines(const std::filesystem::path& file, std::size_t lines) {
    std::ifstream in(file);
    std::deque<std::string> last;
    std::string line;
    while (std::getline(in, line)) {
        last.push_back(line);
        if (last.size() > lines) last.pop_front();
    }
    std::string out;
    for (const auto& l : last) out += "    " + l + "\n";
    return out;
}

}  // namespace granlub
