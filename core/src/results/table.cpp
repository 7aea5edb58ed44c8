// The one reader of granlub's numeric text tables (table.h).
#include "granlub/results/table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/results/file_io.h"

namespace granlub {

Table& Table::add(std::string name, std::vector<double> values) {
    if (!columns.empty() && values.size() != rows())
        throw Error(fmt::format("internal: table column '{}' has {} rows, others have {}", name, values.size(), rows()));
    if (has(name)) throw Error(fmt::format("internal: table column '{}' added twice", name));
    names.push_back(std::move(name));
    columns.push_back(std::move(values));
    return *this;
}

bool Table::has(std::string_view name) const {
    for (const auto& n : names)
        if (n == name) return true;
    return false;
}

bool Table::has_text(std::string_view name) const {
    for (const auto& n : text_names)
        if (n == name) return true;
    return false;
}

const std::vector<double>& Table::column(std::string_view name) const {
    for (std::size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return columns[i];
    throw Error(fmt::format("table has no column '{}' (columns: {})", name, fmt::join(names, ", ")));
}

const std::vector<std::string>& Table::text(std::string_view name) const {
    for (std::size_t i = 0; i < text_names.size(); ++i)
        if (text_names[i] == name) return text_columns[i];
    throw Error(fmt::format("table has no text column '{}' (text columns: {})", name, fmt::join(text_names, ", ")));
}

namespace {

void split(const std::string& line, TableFormat::Separator sep, std::vector<std::string>& cells) {
    cells.clear();
    if (sep == TableFormat::Separator::whitespace) {
        std::istringstream ss(line);
        for (std::string t; ss >> t;) cells.push_back(std::move(t));
        return;
    }
    for (std::size_t start = 0;;) {
        const auto comma = line.find(',', start);
        cells.push_back(line.substr(start, comma - start));
        if (comma == std::string::npos) return;
        start = comma + 1;
    }
}

// The columns in file order: each one's slot in t.columns (numeric) or t.text_columns (text).
struct Slot {
    bool text = false;
    std::size_t index = 0;
};

std::vector<Slot> set_names(Table& t, const std::vector<std::string>& all, const TableFormat& f) {
    std::vector<Slot> slots;
    for (const auto& n : all) {
        const bool text = std::find(f.text.begin(), f.text.end(), n) != f.text.end();
        auto& names = text ? t.text_names : t.names;
        slots.push_back({text, names.size()});
        names.push_back(n);
    }
    t.columns.assign(t.names.size(), {});
    t.text_columns.assign(t.text_names.size(), {});
    return slots;
}

}  // namespace

Table parse_table(std::string_view text, const std::string& source, const TableFormat& f) {
    Table t;
    std::vector<std::string> all;  // every column's name, in file order
    std::vector<Slot> slots;
    if (!f.header && !f.names.empty()) all = f.names, slots = set_names(t, all, f);
    bool named = !all.empty();
    std::size_t first_row_line = 0;
    std::string line;
    std::vector<std::string> cells;
    std::size_t lineno = 0;
    for (std::size_t start = 0; start < text.size();) {
        const std::size_t eol = std::min(text.find('\n', start), text.size());
        line.assign(text.substr(start, eol - start));
        start = eol + 1;
        ++lineno;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        split(line, f.separator, cells);
        if (cells.empty()) continue;  // a whitespace-only line
        if (!named && f.header) {
            if (!f.expected_header.empty() && line != f.expected_header)
                throw Error(fmt::format("{}:{}: header '{}', expected '{}'", source, lineno, line, f.expected_header));
            all = cells;
            slots = set_names(t, all, f);
            named = true;
            continue;
        }
        if (!named) {  // no header, no names: the first row sets the count
            for (std::size_t c = 1; c <= cells.size(); ++c) all.push_back(std::to_string(c));
            slots = set_names(t, all, f);
            named = true;
            first_row_line = lineno;
        }
        if (cells.size() != all.size()) {
            if (f.header)
                throw Error(fmt::format("{}:{}: {} values, the header has {} columns", source, lineno, cells.size(),
                                        all.size()));
            if (!f.names.empty())
                throw Error(fmt::format("{}:{}: {} values, expected {}: {}", source, lineno, cells.size(), all.size(),
                                        fmt::join(all, " ")));
            throw Error(fmt::format("{}:{}: {} values, expected {} as on line {}", source, lineno, cells.size(),
                                    all.size(), first_row_line));
        }
        for (std::size_t c = 0; c < cells.size(); ++c) {
            if (slots[c].text) {
                t.text_columns[slots[c].index].push_back(cells[c]);
                continue;
            }
            if (cells[c].empty() && f.empty_cells) {
                t.columns[slots[c].index].push_back(std::numeric_limits<double>::quiet_NaN());
                continue;
            }
            char* end = nullptr;
            const double v = std::strtod(cells[c].c_str(), &end);
            if (cells[c].empty() || end == cells[c].c_str() || *end != '\0')
                throw Error(fmt::format("{}:{}: '{}' is not a number (column '{}')", source, lineno, cells[c], all[c]));
            if (f.finite && !std::isfinite(v))
                throw Error(fmt::format("{}:{}: non-finite value '{}' in column '{}'{}{}", source, lineno, cells[c],
                                        all[c], f.nonfinite_hint.empty() ? "" : ": ", f.nonfinite_hint));
            t.columns[slots[c].index].push_back(v);
        }
        t.line.push_back(lineno);
    }
    if (f.header && !named) throw Error(fmt::format("{}: empty table (no header row)", source));
    return t;
}

Table read_table(const std::filesystem::path& file, const TableFormat& format) {
    return parse_table(read_file(file), file.string(), format);
}

Table read_solver_output(const std::filesystem::path& file, const TableFormat& format, std::string_view missing) {
    if (!std::filesystem::exists(file)) throw SolverError(fmt::format("{}: {}", file.string(), missing));
    try {
        return read_table(file, format);
    } catch (const SolverError&) {
        throw;
    } catch (const Error& e) {
        throw SolverError(e.what());
    }
}

}  // namespace granlub
