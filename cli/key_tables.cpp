#include "key_tables.h"

#include <algorithm>
#include <cstdio>
#include <cstddef>
#include <sstream>
#include <string_view>

#include <fmt/format.h>

#include "granlub/results/results.h"
#include "granlub/case/schema.h"
#include "granlub/text.h"

namespace granlub::cli {

namespace {

constexpr std::string_view kOpen = "<!-- keys:";
constexpr std::string_view kOpenEnd = "-->";
constexpr std::string_view kClose = "<!-- /keys -->";

std::string_view trimmed(std::string_view s) {
    const auto a = s.find_first_not_of(" \t\r");
    if (a == std::string_view::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) lines.push_back(l);
    return lines;
}

// A Markdown table header whose first column is "key" and which has a "default" column: the
// shape of every key table the pages held before they were generated.
bool key_table_header(std::string_view line) {
    line = trimmed(line);
    if (!line.starts_with('|')) return false;
    std::vector<std::string_view> cells;
    for (std::size_t a = 1; a < line.size();) {
        const auto b = std::min(line.find('|', a), line.size());
        cells.push_back(trimmed(line.substr(a, b - a)));
        a = b + 1;
    }
    return !cells.empty() && (cells[0] == "key" || cells[0] == "`key`") &&
           std::find(cells.begin(), cells.end(), "default") != cells.end();
}

// "page line N: `...` / declarations: `...`" for the first line where two tables differ.
std::string first_difference(const std::vector<std::string>& have, const std::vector<std::string>& want,
                             std::size_t first_line) {
    std::size_t k = 0;
    while (k < have.size() && k < want.size() && have[k] == want[k]) ++k;
    auto show = [](const std::vector<std::string>& v, std::size_t i) {
        return i < v.size() ? "`" + clipped(v[i], 100) + "`" : std::string("(nothing)");
    };
    return fmt::format("line {} reads {}, the declarations give {}", first_line + k, show(have, k), show(want, k));
}

}  // namespace

KeyTablePage refresh_key_tables(const std::string& text, const std::string& file, const Schema& schema) {
    KeyTablePage page;
    const std::vector<std::string> lines = lines_of(text);
    std::string& out = page.text;
    for (std::size_t i = 0; i < lines.size();) {
        const std::string_view line = trimmed(lines[i]);
        if (!line.starts_with(kOpen)) {
            if (key_table_header(line))
                page.problems.push_back(fmt::format(
                    "{}:{}: a key table outside <!-- keys:SECTION --> ... <!-- /keys --> markers; nothing keeps it "
                    "equal to the declarations: put the section's table between markers (cli/key_tables.h)",
                    file, i + 1));
            out += lines[i++] + "\n";
            continue;
        }
        const std::string name(trimmed(line.substr(kOpen.size(), line.size() - kOpen.size() - kOpenEnd.size())));
        std::size_t close = i + 1;
        while (close < lines.size() && trimmed(lines[close]) != kClose) ++close;
        const SectionSpec* spec = line.ends_with(kOpenEnd) ? schema.find(name) : nullptr;
        if (close == lines.size() || !spec) {
            page.problems.push_back(
                close == lines.size()
                    ? fmt::format("{}:{}: `{}` has no closing {}", file, i + 1, clipped(line, 100), kClose)
                    : fmt::format("{}:{}: `{}` names no declared section (`granlub keys` lists them)", file, i + 1,
                                  clipped(line, 100)));
            out += lines[i++] + "\n";
            continue;
        }
        const std::string want = key_table(*spec);
        const std::vector<std::string> have(lines.begin() + static_cast<std::ptrdiff_t>(i) + 1,
                                            lines.begin() + static_cast<std::ptrdiff_t>(close));
        if (have != lines_of(want))
            page.stale.push_back(fmt::format("{}:{}: the [{}] key table differs from the declarations: {}", file,
                                             i + 1, name, first_difference(have, lines_of(want), i + 2)));
        out += lines[i] + "\n" + want + lines[close] + "\n";
        ++page.tables;
        i = close + 1;
    }
    if (!text.empty() && !text.ends_with('\n')) out.pop_back();
    return page;
}

int check_key_tables(const std::vector<std::string>& files, bool update, const Schema& schema) {
    int rc = 0;
    for (const auto& f : files) {
        const KeyTablePage page = refresh_key_tables(read_file(f), f, schema);
        for (const auto& p : page.problems) fmt::print(stderr, "error: {}\n", p);
        if (!page.problems.empty()) rc = 1;
        if (page.stale.empty()) continue;
        if (update) {
            write_file_atomic(f, page.text);
            fmt::print("{}: {} key table(s) rewritten from the declarations\n", f, page.stale.size());
        } else {
            for (const auto& s : page.stale) fmt::print(stderr, "error: {}\n", s);
            fmt::print(stderr, "  (`granlub keys --update {}` rewrites its tables)\n", f);
            rc = 1;
        }
    }
    return rc;
}

}  // namespace granlub::cli
