#include "granlub/yade/process.h"

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

namespace granlub::yade {

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
    const auto t0 = std::chrono::steady_clock::now();
    const pid_t pid = ::fork();
    if (pid < 0) {
        ::close(fd);
        ::close(err_pipe[0]);
        ::close(err_pipe[1]);
        throw SolverError(fmt::format("cannot start {}: fork: {}", argv[0], std::strerror(errno)));
    }
    if (pid == 0) {  // child: own process group (so a timeout kills its children too), log, exec
        ::setpgid(0, 0);
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        const int devnull = ::open("/dev/null", O_RDONLY);
        if (devnull >= 0) ::dup2(devnull, STDIN_FILENO);
        if (::chdir(workdir.c_str()) == 0) ::execv(args[0], args.data());
        const int e = errno;
        [[maybe_unused]] const auto n = ::write(err_pipe[1], &e, sizeof e);
        ::_exit(127);
    }
    ::setpgid(pid, pid);
    ::close(fd);
    ::close(err_pipe[1]);
    int exec_errno = 0;
    const auto got = ::read(err_pipe[0], &exec_errno, sizeof exec_errno);
    ::close(err_pipe[0]);
    if (got == static_cast<ssize_t>(sizeof exec_errno)) {
        int st = 0;
        ::waitpid(pid, &st, 0);
        throw SolverError(fmt::format("cannot start {} in {}: {}", argv[0], workdir.string(), std::strerror(exec_errno)));
    }

    ProcessResult r;
    int status = 0;
    const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
    for (;;) {
        const pid_t w = ::waitpid(pid, &status, WNOHANG);
        if (w == pid) break;
        if (w < 0 && errno != EINTR) throw SolverError(fmt::format("waiting for {}: {}", argv[0], std::strerror(errno)));
        if (timeout_s > 0 && elapsed() > timeout_s) {
            r.timed_out = true;
            ::kill(-pid, SIGTERM);
            for (int i = 0; i < 40 && ::waitpid(pid, &status, WNOHANG) == 0; ++i)
                std::this_thread::sleep_for(std::chrono::milliseconds(50));
            ::kill(-pid, SIGKILL);
            ::waitpid(pid, &status, 0);
            break;
        }
        if (poll) poll();
        std::this_thread::sleep_for(std::chrono::milliseconds(poll ? 200 : 20));
    }
    r.seconds = elapsed();
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

}  // namespace granlub::yade
