// Sweeps side by side in one process: the locks taken once, and each point's readiness
// (granlub/run/pipeline.h).
#include "granlub/run/pipeline.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <map>
#include <mutex>
#include <set>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {

struct SolverState {
    std::set<std::string> finished;
    bool ended = false;
};

// The process's pipeline: which solvers it runs and how far each has got.
struct Board {
    std::mutex m;
    std::condition_variable changed;
    bool active = false;
    std::filesystem::path root;
    std::map<std::string, SolverState> solvers;
};

Board& board() {
    static Board b;
    return b;
}

std::vector<LockRequest> pipeline_locks(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers) {
    std::vector<LockRequest> locks;
    for (const auto& s : solvers)
        for (auto& l : point_locks(results_root(c, o), s, c.select(o.point), LockMode::Exclusive))
            locks.push_back(std::move(l));
    return locks;
}

// Registers the pipeline before its locks are taken (a second one is refused before it waits).
void register_pipeline(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers) {
    Board& b = board();
    std::lock_guard lock(b.m);
    if (b.active) throw Error("internal: a second sweep pipeline in one process");
    b.active = true;
    b.root = results_root(c, o);
    for (const auto& s : solvers) b.solvers[s] = {};
}

void unregister() {
    Board& b = board();
    std::lock_guard lock(b.m);
    b.active = false;
    b.solvers.clear();
    b.changed.notify_all();
}

ResultsLock take_locks(const Case& c, const RunOptions& o, const std::vector<std::string>& solvers) {
    register_pipeline(c, o, solvers);  // a second pipeline throws here, leaving the first as it was
    try {
        return ResultsLock(pipeline_locks(c, o, solvers), o.wait);
    } catch (...) {
        unregister();
        throw;
    }
}

}  // namespace

SweepPipeline::SweepPipeline(const Case& c, const RunOptions& o, std::vector<std::string> solvers)
    : locks_(take_locks(c, o, solvers)) {}

SweepPipeline::~SweepPipeline() { unregister(); }

namespace pipeline {

bool holds(const std::filesystem::path& results_root, const std::string& solver) {
    Board& b = board();
    std::lock_guard lock(b.m);
    return b.active && b.root == results_root && b.solvers.contains(solver);
}

namespace {
bool ready(const Board& b, const std::string& solver, const std::string& point) {
    if (!b.active) return true;
    const auto it = b.solvers.find(solver);
    return it == b.solvers.end() || it->second.ended || it->second.finished.contains(point);
}
}  // namespace

bool pending(const std::string& solver, const std::string& point) {
    Board& b = board();
    std::lock_guard lock(b.m);
    return !ready(b, solver, point);
}

void wait_for(const std::string& solver, const std::string& point) {
    Board& b = board();
    std::unique_lock lock(b.m);
    b.changed.wait(lock, [&] { return ready(b, solver, point); });
}

namespace {
// Applies `change` to `solver`'s state, if it is in the pipeline, and wakes the waiting points.
template <class Change>
void update(const std::string& solver, Change change) {
    Board& b = board();
    std::lock_guard lock(b.m);
    const auto it = b.solvers.find(solver);
    if (!b.active || it == b.solvers.end()) return;
    change(it->second);
    b.changed.notify_all();
}
}  // namespace

void finished(const std::string& solver, const std::string& point) {
    update(solver, [&](SolverState& st) { st.finished.insert(point); });
}

void ended(const std::string& solver) {
    update(solver, [](SolverState& st) { st.ended = true; });
}

}  // namespace pipeline

void lower_this_thread_priority(int steps) {
    const auto tid = static_cast<id_t>(::syscall(SYS_gettid));
    errno = 0;
    const int now = ::getpriority(PRIO_PROCESS, tid);
    if (errno != 0) return;
    if (::setpriority(PRIO_PROCESS, tid, std::min(19, now + steps)) != 0)  // not fatal: only slower
        fmt::print(stderr, "granlub: warning: could not lower the engines' priority: {}\n", std::strerror(errno));
}

}  // namespace granlub
