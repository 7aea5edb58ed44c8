// Locks on a case's results, so that two runs cannot write one solver's results at once and
// `compare` does not read them while a run writes them (issue 34: two sweeps on one case left a
// point with seed 1's summary.json beside seed 2's profile.csv).
//
// One lock file per solver's results and one for the report: <results>/.locks/<name>.lock.
// A run that writes takes its lock exclusively (a sweep: its solver's; `compare`: the report's);
// a run that reads results it does not write takes theirs shared (`compare`: every solver's;
// `granlub yade` with a warm start: dem's). Runs on different solvers or cases never meet.
//
// flock(2), not a pid file: the kernel drops the lock when the process ends however it ends, so
// kill -9 leaves nothing stale. The descriptor is O_CLOEXEC, so the engines that process.cpp
// execs never hold it (and the engine watchdog closes all it inherits): nothing outlives granlub.
// On NFS, Linux (>= 2.6.12) emulates flock with fcntl byte-range locks, which hold across clients
// when the server supports locking; where flock fails as unsupported, granlub warns once and runs
// without that lock (README, "reliability").
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/error.h"

namespace granlub {

enum class LockMode { Shared, Exclusive };

struct LockRequest {
    std::filesystem::path results_root;
    std::string name;  // a solver ("dem") or "report"
    LockMode mode = LockMode::Exclusive;
};

// A lock is held by another run and this one was told not to wait (--no-wait): exit 2.
class ResultsInUse : public Error {
public:
    using Error::Error;
};

// Holds its locks from construction to destruction.
class ResultsLock {
public:
    // Takes every lock, in the order of their files' paths (any two runs take shared locks in the
    // same order, so neither can hold what the other waits for). A lock held elsewhere: with
    // `wait`, one line on stderr names the holder (pid, host, since when, command) and the run
    // waits; without, throws ResultsInUse with that line. Throws Error when a lock file cannot be
    // opened (a results folder granlub could not write anyway).
    //
    // Test hook: with GRANLUB_TEST_LOCK_PAUSE=<fifo> in the environment, a run that took an
    // exclusive lock reads <fifo> to its end before going on, so a test can hold a run inside its
    // lock and release it when it chooses (tests/cli/test_run_lock.cpp).
    ResultsLock(std::vector<LockRequest> locks, bool wait);
    ~ResultsLock();
    ResultsLock(ResultsLock&& other) noexcept;
    ResultsLock& operator=(ResultsLock&&) = delete;
    ResultsLock(const ResultsLock&) = delete;
    ResultsLock& operator=(const ResultsLock&) = delete;

private:
    void take(std::vector<LockRequest> locks, bool wait);
    void release() noexcept;
    std::vector<int> fds_;
};

std::filesystem::path lock_file(const std::filesystem::path& results_root, const std::string& name);

// The line the last holder wrote into a lock file: "pid 4242 on node7 since <UTC> (writing):
// granlub automaton cases/x --seed 1"; "" when none is recorded.
std::string lock_holder(const std::filesystem::path& file);

}  // namespace granlub
