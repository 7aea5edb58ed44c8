// The small shear cell the particle tests run: d = 1 mm grains in an 8 x 6 x 6 mm cell, inserted
// at solid fraction 0.4 (220 grains), gravity and a centripetal force. Each test adds its own
// [operating] keys and [dem] settings (and further sections after them). Small enough for a few
// seconds per run. Text only: `granlub run` tests use it without the dem library.
#pragma once
#include <string>

namespace granlub::test {

inline std::string tiny_cell(const std::string& name, const std::string& operating, const std::string& dem) {
    return "[case]\nname = \"" + name + R"("
[grains]
diameter = 1.0e-3
density = 2500.0
restitution = 0.9
friction = 0.5
[walls]
restitution = 0.8
roughness = 0.5
[cell]
gap = 6.0e-3
length = 8.0e-3
width = 6.0e-3
annulus_radius = 0.05
[operating]
speed = [1.0]
solid_fraction = 0.4
)" + operating + R"(
[body_forces]
gravity = 9.81
[dem]
)" + dem;
}

}  // namespace granlub::test
