// Locks on a case's results, so that two runs cannot write one point's results at once and
// `compare` does not read them while a run writes them (issue 34: two sweeps on one case left a
// point with seed 1's summary.json beside seed 2's profile.csv), while runs on different points
// of one case (two terminals, the tasks of a cluster job array over a shared filesystem) go on
// side by side (issue 76).
//
// One lock file per thing a run writes, named as its path under the results folder:
// <results>/.locks/<name>.lock, where <name> is
//   <solver>/<point>            the point's folder (its top-level files: profile.csv, summary.json)
//   <solver>/<point>/seed-<S>   one realisation of a point run with a set of more than one seed
//   report                      the report
//   continuum/map.csv           the continuum's (U, P) map
// A run that writes takes its locks exclusively (a sweep: each selected point's, or with a set of
// seeds each realisation's it runs; `compare`: the report's); a run that reads results it does not
// write takes theirs shared (`compare`: each point it reads; `granlub yade` with a warm start:
// dem's same points, or with a set of seeds dem's same realisations). Runs on different points,
// solvers or cases never meet.
//
// flock(2), not a pid file: the kernel drops the lock when the process ends however it ends, so
// kill -9 leaves nothing stale. The descriptor is O_CLOEXEC, so the engines that process.cpp
// execs never hold it (and the engine watchdog closes all it inherits): nothing outlives granlub.
// On NFS, Linux (>= 2.6.12) emulates flock with fcntl byte-range locks, which hold across clients
// when the server supports locking; where flock fails as unsupported, granlub warns once and runs
// without that lock (README, "reliability").
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/error.h"

namespace granlub {

enum class LockMode { Shared, Exclusive };

struct LockRequest {
    std::filesystem::path results_root;
    std::string name;  // what it guards, as a path under results_root: "dem/U1.4", "report" (above)
    LockMode mode = LockMode::Exclusive;
};

// The lock on `point`'s folder of `solver` (with one seed, the whole run of that point; with a set
// of seeds, the pooled top-level files).
LockRequest point_lock(const std::filesystem::path& results_root, const std::string& solver, const std::string& point,
                       LockMode mode);
// The lock on realisation `seed` of `point` (results/<solver>/<point>/seed-<S>/).
LockRequest seed_lock(const std::filesystem::path& results_root, const std::string& solver, const std::string& point,
                      std::uint64_t seed, LockMode mode);
// The locks of a run on `points` of `solver`: each point's (`seeds` empty: the layout of one seed),
// or each of the realisations `seeds` of each point (a set of more than one seed: the members the
// run writes or reads).
std::vector<LockRequest> point_locks(const std::filesystem::path& results_root, const std::string& solver,
                                     const std::vector<const OperatingPoint*>& points, LockMode mode,
                                     const std::vector<std::uint64_t>& seeds = {});

// A lock is held by another run and this one was told not to wait (--no-wait): exit 2.
class ResultsInUse : public Error {
public:
    using Error::Error;
};

// Holds its locks from construction to destruction.
class ResultsLock {
public:
    // Takes every lock, in the order of their files' paths (any two runs take their locks in the
    // same order, so neither can hold what the other waits for; a run that takes more locks while
    // it holds some takes only files later in that order: a point's pooling lock after its
    // realisations', <point>/seed-<S>.lock sorting before <point>.lock). A lock held elsewhere: with
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
