// The report as a document model (headings, text, tables, figures, links), built once
// (report_builder.h) and rendered twice: self-contained HTML and Markdown.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace granlub::postproc {

struct Cell {
    std::string text;
    std::string cls;  // "", "ok", "missing", "stale", "corrupt", "failed", "noanswer", "transient", "unknown",
                      // "significant", "uncertain", "code"
};

struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<Cell>> rows;
};

struct FigureRef {
    std::string name;     // plots/<name>.svg
    std::string title;
    std::string caption;  // what is particular to this figure (the report's legend says the rest)
    std::string svg;      // inlined into the HTML
    std::vector<std::pair<std::string, std::string>> files;  // (label, href): SVG, PDF, data, gnuplot source
};

struct Block {
    // FoldBegin .. FoldEnd: a part the reader opens (HTML <details>; Markdown a heading).
    enum class Kind { Heading, Text, Note, Table, Figures, Pre, Links, FoldBegin, FoldEnd } kind = Kind::Text;
    int level = 2;                                   // Heading
    bool open = false;                               // FoldBegin: shown unfolded
    std::string text;                                // Heading, Text, Note, Pre, FoldBegin (its summary)
    Table table;                                     // Table
    std::vector<FigureRef> figures;                  // Figures (shown side by side)
    std::vector<std::pair<std::string, std::string>> links;  // Links: (label, relative href)
};

struct Report {
    std::string title;
    std::vector<Block> blocks;

    Report& heading(std::string text, int level = 2);
    Report& text(std::string text);
    Report& note(std::string text);  // a paragraph in smaller type (HTML class "note"; Markdown: plain text)
    Report& table(Table t);
    Report& figures(std::vector<FigureRef> f);
    Report& pre(std::string text);
    Report& links(std::vector<std::pair<std::string, std::string>> l);
    Report& fold(std::string summary, bool open = false);  // until end_fold()
    Report& end_fold();
};

// One self-contained, well-formed (XHTML-style) file; a navigation bar links every level-2 heading
// (id "s-" + its slug).
std::string render_html(const Report& r);
std::string heading_id(const std::string& text);  // "Wall stresses against speed" -> "s-wall-stresses-against-speed"
std::string render_markdown(const Report& r);  // figures as links to plots/<name>.svg

}  // namespace granlub::postproc
