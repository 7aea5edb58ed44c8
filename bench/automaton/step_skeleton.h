// The floor under Engine::step() that bench_automaton's BM_StepSkeleton measures: one default-rule
// step (jh mode, round clock) that runs the shuffle, the clocks and every "does it move" decision
// exactly as step() does, but counts the move attempts instead of making them, so nothing moves or
// collides and the lattice is frozen. Its cost is what the update order and the clocks alone cost.
// Benchmark only (and its test); the engine reaches it through one friend declaration.
#pragma once
#include <cstdint>

#include "granlub/automaton/engine.h"

namespace granlub::automaton {

struct StepSkeleton {
    // One skeleton step; returns its number of move attempts.
    template <class Rng>
    static std::uint64_t step(Engine<Rng>& e) {
        using E = Engine<Rng>;
        e.skipped_attempts_ = 0;
        if (e.order_.size() > E::kPrefetchFrom) e.template run<Mode::JH, TfRounding::Round, true, false>();
        else e.template run<Mode::JH, TfRounding::Round, false, false>();
        return e.skipped_attempts_;
    }
};

}  // namespace granlub::automaton
