// The rule and protocol variants by name (variants.h). Adding one = its enum value in params.h,
// its rule, and one row here.
#include "granlub/automaton/variants.h"

namespace granlub::automaton {

namespace {
// The table, its names checked once, where it is built.
template <class E>
std::vector<Variant<E>> checked(std::vector<Variant<E>> table, const char* key) {
    registry_checked(table, key);
    return table;
}
}  // namespace

template <>
const std::vector<Variant<Mode>>& variants<Mode>() {
    static const auto t = checked<Mode>({{"jh", Mode::JH}, {"vector", Mode::Vector}}, "mode");
    return t;
}

template <>
const std::vector<Variant<TfRounding>>& variants<TfRounding>() {
    static const auto t = checked<TfRounding>(
        {{"round", TfRounding::Round}, {"ceil", TfRounding::Ceil}, {"accumulate", TfRounding::Accumulate}},
        "tf_rounding");
    return t;
}

template <>
const std::vector<Variant<WallSpeed>>& variants<WallSpeed>() {
    static const auto t = checked<WallSpeed>(
        {{"sequential", WallSpeed::Sequential}, {"by_incidence", WallSpeed::ByIncidence}}, "wall_speed");
    return t;
}

template <>
const std::vector<Variant<StruckDir>>& variants<StruckDir>() {
    static const auto t = checked<StruckDir>({{"line", StruckDir::Line}, {"keep", StruckDir::Keep}}, "struck_dir");
    return t;
}

template <>
const std::vector<Variant<VecBlocked>>& variants<VecBlocked>() {
    static const auto t =
        checked<VecBlocked>({{"deflect", VecBlocked::Deflect}, {"wait", VecBlocked::Wait}}, "vec_blocked");
    return t;
}

template <>
const std::vector<Variant<SteadyProtocol>>& variants<SteadyProtocol>() {
    static const auto t =
        checked<SteadyProtocol>({{"blocks", SteadyProtocol::Blocks}, {"runs", SteadyProtocol::Runs}}, "steady_state");
    return t;
}

}  // namespace granlub::automaton
