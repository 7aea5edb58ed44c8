#include "granlub/progress.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <unistd.h>

#include <fmt/format.h>

namespace granlub {

bool Progress::enabled() {
    const char* env = std::getenv("GRANLUB_PROGRESS");
    if (env && std::strcmp(env, "0") == 0) return false;
    return ::isatty(STDERR_FILENO) == 1;
}

Progress::Progress(std::string label, std::uint64_t total)
    : label_(std::move(label)), total_(total), on_(enabled()), start_(std::chrono::steady_clock::now()),
      last_(start_ - std::chrono::seconds(1)) {}

Progress::~Progress() {
    if (on_) fmt::print(stderr, "\r\033[K");
}

void Progress::update(std::uint64_t done, const std::string& status) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200) && done < total_) return;
    last_ = now;
    const double el = std::chrono::duration<double>(now - start_).count();
    const double frac = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 0.0;
    std::string eta = "--";
    if (frac > 0.0 && frac < 1.0) {
        const double rem = el * (1.0 - frac) / frac;
        eta = rem >= 60 ? fmt::format("{}m{:02d}s", static_cast<int>(rem) / 60, static_cast<int>(rem) % 60)
                        : fmt::format("{:.0f}s", rem);
    }
    fmt::print(stderr, "\r\033[K{} {:5.1f}% ({}/{})  ETA {}  {}", label_, 100.0 * frac, done, total_, eta, status);
    std::fflush(stderr);
}

}  // namespace granlub
