// The particle solvers' box of a case: the cell as the grains see it. In the case room because a
// case's rough walls are laid out in it when the case is checked (wall_bumps.h).
#pragma once

namespace granlub {

struct Case;

// The region the grains live in. x in [0, length) periodic; y in [0, gap] between the walls;
// z in [-width/2, width/2], bounded by side walls unless periodic_z.
struct ParticleBox {
    double length = 0;
    double gap = 0;
    double width = 0;
    bool periodic_z = false;
    double volume() const { return length * gap * width; }
};

// Depth used across z when the case's cell.width = 0 (periodic), in grain diameters. Both
// particle solvers use it, so their boxes are the same.
inline constexpr double kPeriodicDepthDiameters = 10.0;

// The box of a case: cell.length x cell.gap x cell.width, or a periodic depth of
// `periodic_depth` (0: kPeriodicDepthDiameters grain diameters) when cell.width = 0.
ParticleBox particle_box(const Case& c, double periodic_depth = 0);

}  // namespace granlub
