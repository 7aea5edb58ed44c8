#include "granlub/case/schema.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/text.h"

namespace granlub {

bool Range::contains(double v) const {
    if (std::isnan(v)) return false;
    if (lo_open ? !(v > lo) : !(v >= lo)) return false;
    if (hi_open ? !(v < hi) : !(v <= hi)) return false;
    return true;
}

std::string Range::text() const {
    const bool lo_inf = std::isinf(lo);
    const bool hi_inf = std::isinf(hi);
    if (lo_inf && hi_inf) return "any finite number";
    if (hi_inf) return fmt::format("{} {}", lo_open ? ">" : ">=", lo);
    if (lo_inf) return fmt::format("{} {}", hi_open ? "<" : "<=", hi);
    return fmt::format("{}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
}

std::string KeySpec::type_name() const {
    switch (type) {
        case KeyType::Real: return sweepable ? "number or list of numbers" : "number";
        case KeyType::Integer: return integer_list ? "integer or list of integers" : "integer";
        case KeyType::Boolean: return "boolean";
        case KeyType::String: return "string";
        case KeyType::Choice: return "string";
    }
    return "?";
}

std::string KeySpec::allowed_text() const {
    switch (type) {
        case KeyType::Real:
            return fmt::format("{} {}{}", sweepable ? "a number (or non-empty list of numbers)" : "a number",
                               range.text(), unit.empty() ? "" : " " + unit);
        case KeyType::Integer:
            if (integer_list)
                return fmt::format("an integer {}, or a non-empty list of distinct integers {}", range.text(),
                                   list_range.text());
            return fmt::format("an integer {}", range.text());
        case KeyType::Boolean: return "true or false";
        case KeyType::String: return "a string";
        case KeyType::Choice: {
            std::string s = "one of ";
            for (std::size_t i = 0; i < choices.size(); ++i)
                s += fmt::format("{}\"{}\"", i ? ", " : "", choices[i]);
            return s;
        }
    }
    return "?";
}

namespace {
KeySpec make(const std::string& key, KeyType t, std::optional<Value> def, Range r, const std::string& unit,
             const std::string& help) {
    KeySpec k;
    k.name = key;
    k.type = t;
    k.default_value = std::move(def);
    k.range = r;
    k.unit = unit;
    k.doc = help;
    return k;
}
}  // namespace

SectionSpec& SectionSpec::real(const std::string& key, double def, Range r, const std::string& unit,
                               const std::string& help) {
    keys.push_back(make(key, KeyType::Real, Value{def}, r, unit, help));
    return *this;
}
SectionSpec& SectionSpec::real_required(const std::string& key, Range r, const std::string& unit,
                                        const std::string& help) {
    keys.push_back(make(key, KeyType::Real, std::nullopt, r, unit, help));
    return *this;
}
SectionSpec& SectionSpec::real_optional(const std::string& key, Range r, const std::string& unit,
                                        const std::string& help) {
    keys.push_back(make(key, KeyType::Real, std::nullopt, r, unit, help));
    keys.back().optional_key = true;
    return *this;
}
SectionSpec& SectionSpec::sweep(const std::string& key, std::optional<double> def, Range r,
                                const std::string& unit, const std::string& help) {
    std::optional<Value> v;
    if (def) v = Value{std::vector<double>{*def}};
    keys.push_back(make(key, KeyType::Real, v, r, unit, help));
    keys.back().sweepable = true;
    keys.back().optional_key = !def.has_value();
    return *this;
}
SectionSpec& SectionSpec::integer(const std::string& key, std::int64_t def, Range r, const std::string& help) {
    keys.push_back(make(key, KeyType::Integer, Value{def}, r, "", help));
    return *this;
}
SectionSpec& SectionSpec::integer_or_list(const std::string& key, std::int64_t def, Range r, Range members,
                                          const std::string& help) {
    keys.push_back(make(key, KeyType::Integer, Value{def}, r, "", help));
    keys.back().integer_list = true;
    keys.back().list_range = members;
    return *this;
}
SectionSpec& SectionSpec::integer_optional(const std::string& key, Range r, const std::string& help) {
    keys.push_back(make(key, KeyType::Integer, std::nullopt, r, "", help));
    keys.back().optional_key = true;
    return *this;
}
SectionSpec& SectionSpec::boolean(const std::string& key, bool def, const std::string& help) {
    keys.push_back(make(key, KeyType::Boolean, Value{def}, Range::any(), "", help));
    return *this;
}
SectionSpec& SectionSpec::string(const std::string& key, std::string def, const std::string& help) {
    keys.push_back(make(key, KeyType::String, Value{std::move(def)}, Range::any(), "", help));
    return *this;
}
SectionSpec& SectionSpec::choice(const std::string& key, std::string def, std::vector<std::string> allowed,
                                 const std::string& help) {
    keys.push_back(make(key, KeyType::Choice, Value{std::move(def)}, Range::any(), "", help));
    keys.back().choices = std::move(allowed);
    return *this;
}

SectionSpec& SectionSpec::old_spellings(std::vector<std::pair<std::string, std::string>> old_to_new) {
    if (keys.empty() || keys.back().type != KeyType::Choice)
        throw Error(fmt::format("internal: [{}] old_spellings() follows a choice key", name));
    KeySpec& k = keys.back();
    for (const auto& [old, now] : old_to_new)
        if (std::find(k.choices.begin(), k.choices.end(), now) == k.choices.end() ||
            std::find(k.choices.begin(), k.choices.end(), old) != k.choices.end())
            throw Error(fmt::format("internal: [{}] {}: old spelling \"{}\" of \"{}\" is a choice, or names none",
                                    name, k.name, old, now));
    k.old_spellings = std::move(old_to_new);
    return *this;
}

SectionSpec& SectionSpec::neutral_default() {
    if (keys.empty()) throw Error(fmt::format("internal: [{}] neutral_default() follows a key", name));
    keys.back().neutral_default = true;
    return *this;
}

SectionSpec& SectionSpec::old_names(std::vector<std::string> names) {
    if (keys.empty()) throw Error(fmt::format("internal: [{}] old_names() follows a key", name));
    for (const auto& old : names)
        if (find(old) || renamed(old))
            throw Error(fmt::format("internal: [{}] {}: old name \"{}\" is a key, or an old name already", name,
                                    keys.back().name, old));
    keys.back().old_names = std::move(names);
    return *this;
}

const KeySpec* SectionSpec::renamed(const std::string& old) const {
    for (const auto& k : keys)
        if (std::find(k.old_names.begin(), k.old_names.end(), old) != k.old_names.end()) return &k;
    return nullptr;
}

const KeySpec* SectionSpec::find(const std::string& key) const {
    for (const auto& k : keys)
        if (k.name == key) return &k;
    return nullptr;
}

std::string value_text(const Value& v) {
    struct V {
        std::string operator()(double d) const { return fmt::format("{}", d); }
        std::string operator()(std::int64_t i) const { return fmt::format("{}", i); }
        std::string operator()(bool b) const { return b ? "true" : "false"; }
        std::string operator()(const std::string& s) const { return fmt::format("\"{}\"", one_line(s)); }
        std::string operator()(const std::vector<double>& l) const {
            if (l.size() == 1) return fmt::format("{}", l[0]);
            return fmt::format("[{}]", fmt::join(l, ", "));
        }
        std::string operator()(const std::vector<std::int64_t>& l) const { return fmt::format("[{}]", fmt::join(l, ", ")); }
    };
    return std::visit(V{}, v);
}

namespace {
// A table cell: a '|' in the text would end the cell.
std::string cell(const std::string& text) {
    std::string out;
    for (char ch : text) out += ch == '|' ? std::string("\\|") : std::string(1, ch);
    return out;
}
}  // namespace

std::string key_table(const SectionSpec& spec) {
    std::string out = "| key | default | allowed | unit | meaning |\n|---|---|---|---|---|\n";
    for (const auto& k : spec.keys) {
        std::string def = k.default_value ? value_text(*k.default_value) : (k.optional_key ? "(not set)" : "required");
        std::string allowed;
        switch (k.type) {
            case KeyType::Real: allowed = (k.sweepable ? "number or list, " : "") + k.range.text(); break;
            case KeyType::Integer:
                allowed = "integer " + k.range.text() +
                          (k.integer_list ? ", or list of distinct integers " + k.list_range.text() : "");
                break;
            case KeyType::Boolean: allowed = "true, false"; break;
            case KeyType::String: allowed = "string"; break;
            case KeyType::Choice: allowed = fmt::format("{}", fmt::join(k.choices, ", ")); break;
        }
        for (std::size_t i = 0; i < k.old_spellings.size(); ++i)
            allowed += fmt::format("{}{} = {}", i ? ", " : "; old spellings still read: ", k.old_spellings[i].first,
                                   k.old_spellings[i].second);
        for (std::size_t i = 0; i < k.old_names.size(); ++i)
            allowed += fmt::format("{}{}", i ? ", " : "; old name still read: ", k.old_names[i]);
        out += fmt::format("| `{}` | {} | {} | {} | {} |\n", k.name, cell(def), cell(allowed), k.unit, cell(k.doc));
    }
    return out;
}

std::string key_table_markdown(const SectionSpec& spec) {
    return fmt::format("### [{}]\n\n{}\n\n{}", spec.name, spec.doc, key_table(spec));
}

void Section::set(const std::string& key, Value v, std::optional<SourcePos> pos, bool defaulted) {
    values_[key] = std::move(v);
    if (pos) pos_[key] = *pos;
    defaulted_[key] = defaulted;
}

const Value& Section::get(const std::string& key, KeyType expect) const {
    const KeySpec* k = spec_ ? spec_->find(key) : nullptr;
    if (!k) throw Error(fmt::format("internal: [{}] has no declared key '{}'", spec_ ? spec_->name : "?", key));
    const bool compatible = k->type == expect || (expect == KeyType::String && k->type == KeyType::Choice);
    if (!compatible) throw Error(fmt::format("internal: [{}] {} is a {}", spec_->name, key, k->type_name()));
    auto it = values_.find(key);
    if (it == values_.end())
        throw Error(fmt::format("internal: [{}] {} has no value (optional key without default)", spec_->name, key));
    return it->second;
}

double Section::real(const std::string& key) const {
    const Value& v = get(key, KeyType::Real);
    if (auto* l = std::get_if<std::vector<double>>(&v)) {
        if (l->size() != 1)
            throw Error(fmt::format("internal: [{}] {} is a swept list; use list()", spec_->name, key));
        return l->front();
    }
    return std::get<double>(v);
}
std::optional<double> Section::maybe_real(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return real(key);
}
std::int64_t Section::integer(const std::string& key) const {
    const Value& v = get(key, KeyType::Integer);
    if (!std::holds_alternative<std::int64_t>(v))
        throw Error(fmt::format("internal: [{}] {} is a list; use integers()", spec_->name, key));
    return std::get<std::int64_t>(v);
}
const std::vector<std::int64_t>* Section::integers(const std::string& key) const {
    return std::get_if<std::vector<std::int64_t>>(&get(key, KeyType::Integer));
}
std::optional<std::int64_t> Section::maybe_integer(const std::string& key) const {
    if (!has(key)) return std::nullopt;
    return integer(key);
}
bool Section::boolean(const std::string& key) const { return std::get<bool>(get(key, KeyType::Boolean)); }
const std::string& Section::string(const std::string& key) const {
    return std::get<std::string>(get(key, KeyType::String));
}
const std::vector<double>& Section::list(const std::string& key) const {
    return std::get<std::vector<double>>(get(key, KeyType::Real));
}
bool Section::has(const std::string& key) const { return values_.count(key) > 0; }
bool Section::is_default(const std::string& key) const {
    auto it = defaulted_.find(key);
    return it != defaulted_.end() && it->second;
}
std::optional<SourcePos> Section::where(const std::string& key) const {
    auto it = pos_.find(key);
    if (it == pos_.end()) return std::nullopt;
    return it->second;
}

const std::string& Section::file_of(const std::string& key) const {
    auto it = pos_.find(key);
    return it == pos_.end() || it->second.file.empty() ? file_ : it->second.file;
}

void Section::fail(const std::string& key, const std::string& why) const {
    std::string place = file_of(key);
    if (auto p = where(key)) place += fmt::format(":{}:{}", p->line, p->column);
    std::string value = has(key) ? clipped(value_text(values_.at(key))) : "(not set)";
    std::string def = is_default(key) ? " (default)" : "";
    throw CaseError(fmt::format("{}: [{}] {} = {}{}: {}", place, name(), key, value, def, why));
}

// ---------------------------------------------------------------------------------------------
Schema& Schema::add(SectionSpec section) {
    if (find(section.name)) throw Error(fmt::format("internal: section [{}] declared twice", section.name));
    sections_.push_back(std::move(section));
    return *this;
}

Schema& Schema::declare_solver(std::string_view name, const SolverInfo* solver) {
    for (auto& s : sections_)
        if (s.name == name) {
            s.solver = solver;
            return *this;
        }
    throw Error(fmt::format("internal: no section [{}] for a solver's declaration", name));
}

const SectionSpec* Schema::find(std::string_view name) const {
    for (const auto& s : sections_)
        if (s.name == name) return &s;
    return nullptr;
}

}  // namespace granlub
