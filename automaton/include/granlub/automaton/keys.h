// The [automaton] keys and the Params fields they set. Each key is declared once, in
// src/section.cpp, with its default, range and doc (the schema) and the field it fills; from that
// one line the case mapping reads it, validate() checks the field's range, Params() takes its
// default and the summary records it. A new key is its field in params.h and its line there.
// core's BoundKeys (granlub/case/bound_keys.h) is the same idea for [dem] and [yade], without the
// --full/--vtk pairing and the summary's getters this table needs.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "granlub/automaton/params.h"
#include "granlub/case/schema.h"

namespace granlub::automaton {

// One key and its field.
struct KeyBinding {
    std::string key;           // the case-file key
    std::string full_key;      // read instead with --full ("": the same key)
    bool only_with_vtk = false;  // read with --vtk only; Params holds 0 (none) otherwise
    bool output_only = false;    // changes what is written, not the numbers: not in the summary's settings
    std::function<void(Params&, const Value&)> set;
    std::function<Value(const Params&)> get;
};

struct AutomatonKeys {
    SectionSpec spec;
    std::vector<KeyBinding> bindings;
};

// The [automaton] section and its bindings (src/section.cpp).
const AutomatonKeys& automaton_keys();

// Which run the keys are read for: --full selects the *_full keys, --vtk the snapshot interval.
struct KeyUse {
    bool full = false;
    bool vtk = false;
};

// Sets every field whose key the section holds (given or defaulted).
void read_keys(Params& p, const Section& s, KeyUse use);

// The key a field's problem is reported against: `key`, or its *_full partner with --full.
std::string key_name(const std::string& key, KeyUse use);

}  // namespace granlub::automaton
