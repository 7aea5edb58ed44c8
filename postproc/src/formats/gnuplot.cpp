#include "formats/gnuplot.h"

#include <fmt/format.h>

#include "formats/figure_style.h"
#include "formats/svg_plot.h"
#include "formats/format.h"
#include "granlub/results/results.h"

namespace granlub::postproc {
namespace {

std::string quote(const std::string& s) {  // gnuplot single-quoted string: '' escapes '
    std::string out = "'";
    for (char ch : s) out += ch == '\'' ? std::string("''") : std::string(1, ch);
    return out + "'";
}

std::string one_line(std::string s) {
    for (char& ch : s)
        if (ch == '\n') ch = ' ';
    return s;
}

}  // namespace

std::string gnuplot_data(const Figure& f) {
    std::string out = fmt::format("# {}\n# data for {}.gp: one block per series (gnuplot index k), columns x y err\n",
                                  one_line(f.title), f.name);
    int index = 0;
    for (const auto& s : f.series) {
        if (s.x.empty()) continue;
        out += fmt::format("# index {}: {}\n", index++, s.label.empty() ? "(unlabelled line)" : one_line(s.label));
        for (std::size_t i = 0; i < s.x.size(); ++i)
            out += fmt::format("{:.9g} {:.9g} {:.9g}\n", s.x[i], s.y[i], i < s.err.size() ? s.err[i] : 0.0);
        out += "\n\n";
    }
    return out;
}

std::string gnuplot_script(const Figure& f) {
    std::string out = fmt::format(
        "# {} -- written by granlub compare; edit freely, then run:  gnuplot {}.gp\n"
        "# A starting point for your own figure: the report's data, axis limits and labels. The\n"
        "# report's figure itself is drawn by granlub's SVG renderer, not by this script.\n"
        "# For a paper figure, e.g.:  set terminal pdfcairo size 9cm,6.5cm font 'Helvetica,8'\n"
        "set terminal svg size 540,380 font 'DejaVu Sans,13' background '#ffffff'\n"
        "set output {}\n"
        "set encoding utf8\n"
        "set title {} noenhanced\n"
        "set xlabel {} noenhanced\n"
        "set ylabel {} noenhanced\n"
        "set key noenhanced box opaque\n"
        "set grid lc rgb '#e3e3e3'\n",
        one_line(f.title), f.name, quote(f.name + ".gnuplot.svg"), quote(f.title), quote(f.x.label), quote(f.y.label));
    if (f.x.log) out += "set logscale x\n";
    if (f.y.log) out += "set logscale y\n";
    // The same frame and legend corner as the report's SVG.
    const Layout l = layout(f);
    constexpr const char* kKey[] = {"top right", "top left", "bottom right", "bottom left", "below"};
    out += fmt::format("set key {}\n", kKey[l.legend_corner]);
    if (!f.x.categories.empty()) {
        out += "set xtics (";
        for (std::size_t i = 0; i < f.x.categories.size(); ++i)
            out += fmt::format("{}{} {}", i ? ", " : "", quote(f.x.categories[i].second), f.x.categories[i].first);
        out += ")\n";
    }
    out += fmt::format("set xrange [{:.9g}:{:.9g}]\nset yrange [{:.9g}:{:.9g}]\n", l.xlo, l.xhi, l.ylo, l.yhi);
    // Log axes: the SVG's labelled ticks (1-2-5 within a decade), not only the decades.
    const auto log_tics = [&](const char* axis, double lo, double hi) {
        std::string t;
        for (const auto& tick : log_ticks(lo, hi))
            if (!tick.label.empty()) t += fmt::format("{}{} {:.9g}", t.empty() ? "" : ", ", quote(num(tick.value, 6)), tick.value);
        if (!t.empty()) out += fmt::format("set {}tics ({})\nset m{}tics 10\n", axis, t, axis);
    };
    if (f.x.log) log_tics("x", l.xlo, l.xhi);
    if (f.y.log) log_tics("y", l.ylo, l.yhi);

    std::vector<std::string> clauses;
    const std::string data = quote(f.name + ".dat");
    int index = 0;
    for (const auto& s : f.series) {
        if (s.x.empty()) continue;
        // Not steady: faded (gnuplot's #AARRGGBB, AA = transparency), dotted lines and hollow markers.
        const std::string rgb = s.unsteady ? fmt::format("#80{}", style_colour(s.style) + 1) : style_colour(s.style);
        const std::string colour = fmt::format("lc rgb '{}'", rgb);
        const std::string title = s.label.empty() ? "notitle" : "title " + quote(s.label);
        if (s.mark == Mark::Line) {
            if (s.err.size() == s.y.size())
                clauses.push_back(fmt::format(
                    "{} index {} using 1:($2-$3):($2+$3) with filledcurves fc rgb '{}' fs transparent solid 0.22 "
                    "noborder notitle",
                    data, index, style_colour(s.style)));
            clauses.push_back(fmt::format("{} index {} using 1:2 with lines lw {} dt {} {} {}", data, index,
                                          s.dashed ? 1.5 : 2,
                                          s.unsteady ? 3 : s.dashed ? 2 : style_gnuplot_dashtype(s.style), colour,
                                          title));
        } else {
            clauses.push_back(fmt::format("{} index {} using 1:2:3 with yerrorbars pt {} ps 1.1 {} {}", data, index,
                                          style_gnuplot_pointtype(s.style, s.open || s.unsteady), colour, title));
        }
        ++index;
    }
    if (clauses.empty()) {
        out += "set label 'no results' at graph 0.5, 0.5 center\nplot [0:1][0:1] NaN notitle\n";
        return out;
    }
    out += "plot ";
    for (std::size_t i = 0; i < clauses.size(); ++i) out += (i ? ", \\\n     " : "") + clauses[i];
    out += "\n";
    return out;
}

void write_gnuplot(const Figure& f, const std::filesystem::path& dir) {
    write_file_atomic(dir / (f.name + ".dat"), gnuplot_data(f));
    write_file_atomic(dir / (f.name + ".gp"), gnuplot_script(f));
}

}  // namespace granlub::postproc
