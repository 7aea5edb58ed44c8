// The particle solvers' box of a case (particles.h); apart from the particle sets so that the
// case model (rough walls are laid out in it at check time) links without them.
#include "granlub/case.h"
#include "granlub/particles.h"

namespace granlub {

ParticleBox particle_box(const Case& c, double periodic_depth) {
    ParticleBox b;
    b.length = c.cell.length;
    b.gap = c.cell.gap;
    if (c.cell.width > 0) {
        b.width = c.cell.width;
    } else {
        b.periodic_z = true;
        b.width = periodic_depth > 0 ? periodic_depth : kPeriodicDepthDiameters * c.grains.diameter;
    }
    return b;
}

}  // namespace granlub
