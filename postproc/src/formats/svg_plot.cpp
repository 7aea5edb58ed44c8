#include "formats/svg_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "formats/figure_style.h"
#include "formats/format.h"
#include "formats/svg_title.h"

namespace granlub::postproc {
namespace {

constexpr double kWidth = 540, kHeight = 380;
constexpr double kLeft = 78, kRight = 16, kTop = 34, kBottom = 52;
constexpr double kX0 = kLeft, kX1 = kWidth - kRight, kY0 = kTop, kY1 = kHeight - kBottom;

double nice_step(double span, int target) {
    const double raw = span / target;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / mag;
    const double nice = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
    return nice * mag;
}

std::string fixed_label(double v, double step) {
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
    if (std::abs(v) < step * 1e-6) v = 0;  // no "-0"
    return fmt::format("{:.{}f}", v, decimals);
}

struct Range1 {
    double lo = 0, hi = 1;
    bool log = false;
    double t(double v) const { return log ? std::log10(v) : v; }
};

// The axis range from the data (and the error bars), unless fixed.
Range1 axis_range(const Axis& a, const std::vector<Series>& series, bool is_x) {
    Range1 r;
    r.log = a.log;
    if (!a.categories.empty()) {
        double lo = std::numeric_limits<double>::infinity(), hi = -lo;
        for (const auto& c : a.categories) lo = std::min(lo, c.first), hi = std::max(hi, c.first);
        r.lo = lo - 0.6;
        r.hi = hi + 0.6;
        return r;
    }
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& s : series) {
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            const double v = is_x ? s.x[i] : s.y[i];
            const double e = (!is_x && i < s.err.size()) ? s.err[i] : 0.0;
            for (double w : {v - e, v + e, v}) {
                if (!std::isfinite(w) || (a.log && w <= 0)) continue;
                lo = std::min(lo, w);
                hi = std::max(hi, w);
            }
        }
    }
    if (!std::isfinite(lo)) lo = a.log ? 1 : 0, hi = a.log ? 10 : 1;
    if (a.lo) lo = *a.lo;
    if (a.hi) hi = *a.hi;
    if (a.log) {
        if (hi <= lo) lo /= 2, hi *= 2;
        if (!a.lo) lo /= 1.2;
        if (!a.hi) hi *= 1.2;
    } else {
        // Nearly constant data (e.g. a fill-controlled solid fraction): a window of at least
        // +-5 % of the value, so round-off is not magnified into apparent differences.
        const double mid = 0.5 * (lo + hi);
        if (hi - lo < 0.02 * std::abs(mid) || hi <= lo) {
            const double d = mid == 0 ? 1 : std::abs(mid) * 0.05;
            lo = std::min(lo, mid - d), hi = std::max(hi, mid + d);
        }
        // Snap to the enclosing ticks, then leave a small margin so no marker sits on the frame.
        const double step = nice_step(hi - lo, 5);
        const double slo = a.lo ? lo : std::floor(lo / step + 1e-9) * step;
        const double shi = a.hi ? hi : std::ceil(hi / step - 1e-9) * step;
        lo = a.lo ? lo : slo - 0.03 * (shi - slo);
        hi = a.hi ? hi : shi + 0.03 * (shi - slo);
    }
    r.lo = lo;
    r.hi = hi;
    return r;
}

struct Mapper {
    Range1 x, y;
    double px(double v) const { return kX0 + (x.t(v) - x.t(x.lo)) / (x.t(x.hi) - x.t(x.lo)) * (kX1 - kX0); }
    double py(double v) const {
        if (y.log && v <= 0) v = y.lo * 1e-3;  // below the frame, clipped
        return kY1 - (y.t(v) - y.t(y.lo)) / (y.t(y.hi) - y.t(y.lo)) * (kY1 - kY0);
    }
};

std::string tick_text(const std::string& label) {
    // "1e+03" style labels on log axes become 10^3 with a superscript.
    const auto e = label.find("e");
    if (label.rfind("1e", 0) == 0 && e == 1) {
        const int exponent = std::stoi(label.substr(2));
        return fmt::format("10<tspan dy=\"-6\" font-size=\"10\">{}</tspan>", exponent);
    }
    return xml_escape(label);
}

// A result that is not steady: hollow, dashed outline, faded (class "unsteady", for tests and styling).
constexpr const char* kUnsteadyAttrs = "class=\"unsteady\" opacity=\"0.55\"";

void marker(std::string& out, const Series& s, double x, double y) {
    const char* colour = style_colour(s.style);
    const std::string fill = s.open || s.unsteady ? "#ffffff" : colour;
    auto attrs = fmt::format("fill=\"{}\" stroke=\"{}\" stroke-width=\"1.4\"", fill, colour);
    if (s.unsteady) attrs += fmt::format(" stroke-dasharray=\"2 1.5\" {}", kUnsteadyAttrs);
    const int style = s.style;
    switch (((style % 4) + 4) % 4) {
        case 0: out += fmt::format("<circle cx=\"{:.2f}\" cy=\"{:.2f}\" r=\"4.2\" {}/>", x, y, attrs); break;
        case 1:
            out += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"7.6\" height=\"7.6\" {}/>", x - 3.8,
                               y - 3.8, attrs);
            break;
        case 2:
            out += fmt::format("<polygon points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\" {}/>", x, y - 5, x - 4.6,
                               y + 3.6, x + 4.6, y + 3.6, attrs);
            break;
        default:
            out += fmt::format("<polygon points=\"{:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f} {:.2f},{:.2f}\" {}/>", x,
                               y - 5.2, x + 4.4, y, x, y + 5.2, x - 4.4, y, attrs);
    }
}

std::string stroke(const Series& s) {
    const char* dash = s.unsteady ? "1.5 3" : s.dashed ? "5 4" : style_dash(s.style);
    std::string a = fmt::format("fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"", style_colour(s.style),
                                s.dashed ? 1.4 : 1.9);
    if (*dash) a += fmt::format(" stroke-dasharray=\"{}\"", dash);
    if (s.unsteady) a += fmt::format(" {}", kUnsteadyAttrs);
    return a;
}

std::size_t utf8_length(const std::string& s) {
    std::size_t n = 0;
    for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
    return n;
}

bool finite_point(const Series& s, std::size_t i, const Mapper& m) {
    return std::isfinite(s.x[i]) && std::isfinite(s.y[i]) && !(m.x.log && s.x[i] <= 0) && !(m.y.log && s.y[i] <= 0);
}


std::pair<double, double> legend_size(const Figure& f) {
    std::size_t longest = 0, n = 0;
    for (const auto& s : f.series)
        if (!s.label.empty()) ++n, longest = std::max(longest, utf8_length(s.label));
    return {44 + 7.6 * static_cast<double>(longest), 8 + 18 * static_cast<double>(n)};
}

// Top right, top left, bottom right, bottom left (the order gnuplot's key positions follow).
std::array<std::pair<double, double>, 4> legend_corners(double lw, double lh) {
    return {{{kX1 - lw - 6, kY0 + 6}, {kX0 + 6, kY0 + 6}, {kX1 - lw - 6, kY1 - lh - 6}, {kX0 + 6, kY1 - lh - 6}}};
}

int legend_corner(const Figure& f, const Mapper& m) {
    const auto [lw, lh] = legend_size(f);
    const auto corners = legend_corners(lw, lh);
    std::size_t best = 0, best_count = std::numeric_limits<std::size_t>::max();
    for (std::size_t c = 0; c < corners.size(); ++c) {
        std::size_t count = 0;
        for (const auto& s : f.series)
            for (std::size_t i = 0; i < s.x.size(); ++i) {
                if (!finite_point(s, i, m)) continue;
                const double e = i < s.err.size() ? s.err[i] : 0.0;
                for (double v : {s.y[i], s.y[i] + e, s.y[i] - e}) {  // the marker and its bar ends
                    const double x = m.px(s.x[i]), y = m.py(v);
                    if (x >= corners[c].first - 6 && x <= corners[c].first + lw + 6 && y >= corners[c].second - 6 &&
                        y <= corners[c].second + lh + 6)
                        ++count;
                }
            }
        if (count < best_count) best = c, best_count = count;
    }
    // No corner is free of data: below the frame, where it covers nothing.
    return best_count == 0 ? static_cast<int>(best) : kLegendBelow;
}

// The legend below the frame: as many columns as fit the figure's width.
std::size_t below_columns(const Figure& f) {
    const double lw = legend_size(f).first;
    return std::max<std::size_t>(1, static_cast<std::size_t>((kWidth - 20) / lw));
}
std::size_t legend_entries(const Figure& f) {
    return static_cast<std::size_t>(
        std::count_if(f.series.begin(), f.series.end(), [](const Series& s) { return !s.label.empty(); }));
}
double height_of(const Figure& f, int corner) {
    if (corner != kLegendBelow) return kHeight;
    const std::size_t cols = below_columns(f), rows = (legend_entries(f) + cols - 1) / cols;
    return kHeight + 8 + 18 * static_cast<double>(rows);
}

// Two neighbouring tick labels (about 7.8 px per character) would touch.
bool labels_collide(const std::vector<Tick>& ticks, const Mapper& m) {
    double last_right = -std::numeric_limits<double>::infinity();
    for (const auto& t : ticks) {
        if (t.label.empty()) continue;
        const double half = 3.9 * static_cast<double>(t.label.rfind("1e", 0) == 0 ? 4 : utf8_length(t.label));
        if (m.px(t.value) - half < last_right + 4) return true;
        last_right = m.px(t.value) + half;
    }
    return false;
}

}  // namespace

Layout layout(const Figure& f) {
    Mapper m{axis_range(f.x, f.series, true), axis_range(f.y, f.series, false)};
    return {m.x.lo, m.x.hi, m.y.lo, m.y.hi, legend_corner(f, m)};
}

std::vector<Tick> linear_ticks(double lo, double hi) {
    std::vector<Tick> ticks;
    if (!(hi > lo)) return ticks;
    const double step = nice_step(hi - lo, 5);
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1)
        ticks.push_back({k * step, fixed_label(k * step, step)});
    return ticks;
}

std::vector<Tick> log_ticks(double lo, double hi) {
    std::vector<Tick> ticks;
    if (!(lo > 0 && hi > lo)) return ticks;
    const int k0 = static_cast<int>(std::floor(std::log10(lo))), k1 = static_cast<int>(std::ceil(std::log10(hi)));
    auto inside = [&](double v) { return v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9); };
    int decades = 0;
    for (int k = k0; k <= k1; ++k) decades += inside(std::pow(10.0, k)) ? 1 : 0;
    // Up to three decades in view: label 2 and 5 as well (a reader must find 300 Pa); within one
    // decade every mantissa; more decades: the powers of ten only.
    const bool wide = hi / lo > 3.5e3;  // more than three and a half decades
    const std::vector<int> labelled = wide                               ? std::vector<int>{1}
                                      : decades >= 1 || hi / lo > 4 ? std::vector<int>{1, 2, 5}
                                                                        : std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9};
    int labels = 0;
    for (int k = k0; k <= k1; ++k) {
        for (int m = 1; m <= 9; ++m) {
            const double v = m * std::pow(10.0, k);
            if (!inside(v)) continue;
            const bool major = std::find(labelled.begin(), labelled.end(), m) != labelled.end();
            std::string label;
            if (major) label = (m == 1 && decades >= 2) ? fmt::format("1e{:+03d}", k) : num(v, 6);
            labels += major ? 1 : 0;
            ticks.push_back({v, label});
        }
    }
    // Fewer than three labels (1300 to 6000 Pa: 2000 and 5000): label every mantissa.
    if (labels < 3)
        for (auto& t : ticks)
            if (t.label.empty()) t.label = num(t.value, 6), ++labels;
    // A narrow span (1.2 to 3.5 m/s) may hold only two mantissas: add the halves (1.5, 2.5).
    if (labels < 3) {
        for (int k = k0; k <= k1; ++k)
            for (int m = 1; m <= 4; ++m) {
                const double v = (m + 0.5) * std::pow(10.0, k);
                if (inside(v)) ticks.push_back({v, num(v, 6)});
            }
        std::sort(ticks.begin(), ticks.end(), [](const Tick& a, const Tick& b) { return a.value < b.value; });
    }
    return ticks;
}

namespace {

// The svg element, its title, background and the frame's clip path.
void svg_open(const Figure& f, double height, const std::string& clip, std::string& out) {
    out += fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
        "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"13\">\n",
        kWidth, height);
    out += fmt::format("<title>{}</title>\n", xml_escape(f.title));
    out += fmt::format("<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>\n", kWidth, height);
    out += fmt::format("<defs><clipPath id=\"{}\"><rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\"/></clipPath></defs>\n",
                       clip, kX0, kY0, kX1 - kX0, kY1 - kY0);
}

// Grid, ticks, tick labels and the axes' titles.
void svg_axes(const Figure& f, const Mapper& m, std::string& out) {
    std::vector<Tick> xt, yt;
    if (!f.x.categories.empty()) {
        for (const auto& c : f.x.categories) xt.push_back({c.first, c.second});
    } else {
        xt = m.x.log ? log_ticks(m.x.lo, m.x.hi) : linear_ticks(m.x.lo, m.x.hi);
    }
    yt = m.y.log ? log_ticks(m.y.lo, m.y.hi) : linear_ticks(m.y.lo, m.y.hi);
    // A y label closer than a text line to the one below it (4500 under 5000 on a narrow log axis) is dropped; its
    // tick stays, as a minor one.
    double last_y = std::numeric_limits<double>::infinity();
    for (auto& t : yt) {
        if (t.label.empty()) continue;
        if (last_y - m.py(t.value) < 18)
            t.label.clear();
        else
            last_y = m.py(t.value);
    }
    out += "<g stroke=\"#e3e3e3\" stroke-width=\"1\">";
    for (const auto& t : xt)
        if (!t.label.empty() && f.x.categories.empty())
            out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1}\" x2=\"{0:.2f}\" y2=\"{2}\"/>", m.px(t.value), kY0, kY1);
    for (const auto& t : yt)
        if (!t.label.empty())
            out += fmt::format("<line x1=\"{1}\" y1=\"{0:.2f}\" x2=\"{2}\" y2=\"{0:.2f}\"/>", m.py(t.value), kX0, kX1);
    out += "</g>\n<g stroke=\"#333333\" stroke-width=\"1\">";
    for (const auto& t : xt) {
        const double len = t.label.empty() ? 3 : 6;
        out += fmt::format("<line x1=\"{0:.2f}\" y1=\"{1}\" x2=\"{0:.2f}\" y2=\"{2}\"/>", m.px(t.value), kY1, kY1 - len);
    }
    for (const auto& t : yt) {
        const double len = t.label.empty() ? 3 : 6;
        out += fmt::format("<line x1=\"{1}\" y1=\"{0:.2f}\" x2=\"{2}\" y2=\"{0:.2f}\"/>", m.py(t.value), kX0, kX0 + len);
    }
    out += "</g>\n<g fill=\"#222222\">";
    const bool stagger = labels_collide(xt, m);
    for (std::size_t i = 0; i < xt.size(); ++i)
        if (const auto& t = xt[i]; !t.label.empty())
            out += fmt::format("<text x=\"{:.2f}\" y=\"{}\" text-anchor=\"middle\">{}</text>", m.px(t.value),
                               kY1 + 18 + (stagger && i % 2 == 1 ? 16 : 0), tick_text(t.label));
    for (const auto& t : yt)
        if (!t.label.empty())
            out += fmt::format("<text x=\"{}\" y=\"{:.2f}\" text-anchor=\"end\">{}</text>", kX0 - 6, m.py(t.value) + 4.5,
                               tick_text(t.label));
    out += "</g>\n";
    if (!stagger)  // staggered labels take the axis title's row; they name the points themselves
        out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
                           (kX0 + kX1) / 2, kHeight - 12, xml_escape(f.x.label));
    // The y label clears the widest tick label.
    std::size_t widest = 0;
    for (const auto& t : yt) widest = std::max(widest, t.label.rfind("1e", 0) == 0 ? std::size_t{4} : utf8_length(t.label));
    const double ylabel_x = std::max(13.0, kX0 - 14 - 7.6 * static_cast<double>(widest) - 4);
    out += fmt::format(
        "<text transform=\"translate({:.1f},{}) rotate(-90)\" text-anchor=\"middle\" font-size=\"14\">{}</text>\n",
        ylabel_x, (kY0 + kY1) / 2, xml_escape(f.y.label));
}

// Data: bands, then lines, then error bars and markers, all clipped to the frame; the frame.
void svg_data(const Figure& f, const Mapper& m, const std::string& clip, std::string& out) {
    out += fmt::format("<g clip-path=\"url(#{})\">\n", clip);
    for (const auto& s : f.series) {
        if (s.mark != Mark::Line || s.err.size() != s.y.size() || s.y.empty()) continue;
        std::string pts;
        for (std::size_t i = 0; i < s.x.size(); ++i)
            if (finite_point(s, i, m)) pts += fmt::format("{:.2f},{:.2f} ", m.px(s.x[i]), m.py(s.y[i] + s.err[i]));
        for (std::size_t i = s.x.size(); i-- > 0;)
            if (finite_point(s, i, m)) pts += fmt::format("{:.2f},{:.2f} ", m.px(s.x[i]), m.py(s.y[i] - s.err[i]));
        out += fmt::format("<polygon points=\"{}\" fill=\"{}\" fill-opacity=\"{}\" stroke=\"none\"/>\n", pts,
                           style_colour(s.style), s.unsteady ? 0.08 : 0.22);
    }
    for (const auto& s : f.series) {
        if (s.mark != Mark::Line) continue;
        std::string pts;
        for (std::size_t i = 0; i < s.x.size(); ++i)
            if (finite_point(s, i, m)) pts += fmt::format("{:.2f},{:.2f} ", m.px(s.x[i]), m.py(s.y[i]));
        out += fmt::format("<polyline points=\"{}\" {} stroke-linejoin=\"round\"/>\n", pts, stroke(s));
    }
    for (const auto& s : f.series) {
        if (s.mark != Mark::Points) continue;
        const char* colour = style_colour(s.style);
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            if (!finite_point(s, i, m)) continue;
            const double x = m.px(s.x[i]);
            if (i < s.err.size() && s.err[i] > 0) {
                const double a = m.py(s.y[i] - s.err[i]), b = m.py(s.y[i] + s.err[i]);
                out += fmt::format(
                    "<path d=\"M{0:.2f},{1:.2f}V{2:.2f}M{3:.2f},{1:.2f}H{4:.2f}M{3:.2f},{2:.2f}H{4:.2f}\" "
                    "stroke=\"{5}\" stroke-width=\"1.2\" fill=\"none\"{6}/>",
                    x, a, b, x - 3.5, x + 3.5, colour, s.unsteady ? std::string(" ") + kUnsteadyAttrs : "");
            }
            marker(out, s, x, m.py(s.y[i]));
        }
        out += "\n";
    }
    out += "</g>\n";
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#333333\"/>\n", kX0,
                       kY0, kX1 - kX0, kY1 - kY0);
}

// Legend in a frame corner free of data points, else below the frame (never over a marker).
void svg_legend(const Figure& f, int corner, std::string& out) {
    std::vector<const Series*> entries;
    for (const auto& s : f.series)
        if (!s.label.empty()) entries.push_back(&s);
    if (!entries.empty()) {
        const auto [lw, lh] = legend_size(f);
        const std::size_t cols = corner == kLegendBelow ? below_columns(f) : 1;
        const auto [x0, ly] = corner == kLegendBelow ? std::pair(10.0, kHeight) : legend_corners(lw, lh)[corner];
        if (corner != kLegendBelow)
            out += fmt::format(
                "<g><rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"#ffffff\" "
                "fill-opacity=\"0.88\" stroke=\"#bbbbbb\"/>\n",
                x0, ly, lw, lh);
        else
            out += "<g>\n";
        for (std::size_t k = 0; k < entries.size(); ++k) {
            const Series& s = *entries[k];
            const double y = ly + 13 + 18 * static_cast<double>(k / cols);
            const double lx = corner == kLegendBelow ? 10.0 + lw * static_cast<double>(k % cols) : x0;
            if (s.mark == Mark::Line) {
                if (s.err.size() == s.y.size() && !s.y.empty())
                    out += fmt::format(
                        "<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"26\" height=\"10\" fill=\"{}\" fill-opacity=\"{}\"/>",
                        lx + 6, y - 5, style_colour(s.style), s.unsteady ? 0.08 : 0.22);
                out += fmt::format("<line x1=\"{:.2f}\" y1=\"{:.2f}\" x2=\"{:.2f}\" y2=\"{:.2f}\" {}/>", lx + 6, y,
                                   lx + 32, y, stroke(s));
            } else {
                marker(out, s, lx + 19, y);
            }
            out += fmt::format("<text x=\"{:.2f}\" y=\"{:.2f}\">{}</text>\n", lx + 38, y + 4.5, xml_escape(s.label));
        }
        out += "</g>\n";
    }
}

}  // namespace

std::string render_svg(const Figure& f) {
    Mapper m{axis_range(f.x, f.series, true), axis_range(f.y, f.series, false)};
    const int corner = legend_corner(f, m);
    const std::string clip = f.name + "-clip";
    // A title wrapped onto more lines moves everything below it down by as much.
    const SvgTitle title = svg_title(f.title, (kX0 + kX1) / 2, kWidth, 21);
    std::string out;
    out.reserve(16384);
    svg_open(f, height_of(f, corner) + title.extra_height, clip, out);
    out += title.markup;
    if (title.extra_height > 0) out += fmt::format("<g transform=\"translate(0,{})\">\n", title.extra_height);
    svg_axes(f, m, out);
    svg_data(f, m, clip, out);
    svg_legend(f, corner, out);
    if (title.extra_height > 0) out += "</g>\n";
    out += "</svg>\n";
    return out;
}

}  // namespace granlub::postproc
