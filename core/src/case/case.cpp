// Case files: parse with toml++, validate every key against its declaration, resolve defaults,
// expand the [operating] sweep into points with stable ids.
#include "granlub/case/case.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>
#include <unordered_set>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "case_base.h"
#include "case_file.h"
#include "common_sections.h"
#include "granlub/case/wall_bumps.h"
#include "granlub/error.h"
#include "granlub/text.h"

namespace granlub {

std::string to_string(Control c) { return c == Control::Fill ? "fill" : "load"; }
std::string to_string(WallSurface s) { return s == WallSurface::Bumps ? "bumps" : "plane"; }

double Grains::mass() const { return density * std::numbers::pi * diameter * diameter * diameter / 6.0; }

double Grains::rayleigh_time() const {
    const double shear_modulus = youngs_modulus / (2.0 * (1.0 + poisson_ratio));
    return std::numbers::pi * 0.5 * sizes().min() * std::sqrt(density / shear_modulus) /
           (0.1631 * poisson_ratio + 0.8766);
}

std::string hash_hex(std::string_view bytes) {
    std::uint64_t h = 1469598103934665603ULL;  // FNV-1a 64
    for (unsigned char ch : bytes) {
        h ^= ch;
        h *= 1099511628211ULL;
    }
    return fmt::format("{:016x}", h);
}

// ---------------------------------------------------------------------------------------------
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t prev = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            std::size_t cur = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, prev + (a[i - 1] == b[j - 1] ? 0 : 1)});
            prev = cur;
        }
    }
    return row[b.size()];
}

std::string suggestion(const std::string& bad, const std::vector<std::string>& names) {
    if (bad.size() > 64) return "";  // no declared name is that long; spare the quadratic distance
    std::string best;
    std::size_t best_d = 3;
    for (const auto& n : names) {
        std::size_t d = edit_distance(bad, n);
        if (d < best_d) best_d = d, best = n;
    }
    return best.empty() ? "" : fmt::format("did you mean '{}'? ", best);
}

std::string node_text(const toml::node& n) {
    std::ostringstream os;
    if (auto* s = n.as_string()) os << '"' << s->get() << '"';
    else if (n.is_table()) os << "(a table)";
    else if (auto* f = n.as_floating_point()) os << fmt::format("{}", f->get());  // shortest round-trip
    else n.visit([&](const auto& v) { os << v; });
    std::string t = os.str();
    return clipped(one_line(t));
}

[[noreturn]] void bad_value(const std::string& file, const std::string& section, const KeySpec& k,
                            const toml::node& n, const std::string& why) {
    throw CaseError(fmt::format("{}: [{}] {} = {}: {} (allowed: {})", where(file, n.source()), section, k.name,
                                node_text(n), why, k.allowed_text()));
}

double number(const std::string& file, const std::string& section, const KeySpec& k, const toml::node& n) {
    double v;
    if (auto* i = n.as_integer()) v = static_cast<double>(i->get());
    else if (auto* f = n.as_floating_point()) v = f->get();
    else bad_value(file, section, k, n, fmt::format("expected {}", k.type_name()));
    if (!std::isfinite(v)) bad_value(file, section, k, n, "not a finite number");
    if (!k.range.contains(v)) bad_value(file, section, k, n, "out of range");
    if (v != 0 && std::fpclassify(v) == FP_SUBNORMAL)
        bad_value(file, section, k, n, "a subnormal number (below 2.2e-308 in magnitude) loses precision");
    return v == 0 ? 0.0 : v;  // -0 is 0: ids and comparisons must not tell them apart
}

// `notes` receives a warning for each old spelling read (KeySpec::old_spellings).
Value parse_value(const std::string& file, const std::string& section, const KeySpec& k, const toml::node& n,
                  std::vector<std::string>& notes) {
    switch (k.type) {
        case KeyType::Real: {
            if (k.sweepable) {
                if (auto* arr = n.as_array()) {
                    if (arr->empty()) bad_value(file, section, k, n, "empty list: a sweep needs at least one value");
                    if (arr->size() > kMaxOperatingPoints)
                        bad_value(file, section, k, n,
                                  fmt::format("a list of {} values; a case may have at most {} operating points",
                                              arr->size(), kMaxOperatingPoints));
                    std::vector<double> out;
                    std::unordered_set<double> seen;
                    for (const auto& e : *arr) {
                        const double v = number(file, section, k, e);
                        if (!seen.insert(v).second)
                            bad_value(file, section, k, e, fmt::format("{} appears twice in the sweep", v));
                        out.push_back(v);
                    }
                    return out;
                }
                return std::vector<double>{number(file, section, k, n)};
            }
            return number(file, section, k, n);
        }
        case KeyType::Integer: {
            if (auto* arr = n.as_array(); arr && k.integer_list) {
                if (arr->empty()) bad_value(file, section, k, n, "empty list");
                if (arr->size() > kMaxIntegerList)
                    bad_value(file, section, k, n, fmt::format("a list of {} values (at most {})", arr->size(),
                                                               kMaxIntegerList));
                std::vector<std::int64_t> out;
                for (const auto& e : *arr) {  // the message shows the whole list and names the element
                    auto* i = e.as_integer();
                    if (!i) bad_value(file, section, k, n, fmt::format("{} is not an integer", node_text(e)));
                    if (!k.list_range.contains(static_cast<double>(i->get())))
                        bad_value(file, section, k, n, fmt::format("{} is out of range", i->get()));
                    if (std::find(out.begin(), out.end(), i->get()) != out.end())
                        bad_value(file, section, k, n, fmt::format("{} appears twice in the list", i->get()));
                    out.push_back(i->get());
                }
                return out;
            }
            auto* i = n.as_integer();
            if (!i) bad_value(file, section, k, n, "expected an integer");
            double v = static_cast<double>(i->get());
            if (!k.range.contains(v)) bad_value(file, section, k, n, "out of range");
            return std::int64_t{i->get()};
        }
        case KeyType::Boolean: {
            auto* b = n.as_boolean();
            if (!b) bad_value(file, section, k, n, "expected true or false");
            return b->get();
        }
        case KeyType::String:
        case KeyType::Choice: {
            auto* s = n.as_string();
            if (!s) bad_value(file, section, k, n, "expected a string");
            std::string v = s->get();
            if (k.type != KeyType::Choice || std::find(k.choices.begin(), k.choices.end(), v) != k.choices.end())
                return v;
            for (const auto& [old, now] : k.old_spellings)
                if (v == old) {
                    notes.push_back(fmt::format("{}: [{}] {} = \"{}\" is the old spelling of \"{}\", read as that; "
                                                "write \"{}\" (the old spellings will go)",
                                                where(file, n.source()), section, k.name, old, now, now));
                    return now;
                }
            bad_value(file, section, k, n, fmt::format("unknown value; {}", suggestion(v, k.choices)));
        }
    }
    throw Error("internal: unhandled key type");
}

// Fills `out` with the table's values, defaults for keys not given; rejects unknown keys.
void read_section(const std::string& file, const SectionSpec& spec, const toml::table* t,
                  const toml::source_region& header, Section& out, std::set<std::string>& given_as_list,
                  std::vector<std::string>& notes) {
    std::vector<std::string> names;
    for (const auto& k : spec.keys) names.push_back(k.name);
    if (t) {
        for (const auto& [key, node] : *t) {
            const std::string name(key.str());
            if (std::find(spec.subtables.begin(), spec.subtables.end(), name) != spec.subtables.end()) continue;
            const KeySpec* k = spec.find(name);
            if (!k && (k = spec.renamed(name))) {
                if (t->contains(k->name) || out.has(k->name))
                    throw CaseError(fmt::format("{}: [{}] {} is the old name of {}, which is also given: write only {}",
                                                where(file, node.source()), spec.name, name, k->name, k->name));
                notes.push_back(fmt::format("{}: [{}] {} is the old name of {}, read as that; write {} (the old "
                                            "names will go)",
                                            where(file, node.source()), spec.name, name, k->name, k->name));
            }
            if (!k) {
                std::vector<std::string> all = names;
                all.insert(all.end(), spec.subtables.begin(), spec.subtables.end());
                throw CaseError(fmt::format("{}: [{}] {}: unknown key; {}(allowed: {})", where(file, node.source()),
                                            spec.name, clipped(one_line(name)), suggestion(name, all),
                                            fmt::join(all, ", ")));
            }
            Value v = parse_value(file, spec.name, *k, node, notes);
            if (k->sweepable && node.is_array()) given_as_list.insert(k->name);
            const auto& path = node.source().path;  // another file's for a value merged from a base
            out.set(k->name, std::move(v),
                    SourcePos{static_cast<int>(node.source().begin.line), static_cast<int>(node.source().begin.column),
                              path && *path != file ? *path : ""},
                    false);
        }
    }
    for (const auto& k : spec.keys) {
        if (out.has(k.name)) continue;
        if (k.default_value) {
            out.set(k.name, *k.default_value, std::nullopt, true);
        } else if (!k.optional_key) {
            throw CaseError(fmt::format("{}: [{}] {}: required key is missing ({}{}; {})", where(file, header),
                                        spec.name, k.name, k.allowed_text(), k.unit.empty() ? "" : "", k.doc));
        }
    }
}

// "2.0" for whole numbers so that ids read as numbers with a decimal point, else shortest form.
std::string id_number(double v, bool force_decimal) {
    std::string s = fmt::format("{}", v);
    if (force_decimal && s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

// The steps of parse_case, in order.

// Every top-level entry must be a known section, written as a table.
void check_top_level(const toml::table& root, const std::string& source, const Schema& schema) {
    std::vector<std::string> known;
    for (const auto& s : schema.sections())
        if (s.name.find('.') == std::string::npos) known.push_back(s.name);
    for (const auto& [key, node] : root) {
        const std::string name(key.str());
        if (std::find(known.begin(), known.end(), name) == known.end())
            throw CaseError(fmt::format("{}: [{}]: unknown section; {}(allowed: {})", where(source, node.source()),
                                        clipped(one_line(name)), suggestion(name, known), fmt::join(known, ", ")));
        if (!node.is_table())
            throw CaseError(fmt::format("{}: {} = {}: '{}' is a section and must be a table, e.g. [{}]",
                                        where(source, node.source()), name, node_text(node), name, name));
    }
}

// The table of section `spec` ("walls.bottom" is [walls] bottom), or null when the file has none.
const toml::table* section_table(toml::table& root, const SectionSpec& spec, const std::string& source) {
    const auto dot = spec.name.find('.');
    if (dot == std::string::npos) return root[spec.name].as_table();
    const auto parent = spec.name.substr(0, dot);
    const auto child = spec.name.substr(dot + 1);
    auto* p = root[parent].as_table();
    if (!p) return nullptr;
    auto* node = p->get(child);
    if (!node) return nullptr;
    const toml::table* t = node->as_table();
    if (!t)
        throw CaseError(fmt::format("{}: [{}] {} = {}: must be a table, e.g. [{}]", where(source, node->source()),
                                    parent, child, node_text(*node), spec.name));
    return t;
}

// Every declared section read into c.sections (defaults filled in). Returns the [operating] keys
// that were given as lists: they are the swept ones and name the points.
std::set<std::string> read_sections(toml::table& root, const std::string& source, const Schema& schema, Case& c) {
    std::set<std::string> swept_lists;
    for (const auto& spec : schema.sections()) {
        const toml::table* t = section_table(root, spec, source);
        const toml::source_region header = t ? t->source() : toml::source_region{};
        Section sec(&spec, source);
        std::set<std::string> lists;
        read_section(source, spec, t, header, sec, lists, c.warnings);
        if (spec.name == "operating") swept_lists = lists;
        c.sections.emplace(spec.name, std::move(sec));
    }
    return swept_lists;
}

// The common sections resolved into the typed structs of Case.
void resolve_common(Case& c) {
    const Section& cs = c.sections.at("case");
    // The name reaches folder names, decks and data files: a safe character set, checked here. A
    // name taken from the directory is made safe instead (the user did not write it).
    if (cs.string("name").empty()) {
        c.name = sanitized_name(c.dir.filename().string());
        if (c.name.empty()) c.name = "case";
    } else {
        c.name = cs.string("name");
        if (const std::string why = name_problem(c.name); !why.empty())
            cs.fail("name", fmt::format("not a usable case name: {} (allowed: 1 to {} of {}, not starting with "
                                        "'.' or '-')",
                                        why, kMaxNameLength, kNameCharacters));
    }
    c.title = cs.string("title");
    if (const auto at = control_character_offset(c.title))
        cs.fail("title", fmt::format("holds a control character (a line break, tab, ...) at byte {}; a title is "
                                     "one line of text",
                                     *at));
    if (c.title.size() > kMaxTitleBytes)
        cs.fail("title", fmt::format("{} bytes; a title has at most {}", c.title.size(), kMaxTitleBytes));

    const Section& g = c.sections.at("grains");
    c.grains = {g.real("diameter"),       g.real("density"),       g.real("restitution"), g.real("friction"),
                g.real("youngs_modulus"), g.real("poisson_ratio"), g.real("size_spread")};

    const Section& w = c.sections.at("walls");
    auto surface = [](const std::string& v) { return v == "bumps" ? WallSurface::Bumps : WallSurface::Plane; };
    const Wall base{w.real("restitution"), w.real("friction"), w.real("roughness"), surface(w.string("surface")),
                    w.real("bump_diameter")};
    auto wall = [&](const char* side) {
        const Section& s = c.sections.at(fmt::format("walls.{}", side));
        return Wall{s.maybe_real("restitution").value_or(base.restitution),
                    s.maybe_real("friction").value_or(base.friction), s.maybe_real("roughness").value_or(base.roughness),
                    s.string("surface").empty() ? base.surface : surface(s.string("surface")),
                    s.maybe_real("bump_diameter").value_or(base.bump_diameter)};
    };
    c.bottom = wall("bottom");
    c.top = wall("top");
    c.side_walls = w.string("sides") == "as_bottom" ? SideWalls::AsBottom : SideWalls::Plane;

    const Section& cell = c.sections.at("cell");
    c.cell = {cell.string("geometry") == "annulus" ? Geometry::Annulus : Geometry::Slice,
              cell.real("gap"), cell.real("length"), cell.real("width"), cell.real("annulus_radius"),
              cell.real("max_solid_fraction")};
    c.gravity = c.sections.at("body_forces").real("gravity");
}

// geometry = "annulus": a trough with side walls around an inner cylinder that grains can roll
// along (granlub/particles/annulus.h).
void check_ring(const Case& c) {
    const Section& cell = c.sections.at("cell");
    const double d = c.grains.diameter, R = c.cell.annulus_radius, W = c.cell.width;
    if (!cell.has("annulus_radius") || R == 0)
        cell.fail("geometry", "geometry = \"annulus\" needs [cell] annulus_radius > 0, the ring's mean radius");
    if (W == 0)
        cell.fail("width", "geometry = \"annulus\" needs a trough: width > 0 (the ring has side walls; a periodic "
                           "width exists only in a slice)");
    if (R - W / 2 < kMinRingInnerRadiusDiameters * d)
        cell.fail("annulus_radius",
                  fmt::format("the ring's inner wall, annulus_radius - width/2 = {:g} m, is {:.3g} grain diameters "
                              "from the axis; at least {:g} d = {:g} m are needed (a ring too small for its grains)",
                              R - W / 2, (R - W / 2) / d, kMinRingInnerRadiusDiameters, kMinRingInnerRadiusDiameters * d));
}

// Checks that involve more than one key (a single key's range is checked when it is read).
void check_cross_keys(const Case& c, Control control) {
    const Section& cell = c.sections.at("cell");
    const double d = c.grains.diameter;
    if (c.cell.gap < 2 * d)
        cell.fail("gap", fmt::format("the gap must hold at least two grains: gap >= 2 d = {} m", 2 * d));
    if (c.cell.length < 2 * d)
        cell.fail("length", fmt::format("the periodic length must be at least 2 d = {} m", 2 * d));
    if (c.cell.width != 0 && c.cell.width < 2 * d)
        cell.fail("width", fmt::format("the width must be 0 (periodic) or at least 2 d = {} m", 2 * d));
    if (c.cell.annulus_radius != 0 && c.cell.annulus_radius <= c.cell.width / 2)
        cell.fail("annulus_radius", fmt::format("the annulus radius must exceed half the width ({} m)", c.cell.width / 2));
    if (c.cell.ring()) check_ring(c);
    if (const Section& rep = c.sections.at("report"); !rep.string("slice_case").empty() && !c.cell.ring())
        rep.fail("slice_case", "sets the whole ring beside its slice: this case needs [cell] geometry = \"annulus\"");

    const Section& op = c.sections.at("operating");
    if (control == Control::Fill && !op.has("solid_fraction"))
        op.fail("solid_fraction", "control = \"fill\" needs [operating] solid_fraction");
    if (control == Control::Load && !op.has("normal_stress"))
        op.fail("normal_stress", "control = \"load\" needs [operating] normal_stress");
    if (op.has("solid_fraction"))
        for (double nu : op.list("solid_fraction"))
            if (nu >= c.cell.max_solid_fraction)
                op.fail("solid_fraction", fmt::format("every mean solid fraction must be below [cell] "
                                                      "max_solid_fraction = {}", c.cell.max_solid_fraction));

    if (op.has("roughness"))
        for (const char* side : {"bottom", "top"}) {
            const Section& ws = c.sections.at(fmt::format("walls.{}", side));
            if (ws.has("roughness"))
                ws.fail("roughness", fmt::format("[operating] roughness = {} sets both walls' roughness at every "
                                                 "point; give the roughness in one place only",
                                                 clipped(value_text(op.values().at("roughness")))));
        }
}

// The operating points: the Cartesian product of the [operating] lists, speed outermost, then
// solid_fraction, normal_stress, roughness. Swept keys name the point (e.g. U2.0_R0.25).
void expand_sweep(Case& c, Control control, const std::set<std::string>& swept_lists) {
    const Section& op = c.sections.at("operating");
    const auto& speeds = op.list("speed");
    const std::vector<double> none{std::nan("")};
    const auto& nus = op.has("solid_fraction") ? op.list("solid_fraction") : none;
    const auto& ps = op.has("normal_stress") ? op.list("normal_stress") : none;
    const auto& rs = op.has("roughness") ? op.list("roughness") : none;
    // Bounded before expanding: a product of long lists would exhaust memory (each factor <= the bound).
    std::size_t count = 1;
    for (const auto* l : {&speeds, &nus, &ps, &rs}) {
        count *= l->size();
        if (count > kMaxOperatingPoints)
            op.fail("speed", fmt::format("the sweep has {} x {} x {} x {} operating points (speed x solid_fraction x "
                                         "normal_stress x roughness); at most {} are allowed",
                                         speeds.size(), nus.size(), ps.size(), rs.size(), kMaxOperatingPoints));
    }
    c.points.reserve(count);
    for (double U : speeds)
        for (double nu : nus)
            for (double P : ps)
                for (double R : rs) {
                    OperatingPoint p;
                    p.index = c.points.size();
                    p.speed = U;
                    p.control = control;
                    p.solid_fraction = std::isnan(nu) ? 0.0 : nu;
                    p.normal_stress = std::isnan(P) ? 0.0 : P;
                    p.bottom = c.bottom;
                    p.top = c.top;
                    if (!std::isnan(R)) p.bottom.roughness = p.top.roughness = R;
                    p.id = fmt::format("U{}", id_number(U, true));
                    if (swept_lists.count("solid_fraction")) p.id += fmt::format("_nu{}", id_number(nu, false));
                    if (swept_lists.count("normal_stress")) p.id += fmt::format("_P{}", id_number(P, false));
                    if (swept_lists.count("roughness")) p.id += fmt::format("_R{}", id_number(R, false));
                    c.points.push_back(std::move(p));
                }
}

}  // namespace

// ---------------------------------------------------------------------------------------------
Case parse_case(std::string_view text, const std::string& source, const Schema& schema_in) {
    CaseWithBases merged = merge_bases(read_toml(text, source), source);
    toml::table& root = merged.root;
    auto owned = std::make_shared<const Schema>(schema_in);
    const Schema& schema = *owned;

    Case c;
    c.schema = owned;
    c.file = source;
    c.dir = std::filesystem::path(source).parent_path();
    // The bytes of the file and of each base, nearest first: a change in a base is a new case.
    // Without a base the hash of the file's bytes, as before bases existed.
    std::string hashed(text);
    for (const auto& b : merged.bases) {
        hashed += '\0';
        hashed += b.text;
        c.bases.push_back(b.file);
    }
    c.file_hash = hash_hex(hashed);

    check_top_level(root, source, schema);
    const std::set<std::string> swept_lists = read_sections(root, source, schema, c);
    resolve_common(c);
    const Control control =
        c.sections.at("operating").string("control") == "fill" ? Control::Fill : Control::Load;
    check_cross_keys(c, control);
    for (const auto& spec : schema.sections())
        if (spec.validate) spec.validate(c.sections.at(spec.name));
    expand_sweep(c, control, swept_lists);
    check_wall_bumps(c);  // needs every point's roughness
    return c;
}

Case load_case(const std::filesystem::path& dir_or_file, const Schema& schema) {
    const CaseFileText f = read_case_file(dir_or_file);
    return parse_case(f.text, f.file.string(), schema);
}

const Section& Case::section(std::string_view which) const {
    auto it = sections.find(std::string(which));
    if (it == sections.end()) throw Error(fmt::format("internal: case has no section [{}]", which));
    return it->second;
}

std::vector<const OperatingPoint*> Case::select(std::string_view id) const {
    std::vector<const OperatingPoint*> out;
    for (const auto& p : points)
        if (id.empty() || p.id == id) out.push_back(&p);
    if (out.empty()) {
        std::vector<std::string> ids;
        for (const auto& p : points) ids.push_back(p.id);
        throw CaseError(fmt::format("{}: no operating point '{}' (points: {})", file.string(), id, fmt::join(ids, ", ")));
    }
    return out;
}

namespace {
// The sections a solver's results depend on: the common ones, its own, and the ones it uses.
bool feeds(const Case& c, const std::string& section, std::string_view solver_section) {
    if (const auto s = c.sections.find(section); s != c.sections.end() && !s->second.spec().solver_input) return false;
    if (common_sections_contains(section) || section == solver_section) return true;
    const auto it = c.sections.find(std::string(solver_section));
    if (it == c.sections.end()) return false;
    const auto& uses = it->second.spec().uses;
    return std::find(uses.begin(), uses.end(), section) != uses.end();
}
}  // namespace

namespace {
// Whether a key of a section is one of a solver's inputs: given, or defaulted, unless it sits at a
// neutral default (KeySpec::neutral_default), and never when it is no input (KeySpec::input).
bool is_input(const Section& s, const KeySpec& k) {
    if (!k.input || !s.has(k.name)) return false;
    return !(k.neutral_default && k.default_value && s.values().at(k.name) == *k.default_value);
}
}  // namespace

std::map<std::string, std::string> Case::inputs(std::string_view solver_section) const {
    std::map<std::string, std::string> out;
    for (const auto& [sname, s] : sections) {
        if (!feeds(*this, sname, solver_section)) continue;
        for (const auto& k : s.spec().keys)
            if (is_input(s, k)) out[fmt::format("[{}] {}", sname, k.name)] = value_text(s.values().at(k.name));
    }
    return out;
}

std::string Case::inputs_hash(std::string_view solver_section) const {
    // The bytes hashed are fixed (results computed before inputs() existed must stay current):
    // "[section]\n" then "key=value\n" in declaration order, sections in name order.
    std::ostringstream os;
    for (const auto& [sname, s] : sections) {
        if (!feeds(*this, sname, solver_section)) continue;
        os << '[' << sname << "]\n";
        for (const auto& k : s.spec().keys)
            if (is_input(s, k)) os << k.name << '=' << value_text(s.values().at(k.name)) << '\n';
    }
    return hash_hex(os.str());
}

bool common_sections_contains(std::string_view section) {
    static const std::set<std::string, std::less<>> names = [] {
        std::set<std::string, std::less<>> n;
        for (const auto& s : common_sections()) n.insert(s.name);
        return n;
    }();
    return names.count(section) > 0;
}

std::string describe(const Case& c) {
    std::ostringstream os;
    os << fmt::format("# {} (hash {})\n", c.file.string(), c.file_hash);
    for (const auto& b : c.bases)
        os << fmt::format("# base: {} (read first; values marked (from base) were given there, not here)\n",
                          b.string());
    os << "# values marked (default) were not given in the file\n";
    std::vector<const Section*> order;  // declaration order: common sections first
    for (const auto& spec : c.schema->sections()) order.push_back(&c.section(spec.name));
    for (const Section* s : order) {
        os << "\n[" << s->name() << "]\n";
        for (const auto& k : s->spec().keys) {
            std::string val = s->has(k.name) ? value_text(s->values().at(k.name)) : "(not set)";
            std::string note = s->is_default(k.name) ? "(default) " : "";
            if (s->has(k.name) && !s->is_default(k.name) && s->file_of(k.name) != c.file.string())
                note = fmt::format("(from base {}) ", s->file_of(k.name));
            std::string unit = k.unit.empty() ? "" : "[" + k.unit + "] ";
            os << fmt::format("{:<20} = {:<22} # {}{}{}\n", k.name, val, note, unit, k.doc);
        }
    }
    os << fmt::format("\n# {} operating point(s)\n", c.points.size());
    for (const auto& p : c.points) {
        os << fmt::format("#   {:<16} U = {} m/s, control = {}", p.id, p.speed, to_string(p.control));
        if (p.solid_fraction > 0) os << fmt::format(", solid_fraction = {}", p.solid_fraction);
        if (p.normal_stress > 0) os << fmt::format(", normal_stress = {} Pa", p.normal_stress);
        os << fmt::format(", roughness bottom/top = {}/{}\n", p.bottom.roughness, p.top.roughness);
    }
    return os.str();
}

}  // namespace granlub
