// The one reader of the bulk-rheology table (bulk_rheology_table.h): its format line, the columns a fit needs
// and the reading rule that picks the answers.
#include <algorithm>
#include <cmath>
#include <span>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/particles/bulk_rheology_table.h"
#include "granlub/results/file_io.h"
#include "granlub/results/table.h"

namespace granlub {

namespace {

// The columns this reader needs, with their units (cases/bulk_shear/README.md documents every column).
struct Needed {
    const char* name;
    const char* what;
};
constexpr Needed kText[] = {
    {"point", "the operating point id"},
    {"status", "the point's status: steady, transient or dt-unconverged"},
    {"core_dt_check", "the core's Delta-t verdict: converged, unconverged:..., not-checked"}};
constexpr Needed kNumbers[] = {
    {"load_Pa", "the imposed normal stress, Pa"},
    {"pressure_Pa", "the core's pressure P, Pa"},
    {"pressure_err", "P's standard error, Pa"},
    {"I", "the core's inertial number, dimensionless"},
    {"I_err", "I's standard error"},
    {"mu", "the core's stress ratio tau/P, dimensionless"},
    {"mu_err", "mu's standard error"},
    {"nu", "the core's solid fraction, dimensionless"},
    {"nu_err", "nu's standard error"},
    {"T_scaled", "the core's T/(d gamma_dot)^2, dimensionless"},
    {"T_scaled_err", "T_scaled's standard error"}};

constexpr const char* kFormatPrefix = "# format ";

std::string first_line(std::string_view text) {
    std::string l(text.substr(0, text.find('\n')));
    if (!l.empty() && l.back() == '\r') l.pop_back();
    return l;
}

// where the header row ends: the end of the first line that is neither empty nor a comment
std::size_t header_end(std::string_view text) {
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        const std::string_view l = text.substr(start, eol - start);
        if (!l.empty() && l != "\r" && l[0] != '#') return eol;
        start = eol + 1;
    }
    return text.size();
}

// an answer's values must be usable by a fit: refused naming the row and the column
void check_answer(const BulkRow& r, const std::string& source) {
    const auto fail = [&](const char* column, double v, const char* allowed) {
        throw Error(fmt::format("{}:{}: point {} is an answer (status = steady, core_dt_check = converged) but its {} "
                                "= {} (allowed: {})",
                                source, r.line, r.point, column, v, allowed));
    };
    const auto measured = [&](const char* column, const char* err, const Measured& m) {
        if (!std::isfinite(m.value)) fail(column, m.value, "a finite number");
        if (!(m.error >= 0) || !std::isfinite(m.error)) fail(err, m.error, "a finite standard error >= 0");
    };
    measured("I", "I_err", r.inertial);
    measured("mu", "mu_err", r.friction);
    measured("nu", "nu_err", r.solid_fraction);
    measured("T_scaled", "T_scaled_err", r.temperature_scaled);
    measured("pressure_Pa", "pressure_err", r.pressure);
    if (!(r.inertial.value > 0)) fail("I", r.inertial.value, "> 0");
    if (!(r.pressure.value > 0)) fail("pressure_Pa", r.pressure.value, "> 0");
    if (!(r.load > 0)) fail("load_Pa", r.load, "> 0");
    if (!(r.solid_fraction.value > 0 && r.solid_fraction.value < 1)) fail("nu", r.solid_fraction.value, "(0, 1)");
}

}  // namespace

bool is_answer(const BulkRow& r) { return r.status == "steady" && r.core_dt_check == "converged"; }

std::vector<BulkRow> BulkRows::answers() const {
    std::vector<BulkRow> a;
    for (const auto& r : rows)
        if (is_answer(r)) a.push_back(r);
    return a;
}

BulkRows parse_bulk_table(std::string_view text, const std::string& source) {
    const std::string expected = std::string(kFormatPrefix) + kBulkTableFormat;
    const std::string first = first_line(text);
    if (first != expected) {
        if (first.starts_with(kFormatPrefix))
            throw Error(fmt::format("{}:1: a table of format '{}'; expected '{}' (what `granlub bulk-rheology` "
                                    "writes: cases/bulk_shear/README.md)",
                                    source, first.substr(std::string_view(kFormatPrefix).size()), kBulkTableFormat));
        throw Error(fmt::format("{}:1: not a bulk-rheology table: its first line is '{}', expected '{}' (what `granlub "
                                "bulk-rheology` writes: cases/bulk_shear/README.md)",
                                source, first.substr(0, 80), expected));
    }
    TableFormat f;
    for (const auto& n : kText) f.text.push_back(n.name);
    f.text.push_back("dt_check");
    f.text.push_back("Z_source");
    f.empty_cells = true;  // the writer leaves a cell empty when the value is not available (no check, no Z)
    // the columns first, from the header alone: a renamed text column must not fail as a cell that is not a number
    const Table header = parse_table(text.substr(0, header_end(text)), source, {});
    for (const auto& list : {std::span<const Needed>(kText), std::span<const Needed>(kNumbers)})
        for (const auto& n : list)
            if (!header.has(n.name))
                throw Error(fmt::format("{}: no column '{}' ({}): a {} table has it (cases/bulk_shear/README.md)",
                                        source, n.name, n.what, kBulkTableFormat));
    const Table t = parse_table(text, source, f);
    BulkRows out;
    out.source = source;
    for (std::size_t start = 0; start < text.size();) {  // the comment lines after the format line
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        std::string l(text.substr(start, eol - start));
        start = eol + 1;
        if (!l.empty() && l.back() == '\r') l.pop_back();
        if (!l.starts_with('#')) continue;
        if (l == expected) continue;
        out.provenance.push_back(l.substr(l.starts_with("# ") ? 2 : 1));
    }
    const auto num = [&](const char* name, std::size_t i) { return t.column(name)[i]; };
    const auto measured = [&](const char* name, const char* err, std::size_t i) {
        return Measured{num(name, i), num(err, i)};
    };
    for (const char* w : kWallColumns)
        if (!t.has(w)) out.missing_wall_columns.emplace_back(w);
    const bool walls = out.missing_wall_columns.empty();
    for (std::size_t i = 0; i < t.rows(); ++i) {
        BulkRow r;
        r.point = t.text("point")[i];
        r.status = t.text("status")[i];
        r.core_dt_check = t.text("core_dt_check")[i];
        r.line = t.line[i];
        r.load = num("load_Pa", i);
        r.pressure = measured("pressure_Pa", "pressure_err", i);
        r.inertial = measured("I", "I_err", i);
        r.friction = measured("mu", "mu_err", i);
        r.solid_fraction = measured("nu", "nu_err", i);
        r.temperature_scaled = measured("T_scaled", "T_scaled_err", i);
        if (t.has("speed_m_s")) r.speed = num("speed_m_s", i);
        if (walls) {
            r.slip_bottom = measured("slip_bottom_over_U", "slip_bottom_err", i);
            r.slip_top = measured("slip_top_over_U", "slip_top_err", i);
            r.T_wall_bottom = measured("T_wall_bottom_over_U2", "T_wall_bottom_err", i);
            r.T_wall_top = measured("T_wall_top_over_U2", "T_wall_top_err", i);
        }
        if (is_answer(r)) check_answer(r, source);
        out.rows.push_back(std::move(r));
    }
    return out;
}

BulkRows read_bulk_table(const std::filesystem::path& file) { return parse_bulk_table(read_file(file), file.string()); }

}  // namespace granlub
