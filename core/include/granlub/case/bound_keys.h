// A solver's section whose keys each name the settings field they fill: the key is declared once
// (default, range, unit, doc: the schema) with its field, and reading the section is one loop
// (read()), not a line per key in the solver's settings code. A new plain key is its field and its
// line. The field is a member of Settings or of one of its parts (part(&Settings::solver,
// &SolverSettings::cells)); a choice whose values are rows of a registry table (registry.h) fills
// the row's value (an enum). Keys whose values convert otherwise or combine (a choice resolved to a
// registry object, a default from another section, cross-key checks) stay declared on `spec`
// without a field and are read by hand after read(), each solver saying why.
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "granlub/case/schema.h"
#include "granlub/error.h"
#include "granlub/registry.h"

namespace granlub {

// A field one level down: a member of one of Settings' parts.
template <class Settings, class Part, class T>
struct PartField {
    Part Settings::*part;
    T Part::*member;
};
template <class Settings, class Part, class T>
PartField<Settings, Part, T> part(Part Settings::*p, T Part::*member) {
    return {p, member};
}

// Which run the keys are read for: --full reads a key's *_full partner (BoundKeys::full), --vtk the
// keys bound only_with_vtk.
struct KeyUse {
    bool full = false;
    bool vtk = false;
};

template <class Settings>
class BoundKeys {
public:
    // One key and its field.
    struct Binding {
        std::string key;
        std::string full_key;        // read instead with --full ("": the same key)
        bool only_with_vtk = false;  // read with --vtk only; the field holds its own default otherwise
        bool output_only = false;    // changes what is written, not the numbers (a solver's summary leaves it out)
        std::function<void(Settings&, const Value&)> set;
        std::function<Value(const Settings&)> get;  // the field as the case file writes it
    };

    explicit BoundKeys(SectionSpec declared) : spec(std::move(declared)) {}

    SectionSpec spec;

    template <class F>
    BoundKeys& real(const std::string& key, F field, double def, Range r, const std::string& unit,
                    const std::string& doc) {
        spec.real(key, def, r, unit, doc);
        return bind(key, field);
    }
    // No default: the field keeps its own value when the key is absent.
    template <class F>
    BoundKeys& real_optional(const std::string& key, F field, Range r, const std::string& unit,
                             const std::string& doc) {
        spec.real_optional(key, r, unit, doc);
        return bind(key, field);
    }
    template <class F>
    BoundKeys& integer(const std::string& key, F field, std::int64_t def, Range r, const std::string& doc) {
        spec.integer(key, def, r, doc);
        return bind(key, field);
    }
    template <class F>
    BoundKeys& boolean(const std::string& key, F field, bool def, const std::string& doc) {
        spec.boolean(key, def, doc);
        return bind(key, field);
    }
    // A choice among the rows of a registry table (each row a `name` and a `value`): the field takes
    // the chosen row's value; the choices are the table's names in table order.
    template <class F, class Row, class E>
    BoundKeys& choice(const std::string& key, F field, const std::vector<Row>& table, E def, const std::string& doc) {
        spec.choice(key, row_name(table, def), registry_names(table), doc);
        Binding b{key, {}, false, false, {}, {}};
        b.set = [field, table, key](Settings& s, const Value& v) {
            at(s, field) = registry_find(table, std::get<std::string>(v), key).value;
        };
        b.get = [field, table](const Settings& s) { return Value{row_name(table, at(s, field))}; };
        bindings_.push_back(std::move(b));
        return *this;
    }
    // Old names of the key declared last (SectionSpec::old_names).
    BoundKeys& old_names(std::vector<std::string> names) {
        spec.old_names(std::move(names));
        return *this;
    }
    // The key declared last's default is neutral (SectionSpec::neutral_default).
    BoundKeys& neutral_default() {
        spec.neutral_default();
        return *this;
    }
    // The key read instead of the one bound last with --full: declared next, of its type, with its
    // range and unit.
    BoundKeys& full(const std::string& key, double def, const std::string& doc) {
        const KeySpec of = spec.keys.back();
        if (of.type == KeyType::Integer)
            spec.integer(key, static_cast<std::int64_t>(def), of.range, doc);
        else if (of.type == KeyType::Real)
            spec.real(key, def, of.range, of.unit, doc);
        else
            throw Error("internal: [" + spec.name + "] " + of.name + " has a --full partner but is no number");
        last().full_key = key;
        return *this;
    }
    BoundKeys& only_with_vtk() {
        last().only_with_vtk = true;
        return *this;
    }
    BoundKeys& output_only() {
        last().output_only = true;
        return *this;
    }

    // Binds a key declared already (e.g. by a helper shared between solvers) to a field.
    template <class F>
    BoundKeys& bind(const std::string& key, F field) {
        if (!spec.find(key)) throw Error("internal: [" + spec.name + "] binds the undeclared key " + key);
        using T = std::remove_cv_t<std::remove_reference_t<decltype(at(std::declval<Settings&>(), field))>>;
        Binding b{key, {}, false, false, {}, {}};
        b.set = [field](Settings& s, const Value& v) {
            if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, double> || std::is_same_v<T, std::string>)
                at(s, field) = std::get<T>(v);
            else
                at(s, field) = static_cast<T>(std::get<std::int64_t>(v));
        };
        b.get = [field](const Settings& s) {
            if constexpr (std::is_same_v<T, bool> || std::is_same_v<T, double> || std::is_same_v<T, std::string>)
                return Value{at(s, field)};
            else
                return Value{static_cast<std::int64_t>(at(s, field))};
        };
        bindings_.push_back(std::move(b));
        return *this;
    }

    // Sets every bound field from the section's value (given or defaulted; the schema checked it).
    void read(Settings& s, const Section& sec, KeyUse use = {}) const {
        for (const auto& b : bindings_) {
            if (b.only_with_vtk && !use.vtk) continue;
            const std::string& key = use.full && !b.full_key.empty() ? b.full_key : b.key;
            if (sec.has(key)) b.set(s, sec.values().at(key));
        }
    }
    // The key a field's problem is reported against: `key`, or its *_full partner with --full.
    std::string key_name(const std::string& key, KeyUse use) const {
        if (use.full)
            for (const auto& b : bindings_)
                if (b.key == key && !b.full_key.empty()) return b.full_key;
        return key;
    }
    const std::vector<Binding>& bindings() const { return bindings_; }

private:
    template <class T>
    static T& at(Settings& s, T Settings::*f) {
        return s.*f;
    }
    template <class T>
    static const T& at(const Settings& s, T Settings::*f) {
        return s.*f;
    }
    template <class Part, class T>
    static T& at(Settings& s, PartField<Settings, Part, T> f) {
        return s.*f.part.*f.member;
    }
    template <class Part, class T>
    static const T& at(const Settings& s, PartField<Settings, Part, T> f) {
        return s.*f.part.*f.member;
    }
    template <class Row, class E>
    static std::string row_name(const std::vector<Row>& table, E value) {
        for (const Row& r : table)
            if (r.value == value) return r.name;
        throw Error("internal: a registry value without a name");
    }
    Binding& last() {
        if (bindings_.empty()) throw Error("internal: [" + spec.name + "] has no bound key to qualify");
        return bindings_.back();
    }
    std::vector<Binding> bindings_;
};

// The keys a section's declare() builds, built once: the body of each solver's keys function
// (dem_keys(), ...), whose section() is its spec.
template <class Settings, BoundKeys<Settings> (*declare)()>
const BoundKeys<Settings>& keys_once() {
    static const BoundKeys<Settings> keys = declare();
    return keys;
}

}  // namespace granlub
