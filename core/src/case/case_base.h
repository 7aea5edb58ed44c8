// [case] base: a case file that is a variant of another case. Its base's TOML is read first (and
// that base's own base before it: at most kMaxBaseChain bases under one file), then this file's tables
// are merged over it key by key:
//   - a key given here replaces the base's (a list as a whole: `speed = [2.0]` is one speed);
//   - a table given here ([cell], [walls.bottom], ...) is merged the same way, key by key;
//   - a table not given here is the base's;
//   - [case] is never inherited: name, title and base are this file's own (a twin without a name
//     takes its directory's, as every case).
// Nothing is removed: a key that must not apply takes the value that says "none", e.g. [cell]
// annulus_radius = 0.0 (no centripetal force) or width = 0.0 (periodic). Every merged value keeps
// the file it was read from, so messages about it name that file. A base path is relative to the
// file that names it; a directory means the case.toml in it.
#pragma once
#include <cstddef>
#include <vector>

#include <toml++/toml.h>

#include "case_file.h"

namespace granlub {

inline constexpr std::size_t kMaxBaseChain = 8;  // bases under one case: a bound, not a need

struct CaseWithBases {
    toml::table root;                // the file's table merged over its bases'
    std::vector<CaseFileText> bases;  // the bases read, nearest first (empty: no base)
};

// `root`, read from `source`, merged over its bases. Throws CaseError at the [case] base that names
// a missing or unreadable base, one that closes a cycle, or a chain longer than kMaxBaseChain.
CaseWithBases merge_bases(toml::table root, const std::string& source);

}  // namespace granlub
