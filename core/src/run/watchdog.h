// The guard that makes an engine die with granlub, however granlub ends (kill -9, Ctrl-C, a
// crash). run_process forks it before the engine; it leads a new process group which the engine
// joins, and holds one end of a socket whose other end only granlub holds.
//
// Why a process and not PR_SET_PDEATHSIG: the death signal reaches only the direct child (mpirun),
// and SIGKILL of mpirun leaves its ranks running (Open MPI puts each rank in its own group). A
// socket's end-of-file reaches the watchdog whatever ends granlub, and the watchdog then sends
// SIGTERM to the group (mpirun forwards it to its ranks), waits a grace time, sends SIGKILL.
// Leading the group itself means the group id cannot be reused by an unrelated process while the
// watchdog lives, so it never signals a stranger.
#pragma once
#include <sys/types.h>

namespace granlub {

class Watchdog {
public:
    Watchdog();  // forks the watchdog; throws SolverError when it cannot
    ~Watchdog();  // dismiss()
    Watchdog(const Watchdog&) = delete;
    Watchdog& operator=(const Watchdog&) = delete;

    // The process group for the engine: setpgid(engine, group()).
    pid_t group() const { return pid_; }

    // granlub is done with the group (the engine is reaped): the watchdog exits without killing
    // anything, and is reaped. Idempotent.
    void dismiss();

private:
    pid_t pid_ = -1;
    int fd_ = -1;
};

}  // namespace granlub
