#include "report_checks.h"

#include <map>
#include <regex>

#include <fmt/format.h>

#include "formats/svg_title.h"
#include "report/shared_captions.h"
#include "synthetic.h"

namespace granlub::test {
namespace {

std::string unescape(std::string s) {
    for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
             {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&apos;", "'"}, {"&amp;", "&"}})
        for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
            s.replace(at, from.size(), to);
    return s;
}

}  // namespace

std::vector<std::string> cut_title_lines(const std::string& svg) {
    std::smatch m;
    if (!std::regex_search(svg, m, std::regex(R"re(<svg [^>]*width="([0-9.]+)")re"))) return {"no <svg width>"};
    const double width = std::stod(m[1]);
    if (!std::regex_search(svg, m, std::regex(R"re(<text class="title" x="([0-9.]+)"[^>]*>(.*?)</text>)re")))
        return {"no title (<text class=\"title\">)"};
    const double centre = std::stod(m[1]);
    const double room = postproc::title_room(centre, width);
    const std::string lines = m[2];
    std::vector<std::string> cut;
    const std::regex tspan(R"re(<tspan([^>]*)>([^<]*)</tspan>)re"), squeezed(R"re(textLength="([0-9.]+)")re");
    for (std::sregex_iterator it(lines.begin(), lines.end(), tspan), end; it != end; ++it) {
        const std::string attrs = (*it)[1], text = unescape((*it)[2]);
        std::smatch s;
        const double w = std::regex_search(attrs, s, squeezed) ? std::stod(s[1])
                                                                : postproc::bold_text_width(text, postproc::kTitleFontSize);
        if (w > room + 1e-6)
            cut.push_back(fmt::format("\"{}\": {:.1f} px wide, {:.1f} px of room around x = {}", text, w, room, centre));
    }
    return cut;
}

std::vector<std::string> cut_titles(const std::filesystem::path& plots) {
    std::vector<std::string> cut;
    for (const auto& e : std::filesystem::directory_iterator(plots))
        if (e.path().extension() == ".svg" && !e.path().stem().string().ends_with(".gnuplot"))
            for (const auto& c : cut_title_lines(slurp(e.path()))) cut.push_back(e.path().filename().string() + ": " + c);
    return cut;
}

std::vector<std::string> repeated_caption_sentences(const std::string& html) {
    std::map<std::string, int> count;
    const std::regex caption(R"re(<figcaption>([\s\S]*?)</figcaption>)re"), link(R"re(<a [^>]*>[^<]*</a>)re");
    for (std::sregex_iterator it(html.begin(), html.end(), caption), end; it != end; ++it) {
        const std::string text = unescape(std::regex_replace(std::string((*it)[1]), link, ""));
        for (const auto& s : postproc::caption_sentences(text)) ++count[s];
    }
    std::vector<std::string> repeated;
    for (const auto& [s, n] : count)
        if (n > 2) repeated.push_back(fmt::format("{}x {}", n, s));
    return repeated;
}

}  // namespace granlub::test
