// The [automaton] keys and the Params fields they set. Each key is declared once, in
// src/section.cpp, through core's BoundKeys (granlub/case/bound_keys.h) as [continuum], [dem] and
// [yade] are, with its default, range and doc (the schema) and the field it fills; from that one
// line the case mapping reads it (read(): --full reads its *_full partner, --vtk the snapshot
// interval), validate() checks the field's range, Params() takes its default and the summary
// records it (get()). A new key is its field in params.h and its line there.
#pragma once
#include "granlub/automaton/params.h"
#include "granlub/case/bound_keys.h"

namespace granlub::automaton {

// The [automaton] section and its bindings (src/section.cpp).
const BoundKeys<Params>& automaton_keys();

}  // namespace granlub::automaton
