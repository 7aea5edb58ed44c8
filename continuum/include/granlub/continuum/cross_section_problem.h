// The GKL model on the trough's cross-section (continuum/README.md "The trough's cross-section"): fully developed
// flow along the trough, u(y, z) and nu(y, z) on the rectangle H x W, scaled by H (y^ in [0, 1] from the moving
// floor, z^ in [0, A], A = W/H, z^ = 0 the outer side wall). The 1-D equations of problem.h in their 2-D form
// (the same closures, node_coefficients(); the same wall condition, wall_condition.h, on each wall in its frame):
//   div(M grad u^) = 0,   div(K grad nu) = Pi M |grad u^|^2 - Lambda^2 C
// Floor (y^ = 0) and both side walls move at U, the top (y^ = 1) is still; each wall has its own WallBC.
// Pressure uniform (P_y = the load), or with the body forces on the field p^ = p/P_y of their potential part
// (cross_section_solver.h); T = p/(rho_p f_p(nu)) locally, so with p^ the coefficients become
//   M -> p^^1/2 M,  K -> p^^3/2 K,  C -> p^^3/2 C,  and the heat flux gains -p^^1/2 K_p grad p^,  K_p = f_kappa f_p^-3/2
// and a wall condition sees Pi/p^ (derivation: docs/continuum-model.md §11); a contact stress's share pi_c = p_c/p and
// its cap nu_P are the local p's (§2.9a). No secondary flow.
#pragma once
#include <vector>

#include "granlub/continuum/problem.h"

namespace granlub::continuum {

enum class CrossSectionWall { Floor = 0, Top = 1, Outer = 2, Inner = 3 };
inline constexpr int kCrossSectionWalls = 4;

// A test hook (manufactured solutions): a volume source added to each equation and a correction added to the
// normal gradients a wall condition imposes. Null in every run, where it costs one pointer test per node.
class CrossSectionSource {
public:
    virtual ~CrossSectionSource() = default;
    // Added to div(M grad u^) and to div(K grad nu) - (Pi M |grad u^|^2 - Lambda^2 C) at (y^, z^).
    virtual void volume(double y, double z, double& su, double& snu) const = 0;
    // Added to du^/dn and dnu/dn of wall `w` at (y^, z^) (n into the flow).
    virtual void wall(CrossSectionWall w, double y, double z, double& du, double& dnu) const = 0;
};

// Body forces over the cross-section, dimensionless (zero: off).
struct CrossSectionBodyForces {
    double gravity = 0;  // rho_p g sigma / P_y: dp^/dy^ = -Lambda gravity nu (gravity along -y)
    double radius = 0;   // the outer side wall's radius / sigma; 0 = no centripetal force. dp^/dz^ = -Pi nu u^^2 / r^,
                         // r^ = r/H = radius/Lambda - z^ (z^ = 0 the outer wall)
    bool on() const { return gravity != 0 || radius != 0; }
};

struct CrossSectionProblem {
    // closures, Lambda = H/sigma, Pi = rho_p U^2/P_y, mode (Load or Inventory), inventory = Lambda x mean nu over
    // the cross-section (grains per length / (sigma W)), the floor (bottom) and top walls.
    Problem gap;
    WallBC outer, inner;         // side walls at z^ = 0 and z^ = A, moving with the floor
    double width = 0;            // W / sigma; A = width / Lambda (so the gap unknown of Inventory changes A)
    bool periodic = false;       // side walls removed: periodic in z^ (the 1-D check)
    const CrossSectionSource* source = nullptr;  // tests only
    CrossSectionBodyForces body;
    std::vector<double> pressure;  // p^ per node while solving with body forces; empty = uniform (1)

    double aspect(double Lambda) const { return width / Lambda; }
    const WallBC& wall(CrossSectionWall w) const;
};

struct CrossSectionSettings {
    int cells_y = 40, cells_z = 100;  // cells across the gap and across the width
    double tolerance = 1e-10;         // max norm of the flux balances (per unit width, as the 1-D solver's)
    int max_iterations = 50;
    int max_continuation_steps = 200;
};

// Node values, node (i, j) at j * (cells_y + 1) + i: y^_i = i / cells_y, z^_j = j A / cells_z; with periodic z
// the nodes j = 0 .. cells_z - 1.
struct CrossSectionSolution {
    int cells_y = 0, cells_z = 0;
    bool periodic = false;
    std::vector<double> u, nu;
    std::vector<double> pressure;  // p^ = p/P_y per node; empty = uniform (no body forces)
    double Pi = 0, Lambda = 0;
    int iterations = 0, continuation_steps = 0;
    double residual = 0;
    int ny() const { return cells_y + 1; }
    int nz() const { return periodic ? cells_z : cells_z + 1; }
    std::size_t at(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(ny()) + static_cast<std::size_t>(i); }
};

// Outputs per wall, dimensionless: tau/P_y and slip/U averaged along the wall (trapezoid rule over its nodes),
// the force per unit length over P_y H, the wall's work and what the wall removes from the fluctuation energy
// (slip work minus the energy flux the condition returns, K dnu/dn), per unit length over P_y U H.
struct CrossSectionWallOutput {
    double tau = 0, slip = 0, force = 0, work = 0, sink = 0;
    double normal = 1;  // mean normal stress / P_y
    bool present = false;
};
struct CrossSectionObservables {
    CrossSectionWallOutput walls[kCrossSectionWalls];
    double nu_mean = 0, nu_max_node = 0;
    double bulk_dissipation = 0;  // per unit length over P_y U H
    // the contact stress's work (docs/continuum-model.md §2.9), dissipated in the contacts: in the bulk and the
    // walls' contact tractions times their slips, per unit length over P_y U H (0 without it)
    double contact_dissipation = 0;
    double side_share = 0;        // side walls' force over the top wall's
    double force_balance = 0;     // sum of the walls' forces (signed: moving walls +) over the top's
    double energy_defect = 0;     // (work - bulk dissipation - sinks - contact dissipation) / work, O(h^2)
};
CrossSectionObservables observe(const CrossSectionProblem& p, const CrossSectionSolution& s);

// The column at mid-width (interpolated between the two middle columns when cells_z is odd): 1-D Solution.
Solution mid_width_profile(const CrossSectionSolution& s);
// p^ on the same column (1 without body forces).
std::vector<double> mid_width_pressure(const CrossSectionSolution& s);

}  // namespace granlub::continuum
