// Wrapped SVG titles (see svg_title.h).
#include "formats/svg_title.h"

#include <algorithm>
#include <array>
#include <sstream>

#include <fmt/format.h>

#include "formats/format.h"

namespace granlub::postproc {
namespace {

// DejaVu Sans Bold 2.37 (Debian fonts-dejavu-core), hmtx advance widths of U+0020..U+007E in font
// units (2048 per em), read from DejaVuSans-Bold.ttf.
constexpr double kUnitsPerEm = 2048;
constexpr std::array<int, 95> kAsciiAdvance = {
    713,  934,  1067, 1716, 1425, 2052, 1786, 627,  936,  936,  1071, 1716, 778,  850,  778,  748,  1425, 1425, 1425,
    1425, 1425, 1425, 1425, 1425, 1425, 1425, 819,  819,  1716, 1716, 1716, 1188, 2048, 1585, 1561, 1503, 1700, 1399,
    1399, 1681, 1714, 762,  762,  1587, 1305, 2038, 1714, 1741, 1501, 1741, 1577, 1475, 1397, 1663, 1585, 2259, 1579,
    1483, 1485, 936,  748,  936,  1716, 1024, 1024, 1382, 1466, 1214, 1466, 1389, 891,  1466, 1458, 702,  702,  1362,
    702,  2134, 1458, 1407, 1466, 1466, 1010, 1219, 979,  1458, 1335, 1892, 1321, 1335, 1192, 1458, 748,  1458, 1716};

// The code points of a UTF-8 string (a malformed byte counts as one character).
std::vector<char32_t> code_points(std::string_view s) {
    std::vector<char32_t> out;
    for (std::size_t i = 0; i < s.size();) {
        const auto b = static_cast<unsigned char>(s[i]);
        const std::size_t n = b < 0x80 ? 1 : (b >> 5) == 0x6 ? 2 : (b >> 4) == 0xE ? 3 : (b >> 3) == 0x1E ? 4 : 1;
        char32_t c = n == 1 ? b : b & (0x7F >> n);
        for (std::size_t k = 1; k < n && i + k < s.size(); ++k) c = (c << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
        out.push_back(c);
        i += n;
    }
    return out;
}

}  // namespace

double bold_text_width(std::string_view text, double font_size) {
    double units = 0;
    for (char32_t c : code_points(text)) {
        if (c >= 0x20 && c <= 0x7E)
            units += kAsciiAdvance[c - 0x20];
        else if (c < 0x300 || c > 0x36F)  // combining marks (the bar of ν̄) take no width
            units += kUnitsPerEm;
    }
    return units / kUnitsPerEm * font_size;
}

double title_room(double centre, double figure_width) {
    return 2 * (std::min(centre, figure_width - centre) - kTitleMargin);
}

std::vector<std::string> title_lines(const std::string& title, double room) {
    std::vector<std::string> lines;
    std::istringstream words(title);
    for (std::string w; words >> w;) {
        if (!lines.empty() && bold_text_width(lines.back() + " " + w, kTitleFontSize) <= room)
            lines.back() += " " + w;
        else
            lines.push_back(w);
    }
    if (lines.empty()) lines.emplace_back();
    return lines;
}

SvgTitle svg_title(const std::string& title, double centre, double figure_width, double baseline) {
    const double room = title_room(centre, figure_width);
    const std::vector<std::string> lines = title_lines(title, room);
    SvgTitle t;
    t.extra_height = kTitleLineHeight * static_cast<double>(lines.size() - 1);
    t.markup = fmt::format("<text class=\"title\" x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"{}\" "
                           "font-weight=\"bold\">",
                           centre, baseline, kTitleFontSize);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        // one word wider than the room: squeezed into it rather than cut at the edge
        const std::string squeeze = bold_text_width(lines[k], kTitleFontSize) > room
                                        ? fmt::format(" textLength=\"{}\" lengthAdjust=\"spacingAndGlyphs\"", room)
                                        : "";
        t.markup += fmt::format("<tspan x=\"{}\" dy=\"{}\"{}>{}</tspan>", centre, k == 0 ? 0 : kTitleLineHeight,
                                squeeze, xml_escape(lines[k]));
    }
    t.markup += "</text>\n";
    return t;
}

}  // namespace granlub::postproc
