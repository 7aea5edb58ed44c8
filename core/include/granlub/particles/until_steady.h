// Until steady, with a cap: how a particle run that is not steady at its length is continued, and
// what its summary says of it. The engine continues the run from its own final state at the same
// time step (one longer run, cut into pieces); this file holds the policy and the record, so that
// every engine that continues runs does it alike.
//
// The run doubles: each piece is as long as all before it (1, 1, 2, 4 ... run lengths), until a
// piece is steady or the next would pass the cap. Not repeated pieces of one length: a window too
// short to resolve a drift stays too short however often it is repeated (measured on a 220-grain
// cell, 2026-11-26: 0.06 s pieces never passed the drift checks), and doubling makes the run as
// long as "run longer" would, at most twice what was needed. The last piece is judged and averaged
// alone; the earlier ones are its transient. [ASSUMPTION] doubling and the judging of the last
// piece alone are our choices.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "granlub/case/case.h"
#include "granlub/case/schema.h"

namespace granlub {

// The keys (time_max, time_max_full) are declared by add_until_steady_keys (particle_section.h).

// The cap of a run of `length` s (the section's `time` or `time_full`): 0 = off. Fails naming the
// key when it leaves no room for a continuation (neither 0 nor at least twice the length).
struct UntilSteadyCap {
    double time_max = 0;   // s
    std::string key;       // "[<section>] time_max" or "... time_max_full": a transient's hint names it
    // the cap in run lengths (floor(time_max / length)), for next_piece
    std::int64_t lengths(double length) const;
};
UntilSteadyCap until_steady_cap(const Section& s, bool full, double length);

// The next piece in run lengths, or 0 to stop: `done` run lengths simulated so far, the last piece
// steady or not, and the cap in run lengths (floor(time_max / run length); 0 = no continuation).
std::int64_t next_piece(bool steady, std::int64_t done, std::int64_t cap);

// What the run's summary records of a continued run.
struct Continuation {
    int pieces = 1;
    double earlier_s = 0;   // simulated time before the last piece
    double last_s = 0;      // the last piece's
    double time_max_s = 0;  // the cap
    std::string cap_key = "time_max";  // the key that sets it, for the transient's hint
};

// One piece of a run, as the engine reports it: steady or not, and its simulated time.
struct PieceRun {
    bool steady = false;
    double simulated_s = 0;
};

// The loop both engines run: piece(times, index) runs a piece `times` run lengths long (index 0:
// the run itself; after that, from the previous piece's final state), until a piece is steady or
// the next would pass the cap (`length`: the run's nominal length, s). Says on stderr when it
// continues (`label`: "dem U2.0"); returns the record for record_continuation().
Continuation continue_until_steady(const UntilSteadyCap& cap, double length, const std::string& label,
                                   const std::function<PieceRun(std::int64_t times, int index)>& piece);

// Writes run.continuation, counts run.steady_state_start_s from the run's start (the piece's
// pipeline counted it from the piece's), and, when the last piece is still not steady, the
// transient's reason with the cap that stopped it. `run` is the last piece's run record.
void record_continuation(nlohmann::json& run, const Continuation& k);

// What the console line of a continued run adds ("" for one piece): the line's times are the last
// piece's.
std::string continuation_note(const Continuation& k);

}  // namespace granlub
