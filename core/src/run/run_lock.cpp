// Locks on a case's results: flock(2) on <results>/.locks/<name>.lock, one per point (run_lock.h).
#include "granlub/run/run_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "granlub/results/results.h"
#include "granlub/text.h"

namespace granlub {

namespace {

// The holder line is written over the same bytes by each holder (shared holders may write at
// once): a fixed size, so one pwrite replaces the whole line and no tail of a longer one remains.
constexpr std::size_t kRecordBytes = 512;

std::string this_command() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    std::string raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::replace(raw.begin(), raw.end(), '\0', ' ');
    while (!raw.empty() && raw.back() == ' ') raw.pop_back();
    return raw.empty() ? "granlub" : raw;
}

std::string host_name() {
    char buf[256] = {};
    return ::gethostname(buf, sizeof buf - 1) == 0 ? std::string(buf) : std::string("?");
}

std::string holder_record(LockMode mode) {
    std::string line = fmt::format("pid {} on {} since {} ({}): {}", ::getpid(), host_name(), utc_now(),
                                   mode == LockMode::Exclusive ? "writing" : "reading", this_command());
    line = clipped(one_line(line), kRecordBytes - 40);
    line.resize(kRecordBytes - 1, ' ');
    return line + '\n';
}

std::string trimmed(std::string s) {
    while (!s.empty() && (s.back() == ' ' || s.back() == '\n' || s.back() == '\0')) s.pop_back();
    return s;
}

std::string read_holder(int fd) {
    std::string buf(kRecordBytes, '\0');
    const ssize_t n = ::pread(fd, buf.data(), buf.size(), 0);
    buf.resize(n > 0 ? static_cast<std::size_t>(n) : 0);
    return trimmed(std::move(buf));
}

// What a lock guards, for the waiting line and the error: "the dem results in <results>/dem/U1.4".
std::string guarded(const LockRequest& r) {
    const std::filesystem::path what = r.results_root / r.name;
    const std::string solver = std::filesystem::path(r.name).begin()->string();
    return r.name == "report" ? fmt::format("the report in {}", what.string())
                              : fmt::format("the {} results in {}", solver, what.string());
}

// flock is not supported here (some network and FUSE file systems): not a reason to refuse the run.
bool unsupported(int e) { return e == ENOLCK || e == EOPNOTSUPP || e == ENOSYS; }

int flock_retrying(int fd, int op) {
    int rc;
    do rc = ::flock(fd, op);
    while (rc != 0 && errno == EINTR);
    return rc;
}

// The test hook of run_lock.h: block until the test closes its end of the fifo.
void test_pause() {
    const char* fifo = std::getenv("GRANLUB_TEST_LOCK_PAUSE");
    if (!fifo || !*fifo) return;
    const int fd = ::open(fifo, O_RDONLY | O_CLOEXEC);
    if (fd < 0) return;
    char buf[64];
    for (;;) {
        const ssize_t n = ::read(fd, buf, sizeof buf);
        if (n == 0 || (n < 0 && errno != EINTR)) break;
    }
    ::close(fd);
}

}  // namespace

std::filesystem::path lock_file(const std::filesystem::path& results_root, const std::string& name) {
    return results_root / ".locks" / (name + ".lock");
}

LockRequest point_lock(const std::filesystem::path& results_root, const std::string& solver, const std::string& point,
                       LockMode mode) {
    return {results_root, solver + "/" + point, mode};
}

LockRequest seed_lock(const std::filesystem::path& results_root, const std::string& solver, const std::string& point,
                      std::uint64_t seed, LockMode mode) {
    return {results_root, fmt::format("{}/{}/seed-{}", solver, point, seed), mode};
}

std::vector<LockRequest> point_locks(const std::filesystem::path& results_root, const std::string& solver,
                                     const std::vector<const OperatingPoint*>& points, LockMode mode,
                                     const std::vector<std::uint64_t>& seeds) {
    std::vector<LockRequest> locks;
    for (const OperatingPoint* p : points) {
        if (seeds.empty()) locks.push_back(point_lock(results_root, solver, p->id, mode));
        for (const std::uint64_t s : seeds) locks.push_back(seed_lock(results_root, solver, p->id, s, mode));
    }
    return locks;
}

std::string lock_holder(const std::filesystem::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return "";
    std::string h = read_holder(fd);
    ::close(fd);
    return h;
}

ResultsLock::ResultsLock(std::vector<LockRequest> locks, bool wait) {
    try {
        take(std::move(locks), wait);
    } catch (...) {
        release();  // the locks taken before the one that failed: no destructor runs for them
        throw;
    }
}

namespace {

// The lock file's descriptor, O_CLOEXEC: an engine exec'd while the lock is held must not keep it
// alive after granlub. `can_record`: open for writing (another user's file is opened read-only,
// which flock accepts, and its holder line is left as it is).
int open_lock_file(const LockRequest& r, bool& can_record) {
    const auto file = lock_file(r.results_root, r.name);
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    can_record = fd >= 0;
    if (fd < 0 && errno == EACCES) fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        const int e = errno;
        throw Error(fmt::format("{}: cannot open the lock file: {} (granlub locks {} while a run uses them)",
                                file.string(), std::strerror(e), guarded(r)));
    }
    return fd;
}

// Locks fd in mode `op`: at once when free; else waits, saying for whom, or (no `wait`) throws
// ResultsInUse. False when the file system cannot lock (warned once): the run goes on unlocked.
bool lock_or_wait(int fd, int op, const LockRequest& r, bool wait) {
    const auto file = lock_file(r.results_root, r.name).string();
    if (flock_retrying(fd, op | LOCK_NB) == 0) return true;
    const int e = errno;
    if (unsupported(e)) {
        static std::atomic<bool> warned{false};
        if (!warned.exchange(true))
            fmt::print(stderr,
                       "granlub: warning: {}: this file system cannot lock files ({}); running without a lock: do "
                       "not start another run on these results until this one ends\n",
                       file, std::strerror(e));
        return false;
    }
    if (e != EWOULDBLOCK) throw Error(fmt::format("{}: cannot lock: {}", file, std::strerror(e)));
    const std::string holder = read_holder(fd);
    const std::string who = holder.empty() ? "another run (it has not yet said which)" : holder;
    if (!wait)
        throw ResultsInUse(fmt::format("{} are in use by {} ({}); not waiting (--no-wait; without it granlub waits "
                                       "for that run to end)",
                                       guarded(r), who, file));
    fmt::print(stderr, "granlub: waiting for {}: in use by {} ({}; --no-wait fails instead)\n", guarded(r), who, file);
    std::fflush(stderr);
    const auto t0 = std::chrono::steady_clock::now();
    if (flock_retrying(fd, op) != 0) {
        const int e2 = errno;
        throw Error(fmt::format("{}: cannot lock: {}", file, std::strerror(e2)));
    }
    fmt::print(stderr, "granlub: {} free after {:.0f} s, going on\n", guarded(r),
               std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    return true;
}

// One descriptor a lock, held together: a sweep of many points (a case may have 10 000) needs more
// than the usual soft limit of 1024, so the soft limit is raised towards the hard one when needed.
void make_room_for(std::size_t descriptors) {
    rlimit lim{};
    if (::getrlimit(RLIMIT_NOFILE, &lim) != 0) return;
    const rlim_t want = static_cast<rlim_t>(descriptors) + 256;  // the engines' pipes, logs and files
    if (lim.rlim_cur == RLIM_INFINITY || lim.rlim_cur >= want) return;
    lim.rlim_cur = lim.rlim_max == RLIM_INFINITY ? want : std::min(want, lim.rlim_max);
    ::setrlimit(RLIMIT_NOFILE, &lim);  // where it fails, opening a lock file says why
}

}  // namespace

void ResultsLock::take(std::vector<LockRequest> locks, bool wait) {
    // one order for every run; the same file asked for twice is taken once, in the stronger mode
    const auto file_of = [](const LockRequest& r) { return lock_file(r.results_root, r.name); };
    std::sort(locks.begin(), locks.end(), [&](const auto& a, const auto& b) { return file_of(a) < file_of(b); });
    for (std::size_t i = 1; i < locks.size();)
        if (file_of(locks[i]) == file_of(locks[i - 1])) {
            if (locks[i].mode == LockMode::Exclusive) locks[i - 1].mode = LockMode::Exclusive;
            locks.erase(locks.begin() + static_cast<std::ptrdiff_t>(i));
        } else {
            ++i;
        }
    make_room_for(locks.size());
    bool writes = false;
    for (const LockRequest& r : locks) {
        bool can_record = false;
        const int fd = open_lock_file(r, can_record);
        fds_.push_back(fd);  // closed by release(), also when this or a later lock throws
        if (!lock_or_wait(fd, r.mode == LockMode::Exclusive ? LOCK_EX : LOCK_SH, r, wait)) continue;
        if (can_record) {
            const std::string rec = holder_record(r.mode);
            [[maybe_unused]] const ssize_t n = ::pwrite(fd, rec.data(), rec.size(), 0);
        }
        writes = writes || r.mode == LockMode::Exclusive;
    }
    if (writes) test_pause();
}

ResultsLock::ResultsLock(ResultsLock&& other) noexcept : fds_(std::move(other.fds_)) { other.fds_.clear(); }

ResultsLock::~ResultsLock() { release(); }

void ResultsLock::release() noexcept {
    for (const int fd : fds_) {
        ::flock(fd, LOCK_UN);  // also for a copy of the descriptor in a child between fork and exec
        ::close(fd);
    }
    fds_.clear();
}

}  // namespace granlub
