// Progress for long runs: a single updating line (done/total, rate, ETA and a free-text status)
// on a terminal; silent when stderr is not a terminal, so logs stay clean.
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
    static bool enabled();  // stderr is a terminal and GRANLUB_PROGRESS != 0

private:
    std::string label_;
    std::uint64_t total_;
    bool on_;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace granlub
