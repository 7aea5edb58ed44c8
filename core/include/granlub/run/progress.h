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
    // log_every: the interval of a log's lines (tests shorten it)
    Progress(std::string label, std::uint64_t total, std::chrono::milliseconds log_every = std::chrono::minutes(1));
    ~Progress();  // clears a terminal's line
    // Cheap to call often: redraws a terminal's line at most ~5 times per second.
    void update(std::uint64_t done, const std::string& status = "");
    // Whether an update now would print: lets a caller skip the work of counting progress.
    bool due() const;
    static bool enabled();  // GRANLUB_PROGRESS != 0 (a terminal or a log)

private:
    std::chrono::milliseconds interval() const;  // between a terminal's redraws or a log's lines
    std::string label_;
    std::uint64_t total_;
    bool on_;
    bool terminal_;  // redraw one line; otherwise append a line every log_every_
    std::chrono::milliseconds log_every_;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace granlub
