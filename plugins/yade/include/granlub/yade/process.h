// Running an external program: no shell, stdout and stderr into a log file, a wall-clock limit
// (the whole process group is killed on expiry), and the exit status. Used for YADE, whose
// periodic collider can hang (yade.md section 5), so the limit is not optional.
#pragma once
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace granlub::yade {

struct ProcessResult {
    int exit_code = -1;    // when it exited normally
    int signal = 0;        // when it was killed by a signal (0: not)
    bool timed_out = false;
    double seconds = 0;
    std::string describe() const;  // "exit code 3", "killed by signal 9", "timed out after 12 s"
};

// Full path of `name` (as given when it contains a '/', else searched on PATH), or nothing.
std::optional<std::filesystem::path> find_executable(const std::string& name);

// Runs argv[0] with argv[1..] in `workdir`, appending stdout and stderr to `log`. `poll` is
// called about 5 times per second while it runs (progress). Throws SolverError when it cannot
// be started.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& workdir,
                          const std::filesystem::path& log, double timeout_s,
                          const std::function<void()>& poll = {});

// The last `lines` lines of a text file (for error messages quoting a log).
std::string tail_lines(const std::filesystem::path& file, std::size_t lines);

}  // namespace granlub::yade
