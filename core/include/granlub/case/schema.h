// Declaring case keys: every key is declared once, here-style, with its type, default, range,
// unit and a one-line doc. The declaration drives validation, `granlub check` output, `granlub
// keys` and the key tables in the READMEs, which are key_table() output between marker comments,
// rewritten by `granlub keys --update` and checked by the repo_key_tables test (cli/key_tables.h).
// (Idea borrowed from deal.II's ParameterHandler.)
//
// A module declares its own section in one function, one line per key (continuum/src/section.cpp
// is a full example):
//
//   SectionSpec s("continuum", "GKL continuum solver");
//   s.choice("method", "fv", {"fv", "shooting"}, "solver");
//   s.integer("cells", 200, Range::closed(100, 1e6), "finite-volume cells across the gap");
//   s.real("tolerance", 1e-10, Range::positive(), "", "Newton tolerance on the max-norm residual");
#pragma once
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace granlub {

struct SolverInfo;  // granlub/run/solver_info.h: carried by a solver's section, not read here

// Closed/open numeric interval; the text form is used in error messages ("allowed: (0, 1]").
struct Range {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool lo_open = false;
    bool hi_open = false;

    static Range any() { return {}; }
    static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
    static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
    static Range unit() { return {0.0, 1.0, false, false}; }            // [0, 1]
    static Range at_least(double v) { return {v, std::numeric_limits<double>::infinity(), false, false}; }
    static Range closed(double a, double b) { return {a, b, false, false}; }
    static Range open_closed(double a, double b) { return {a, b, true, false}; }  // (a, b]
    static Range open(double a, double b) { return {a, b, true, true}; }

    bool contains(double v) const;
    std::string text() const;
};

enum class KeyType { Real, Integer, Boolean, String, Choice };

// A value as stored after parsing. Sweepable keys hold a list of reals; an integer key that takes a
// list (SectionSpec::integer_or_list), given one, holds that list of integers.
using Value = std::variant<double, std::int64_t, bool, std::string, std::vector<double>, std::vector<std::int64_t>>;

struct KeySpec {
    std::string name;
    KeyType type = KeyType::Real;
    std::optional<Value> default_value;  // empty: required, unless optional_key
    bool optional_key = false;           // may be absent with no default (e.g. per-wall overrides)
    bool sweepable = false;              // a list of values is swept (only in [operating])
    Range range;
    std::vector<std::string> choices;    // for Choice
    // Choice: old spellings still read, each with the choice it now is (SectionSpec::old_spellings).
    std::vector<std::pair<std::string, std::string>> old_spellings;
    // Old names of the key itself, still read (SectionSpec::old_names).
    std::vector<std::string> old_names;
    std::string unit;                    // SI unit, "" = dimensionless
    std::string doc;
    // The default does what was computed before the key existed: at its default the key is left
    // out of the inputs hash (Case::inputs_hash), so adding it made no earlier result stale.
    bool neutral_default = false;
    // Integer keys: a non-empty list of distinct integers, each in list_range, is also taken
    // (SectionSpec::integer_or_list; e.g. [particles] seeds: a count or the seeds themselves).
    bool integer_list = false;
    Range list_range;
    // False: not one of the results' inputs (never in the inputs hash), for a key that chooses
    // which results are computed, not what any of them is ([particles] seeds).
    bool input = true;

    std::string allowed_text() const;    // "a real number in (0, 1]", "one of "a", "b"", ...
    std::string type_name() const;
};

class Section;

struct SectionSpec {
    std::string name;
    std::string doc;
    std::vector<KeySpec> keys;
    std::vector<std::string> subtables;  // allowed nested tables, e.g. walls.top / walls.bottom
    // Shared sections a solver's results also depend on (e.g. [particles] for dem and yade):
    // part of its inputs hash, so a change there makes its results stale.
    std::vector<std::string> uses;
    // False for a section no solver reads (e.g. [report]): in no solver's inputs hash, so a change
    // there leaves every result current.
    bool solver_input = true;
    // The declaration of the solver this section is (granlub/run/solver_info.h), set by
    // Schema::declare_solver; nullptr for the common sections and where no solver is linked.
    const SolverInfo* solver = nullptr;
    // Cross-key checks of this section; call Section::fail(key, why) to reject.
    std::function<void(const Section&)> validate;

    SectionSpec() = default;
    SectionSpec(std::string name_, std::string doc_) : name(std::move(name_)), doc(std::move(doc_)) {}

    SectionSpec& real(const std::string& key, double def, Range r, const std::string& unit, const std::string& doc);
    SectionSpec& real_required(const std::string& key, Range r, const std::string& unit, const std::string& doc);
    SectionSpec& real_optional(const std::string& key, Range r, const std::string& unit, const std::string& doc);
    SectionSpec& sweep(const std::string& key, std::optional<double> def, Range r, const std::string& unit,
                       const std::string& doc);
    SectionSpec& integer(const std::string& key, std::int64_t def, Range r, const std::string& doc);
    SectionSpec& integer_optional(const std::string& key, Range r, const std::string& doc);
    // An integer in `r`, or a non-empty list of distinct integers each in `members` (Section::integers).
    SectionSpec& integer_or_list(const std::string& key, std::int64_t def, Range r, Range members,
                                 const std::string& doc);
    SectionSpec& boolean(const std::string& key, bool def, const std::string& doc);
    SectionSpec& string(const std::string& key, std::string def, const std::string& doc);
    SectionSpec& choice(const std::string& key, std::string def, std::vector<std::string> allowed,
                        const std::string& doc);
    // Renamed values of the choice key declared last, as {old, new} pairs: a case that writes an old
    // spelling still parses, as the new value, with a warning naming it (Case::warnings).
    SectionSpec& old_spellings(std::vector<std::pair<std::string, std::string>> old_to_new);
    // Old names of the key declared last: a case that writes an old name still parses, as this key,
    // with a warning naming it (Case::warnings), as old spellings of values do.
    SectionSpec& old_names(std::vector<std::string> names);
    // The key declared last does at its default what was computed before it existed
    // (KeySpec::neutral_default): adding it made no earlier result stale.
    SectionSpec& neutral_default();

    const KeySpec* find(const std::string& key) const;
    // The key that `old` is an old name of, or null.
    const KeySpec* renamed(const std::string& old) const;
};

// Where a value came from, for error messages.
struct SourcePos {
    int line = 0;
    int column = 0;
    std::string file;  // "" = the section's file; a base's for a value merged from it ([case] base)
};

// The resolved values of one section.
class Section {
public:
    Section() = default;
    Section(const SectionSpec* spec, std::string file) : spec_(spec), file_(std::move(file)) {}

    double real(const std::string& key) const;
    std::optional<double> maybe_real(const std::string& key) const;
    std::int64_t integer(const std::string& key) const;
    std::optional<std::int64_t> maybe_integer(const std::string& key) const;
    bool boolean(const std::string& key) const;
    const std::string& string(const std::string& key) const;  // String and Choice keys
    const std::vector<double>& list(const std::string& key) const;  // sweepable keys
    // An integer_or_list key given as a list: that list; null when it holds one integer (integer()).
    const std::vector<std::int64_t>* integers(const std::string& key) const;
    bool has(const std::string& key) const;
    bool is_default(const std::string& key) const;
    std::optional<SourcePos> where(const std::string& key) const;
    // The file the key's value was read from: the case's, or a base's ([case] base).
    const std::string& file_of(const std::string& key) const;

    // Throws CaseError "<file>:<line>:<col>: [section] key = value: why".
    [[noreturn]] void fail(const std::string& key, const std::string& why) const;

    const SectionSpec& spec() const { return *spec_; }
    const std::string& name() const { return spec_->name; }
    const std::map<std::string, Value>& values() const { return values_; }

    // Used by the parser.
    void set(const std::string& key, Value v, std::optional<SourcePos> pos, bool defaulted);

private:
    const Value& get(const std::string& key, KeyType expect) const;
    const SectionSpec* spec_ = nullptr;
    std::string file_;
    std::map<std::string, Value> values_;
    std::map<std::string, SourcePos> pos_;
    std::map<std::string, bool> defaulted_;
};

// All sections a case may have: the common ones (case, grains, walls with walls.bottom and
// walls.top, cell, operating, body_forces, report), [particles], which the particle solvers share
// (particles_section() in case.h), plus whatever the solver modules add. common() is defined with
// the common sections' declarations (src/case/common_sections.cpp).
class Schema {
public:
    static Schema common();            // the common sections and [particles]: every section but the solvers'
    Schema& add(SectionSpec section);  // a solver's section
    // The declaration of the solver whose section is `name` (its kSolver row, which outlives the
    // schema), carried by that section for what reads the case; throws Error for an unknown section.
    Schema& declare_solver(std::string_view name, const SolverInfo* solver);
    const SectionSpec* find(std::string_view name) const;
    const std::vector<SectionSpec>& sections() const { return sections_; }

private:
    std::vector<SectionSpec> sections_;
};

std::string value_text(const Value& v);

// The section's keys as a Markdown table (key, default, allowed, unit, meaning): what the READMEs'
// marked key tables hold.
std::string key_table(const SectionSpec& spec);
// The same under a "### [section]" heading and the section's doc: what `granlub keys` prints.
std::string key_table_markdown(const SectionSpec& spec);

}  // namespace granlub
