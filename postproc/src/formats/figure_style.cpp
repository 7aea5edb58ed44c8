#include "formats/figure_style.h"

namespace granlub::postproc {
namespace {
// Okabe, M. & Ito, K. (2008) "Color Universal Design": blue, vermillion, bluish green,
// reddish purple, orange, sky blue, black.
constexpr const char* kColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                    "#E69F00", "#56B4E9", "#000000"};
constexpr const char* kDashes[] = {"", "7 3", "2 2", "9 3 2 3"};
constexpr int kN = static_cast<int>(sizeof(kColours) / sizeof(kColours[0]));
int wrap(int s, int n) { return ((s % n) + n) % n; }
}  // namespace

const char* style_colour(int style) { return kColours[wrap(style, kN)]; }
const char* style_dash(int style) { return kDashes[wrap(style, 4)]; }
int style_gnuplot_dashtype(int style) { return wrap(style, 4) + 1; }
int style_gnuplot_pointtype(int style, bool open) {
    // gnuplot: 7 circle, 5 square, 9 triangle, 13 diamond (filled); 6, 4, 8, 12 open.
    constexpr int filled[] = {7, 5, 9, 13};
    constexpr int hollow[] = {6, 4, 8, 12};
    return open ? hollow[wrap(style, 4)] : filled[wrap(style, 4)];
}

}  // namespace granlub::postproc
