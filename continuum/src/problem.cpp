#include "granlub/continuum/problem.h"

#include "granlub/continuum/walls/wall_condition.h"

#include <algorithm>
#include <cmath>

namespace granlub::continuum {

bool Problem::symmetric() const {
    const auto& a = bottom.params;
    const auto& b = top.params;
    return bottom.family == top.family && a.restitution == b.restitution &&
           a.dissipation_e() == b.dissipation_e() && a.r5 == b.r5 && a.r6 == b.r6 &&
           a.r7 == b.r7 && a.r8 == b.r8 && a.slip_dissipation == b.slip_dissipation && a.energy == b.energy &&
           a.impacts == b.impacts && a.contact_slip_share == b.contact_slip_share;
}

NodeCoefficients node_coefficients(const Closures& c, double nu, double pressure) {
    const auto s = c.state(nu, pressure);
    const D1 M = s.M(), K = s.K(), C = s.C();
    return {M.v, M.d[0], K.v, K.d[0], C.v, C.d[0]};
}

WallCoefficients wall_coefficients(const Problem& p, const WallBC& w, double nu, double pressure) {
    return w.family->coefficients(p.closures->state(nu, pressure), w.params, p.closures->numax());
}

namespace {

// The wall condition's gradients at a wall node, in y^: n = +y^ at the bottom (u^_wall = 1), -y^ at the top
// (u^_wall = 0).
WallGradients<double> wall_y_gradients(const Problem& p, bool top, double u, double nu) {
    const WallBC& w = top ? p.top : p.bottom;
    const auto g = wall_gradients(w.params, wall_coefficients(p, w, nu), top ? -u : 1.0 - u, p.Lambda, p.Pi);
    return top ? WallGradients<double>{-g.du, -g.dnu} : g;
}

}  // namespace

double wall_du(const Problem& p, bool top, double u, double nu) { return wall_y_gradients(p, top, u, nu).du; }

Problem solved_problem(const Problem& p, const Solution& s) {
    Problem q = p;
    q.Pi = s.Pi;
    if (s.Lambda > 0) q.Lambda = s.Lambda;
    q.mode = Mode::Load;
    return q;
}

Observables observe(const Problem& p0, const Solution& s) {
    const Problem p = solved_problem(p0, s);
    Observables o;
    const std::size_t n = s.nodes();
    const double h = 1.0 / static_cast<double>(n - 1);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (i == 0 || i + 1 == n ? 0.5 : 1.0) * s.nu[i];
    o.nu_mean = sum * h;
    // centre by linear interpolation (a node when N is even)
    const double xc = 0.5 * static_cast<double>(n - 1);
    const auto ic = static_cast<std::size_t>(std::floor(xc));
    const double fc = xc - static_cast<double>(ic);
    const std::size_t jc = std::min(ic + 1, n - 1);
    o.nu_centre = (1 - fc) * s.nu[ic] + fc * s.nu[jc];
    o.nu_bottom = s.nu.front();
    o.nu_top = s.nu.back();
    o.nu_max_node = *std::max_element(s.nu.begin(), s.nu.end());
    o.slip_bottom = 1.0 - s.u.front();
    o.slip_top = s.u.back();
    o.du_bottom = wall_du(p, false, s.u.front(), s.nu.front());
    o.du_top = wall_du(p, true, s.u.back(), s.nu.back());
    const double scale = std::sqrt(s.Pi) / p.Lambda;
    const ContactStress& cs = p.closures->contact();  // its shear mu_c pi_c adds to the kinetic one (§2.9)
    const double mu_c = cs.active() ? cs.friction : 0.0;
    o.tau_bottom = scale * node_coefficients(*p.closures, o.nu_bottom).M * std::abs(o.du_bottom);
    o.tau_top = scale * node_coefficients(*p.closures, o.nu_top).M * std::abs(o.du_top);
    if (mu_c > 0) {
        o.tau_bottom += mu_c * cs.ratio(o.nu_bottom) * std::abs(cs.sign(o.du_bottom));
        o.tau_top += mu_c * cs.ratio(o.nu_top) * std::abs(cs.sign(o.du_top));
    }
    const auto T = [&](double nu) { return 1.0 / p.closures->state(nu).fp.v; };
    o.T_bottom = T(o.nu_bottom);
    o.T_top = T(o.nu_top);
    const double Tc0 = T(s.nu[ic]), Tc1 = T(s.nu[jc]);
    o.T_centre = (1 - fc) * Tc0 + fc * Tc1;
    return o;
}

double energy_balance_defect(const Problem& p0, const Solution& s) {
    const Problem p = solved_problem(p0, s);
    const std::size_t n = s.nodes();
    const double h = 1.0 / static_cast<double>(n - 1);
    const double L = p.Lambda, Pi = s.Pi;
    double integral = 0;
    for (std::size_t i = 0; i < n; ++i) {
        double du;
        if (i == 0) du = wall_du(p, false, s.u[0], s.nu[0]);
        else if (i + 1 == n) du = wall_du(p, true, s.u[i], s.nu[i]);
        else du = (s.u[i + 1] - s.u[i - 1]) / (2 * h);
        const auto c = node_coefficients(*p.closures, s.nu[i]);
        const double S = Pi * c.M * du * du - L * L * c.C;
        integral += (i == 0 || i + 1 == n ? 0.5 : 1.0) * h * S;
    }
    // wall gradients nu' from the energy wall conditions
    const auto dnu = [&](bool top) {
        return top ? wall_y_gradients(p, true, s.u.back(), s.nu.back()).dnu
                   : wall_y_gradients(p, false, s.u.front(), s.nu.front()).dnu;
    };
    const double K0 = node_coefficients(*p.closures, s.nu.front()).K;
    const double KN = node_coefficients(*p.closures, s.nu.back()).K;
    return integral - (KN * dnu(true) - K0 * dnu(false));
}

EnergyBudget energy_budget(const Problem& p0, const Solution& s) {
    const Problem p = solved_problem(p0, s);
    const std::size_t n = s.nodes();
    const double h = 1.0 / static_cast<double>(n - 1), L = p.Lambda, Pi = s.Pi;
    // Dimensionless (§5): tau^ = M |u^'| is constant, tau/P = sqrt(Pi) tau^/Lambda; per P U the
    // wall work is tau/P, the energy equation's terms carry the factor sqrt(Pi)/Lambda / Pi.
    const double M0 = node_coefficients(*p.closures, s.nu.front()).M;
    const double tau_hat = M0 * std::abs(wall_du(p, false, s.u.front(), s.nu.front()));
    const double scale = 1.0 / (std::sqrt(Pi) * L);  // energy-equation units -> P U
    EnergyBudget b;
    b.wall_work = std::sqrt(Pi) / L * tau_hat;
    // The contact stress's work (§2.9), dissipated in the contacts: mu_c pi_c u^' sgn_eps(u^') (-> |u^'|) across the
    // gap, summed over the faces as the FV momentum flux has it (face pi_c the node mean, u^' the face difference),
    // and mu_c pi_c |sgn_eps(u^'_w)| |slip| at each wall, per P U.
    const ContactStress& cs = p.closures->contact();
    if (cs.active() && cs.friction > 0) {
        const double mu_c = cs.friction;
        const double du0 = wall_du(p, false, s.u.front(), s.nu.front()), du1 = wall_du(p, true, s.u.back(), s.nu.back());
        b.wall_work += mu_c * cs.ratio(s.nu.front()) * std::abs(cs.sign(du0));
        double bulk = 0;
        for (std::size_t i = 0; i + 1 < n; ++i) {
            const double du = (s.u[i + 1] - s.u[i]) / h;
            bulk += h * 0.5 * (cs.ratio(s.nu[i]) + cs.ratio(s.nu[i + 1])) * du * cs.sign(du);
        }
        b.contact_dissipation = mu_c * (bulk + cs.ratio(s.nu.front()) * std::abs(cs.sign(du0)) * (1.0 - s.u.front()) +
                                        cs.ratio(s.nu.back()) * std::abs(cs.sign(du1)) * s.u.back());
    }
    double bulk = 0;
    for (std::size_t i = 0; i < n; ++i)
        bulk += (i == 0 || i + 1 == n ? 0.5 : 1.0) * h * L * L * node_coefficients(*p.closures, s.nu[i]).C;
    b.bulk_dissipation = scale * bulk;
    for (bool top : {false, true}) {
        const WallBC& w = top ? p.top : p.bottom;
        const double nu = top ? s.nu.back() : s.nu.front();
        const double slip = top ? -s.u.back() : 1.0 - s.u.front();
        const WallCoefficients c = wall_coefficients(p, w, nu);
        const NodeCoefficients k = node_coefficients(*p.closures, nu);
        // the kinetic traction at this wall: uniform without a contact stress, not with one (only the sum is)
        const double tau_w =
            cs.active() ? k.M * std::abs(wall_du(p, top, top ? s.u.back() : s.u.front(), nu)) : tau_hat;
        const double collisional = wall_collisional_sink(w.params, c, k.K, slip, L, Pi);
        const double unreturned = wall_unreturned_slip_work(w.params, slip, Pi, tau_w);
        b.wall_dissipation += scale * (collisional + unreturned);
        b.wall_collisional += scale * collisional;
        b.wall_unreturned_slip_work += scale * unreturned;
    }
    return b;
}

}  // namespace granlub::continuum
