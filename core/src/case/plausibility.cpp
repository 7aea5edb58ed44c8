#include "granlub/case/plausibility.h"

#include <algorithm>

#include <fmt/format.h>

#include "granlub/case/case.h"

namespace granlub {

namespace {
// Ranges beyond which a granular-lubrication case is most likely mistyped (SI units expected).
constexpr double kMaxDiameters = 1000;     // gap, length or width in grain diameters
constexpr double kDiameter[2] = {1e-6, 0.1};  // m: micron powders to pebbles
constexpr double kDensity[2] = {100, 25000};  // kg/m^3: foams to the densest metals
constexpr double kMaxSpeed = 100;             // m/s
constexpr double kMaxStress = 1e8;            // Pa: 100 MPa crushes most grains
}  // namespace

std::vector<std::string> plausibility_warnings(const Case& c) {
    std::vector<std::string> w;
    const double d = c.grains.diameter;
    if (d < kDiameter[0] || d > kDiameter[1])
        w.push_back(fmt::format("[grains] diameter = {:g} m is outside {:g} to {:g} m: is the unit metres?", d,
                                kDiameter[0], kDiameter[1]));
    const double rho = c.grains.density;
    if (rho < kDensity[0] || rho > kDensity[1])
        w.push_back(fmt::format("[grains] density = {:g} kg/m^3 is outside {:g} to {:g} kg/m^3: is the unit kg/m^3?",
                                rho, kDensity[0], kDensity[1]));
    for (const auto& [key, v] : {std::pair{"gap", c.cell.gap}, {"length", c.cell.length}, {"width", c.cell.width}})
        if (v / d > kMaxDiameters)
            w.push_back(fmt::format("[cell] {} = {:g} m is {:.0f} grain diameters (more than {:g}): is the unit "
                                    "metres?",
                                    key, v, v / d, kMaxDiameters));
    double top_speed = 0, top_stress = 0;
    for (const auto& p : c.points) top_speed = std::max(top_speed, p.speed), top_stress = std::max(top_stress, p.normal_stress);
    if (top_speed > kMaxSpeed)
        w.push_back(fmt::format("[operating] speed = {:g} m/s is above {:g} m/s: is the unit m/s?", top_speed, kMaxSpeed));
    if (top_stress > kMaxStress)
        w.push_back(fmt::format("[operating] normal_stress = {:g} Pa is above {:g} Pa, where grains crush: is the unit "
                                "Pa?",
                                top_stress, kMaxStress));
    return w;
}

}  // namespace granlub
