// The whole ring against its slice (ring_slice.h).
#include "report/ring_slice.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "figures/figures.h"
#include "formats/format.h"
#include "granlub/error.h"
#include "granlub/results/table.h"
#include "granlub/run/solver_info.h"

namespace granlub::postproc {
namespace {

using Data = granlub::Table;  // a numeric table (core table.h), not the report's

constexpr const char* kWidthFile = "width_profile.csv";  // core cross_section.h, kWidthProfileFile

struct Quantity {
    const char* key;    // summary output (collect.h's derived names allowed)
    const char* label;  // for the table
    double scale;       // shown value = value * scale
};

constexpr Quantity kQuantities[] = {
    {"mean_solid_fraction", "ν̄ (over the mean gap)", 1.0},
    {"gap", "gap (mm)", 1e3},
    {"normal_stress_top", "σ_yy top (Pa)", 1.0},
    {"normal_stress_bottom", "σ_yy floor (Pa)", 1.0},
    {"shear_stress_bottom", "τ floor (Pa)", 1.0},
    {"shear_stress_top", "τ top (Pa)", 1.0},
    {"shear_stress_outer", "τ outer side wall (Pa)", 1.0},
    {"shear_stress_inner", "τ inner side wall (Pa)", 1.0},
    {"side_wall_support", "side walls' support of the weight (Pa)", 1.0},
    {"slip_bottom_over_U", "slip floor / U", 1.0},
    {"slip_top_over_U", "slip top / U", 1.0},
};

// The width profile of a run (granlub dem writes it beside profile.csv); nullopt with `why` set
// when the run has none (results written before granlub wrote it) or it cannot be read.
std::optional<Data> width_profile(const Run& r, std::string& why) {
    const auto file = r.dir / kWidthFile;
    if (!std::filesystem::exists(file)) {
        why = fmt::format("{} has no {} (written by granlub dem since the whole ring; rerun it with --force)",
                          r.dir.string(), kWidthFile);
        return std::nullopt;
    }
    try {
        return read_table(file);
    } catch (const Error& e) {
        why = e.what();
        return std::nullopt;
    }
}

// Solid fraction of the outer half of the width (z/W < 0) over the inner half's, with the bands'
// standard errors combined: the radial packing in one number.
std::pair<double, double> outer_over_inner(const Data& w) {
    const auto& z = w.column("z_over_W");
    const auto& nu = w.column("solid_fraction");
    const auto& se = w.column("solid_fraction_stderr");
    double o = 0, i = 0, vo = 0, vi = 0;
    for (std::size_t k = 0; k < z.size(); ++k) {
        (z[k] < 0 ? o : i) += nu[k];
        (z[k] < 0 ? vo : vi) += se[k] * se[k];
    }
    const double ratio = o / i;
    return {ratio, ratio * std::sqrt(vo / (o * o) + vi / (i * i))};
}

void add_row(Table& t, const std::string& point, const std::string& label, std::optional<double> a,
             std::optional<double> sa, std::optional<double> b, std::optional<double> sb, bool both_steady) {
    std::vector<Cell> row{{point, ""}, {label, ""}, {value_pm(a, sa), ""}, {value_pm(b, sb), ""}};
    if (!a || !b) {
        row.push_back({"", ""});
        row.push_back({"", ""});
    } else {
        const double d = *a - *b, se = std::hypot(sa.value_or(0), sb.value_or(0));
        row.push_back({num(d, 3), ""});
        if (!both_steady)
            row.push_back({"not compared (not both steady)", "transient"});
        else if (se > 0)
            row.push_back({num(d / se, 2), std::abs(d / se) > 2 ? "significant" : ""});
        else
            row.push_back({"", ""});
    }
    t.rows.push_back(std::move(row));
}

Series series(const std::string& label, int style, bool steady, std::vector<double> x, std::vector<double> y,
              std::vector<double> err) {
    Series s;
    s.unsteady = !steady;
    s.label = steady ? label : label + ": not steady";
    s.style = style;
    s.x = std::move(x);
    s.y = std::move(y);
    s.err = std::move(err);
    return s;
}

std::vector<double> stderr_or_empty(const Data& t, const char* name) {
    return t.has(name) ? t.column(name) : std::vector<double>{};
}

// Across the width (solid fraction, u/U) and across the gap (solid fraction, u/U), ring and slice.
void add_figures(RingSlicePart& part, const OperatingPoint& p, const Run& ring, const Run& slice,
                 const std::optional<Data>& wr, const std::optional<Data>& ws) {
    const std::string slug = point_slug(p);
    const bool rs = ring.steady(), ss = slice.steady();
    const char* what[] = {"solid_fraction", "u_over_U"};
    const char* label[] = {"solid fraction ν", "u/U"};
    const char* name[] = {"Solid fraction", "Velocity"};
    const char* suffix[] = {"nu", "u"};
    for (int k = 0; k < 2; ++k) {
        if (wr && ws) {
            Figure f;
            f.name = fmt::format("ring_slice_{}_width_{}", slug, suffix[k]);
            f.title = fmt::format("{} across the width, {}: whole ring and slice", name[k], p.id);
            f.caption = fmt::format(
                "{} across the trough's width, averaged over the gap and along the flow; z/W = −1/2 is the outer "
                "wall (the ring's in the equal-area frame; where the slice's centripetal force pushes). Bands ±1 "
                "standard error.",
                label[k]);
            f.x.label = "z/W (−1/2: outer wall, +1/2: inner wall)";
            f.x.lo = -0.5;
            f.x.hi = 0.5;
            f.y.label = label[k];
            if (k == 0) f.y.lo = 0;
            f.series.push_back(series("whole ring", 0, rs, wr->column("z_over_W"), wr->column(what[k]),
                                      stderr_or_empty(*wr, fmt::format("{}_stderr", what[k]).c_str())));
            f.series.push_back(series("slice + body force", 1, ss, ws->column("z_over_W"), ws->column(what[k]),
                                      stderr_or_empty(*ws, fmt::format("{}_stderr", what[k]).c_str())));
            part.figures.push_back(std::move(f));
        }
        Figure g;
        g.name = fmt::format("ring_slice_{}_gap_{}", slug, suffix[k]);
        g.title = fmt::format("{} across the gap, {}: whole ring and slice", name[k], p.id);
        g.caption = fmt::format("{} across the gap, averaged over the width and along the flow. Bands ±1 standard "
                                "error.",
                                label[k]);
        g.x.label = "y/H (0: moving floor, 1: top)";
        g.x.lo = 0;
        g.x.hi = 1;
        g.y.label = label[k];
        if (k == 0) g.y.lo = 0;
        const std::string se = fmt::format("{}_stderr", what[k]);
        for (const auto& [run, who, style, steady] :
             {std::tuple{&ring, "whole ring", 0, rs}, std::tuple{&slice, "slice + body force", 1, ss}})
            g.series.push_back(series(who, style, steady, run->y(), run->profile->column(what[k]),
                                      run->profile->has(se) ? run->profile->column(se) : std::vector<double>{}));
        part.figures.push_back(std::move(g));
    }
}

// [report] slice_case, relative to the file that gives it (a base's when inherited: [case] base).
std::filesystem::path slice_case_path(const Case& ring) {
    const Section& rep = ring.section("report");
    return std::filesystem::path(rep.file_of("slice_case")).parent_path() / rep.string("slice_case");
}

}  // namespace

std::string ring_solver(const Case& c) {
    if (c.schema)
        for (const SolverInfo* s : declared_solvers(*c.schema))
            if (s->whole_ring) return s->name;
    return {};
}

RingSlicePart ring_slice_part(const Case& ring, const Collection& col) {
    RingSlicePart part;
    part.slice_case = ring.section("report").string("slice_case");
    if (part.slice_case.empty()) return part;
    part.solver = ring_solver(ring);
    if (part.solver.empty()) {
        part.notes.push_back("No solver built into granlub runs the whole ring: nothing to set beside the slice.");
        return part;
    }
    Case slice;
    try {
        slice = load_case(slice_case_path(ring), *ring.schema);
    } catch (const Error& e) {
        part.notes.push_back(fmt::format("[report] slice_case = \"{}\": {}", part.slice_case, e.what()));
        return part;
    }
    if (slice.cell.ring()) {
        part.notes.push_back(fmt::format("[report] slice_case = \"{}\" is a whole ring too ([cell] geometry = "
                                        "\"annulus\"): nothing to set it against",
                                        part.slice_case));
        return part;
    }
    const Collection scol = collect(slice, RunOptions{});
    for (const auto* c : {&col, &scol})
        if (std::find(c->solvers.begin(), c->solvers.end(), part.solver) == c->solvers.end()) {
            part.notes.push_back(fmt::format("No granlub {} results in {}: run `granlub {}` on {} first.", part.solver,
                                            c->root.string(), part.solver,
                                            c == &col ? ring.dir.string() : slice.dir.string()));
            return part;
        }
    part.table.header = {"point", "quantity", "whole ring", "slice", "ring − slice", "z"};
    for (const OperatingPoint* p : col.points) {
        const OperatingPoint* q = nullptr;
        for (const OperatingPoint* s : scol.points)
            if (s->id == p->id) q = s;
        if (!q) {
            part.notes.push_back(fmt::format("point {}: {} has no point of that id", p->id, slice.name));
            continue;
        }
        if (q->speed != p->speed || q->control != p->control || q->normal_stress != p->normal_stress ||
            (p->control == Control::Fill && q->solid_fraction != p->solid_fraction)) {
            part.notes.push_back(fmt::format("point {}: {}'s point of that id asks another question (speed, control, "
                                            "load or fill differ)",
                                            p->id, slice.name));
            continue;
        }
        const Run& r = col.run(part.solver, p->id);
        const Run& s = scol.run(part.solver, q->id);
        if (!r.usable() || !s.usable()) {
            part.notes.push_back(fmt::format("point {}: granlub {}'s result is {} for the ring, {} for the slice ({})",
                                            p->id, part.solver, r.state_name(), s.state_name(), slice.dir.string()));
            continue;
        }
        const bool both = r.steady() && s.steady();
        for (const auto& k : kQuantities) {
            auto scaled = [&](const Run& run, bool err) {
                const auto v = err ? run.scalar_stderr(k.key) : run.scalar(k.key);
                return v ? std::optional(*v * k.scale) : std::nullopt;
            };
            if (!r.scalar(k.key) && !s.scalar(k.key)) continue;  // neither run has it (older results)
            add_row(part.table, p->id, k.label, scaled(r, false), scaled(r, true), scaled(s, false), scaled(s, true),
                    both);
        }
        std::string why_r, why_s;
        const auto wr = width_profile(r, why_r), ws = width_profile(s, why_s);
        if (wr && ws) {
            const auto [a, sa] = outer_over_inner(*wr);
            const auto [b, sb] = outer_over_inner(*ws);
            add_row(part.table, p->id, "ν outer half / ν inner half", a, sa, b, sb, both);
        }
        for (const auto* why : {&why_r, &why_s})
            if (!why->empty()) part.notes.push_back(fmt::format("point {}: {}", p->id, *why));
        add_figures(part, *p, r, s, wr, ws);
    }
    return part;
}

std::optional<Case> slice_case(const Case& ring) {
    const std::string slice_case = ring.section("report").string("slice_case");
    if (slice_case.empty()) return std::nullopt;
    try {
        return load_case(slice_case_path(ring), *ring.schema);  // as ring_slice_part() above
    } catch (const Error&) {
        return std::nullopt;  // ring_slice_part says why in the report
    }
}

}  // namespace granlub::postproc
