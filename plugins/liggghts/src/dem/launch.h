// Running granlub-liggghts on a deck: finding the driver, mpirun for several ranks, progress
// while it runs, and a clear error (with the log's ERROR line) when it fails.
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace granlub::dem {

// The driver: $GRANLUB_LIGGGHTS_DRIVER, else granlub-liggghts next to the running executable,
// else the one of the build tree, else on PATH. Throws SolverError listing where it looked.
std::filesystem::path find_driver();

struct EngineRun {
    double wall_clock_s = 0;
    double loop_time_s = 0;  // sum of LIGGGHTS' "Loop time of ..." lines (0 if none)
    int ranks = 1;
    std::vector<std::string> command;
};

// Runs `driver -in deck` in `dir` (on `np` ranks through mpirun when np > 1), stdout and stderr
// to dir/liggghts.out. `total_steps` and `progress_file` (lines of which count `steps_per_line`
// steps) drive the progress line. Throws SolverError on failure.
EngineRun run_engine(const std::filesystem::path& dir, const std::string& deck, int np, std::int64_t total_steps,
                     const std::string& progress_file, std::int64_t steps_per_line, const std::string& label);

}  // namespace granlub::dem
