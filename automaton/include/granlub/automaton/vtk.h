// ParaView snapshots of the lattice: VTK XML ImageData (.vti), one cell per lattice site
// including the two wall rows, plus a .pvd collection indexing them in time.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "granlub/automaton/ensemble.h"

namespace granlub::automaton {

// Cell arrays: "state" (0 empty, 1 grain, 2 moving wall, 3 stationary wall), "u_over_U" (u_p/U of
// the grain, wall speed on the walls), "direction" (0..7 counter-clockwise from +x; -1 elsewhere),
// "velocity" (u_p times the unit lattice direction, for glyphs). Spacing = grain diameter d (m);
// y = 0 is the moving wall's top face.
std::string lattice_vti(const Lattice& e, double diameter);

// A .pvd collection: (time in s, file name relative to the .pvd) per snapshot.
std::string snapshot_pvd(const std::vector<std::pair<double, std::string>>& files);

}  // namespace granlub::automaton
