// The rule and protocol variants by name (variants.h). Adding one = its enum value in params.h,
// its rule, and one row here.
#include "granlub/automaton/variants.h"

#include <initializer_list>

namespace granlub::automaton {

namespace {
// The table of E, built and its names checked once, on first use (one table per enum, so the
// function-local static is that table).
template <class E>
const std::vector<Variant<E>>& once(std::initializer_list<Variant<E>> rows, const char* key) {
    static const std::vector<Variant<E>> table = [&] {
        std::vector<Variant<E>> t(rows);
        registry_checked(t, key);
        return t;
    }();
    return table;
}
}  // namespace

template <>
const std::vector<Variant<Mode>>& variants<Mode>() {
    return once<Mode>({{"jh", Mode::JH}, {"vector", Mode::Vector}}, "mode");
}
template <>
const std::vector<Variant<TfRounding>>& variants<TfRounding>() {
    return once<TfRounding>(
        {{"round", TfRounding::Round}, {"ceil", TfRounding::Ceil}, {"accumulate", TfRounding::Accumulate}},
        "tf_rounding");
}
template <>
const std::vector<Variant<WallSpeed>>& variants<WallSpeed>() {
    return once<WallSpeed>({{"sequential", WallSpeed::Sequential}, {"by_incidence", WallSpeed::ByIncidence}},
                           "wall_speed");
}
template <>
const std::vector<Variant<StruckDir>>& variants<StruckDir>() {
    return once<StruckDir>({{"line", StruckDir::Line}, {"keep", StruckDir::Keep}}, "struck_dir");
}
template <>
const std::vector<Variant<VecBlocked>>& variants<VecBlocked>() {
    return once<VecBlocked>({{"deflect", VecBlocked::Deflect}, {"wait", VecBlocked::Wait}}, "vec_blocked");
}
template <>
const std::vector<Variant<SteadyProtocol>>& variants<SteadyProtocol>() {
    return once<SteadyProtocol>({{"blocks", SteadyProtocol::Blocks}, {"runs", SteadyProtocol::Runs}}, "steady_state");
}

}  // namespace granlub::automaton
