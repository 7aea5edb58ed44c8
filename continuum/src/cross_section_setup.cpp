#include "granlub/continuum/cross_section_setup.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "granlub/case/wall_bumps.h"
#include "granlub/continuum/command.h"
#include "granlub/continuum/cross_section_solver.h"
#include "granlub/particles/cross_section.h"
#include "granlub/error.h"
#include "granlub/results/file_io.h"

namespace granlub::continuum {

// Fewest cells per grain diameter across the gap and the width: the walls' layers of nu and T are one to two
// diameters thick in the 1-D solutions, and 4 cells per diameter keep the 40 x 100 grid of S&T's trough above it
// (4 H/d = 20.3, 4 W/d = 96.6) [ASSUMPTION: our resolution rule].
constexpr double kCellsPerDiameter = 4.0;

void resolve_cross_section_settings(const Case& c, Settings& s) {
    const Section& sec = c.section(kSolver.name);
    s.cross_section = sec.string("geometry") == "cross_section";
    // cells_y, cells_z and side_roughness are plain keys, read with the others (section.cpp); these are the checks.
    s.body_forces = sec.string("body_forces") == "on";
    if (!s.cross_section) {
        if (s.body_forces)
            sec.fail("body_forces", "body_forces = \"on\" needs the cross-section (the 1-D gap has p_yy uniform, S&T "
                                    "Eq. 6b); allowed: \"off\", or geometry = \"cross_section\"");
        if (sec.has("side_roughness"))
            sec.fail("side_roughness", "side_roughness is a side wall's R, and only the cross-section has side walls "
                                       "(allowed: remove it, or geometry = \"cross_section\")");
        return;
    }
    if (!(c.cell.width > 0))
        sec.fail("geometry", fmt::format("geometry = \"cross_section\" needs the trough's side walls, but [cell] width = "
                                         "{} (periodic); allowed: [cell] width > 0, or geometry = \"gap\"",
                                         c.cell.width));
    if (s.method == Method::Shooting)
        sec.fail("method", "method = \"shooting\" solves the 1-D gap only; with geometry = \"cross_section\" allowed: \"fv\"");
    // the contact stress's constants are checked as on the 1-D gap (case_setup.cpp)
    for (const OperatingPoint& p : c.points)
        if (p.control != Control::Load)
            sec.fail("geometry", fmt::format("geometry = \"cross_section\" solves under a load, but point {} has "
                                             "[operating] control = fill (allowed: control = \"load\", or geometry = "
                                             "\"gap\")",
                                             p.id));
    const double d = c.grains.diameter;
    const auto need = [&](const char* key, int cells, double length, const char* across) {
        const int least = static_cast<int>(std::ceil(kCellsPerDiameter * length / d - 1e-9));
        if (cells < least)
            sec.fail(key, fmt::format("{} cells across the {} ({} m) are {:.2f} per grain diameter: too coarse for the "
                                      "walls' layers (allowed: at least {} per diameter, >= {})",
                                      cells, across, length, cells * d / length, kCellsPerDiameter, least));
    };
    need("cross_section_cells_y", s.cells_y, c.cell.gap, "gap");
    need("cross_section_cells_z", s.cells_z, c.cell.width, "width");
}

CrossSectionProblem cross_section_problem_for(const Case& c, const Settings& s, const OperatingPoint& p) {
    CrossSectionProblem x;
    x.gap = problem_for(c, s, p);  // closures, Pi, floor and top walls, the gap's domain (bump tops) and mode
    const double d = c.grains.diameter, W = c.cell.width;
    // Side walls ([walls] sides): as_bottom = the floor's surface on each side wall, so the floor's condition;
    // plane = smooth frictional planes in the particle solvers, which GKL's roughness-based families cannot tell
    // from a rough plane: the floor's restitution with the roughness as declared, as the plane floor and top of
    // cases/sawyer2001_poly take it [ASSUMPTION]. side_roughness sets R5..R8 of both.
    // With wall_roughness = "built" plane side walls take their impact law's factors (walls/flat_wall.h).
    const bool as_bottom = c.side_walls == SideWalls::AsBottom;
    WallBC side = x.gap.bottom;
    if (!as_bottom && s.plane_walls_from_impact) {
        side.params = plane_wall_params(s, p.bottom);
    } else if (!as_bottom) {
        const double r = p.bottom.roughness;
        side.params.r5 = side.params.r6 = side.params.r7 = side.params.r8 = r;
    }
    if (s.side_roughness >= 0)
        side.params.r5 = side.params.r6 = side.params.r7 = side.params.r8 = s.side_roughness;
    if (!(side.params.r5 > 0))
        throw SolverError(fmt::format("R5 = 0 at the side walls ([continuum] side_roughness, or the wall roughness): a "
                                      "smooth wall exerts no traction in GKL; set [continuum] side_roughness > 0"));
    x.outer = x.inner = side;
    // With the wall at the bumps' tops, bumpy side walls narrow the width as the floor's narrow the gap.
    const double side_offset = as_bottom && s.wall_at_bump_tops ? 2 * bump_protrusion(c, p.bottom) : 0.0;
    const double Wc = W - side_offset;
    x.width = Wc / d;
    // the grains per length the particle solvers insert, solid_fraction x gap x W, over d W_c
    x.gap.inventory = p.solid_fraction * c.cell.gap * W / (d * Wc);
    if (s.body_forces) {
        x.body.gravity = c.grains.density * c.gravity * d / p.normal_stress;
        // the outer side wall's radius: the centripetal force points from it to the axis
        x.body.radius = c.cell.annulus_radius > 0 ? (c.cell.annulus_radius + Wc / 2) / d : 0.0;
    }
    return x;
}

namespace {

// Where the continuum's domain lies in the particle solvers' frame (m): y from the floor's bump centres over the gap
// between the centre planes, z from the outer wall over the width; the domain starts at off_y, off_z.
struct Frame {
    double d, gap, width, off_y, Hc, off_z, Wc;
};

// section.csv on the particle solvers' cells (cross_section.h: about one grain diameter each, y across the gap from
// the floor, z/W from -1/2 at the outer wall, z fastest): per cell the solid volume fraction (the room outside the
// continuum's domain, between bumps, counts as empty) and the grain-weighted u/U (0 in a cell without grains), by
// a 16 x 16 midpoint rule on the bilinear interpolant of the nodes.
Profile section_table(const CrossSectionSolution& s, const Frame& f) {
    const std::size_t ny = CrossSection::cells_for_grains(f.d, f.gap), nz = CrossSection::cells_for_grains(f.d, f.width);
    constexpr int kSamples = 16;
    const auto node = [&](double yh, double zh, double& nu, double& u) {  // yh, zh in [0, 1] over the domain
        const double a = std::clamp(yh, 0.0, 1.0) * s.cells_y, b = std::clamp(zh, 0.0, 1.0) * s.cells_z;
        const int i = std::min(static_cast<int>(a), s.cells_y - 1), j = std::min(static_cast<int>(b), s.cells_z - 1);
        const double fa = a - i, fb = b - j;
        const auto lerp = [&](const std::vector<double>& v) {
            return (1 - fa) * ((1 - fb) * v[s.at(i, j)] + fb * v[s.at(i, j + 1)]) +
                   fa * ((1 - fb) * v[s.at(i + 1, j)] + fb * v[s.at(i + 1, j + 1)]);
        };
        nu = lerp(s.nu), u = lerp(s.u);
    };
    std::vector<double> y, z, nu, u;
    for (std::size_t k = 0; k < ny; ++k)
        for (std::size_t m = 0; m < nz; ++m) {
            double V = 0, P = 0;
            for (int a = 0; a < kSamples; ++a)
                for (int b = 0; b < kSamples; ++b) {
                    const double ym = (static_cast<double>(k) + (a + 0.5) / kSamples) * f.gap / static_cast<double>(ny);
                    const double zm = (static_cast<double>(m) + (b + 0.5) / kSamples) * f.width / static_cast<double>(nz);
                    const double yh = (ym - f.off_y) / f.Hc, zh = (zm - f.off_z) / f.Wc;
                    if (yh < 0 || yh > 1 || zh < 0 || zh > 1) continue;
                    double n_, u_;
                    node(yh, zh, n_, u_);
                    V += n_, P += n_ * u_;
                }
            y.push_back((static_cast<double>(k) + 0.5) / static_cast<double>(ny));
            z.push_back((static_cast<double>(m) + 0.5) / static_cast<double>(nz) - 0.5);
            nu.push_back(V / (kSamples * kSamples));
            u.push_back(V > 0 ? P / V : 0.0);
        }
    Profile t;
    t.add("y_over_H", std::move(y)).add("z_over_W", std::move(z)).add("solid_fraction", std::move(nu));
    t.add("u_over_U", std::move(u));
    return t;
}

}  // namespace

PointResult solve_cross_section_point(const Case& c, const OperatingPoint& p, const Settings& s,
                                      const std::filesystem::path& dir) {
    const CrossSectionProblem q = cross_section_problem_for(c, s, p);
    CrossSectionSettings st;
    st.cells_y = s.cells_y, st.cells_z = s.cells_z;
    st.tolerance = s.solver.tolerance;
    st.max_iterations = s.solver.max_iterations;
    st.max_continuation_steps = s.solver.max_continuation_steps;
    const auto t0 = std::chrono::steady_clock::now();
    const CrossSectionSolution sol = solve_cross_section(q, st);
    const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const CrossSectionObservables o = observe(q, sol);
    const Solution mid = mid_width_profile(sol);
    const std::vector<double> p_mid = mid_width_pressure(sol);

    const double U = p.speed, rho = c.grains.density, d = c.grains.diameter;
    const double P = rho * U * U / sol.Pi, T_scale = P / rho;
    // gap and mean nu between the planes through the bumps' centres (as the 1-D solver reports them)
    const double offset = c.cell.gap - q.gap.Lambda * d;  // what wall_plane = "bump_tops" takes off the gap
    const double Hc = sol.Lambda * d, gap = Hc + offset, Wc = q.width * d, W = c.cell.width;
    const double nu_mean = o.nu_mean * Hc * Wc / (gap * W);
    const double off_y = s.wall_at_bump_tops ? bump_protrusion(c, p.bottom) : 0.0;
    const Frame frame{d, gap, W, off_y, Hc, 0.5 * (W - Wc), Wc};
    write_file_atomic(dir / kSectionFile,
                      profile_csv(section_table(sol, frame),
                                  {fmt::format("granlub continuum, geometry = cross_section: case {}, point {}", c.name, p.id),
                                   "solid fraction and u/U over the cross-section: y across the gap (0 = moving floor), z "
                                   "across the width (z/W = -1/2: the outer wall); the particle solvers' cells, "
                                   "averaged over the continuum's solution"}));

    PointResult r;
    std::vector<double> T_over_U2(mid.nodes());
    for (std::size_t i = 0; i < mid.nodes(); ++i)
        T_over_U2[i] = p_mid[i] / (sol.Pi * q.gap.closures->state(mid.nu[i], p_mid[i]).fp.v);  // T = p/(rho_p f~_p)
    Summary& m = r.summary;
    m = make_summary(c, p, kSolver);
    r.profile.add("y_over_H", profile_y_over_H(mid.y, off_y, Hc, gap, s, m))
        .add("u_over_U", mid.u).add("solid_fraction", mid.nu).add("temperature_over_U2", T_over_U2);
    const auto& fl = o.walls[0];
    const auto& tp = o.walls[1];
    const auto& ou = o.walls[2];
    const auto& in = o.walls[3];
    m.set("normal_stress_bottom", P * fl.normal, "Pa").set("normal_stress_top", P * tp.normal, "Pa");
    m.set("normal_stress_outer", P * ou.normal, "Pa").set("normal_stress_inner", P * in.normal, "Pa");
    m.set("shear_stress_bottom", P * fl.tau, "Pa").set("shear_stress_top", P * tp.tau, "Pa");
    m.set("shear_stress_outer", P * ou.tau, "Pa").set("shear_stress_inner", P * in.tau, "Pa");
    m.set("shear_stress_side", 0.5 * P * (ou.tau + in.tau), "Pa");
    m.set("slip_bottom", U * fl.slip, "m/s").set("slip_top", U * tp.slip, "m/s");
    m.set("slip_outer", U * ou.slip, "m/s").set("slip_inner", U * in.slip, "m/s");
    m.set("slip_over_U_bottom", fl.slip, "").set("slip_over_U_top", tp.slip, "");
    m.set("slip_over_U_outer", ou.slip, "").set("slip_over_U_inner", in.slip, "");
    m.set("side_wall_drag_share", o.side_share, "");
    m.set("mean_solid_fraction", nu_mean, "").set("max_solid_fraction", s.closures->numax(), "");
    const std::size_t n = mid.nodes(), ic = (n - 1) / 2;
    m.set("solid_fraction_centre", mid.nu[ic], "").set("solid_fraction_bottom", mid.nu.front(), "")
        .set("solid_fraction_top", mid.nu.back(), "");
    m.set("temperature_centre", T_scale * sol.Pi * T_over_U2[ic], "m^2/s^2")
        .set("temperature_bottom", T_scale * sol.Pi * T_over_U2.front(), "m^2/s^2")
        .set("temperature_top", T_scale * sol.Pi * T_over_U2.back(), "m^2/s^2");
    m.set("stress_ratio", fl.tau, "").set("pi_number", sol.Pi, "");
    const double du_c = std::abs(mid.u[ic + 1] - mid.u[ic - 1]) / (mid.y[ic + 1] - mid.y[ic - 1]);
    m.set("inertial_number", (U * du_c / Hc) * d / std::sqrt(P / rho), "");  // at mid-width, mid-gap
    if (s.gap_from_inventory) m.set("gap", gap, "m");
    m.run["geometry"] = "cross_section";
    m.run["cells_y"] = s.cells_y;
    m.run["cells_z"] = s.cells_z;
    m.run["side_walls"] = {{"sides", c.side_walls == SideWalls::AsBottom ? "as_bottom" : "plane"},
                           {"r5", q.outer.params.r5}, {"r6", q.outer.params.r6},
                           {"slip_dissipation", q.outer.params.slip_dissipation},
                           {"impacts", q.outer.params.impacts ? "stick_and_slide" : "linear"},
                           {"restitution", q.outer.params.restitution},
                           {"width_m", Wc}};
    const double PU = P * U * Hc;  // per unit length: the dimensionless budget is over P U H_c
    nlohmann::json walls = nlohmann::json::object();
    const char* names[] = {"floor", "top", "outer", "inner"};
    for (int w = 0; w < kCrossSectionWalls; ++w)
        walls[names[w]] = {{"work_W_m", PU * o.walls[w].work}, {"sink_W_m", PU * o.walls[w].sink}};
    m.run["energy_budget"] = {{"walls", walls},
                              {"bulk_dissipation_W_m", PU * o.bulk_dissipation},
                              {"contact_dissipation_W_m", PU * o.contact_dissipation},
                              {"relative_defect", o.energy_defect}};
    m.run["force_balance"] = o.force_balance;
    m.run["body_forces"] = s.body_forces ? fmt::format("gravity {} m/s^2 and the centripetal force (outer wall radius {} m) "
                                                       "through the potential part of their pressure field, the top's "
                                                       "mean = the load; no secondary flow",
                                                       c.gravity, q.body.radius * d)
                                         : "not modelled: the pressure is uniform over the cross-section, P_y = the load";
    record_run(m, s, {sol.iterations, sol.residual, sol.continuation_steps, secs, o.nu_max_node});
    r.line = fmt::format("nu={:.4f} tau floor/top/outer/inner={:.4g}/{:.4g}/{:.4g}/{:.4g} Pa slip/U={:.3f}/{:.3f} "
                         "side share={:.3f} it={}",
                         nu_mean, P * fl.tau, P * tp.tau, P * ou.tau, P * in.tau, fl.slip, tp.slip, o.side_share,
                         sol.iterations);
    if (s.gap_from_inventory) r.line += fmt::format(" gap={:.3f} mm", 1e3 * gap);
    if (s.ordering_fraction > 0 && o.nu_max_node > s.ordering_fraction) r.line += " ORDERED";
    return r;
}

}  // namespace granlub::continuum
