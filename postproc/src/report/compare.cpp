// `granlub compare`: collect the results, compute the metrics, draw the figures, write the report
// into a staging folder and swap it in whole, so results/report/ is never half old, half new.
#include <unistd.h>

#include <algorithm>
#include <cstdio>

#include <fmt/format.h>

#include "figures/registry.h"
#include "formats/gnuplot.h"
#include "formats/pdf.h"
#include "formats/svg_plot.h"
#include "formats/format.h"
#include "granlub/error.h"
#include "granlub/postproc/command.h"
#include "granlub/run/run_lock.h"
#include "granlub/run/solver_info.h"
#include "report/paraview.h"
#include "report/regimes.h"
#include "report/report_builder.h"
#include "report/ring_slice.h"
#include "results/collect.h"
#include "statistics/metrics.h"

namespace granlub::postproc {
namespace {

// The figure's PDF beside its SVG (formats/pdf.h), linked second, when rsvg-convert is there.
void add_pdf(FigureRef& r, const std::filesystem::path& plots, const std::optional<std::filesystem::path>& converter) {
    if (!converter) return;
    write_pdf(*converter, plots / (r.name + ".svg"));
    r.files.insert(r.files.begin() + (r.files.empty() ? 0 : 1), {"PDF", "plots/" + r.name + ".pdf"});
}

// Renders each figure to SVG, writes it with its PDF, data and gnuplot source into plots/, and
// returns the references the report inlines.
std::vector<FigureRef> emit(const std::vector<Figure>& figs, const std::filesystem::path& plots,
                            const std::optional<std::filesystem::path>& converter) {
    std::vector<FigureRef> refs;
    for (const auto& f : figs) {
        FigureRef r{f.name, f.title, f.caption, render_svg(f),
                    {{"SVG", "plots/" + f.name + ".svg"}, {"data", "plots/" + f.name + ".dat"},
                     {"gnuplot source", "plots/" + f.name + ".gp"}}};
        write_file_atomic(plots / (f.name + ".svg"), r.svg);
        write_gnuplot(f, plots);
        add_pdf(r, plots, converter);
        refs.push_back(std::move(r));
    }
    return refs;
}

// Every row of the figure registry: per point (with usable results) or once for the case.
ReportFigures draw_figures(const Case& c, const Collection& col, const std::filesystem::path& plots,
                           const std::optional<std::filesystem::path>& converter) {
    ReportFigures figs;
    for (const FigureRow& row : figure_registry()) {
        auto draw = [&](std::size_t point, const std::string& id) {
            const FigureInput in{c, col, point, plots};
            FigureGroup g{row.heading, id, row.model ? emit(row.model(in), plots, converter) : std::vector<FigureRef>{}};
            if (row.drawn)
                for (auto& f : row.drawn(in)) {
                    add_pdf(f, plots, converter);
                    g.refs.push_back(std::move(f));
                }
            if (!g.refs.empty()) figs.groups.push_back(std::move(g));
        };
        if (!row.per_point) {
            draw(0, "");
            continue;
        }
        for (std::size_t i = 0; i < col.points.size(); ++i)
            if (!col.usable(col.points[i]->id).empty()) draw(i, col.points[i]->id);
    }
    return figs;
}

void replace_dir(const std::filesystem::path& staging, const std::filesystem::path& target) {
    std::error_code ec;
    const auto old = target.parent_path() / fmt::format(".report.old-{}", ::getpid());
    if (std::filesystem::exists(target, ec)) std::filesystem::rename(target, old);
    std::filesystem::rename(staging, target);
    std::filesystem::remove_all(old, ec);
}

std::string text_table(const Table& t) {
    // Column widths in characters (UTF-8 aware enough for the labels used here).
    auto width = [](const std::string& s) {
        std::size_t n = 0;
        for (unsigned char ch : s) n += (ch & 0xC0) != 0x80;
        return n;
    };
    std::vector<std::size_t> w(t.header.size());
    for (std::size_t k = 0; k < w.size(); ++k) w[k] = width(t.header[k]);
    for (const auto& row : t.rows)
        for (std::size_t k = 0; k < row.size() && k < w.size(); ++k) w[k] = std::max(w[k], width(row[k].text));
    std::string out;
    auto line = [&](auto get) {
        for (std::size_t k = 0; k < w.size(); ++k) {
            const std::string s = get(k);
            out += s + std::string(w[k] - width(s) + 2, ' ');
        }
        while (!out.empty() && out.back() == ' ') out.pop_back();
        out += '\n';
    };
    line([&](std::size_t k) { return t.header[k]; });
    for (const auto& row : t.rows) line([&](std::size_t k) { return k < row.size() ? row[k].text : std::string(); });
    return out;
}

// What compare locks (granlub/run/run_lock.h): each point it reads, shared, so that no run
// rewrites it half-way through the reading, and nothing else, so that runs on other points go on
// (every known solver's points whether or not their folder exists yet: a sweep that holds its
// locks may not have made it); the continuum's map; the report, exclusive, so that two compares
// do not swap their reports in at once; and the slice case's dem points it sets beside a ring's.
std::vector<LockRequest> compare_locks(const Case& c, const RunOptions& o) {
    const auto root = results_root(c, o);
    std::vector<LockRequest> locks{{root, "report", LockMode::Exclusive}};
    if (c.schema)
        for (const SolverInfo* s : declared_solvers(*c.schema))
            if (s->map) locks.push_back({root, fmt::format("{}/{}", s->name, kMapFile), LockMode::Shared});
    const auto add = [&](const std::filesystem::path& r, const std::string& solver,
                         const std::vector<const OperatingPoint*>& points) {
        for (auto& l : point_locks(r, solver, points, LockMode::Shared)) locks.push_back(std::move(l));
    };
    const auto points = c.select(o.point);
    const std::vector<std::string> known = known_solvers(c);
    for (const auto& s : known) add(root, s, points);
    for (const auto& s : result_solvers(known, root)) add(root, s, points);  // duplicates: one lock
    if (const auto slice = slice_case(c); slice && !ring_solver(c).empty())
        add(results_root(*slice, RunOptions{}), ring_solver(c), slice->select(""));
    return locks;
}

}  // namespace

int compare(const Case& c, const RunOptions& o) {
    const ResultsLock lock(compare_locks(c, o), o.wait);  // until the report is in place
    const Collection col = collect(c, o);
    std::size_t problems = 0;
    for (const auto& [key, r] : col.runs) {
        if (r.status.state == ResultState::Stale || r.status.state == ResultState::Corrupt) {
            ++problems;
            fmt::print(stderr, "granlub compare: leaving out {} {} ({}): {}\n", r.solver, r.point->id,
                       state_name(r.status.state), r.status.reason);
        } else if (r.usable() && !r.steady()) {
            fmt::print(stderr, "granlub compare: {} {} is {} ({}): shown greyed, not fitted or compared\n", r.solver,
                       r.point->id, r.state_name(), r.state_reason());
        }
    }
    const std::size_t usable = col.count(ResultState::Complete);
    if (usable == 0)
        throw Error(fmt::format("{}: no usable results to compare ({} stale or corrupt); run a solver first, e.g. "
                                "`granlub continuum {}`",
                                col.root.string(), problems, c.dir.string()));

    const auto target = col.root / "report";
    const auto staging = col.root / fmt::format(".report.partial-{}", ::getpid());
    std::error_code ec;
    std::filesystem::remove_all(staging, ec);
    try {
        const auto plots = staging / "plots";
        std::filesystem::create_directories(plots);
        const auto metrics = compute_metrics(col);
        const auto converter = pdf_converter();
        if (!converter)
            fmt::print(stderr, "granlub compare: rsvg-convert not found (Debian package librsvg2-bin): the figures have "
                               "no PDF\n");
        ReportFigures figs = draw_figures(c, col, plots, converter);
        figs.pdf = converter.has_value();
        const RingSlicePart ring = ring_slice_part(c, col);
        figs.ring_slice = emit(ring.figures, plots, converter);
        const RegimePart regime = regime_part(c, col);
        figs.regime = emit(regime.figures, plots, converter);
        const auto vtm = write_paraview(col, c.cell.gap, c.cell.width, staging / "paraview");
        const Report rep = build_report(c, col, metrics, figs, vtm, &ring, &regime);
        write_file_atomic(staging / "metrics.csv", metrics_csv(metrics));
        write_file_atomic(staging / "report.md", render_markdown(rep));
        write_file_atomic(staging / "index.html", render_html(rep));  // last: the completion marker
        replace_dir(staging, target);
    } catch (...) {
        std::filesystem::remove_all(staging, ec);
        throw;
    }
    std::vector<std::string> compared;
    for (const auto& s : col.solvers)
        if (col.any_usable(s)) compared.push_back(s);
    std::string missing;
    for (const auto& s : col.solvers)
        if (!col.any_usable(s)) missing += (missing.empty() ? "" : ", ") + s;
    for (const auto& s : col.missing_solvers) missing += (missing.empty() ? "" : ", ") + s;
    std::string names;
    for (const auto& s : compared) names += (names.empty() ? "" : ", ") + s;
    fmt::print("compare: {} ({} of {} runs usable; solvers: {}{})\n", (target / "index.html").string(), usable,
               col.runs.size(), names, missing.empty() ? "" : "; missing: " + missing);
    return problems ? 1 : 0;
}

std::string summary_table(const Case& c, const RunOptions& o) {
    // Unlocked: a printed table of what is there now; a point another run is rewriting shows as
    // missing or corrupt, which is what it is at that moment (the report is the locked reading).
    const Collection col = collect(c, o);
    Table t = key_numbers(c, col);
    // Rows for what is not usable, so the table also says what failed; then why, under the table.
    std::string why;
    for (const auto& s : col.solvers)
        for (const OperatingPoint* p : col.points) {
            const Run& r = col.run(s, p->id);
            if (!r.usable()) t.rows.push_back({{s, ""}, {p->id, ""}, {r.state_name(), ""}});
            if (const auto reason = r.state_reason(); !reason.empty())
                why += fmt::format("{} {}: {}: {}\n", s, p->id, r.state_name(), reason);
        }
    for (const auto& s : col.missing_solvers) t.rows.push_back({{s, ""}, {"(all)", ""}, {"no results", ""}});
    return text_table(t) + why;
}

}  // namespace granlub::postproc
