// Vertex-centred FV + Newton (docs/continuum-model.md §6.1). See fv_solver.h for the method.
#include "granlub/continuum/fv_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "block_tridiagonal.h"
#include "contact_continuation.h"
#include "damped_newton.h"
#include "granlub/continuum/homogeneous.h"
#include "granlub/continuum/walls/wall_condition.h"
#include "granlub/error.h"

namespace granlub::continuum {
namespace {

using D7 = Dual<7>;
// Local stencil slots of the Jacobian row of node i.
enum Slot { kUm = 0, kSm = 1, kUc = 2, kSc = 3, kUp = 4, kSp = 5, kLam = 6 };

// Node closures with derivatives taken w.r.t. the logit unknown s.
struct Node {
    double nu, dnu, M, dM, K, dK, C, dC;
    double pc, dpc;  // the contact pressure over P_y and its s-derivative (0 without a contact stress, §2.9)
};
struct WallNode {
    double b5, db5, b6, db6, b7, db7, b8, db8, xs, dxs;  // xs: xi per slip (WallCoefficients)
};

// The values one node's residual needs.
template <class S>
struct Local {
    S um, uc, up, nm, nc, np, Mm, Mc, Mp, Km, Kc, Kp, Cc, Pi, L, b5, b6, b7, b8, xs;
    S pcm, pcc, pcp;  // contact pressure over P_y at the three nodes (§2.9)
};

enum class Kind { Interior, Bottom, Top };

// Flux balance of node i's control volume (§6.1). Bottom/top are the wall half-cells.
// The contact stress (§2.9) adds k pi_c sgn_eps(u^') to the signed momentum flux M u^' (k = mu_c Lambda/sqrt(Pi)),
// at the faces (pi_c the node average, u^' the face difference) and at the walls (the wall node's pi_c and the
// wall condition's u^': the wall's contact friction taken equal to the bulk's [ASSUMPTION], so that the kinetic
// wall conditions balance the kinetic stress). cs = nullptr (no contact shear): the residual as without it.
template <class S>
void node_residual(Kind kind, const Local<S>& l, const WallParams* w, double h, bool faces, const ContactStress* cs,
                   S& Ru, S& Rn) {
    const S& L = l.L;
    const S L2 = L * L;
    if (kind == Kind::Interior) {
        // The shear work at the node: M u^'^2 with the central u^', or with a contact stress the mean of the two
        // faces' M u^'^2 (there conduction vanishes with T as nu -> nu_P, and the central difference would let odd
        // and even nodes decouple).
        const S du = (l.up - l.um) / (2 * h);
        S src = l.Pi * l.Mc * du * du - L2 * l.Cc;  // (this order: bit for bit as without the branch)
        if (faces) {
            const S dup = (l.up - l.uc) / h, dum = (l.uc - l.um) / h;
            src = l.Pi * 0.25 * ((l.Mc + l.Mp) * dup * dup + (l.Mm + l.Mc) * dum * dum) - L2 * l.Cc;
        }
        Ru = (0.5 * (l.Mc + l.Mp) * (l.up - l.uc) - 0.5 * (l.Mm + l.Mc) * (l.uc - l.um)) / h;
        Rn = (0.5 * (l.Kc + l.Kp) * (l.np - l.nc) - 0.5 * (l.Km + l.Kc) * (l.nc - l.nm)) / h - h * src;
    } else if (kind == Kind::Bottom) {
        // n = +y^, slip = 1 - u^: the wall condition's gradients are y^-gradients as they stand.
        const auto g = wall_gradients(*w, l.b5, l.b6, l.b7, l.b8, l.xs, S(1.0 - l.uc), L, l.Pi);
        const S& du = g.du;
        const S& dn = g.dnu;
        const S src = l.Pi * l.Mc * du * du - L2 * l.Cc;
        Ru = 0.5 * (l.Mc + l.Mp) * (l.up - l.uc) / h - l.Mc * du;
        Rn = 0.5 * (l.Kc + l.Kp) * (l.np - l.nc) / h - l.Kc * dn - 0.5 * h * src;
    } else {
        // n = -y^, slip = 0 - u^: y^-gradients are minus the wall condition's.
        const auto g = wall_gradients(*w, l.b5, l.b6, l.b7, l.b8, l.xs, S(-l.uc), L, l.Pi);
        const S du = -g.du;
        const S dn = -g.dnu;
        const S src = l.Pi * l.Mc * du * du - L2 * l.Cc;
        Ru = l.Mc * du - 0.5 * (l.Mm + l.Mc) * (l.uc - l.um) / h;
        Rn = l.Kc * dn - 0.5 * (l.Km + l.Kc) * (l.nc - l.nm) / h - 0.5 * h * src;
    }
    if (cs) {  // the fluxes of closures/contact_stress.h, shared with the cross-section
        const S k = cs->scale(L, l.Pi), none(0.0);
        const auto face = [&](const S& pa, const S& pb, const S& ua, const S& ub) {
            return cs->face_flux(pa, pb, S((ub - ua) / h), none);
        };
        if (kind == Kind::Interior) {
            Ru = Ru + k * (face(l.pcc, l.pcp, l.uc, l.up) - face(l.pcm, l.pcc, l.um, l.uc));  // Ru is a flux difference
        } else if (kind == Kind::Bottom) {
            const S du = wall_gradients(*w, l.b5, l.b6, l.b7, l.b8, l.xs, S(1.0 - l.uc), L, l.Pi).du;
            Ru = Ru + k * (face(l.pcc, l.pcp, l.uc, l.up) - cs->wall_flux(l.pcc, du, none));
        } else {
            const S du = -wall_gradients(*w, l.b5, l.b6, l.b7, l.b8, l.xs, S(-l.uc), L, l.Pi).du;
            Ru = Ru + k * (cs->wall_flux(l.pcc, du, none) - face(l.pcm, l.pcc, l.um, l.uc));
        }
    }
}

// The unknowns: u^ and the logit s of every node.
struct Unknowns {
    std::vector<double> u, s;
};

class Fv {
public:
    Fv(const Problem& p, int cells)
        : p_(p), N_(static_cast<std::size_t>(cells)), n_(N_ + 1), h_(1.0 / cells), cap_(p.closures->cap()),
          fill_(p.mode == Mode::Fill), inventory_(p.mode == Mode::Inventory),
          contact_(p.closures->contact().active() && p.closures->contact().friction > 0 ? &p.closures->contact() : nullptr),
          faces_(p.closures->contact().active()), nodes_(n_), F_(n_), Fl_(n_),
          x_(n_), y_(n_), J_(n_) {}

    std::size_t nodes() const { return n_; }
    double h() const { return h_; }
    double cap() const { return cap_; }
    bool fill() const { return fill_; }
    bool inventory() const { return inventory_; }
    bool bordered() const { return fill_ || inventory_; }
    // The bordering unknown lambda: ln Pi (Fill), ln Lambda (Inventory), unused (Load).
    double Pi_of(double lam) const { return fill_ ? std::exp(lam) : p_.Pi; }
    double Lambda_of(double lam) const { return inventory_ ? std::exp(lam) : p_.Lambda; }

    double nu_of(double s) const { return cap_ / (1.0 + std::exp(-s)); }

    // Residual (and Jacobian when `jac`) at unknowns u, s, lambda; returns the max norm.
    double evaluate(const std::vector<double>& u, const std::vector<double>& s, double lam, bool jac) {
        const double Pi = Pi_of(lam), L = Lambda_of(lam);
        L_ = L;
        for (std::size_t i = 0; i < n_; ++i) {
            const double nu = nu_of(s[i]);
            const double dnu = nu * (1.0 - nu / cap_);
            const auto c = node_coefficients(*p_.closures, nu);
            const ContactStress& cs = p_.closures->contact();
            nodes_[i] = {nu, dnu, c.M, c.dM * dnu, c.K, c.dK * dnu, c.C, c.dC * dnu, cs.ratio(nu), cs.dratio(nu) * dnu};
        }
        wall_[0] = wall_node(p_.bottom, nodes_[0]);
        wall_[1] = wall_node(p_.top, nodes_[N_]);
        double norm = 0;
        for (std::size_t i = 0; i < n_; ++i) {
            const Kind kind = i == 0 ? Kind::Bottom : (i == N_ ? Kind::Top : Kind::Interior);
            const WallParams* w = kind == Kind::Bottom ? &p_.bottom.params : (kind == Kind::Top ? &p_.top.params : nullptr);
            const WallNode& wn = wall_[kind == Kind::Top ? 1 : 0];
            const std::size_t im = i == 0 ? 0 : i - 1, ip = i == N_ ? N_ : i + 1;
            if (!jac) {
                Local<double> l{u[im], u[i], u[ip], nodes_[im].nu, nodes_[i].nu, nodes_[ip].nu,
                                nodes_[im].M, nodes_[i].M, nodes_[ip].M, nodes_[im].K, nodes_[i].K, nodes_[ip].K,
                                nodes_[i].C, Pi, L, wn.b5, wn.b6, wn.b7, wn.b8, wn.xs,
                                nodes_[im].pc, nodes_[i].pc, nodes_[ip].pc};
                double ru, rn;
                node_residual(kind, l, w, h_, faces_, contact_, ru, rn);
                F_[i] = {ru, rn};
            } else {
                const Node& a = nodes_[im];
                const Node& c = nodes_[i];
                const Node& b = nodes_[ip];
                Local<D7> l{D7::variable(u[im], kUm), D7::variable(u[i], kUc), D7::variable(u[ip], kUp),
                            D7::lifted(a.nu, kSm, a.dnu), D7::lifted(c.nu, kSc, c.dnu), D7::lifted(b.nu, kSp, b.dnu),
                            D7::lifted(a.M, kSm, a.dM), D7::lifted(c.M, kSc, c.dM), D7::lifted(b.M, kSp, b.dM),
                            D7::lifted(a.K, kSm, a.dK), D7::lifted(c.K, kSc, c.dK), D7::lifted(b.K, kSp, b.dK),
                            D7::lifted(c.C, kSc, c.dC), D7::lifted(Pi, kLam, fill_ ? Pi : 0.0),
                            D7::lifted(L, kLam, inventory_ ? L : 0.0),
                            D7::lifted(wn.b5, kSc, wn.db5), D7::lifted(wn.b6, kSc, wn.db6),
                            D7::lifted(wn.b7, kSc, wn.db7), D7::lifted(wn.b8, kSc, wn.db8),
                            D7::lifted(wn.xs, kSc, wn.dxs),
                            D7::lifted(a.pc, kSm, a.dpc), D7::lifted(c.pc, kSc, c.dpc), D7::lifted(b.pc, kSp, b.dpc)};
                D7 ru, rn;
                node_residual(kind, l, w, h_, faces_, contact_, ru, rn);
                F_[i] = {ru.v, rn.v};
                const auto blk = [&](int su, int ss) {
                    Eigen::Matrix2d m;
                    m << ru.d[su], ru.d[ss], rn.d[su], rn.d[ss];
                    return m;
                };
                // At the walls the stencil reuses node i for the missing neighbour: fold those columns back.
                J_.diag[i] = blk(kUc, kSc);
                J_.lower[i] = blk(kUm, kSm);
                J_.upper[i] = blk(kUp, kSp);
                if (i == 0) { J_.diag[i] += J_.lower[i]; J_.lower[i].setZero(); }
                if (i == N_) { J_.diag[i] += J_.upper[i]; J_.upper[i].setZero(); }
                Fl_[i] = {ru.d[kLam], rn.d[kLam]};
            }
            norm = std::max({norm, std::abs(F_[i][0]), std::abs(F_[i][1])});
            if (!std::isfinite(F_[i][0]) || !std::isfinite(F_[i][1])) return std::numeric_limits<double>::infinity();
        }
        if (fill_) {
            g_ = mean_nu() - p_.nu_mean;
            norm = std::max(norm, std::abs(g_));
        } else if (inventory_) {
            g_ = L * mean_nu() - p_.inventory;
            norm = std::max(norm, std::abs(g_));
        }
        return norm;
    }

    // The largest difference between the exact Jacobian at (u, s) and central differences of the residual with
    // steps `step` (Load mode: no bordering column), relative to max(1, |entry|); for tests (§2.4).
    double jacobian_defect(const std::vector<double>& u, const std::vector<double>& s, double step) {
        const double lam = std::log(p_.Pi);
        evaluate(u, s, lam, true);
        const detail::BlockTridiagonal J = J_;
        double worst = 0;
        for (std::size_t j = 0; j < n_; ++j) {
            for (int k = 0; k < 2; ++k) {
                std::vector<double> up = u, sp = s, um = u, sm = s;
                (k == 0 ? up : sp)[j] += step;
                (k == 0 ? um : sm)[j] -= step;
                evaluate(up, sp, lam, false);
                const std::vector<Eigen::Vector2d> Fp = F_;
                evaluate(um, sm, lam, false);
                for (std::size_t i = (j == 0 ? 0 : j - 1); i <= std::min(N_, j + 1); ++i) {
                    const Eigen::Matrix2d& blk = i == j ? J.diag[i] : (i < j ? J.upper[i] : J.lower[i]);
                    for (int r = 0; r < 2; ++r) {
                        const double fd = (Fp[i][r] - F_[i][r]) / (2 * step), ex = blk(r, k);
                        worst = std::max(worst, std::abs(fd - ex) / std::max(1.0, std::abs(ex)));
                    }
                }
            }
        }
        return worst;
    }

    double mean_nu() const {
        double m = 0;
        for (std::size_t i = 0; i < n_; ++i) m += weight(i) * nodes_[i].nu;
        return m;
    }
    double weight(std::size_t i) const { return (i == 0 || i == N_) ? 0.5 * h_ : h_; }

    // The interface of detail::damped_newton (damped_newton.h).
    double evaluate(const Unknowns& x, double lam, bool jac) { return evaluate(x.u, x.s, lam, jac); }
    bool step(Unknowns& dx, double& dlam) { return step(dx.u, dx.s, dlam); }
    void step_sizes(const Unknowns& dx, double& du, double& ds) const {
        for (std::size_t i = 0; i < n_; ++i) du = std::max(du, std::abs(dx.u[i])), ds = std::max(ds, std::abs(dx.s[i]));
    }
    void advance(Unknowns& out, const Unknowns& x, double a, const Unknowns& dx) const {
        for (std::size_t i = 0; i < n_; ++i) out.u[i] = x.u[i] + a * dx.u[i], out.s[i] = x.s[i] + a * dx.s[i];
    }

    // Newton step for the last evaluate(..., jac = true). False when the matrix is singular.
    bool step(std::vector<double>& du, std::vector<double>& ds, double& dlam) {
        if (!J_.factorise()) return false;
        for (std::size_t i = 0; i < n_; ++i) x_[i] = -F_[i];
        J_.solve(x_);
        dlam = 0;
        if (bordered()) {
            // Bordered system [J c; r k]: x = x1 - dlam x2, r.x + k dlam = -g  (§6.1 "Fill mode");
            // Fill: g = mean nu - target, k = 0; Inventory: g = Lambda mean nu - inventory, k = Lambda mean nu.
            for (std::size_t i = 0; i < n_; ++i) y_[i] = Fl_[i];
            J_.solve(y_);
            const double scale = inventory_ ? L_ : 1.0, k = inventory_ ? L_ * mean_nu() : 0.0;
            double rx1 = 0, rx2 = 0;
            for (std::size_t i = 0; i < n_; ++i) {
                const double r = scale * weight(i) * nodes_[i].dnu;
                rx1 += r * x_[i][1];
                rx2 += r * y_[i][1];
            }
            if (!(std::abs(rx2 - k) > 0)) return false;
            dlam = (rx1 + g_) / (rx2 - k);
            for (std::size_t i = 0; i < n_; ++i) x_[i] -= dlam * y_[i];
        }
        for (std::size_t i = 0; i < n_; ++i) {
            du[i] = x_[i][0];
            ds[i] = x_[i][1];
        }
        return true;
    }

private:
    WallNode wall_node(const WallBC& w, const Node& n) const {
        const auto b = wall_coefficients(p_, w, n.nu);
        return {b.b5.v, b.b5.d[0] * n.dnu, b.b6.v, b.b6.d[0] * n.dnu,
                b.b7.v, b.b7.d[0] * n.dnu, b.b8.v, b.b8.d[0] * n.dnu, b.xi_per_slip.v, b.xi_per_slip.d[0] * n.dnu};
    }

    const Problem& p_;
    std::size_t N_, n_;
    double h_, cap_;
    bool fill_, inventory_;
    const ContactStress* contact_;  // its shear (§2.9); nullptr without one or with mu_c = 0
    bool faces_;  // shear work from the faces' gradients (with a contact stress)
    double L_ = 0;  // Lambda of the last evaluate()
    std::vector<Node> nodes_;
    WallNode wall_[2]{};
    std::vector<Eigen::Vector2d> F_, Fl_, x_, y_;
    double g_ = 0;
    detail::BlockTridiagonal J_;
};

}  // namespace

NewtonReport newton_fv(const Problem& p, const SolverSettings& st, Solution& sol) {
    Fv fv(p, st.cells);
    const std::size_t n = fv.nodes();
    if (sol.nodes() != n) throw Error("newton_fv: the initial guess is not on the solver's mesh");
    const double cap = fv.cap();
    Unknowns x{sol.u, std::vector<double>(n)}, dx{std::vector<double>(n), std::vector<double>(n)}, xt = dx;
    for (std::size_t i = 0; i < n; ++i) {
        const double nu = std::clamp(sol.nu[i], 1e-9 * cap, (1 - 1e-12) * cap);
        x.s[i] = std::log(nu / (cap - nu));
    }
    double lam = fv.inventory() ? std::log(sol.Lambda > 0 ? sol.Lambda : p.Lambda)
                                : std::log(sol.Pi > 0 ? sol.Pi : p.Pi);
    NewtonReport rep = detail::damped_newton(fv, x, lam, dx, xt, st.tolerance, st.max_iterations);
    for (std::size_t i = 0; i < n; ++i) {
        sol.u[i] = x.u[i];
        sol.nu[i] = fv.nu_of(x.s[i]);
    }
    sol.Pi = fv.Pi_of(lam);
    sol.Lambda = fv.Lambda_of(lam);
    sol.residual = rep.residual;
    if (rep.converged) {
        // Guard against the spurious "empty channel" branch (§6.3).
        const double m = fv.mean_nu();
        if (m < 0.01) {
            rep.converged = false;
            rep.why = "Newton fell onto the empty-channel branch (mean nu < 0.01)";
        }
    }
    return rep;
}

double fv_jacobian_defect(const Problem& p, const Solution& s, double step) {
    if (p.mode != Mode::Load) throw Error("fv_jacobian_defect: Load mode only");
    Fv fv(p, static_cast<int>(s.nodes() - 1));
    const double cap = fv.cap();
    std::vector<double> lg(s.nodes());
    for (std::size_t i = 0; i < s.nodes(); ++i) lg[i] = std::log(s.nu[i] / (cap - s.nu[i]));
    return fv.jacobian_defect(s.u, lg, step);
}

double fv_residual_norm(const Problem& p, const Solution& s) {
    Fv fv(p, static_cast<int>(s.nodes() - 1));
    const double cap = fv.cap();
    std::vector<double> lg(s.nodes());
    for (std::size_t i = 0; i < s.nodes(); ++i) lg[i] = std::log(s.nu[i] / (cap - s.nu[i]));
    return fv.evaluate(s.u, lg, std::log(fv.inventory() ? s.Lambda : s.Pi), false);
}

namespace {

Solution initial_guess(const Problem& p, int cells) {
    const UniformShear h = p.mode == Mode::Load   ? uniform_shear_load(p)
                           : p.mode == Mode::Fill ? uniform_shear_fill(p)
                                                  : uniform_shear_inventory(p);
    return uniform_solution(h, cells);
}

std::string describe(const Problem& p) {
    std::ostringstream m;
    if (p.mode == Mode::Fill) m << "mean nu = " << p.nu_mean;
    else m << "Pi = rho U^2/P = " << p.Pi;
    if (p.mode == Mode::Inventory) m << ", grains per wall area / d = " << p.inventory;
    else m << ", Lambda = H/d = " << p.Lambda;
    return m.str();
}

// Without a contact stress: Newton from the uniform-shear guess, else continuation in ln Lambda and ln Pi / mean nu.
Solution solve_fv_kinetic(const Problem& p, const SolverSettings& st) {
    int total = 0;
    std::string first_why;
    double first_res = 0;
    try {
        Solution s = initial_guess(p, st.cells);
        const auto rep = newton_fv(p, st, s);
        total += rep.iterations;
        if (rep.converged) {
            s.iterations = total;
            return s;
        }
        first_why = rep.why;
        first_res = rep.residual;
    } catch (const SolverError& e) {
        first_why = e.what();
    }
    // Automatic continuation (§6.1): from an easy problem (Lambda <= 5, moderate Pi or
    // mean nu) to the target, in ln Lambda and ln Pi (Load) or mean nu (Fill), halving the step
    // when Newton fails (or after a step that needed many iterations).
    Problem start = p;
    start.Lambda = p.mode == Mode::Inventory ? p.Lambda : std::min(p.Lambda, 5.0);
    if (p.mode != Mode::Fill) start.Pi = std::clamp(p.Pi, 0.3, 3.0);
    else start.nu_mean = std::clamp(p.nu_mean, 0.3 * p.closures->cap(), 0.9 * p.closures->cap());
    const auto at = [&](double t) {
        Problem q = p;
        q.Lambda = std::exp((1 - t) * std::log(start.Lambda) + t * std::log(p.Lambda));
        if (p.mode != Mode::Fill) q.Pi = std::exp((1 - t) * std::log(start.Pi) + t * std::log(p.Pi));
        else q.nu_mean = (1 - t) * start.nu_mean + t * p.nu_mean;
        return q;
    };
    Solution s;
    try {
        s = initial_guess(start, st.cells);
    } catch (const SolverError& e) {
        throw SolverError(first_why + "; continuation could not start: " + e.what());
    }
    auto rep = newton_fv(start, st, s);
    total += rep.iterations;
    if (!rep.converged) {
        std::ostringstream m;
        m << first_why << " (residual " << first_res << "), and continuation could not start at " << describe(start)
          << ": " << rep.why << " (residual " << rep.residual
          << "); try more [continuum] max_iterations or check the operating point";
        throw SolverError(m.str());
    }
    const auto c = detail::continuation(
        s, [&](double t, Solution& trial) { return newton_fv(at(t), st, trial); }, st.max_continuation_steps, total);
    if (!c.reached) {
        const NewtonReport& last = c.steps > 1 ? c.last : rep;
        std::ostringstream m;
        m << first_why << " (residual " << first_res << "); continuation stalled at " << describe(at(c.t))
          << " after " << c.steps - 1 << " steps (last Newton residual " << last.residual << ": " << last.why
          << "); try more [continuum] cells, a larger max_continuation_steps, or a less extreme operating point";
        throw SolverError(m.str());
    }
    s.iterations = total;
    s.continuation_steps = c.steps;
    return s;
}

}  // namespace

Solution solve_fv(const Problem& p, const SolverSettings& st) {
    const ContactStress& cs = p.closures->contact();
    if (!cs.active()) return solve_fv_kinetic(p, st);
    // With a contact stress (§2.9): its two continuations (contact_continuation.h).
    return detail::contact_continuation<Solution>(
        cs,
        [&](double coefficient, double friction) {
            Problem q = p;
            q.closures = detail::scaled_contact(*p.closures, cs, coefficient, friction);
            return q;
        },
        [&](const Problem& q) { return solve_fv_kinetic(q, st); },
        [&](const Problem& q, Solution& trial) { return newton_fv(q, st, trial); },
        [](const Problem& q) { return q.closures->cap(); }, st.max_continuation_steps, describe(p));
}

}  // namespace granlub::continuum
