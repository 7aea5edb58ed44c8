// A solver's section whose keys each name the settings field they fill: the key is declared once
// (default, range, unit, doc: the schema) with its field, and reading the section is one loop
// (read()), not a line per key in the solver's settings code. A new plain key is its field and its
// line. Keys that need a conversion (a choice to an enum, a run length derived from several keys)
// stay declared without a field and are read by hand. The automaton's KeyTable
// (automaton/src/section.cpp) is the same idea with its --full and --vtk extras.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "granlub/case/schema.h"
#include "granlub/error.h"

namespace granlub {

template <class Settings>
class BoundKeys {
public:
    explicit BoundKeys(SectionSpec declared) : spec(std::move(declared)) {}

    SectionSpec spec;

    BoundKeys& real(const std::string& key, double Settings::*field, double def, Range r, const std::string& unit,
                    const std::string& doc) {
        spec.real(key, def, r, unit, doc);
        return bind(key, field);
    }
    template <class T>
    BoundKeys& integer(const std::string& key, T Settings::*field, std::int64_t def, Range r, const std::string& doc) {
        spec.integer(key, def, r, doc);
        return bind(key, field);
    }
    BoundKeys& boolean(const std::string& key, bool Settings::*field, bool def, const std::string& doc) {
        spec.boolean(key, def, doc);
        return bind(key, field);
    }
    // Old names of the key declared last (SectionSpec::old_names).
    BoundKeys& old_names(std::vector<std::string> names) {
        spec.old_names(std::move(names));
        return *this;
    }

    // Binds a key declared already (e.g. by a helper shared between solvers) to a field.
    template <class T>
    BoundKeys& bind(const std::string& key, T Settings::*field) {
        if (!spec.find(key)) throw Error("internal: [" + spec.name + "] binds the undeclared key " + key);
        bindings_.push_back({key, [field](Settings& s, const Value& v) {
                                 if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, double> ||
                                               std::is_same_v<T, std::string>)
                                     s.*field = std::get<T>(v);
                                 else
                                     s.*field = static_cast<T>(std::get<std::int64_t>(v));
                             }});
        return *this;
    }

    // Sets every bound field from the section's value (given or defaulted; the schema checked it).
    void read(Settings& s, const Section& sec) const {
        for (const auto& b : bindings_)
            if (sec.has(b.key)) b.set(s, sec.values().at(b.key));
    }

private:
    struct Binding {
        std::string key;
        std::function<void(Settings&, const Value&)> set;
    };
    std::vector<Binding> bindings_;
};

}  // namespace granlub
