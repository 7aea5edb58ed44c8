// A figure's title in SVG, wrapped so that it never runs past the figure's edge: the lines break
// between words where the estimated width (DejaVu Sans Bold, the first of the figures' fonts and
// the widest of them) would pass the width available around the title's centre. The plots and the
// cross-section maps both draw their titles here; the tests measure the titles with the same
// estimate.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace granlub::postproc {

inline constexpr double kTitleFontSize = 14;    // px, bold
inline constexpr double kTitleLineHeight = 17;  // px between the baselines of a wrapped title
inline constexpr double kTitleMargin = 6;       // px kept clear of the figure's edges

// The advance width in px of `text` (UTF-8) in DejaVu Sans Bold at `font_size`: the font's own
// advance per ASCII character, 0 for combining marks, one em for any other character (Greek
// letters and the mathematical signs are narrower).
double bold_text_width(std::string_view text, double font_size);

// The widest a title line centred at `centre` may be in a figure `figure_width` px wide.
double title_room(double centre, double figure_width);

// `title` broken between words into lines no wider than `room` at the title's size; a single word
// wider than that stays one line (svg_title squeezes it).
std::vector<std::string> title_lines(const std::string& title, double room);

// The <text> element of the title centred at `centre` with its first baseline at `baseline`, and
// how much taller than one line it is (what the figure grows by).
struct SvgTitle {
    std::string markup;
    double extra_height = 0;
};
SvgTitle svg_title(const std::string& title, double centre, double figure_width, double baseline);

}  // namespace granlub::postproc
