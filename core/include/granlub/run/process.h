// Running an external engine (LIGGGHTS, YADE): no shell, stdin /dev/null, stdout and stderr
// appended to a log file, an optional wall-clock limit, and the exit status. The engine runs in
// its own process group (a timeout kills mpirun and its ranks together) and dies with granlub,
// whatever ends granlub: kill -9, Ctrl-C, a crash (see core/src/run/watchdog.h).
#pragma once
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace granlub {

struct ProcessResult {
    int exit_code = -1;    // when it exited normally
    int signal = 0;        // when it was killed by a signal (0: not)
    bool timed_out = false;
    double seconds = 0;
    std::string describe() const;  // "exit code 3", "killed by signal 9", "timed out after 12 s"
};

// Full path of `name` (as given when it contains a '/', else searched on PATH), or nothing.
std::optional<std::filesystem::path> find_executable(const std::string& name);

// Runs argv[0] (a path: no PATH search) with argv[1..] in `workdir`, appending stdout and stderr
// to `log`. `timeout_s` <= 0: no limit. `poll` is called about 5 times per second while it runs
// (progress). Throws SolverError when it cannot be started; when `poll` throws, the engine is
// killed and reaped before the exception goes on.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& workdir,
                          const std::filesystem::path& log, double timeout_s,
                          const std::function<void()>& poll = {});

// The last `lines` lines of a text file (for error messages quoting a log).
std::string tail_lines(const std::filesystem::path& file, std::size_t lines);

}  // namespace granlub
