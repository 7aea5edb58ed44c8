// Cross-section heat maps (see cross_section_map.h).
#include "figures/cross_section_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <set>

#include <fmt/format.h>

#include "figures/figures.h"
#include "formats/svg_plot.h"
#include "formats/format.h"
#include "formats/svg_title.h"
#include "granlub/error.h"
#include "granlub/particles/cross_section.h"
#include "results/scope.h"

namespace granlub::postproc {

namespace {

// The viridis colour map (van der Walt & Smith 2015, matplotlib), at five stops, interpolated:
// perceptually uniform and readable in greyscale and by colour-blind readers.
std::string colour(double t) {
    static constexpr std::array<std::array<double, 3>, 5> stops{{{68, 1, 84}, {59, 82, 139}, {33, 145, 140},
                                                                  {94, 201, 98}, {253, 231, 37}}};
    t = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
    const auto k = std::min<std::size_t>(3, static_cast<std::size_t>(t));
    const double f = t - static_cast<double>(k);
    auto c = [&](std::size_t i) { return static_cast<int>(std::lround(stops[k][i] + f * (stops[k + 1][i] - stops[k][i]))); };
    return fmt::format("#{:02x}{:02x}{:02x}", c(0), c(1), c(2));
}

}  // namespace

std::optional<CrossSectionMap> read_cross_section(const Run& r) {
    const auto file = r.dir / kSectionFile;
    if (!std::filesystem::exists(file)) return std::nullopt;
    const Profile t = read_table(file);
    CrossSectionMap m;
    m.y = t.column("y_over_H"), m.z = t.column("z_over_W"), m.nu = t.column("solid_fraction"), m.u = t.column("u_over_U");
    m.ny = std::set<double>(m.y.begin(), m.y.end()).size();
    m.nz = std::set<double>(m.z.begin(), m.z.end()).size();
    if (m.ny * m.nz != t.rows() || m.ny < 2 || m.nz < 2)
        throw Error(fmt::format("{}: {} rows are not a grid of {} y x {} z cells", file.string(), t.rows(), m.ny, m.nz));
    return m;
}

ColourScale colour_scale(const std::vector<const std::vector<double>*>& maps) {
    double lo = 0, hi = 0;
    for (const auto* values : maps)
        for (double v : *values) hi = std::max(hi, v), lo = std::min(lo, v);
    if (!(hi > lo)) hi = lo + 1;
    return {lo, hi};
}

std::string render_cross_section_svg(const CrossSectionMap& m, const std::vector<double>& values,
                                     const std::string& title, const std::string& bar_label, const std::string& stamp,
                                     const ColourScale* scale, const std::string& what) {
    constexpr double W = 540, x0 = 70, x1 = 430, y0 = 40, y1 = 320, bx0 = 455, bx1 = 475;
    const double H = what.empty() ? 380 : 400;
    const ColourScale own = colour_scale({&values});
    const double lo = (scale ? *scale : own).lo, hi = (scale ? *scale : own).hi;
    const std::vector<Tick> bar = linear_ticks(lo, hi);
    const double cw = (x1 - x0) / static_cast<double>(m.nz), ch = (y1 - y0) / static_cast<double>(m.ny);
    // A title wrapped onto more lines moves the map below it down by as much.
    const SvgTitle heading = svg_title(title, 0.5 * W, W, 24);
    std::string out = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" viewBox=\"0 0 {0} {1}\" "
        "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\"13\">\n<title>{2}</title>\n"
        "<rect width=\"{0}\" height=\"{1}\" fill=\"#ffffff\"/>\n",
        W, H + heading.extra_height, xml_escape(title));
    out += heading.markup;
    if (heading.extra_height > 0) out += fmt::format("<g transform=\"translate(0,{})\">\n", heading.extra_height);
    // cells: row k (y) from the floor up, column (z) from the outer wall (z/W = -1/2) to the right
    for (std::size_t c = 0; c < values.size(); ++c) {
        const auto k = static_cast<std::size_t>(std::floor(m.y[c] * static_cast<double>(m.ny)));
        const auto j = static_cast<std::size_t>(std::floor((m.z[c] + 0.5) * static_cast<double>(m.nz)));
        out += fmt::format("<rect x=\"{:.2f}\" y=\"{:.2f}\" width=\"{:.2f}\" height=\"{:.2f}\" fill=\"{}\"{}/>\n",
                           x0 + cw * static_cast<double>(j), y1 - ch * static_cast<double>(k + 1), cw + 0.3, ch + 0.3,
                           colour((values[c] - lo) / (hi - lo)), !stamp.empty() ? " fill-opacity=\"0.45\"" : "");
    }
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#000\"/>\n", x0, y0,
                       x1 - x0, y1 - y0);
    // axes: z/W along x, y/H up
    for (double t : {-0.5, -0.25, 0.0, 0.25, 0.5}) {
        const double x = x0 + (t + 0.5) * (x1 - x0);
        out += fmt::format("<line x1=\"{0:.1f}\" y1=\"{1}\" x2=\"{0:.1f}\" y2=\"{2}\" stroke=\"#000\"/>"
                           "<text x=\"{0:.1f}\" y=\"{3}\" text-anchor=\"middle\">{4}</text>\n",
                           x, y1, y1 + 5, y1 + 19, num(t, 3));
    }
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const double y = y1 - t * (y1 - y0);
        out += fmt::format("<line x1=\"{1}\" y1=\"{0:.1f}\" x2=\"{2}\" y2=\"{0:.1f}\" stroke=\"#000\"/>"
                           "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5}</text>\n",
                           y, x0 - 5, x0, x0 - 8, y + 4, num(t, 3));
    }
    out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"14\">z/W across the width "
                       "(−½: outer wall)</text>\n",
                       0.5 * (x0 + x1), y1 + 40);
    if (!what.empty())
        out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"12\" fill=\"#444\">{}</text>\n",
                           0.5 * (x0 + x1), y1 + 62, xml_escape(what));
    out += fmt::format("<text transform=\"translate(22,{}) rotate(-90)\" text-anchor=\"middle\" font-size=\"14\">"
                       "y/H across the gap (0: moving floor)</text>\n",
                       0.5 * (y0 + y1));
    // colour bar with its ticks
    constexpr int kSteps = 32;
    for (int s = 0; s < kSteps; ++s) {
        const double t0 = static_cast<double>(s) / kSteps;
        out += fmt::format("<rect x=\"{}\" y=\"{:.2f}\" width=\"{}\" height=\"{:.2f}\" fill=\"{}\"/>\n", bx0,
                           y1 - (t0 + 1.0 / kSteps) * (y1 - y0), bx1 - bx0, (y1 - y0) / kSteps + 0.3,
                           colour(t0 + 0.5 / kSteps));
    }
    out += fmt::format("<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#000\"/>\n", bx0, y0,
                       bx1 - bx0, y1 - y0);
    for (const Tick& t : bar) {
        // a tick at an end of the bar up to rounding (0.6 of a bar ending at 0.6) is labelled
        if (t.label.empty() || t.value < lo - 1e-9 * (hi - lo) || t.value > hi + 1e-9 * (hi - lo)) continue;
        const double y = y1 - (t.value - lo) / (hi - lo) * (y1 - y0);
        out += fmt::format("<line x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\" stroke=\"#000\"/>"
                           "<text x=\"{3}\" y=\"{4:.1f}\">{5}</text>\n",
                           bx1, y, bx1 + 4, bx1 + 7, y + 4, xml_escape(t.label));
    }
    out += fmt::format("<text transform=\"translate({},{}) rotate(-90)\" text-anchor=\"middle\" font-size=\"14\">{}"
                       "</text>\n",
                       W - 12, 0.5 * (y0 + y1), xml_escape(bar_label));
    if (!stamp.empty())
        out += fmt::format("<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"22\" fill=\"#b00000\" "
                           "font-weight=\"bold\">{}</text>\n",
                           0.5 * (x0 + x1), 0.5 * (y0 + y1), xml_escape(stamp));
    if (heading.extra_height > 0) out += "</g>\n";
    out += "</svg>\n";
    return out;
}

// What a map of a run that is not steady is stamped with: its state, named as what it is.
std::string cross_section_stamp(const Run& r) {
    if (r.steady()) return "";
    const std::string state = r.state_name();
    if (state == "transient") return "TRANSIENT — not a result";
    if (state == "dt-unconverged") return "DT-UNCONVERGED — Δt changes it";
    return "STATUS UNKNOWN — not checked";
}

std::string cross_section_what(const Run& r) {
    if (run_text(r, "geometry") == "cross_section")
        return "the continuum's steady solution (fully developed flow), no time average";
    return "a time average along the flow and over the run's steady window";
}

std::vector<FigureRef> cross_section_figures(const Collection& col, std::size_t i, const std::filesystem::path& plots) {
    std::vector<FigureRef> refs;
    const OperatingPoint& p = *col.points[i];
    std::vector<std::pair<const Run*, CrossSectionMap>> maps;
    for (const Run* r : col.usable(p.id))
        if (auto m = read_cross_section(*r)) maps.emplace_back(r, std::move(*m));
    // One colour scale per quantity over the point's maps: the same colour is the same value in each.
    std::vector<const std::vector<double>*> nus, us;
    for (const auto& [r, m] : maps) nus.push_back(&m.nu), us.push_back(&m.u);
    const ColourScale nu_scale = colour_scale(nus), u_scale = colour_scale(us);
    // every solver's ν map, then every solver's u/U map: the solvers' maps of a quantity side by side
    std::vector<FigureRef> u_refs;
    for (const auto& [r, m] : maps) {
        const bool unsteady = !r->steady();
        const std::string state = unsteady ? fmt::format(" ({})", r->state_name()) : "";
        const std::string base = fmt::format("cross_section_{}_{}", r->solver, point_slug(p));
        struct Q {
            const char* key;
            const std::vector<double>& v;
            const char* label;
            const char* bar;
            const ColourScale& scale;
        };
        const bool solved = run_text(*r, "geometry") == "cross_section";
        for (const Q& q : {Q{"nu", m.nu, "solid fraction ν", "ν", nu_scale},
                           Q{"u", m.u, "streamwise velocity u/U", "u/U", u_scale}}) {
            const std::string name = base + "_" + q.key;
            const std::string title = fmt::format("{} {}: {}{}", r->solver, p.id, q.label, state);
            // What the quantity is and whether the run is steady: the title and the stamp. What every
            // map shares is one sentence, said once above the maps (report/shared_captions.h).
            FigureRef f{name, title,
                        std::string("The trough's cross-section, the flow out of the page, in the particle runs' cells "
                                    "of about one grain diameter; the maps of a quantity at a point share one colour "
                                    "scale. ") +
                            (solved ? "The continuum's map: its steady solution for flow fully developed along the "
                                      "trough (a boundary-value problem, no time average), averaged over each cell."
                                    : "A particle run's map: averaged along the flow and over the steady window."),
                        render_cross_section_svg(m, q.v, title, q.bar, cross_section_stamp(*r), &q.scale,
                                                 cross_section_what(*r)),
                        {{"SVG", "plots/" + name + ".svg"}, {"data (CSV)", "plots/" + base + ".csv"}}};
            write_file_atomic(plots / (name + ".svg"), f.svg);
            std::filesystem::copy_file(r->dir / kSectionFile, plots / (base + ".csv"),
                                       std::filesystem::copy_options::overwrite_existing);
            (q.key == std::string("nu") ? refs : u_refs).push_back(std::move(f));
        }
    }
    refs.insert(refs.end(), std::make_move_iterator(u_refs.begin()), std::make_move_iterator(u_refs.end()));
    return refs;
}

}  // namespace granlub::postproc
