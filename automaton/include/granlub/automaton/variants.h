// The named variants of the automaton's rules and protocols, one table per switch ([automaton]
// mode, tf_rounding, wall_speed, struck_dir, vec_blocked, steady_state): each row is a case-file
// value and its enum. The section takes its choices and defaults from these tables, the case
// mapping looks values up in them and the summary writes names back from them, through core's
// registry helpers (granlub/registry.h) as the continuum's g0 and wall registries do: a variant
// is spelled once, in src/variants.cpp.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "granlub/automaton/params.h"
#include "granlub/error.h"
#include "granlub/registry.h"

namespace granlub::automaton {

template <class E>
struct Variant {
    const char* name;  // the case-file value
    E value;
};

// The table of one switch (defined in variants.cpp for each enum of params.h).
template <class E>
const std::vector<Variant<E>>& variants();
template <> const std::vector<Variant<Mode>>& variants<Mode>();
template <> const std::vector<Variant<TfRounding>>& variants<TfRounding>();
template <> const std::vector<Variant<WallSpeed>>& variants<WallSpeed>();
template <> const std::vector<Variant<StruckDir>>& variants<StruckDir>();
template <> const std::vector<Variant<VecBlocked>>& variants<VecBlocked>();
template <> const std::vector<Variant<SteadyProtocol>>& variants<SteadyProtocol>();

template <class E>
std::vector<std::string> variant_names() {
    return registry_names(variants<E>());
}

// The variant called `name`; throws Error "unknown <key> ..." naming the allowed values.
template <class E>
E variant(std::string_view name, std::string_view key) {
    return registry_find(variants<E>(), name, key).value;
}

// The case-file value of `e`.
template <class E>
const char* variant_name(E e) {
    for (const auto& v : variants<E>())
        if (v.value == e) return v.name;
    throw Error("internal: an automaton variant without a name");
}

}  // namespace granlub::automaton
