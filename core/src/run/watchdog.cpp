#include "watchdog.h"

#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <ctime>

#include <fmt/format.h>

#include "granlub/error.h"

namespace granlub {

namespace {

constexpr char kQuit = 'q';
constexpr int kGraceSeconds = 2;  // between SIGTERM and SIGKILL: mpirun needs it to stop its ranks

// The watchdog's whole life. Only system calls (the parent may have had other threads at fork).
[[noreturn]] void watch(int fd) {
    // Not an orphan to be stopped by the terminal or by a kill of the group: only end-of-file ends it.
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    for (const int s : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE}) ::sigaction(s, &ignore, nullptr);
    // Hold nothing but the socket: no log, no terminal, no pipe of granlub's caller (whose reader
    // would wait for it), no other run's socket (which would hide granlub's death from its watchdog).
    if (fd != 0) ::dup2(fd, 0);
    ::close_range(1, ~0U, 0);
    [[maybe_unused]] const int cd = ::chdir("/");

    char c = 0;
    ssize_t n;
    do n = ::read(0, &c, 1);
    while (n < 0 && errno == EINTR);
    if (n == 1 && c == kQuit) ::_exit(0);

    // granlub is gone: stop the group, then kill what is left (this process included).
    const pid_t group = ::getpgrp();
    ::kill(-group, SIGTERM);
    timespec t{kGraceSeconds, 0};
    while (::nanosleep(&t, &t) != 0 && errno == EINTR) {}
    ::kill(-group, SIGKILL);
    ::_exit(0);
}

}  // namespace

Watchdog::Watchdog() {
    int sv[2];
    // a socket rather than a pipe: send() with MSG_NOSIGNAL cannot raise SIGPIPE in granlub
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
        throw SolverError(fmt::format("cannot start the engine watchdog: socketpair: {}", std::strerror(errno)));
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        ::close(sv[0]);
        ::close(sv[1]);
        throw SolverError(fmt::format("cannot start the engine watchdog: fork: {}", std::strerror(e)));
    }
    if (pid == 0) {
        ::setpgid(0, 0);
        watch(sv[1]);
    }
    ::setpgid(pid, pid);  // also here: the engine may join the group before the child ran setpgid
    ::close(sv[1]);
    pid_ = pid;
    fd_ = sv[0];
}

Watchdog::~Watchdog() { dismiss(); }

void Watchdog::dismiss() {
    if (pid_ < 0) return;
    const char quit = kQuit;
    ::send(fd_, &quit, 1, MSG_NOSIGNAL);  // fails harmlessly when the watchdog was killed with the group
    ::close(fd_);
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {}
    pid_ = -1;
    fd_ = -1;
}

}  // namespace granlub
