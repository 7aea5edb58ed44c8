// Vertex-centred FV + Newton on the trough's cross-section. See cross_section_solver.h for the method.
#include "granlub/continuum/cross_section_solver.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>

#include "contact_continuation.h"
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

using D = Dual<19>;
// Stencil members: centre, south (i - 1), north (i + 1), west (j - 1), east (j + 1), and the four diagonal
// neighbours (the contact shear's tangential gradients at the faces only; without it they are not in the pattern);
// member m has the unknown slots 2m (u^) and 2m + 1 (s); slot 18 is the bordering unknown ln Lambda.
constexpr int kMembers = 9, kLam = 18;
enum Member { kC = 0, kS = 1, kN = 2, kW = 3, kE = 4, kSW = 5, kSE = 6, kNW = 7, kNE = 8 };

// Node closures with derivatives in the logit unknown s.
struct NodeVal {
    double nu, dnu, M, dM, K, dK, C, dC;
    double Kp = 0, dKp = 0, p = 1;  // with a pressure field: p^^1/2 K_p of the grad-p heat flux, and p^
    double pc = 0, dpc = 0;         // the contact pressure over P_y (docs/continuum-model.md §2.9), 0 without one
};
// A wall's coefficients b5..b8 and xi per slip (WallCoefficients) at a node, with d/ds.
struct WallVal {
    double b[5], db[5];
};

template <class S>
struct Local {
    S u[kMembers], nu[kMembers], M[kMembers], K[kMembers], Kp[kMembers], pc[kMembers];
    double p[kMembers];
    S C, Pi, L, hz;
    S b[kCrossSectionWalls][5];  // the coefficients of the walls the node lies on
    // with the contact shear: members S, N (W, E) on the centre's side wall (floor or top) carry that wall's
    // coefficients, for their z^ (y^) gradient
    S bt[kMembers][5];
};

// Which faces of node (i, j)'s control volume are walls, and where it is.
struct NodeGeom {
    bool wall[kCrossSectionWalls];
    double y, z;
};

// The flux balance of one control volume per unit width (1-D units: the 1-D solver's residual when nothing
// depends on z^). Ru = div(M grad u^ + tau_c), Rn = div(K grad nu) - source, integrated over the CV and divided by
// its z^-width. The contact shear tau_c (closures/contact_stress.h; `cs` null without it) at a face: the faces'
// mean pi_c, the face difference as the normal gradient and the mean of the two nodes' tangential gradients (central
// differences, or a wall condition's gradient on a wall) across it; at a wall face the node's pi_c and gradients.
template <class S>
void residual(const CrossSectionProblem& p, const NodeGeom& g, const Local<S>& l, double hy, const ContactStress* cs,
              S& Ru, S& Rn) {
    using W = CrossSectionWall;
    // the condition of wall w at member m (coefficients b), as the gradient along n into the flow
    const auto at_wall = [&](W w, int m, const S* b) {
        const WallBC& bc = p.wall(w);
        const S slip = w == W::Top ? S(-l.u[m]) : S(1.0 - l.u[m]);  // the top is still, the others move at U
        // the wall condition at the local pressure: Pi = rho U^2 / p (the b's are in P-scaled form)
        auto gr = wall_gradients(bc.params, b[0], b[1], b[2], b[3], b[4], slip, l.L, l.Pi / l.p[m]);
        if (p.source) {
            const double dy = m == kS ? -hy : (m == kN ? hy : 0.0), dz = m == kW ? -value(l.hz) : (m == kE ? value(l.hz) : 0.0);
            double cu = 0, cn = 0;
            p.source->wall(w, g.y + dy, g.z + dz, cu, cn);
            gr.du = gr.du + cu;
            gr.dnu = gr.dnu + cn;
        }
        return gr;
    };
    const bool floor = g.wall[0], top = g.wall[1], outer = g.wall[2], inner = g.wall[3];
    // y^: fluxes M du/dy on the south and north faces, and du/dy at the node
    S Fu_s, Fu_n, Fn_s, Fn_n, Fu_w, Fu_e, Fn_w, Fn_e, duy(0.0), duz(0.0);
    if (floor) {  // n = +y^, u^_wall = 1
        const auto gr = at_wall(W::Floor, kC, l.b[0]);
        Fu_s = l.M[kC] * gr.du, Fn_s = l.K[kC] * gr.dnu, duy = gr.du;
    } else {
        Fu_s = 0.5 * (l.M[kS] + l.M[kC]) * (l.u[kC] - l.u[kS]) / hy;
        Fn_s = 0.5 * (l.K[kS] + l.K[kC]) * (l.nu[kC] - l.nu[kS]) / hy -
               0.5 * (l.Kp[kS] + l.Kp[kC]) * ((l.p[kC] - l.p[kS]) / hy);
    }
    if (top) {  // n = -y^, u^_wall = 0
        const auto gr = at_wall(W::Top, kC, l.b[1]);
        Fu_n = -(l.M[kC] * gr.du), Fn_n = -(l.K[kC] * gr.dnu), duy = -gr.du;
    } else {
        Fu_n = 0.5 * (l.M[kC] + l.M[kN]) * (l.u[kN] - l.u[kC]) / hy;
        Fn_n = 0.5 * (l.K[kC] + l.K[kN]) * (l.nu[kN] - l.nu[kC]) / hy -
               0.5 * (l.Kp[kC] + l.Kp[kN]) * ((l.p[kN] - l.p[kC]) / hy);
    }
    if (!floor && !top) duy = (l.u[kN] - l.u[kS]) / (2 * hy);
    // z^: the side walls move with the floor
    if (outer) {  // n = +z^
        const auto gr = at_wall(W::Outer, kC, l.b[2]);
        Fu_w = l.M[kC] * gr.du, Fn_w = l.K[kC] * gr.dnu, duz = gr.du;
    } else {
        Fu_w = 0.5 * (l.M[kW] + l.M[kC]) * (l.u[kC] - l.u[kW]) / l.hz;
        Fn_w = 0.5 * (l.K[kW] + l.K[kC]) * (l.nu[kC] - l.nu[kW]) / l.hz -
               0.5 * (l.Kp[kW] + l.Kp[kC]) * ((l.p[kC] - l.p[kW]) / l.hz);
    }
    if (inner) {  // n = -z^
        const auto gr = at_wall(W::Inner, kC, l.b[3]);
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
    S src = l.Pi * l.M[kC] * (duy * duy + duz * duz) - l.L * l.L * l.C;  // shear work - collisional dissipation
    if (cs) {
        // The contact shear's fluxes. Tangential gradients at the neighbours: du/dz at S and N (on the centre's
        // side wall if it has one, else central over their diagonal neighbours), du/dy at W and E (likewise).
        const auto dz_at = [&](int m, int mw, int me) {
            if (outer) return S(at_wall(W::Outer, m, l.bt[m]).du);
            if (inner) return S(-at_wall(W::Inner, m, l.bt[m]).du);
            return S((l.u[me] - l.u[mw]) / (2.0 * l.hz));
        };
        const auto dy_at = [&](int m, int ms, int mn) {
            if (floor) return S(at_wall(W::Floor, m, l.bt[m]).du);
            if (top) return S(-at_wall(W::Top, m, l.bt[m]).du);
            return S((l.u[mn] - l.u[ms]) / (2 * hy));
        };
        const S k = cs->scale(l.L, l.Pi);
        if (floor) Fu_s = Fu_s + k * cs->wall_flux(l.pc[kC], duy, duz);
        else Fu_s = Fu_s + k * cs->face_flux(l.pc[kS], l.pc[kC], S((l.u[kC] - l.u[kS]) / hy), S(0.5 * (dz_at(kS, kSW, kSE) + duz)));
        if (top) Fu_n = Fu_n + k * cs->wall_flux(l.pc[kC], duy, duz);
        else Fu_n = Fu_n + k * cs->face_flux(l.pc[kC], l.pc[kN], S((l.u[kN] - l.u[kC]) / hy), S(0.5 * (duz + dz_at(kN, kNW, kNE))));
        if (outer) Fu_w = Fu_w + k * cs->wall_flux(l.pc[kC], duz, duy);
        else Fu_w = Fu_w + k * cs->face_flux(l.pc[kW], l.pc[kC], S((l.u[kC] - l.u[kW]) / l.hz), S(0.5 * (dy_at(kW, kSW, kNW) + duy)));
        if (inner) Fu_e = Fu_e + k * cs->wall_flux(l.pc[kC], duz, duy);
        else Fu_e = Fu_e + k * cs->face_flux(l.pc[kC], l.pc[kE], S((l.u[kE] - l.u[kC]) / l.hz), S(0.5 * (duy + dy_at(kE, kSE, kNE))));
        // The kinetic shear work as the 1-D solver has it with the branch (fv_solver.cpp): the mean of the faces'
        // M u^'^2 along each axis (a wall's gradient on a wall face), the discrete counterpart of the momentum flux.
        const auto face_work = [](const S& Ma, const S& Mb, const S& du) { return 0.5 * (Ma + Mb) * du * du; };
        const S wy_work = floor || top ? S(l.M[kC] * duy * duy)
                                       : S(0.5 * (face_work(l.M[kC], l.M[kN], S((l.u[kN] - l.u[kC]) / hy)) +
                                                  face_work(l.M[kS], l.M[kC], S((l.u[kC] - l.u[kS]) / hy))));
        const S wz_work = outer || inner ? S(l.M[kC] * duz * duz)
                                         : S(0.5 * (face_work(l.M[kC], l.M[kE], S((l.u[kE] - l.u[kC]) / l.hz)) +
                                                    face_work(l.M[kW], l.M[kC], S((l.u[kC] - l.u[kW]) / l.hz))));
        src = l.Pi * (wy_work + wz_work) - l.L * l.L * l.C;
    }
    Ru = (Fu_n - Fu_s) + ratio * (Fu_e - Fu_w);
    Rn = (Fn_n - Fn_s) + ratio * (Fn_e - Fn_w) - wy * src;
    if (p.source) {
        double su = 0, sn = 0;
        p.source->volume(g.y, g.z, su, sn);
        Ru = Ru + wy * su;
        Rn = Rn + wy * sn;
    }
}

// The logit's cap nu < cap per node (n nodes): the closures' (Closures::cap), at the node's p^ with a pressure field
// (with a contact stress the root nu_P of p_c(nu_P) = p there, §2.9a; without one g0's, the same at every node).
std::vector<double> node_caps(const CrossSectionProblem& p, std::size_t n) {
    if (p.pressure.empty()) return std::vector<double>(n, p.gap.closures->cap());
    std::vector<double> c(n);
    for (std::size_t k = 0; k < n; ++k) c[k] = p.gap.closures->cap(p.pressure[k]);
    return c;
}

class Fv2 {
public:
    Fv2(const CrossSectionProblem& p, const CrossSectionSettings& st)
        : p_(p), Ny_(st.cells_y), Nz_(st.cells_z), ny_(Ny_ + 1), nz_(p.periodic ? Nz_ : Nz_ + 1),
          n_(static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_)), hy_(1.0 / Ny_),
          caps_(node_caps(p, n_)), inventory_(p.gap.mode == Mode::Inventory),
          contact_(p.gap.closures->contact().active() && p.gap.closures->contact().friction > 0
                       ? &p.gap.closures->contact() : nullptr),
          nodes_(n_), walls_(n_),
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
    const std::vector<double>& caps() const { return caps_; }
    bool inventory() const { return inventory_; }
    double Lambda_of(double lam) const { return inventory_ ? std::exp(lam) : p_.gap.Lambda; }
    double nu_of(std::size_t k, double s) const { return caps_[k] / (1.0 + std::exp(-s)); }
    long idx(int i, int j) const { return static_cast<long>(j) * ny_ + i; }
    // Node of stencil member m of (i, j), or -1 where a wall closes the control volume.
    long member(int i, int j, int m) const {
        switch (m) {
            case kC: return idx(i, j);
            case kS: return i > 0 ? idx(i - 1, j) : -1;
            case kN: return i < Ny_ ? idx(i + 1, j) : -1;
            case kW: return j > 0 ? idx(i, j - 1) : (p_.periodic ? idx(i, nz_ - 1) : -1);
            case kE: return j < nz_ - 1 ? idx(i, j + 1) : (p_.periodic ? idx(i, 0) : -1);
            default: {  // the diagonals: with the contact shear only
                if (!contact_) return -1;
                const int di = m == kSW || m == kSE ? -1 : 1, dj = m == kSW || m == kNW ? -1 : 1;
                const int a = i + di, b = j + dj;
                if (a < 0 || a > Ny_) return -1;
                if (b >= 0 && b < nz_) return idx(a, b);
                return p_.periodic ? idx(a, (b + nz_) % nz_) : -1;
            }
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
        jac = jac && !chord_;
        // a chord step's line search has evaluated its accepted point already
        if (!jac && last_ok_ && lam == last_lam_ && x == last_x_) return last_norm_;
        last_ok_ = false;
        const double norm = evaluate_at(x, lam, jac);
        if (!jac) last_x_ = x, last_lam_ = lam, last_norm_ = norm, last_ok_ = true;
        return norm;
    }
    double evaluate_at(const Eigen::VectorXd& x, double lam, bool jac) {
        const double L = Lambda_of(lam), Pi = p_.gap.Pi;
        const double hz = p_.aspect(L) / Nz_;
        L_ = L;
        for (std::size_t k = 0; k < n_; ++k) {
            const double nu = nu_of(k, x[static_cast<Eigen::Index>(2 * k + 1)]);
            const double dnu = nu * (1.0 - nu / caps_[k]);
            const double pk = p_.pressure.empty() ? 1.0 : p_.pressure[k];
            const auto c = node_coefficients(*p_.gap.closures, nu, pk);
            nodes_[k] = {nu, dnu, c.M, c.dM * dnu, c.K, c.dK * dnu, c.C, c.dC * dnu};
            if (!p_.pressure.empty()) at_pressure(nodes_[k], pk);
            // the contact shear's p_c over P_y (not over the local p: the momentum equation is in units of P_y)
            const ContactStress& cs = p_.gap.closures->contact();
            nodes_[k].pc = cs.ratio(nu), nodes_[k].dpc = cs.dratio(nu) * dnu;
        }
        // the walls' coefficients first: with the contact shear a node's stencil reads its neighbours' too
        for (int j = 0; j < nz_; ++j)
            for (int i = 0; i < ny_; ++i) {
                const std::size_t k = static_cast<std::size_t>(idx(i, j));
                const NodeGeom g = geom(i, j, hz);
                for (int w = 0; w < kCrossSectionWalls; ++w)
                    if (g.wall[w]) walls_[k][w] = wall_val(p_.wall(static_cast<CrossSectionWall>(w)), nodes_[k]);
            }
        if (jac) std::fill(J_.valuePtr(), J_.valuePtr() + J_.nonZeros(), 0.0);
        double norm = 0, mean = 0;
        for (int j = 0; j < nz_; ++j)
            for (int i = 0; i < ny_; ++i) {
                const std::size_t k = static_cast<std::size_t>(idx(i, j));
                const NodeGeom g = geom(i, j, hz);
                mean += weight(i, j) * nodes_[k].nu;
                double ru, rn;
                if (!jac) {
                    Local<double> l;
                    fill_local(l, i, j, x, Pi, L, hz, g, [](double v, int, double) { return v; });
                    residual(p_, g, l, hy_, contact_, ru, rn);
                } else {
                    Local<D> l;
                    fill_local(l, i, j, x, Pi, L, hz, g, [](double v, int slot, double dv) { return D::lifted(v, slot, dv); });
                    l.L = D::lifted(L, kLam, inventory_ ? L : 0.0);
                    l.hz = D::lifted(hz, kLam, inventory_ ? -hz : 0.0);  // A = width/Lambda
                    D dru, drn;
                    residual(p_, g, l, hy_, contact_, dru, drn);
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
        if (!chord_) lu_.factorize(J_);
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

    // The problem's pressure field changed (a Picard pass): the caps follow.
    void pressure_changed() { caps_ = node_caps(p_, n_), last_ok_ = false; }
    // Chord steps: the last factorised Jacobian (and bordering column) for every step, none evaluated (a Picard pass
    // after the first, where the pressure has moved little). Only after a step without them.
    void set_chord(bool on) { chord_ = on; }

    // The largest difference between the exact Jacobian at x and central differences of the residual with steps
    // `step`, relative to max(1, |entry|) (Load mode; tests, as fv_jacobian_defect).
    double jacobian_defect(const Eigen::VectorXd& x, double lam, double step) {
        evaluate(x, lam, true);
        const Eigen::MatrixXd J = Eigen::MatrixXd(J_);
        double worst = 0;
        for (Eigen::Index c = 0; c < x.size(); ++c) {
            Eigen::VectorXd xp = x, xm = x;
            xp[c] += step, xm[c] -= step;
            evaluate(xp, lam, false);
            const Eigen::VectorXd Fp = F_;
            evaluate(xm, lam, false);
            for (Eigen::Index r = 0; r < x.size(); ++r) {
                const double fd = (Fp[r] - F_[r]) / (2 * step), ex = J(r, c);
                worst = std::max(worst, std::abs(fd - ex) / std::max(1.0, std::abs(ex)));
            }
        }
        return worst;
    }

private:
    // T = p/(rho_p f_p) at the local p^: M -> p^^1/2 M, K and C -> p^^3/2 K, C; K_p = p^^1/2 f_kappa f_p^-3/2.
    // With a contact stress (§2.9a) T = (p - p_c)/(rho_p f_p) = p/(rho_p f~_p), f~_p = f_p/(1 - p_c/p) at the local p:
    // M, K, C are the closures' at p^ (node_coefficients), and the grad-p part of -kappa grad T has the kinetic
    // f_p, K_p = f_kappa f~_p^-1/2 / f_p (f_p = f~_p without one).
    void at_pressure(NodeVal& n, double p) const {
        const auto st = p_.gap.closures->state(n.nu, p);
        const D1 Kp = p_.gap.closures->contact().active() ? st.fk / (sqrt(st.fp) * st.fpk) : st.fk * pow(st.fp, -1.5);
        const double a = std::sqrt(p), b = p * a;
        n.M *= a, n.dM *= a, n.K *= b, n.dK *= b, n.C *= b, n.dC *= b;
        n.Kp = a * Kp.v, n.dKp = a * Kp.d[0] * n.dnu, n.p = p;
    }

    WallVal wall_val(const WallBC& w, const NodeVal& n) const {
        const auto b = wall_coefficients(p_.gap, w, n.nu, n.p);
        return {{b.b5.v, b.b6.v, b.b7.v, b.b8.v, b.xi_per_slip.v},
                {b.b5.d[0] * n.dnu, b.b6.d[0] * n.dnu, b.b7.d[0] * n.dnu, b.b8.d[0] * n.dnu,
                 b.xi_per_slip.d[0] * n.dnu}};
    }

    template <class S, class Lift>
    void fill_local(Local<S>& l, int i, int j, const Eigen::VectorXd& x, double Pi, double L, double hz,
                    const NodeGeom& g, const Lift& lift) const {
        for (int m = 0; m < kMembers; ++m) {
            const long nb = member(i, j, m);
            if (nb < 0) {
                l.u[m] = l.nu[m] = l.M[m] = l.K[m] = l.Kp[m] = l.pc[m] = S(0.0);
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
            l.pc[m] = lift(n.pc, 2 * m + 1, n.dpc);
        }
        const NodeVal& c = nodes_[static_cast<std::size_t>(idx(i, j))];
        l.C = lift(c.C, 1, c.dC);
        l.Pi = S(Pi), l.L = S(L), l.hz = S(hz);
        for (int w = 0; w < kCrossSectionWalls; ++w)
            if (g.wall[w]) {
                const WallVal& b = walls_[static_cast<std::size_t>(idx(i, j))][w];
                for (int q = 0; q < 5; ++q) l.b[w][q] = lift(b.b[q], 1, b.db[q]);
            }
        if (!contact_) return;
        // the tangential gradients' walls: S and N on the centre's side wall, W and E on its floor or top
        const auto tangential = [&](int m, int w) {
            const long nb = member(i, j, m);
            if (nb < 0) return;
            const WallVal& b = walls_[static_cast<std::size_t>(nb)][w];
            for (int q = 0; q < 5; ++q) l.bt[m][q] = lift(b.b[q], 2 * m + 1, b.db[q]);
        };
        for (int w : {2, 3})
            if (g.wall[w]) tangential(kS, w), tangential(kN, w);
        for (int w : {0, 1})
            if (g.wall[w]) tangential(kW, w), tangential(kE, w);
    }

    const CrossSectionProblem& p_;
    int Ny_, Nz_, ny_, nz_;
    std::size_t n_;
    double hy_;
    std::vector<double> caps_;  // the logit's cap per node: uniform but with a contact stress under body forces
    bool inventory_;
    const ContactStress* contact_;  // its shear (§2.9); nullptr without one or with mu_c = 0
    bool chord_ = false;
    Eigen::VectorXd last_x_;  // the last residual-only evaluation (its F_, nodes_ and norm are current)
    double last_lam_ = 0, last_norm_ = 0;
    bool last_ok_ = false;
    double L_ = 0, mean_ = 0, g_ = 0;
    std::vector<NodeVal> nodes_;
    std::vector<std::array<WallVal, kCrossSectionWalls>> walls_;
    Eigen::VectorXd F_, Fl_, x_, y_;
    Eigen::SparseMatrix<double> J_;
    std::vector<long> pos_;
    Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu_;
};

Eigen::VectorXd unknowns(const CrossSectionSolution& s, const std::vector<double>& caps) {
    Eigen::VectorXd x(static_cast<Eigen::Index>(2 * s.u.size()));
    for (std::size_t k = 0; k < s.u.size(); ++k) {
        const double cap = caps[k];
        const double nu = std::clamp(s.nu[k], 1e-9 * cap, (1 - 1e-12) * cap);
        x[static_cast<Eigen::Index>(2 * k)] = s.u[k];
        x[static_cast<Eigen::Index>(2 * k + 1)] = std::log(nu / (cap - nu));
    }
    return x;
}

}  // namespace cross_section_fv

namespace cross_section_fv {

// Newton with `fv` (on the problem p) from sol; sol holds the last iterate.
NewtonReport newton_with(Fv2& fv, const CrossSectionProblem& p, const CrossSectionSettings& st,
                         CrossSectionSolution& sol) {
    if (sol.u.size() != fv.nodes() || sol.cells_y != st.cells_y || sol.cells_z != st.cells_z)
        throw Error("newton_cross_section: the initial guess is not on the solver's grid");
    Eigen::VectorXd x = unknowns(sol, fv.caps()), dx(x.size()), xt(x.size());
    double lam = std::log(fv.inventory() ? (sol.Lambda > 0 ? sol.Lambda : p.gap.Lambda) : p.gap.Lambda);
    NewtonReport rep = detail::damped_newton(fv, x, lam, dx, xt, st.tolerance, st.max_iterations);
    for (std::size_t k = 0; k < sol.u.size(); ++k) {
        sol.u[k] = x[static_cast<Eigen::Index>(2 * k)];
        sol.nu[k] = fv.nu_of(k, x[static_cast<Eigen::Index>(2 * k + 1)]);
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

}  // namespace cross_section_fv

NewtonReport newton_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st,
                                  CrossSectionSolution& sol) {
    cross_section_fv::Fv2 fv(p, st);
    return cross_section_fv::newton_with(fv, p, st, sol);
}

namespace cross_section_fv {

// The problem at the solution's pressure field (body forces) unless the problem has its own.
CrossSectionProblem at_solution_pressure(const CrossSectionProblem& p, const CrossSectionSolution& s) {
    CrossSectionProblem q = p;
    if (q.pressure.empty()) q.pressure = s.pressure;
    return q;
}

}  // namespace cross_section_fv

double cross_section_jacobian_defect(const CrossSectionProblem& p0, const CrossSectionSolution& s, double step) {
    using namespace cross_section_fv;
    if (p0.gap.mode != Mode::Load) throw Error("cross_section_jacobian_defect: Load mode only");
    const CrossSectionProblem p = at_solution_pressure(p0, s);
    CrossSectionSettings st;
    st.cells_y = s.cells_y, st.cells_z = s.cells_z;
    Fv2 fv(p, st);
    return fv.jacobian_defect(unknowns(s, fv.caps()), std::log(p.gap.Lambda), step);
}

double cross_section_residual(const CrossSectionProblem& p0, const CrossSectionSolution& s) {
    using namespace cross_section_fv;
    const CrossSectionProblem p = at_solution_pressure(p0, s);
    CrossSectionSettings st;
    st.cells_y = s.cells_y, st.cells_z = s.cells_z;
    Fv2 fv(p, st);
    return fv.evaluate(unknowns(s, fv.caps()), std::log(fv.inventory() ? s.Lambda : p.gap.Lambda), false);
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
// would drive a secondary flow, which this model leaves out [ASSUMPTION]. p is the whole normal stress, p_KT + p_c
// with a contact stress (§2.9a: its pressure isotropic as the kinetic one [ASSUMPTION: as OpenFOAM's frictional
// pressure]), so the field is the same with or without one.
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

namespace cross_section_fv {

// With the contact stress (§2.9): the 1-D solver's two continuations (contact_continuation.h), from the kinetic
// solution. On a bed near nu_P the moving side walls loosen the bed beside them and push the rest onto the cap,
// where T = 0 and the conduction and kinetic shear vanish, and Newton stalls there: measured on the rough trough at
// 2250 Pa with Johnson & Jackson's constants (bench_continuum's BM_cross_section_point_contact), Newton from the 1-D
// solution with the whole branch and the kinetic solve at the full contact pressure both stall, and the pressure's
// continuation with the 1-D's start 1e-6 below the cap needs 330 iterations. So: no direct attempts, a start sits
// 2 % of nu_P - nu_min below the cap (pi_c ~ 0.85 there), and the first step is half the way (the whole way stalls
// there); and a step is "hard" (halving the next) above 25 iterations, not 12: with the contact shear the cross-section's
// Newton needs 15-18 iterations however short the step (the illustrative constants' wide cross-section at 1 m/s, where
// halving after each converged step never reached mu_c) [ASSUMPTION: numerical choices, measured].
CrossSectionSolution solve_with_contact(const CrossSectionProblem& p, const CrossSectionSettings& st) {
    const ContactStress& cs = p.gap.closures->contact();
    return detail::contact_continuation<CrossSectionSolution>(
        cs,
        [&](double coefficient, double friction) {
            CrossSectionProblem q = p;
            q.gap.closures = detail::scaled_contact(*p.gap.closures, cs, coefficient, friction);
            return q;
        },
        [&](const CrossSectionProblem& q) { return solve_at_uniform_pressure(q, st); },
        [&](const CrossSectionProblem& q, CrossSectionSolution& trial) { return newton_cross_section(q, st, trial); },
        [](const CrossSectionProblem& q) { return q.gap.closures->cap(); }, st.max_continuation_steps,
        "cross-section at " + describe(p), detail::ContactPath{false, 0.5, 25, 1e-6, 0.02});
}

}  // namespace cross_section_fv

CrossSectionSolution solve_cross_section(const CrossSectionProblem& p, const CrossSectionSettings& st) {
    using namespace cross_section_fv;
    CrossSectionSolution s = p.gap.closures->contact().active() ? cross_section_fv::solve_with_contact(p, st)
                                                                : cross_section_fv::solve_at_uniform_pressure(p, st);
    if (!p.body.on()) return s;
    // The body forces' pressure from the last (u^, nu), then Newton at that pressure, until p^ settles: the forces
    // move p^ by a few per cent, so the passes contract fast. Newton takes chord steps (the last factorised Jacobian,
    // after two full steps in the first pass), full ones where those fail: the passes' p^ differ little, and the
    // factorisation is most of a step's cost [numerical choice, measured on bench_continuum's contact point with
    // body forces: 1.1 s of Picard passes with full steps, 0.3 s with these]. With a contact stress the cap nu_P moves
    // with p^ at each node; nu keeps its place between 0 and the cap (the logit unknown) from one pass to the next
    // [ASSUMPTION: numerical; a node over its new cap would have T = 0].
    CrossSectionProblem q = p;
    q.pressure.assign(s.u.size(), 1.0);
    Fv2 fv(q, st);
    for (int pass = 0; pass < 50; ++pass) {
        std::vector<double> pr = pressure_field(p, s);
        double change = 0;
        for (std::size_t k = 0; k < pr.size(); ++k) change = std::max(change, std::abs(pr[k] - q.pressure[k]));
        if (pass > 0 && change < 1e-10) {  // s solves the field it gives
            s.pressure = q.pressure;
            return s;
        }
        const std::vector<double> was = fv.caps();
        q.pressure.swap(pr);
        fv.pressure_changed();
        for (std::size_t k = 0; k < was.size(); ++k)
            if (fv.caps()[k] != was[k]) s.nu[k] *= fv.caps()[k] / was[k];
        CrossSectionSolution from = s;
        if (pass == 0) {  // one full step for a Jacobian at this pressure
            CrossSectionSettings one = st;
            one.max_iterations = 2;
            const auto first = newton_with(fv, q, one, s);
            s.iterations += first.iterations;
        }
        fv.set_chord(true);
        auto rep = newton_with(fv, q, st, s);
        if (!rep.converged) {
            s.iterations += rep.iterations;
            s = from;
            fv.set_chord(false);
            rep = newton_with(fv, q, st, s);
        }
        s.iterations += rep.iterations;
        if (!rep.converged)
            throw SolverError("cross-section with the body forces: Newton at the forces' pressure failed: " + rep.why +
                              "; try finer cross_section_cells_y/z or [continuum] body_forces = \"off\"");
    }
    throw SolverError("cross-section with the body forces: the pressure field did not settle in 50 passes; try "
                      "[continuum] body_forces = \"off\"");
}

}  // namespace granlub::continuum
