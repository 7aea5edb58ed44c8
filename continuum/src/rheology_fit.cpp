// The closures' constants fitted on a bulk-rheology table (rheology_fit.h).
#include "granlub/continuum/rheology_fit.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>

#include <fmt/format.h>
#include <gsl/gsl_blas.h>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_multifit_nlinear.h>

#include "granlub/continuum/command.h"
#include "granlub/error.h"
#include "gsl_quiet.h"
#include "wall_fit.h"

namespace granlub::continuum {

namespace {

// The constants a fit may free and the branch each belongs to ("" = any case).
struct Fittable {
    const char* key;
    const char* branch;  // the [continuum] choice that must be made for the key to mean anything
};
constexpr Fittable kFittable[] = {
    {"correlation_constant", "correlation_length = \"jenkins_berzi\""},
    {"contact_coefficient", "contact_stress = \"johnson_jackson\""},
    {"contact_onset_fraction", "contact_stress = \"johnson_jackson\""},
    {"contact_exponent_onset", "contact_stress = \"johnson_jackson\""},
    {"contact_exponent_jamming", "contact_stress = \"johnson_jackson\""},
    {"contact_friction", "contact_stress = \"johnson_jackson\""},
    {"max_solid_fraction", ""},
    {"slip_dissipation", ""},  // wall keys (wall_fit.h): fitted on the table's walls' columns
    {"r5", ""},
};

bool in_branch(const Settings& s, const std::string& key) {
    if (key == "correlation_constant") return s.closures->params().correlation_length == CorrelationLength::JenkinsBerzi;
    if (key.starts_with("contact_")) return s.contact.active();
    return true;
}

// The constants of one trial: the case's closures with the free ones replaced.
struct FitTrial {
    ClosureParams params;
    double numax = 0;
    ContactStress contact;  // coefficient Fr in Pa, as Settings holds it
    double slip_dissipation = 0;  // f_t
    std::optional<double> r5;     // R5 at both walls, when free (else each wall's as the case gives it)
};

FitTrial case_trial(const Settings& s) {
    return {s.closures->params(), s.closures->numax(), s.contact, s.slip_dissipation, std::nullopt};
}

double& constant(FitTrial& t, const std::string& key) {
    if (key == "correlation_constant") return t.params.correlation_constant;
    if (key == "contact_coefficient") return t.contact.coefficient;
    if (key == "contact_onset_fraction") return t.contact.onset;
    if (key == "contact_exponent_onset") return t.contact.n;
    if (key == "contact_exponent_jamming") return t.contact.m;
    if (key == "contact_friction") return t.contact.friction;
    if (key == "max_solid_fraction") return t.numax;
    if (key == "slip_dissipation") return t.slip_dissipation;
    if (key == "r5") return t.r5 ? *t.r5 : t.r5.emplace(0.0);  // engaged: free
    throw Error(fmt::format("internal: no fittable constant '{}'", key));
}

// The closures of a trial at a row's pressure P (Pa): the contact stress enters as pi_c = p_c/P, as problem_for
// gives it each point's load (§2.9); its nu_c is g0's nu_max. The row's P is the core's measured pressure
// (pressure_Pa), against which its I is defined [ASSUMPTION: the load, load_Pa, differs from it by the walls'
// normal-stress imbalance, a percent or less in the steady rows].
Closures trial_closures(const Settings& s, const FitTrial& t) {
    const std::shared_ptr<const Closures>& base = s.closures;
    std::shared_ptr<const RadialDistribution> g0 =
        t.numax == base->numax() ? std::shared_ptr<const RadialDistribution>(base, &base->g0())
                                 : std::shared_ptr<const RadialDistribution>(make_g0(s.g0_name, t.numax));
    return Closures(t.params, std::move(g0), std::shared_ptr<const ClosureFamily>(base, &base->family()));
}

Closures closures_at(const Settings& s, const FitTrial& t, double P) {
    const Closures c = trial_closures(s, t);
    if (!t.contact.active()) return c;
    ContactStress cs = t.contact;
    cs.jamming = t.numax;
    cs.coefficient /= P;
    return c.with_contact(cs);
}

// The case's Settings with a trial's constants, as the 1-D solve takes them (problem_for scales the contact stress
// by each point's load, so Fr stays in Pa here).
Settings trial_settings(const Settings& s, const FitTrial& t) {
    Settings x = s;
    x.closures = std::make_shared<Closures>(trial_closures(s, t));
    x.contact = t.contact;
    if (x.contact.active()) x.contact.jamming = t.numax;
    x.slip_dissipation = t.slip_dissipation;
    x.r5_fit = t.r5;
    return x;
}

// Each free constant is fitted as an unbounded theta mapped into the key's declared range (section.cpp): a
// logistic map onto [lo, hi], x = lo + exp(theta) when hi is infinite; contact_onset_fraction's upper end is
// the trial's nu_c. So every trial is a closure set the case could hold [ASSUMPTION: our choice; the standard
// errors are carried back by the map's slope, dx = x'(theta) dtheta, first order in dtheta].
struct ConstantMap {
    std::string key;
    double lo = 0, hi = 0;
    double x(double theta, double top) const {
        const double h = std::min(hi, top);
        if (std::isinf(h)) return lo + std::exp(theta);
        return lo + (h - lo) / (1 + std::exp(-theta));
    }
    double slope(double theta, double top) const {
        const double h = std::min(hi, top);
        if (std::isinf(h)) return std::exp(theta);
        const double q = 1 / (1 + std::exp(-theta));
        return (h - lo) * q * (1 - q);
    }
    double theta(double value, double top) const {
        const double h = std::min(hi, top);
        if (std::isinf(h)) return std::log(value - lo);
        return std::log((value - lo) / (h - value));
    }
};

// A residual where a trial's closures cannot reach a row's I: large, so the trust region rejects the step
// [ASSUMPTION: a numerical choice; a fit never ends there, it starts where every row is reached].
constexpr double kUnreachable = 1e3;

struct FitProblem {
    const Settings* s = nullptr;
    const std::vector<BulkRow>* rows = nullptr;
    std::vector<ConstantMap> maps;
    bool temperature = false;
    bool core = true;    // the core's mu, nu (T) are residuals: a closure constant is free
    bool walls = false;  // the walls' slips and T are residuals: a wall key is free
    const Case* bulk = nullptr;                  // with walls: the bulk case (FitOptions::bulk)
    std::vector<const OperatingPoint*> points;   // with walls: each row's point of it
    std::exception_ptr failure;  // an unexpected error inside GSL's callback, rethrown after

    std::size_t core_per_row() const { return core ? (temperature ? 3 : 2) : 0; }
    std::size_t per_row() const { return core_per_row() + (walls ? detail::kWallResiduals : 0); }
    // The trial of theta; nu_c (max_solid_fraction) first, as the onset's range ends there.
    FitTrial trial(const double* theta) const {
        FitTrial t = case_trial(*s);
        for (std::size_t k = 0; k < maps.size(); ++k)
            if (maps[k].key == "max_solid_fraction") t.numax = maps[k].x(theta[k], INFINITY);
        for (std::size_t k = 0; k < maps.size(); ++k)
            if (maps[k].key != "max_solid_fraction") constant(t, maps[k].key) = maps[k].x(theta[k], top(maps[k], t));
        return t;
    }
    static double top(const ConstantMap& m, const FitTrial& t) {
        return m.key == "contact_onset_fraction" ? t.numax : std::numeric_limits<double>::infinity();
    }
    // The homogeneous shear of one row; throws SolverError when the closures do not reach its I.
    SimpleShear model(const FitTrial& t, const BulkRow& r) const {
        return simple_shear_at_inertial(closures_at(*s, t, r.pressure.value), r.inertial.value);
    }
    // The bulk case's 1-D solve at row i's point; throws SolverError when it does not solve.
    WallLayers wall_model(const FitTrial& t, std::size_t i) const {
        return detail::wall_model(*bulk, trial_settings(*s, t), *points[i]);
    }
};

// (model - table)/error, the weighted least-squares residuals.
void fit_residuals(const SimpleShear& m, const BulkRow& r, bool temperature, double* f) {
    f[0] = (m.stress_ratio - r.friction.value) / r.friction.error;
    f[1] = (m.nu - r.solid_fraction.value) / r.solid_fraction.error;
    if (temperature) f[2] = (m.temperature - r.temperature_scaled.value) / r.temperature_scaled.error;
}

// GSL evaluates into strided views (its finite-difference Jacobian writes f into a column of J): element by element.
int gsl_residuals(const gsl_vector* theta, void* params, gsl_vector* f) {
    auto& p = *static_cast<FitProblem*>(params);
    try {
        std::vector<double> th(theta->size);
        for (std::size_t k = 0; k < th.size(); ++k) th[k] = gsl_vector_get(theta, k);
        const FitTrial t = p.trial(th.data());
        const std::optional<Settings> x = p.walls ? std::optional(trial_settings(*p.s, t)) : std::nullopt;
        for (std::size_t i = 0; i < p.rows->size(); ++i) {
            double fi[3 + detail::kWallResiduals];
            std::fill(std::begin(fi), std::end(fi), kUnreachable);
            if (p.core) try {
                    fit_residuals(p.model(t, (*p.rows)[i]), (*p.rows)[i], p.temperature, fi);
                } catch (const SolverError&) {
                    std::fill(fi, fi + 3, kUnreachable);
                }
            if (p.walls) try {
                    detail::wall_residuals(detail::wall_model(*p.bulk, *x, *p.points[i]), (*p.rows)[i],
                                           fi + p.core_per_row());
                } catch (const SolverError&) {
                    std::fill(fi + p.core_per_row(), fi + p.per_row(), kUnreachable);
                }
            for (std::size_t j = 0; j < p.per_row(); ++j)
                gsl_vector_set(f, i * p.per_row() + j, std::isfinite(fi[j]) ? fi[j] : kUnreachable);
        }
        return GSL_SUCCESS;
    } catch (...) {
        p.failure = std::current_exception();
        return GSL_EBADFUNC;
    }
}

// With a wall key free, the Jacobian by central differences of a fixed step in theta, kWallStep max(1, |theta|):
// GSL's step, sqrt(eps) |theta|, moves f_t by ~1e-9 (and by nothing at theta ~ 0), below what the 1-D solve's
// Newton tolerance resolves in the slips and T, so its slopes were noise [ASSUMPTION: 1e-4, a numerical choice;
// the central difference's error is O(step^2)].
constexpr double kWallStep = 1e-4;
int gsl_wall_jacobian(const gsl_vector* theta, void* params, gsl_matrix* J) {
    const std::size_t n = J->size1, p = J->size2;
    const std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> th(gsl_vector_alloc(p), gsl_vector_free),
        up(gsl_vector_alloc(n), gsl_vector_free), down(gsl_vector_alloc(n), gsl_vector_free);
    for (std::size_t j = 0; j < p; ++j) {
        gsl_vector_memcpy(th.get(), theta);
        const double t = gsl_vector_get(theta, j), h = kWallStep * std::max(1.0, std::abs(t));
        gsl_vector_set(th.get(), j, t + h);
        if (const int s = gsl_residuals(th.get(), params, up.get()); s != GSL_SUCCESS) return s;
        gsl_vector_set(th.get(), j, t - h);
        if (const int s = gsl_residuals(th.get(), params, down.get()); s != GSL_SUCCESS) return s;
        for (std::size_t i = 0; i < n; ++i)
            gsl_matrix_set(J, i, j, (gsl_vector_get(up.get(), i) - gsl_vector_get(down.get(), i)) / (2 * h));
    }
    return GSL_SUCCESS;
}

std::vector<std::string> check_free(const Settings& s, const FitOptions& o) {
    std::vector<std::string> free = o.free.empty() ? default_free_keys(s) : o.free;
    const std::vector<std::string> allowed = default_free_keys(s);
    const auto allowed_text = [&] {
        std::vector<std::string> a = allowed;
        a.push_back("max_solid_fraction");
        a.push_back("slip_dissipation");
        a.push_back("r5");
        return fmt::format("{}", fmt::join(a, ", "));
    };
    if (free.empty())
        throw CaseError("continuum-fit: the case's closures have no constant to fit: choose a branch with constants "
                        "([continuum] correlation_length = \"jenkins_berzi\" with correlation_constant, or "
                        "contact_stress = \"johnson_jackson\" with its contact_* constants), or free "
                        "max_solid_fraction (--free max_solid_fraction)");
    for (std::size_t i = 0; i < free.size(); ++i) {
        const std::string& k = free[i];
        const auto it = std::find_if(std::begin(kFittable), std::end(kFittable),
                                     [&](const Fittable& f) { return k == f.key; });
        if (it == std::end(kFittable))
            throw CaseError(fmt::format("continuum-fit --free {}: not a constant a fit can free (allowed in this case: "
                                        "{})",
                                        k, allowed_text()));
        if (!in_branch(s, k))
            throw CaseError(fmt::format("continuum-fit --free {}: a constant of {}, which this case does not choose "
                                        "(allowed in this case: {}; or choose the branch in [continuum] and set its "
                                        "constants as the fit's start)",
                                        k, it->branch, allowed_text()));
        if (std::find(free.begin(), free.begin() + static_cast<std::ptrdiff_t>(i), k) != free.begin() + static_cast<std::ptrdiff_t>(i))
            throw CaseError(fmt::format("continuum-fit --free {}: named twice", k));
    }
    return free;
}

void check_rows(const std::vector<BulkRow>& answers, const std::vector<std::string>& free, const FitOptions& o,
                bool core, const std::string& source) {
    // [ASSUMPTION] one answer per free constant, and two at least: one row fixes mu and nu at a single I, not
    // their course with I, which is what the constants are fitted to describe. The wall constants alone: one
    // answer (four residuals: two slips, two near-wall T) per free constant.
    const std::size_t need = std::max<std::size_t>(free.size(), core ? 2 : 1);
    if (answers.size() < need)
        throw CaseError(fmt::format(
            "{}: {} answer row(s) (status = steady and core_dt_check = converged); the fit of {} free constant(s) ({}) "
            "needs at least {}: one answer per free constant{}; allowed: a table with at least {} answers{}",
            source, answers.size(), free.size(), fmt::join(free, ", "), need,
            core ? ", and two at least (one row fixes mu and nu at a single I, not their course with I)" : "", need,
            answers.size() >= (core ? 2u : 1u) ? fmt::format(", or at most {} constants with --free", answers.size())
                                               : ""));
    for (const BulkRow& r : answers) {
        if (!core) break;  // the core's errors weight nothing
        const auto positive = [&](const char* column, double e) {
            if (!(e > 0))
                throw CaseError(fmt::format("{}:{}: point {}: {} = {} cannot weight a fit (the residuals are in units "
                                            "of the row's own error; allowed: > 0)",
                                            source, r.line, r.point, column, e));
        };
        positive("mu_err", r.friction.error);
        positive("nu_err", r.solid_fraction.error);
        if (o.temperature) positive("T_scaled_err", r.temperature_scaled.error);
    }
}

}  // namespace

const std::vector<std::string>& fittable_keys() {
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> k;
        for (const auto& f : kFittable) k.push_back(f.key);
        return k;
    }();
    return keys;
}

std::vector<std::string> default_free_keys(const Settings& s) {
    std::vector<std::string> k;
    for (const auto& f : kFittable)
        if (*f.branch && in_branch(s, f.key)) k.push_back(f.key);
    return k;
}

FitResult fit_bulk_rheology(const Settings& s, const std::vector<BulkRow>& answers, const FitOptions& o,
                            const std::string& source) {
    detail::gsl_quiet();
    const std::vector<std::string> free = check_free(s, o);
    std::vector<std::string> wall_keys;
    for (const std::string& k : free)
        if (detail::is_wall_key(k)) wall_keys.push_back(k);
    FitProblem prob;
    prob.s = &s;
    prob.rows = &answers;
    prob.temperature = o.temperature;
    prob.core = wall_keys.size() < free.size();
    prob.walls = !wall_keys.empty();
    check_rows(answers, free, o, prob.core, source);
    if (prob.walls) {
        detail::check_wall_columns(o.missing_wall_columns, wall_keys, source);
        if (!o.bulk)
            throw CaseError(fmt::format("continuum-fit --free {}: a wall constant is fitted on the bulk case's walls, "
                                        "and no bulk case was given (allowed: --bulk-case DIR)",
                                        fmt::join(wall_keys, ", ")));
        prob.bulk = o.bulk;
        prob.points = detail::wall_points(s, *o.bulk, answers, wall_keys, source);
    }
    const bool r5 = std::find(free.begin(), free.end(), "r5") != free.end();
    FitResult res;
    res.temperature = o.temperature;
    res.core = prob.core;
    res.walls = prob.walls;
    // The start: the case's constants, each inside its key's range.
    FitTrial start = case_trial(s);
    if (r5 && !prob.points.empty()) start.r5 = detail::case_r5(*o.bulk, s, *prob.points.front());
    const std::size_t p = free.size();
    std::vector<double> theta0(p);
    for (const std::string& k : free) {
        const KeySpec* spec = continuum_keys().spec.find(k);
        if (!spec) throw Error(fmt::format("internal: [continuum] declares no key '{}'", k));
        prob.maps.push_back({k, spec->range.lo, spec->range.hi});
    }
    // nu_c before the onset fraction, whose range ends at it
    for (int pass = 0; pass < 2; ++pass)
        for (std::size_t j = 0; j < p; ++j) {
            if ((free[j] == "max_solid_fraction") != (pass == 0)) continue;
            const ConstantMap& m = prob.maps[j];
            const double top = FitProblem::top(m, start), h = std::min(m.hi, top);
            double& v = constant(start, free[j]);
            FitConstant c;
            c.key = free[j];
            c.start = c.value = v;
            c.low = m.lo;
            c.high = h;
            // [ASSUMPTION] a start on the range's edge (e.g. contact_friction = 0) is moved 1e-3 of the range inside
            const double inside = std::isinf(h) ? 1e-3 * std::max(std::abs(v), 1.0) : 1e-3 * (h - m.lo);
            if (v - m.lo < inside) v = m.lo + inside, c.moved_inside = true;
            if (!std::isinf(h) && h - v < inside) v = h - inside, c.moved_inside = true;
            // [ASSUMPTION] a wall key (f_t, default 0) on its edge starts mid-range instead: 1e-3 inside, the map's
            // slope makes the finite-difference step in f_t ~1e-10, below what the 1-D solve resolves
            if (c.moved_inside && detail::is_wall_key(c.key) && !std::isinf(h)) v = 0.5 * (m.lo + h);
            c.fit_start = v;
            theta0[j] = m.theta(v, top);
            res.constants.push_back(c);
        }
    std::vector<FitConstant> ordered;  // back to the order of `free`
    for (const std::string& k : free)
        for (const FitConstant& c : res.constants)
            if (c.key == k) ordered.push_back(c);
    res.constants = ordered;
    // Every answer must be reachable at the start: the row and the range the closures cover.
    const FitTrial t0 = prob.trial(theta0.data());
    for (std::size_t i = 0; i < answers.size() && prob.walls; ++i) {
        try {
            prob.wall_model(t0, i);
        } catch (const SolverError& e) {
            throw CaseError(fmt::format("{}:{}: point {}: the bulk case {} does not solve at the start's constants ({}); "
                                        "allowed: a start ([continuum] constants) at which it solves",
                                        source, answers[i].line, answers[i].point, o.bulk->file.string(), e.what()));
        }
    }
    for (const BulkRow& r : answers) {
        if (!prob.core) break;  // printed at the end, not fitted
        try {
            prob.model(t0, r);
        } catch (const SolverError& e) {
            throw CaseError(fmt::format("{}:{}: point {} (P = {:.0f} Pa): I = {} is outside what the case's closures "
                                        "reach at its constants ({}); allowed: rows inside that range, or a start "
                                        "([continuum] constants) whose closures reach it",
                                        source, r.line, r.point, r.pressure.value, r.inertial.value, e.what()));
        }
    }

    const std::size_t n = answers.size() * prob.per_row();
    res.residuals = n;
    res.dof = n - p;
    gsl_multifit_nlinear_fdf fdf{};
    fdf.f = gsl_residuals;
    fdf.df = prob.walls ? gsl_wall_jacobian : nullptr;  // else GSL's finite-difference Jacobian
    fdf.fvv = nullptr;
    fdf.n = n;
    fdf.p = p;
    fdf.params = &prob;
    gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
    // [ASSUMPTION] central differences: simple_shear_at_inertial bisects nu to 1e-15, forward differences of
    // step sqrt(eps) would keep about half the digits of the slopes the covariance is made of
    params.fdtype = GSL_MULTIFIT_NLINEAR_CTRDIFF;
    const std::unique_ptr<gsl_multifit_nlinear_workspace, void (*)(gsl_multifit_nlinear_workspace*)> w(
        gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p), gsl_multifit_nlinear_free);
    const std::unique_ptr<gsl_vector, void (*)(gsl_vector*)> x0(gsl_vector_alloc(p), gsl_vector_free);
    for (std::size_t j = 0; j < p; ++j) gsl_vector_set(x0.get(), j, theta0[j]);
    int status = gsl_multifit_nlinear_init(x0.get(), &fdf, w.get());
    if (prob.failure) std::rethrow_exception(prob.failure);
    // [ASSUMPTION] tolerances: a step below 1e-10 of theta or a gradient below 1e-10 ends it; 200 iterations
    constexpr std::size_t kMaxIterations = 200;
    int info = 0;
    if (status == GSL_SUCCESS)
        status = gsl_multifit_nlinear_driver(kMaxIterations, 1e-10, 1e-10, 0.0, nullptr, nullptr, &info, w.get());
    if (prob.failure) std::rethrow_exception(prob.failure);
    res.iterations = gsl_multifit_nlinear_niter(w.get());
    // GSL's driver reports no decrease from the very start as GSL_EMAXITER with info = GSL_ENOPROG
    if (status == GSL_EMAXITER && info == GSL_ENOPROG && res.iterations <= 1)
        res.stop = "no step from the start lowered chi2: the start is a minimum to numerical precision, or no row "
                   "depends on the free constants there";
    else if (status == GSL_ENOPROG)
        res.stop = "no further decrease of chi2 within the trust region (GSL_ENOPROG): at a minimum to numerical "
                   "precision, or stuck";
    else if (status != GSL_SUCCESS)
        throw SolverError(fmt::format("continuum-fit: the fit did not converge ({}) after {} iterations; try other "
                                      "starting constants in [continuum] or fewer free constants (--free)",
                                      gsl_strerror(status), res.iterations));
    else
        res.stop = info == 1 ? "the step in the constants fell below 1e-10 (relative)"
                             : "the gradient of chi2 fell below 1e-10 (relative)";

    // The constants, their covariance (J^T J)^-1 with J of the weighted residuals: the errors as the table gives
    // them (not scaled by chi2/dof). GSL drops columns with |R_kk| <= 1e-10 |R_11| (linearly dependent).
    const gsl_vector* position = gsl_multifit_nlinear_position(w.get());
    std::vector<double> th(p);
    for (std::size_t j = 0; j < p; ++j) th[j] = gsl_vector_get(position, j);
    const std::unique_ptr<gsl_matrix, void (*)(gsl_matrix*)> cov(gsl_matrix_alloc(p, p), gsl_matrix_free);
    const gsl_matrix* J = gsl_multifit_nlinear_jac(w.get());
    gsl_multifit_nlinear_covar(J, 1e-10, cov.get());
    FitTrial fitted = prob.trial(th.data());
    res.correlation.assign(p, std::vector<double>(p, 0.0));
    for (std::size_t j = 0; j < p; ++j) {
        FitConstant& c = res.constants[j];
        c.value = constant(fitted, c.key);
        const double var = gsl_matrix_get(cov.get(), j, j);
        c.determined = var > 0;
        const gsl_vector_const_view column = gsl_matrix_const_column(J, j);
        c.no_effect = gsl_blas_dnrm2(&column.vector) == 0.0;
        c.error = c.determined ? prob.maps[j].slope(th[j], FitProblem::top(prob.maps[j], fitted)) * std::sqrt(var)
                               : std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < p; ++k) {
            const double vk = gsl_matrix_get(cov.get(), k, k);
            res.correlation[j][k] = var > 0 && vk > 0 ? gsl_matrix_get(cov.get(), j, k) / std::sqrt(var * vk) : 0.0;
        }
    }
    // Every row at the fitted constants (T's residual printed when not fitted; the core's when no closure constant
    // is free, NaN where the closures do not reach the row's I).
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < answers.size(); ++i) {
        const BulkRow& r = answers[i];
        FitRow fr{r, {}, kNaN, kNaN, kNaN, {}, 0, 0, 0, 0};
        try {
            fr.model = prob.model(fitted, r);
            double f[3] = {0, 0, 0};
            fit_residuals(fr.model, r, false, f);
            fr.mu = f[0];
            fr.nu = f[1];
            fr.T = r.temperature_scaled.error > 0
                       ? (fr.model.temperature - r.temperature_scaled.value) / r.temperature_scaled.error
                       : kNaN;
        } catch (const SolverError&) {
            if (prob.core) throw;
        }
        if (prob.core) res.chi2 += fr.mu * fr.mu + fr.nu * fr.nu + (o.temperature ? fr.T * fr.T : 0.0);
        if (prob.walls) {
            fr.walls = prob.wall_model(fitted, i);
            double f[detail::kWallResiduals];
            detail::wall_residuals(fr.walls, r, f);
            fr.slip_bottom = f[0], fr.slip_top = f[1], fr.T_bottom = f[2], fr.T_top = f[3];
            for (double x : f) res.chi2 += x * x;
        }
        res.rows.push_back(fr);
    }
    res.p_value = res.dof > 0 ? gsl_cdf_chisq_Q(res.chi2, static_cast<double>(res.dof)) : 1.0;
    return res;
}

Case bulk_case_for(const Case& bulk, const Case& fitted) {
    Case b = bulk;
    b.sections.insert_or_assign(std::string(kSolver.name), fitted.section(kSolver.name));
    return b;
}

std::string fit_report(const FitResult& r) {
    std::string out;
    const double scale = r.dof > 0 ? std::sqrt(r.chi2 / static_cast<double>(r.dof)) : 1.0;
    const std::string core = r.temperature ? "mu, nu and T/(d gdot)^2" : "mu and nu";
    const std::string walls = "the walls' slips and near-wall T (the bulk case's 1-D solve)";
    out += fmt::format("fitted on {} of {} answer row(s) (residuals {} - constants {} = {} degrees of freedom), "
                       "{} iteration(s): {}\n\n",
                       r.core && r.walls ? core + " and " + walls : r.core ? core : walls, r.rows.size(), r.residuals,
                       r.constants.size(), r.dof, r.iterations, r.stop);
    out += fmt::format("{:<26} {:>12} {:>12} {:>12} {:>16}  range\n", "constant", "start", "fitted", "std. error",
                       "x sqrt(chi2/dof)");
    for (const FitConstant& c : r.constants) {
        const std::string err = c.determined ? fmt::format("{:.4g}", c.error) : "undetermined";
        const std::string scaled = c.determined ? fmt::format("{:.4g}", c.error * std::max(scale, 1.0)) : "";
        out += fmt::format("{:<26} {:>12.6g} {:>12.6g} {:>12} {:>16}  [{:g}, {:g}]{}\n", c.key, c.start, c.value, err,
                           scaled, c.low, c.high, c.moved_inside ? fmt::format(" (the case's value is on its edge: started at {:g})", c.fit_start) : "");
    }
    for (const FitConstant& c : r.constants)
        if (!c.determined)
            out += fmt::format("  {}: not determined by these rows: {}; the fit leaves it where it started\n", c.key,
                               c.no_effect ? "no row's mu or nu depends on it at these constants (for "
                                             "correlation_constant: L* = 1 at every row; a start where L* > 1 lets "
                                             "the fit move it)"
                                           : "its effect on the rows is a combination of the other constants'");
    if (r.constants.size() > 1) {
        out += "\ncorrelation\n";
        out += fmt::format("{:<26}", "");
        for (std::size_t k = 0; k < r.constants.size(); ++k) out += fmt::format(" {:>7}", fmt::format("[{}]", k + 1));
        out += "\n";
        for (std::size_t j = 0; j < r.constants.size(); ++j) {
            out += fmt::format("{:<26}", fmt::format("[{}] {}", j + 1, r.constants[j].key));
            for (std::size_t k = 0; k < r.constants.size(); ++k) out += fmt::format(" {:>7.3f}", r.correlation[j][k]);
            out += "\n";
        }
    }
    out += fmt::format("\n{:<14} {:>7} {:>9} {:>17} {:>8} {:>7} {:>17} {:>8} {:>7} {:>15} {:>7} {:>7}\n", "point", "P Pa",
                       "I", "mu table", "mu fit", "dmu/err", "nu table", "nu fit", "dnu/err", "T table", "T fit", "dT/err");
    for (const FitRow& f : r.rows) {
        const BulkRow& b = f.row;
        out += fmt::format("{:<14} {:>7.0f} {:>9.4g} {:>17} {:>8.4f} {:>+7.2f} {:>17} {:>8.4f} {:>+7.2f} {:>15} {:>7.3f} "
                           "{:>+7.2f}{}\n",
                           b.point, b.pressure.value, b.inertial.value,
                           fmt::format("{:.4f} ± {:.4f}", b.friction.value, b.friction.error), f.model.stress_ratio, f.mu,
                           fmt::format("{:.4f} ± {:.4f}", b.solid_fraction.value, b.solid_fraction.error), f.model.nu,
                           f.nu, fmt::format("{:.3f} ± {:.3f}", b.temperature_scaled.value, b.temperature_scaled.error),
                           f.model.temperature, f.T, !r.core ? " (not fitted)" : r.temperature ? "" : " (T not fitted)");
    }
    if (r.walls) {
        out += fmt::format("\n{:<14} {:>17} {:>8} {:>7} {:>17} {:>8} {:>7} {:>17} {:>8} {:>7} {:>17} {:>8} {:>7}\n",
                           "point", "slip_b/U table", "fit", "d/err", "slip_t/U table", "fit", "d/err", "T_b/U2 table",
                           "fit", "d/err", "T_t/U2 table", "fit", "d/err");
        const auto cell = [](const Measured& m) { return fmt::format("{:.4g} ± {:.2g}", m.value, m.error); };
        for (const FitRow& f : r.rows)
            out += fmt::format("{:<14} {:>17} {:>8.4g} {:>+7.2f} {:>17} {:>8.4g} {:>+7.2f} {:>17} {:>8.4g} {:>+7.2f} "
                               "{:>17} {:>8.4g} {:>+7.2f}\n",
                               f.row.point, cell(f.row.slip_bottom), f.walls.slip_bottom.value, f.slip_bottom,
                               cell(f.row.slip_top), f.walls.slip_top.value, f.slip_top, cell(f.row.T_wall_bottom),
                               f.walls.T_bottom.value, f.T_bottom, cell(f.row.T_wall_top), f.walls.T_top.value, f.T_top);
    }
    out += fmt::format("\nchi2 = {:.4g} for {} degrees of freedom: chi2/dof = {:.4g}, P(chi2 >= {:.4g}) = {:.3g}\n",
                       r.chi2, r.dof, r.dof ? r.chi2 / static_cast<double>(r.dof) : 0.0, r.chi2, r.p_value);
    // [ASSUMPTION] 1e-3: below it the residuals are not the table's errors (the closures cannot follow the rows)
    if (r.p_value < 1e-3)
        out += fmt::format("the closures do not describe the table within its errors (P = {:.3g} < 0.001): the fitted "
                           "constants are the least bad, not a description; the errors above scaled by "
                           "sqrt(chi2/dof) = {:.3g} are the closer guide\n",
                           r.p_value, scale);
    return out;
}

std::string fit_fragment(const FitResult& r, const std::vector<std::string>& provenance) {
    std::string out;
    for (const auto& l : provenance) out += "# " + l + "\n";
    out += fmt::format("# chi2 = {:.6g}, {} degrees of freedom, chi2/dof = {:.6g}, P(chi2 >= chi2 fitted) = {:.6g}\n",
                       r.chi2, r.dof, r.dof ? r.chi2 / static_cast<double>(r.dof) : 0.0, r.p_value);
    out += "[continuum]\n";
    for (const FitConstant& c : r.constants)
        out += fmt::format("{} = {:.6g}  # {}\n", c.key, c.value,
                           c.determined ? fmt::format("+- {:.3g} (one standard error)", c.error)
                                        : std::string("not determined by the table"));
    return out;
}

}  // namespace granlub::continuum
