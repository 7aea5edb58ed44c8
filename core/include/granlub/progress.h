// Progress for long runs: a single updating line (done/total, ETA and a free-text status) on a
// terminal. When stderr is not a terminal (a log file, CI), a plain line once a minute, so a
// 30-minute run leaves a trace in its log and a short one leaves none. GRANLUB_PROGRESS=0: silent.
#pragma once
#include <chrono>
#include <cstdint>
#include <string>

namespace granlub {

class Progress {
public:
    Progress(std::string label, std::uint64_t total);
    ~Progress();  // clears the line
    // Cheap to call often: redraws at most ~5 times per second.
    void update(std::uint64_t done, const std::string& status = "");
    static bool enabled();  // GRANLUB_PROGRESS != 0 (a terminal or a log)

private:
    std::string label_;
    std::uint64_t total_;
    bool on_;
    bool terminal_;  // redraw one line; otherwise append a line once a minute
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace granlub
