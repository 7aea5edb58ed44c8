// Run-time switches as compile-time constants: with_constant(value, f) calls f with a
// std::integral_constant holding `value`, so that one generic lambda instantiates the step loop for
// every combination instead of one hand-written call per combination.
#pragma once
#include <type_traits>

#include "granlub/automaton/params.h"

namespace granlub::automaton {

template <class F>
decltype(auto) with_constant(bool b, F&& f) {
    return b ? f(std::true_type{}) : f(std::false_type{});
}

template <class F>
decltype(auto) with_constant(Mode m, F&& f) {
    if (m == Mode::JH) return f(std::integral_constant<Mode, Mode::JH>{});
    return f(std::integral_constant<Mode, Mode::Vector>{});
}

template <class F>
decltype(auto) with_constant(TfRounding t, F&& f) {
    if (t == TfRounding::Accumulate) return f(std::integral_constant<TfRounding, TfRounding::Accumulate>{});
    if (t == TfRounding::Ceil) return f(std::integral_constant<TfRounding, TfRounding::Ceil>{});
    return f(std::integral_constant<TfRounding, TfRounding::Round>{});
}

}  // namespace granlub::automaton
