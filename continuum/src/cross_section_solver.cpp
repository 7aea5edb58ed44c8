// Vertex-centred FV + Newton on the trough's cross-section. See cross_section_solver.h for the method.
#include "granlub/continuum/cross_section_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "damped_newton.h"
#include "granlub/continuum/fv_solver.h"
#include "granlub/continuum/walls/wall_condition.h"
#include "granlub/error.h"

namespace granlub::continuum {

const WallBC& CrossSectionProblem::wall(CrossSectionWall w) const {
    switch (w) {
        case CrossSectionWall::Floor: return gap.bottom;
        case CrossSectionWall::Top: return gap.top;
        case CrossSectionWall::Outer: return outer;
        default: return inner;
    }
}

namespace cross_section_fv {  // named: the library is a unity build beside fv_solver.cpp

using D = Dual<11>;
// Stencil members: centre, south (i - 1), north (i + 1), west (j - 1), east (j + 1); member m has the unknown
// slots 2m (u^) and 2m + 1 (s); slot 10 is the bordering unknown ln Lambda.
constexpr int kMembers = 5, kLam = 10;
enum Member { kC = 0, kS = 1, kN = 2, kW = 3, kE = 4 };

// Node closures with derivatives in the logit unknown s.
struct NodeVal {
    double nu, dnu, M, dM, K, dK, C, dC;
    double Kp = 0, dKp = 0, p = 1;  // with a pressure field: p^^1/2 K_p of the grad-p heat flux, and p^
};
// A wall's coefficients b5..b8 at a node, with d/ds.
struct WallVal {
    double b[4], db[4];
};

template <class S>
struct Local {
    S u[kMembers], nu[kMembers], M[kMembers], K[kMembers], Kp[kMembers];
    double p[kMembers];
    S C, Pi, L, hz;
    S b[kCrossSectionWalls][4];  // the coefficients of the walls the node lies on
};

// Which faces of node (i, j)'s control volume are walls, and where it is.
struct NodeGeom {
    bool wall[kCrossSectionWalls];
    double y, z;
};

// The flux balance of one control volume per unit width (1-D units: the 1-D solver's residual when nothing
// depends on z^). Ru = div(M grad u^), Rn = div(K grad nu) - source, integrated over the CV and divided by its
// z^-width.
template <class S>
void residual(const CrossSectionProblem& p, const NodeGeom& g, const Local<S>& l, double hy, S& Ru, S& Rn) {
    using W = CrossSectionWall;
    const auto at_wall = [&](W w, const S& slip) {
        const WallBC& bc = p.wall(w);
        const int k = static_cast<int>(w);
        // the wall condition at the local pressure: Pi = rho U^2 / p (the b's are in P-scaled form)
        auto gr = wall_gradients(bc.params, l.b[k][0], l.b[k][1], l.b[k][2], l.b[k][3], slip, l.L, l.Pi / l.p[kC]);
        if (p.source) {
            double cu = 0, cn = 0;
            p.source->wall(w, g.y, g.z, cu, cn);
            gr.du = gr.du + cu;
            gr.dnu = gr.dnu + cn;
        }
        return gr;
    };
    const bool floor = g.wall[0], top = g.wall[1], outer = g.wall[2], inner = g.wall[3];
    // y^: fluxes M du/dy on the south and north faces, and du/dy at the node
    S Fu_s, Fu_n, Fn_s, Fn_n, duy, duz, Fu_w, Fu_e, Fn_w, Fn_e;
    if (floor) {  // n = +y^, u^_wall = 1
        const auto gr = at_wall(W::Floor, S(1.0 - l.u[kC]));
        Fu_s = l.M[kC] * gr.du, Fn_s = l.K[kC] * gr.dnu, duy = gr.du;
    } else {
        Fu_s = 0.5 * (l.M[kS] + l.M[kC]) * (l.u[kC] - l.u[kS]) / hy;
        Fn_s = 0.5 * (l.K[kS] + l.K[kC]) * (l.nu[kC] - l.nu[kS]) / hy -
               0.5 * (l.Kp[kS] + l.Kp[kC]) * ((l.p[kC] - l.p[kS]) / hy);
    }
    if (top) {  // n = -y^, u^_wall = 0
        const auto gr = at_wall(W::Top, S(-l.u[kC]));
        Fu_n = -(l.M[kC] * gr.du), Fn_n = -(l.K[kC] * gr.dnu), duy = -gr.du;
    } else {
        Fu_n = 0.5 * (l.M[kC] + l.M[kN]) * (l.u[kN] - l.u[kC]) / hy;
        Fn_n = 0.5 * (l.K[kC] + l.K[kN]) * (l.nu[kN] - l.nu[kC]) / hy -
               0.5 * (l.Kp[kC] + l.Kp[kN]) * ((l.p[kN] - l.p[kC]) / hy);
    }
    if (!floor && !top) duy = (l.u[kN] - l.u[kS]) / (2 * hy);
    // z^: the side walls move with the floor
    if (outer) {  // n = +z^
        const auto gr = at_wall(W::Outer, S(1.0 - l.u[kC]));
        Fu_w = l.M[kC] * gr.du, Fn_w = l.K[kC] * gr.dnu, duz = gr.du;
    } else {
        Fu_w = 0.5 * (l.M[kW] + l.M[kC]) * (l.u[kC] - l.u[kW]) / l.hz;
        Fn_w = 0.5 * (l.K[kW] + l.K[kC]) * (l.nu[kC] - l.nu[kW]) / l.hz -
               0.5 * (l.Kp[kW] + l.Kp[kC]) * ((l.p[kC] - l.p[kW]) / l.hz);
    }
    if (inner) {  // n = -z^
        const auto gr = at_wall(W::Inner, S(1.0 - l.u[kC]));
        Fu_e = -(l.M[kC] * gr.du), Fn_e = -(l.K[kC] * gr.dnu), duz = -gr.du;
    } else {
        Fu_e = 0.5 * (l.M[kC] + l.M[kE]) * (l.u[kE] - l.u[kC]) / l.hz;
        Fn_e = 0.5 * (l.K[kC] + l.K[kE]) * (l.nu[kE] - l.nu[kC]) / l.hz -
               0.5 * (l.Kp[kC] + l.Kp[kE]) * ((l.p[kE] - l.p[kC]) / l.hz);
    }
    if (!outer && !inner) duz = (l.u[kE] - l.u[kW]) / (2.0 * l.hz);
    const double wy = (floor || top ? 0.5 : 1.0) * hy;
    const double wzf = outer || inner ? 0.5 : 1.0;
    const S ratio = (wy / wzf) / l.hz;  // CV height over CV width
    const S src = l.Pi * l.M[kC] * (duy * duy + duz * duz) - l.L * l.L * l.C;
    Ru = (Fu_n - Fu_s) + ratio * (Fu_e - Fu_w);
    Rn = (Fn_n - Fn_s) + ratio * (Fn_e - Fn_w) - wy * src;
    if (p.source) {
        double su = 0, sn = 0;
        p.source->volume(g.y, g.z, su, sn);
        Ru = Ru + wy * su;
        Rn = Rn + wy * sn;
    }
}

class Fv2 {
public:
    Fv2(const CrossSectionProblem& p, const CrossSectionSettings& st)
        : p_(p), Ny_(st.cells_y), Nz_(st.cells_z), ny_(Ny_ + 1), nz_(p.periodic ? Nz_ : Nz_ + 1),
          n_(static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_)), hy_(1.0 / Ny_),
          cap_(p.gap.closures->cap()), inventory_(p.gap.mode == Mode::Inventory), nodes_(n_), walls_(n_),
          F_(static_cast<Eigen::Index>(2 * n_)), Fl_(F_.size()), x_(F_.size()), y_(F_.size()) {
        if (p.gap.mode == Mode::Fill) throw SolverError("the cross-section solves a load (Load or Inventory), not a fill");
        if (Ny_ < 2 || Nz_ < (p.periodic ? 3 : 2)) throw SolverError("the cross-section needs at least 2 x 3 cells");
        // Sparsity of the 5-point stencil in 2x2 blocks; each entry's place in the value array kept, so the
        // Newton loop refills the values in place.
        // every (row, column) of the pattern: node k's two residuals against member m's two unknowns, slot 2a + b
        const auto each_entry = [&](const auto& f) {
            for (int j = 0; j < nz_; ++j)
                for (int i = 0; i < ny_; ++i)
                    for (int m = 0; m < kMembers; ++m) {
                        const long nb = member(i, j, m);
                        if (nb < 0) continue;
                        const std::size_t slot = (static_cast<std::size_t>(idx(i, j)) * kMembers + m) * 4;
                        for (int a = 0; a < 2; ++a)
                            for (int b = 0; b < 2; ++b) f(slot + 2 * a + b, 2 * idx(i, j) + a, 2 * nb + b);
                    }
        };
        std::vector<Eigen::Triplet<double>> t;
        t.reserve(n_ * kMembers * 4);
        each_entry([&](std::size_t, long r, long c) { t.emplace_back(r, c, 0.0); });
        J_.resize(static_cast<Eigen::Index>(2 * n_), static_cast<Eigen::Index>(2 * n_));
        J_.setFromTriplets(t.begin(), t.end());
        J_.makeCompressed();
        pos_.assign(n_ * kMembers * 4, -1);
        each_entry([&](std::size_t slot, long r, long c) { pos_[slot] = &J_.coeffRef(r, c) - J_.valuePtr(); });
        lu_.analyzePattern(J_);
    }

    std::size_t nodes() const { return n_; }
    double cap() const { return cap_; }
    bool inventory() const { return inventory_; }
    double Lambda_of(double lam) const { return inventory_ ? std::exp(lam) : p_.gap.Lambda; }
    double nu_of(double s) const { return cap_ / (1.0 + std::exp(-s)); }
    long idx(int i, int j) const { return static_cast<long>(j) * ny_ + i; }
    // Node of stencil member m of (i, j), or -1 where a wall closes the control volume.
    long member(int i, int j, int m) const {
        switch (m) {
            case kC: return idx(i, j);
            case kS: return i > 0 ? idx(i - 1, j) : -1;
            case kN: return i < Ny_ ? idx(i + 1, j) : -1;
            case kW: return j > 0 ? idx(i, j - 1) : (p_.periodic ? idx(i, nz_ - 1) : -1);
            default: return j < nz_ - 1 ? idx(i, j + 1) : (p_.periodic ? idx(i, 0) : -1);
        }
    }
    NodeGeom geom(int i, int j, double hz) const {
        const bool sides = !p_.periodic;
        return {{i == 0, i == Ny_, sides && j == 0, sides && j == Nz_}, i * hy_, j * hz};
    }
    // Weight of node (i, j) in the cross-section mean (sums to 1).
    double weight(int i, int j) const {
        const double wy = (i == 0 || i == Ny_ ? 0.5 : 1.0) / Ny_;
        const double wz = (!p_.periodic && (j == 0 || j == Nz_) ? 0.5 : 1.0) / Nz_;
        return wy * wz;
    }

    // Residual (and Jacobian when `jac`) at x = (u^, s) interleaved per node and lam; the max norm.
    double evaluate(const Eigen::VectorXd& x, double lam, bool jac) {
        const double L = Lambda_of(lam), Pi = p_.gap.Pi;
        const double hz = p_.aspect(L) / Nz_;
        L_ = L;
        for (std::size_t k = 0; k < n_; ++k) {
            const double nu = nu_of(x[static_cast<Eigen::Index>(2 * k + 1)]);
            const double dnu = nu * (1.0 - nu / cap_);
            const auto c = node_coefficients(*p_.gap.closures, nu);
            nodes_[k] = {nu, dnu, c.M, c.dM * dnu, c.K, c.dK * dnu, c.C, c.dC * dnu};
            if (!p_.pressure.empty()) at_pressure(nodes_[k], p_.pressure[k]);
        }
        if (jac) std::fill(J_.valuePtr(), J_.valuePtr() + J_.nonZeros(), 0.0);
        double norm = 0, mean = 0;
        for (int j = 0; j < nz_; ++j)
            for (int i = 0; i < ny_; ++i) {
                const std::size_t k = static_cast<std::size_t>(idx(i, j));
                const NodeGeom g = geom(i, j, hz);
                mean += weight(i, j) * nodes_[k].nu;
                for (int w = 0; w < kCrossSectionWalls; ++w)
                    if (g.wall[w]) walls_[k][w] = wall_val(p_.wall(static_cast<CrossSectionWall>(w)), nodes_[k]);
                double ru, rn;
                if (!jac) {
                    Local<double> l;
                    fill_local(l, i, j, x, Pi, L, hz, g, [](double v, int, double) { return v; });
                    residual(p_, g, l, hy_, ru, rn);
                } else {
                    Local<D> l;
                    fill_local(l, i, j, x, Pi, L, hz, g, [](double v, int slot, double dv) { return D::lifted(v, slot, dv); });
                    l.L = D::lifted(L, kLam, inventory_ ? L : 0.0);
                    l.hz = D::lifted(hz, kLam, inventory_ ? -hz : 0.0);  // A = width/Lambda
                    D dru, drn;
                    residual(p_, g, l, hy_, dru, drn);
                    ru = dru.v, rn = drn.v;
                    double* v = J_.valuePtr();
                    for (int m = 0; m < kMembers; ++m) {
                        const long* ps = &pos_[(k * kMembers + static_cast<std::size_t>(m)) * 4];
                        if (ps[0] < 0) continue;
                        v[ps[0]] += dru.d[2 * m], v[ps[1]] += dru.d[2 * m + 1];
                        v[ps[2]] += drn.d[2 * m], v[ps[3]] += drn.d[2 * m + 1];
                    }
                    Fl_[static_cast<Eigen::Index>(2 * k)] = dru.d[kLam];
                    Fl_[static_cast<Eigen::Index>(2 * k + 1)] = drn.d[kLam];
                }
                F_[static_cast<Eigen::Index>(2 * k)] = ru;
                F_[static_cast<Eigen::Index>(2 * k + 1)] = rn;
                if (!std::isfinite(ru) || !std::isfinite(rn)) return std::numeric_limits<double>::infinity();
                norm = std::max({norm, std::abs(ru), std::abs(rn)});
            }
        mean_ = mean;
        if (inventory_) {
            g_ = L * mean - p_.gap.inventory;
            norm = std::max(norm, std::abs(g_));
        }
        return norm;
    }

    // The rest of detail::damped_newton's interface (damped_newton.h).
    void step_sizes(const Eigen::VectorXd& dx, double& du, double& ds) const {
        for (Eigen::Index k = 0; k < dx.size(); k += 2) du = std::max(du, std::abs(dx[k])), ds = std::max(ds, std::abs(dx[k + 1]));
    }
    void advance(Eigen::VectorXd& out, const Eigen::VectorXd& x, double a, const Eigen::VectorXd& dx) const {
        out = x + a * dx;
    }

    // Newton step for the last evaluate(..., true): dx and dlam. False when the matrix is singular.
    bool step(Eigen::VectorXd& dx, double& dlam) {
        lu_.factorize(J_);
        if (lu_.info() != Eigen::Success) return false;
        x_ = lu_.solve(F_);
        x_ = -x_;
        dlam = 0;
        if (inventory_) {
            // Bordered as the 1-D Inventory (fv_solver.cpp): dx = x1 - dlam x2, r.dx + k dlam = -g.
            y_ = lu_.solve(Fl_);
            double rx1 = 0, rx2 = 0;
            for (int j = 0; j < nz_; ++j)
                for (int i = 0; i < ny_; ++i) {
                    const auto k = static_cast<std::size_t>(idx(i, j));
                    const double r = L_ * weight(i, j) * nodes_[k].dnu;
                    rx1 += r * x_[static_cast<Eigen::Index>(2 * k + 1)];
                    rx2 += r * y_[static_cast<Eigen::Index>(2 * k + 1)];
                }
            const double kk = L_ * mean_;
            if (!(std::abs(rx2 - kk) > 0)) return false;
            dlam = (rx1 + g_) / (rx2 - kk);
            x_ -= dlam * y_;
        }
        dx = x_;
        return true;
    }

    double mean_nu() const { return mean_; }

private:
    // T = p/(rho_p f_p) at the local p^: M -> p^^1/2 M, K and C -> p^^3/2 K, C; K_p = p^^1/2 f_kappa f_p^-3/2.
    void at_pressure(NodeVal& n, double p) const {
        const auto st = p_.gap.closures->state(n.nu);
        const D1 Kp = st.fk * pow(st.fp, -1.5);
        const double a = std::sqrt(p), b = p * a;
        n.M *= a, n.dM *= a, n.K *= b, n.dK *= b, n.C *= b, n.dC *= b;
        n.Kp = a * Kp.v, n.dKp = a * Kp.d[0] * n.dnu, n.p = p;
    }

    WallVal wall_val(const WallBC& w, const NodeVal& n) const {
        const auto b = wall_coefficients(p_.gap, w, n.nu);
        return {{b.b5.v, b.b6.v, b.b7.v, b.b8.v},
                {b.b5.d[0] * n.dnu, b.b6.d[0] * n.dnu, b.b7.d[0] * n.dnu, b.b8.d[0] * n.dnu}};
    }

    template <class S, class Lift>
    void fill_local(Local<S>& l, int i, int j, const Eigen::VectorXd& x, double Pi, double L, double hz,
                    const NodeGeom& g, const Lift& lift) const {
        for (int m = 0; m < kMembers; ++m) {
            const long nb = member(i, j, m);
            if (nb < 0) {
                l.u[m] = l.nu[m] = l.M[m] = l.K[m] = l.Kp[m] = S(0.0);
                l.p[m] = 1.0;
                continue;
            }
            const NodeVal& n = nodes_[static_cast<std::size_t>(nb)];
            l.u[m] = lift(x[2 * nb], 2 * m, 1.0);
            l.nu[m] = lift(n.nu, 2 * m + 1, n.dnu);
            l.M[m] = lift(n.M, 2 * m + 1, n.dM);
            l.K[m] = lift(n.K, 2 * m + 1, n.dK);
            l.Kp[m] = lift(n.Kp, 2 * m + 1, n.dKp);
            l.p[m] = n.p;
        }
        const NodeVal& c = nodes_[static_cast<std::size_t>(idx(i, j))];
        l.C = lift(c.C, 1, c.dC);
        l.Pi = S(Pi), l.L = S(L), l.hz = S(hz);
        for (int w = 0; w < kCrossSectionWalls; ++w)
            if (g.wall[w]) {
                const WallVal& b = walls_[static_cast<std::size_t>(idx(i, j))][w];
                for (int q = 0; q < 4; ++q) l.b[w][q] = lift(b.b[q], 1, b.db[q]);
            }
    }

    const CrossSectionProblem& p_;
    int Ny_, Nz_, ny_, nz_;
    std::size_t n_;
    double hy_, cap_;
    bool inventory_;
    double L_ = 0, mean_ = 0, g_ = 0;
    std::vector<NodeVal> nodes_;
    std::vector<std::array<WallVal, kCrossSectionWalls>> walls_;
    Eigen::VectorXd F_, Fl_, x_, y_;
    Eigen::SparseMatrix<double> J_;
    std::vector<long> pos_;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

Eigen::VectorXd unknowns(const CrossSectionSolution& s, double cap) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(2 * s.u.size()));
    for (std::size_t k = 0; k < s.u.size(); ++k) {
        const double nu = std::clamp(s.nu[k], 1e-9 * cap, (1 - 1e-12) * cap);
        x[static_cast<Eigen::Index>(2 * k)] = s.u[k];
        x[static_cast<Eigen::Index>(2 * k + 1)] = std::log(nu / (cap - nu));
    }
    return x;
}

}  // namespace cross_section_fv

NewtonReport newton_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st,
                                  CrossSectionSolution& sol) {
    using namespace cross_section_fv;
    Fv2 fv(p, st);
    if (sol.u.size() != fv.nodes() || sol.cells_y != st.cells_y || sol.cells_z != st.cells_z)
        throw Error("newton_cross_section: the initial guess is not on the solver's grid");
    Eigen::VectorXd x = unknowns(sol, fv.cap()), dx(x.size()), xt(x.size());
    double lam = std::log(fv.inventory() ? (sol.Lambda > 0 ? sol.Lambda : p.gap.Lambda) : p.gap.Lambda);
    NewtonReport rep = detail::damped_newton(fv, x, lam, dx, xt, st.tolerance, st.max_iterations);
    for (std::size_t k = 0; k < sol.u.size(); ++k) {
        sol.u[k] = x[static_cast<Eigen::Index>(2 * k)];
        sol.nu[k] = fv.nu_of(x[static_cast<Eigen::Index>(2 * k + 1)]);
    }
    sol.Pi = p.gap.Pi;
    sol.Lambda = fv.Lambda_of(lam);
    sol.residual = rep.residual;
    if (rep.converged && fv.mean_nu() < 0.01) {
        rep.converged = false;
        rep.why = "Newton fell onto the empty-channel branch (mean nu < 0.01)";
    }
    return rep;
}

double cross_section_residual(const CrossSectionProblem& p, const CrossSectionSolution& s) {
    using namespace cross_section_fv;
    CrossSectionSettings st;
    st.cells_y = s.cells_y, st.cells_z = s.cells_z;
    Fv2 fv(p, st);
    return fv.evaluate(unknowns(s, fv.cap()), std::log(fv.inventory() ? s.Lambda : p.gap.Lambda), false);
}

namespace cross_section_fv {  // named: the library is a unity build beside fv_solver.cpp

// The 1-D solution of the same gap on the same nodes in y^, the same in every column.
CrossSectionSolution initial_guess(const CrossSectionProblem& p, const CrossSectionSettings& st) {
    SolverSettings s1;
    s1.cells = st.cells_y;
    s1.tolerance = st.tolerance;
    s1.max_iterations = st.max_iterations;
    s1.max_continuation_steps = st.max_continuation_steps;
    const Solution g = solve_fv(p.gap, s1);
    CrossSectionSolution s;
    s.cells_y = st.cells_y, s.cells_z = st.cells_z, s.periodic = p.periodic;
    s.u.resize(static_cast<std::size_t>(s.ny() * s.nz()));
    s.nu.resize(s.u.size());
    for (int j = 0; j < s.nz(); ++j)
        for (int i = 0; i < s.ny(); ++i) {
            s.u[s.at(i, j)] = g.u[static_cast<std::size_t>(i)];
            s.nu[s.at(i, j)] = g.nu[static_cast<std::size_t>(i)];
        }
    s.Pi = g.Pi;
    s.Lambda = g.Lambda;
    return s;
}

// The potential part of the body forces f (cross_section_problem.h) at the solution's u^, nu: in every control
// volume the flux balance of grad p^ - f, (grad p^ - f).n = 0 on the walls, and the mean of p^ over the top wall
// = 1 (the load) in place of one node's balance (the balances sum to zero). Without secondary flow the cross-
// section's y and z momentum balances are grad p^ = f, which has a solution only where curl f = 0; the rest of f
// would drive a secondary flow, which this model leaves out [ASSUMPTION].
std::vector<double> pressure_field(const CrossSectionProblem& p, const CrossSectionSolution& s) {
    const int Ny = s.cells_y, Nz = s.cells_z, ny = s.ny(), nz = s.nz();
    const double L = s.Lambda, Pi = p.gap.Pi, hy = 1.0 / Ny, hz = p.aspect(L) / Nz;
    const auto k = [&](int i, int j) { return static_cast<Eigen::Index>(j) * ny + i; };
    std::vector<double> fy(s.u.size()), fz(s.u.size());
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < ny; ++i) {
            const std::size_t c = s.at(i, j);
            fy[c] = -L * p.body.gravity * s.nu[c];
            const double r = p.body.radius / L - j * hz;  // r/H, the outer wall at z^ = 0
            fz[c] = p.body.radius > 0 ? -Pi * s.nu[c] * s.u[c] * s.u[c] / r : 0.0;
        }
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(s.u.size()));
    const int i_ref = Ny, j_ref = nz / 2;  // the balance replaced by the load
    for (int j = 0; j < nz; ++j)
        for (int i = 0; i < ny; ++i) {
            const Eigen::Index c = k(i, j);
            if (i == i_ref && j == j_ref) continue;
            const double wy = (i == 0 || i == Ny ? 0.5 : 1.0) * hy;
            const double wz = (!p.periodic && (j == 0 || j == Nz) ? 0.5 : 1.0) * hz;
            // face to neighbour nb at distance h, face area a, outward sign sg along the axis, f along the axis
            const auto face = [&](Eigen::Index nb, double h, double a, double sg, const std::vector<double>& f) {
                t.emplace_back(c, nb, a / h);
                t.emplace_back(c, c, -a / h);
                b[c] += sg * a * 0.5 * (f[static_cast<std::size_t>(c)] + f[static_cast<std::size_t>(nb)]);
            };
            if (i < Ny) face(k(i + 1, j), hy, wz, 1.0, fy);
            if (i > 0) face(k(i - 1, j), hy, wz, -1.0, fy);
            if (j < nz - 1 || p.periodic) face(k(i, (j + 1) % nz), hz, wy, 1.0, fz);
            if (j > 0 || p.periodic) face(k(i, (j + nz - 1) % nz), hz, wy, -1.0, fz);
        }
    for (int j = 0; j < nz; ++j) {
        const double w = (!p.periodic && (j == 0 || j == Nz) ? 0.5 : 1.0) / Nz;
        t.emplace_back(k(i_ref, j_ref), k(Ny, j), w);
    }
    b[k(i_ref, j_ref)] = 1.0;
    Eigen::SparseMatrix<double> A(b.size(), b.size());
    A.setFromTriplets(t.begin(), t.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu(A);
    if (lu.info() != Eigen::Success) throw SolverError("cross-section: the pressure field's matrix is singular");
    const Eigen::VectorXd x = lu.solve(b);
    return {x.data(), x.data() + x.size()};
}

std::string describe(const CrossSectionProblem& p) {
    std::ostringstream m;
    m << "Pi = rho U^2/P = " << p.gap.Pi;
    if (p.gap.mode == Mode::Inventory) m << ", grains per length / (d W) = " << p.gap.inventory;
    else m << ", Lambda = H/d = " << p.gap.Lambda;
    return m.str();
}

}  // namespace cross_section_fv

namespace cross_section_fv {

CrossSectionSolution solve_at_uniform_pressure(const CrossSectionProblem& p, const CrossSectionSettings& st) {
    using cross_section_fv::describe;
    int total = 0;
    std::string first_why;
    double first_res = 0;
    try {
        CrossSectionSolution s = initial_guess(p, st);
        const auto rep = newton_cross_section(p, st, s);
        total += rep.iterations;
        if (rep.converged) {
            s.iterations = total;
            return s;
        }
        first_why = rep.why, first_res = rep.residual;
    } catch (const SolverError& e) {
        first_why = e.what();
    }
    // Continuation as the 1-D solver's (fv_solver.cpp): from Lambda <= 5 and Pi in [0.3, 3] to the target.
    CrossSectionProblem start = p;
    if (p.gap.mode != Mode::Inventory) start.gap.Lambda = std::min(p.gap.Lambda, 5.0);
    start.gap.Pi = std::clamp(p.gap.Pi, 0.3, 3.0);
    const auto at = [&](double t) {
        CrossSectionProblem q = p;
        q.gap.Lambda = std::exp((1 - t) * std::log(start.gap.Lambda) + t * std::log(p.gap.Lambda));
        q.gap.Pi = std::exp((1 - t) * std::log(start.gap.Pi) + t * std::log(p.gap.Pi));
        return q;
    };
    CrossSectionSolution s;
    try {
        s = initial_guess(start, st);
    } catch (const SolverError& e) {
        throw SolverError(first_why + "; continuation could not start: " + e.what());
    }
    auto rep = newton_cross_section(start, st, s);
    total += rep.iterations;
    if (!rep.converged) {
        std::ostringstream m;
        m << "cross-section: " << first_why << " (residual " << first_res << "), and continuation could not start at "
          << describe(start) << ": " << rep.why << " (residual " << rep.residual
          << "); try more [continuum] max_iterations or finer cross_section_cells_y/z";
        throw SolverError(m.str());
    }
    const auto c = detail::continuation(
        s, [&](double t, CrossSectionSolution& trial) { return newton_cross_section(at(t), st, trial); },
        st.max_continuation_steps, total);
    if (!c.reached) {
        std::ostringstream m;
        m << "cross-section: " << first_why << " (residual " << first_res << "); continuation stalled at "
          << describe(at(c.t)) << " after " << c.steps - 1 << " steps (" << c.last.why
          << "); try finer cross_section_cells_y/z or a less extreme operating point";
        throw SolverError(m.str());
    }
    s.iterations = total;
    s.continuation_steps = c.steps;
    return s;
}

}  // namespace cross_section_fv

CrossSectionSolution solve_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st) {
    CrossSectionSolution s = cross_section_fv::solve_at_uniform_pressure(p, st);
    if (!p.body.on()) return s;
    // The body forces' pressure from the last (u^, nu), then Newton at that pressure, until p^ settles: the forces
    // move p^ by a few per cent, so the passes contract fast.
    CrossSectionProblem q = p;
    q.pressure.assign(s.u.size(), 1.0);
    for (int pass = 0; pass < 50; ++pass) {
        std::vector<double> pr = cross_section_fv::pressure_field(p, s);
        double change = 0;
        for (std::size_t k = 0; k < pr.size(); ++k) change = std::max(change, std::abs(pr[k] - q.pressure[k]));
        q.pressure.swap(pr);
        const auto rep = newton_cross_section(q, st, s);
        s.iterations += rep.iterations;
        if (!rep.converged)
            throw SolverError("cross-section with the body forces: Newton at the forces' pressure failed: " + rep.why +
                              "; try finer cross_section_cells_y/z or [continuum] body_forces = \"off\"");
        if (change < 1e-10) {
            s.pressure = q.pressure;
            return s;
        }
    }
    throw SolverError("cross-section with the body forces: the pressure field did not settle in 50 passes; try "
                      "[continuum] body_forces = \"off\"");
}

}  // namespace granlub::continuum
