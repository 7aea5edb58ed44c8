#include "formats/report.h"

#include <cctype>

#include <fmt/format.h>

#include "formats/format.h"

namespace granlub::postproc {

namespace {
Block block_of(Block::Kind kind, std::string text = "") {
    Block b;
    b.kind = kind;
    b.text = std::move(text);
    return b;
}
}  // namespace

Report& Report::heading(std::string t, int level) {
    blocks.push_back(block_of(Block::Kind::Heading, std::move(t)));
    blocks.back().level = level;
    return *this;
}
Report& Report::text(std::string t) {
    blocks.push_back(block_of(Block::Kind::Text, std::move(t)));
    return *this;
}
Report& Report::note(std::string t) {
    blocks.push_back(block_of(Block::Kind::Note, std::move(t)));
    return *this;
}
Report& Report::table(Table t) {
    blocks.push_back(block_of(Block::Kind::Table));
    blocks.back().table = std::move(t);
    return *this;
}
Report& Report::figures(std::vector<FigureRef> f) {
    blocks.push_back(block_of(Block::Kind::Figures));
    blocks.back().figures = std::move(f);
    return *this;
}
Report& Report::pre(std::string t) {
    blocks.push_back(block_of(Block::Kind::Pre, std::move(t)));
    return *this;
}
Report& Report::links(std::vector<std::pair<std::string, std::string>> l) {
    blocks.push_back(block_of(Block::Kind::Links));
    blocks.back().links = std::move(l);
    return *this;
}
Report& Report::fold(std::string summary, bool open) {
    blocks.push_back(block_of(Block::Kind::FoldBegin, std::move(summary)));
    blocks.back().open = open;
    return *this;
}
Report& Report::end_fold() {
    blocks.push_back(block_of(Block::Kind::FoldEnd));
    return *this;
}

std::string heading_id(const std::string& text) {
    std::string slug;
    bool dash = false;  // a run of separators becomes one '-'
    for (unsigned char ch : text) {
        if (std::isalnum(ch)) {
            if (dash && !slug.empty()) slug.push_back('-');
            slug.push_back(static_cast<char>(std::tolower(ch)));
            dash = false;
        } else if (ch < 0x80) {
            dash = true;  // non-ASCII (ν, σ) is left out
        }
    }
    return fmt::format("s-{}", slug);
}

namespace {

constexpr const char* kStyle = R"(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 1.5em auto; max-width: 1700px;
       padding: 0 1.5em; color: #222; line-height: 1.45; }
h1 { font-size: 1.2em; border-bottom: 2px solid #0072B2; padding-bottom: .2em; margin: .4em 0 .3em; }
h2 { font-size: 1.3em; margin-top: 1.8em; border-bottom: 1px solid #ccc; }
h2#s-summary { margin-top: .6em; }
h2#s-summary + .tw table { font-size: .8em; margin-top: .3em; }  /* the summary: within the first screen */
h2#s-summary + .tw td, h2#s-summary + .tw th { padding: .15em .4em; line-height: 1.3; }
h2#s-summary + .tw td:first-child { white-space: nowrap; }
p.note { font-size: .85em; margin: .4em 0; }
h3 { font-size: 1.1em; margin-top: 1.3em; }
table { border-collapse: collapse; margin: .6em 0 1em; font-size: .9em; }
th, td { border: 1px solid #ccc; padding: .25em .6em; text-align: left; vertical-align: top; }
th { background: #f2f2f2; }
td.ok { background: #e3f4ea; } td.missing { background: #f3f3f3; color: #777; }
td.stale { background: #fff3d6; } td.corrupt { background: #fbe0dc; }
td.significant { font-weight: bold; background: #fff3d6; }
td.transient, td.unknown { color: #888; font-style: italic; background: #f3f3f3; }
td.failed { background: #fbe0dc; } td.noanswer { background: #eef0f7; color: #555; }
td.code { font-family: monospace; font-size: .85em; max-width: 40em; word-break: break-all; }
td.uncertain { background: #fff3d6; font-style: italic; }
.tw { max-width: 100%; overflow-x: auto; }
.figs { display: grid; grid-template-columns: repeat(auto-fill, minmax(420px, 1fr)); gap: 1em; }
figure { margin: 0; max-width: 540px; min-width: 0; }
figcaption a { margin-right: .5em; }
figure svg { width: 100%; height: auto; border: 1px solid #eee; }
figcaption { font-size: .85em; color: #444; }
pre { background: #f7f7f7; padding: .8em; overflow-x: auto; font-size: .85em; }
nav { position: sticky; top: 0; background: #ffffffee; border-bottom: 1px solid #ccc; padding: .3em 0;
      display: flex; flex-wrap: wrap; font-size: .8em; z-index: 1; }
nav a { margin-right: 1em; color: #0072B2; text-decoration: none; white-space: nowrap; }
h2 { scroll-margin-top: 2.5em; }
details { margin: .4em 0 .8em; }
summary { cursor: pointer; font-weight: bold; font-size: 1.05em; padding: .2em 0; }
)";

std::string html_cell(const Cell& c, const char* tag) {
    if (c.cls.empty()) return fmt::format("<{0}>{1}</{0}>", tag, xml_escape(c.text));
    return fmt::format("<{0} class=\"{1}\">{2}</{0}>", tag, c.cls, xml_escape(c.text));
}

std::string md_escape(const std::string& s) {
    std::string out;
    for (char ch : s) {
        if (ch == '|') out += "\\|";
        else if (ch == '\n') out += ' ';
        else out += ch;
    }
    return out;
}

}  // namespace

std::string render_html(const Report& r) {
    std::string out = "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" lang=\"en\">\n<head>\n"
                      "<meta charset=\"utf-8\"/>\n<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n";
    out += fmt::format("<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n", xml_escape(r.title),
                       kStyle, xml_escape(r.title));
    out += "<nav>";
    for (const auto& b : r.blocks)
        if (b.kind == Block::Kind::Heading && b.level == 2)
            out += fmt::format("<a href=\"#{}\">{}</a>", heading_id(b.text), xml_escape(b.text));
    out += "</nav>\n";
    for (const auto& b : r.blocks) {
        switch (b.kind) {
            case Block::Kind::Heading:
                if (b.level == 2)
                    out += fmt::format("<h2 id=\"{}\">{}</h2>\n", heading_id(b.text), xml_escape(b.text));
                else
                    out += fmt::format("<h{0}>{1}</h{0}>\n", b.level, xml_escape(b.text));
                break;
            case Block::Kind::FoldBegin:
                out += fmt::format("<details{}>\n<summary>{}</summary>\n", b.open ? " open=\"open\"" : "",
                                   xml_escape(b.text));
                break;
            case Block::Kind::FoldEnd: out += "</details>\n"; break;
            case Block::Kind::Text: out += fmt::format("<p>{}</p>\n", xml_escape(b.text)); break;
            case Block::Kind::Note: out += fmt::format("<p class=\"note\">{}</p>\n", xml_escape(b.text)); break;
            case Block::Kind::Pre: out += fmt::format("<pre>{}</pre>\n", xml_escape(b.text)); break;
            case Block::Kind::Table:
                out += "<div class=\"tw\"><table>\n<thead><tr>";
                for (const auto& h : b.table.header) out += html_cell({h, ""}, "th");
                out += "</tr></thead>\n<tbody>\n";
                for (const auto& row : b.table.rows) {
                    out += "<tr>";
                    for (const auto& c : row) out += html_cell(c, "td");
                    out += "</tr>\n";
                }
                out += "</tbody>\n</table></div>\n";
                break;
            case Block::Kind::Figures:
                out += "<div class=\"figs\">\n";
                for (const auto& f : b.figures) {
                    std::string links;
                    for (const auto& [label, href] : f.files)
                        links += fmt::format(" <a href=\"{}\">{}</a>", xml_escape(href), xml_escape(label));
                    out += fmt::format("<figure id=\"{}\">\n{}<figcaption>{}{}</figcaption>\n</figure>\n", f.name, f.svg,
                                       xml_escape(f.caption), links);
                }
                out += "</div>\n";
                break;
            case Block::Kind::Links:
                out += "<ul>\n";
                for (const auto& [label, href] : b.links)
                    out += fmt::format("<li><a href=\"{}\">{}</a></li>\n", xml_escape(href), xml_escape(label));
                out += "</ul>\n";
                break;
        }
    }
    out += "</body>\n</html>\n";
    return out;
}

std::string render_markdown(const Report& r) {
    std::string out = fmt::format("# {}\n\n", r.title);
    for (const auto& b : r.blocks) {
        switch (b.kind) {
            case Block::Kind::Heading: out += fmt::format("{} {}\n\n", std::string(static_cast<std::size_t>(b.level), '#'), b.text); break;
            case Block::Kind::FoldBegin: out += fmt::format("#### {}\n\n", b.text); break;
            case Block::Kind::FoldEnd: break;
            case Block::Kind::Text:
            case Block::Kind::Note: out += b.text + "\n\n"; break;
            case Block::Kind::Pre: out += "```\n" + b.text + (b.text.ends_with('\n') ? "" : "\n") + "```\n\n"; break;
            case Block::Kind::Table: {
                out += "|";
                for (const auto& h : b.table.header) out += fmt::format(" {} |", md_escape(h));
                out += "\n|";
                for (std::size_t i = 0; i < b.table.header.size(); ++i) out += "---|";
                out += "\n";
                for (const auto& row : b.table.rows) {
                    out += "|";
                    for (const auto& c : row) {
                        const std::string t = md_escape(c.text);
                        // Not steady (transient, unknown): italic, never bold.
                        const bool greyed = c.cls == "transient" || c.cls == "unknown" || c.cls == "uncertain";
                        out += " " + (c.cls == "significant" && !t.empty() ? "**" + t + "**"
                                      : c.cls == "code" && !t.empty()      ? "`" + t + "`"
                                      : greyed && !t.empty()               ? "_" + t + "_"
                                                                           : t) + " |";
                    }
                    out += "\n";
                }
                out += "\n";
                break;
            }
            case Block::Kind::Figures:
                for (const auto& f : b.figures) {
                    std::string links;
                    for (const auto& [label, href] : f.files) links += fmt::format("{}[{}]({})", links.empty() ? "" : " · ", label, href);
                    // a caption left empty (its sentences said above the figures) leaves no empty emphasis
                    const std::string caption = f.caption.empty() ? "" : "*" + f.caption + "*";
                    const std::string files = links.empty() ? "" : (caption.empty() ? "(" : " (") + links + ")";
                    out += fmt::format("![{}](plots/{}.svg)\n\n{}{}\n\n", f.title, f.name, caption, files);
                }
                break;
            case Block::Kind::Links:
                for (const auto& [label, href] : b.links) out += fmt::format("- [{}]({})\n", label, href);
                out += "\n";
                break;
        }
    }
    return out;
}

}  // namespace granlub::postproc
