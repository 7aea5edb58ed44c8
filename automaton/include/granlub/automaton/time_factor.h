// JH06's time factor (docs/automaton-model.md §2.4): a grain of speed u_p moves once every
// TF = round_half_up(U/u_p) of its updates (or ceil, or a continuous-rate progress counter),
// capped at tf_max; below U/tf_max it is at rest. Lattice units, U = 1.
#pragma once
#include <type_traits>

#include "granlub/automaton/params.h"

namespace granlub::automaton {

// Does a grain of speed u (>= 1/tf_max) move when its clock reaches c (an integer >= 1)? I.e.
// c >= TF(u). Written with a multiplication instead of a division: for integer c,
// c >= floor(1/u + 1/2) <=> u (c + 1/2) > 1, and c >= ceil(1/u) <=> u c >= 1.
template <TfRounding T>
bool fires(double c, double u, double tf_max) {
    return (c >= tf_max) | (T == TfRounding::Ceil ? u * c >= 1.0 : u * (c + 0.5) > 1.0);
}

// The clock: an integer count of updates (round, ceil) or the progress counter (accumulate).
template <TfRounding T>
using ClockOf = std::conditional_t<T == TfRounding::Accumulate, double, unsigned>;

// One update's clock rule. A grain at rest (u < rest = 1/tf_max) never starts a move and keeps its
// clock; it can still be struck [ASSUMPTION]. Otherwise the clock advances and the grain moves ("go",
// returned) when its time factor is up; k1 is the clock after this update. Selects, not branches.
template <TfRounding T>
bool clock_decides(double u, ClockOf<T> k0, ClockOf<T>& k1, double rest, double tf_max) {
    const bool moving = u >= rest;
    bool go;
    if constexpr (T == TfRounding::Accumulate) {  // continuous rate, cf. the Gutt-Haff lattice grain model
        const double a = k0 + u;
        go = moving && a >= 1.0;
        k1 = !moving ? k0 : (go ? a - 1.0 : a);
    } else {  // TF = round(U/u_p) [JH06 §CA]: move once every TF updates
        const unsigned t = k0 + 1u;
        go = moving && fires<T>(static_cast<double>(t), u, tf_max);
        k1 = !moving ? k0 : (go ? 0u : t);
    }
    return go;
}

}  // namespace granlub::automaton
