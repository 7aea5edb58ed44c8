#include "tables/twin_targets.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "formats/format.h"
#include "granlub/run/solver_info.h"
#include "statistics/metrics.h"
#include "statistics/stats.h"
#include "tables/twin_thresholds.h"

namespace granlub::postproc {

TwinSolvers twin_solvers(const Case& c, const Collection& col) {
    TwinSolvers t;
    if (!c.schema) return t;
    for (const SolverInfo* s : declared_solvers(*c.schema)) {
        const bool collected = std::find(col.solvers.begin(), col.solvers.end(), s->name) != col.solvers.end();
        if (!collected || !col.any_usable(s->name)) continue;
        if (s->kind == SolverKind::Continuum && t.model.empty()) t.model = s->name;
        if (s->kind == SolverKind::Particles && t.particles.empty()) t.particles = s->name;
    }
    return t;
}

double twin_gap(const Case& c, const Run& r, bool* fixed) {
    const auto g = r.scalar("gap");
    if (fixed) *fixed = !g;
    return g.value_or(c.cell.gap);
}

namespace {

// A rounding slack on each band, so that a value on its edge (the constant μ at an interval's end) is in.
bool within(double d, double band) { return std::abs(d) <= band * (1 + 1e-9); }

struct WallMu {
    const char* target;
    const char* wall;
    const char* tau;
    const char* sigma;
};
constexpr WallMu kWalls[] = {{"μ floor", "floor", "shear_stress_bottom", "normal_stress_bottom"},
                             {"μ top", "top", "shear_stress_top", "normal_stress_top"}};

// μ = |τ|/σ_yy on a wall and its standard error from τ's and σ's (independent, relative errors added in
// quadrature; nothing when neither has one).
struct Mu {
    double v = 0;
    std::optional<double> se;
};
std::optional<Mu> wall_mu(const Run& r, const WallMu& w) {
    const auto tau = r.scalar(w.tau), sigma = r.scalar(w.sigma);
    if (!tau || !sigma || *sigma <= 0) return std::nullopt;
    Mu m{std::abs(*tau) / *sigma, std::nullopt};
    const auto st = r.scalar_stderr(w.tau), ss = r.scalar_stderr(w.sigma);
    if (st || ss)
        m.se = m.v * std::hypot(st && *tau != 0 ? *st / *tau : 0.0, ss ? *ss / *sigma : 0.0);
    return m;
}

std::string pct(double rel) { return fmt::format("{:+.1f} %", 100 * rel); }

TargetCheck check(std::string target, std::string rule, std::optional<double> dem = std::nullopt,
                  std::optional<double> se = std::nullopt) {
    TargetCheck t;
    t.target = std::move(target), t.rule = std::move(rule), t.dem = dem, t.dem_se = se;
    return t;
}

// Relative targets (μ, its rise): |model − dem| ≤ band |dem|.
TargetCheck relative_check(std::string target, std::string rule, double band, double dem, std::optional<double> se,
                           double model) {
    TargetCheck t = check(std::move(target), std::move(rule), dem, se);
    t.model = model;
    t.judged = true;
    const double d = model - dem;
    t.difference = dem != 0 ? d / std::abs(dem) : d;
    t.met = dem != 0 ? within(*t.difference, band) : d == 0;
    t.within_dem_error = !t.met && se && std::abs(d) - band * std::abs(dem) <= kTwinDemErrorZ * *se;
    return t;
}

// Absolute targets (slip, gap): |model − dem| ≤ band.
TargetCheck absolute_check(std::string target, std::string rule, double band, double dem, std::optional<double> se,
                           double model) {
    TargetCheck t = check(std::move(target), std::move(rule), dem, se);
    t.model = model, t.difference = model - dem;
    t.judged = true;
    t.met = within(*t.difference, band);
    t.within_dem_error = !t.met && se && std::abs(*t.difference) - band <= kTwinDemErrorZ * *se;
    return t;
}

TargetCheck unjudged(std::string target, std::string rule, std::string why) {
    TargetCheck t = check(std::move(target), std::move(rule));
    t.note = std::move(why);
    return t;
}

const std::string kMuRule = fmt::format("within {:g} % of the DEM's", 100 * kTwinMuRelative);
const std::string kSlipRule = fmt::format("within {:g} U", kTwinSlipOverU);
const std::string kNuRule =
    fmt::format("RMS ≤ {:g} over {:g} ≤ y/H ≤ {:g}, the DEM's ν over {:g} grain diameter", kTwinNuCoreRms, kTwinCoreLo,
                kTwinCoreHi, kTwinNuGrainWindow);
const std::string kGapRule = fmt::format("within {:g} mm", kTwinGap * 1e3);
const std::string kTRule = fmt::format("ratio within [1/{0:g}, {0:g}] where the DEM resolves T", kTwinTemperatureFactor);
const std::string kRiseRule = fmt::format("within {:g} % of the DEM's rise", 100 * kTwinRiseRelative);

// The DEM's ν at station i coarse-grained over one grain diameter: the mean of its stations within
// half a diameter (half_width, in y/H) of y_i. A continuum's ν is a field on scales above a grain
// (coarse-graining, Goldhirsch, Granular Matter 12 (2010) 239); the DEM's stations (about a third of a
// diameter) also resolve the layers the walls template, which no kinetic theory describes
// [ASSUMPTION, ours: a box one diameter wide; the per-station RMS is shown beside it].
double coarse_grained(const std::vector<double>& y, const std::vector<double>& v, std::size_t i, double half_width) {
    double sum = 0;
    int n = 0;
    for (std::size_t j = 0; j < y.size(); ++j)
        if (std::abs(y[j] - y[i]) <= half_width * (1 + 1e-9)) sum += v[j], ++n;
    return sum / n;
}

// ν(y) over the core: RMS of the model's solid fraction, interpolated onto the DEM's core stations,
// minus the DEM's coarse-grained over one diameter (kTwinNuGrainWindow); `dem` is the DEM's core mean,
// `model` the model's there, dem_se the DEM's noise RMS. The note gives the per-station RMS too.
TargetCheck nu_core(const Case& c, const Run& dem, const Run& model, double dem_gap) {
    const auto yd = dem.y(), ym = model.y();
    const auto& nd = dem.profile->column("solid_fraction");
    const auto& nm = model.profile->column("solid_fraction");
    const std::string se_col = "solid_fraction_stderr";
    const bool has_se = dem.profile->has(se_col);
    const double half = kTwinNuGrainWindow * c.grains.diameter / dem_gap / 2;
    double sum2 = 0, raw2 = 0, noise2 = 0, mean_d = 0, mean_m = 0;
    int n = 0;
    for (std::size_t i = 0; i < yd.size(); ++i) {
        if (yd[i] < kTwinCoreLo || yd[i] > kTwinCoreHi || yd[i] < ym.front() || yd[i] > ym.back()) continue;
        const double m = interpolate(ym, nm, yd[i]), g = coarse_grained(yd, nd, i, half);
        sum2 += (m - g) * (m - g);
        raw2 += (m - nd[i]) * (m - nd[i]);
        if (has_se) noise2 += std::pow(dem.profile->column(se_col)[i], 2);
        mean_d += nd[i], mean_m += m, ++n;
    }
    if (n == 0) return unjudged("ν(y) core", kNuRule, "no DEM station in the core");
    TargetCheck t = check("ν(y) core", kNuRule, mean_d / n);
    t.model = mean_m / n, t.difference = std::sqrt(sum2 / n);
    if (has_se) t.dem_se = std::sqrt(noise2 / n);
    t.judged = true;
    t.met = *t.difference <= kTwinNuCoreRms * (1 + 1e-9);
    t.within_dem_error = !t.met && t.dem_se && *t.difference - kTwinNuCoreRms <= kTwinDemErrorZ * *t.dem_se;
    t.note = fmt::format("core means; {} DEM stations, each the mean over one grain diameter; per station (the "
                         "layers resolved) RMS {:.3g}",
                         n, std::sqrt(raw2 / n));
    return t;
}

// T(y): at each DEM station that resolves T (kTwinTemperatureMaxRelativeError), the model's T over the
// DEM's; the worst ratio (farthest from 1 in log) is the difference, the DEM's and the model's T there
// the values.
TargetCheck temperature(const Run& dem, const Run& model) {
    const std::string col = "temperature_over_U2", se_col = "temperature_over_U2_stderr";
    if (!dem.profile->has(col) || !dem.profile->has(se_col) || !model.profile->has(col))
        return unjudged("T(y)", kTRule, "no T with standard errors in the DEM's profile");
    const auto yd = dem.y(), ym = model.y();
    const auto &td = dem.profile->column(col), &sd = dem.profile->column(se_col), &tm = model.profile->column(col);
    TargetCheck t = check("T(y)", kTRule);
    int n = 0;
    double worst = -1;
    bool all_in = true, all_in_error = true;
    for (std::size_t i = 0; i < yd.size(); ++i) {
        if (!(std::isfinite(td[i]) && td[i] > 0 && std::isfinite(sd[i]) && sd[i] < kTwinTemperatureMaxRelativeError * td[i]))
            continue;
        if (yd[i] < ym.front() || yd[i] > ym.back()) continue;
        ++n;
        const double m = interpolate(ym, tm, yd[i]);
        const double ratio = m / td[i];
        const double lo = 1 / kTwinTemperatureFactor, hi = kTwinTemperatureFactor;
        const bool in = ratio >= lo * (1 - 1e-9) && ratio <= hi * (1 + 1e-9);
        all_in = all_in && in;
        // within the DEM's error: some T_DEM within kTwinDemErrorZ standard errors gives a ratio in the band
        const double r_lo = m / (td[i] + kTwinDemErrorZ * sd[i]);
        const double r_hi = td[i] > kTwinDemErrorZ * sd[i] ? m / (td[i] - kTwinDemErrorZ * sd[i])
                                                          : std::numeric_limits<double>::infinity();
        all_in_error = all_in_error && r_hi >= lo && r_lo <= hi;
        const double off = ratio > 0 ? std::abs(std::log(ratio)) : std::numeric_limits<double>::infinity();
        if (off > worst) {
            worst = off;
            t.dem = td[i], t.dem_se = sd[i], t.model = m, t.difference = ratio;
            t.note = fmt::format("worst at y/H = {}", num(yd[i], 3));
        }
    }
    if (n == 0)
        return unjudged("T(y)", kTRule,
                        fmt::format("the DEM resolves T at no station (standard error < {:g} % of T)",
                                    100 * kTwinTemperatureMaxRelativeError));
    t.judged = true;
    t.met = all_in;
    t.within_dem_error = !all_in && all_in_error;
    t.note += fmt::format(", {} resolved station{}", n, n == 1 ? "" : "s");
    return t;
}

// The continuum's checks at a judged point, in the order of every point's table.
std::vector<TargetCheck> continuum_checks(const Case& c, const Run& dem, const Run& model) {
    std::vector<TargetCheck> out;
    const bool ok = model.steady();
    const std::string why = fmt::format("no steady continuum result ({})", model.state_name());
    // A judged target the continuum has no value for: missed, and why.
    auto missed = [&](std::string target, const std::string& rule, std::optional<double> d, std::optional<double> se,
                      std::string note) {
        TargetCheck t = check(std::move(target), rule, d, se);
        t.judged = true, t.note = std::move(note);
        return t;
    };
    for (const WallMu& w : kWalls) {
        const auto d = wall_mu(dem, w), m = ok ? wall_mu(model, w) : std::nullopt;
        if (!d) out.push_back(unjudged(w.target, kMuRule, "the DEM has no stresses on this wall"));
        else if (!m) out.push_back(missed(w.target, kMuRule, d->v, d->se, ok ? "no stresses in the continuum's result" : why));
        else out.push_back(relative_check(w.target, kMuRule, kTwinMuRelative, d->v, d->se, m->v));
    }
    for (const char* q : {"slip_bottom_over_U", "slip_top_over_U"}) {
        const std::string target = q == std::string("slip_bottom_over_U") ? "slip floor / U" : "slip top / U";
        const auto d = dem.scalar(q), m = ok ? model.scalar(q) : std::nullopt;
        if (!d) out.push_back(unjudged(target, kSlipRule, "the DEM has no slip here"));
        else if (!m) out.push_back(missed(target, kSlipRule, d, dem.scalar_stderr(q), ok ? "no slip in the continuum's result" : why));
        else out.push_back(absolute_check(target, kSlipRule, kTwinSlipOverU, *d, dem.scalar_stderr(q), *m));
    }
    bool fixed = false;
    const double gd = twin_gap(c, dem), gm = ok ? twin_gap(c, model, &fixed) : 0;
    out.push_back(ok ? nu_core(c, dem, model, gd) : missed("ν(y) core", kNuRule, std::nullopt, std::nullopt, why));
    if (ok) {
        out.push_back(absolute_check("gap", kGapRule, kTwinGap, gd, dem.scalar_stderr("gap"), gm));
        if (fixed) out.back().note = "the case's gap: the continuum keeps it fixed";
    } else {
        out.push_back(missed("gap", kGapRule, gd, dem.scalar_stderr("gap"), why));
    }
    out.push_back(ok ? temperature(dem, model) : missed("T(y)", kTRule, std::nullopt, std::nullopt, why));
    return out;
}

// The constant μ's checks: μ at each wall; the rest it does not model (not judged).
std::vector<TargetCheck> constant_checks(const Run& dem, double floor, double top) {
    std::vector<TargetCheck> out;
    for (const WallMu& w : kWalls) {
        const auto d = wall_mu(dem, w);
        const double mu0 = &w == &kWalls[0] ? floor : top;
        out.push_back(d ? relative_check(w.target, kMuRule, kTwinMuRelative, d->v, d->se, mu0)
                        : unjudged(w.target, kMuRule, "the DEM has no stresses on this wall"));
    }
    for (const auto& [target, rule] : {std::pair{"slip floor / U", kSlipRule}, std::pair{"slip top / U", kSlipRule},
                                       std::pair{"ν(y) core", kNuRule}, std::pair{"gap", kGapRule},
                                       std::pair{"T(y)", kTRule}})
        out.push_back(unjudged(target, rule, "a constant μ has none"));
    return out;
}

bool all_met(const std::vector<TargetCheck>& checks) {
    bool any = false;
    for (const auto& t : checks) {
        if (!t.judged) continue;
        any = true;
        if (!t.met) return false;
    }
    return any;
}

// The number of distinct μ0 a wall's band set can take is small: the SSE-best constant, and for each
// point's band its left edge moved towards the SSE-best within the bands that contain that edge.
std::vector<double> candidates(const std::vector<double>& mu) {
    double a = 0, b = 0;
    for (double m : mu) a += 1 / m, b += 1 / (m * m);
    const double best = a / b;  // argmin Σ ((μ0 − μ_i)/μ_i)²
    std::vector<double> out{best};
    for (double left : mu) {
        const double lo = (1 - kTwinMuRelative) * left;
        double hi = std::numeric_limits<double>::infinity();
        for (double m : mu)
            if (within(lo - m, kTwinMuRelative * m)) hi = std::min(hi, (1 + kTwinMuRelative) * m);
        out.push_back(std::clamp(best, lo, std::max(lo, hi)));
    }
    return out;
}

double sse(const std::vector<double>& mu, double mu0) {
    double s = 0;
    for (double m : mu) s += std::pow((mu0 - m) / m, 2);
    return s;
}

std::string group_label(const PointGroup& g) {
    if (!g.points.empty() && std::all_of(g.points.begin(), g.points.end(),
                                         [](const OperatingPoint* p) { return p->control == Control::Load; }))
        return fmt::format("P = {} Pa", num(g.points.front()->normal_stress));
    return g.label.empty() ? "every point" : g.label;
}

// The closures of the continuum as run, from its summary's run block (continuum case_setup.cpp record_run).
std::string closures_text(const Collection& col, const std::string& model) {
    for (const OperatingPoint* p : col.points) {
        const Run& r = col.run(model, p->id);
        if (!r.usable() || !r.summary->run.is_object()) continue;
        const auto& run = r.summary->run;
        std::vector<std::string> parts;
        for (const auto& [key, label] : {std::pair{"closures", "closures"}, std::pair{"g0", "g0"},
                                         std::pair{"correlation_length", "correlation length"},
                                         std::pair{"contact_stress", "contact stress"},
                                         std::pair{"wall_model", "wall model"},
                                         std::pair{"wall_friction_restitution", "wall friction restitution"},
                                         std::pair{"wall_roughness", "wall roughness"}}) {
            if (!run.contains(key)) continue;
            const auto& v = run[key];
            if (v.is_string()) parts.push_back(fmt::format("{} = {}", label, v.get<std::string>()));
            else if (v.is_object())  // a record: named by its model, or (wall_roughness) by where R came from
                for (const char* name : {"model", "source"})
                    if (v.contains(name) && v[name].is_string()) {
                        parts.push_back(fmt::format("{} = {}", label, v[name].get<std::string>()));
                        break;
                    }
        }
        if (!parts.empty()) return list_text(parts);
    }
    return "its closures not recorded in its summary";
}

std::string required_text(int listed) {
    return listed <= kTwinAllPointsUpTo ? "all judged points"
                                        : fmt::format("≥ {:g} % of the judged points", 100 * kTwinPointsFraction);
}

void count(ModelCount& m, const TwinTargets& t, bool TwinPoint::*met, TargetCheck TwinRise::*rise) {
    m.listed = static_cast<int>(t.points.size());
    for (const auto& p : t.points) {
        if (!p.judged) continue;
        ++m.judged;
        m.met += p.*met ? 1 : 0;
    }
    m.required = m.listed <= kTwinAllPointsUpTo ? m.judged
                                                : static_cast<int>(std::ceil(kTwinPointsFraction * m.judged - 1e-9));
    for (const auto& r : t.rises) {
        if (!(r.*rise).judged) continue;
        ++m.rises;
        m.rises_met += (r.*rise).met ? 1 : 0;
    }
    m.overall = m.judged > 0 && m.met >= m.required && m.rises_met == m.rises;
}

Cell verdict_cell(const TargetCheck& t) {
    if (!t.judged) return {"not judged", "missing"};
    if (t.met) return {"met", "ok"};
    return {t.within_dem_error ? fmt::format("missed (by less than {:g} DEM standard errors beyond the band)",
                                             kTwinDemErrorZ)
                               : "missed",
            "failed"};
}

bool is_gap(const TargetCheck& t) { return t.target == "gap"; }
bool is_relative(const TargetCheck& t) { return t.target.starts_with("μ"); }
bool is_ratio(const TargetCheck& t) { return t.target == "T(y)"; }

std::string value_text(const TargetCheck& t, std::optional<double> v, std::optional<double> se) {
    if (!v) return "—";
    if (is_gap(t)) return value_pm(*v * 1e3, se ? std::optional(*se * 1e3) : std::nullopt, 4) + " mm";
    return value_pm(v, se, 3);
}

std::string difference_text(const TargetCheck& t) {
    if (!t.difference) return "—";
    if (is_relative(t)) return pct(*t.difference);
    if (is_gap(t)) return fmt::format("{:+.3f} mm", *t.difference * 1e3);
    if (is_ratio(t)) return fmt::format("ratio {}", num(*t.difference, 3));
    if (t.target.starts_with("ν")) return fmt::format("RMS {}", num(*t.difference, 2));
    return fmt::format("{:+.3f}", *t.difference);
}

std::string with_note(std::string s, const std::string& note) { return note.empty() ? s : s + " (" + note + ")"; }

}  // namespace

bool twin_applies(const Case& c, const Collection& col) {
    const TwinSolvers s = twin_solvers(c, col);
    return c.cell.width <= 0 && !c.cell.ring() && !s.model.empty() && !s.particles.empty();
}

std::pair<double, double> twin_constant_mu(const std::vector<double>& floor, const std::vector<double>& top) {
    if (floor.empty() || top.empty()) return {0, 0};
    const auto cf = candidates(floor), ct = candidates(top);
    std::pair<double, double> best{cf.front(), ct.front()};
    int best_n = -1;
    double best_sse = 0;
    for (double f : cf)
        for (double t : ct) {
            int n = 0;
            for (std::size_t i = 0; i < floor.size() && i < top.size(); ++i)
                n += within(f - floor[i], kTwinMuRelative * floor[i]) && within(t - top[i], kTwinMuRelative * top[i]);
            const double s = sse(floor, f) + sse(top, t);
            if (n > best_n || (n == best_n && s < best_sse)) best = {f, t}, best_n = n, best_sse = s;
        }
    return best;
}

TwinTargets twin_targets(const Case& c, const Collection& col) {
    TwinTargets t;
    t.solvers = twin_solvers(c, col);
    const std::string &particles = t.solvers.particles, &model = t.solvers.model;
    t.closures = closures_text(col, model);
    t.equal_grains = c.grains.size_spread == 0;
    // The constant μ over the judged points (the DEM steady, μ on both walls).
    std::vector<double> floor, top;
    for (const OperatingPoint* p : col.points) {
        const Run& d = col.run(particles, p->id);
        if (!d.steady()) continue;
        const auto f = wall_mu(d, kWalls[0]), u = wall_mu(d, kWalls[1]);
        if (f && u) floor.push_back(f->v), top.push_back(u->v);
    }
    std::tie(t.constant_floor, t.constant_top) = twin_constant_mu(floor, top);
    for (const OperatingPoint* p : col.points) {
        TwinPoint tp;
        tp.point = p;
        const Run& d = col.run(particles, p->id);
        tp.judged = d.steady();
        tp.dem_state = d.state_name();
        tp.dt_checked = d.usable() && d.summary->run.is_object() && d.summary->run.contains("dt_refinement");
        if (tp.judged) {
            tp.continuum = continuum_checks(c, d, col.run(model, p->id));
            tp.constant = constant_checks(d, t.constant_floor, t.constant_top);
            tp.continuum_met = all_met(tp.continuum);
            tp.constant_met = all_met(tp.constant);
        }
        t.points.push_back(std::move(tp));
    }
    // μ's rise per load and wall, between the slowest and fastest judged DEM points.
    for (const PointGroup& g : speed_groups(col.points)) {
        std::vector<const OperatingPoint*> judged;
        for (const OperatingPoint* p : g.points)
            if (col.run(particles, p->id).steady()) judged.push_back(p);
        if (judged.size() < 2) continue;
        const auto [slow, fast] = std::minmax_element(judged.begin(), judged.end(), [](auto* a, auto* b) {
            return a->speed < b->speed;
        });
        if ((*slow)->speed == (*fast)->speed) continue;
        const Run &ds = col.run(particles, (*slow)->id), &df = col.run(particles, (*fast)->id);
        const Run &ms = col.run(model, (*slow)->id), &mf = col.run(model, (*fast)->id);
        for (const WallMu& w : kWalls) {
            const auto a = wall_mu(ds, w), b = wall_mu(df, w);
            if (!a || !b) continue;
            TwinRise r;
            r.group = group_label(g), r.wall = w.wall, r.slow = (*slow)->speed, r.fast = (*fast)->speed;
            const std::string target = fmt::format("μ's rise, {}", w.wall);
            std::optional<double> se;
            if (a->se || b->se) se = std::hypot(a->se.value_or(0), b->se.value_or(0));
            const double rise = b->v - a->v;
            const auto ma = ms.steady() ? wall_mu(ms, w) : std::nullopt, mb = mf.steady() ? wall_mu(mf, w) : std::nullopt;
            if (ma && mb) {
                r.continuum = relative_check(target, kRiseRule, kTwinRiseRelative, rise, se, mb->v - ma->v);
            } else {
                r.continuum = check(target, kRiseRule, rise, se);
                r.continuum.judged = true, r.continuum.note = "no steady continuum result at both speeds";
            }
            r.constant = relative_check(target, kRiseRule, kTwinRiseRelative, rise, se, 0);
            t.rises.push_back(std::move(r));
        }
    }
    count(t.continuum, t, &TwinPoint::continuum_met, &TwinRise::continuum);
    count(t.constant, t, &TwinPoint::constant_met, &TwinRise::constant);
    return t;
}

Table twin_count_table(const TwinTargets& t) {
    Table tab;
    tab.header = {"model", "points meeting every target", "needed", "μ's rise met", "overall"};
    std::vector<std::string> not_judged;
    for (const auto& p : t.points)
        if (!p.judged) not_judged.push_back(fmt::format("{} ({})", p.point->id, p.dem_state));
    const std::string denominator =
        not_judged.empty() ? ""
                           : fmt::format("; {} of {} points not judged (no steady DEM result): {}", not_judged.size(),
                                         t.points.size(), list_text(not_judged));
    auto row = [&](const std::string& model, const ModelCount& m) {
        tab.rows.push_back({{model, ""},
                            {fmt::format("{} of {} judged{}", m.met, m.judged, denominator), ""},
                            {fmt::format("{} ({})", m.required, required_text(m.listed)), ""},
                            {m.rises == 0 ? "— (no load with two judged speeds)"
                                          : fmt::format("{} of {}", m.rises_met, m.rises),
                             ""},
                            {m.overall ? "met" : "missed", m.overall ? "ok" : "failed"}});
    };
    row(fmt::format("continuum as run ({})", t.closures), t.continuum);
    row(fmt::format("constant μ (floor {}, top {}): μ targets only", num(t.constant_floor, 3), num(t.constant_top, 3)),
        t.constant);
    return tab;
}

Table twin_rise_table(const TwinTargets& t) {
    Table tab;
    tab.header = {"load", "wall", "speeds (m/s)", "DEM's rise", "continuum's rise", "difference", "verdict",
                  "constant μ's rise", "difference", "verdict"};
    for (const auto& r : t.rises)
        tab.rows.push_back({{r.group, ""},
                            {r.wall, ""},
                            {fmt::format("{} → {}", num(r.slow), num(r.fast)), ""},
                            {value_text(r.continuum, r.continuum.dem, r.continuum.dem_se), ""},
                            {with_note(value_text(r.continuum, r.continuum.model, std::nullopt), r.continuum.note), ""},
                            {difference_text(r.continuum), ""},
                            verdict_cell(r.continuum),
                            {"0", ""},
                            {difference_text(r.constant), ""},
                            verdict_cell(r.constant)});
    return tab;
}

Table twin_by_target_table(const TwinTargets& t) {
    Table tab;
    tab.header = {"target", "rule", "continuum: met at", "constant μ: met at"};
    const TwinPoint* first = nullptr;
    for (const auto& p : t.points)
        if (p.judged && !first) first = &p;
    if (!first) return tab;
    auto tally = [&](std::size_t i, std::vector<TargetCheck> TwinPoint::*model) {
        int met = 0, judged = 0;
        for (const auto& p : t.points)
            if (p.judged && ((p.*model)[i]).judged) ++judged, met += ((p.*model)[i]).met;
        if (judged == 0) return Cell{"— (not judged)", ""};
        return Cell{fmt::format("{} of {}", met, judged), met == judged ? "ok" : "failed"};
    };
    for (std::size_t i = 0; i < first->continuum.size(); ++i)
        tab.rows.push_back({{first->continuum[i].target, ""},
                            {first->continuum[i].rule, ""},
                            tally(i, &TwinPoint::continuum),
                            tally(i, &TwinPoint::constant)});
    return tab;
}

Table twin_point_table(const TwinPoint& p) {
    Table tab;
    tab.header = {"target", "rule", "DEM (± se)", "continuum", "difference", "verdict", "constant μ", "difference",
                  "verdict"};
    for (std::size_t i = 0; i < p.continuum.size(); ++i) {
        const TargetCheck &m = p.continuum[i], &k = p.constant[i];
        tab.rows.push_back({{m.target, ""},
                            {m.rule, ""},
                            {value_text(m, m.dem, m.dem_se), ""},
                            {with_note(value_text(m, m.model, std::nullopt), m.note), ""},
                            {difference_text(m), ""},
                            verdict_cell(m),
                            {k.model ? num(*k.model, 3) : "— (" + k.note + ")", ""},
                            {difference_text(k), ""},
                            verdict_cell(k)});
    }
    const auto met = [](bool b) { return Cell{b ? "every judged target met" : "missed", b ? "ok" : "failed"}; };
    tab.rows.push_back({{"the point", ""}, {"", ""}, {"", ""}, {"", ""}, {"", ""}, met(p.continuum_met), {"", ""},
                        {"", ""}, met(p.constant_met)});
    return tab;
}

}  // namespace granlub::postproc
