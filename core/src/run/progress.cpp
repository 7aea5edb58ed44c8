#include "granlub/run/progress.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <unistd.h>

#include <fmt/format.h>

namespace granlub {

bool Progress::enabled() {
    const char* env = std::getenv("GRANLUB_PROGRESS");
    return !(env && std::strcmp(env, "0") == 0);
}

namespace {
constexpr auto kRedraw = std::chrono::milliseconds(200);  // a terminal's line
}  // namespace

Progress::Progress(std::string label, std::uint64_t total, std::chrono::milliseconds log_every)
    : label_(std::move(label)),
      total_(total),
      on_(enabled()),
      terminal_(::isatty(STDERR_FILENO) == 1),
      log_every_(log_every),
      start_(std::chrono::steady_clock::now()),
      last_(terminal_ ? start_ - std::chrono::seconds(1) : start_) {}

Progress::~Progress() {
    if (on_ && terminal_) fmt::print(stderr, "\r\033[K");
}

std::chrono::milliseconds Progress::interval() const {
    return terminal_ ? kRedraw : log_every_;
}

bool Progress::due() const {
    return on_ && std::chrono::steady_clock::now() - last_ >= interval();
}

void Progress::update(std::uint64_t done, const std::string& status) {
    if (!on_) return;
    const auto now = std::chrono::steady_clock::now();
    // a terminal's line also shows the end; a log's lines keep their interval
    if (now - last_ < interval() && !(terminal_ && done >= total_)) return;
    last_ = now;
    const double el = std::chrono::duration<double>(now - start_).count();
    const double frac = total_ ? static_cast<double>(done) / static_cast<double>(total_) : 0.0;
    std::string eta = "--";
    if (frac > 0.0 && frac < 1.0) {
        const double rem = el * (1.0 - frac) / frac;
        eta = rem >= 60 ? fmt::format("{}m{:02d}s", static_cast<int>(rem) / 60, static_cast<int>(rem) % 60)
                        : fmt::format("{:.0f}s", rem);
    }
    fmt::print(stderr, "{}{} {:5.1f}% ({}/{})  ETA {}  {}{}", terminal_ ? "\r\033[K" : "", label_, 100.0 * frac, done,
               total_, eta, status, terminal_ ? "" : "\n");
    std::fflush(stderr);
}

}  // namespace granlub
