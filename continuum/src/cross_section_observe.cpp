// The cross-section's outputs per wall and its budgets (cross_section_problem.h).
#include <algorithm>
#include <cmath>

#include "granlub/continuum/cross_section_problem.h"
#include "granlub/continuum/walls/wall_condition.h"

namespace granlub::continuum {

CrossSectionObservables observe(const CrossSectionProblem& p0, const CrossSectionSolution& s) {
    const Problem p = [&] {
        Problem q = p0.gap;
        q.Lambda = s.Lambda > 0 ? s.Lambda : q.Lambda;
        q.Pi = s.Pi;
        return q;
    }();
    const double L = p.Lambda, Pi = p.Pi, A = p0.aspect(L);
    const int Ny = s.cells_y, Nz = s.cells_z;
    const double hy = 1.0 / Ny, hz = A / Nz;
    const double stress = std::sqrt(Pi) / L;  // tau/P = stress x M |du/dn|
    const double energy = 1.0 / (std::sqrt(Pi) * L);  // energy-equation units -> P U (docs/continuum-model.md §8.5)
    CrossSectionObservables o;
    const auto wy = [&](int i) { return (i == 0 || i == Ny ? 0.5 : 1.0) * hy; };
    const auto wz = [&](int j) { return (!s.periodic && (j == 0 || j == Nz) ? 0.5 : 1.0) * hz; };
    // p^ at a node (1 without body forces); T = p/(rho_p f_p) scales M by p^^1/2, K and C by p^^3/2 (and with a
    // contact stress the closures see pi_c = p_c/p there, §2.9a)
    const auto pr = [&](std::size_t k) { return s.pressure.empty() ? 1.0 : s.pressure[k]; };
    double bulk = 0, mean = 0;
    for (int j = 0; j < s.nz(); ++j)
        for (int i = 0; i < s.ny(); ++i) {
            const double nu = s.nu[s.at(i, j)];
            mean += wy(i) * wz(j) * nu;
            const double pk = pr(s.at(i, j));
            bulk += wy(i) * wz(j) * L * L * std::pow(pk, 1.5) * node_coefficients(*p.closures, nu, pk).C;
            o.nu_max_node = std::max(o.nu_max_node, nu);
        }
    o.nu_mean = mean / A;
    o.bulk_dissipation = energy * bulk;
    // The contact shear (docs/continuum-model.md §2.9; 0 without it), as the solver's fluxes have it
    // (cross_section_solver.cpp): tau_c/P = mu_c pi_c x the regularised direction (closures/contact_stress.h), with
    // the nodes' gradients from the wall conditions on the walls and central differences elsewhere.
    const ContactStress& cs = p.closures->contact();
    const bool contact = cs.active() && cs.friction > 0;
    using W = CrossSectionWall;
    const auto wall_dn = [&](W w, std::size_t k) {  // du/dn into the flow from wall w's condition at node k
        const WallBC& bc = p0.wall(w);
        return wall_gradients(bc.params, wall_coefficients(p, bc, s.nu[k], pr(k)), (w == W::Top ? 0.0 : 1.0) - s.u[k],
                              L, Pi / pr(k)).du;
    };
    const auto du_dz = [&](int i, int j) {
        if (!s.periodic && j == 0) return wall_dn(W::Outer, s.at(i, 0));
        if (!s.periodic && j == Nz) return -wall_dn(W::Inner, s.at(i, Nz));
        const int jm = (j + s.nz() - 1) % s.nz(), jp = (j + 1) % s.nz();
        return (s.u[s.at(i, jp)] - s.u[s.at(i, jm)]) / (2 * hz);
    };
    const auto du_dy = [&](int i, int j) {
        if (i == 0) return wall_dn(W::Floor, s.at(0, j));
        if (i == Ny) return -wall_dn(W::Top, s.at(Ny, j));
        return (s.u[s.at(i + 1, j)] - s.u[s.at(i - 1, j)]) / (2 * hy);
    };
    if (contact) {  // its work in the bulk, face by face: face length x tau_c x the jump of u^
        double faces = 0;
        for (int j = 0; j < s.nz(); ++j)
            for (int i = 0; i < s.ny(); ++i) {
                const std::size_t k = s.at(i, j);
                const double pc = cs.ratio(s.nu[k]);
                if (i < Ny) {
                    const std::size_t n = s.at(i + 1, j);
                    const double du = s.u[n] - s.u[k];
                    faces += wz(j) * cs.face_flux(pc, cs.ratio(s.nu[n]), du / hy, 0.5 * (du_dz(i, j) + du_dz(i + 1, j))) * du;
                }
                if (j < Nz || s.periodic) {
                    const int je = (j + 1) % s.nz();
                    const std::size_t e = s.at(i, je);
                    const double du = s.u[e] - s.u[k];
                    faces += wy(i) * cs.face_flux(pc, cs.ratio(s.nu[e]), du / hz, 0.5 * (du_dy(i, j) + du_dy(i, je))) * du;
                }
            }
        o.contact_dissipation = cs.friction * faces;
    }
    // One wall: its nodes, the wall's speed and the length each node stands for.
    const auto wall = [&](CrossSectionWall w) {
        CrossSectionWallOutput r;
        r.present = true;
        const WallBC& bc = p0.wall(w);
        const bool along_z = w == CrossSectionWall::Floor || w == CrossSectionWall::Top;
        const double u_wall = w == CrossSectionWall::Top ? 0.0 : 1.0;
        const int n = along_z ? s.nz() : s.ny();
        double length = 0, normal = 0;
        for (int k = 0; k < n; ++k) {
            const int i = along_z ? (w == CrossSectionWall::Floor ? 0 : Ny) : k;
            const int j = along_z ? k : (w == CrossSectionWall::Outer ? 0 : Nz);
            const double u = s.u[s.at(i, j)], nu = s.nu[s.at(i, j)], pw = pr(s.at(i, j));
            const double ds = along_z ? wz(j) : wy(i);
            const double slip = u_wall - u;
            const auto g = wall_gradients(bc.params, wall_coefficients(p, bc, nu, pw), slip, L, Pi / pw);
            const auto c0 = node_coefficients(*p.closures, nu, pw);
            const double M = std::sqrt(pw) * c0.M, K = std::pow(pw, 1.5) * c0.K;
            double traction = -stress * M * g.du;  // on the flow along x, tau/P: + forward
            if (contact) {  // the wall's contact traction; its slip work is dissipated in the contacts
                const double tangential = along_z ? du_dz(i, j) : du_dy(i, j);
                const double tc = -cs.friction * cs.wall_flux(cs.ratio(nu), g.du, tangential);
                traction += tc;
                o.contact_dissipation += ds * tc * slip;
            }
            r.force += ds * traction;
            r.slip += ds * std::abs(slip);
            r.work += ds * traction * u_wall;
            // what the wall takes from the fluctuation energy: the slip work it does minus the flux K dnu/dn it
            // returns to the flow (the condition's own split; docs/continuum-model.md §8.5)
            r.sink += ds * energy * (Pi * M * std::abs(g.du) * std::abs(slip) - K * g.dnu);
            normal += ds * pw;
            length += ds;
        }
        r.tau = std::abs(r.force) / length;
        r.slip /= length;
        r.normal = normal / length;
        return r;
    };
    o.walls[0] = wall(CrossSectionWall::Floor);
    o.walls[1] = wall(CrossSectionWall::Top);
    if (!s.periodic) {
        o.walls[2] = wall(CrossSectionWall::Outer);
        o.walls[3] = wall(CrossSectionWall::Inner);
    }
    const double top = std::abs(o.walls[1].force);
    double sum = 0, work = 0, sinks = 0;
    for (const auto& w : o.walls) sum += w.force, work += w.work, sinks += w.sink;
    o.force_balance = sum / top;
    o.side_share = (std::abs(o.walls[2].force) + std::abs(o.walls[3].force)) / top;
    o.energy_defect = (work - o.bulk_dissipation - sinks - o.contact_dissipation) / work;
    return o;
}

std::vector<double> mid_width_pressure(const CrossSectionSolution& s) {
    const double jm = s.periodic ? 0.0 : 0.5 * s.cells_z;
    const int j0 = static_cast<int>(std::floor(jm)), j1 = std::min(j0 + 1, s.nz() - 1);
    const double f = jm - j0;
    std::vector<double> p(static_cast<std::size_t>(s.ny()), 1.0);
    if (!s.pressure.empty())
        for (int i = 0; i < s.ny(); ++i)
            p[static_cast<std::size_t>(i)] = (1 - f) * s.pressure[s.at(i, j0)] + f * s.pressure[s.at(i, j1)];
    return p;
}

Solution mid_width_profile(const CrossSectionSolution& s) {
    Solution m;
    const int ny = s.ny();
    // the middle of z^ in [0, A] (walls) or of the periodic nodes 0 .. N - 1 (any column: all the same there)
    const double jm = s.periodic ? 0.0 : 0.5 * s.cells_z;
    const int j0 = static_cast<int>(std::floor(jm)), j1 = std::min(j0 + 1, s.nz() - 1);
    const double f = jm - j0;
    for (int i = 0; i < ny; ++i) {
        m.y.push_back(static_cast<double>(i) / s.cells_y);
        m.u.push_back((1 - f) * s.u[s.at(i, j0)] + f * s.u[s.at(i, j1)]);
        m.nu.push_back((1 - f) * s.nu[s.at(i, j0)] + f * s.nu[s.at(i, j1)]);
    }
    m.Pi = s.Pi;
    m.Lambda = s.Lambda;
    m.iterations = s.iterations;
    m.residual = s.residual;
    m.continuation_steps = s.continuation_steps;
    return m;
}

}  // namespace granlub::continuum
