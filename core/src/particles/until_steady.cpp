// Until steady, with a cap (until_steady.h).
#include "granlub/particles/until_steady.h"

#include <cmath>

#include <fmt/format.h>

#include "granlub/results/run_status.h"

namespace granlub {

std::int64_t UntilSteadyCap::lengths(double length) const {
    return length > 0 ? static_cast<std::int64_t>(std::floor(time_max / length + 1e-9)) : 0;
}

UntilSteadyCap until_steady_cap(const Section& s, bool full, double length) {
    const std::string key = full ? "time_max_full" : "time_max";
    UntilSteadyCap c{s.real(key), "[" + s.name() + "] " + key};
    if (c.time_max > 0 && c.time_max < 2 * length * (1 - 1e-9))
        s.fail(key, fmt::format("{:g} s leaves no room to continue a run of {:g} s ({}): 0 (off) or at least twice "
                                "the run's length",
                                c.time_max, length, full ? "time_full" : "time"));
    return c;
}

std::int64_t next_piece(bool steady, std::int64_t done, std::int64_t cap) {
    if (steady || done < 1 || cap - done < done) return 0;
    return done;
}

Continuation continue_until_steady(const UntilSteadyCap& cap, double length, const std::string& label,
                                   const std::function<PieceRun(std::int64_t times, int index)>& piece) {
    Continuation k{.time_max_s = cap.time_max, .cap_key = cap.key};
    const std::int64_t lengths = cap.lengths(length);
    std::int64_t times = 1, done = 0;
    for (;;) {
        const PieceRun run = piece(times, k.pieces - 1);
        k.last_s = run.simulated_s;
        done += times;
        times = next_piece(run.steady, done, lengths);
        if (times == 0) return k;
        k.earlier_s += k.last_s;
        ++k.pieces;
        fmt::print(stderr, "{}: not steady after {:.3g} s; continuing from its end for {:.3g} s ({} {:g} s)\n", label,
                   k.earlier_s, static_cast<double>(times) * length, k.cap_key, k.time_max_s);
    }
}

void record_continuation(nlohmann::json& run, const Continuation& k) {
    const double total = k.earlier_s + k.last_s;
    run["continuation"] = {{"pieces", k.pieces},
                           {"last_piece_s", k.last_s},
                           {"earlier_s", k.earlier_s},
                           {"simulated_s", total},
                           {"time_max_s", k.time_max_s},
                           {"rule", "not steady: continued from its end by a piece as long as the run so far, until a "
                                    "piece is steady or the next would pass time_max"},
                           {"reported", "the last piece (this folder's files); the earlier ones are the transient"}};
    if (run.contains("steady_state_start_s") && run["steady_state_start_s"].is_number())
        run["steady_state_start_s"] = run["steady_state_start_s"].get<double>() + k.earlier_s;
    if (!run.value("steady_state_detected", false))
        set_regime(run, RegimeStatus::Transient,
                   fmt::format("no steady state detected in {:.3g} s of simulated time (the last {:.3g} s judged; the "
                               "next piece would pass {} = {:g} s): raise {}",
                               total, k.last_s, k.cap_key, k.time_max_s, k.cap_key));
}

std::string continuation_note(const Continuation& k) {
    if (k.pieces < 2) return "";
    return fmt::format(" [continued until steady: the last {:.3g} s of {:.3g} s, its times counted from its start]",
                       k.last_s, k.earlier_s + k.last_s);
}

}  // namespace granlub
