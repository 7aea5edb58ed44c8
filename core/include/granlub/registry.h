// One way to register alternatives (a g0 form, a wall family, a solver module): a table of rows,
// each with a `name` (the case-file value or subcommand), looked up here with one error message,
// as LAMMPS' gran_sub_mod_register.cpp keeps one row per granular sub-model. Adding an
// alternative is its own file plus one row in its table.
#pragma once
#include <algorithm>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "granlub/error.h"

namespace granlub {

// The names of a table's rows, in table order.
template <class Row>
std::vector<std::string> registry_names(const std::vector<Row>& table) {
    std::vector<std::string> names;
    for (const Row& r : table) names.emplace_back(r.name);
    return names;
}

// {old_name, name} for every row with an old spelling (a Row::old_name that is not null): what a
// case-file key still accepts (SectionSpec::old_spellings).
template <class Row>
std::vector<std::pair<std::string, std::string>> registry_old_names(const std::vector<Row>& table) {
    std::vector<std::pair<std::string, std::string>> out;
    for (const Row& r : table)
        if (r.old_name) out.emplace_back(r.old_name, r.name);
    return out;
}

// The row called `name`; throws Error `unknown <what> "<name>" (allowed: a, b, ...)` otherwise.
template <class Row>
const Row& registry_find(const std::vector<Row>& table, std::string_view name, std::string_view what) {
    const auto it = std::find_if(table.begin(), table.end(), [&](const Row& r) { return name == r.name; });
    if (it != table.end()) return *it;
    std::string allowed;
    for (const Row& r : table) allowed += std::string(allowed.empty() ? "" : ", ") + std::string(r.name);
    throw Error("unknown " + std::string(what) + " \"" + std::string(name) + "\" (allowed: " + allowed + ")");
}

// Checks a table once, where it is built: names non-empty and unique. Returns the table.
template <class Row>
const std::vector<Row>& registry_checked(const std::vector<Row>& table, std::string_view what) {
    std::set<std::string, std::less<>> seen;
    for (const Row& r : table) {
        const std::string n(r.name);
        if (n.empty() || !seen.insert(n).second)
            throw Error("internal: " + std::string(what) + " registry has an empty or repeated name \"" + n + "\"");
    }
    return table;
}

}  // namespace granlub
