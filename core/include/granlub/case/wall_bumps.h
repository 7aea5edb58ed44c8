// Rough walls of the particle solvers ([walls] surface = "bumps"): a monolayer of fixed spheres on
// the floor and on the loaded top (and on the side walls with [walls] sides = "as_bottom"), moving
// with their wall, as the experiment's rough surfaces (a
// bonded monolayer of glass beads, Sawyer & Tichy 2001). Declared and laid out here once; both
// particle engines build the same bumps from it.
//
// Layout: bumps of diameter d_w with their centres on the wall's plane (y = 0, and the top wall's
// position), on a hexagonal lattice with its rows along the flow: centres l apart along x, rows
// l sqrt(3)/2 apart across the width, every other row shifted by l/2. The plane stays a wall: a
// grain that falls between bumps meets it.
//
// One roughness R for the three solvers. Jenkins & Richman (1986, J. Fluid Mech. 171:53, §2) and
// Richman (1988, Acta Mech. 75:227) measure a bumpy wall by the angle theta between the wall normal
// and the line from a bump's centre to a grain resting between two neighbouring bumps:
//   sin(theta) = (d_w + s) / (d_w + d) = l / (d_w + d),   s = l - d_w the gap between bumps.
// granlub takes R = sin(theta) [ASSUMPTION: the mapping]. The continuum's R (Sawyer & Tichy's
// roughness factors R5..R8, which give it no geometry) and the automaton's R (Jasti & Higgs 2006,
// Fig. 2: 0 smooth, 1 "very rough", the fraction of a grain that fits the gap between the wall's
// asperities) then describe the wall the particle solvers build: R -> 0 for bumps much smaller than
// a grain; R = 1/2 for touching bumps of the grains' size (S&T's value); R = 1 for a gap s = d, in
// which a grain fits whole. So l = R (d_w + d), which needs l >= d_w: R >= d_w / (d_w + d). With
// bump_diameter = 0 the bumps are the largest that reach R: d_w = min(d, R d / (1 - R)) (touching
// below R = 1/2, the grains' size above). R = 0 is the plane alone.
//
// The periodic length holds a whole number of bumps: l is rounded to L / n, and the R that gives
// (written to the summary) must stay within kBumpRoughnessTolerance of the case's.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace granlub {

struct Case;
struct OperatingPoint;
struct Wall;
struct ParticleBox;

// WallSurface (plane or bumps) is the case's (case.h).

inline constexpr double kBumpRoughnessTolerance = 0.01;  // |R built - R asked|

struct BumpLayer {
    double diameter = 0;          // d_w, m
    double spacing = 0;           // l along the flow, m (L / count_x)
    double row_spacing = 0;       // across the width, m
    std::size_t count_x = 0, rows = 0;
    double roughness = 0;         // R built: l / (d_w + d)
    // centres in the wall's plane: x along the flow, and across it z (in [-W/2, W/2]) on the floor
    // and the top, y (the height above the floor) on a side wall (side_bumps)
    std::vector<double> x, across;
    std::size_t size() const { return x.size(); }
};

// The bumps of one wall of a point in the particle box (x periodic with box.length; z between the
// side walls, or periodic with box.width), or none for a plane wall or R = 0. Throws CaseError
// naming the key, the value and what is allowed when R cannot be built (bumps too large for R, a
// periodic length that holds no whole number of bumps near R, bumps that leave no room in the gap).
std::optional<BumpLayer> wall_bumps(const Case& c, const OperatingPoint& p, const Wall& w, const char* side,
                                    const ParticleBox& box);

// The bumps of each side wall of a point ([walls] sides = "as_bottom", side walls at z = -W/2 and
// W/2), or none for plane sides, a plane floor or a periodic width. The floor's bumps (their
// diameter, their spacing along the flow, R) on a hexagonal lattice in the wall's x-y plane: rows
// l sqrt(3)/2 apart in height, every other one shifted by l/2, from one row above the floor (the
// corner's row would sit on the floor's line) up to y_top, the highest the top wall can go. Rows
// above the top wall meet no grain. Throws CaseError as wall_bumps, or when y_top holds no row.
std::optional<BumpLayer> side_bumps(const Case& c, const OperatingPoint& p, const ParticleBox& box, double y_top);

// The most bumps one wall's layer may have: far beyond any cell a particle engine runs here, and refused before
// the layout is counted into integers or allocated (an absurd [cell] length or width).
inline constexpr double kMaxBumpsPerLayer = 1e7;

// The layer b moved `shift` m along x from its layout, its x wrapped into [0, length) as the
// layout's. A wall moving at U has carried its bumps U t in the time t since the layout: a run that
// starts from a state of time t (particles.h ParticleState::time) places them there.
BumpLayer moved_bumps(const BumpLayer& b, double shift, double length);

// How far a wall's bumps reach into the gap, m: half their diameter, 0 for a plane (no layout).
double bump_protrusion(const Case& c, const Wall& w);

// run.walls.<side> of a particle summary: "plane", or the layer (diameter, spacing, rows, R built).
nlohmann::json walls_json(const std::optional<BumpLayer>& bumps);

// What the check of a case needs: every point's bumps laid out once (throws as wall_bumps).
void check_wall_bumps(const Case& c);

}  // namespace granlub
