// The report as a document model (headings, text, tables, figures, links), built once
// (report_builder.h) and rendered twice: self-contained HTML and Markdown.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace granlub::postproc {

struct Cell {
    std::string text;
    std::string cls;  // "", "ok", "missing", "stale", "corrupt", "failed", "transient", "unknown", "significant", "code"
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<Cell>> rows;
};

struct FigureRef {
    std::string name;     // plots/<name>.svg
    std::string title;
    std::string caption;
    std::string svg;      // inlined into the HTML
};

struct Block {
    enum class Kind { Heading, Text, Table, Figures, Pre, Links } kind = Kind::Text;
    int level = 2;                                   // Heading
    std::string text;                                // Heading, Text, Pre
    Table table;                                     // Table
    std::vector<FigureRef> figures;                  // Figures (shown side by side)
    std::vector<std::pair<std::string, std::string>> links;  // Links: (label, relative href)
};

struct Report {
    std::string title;
    std::vector<Block> blocks;

    Report& heading(std::string text, int level = 2);
    Report& text(std::string text);
    Report& table(Table t);
    Report& figures(std::vector<FigureRef> f);
    Report& pre(std::string text);
    Report& links(std::vector<std::pair<std::string, std::string>> l);
};

std::string render_html(const Report& r);      // one self-contained, well-formed (XHTML-style) file
std::string render_markdown(const Report& r);  // figures as links to plots/<name>.svg

}  // namespace granlub::postproc
