// Rough walls: the bump layer of a wall (wall_bumps.h).
#include "granlub/case/wall_bumps.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/case/particle_box.h"

namespace granlub {


namespace {

// Where a wall's keys live, for messages: [walls.<side>] when given there, else [walls].
const Section& wall_section(const Case& c, const char* side, const char* key) {
    const Section& s = c.section(fmt::format("walls.{}", side));
    return s.has(key) ? s : c.section("walls");
}

// The message's prefix: the key that sets R (swept in [operating], or a wall's).
std::string roughness_key(const Case& c, const char* side) {
    if (c.section("operating").has("roughness")) return "[operating] roughness";
    return c.section(fmt::format("walls.{}", side)).has("roughness") ? fmt::format("[walls.{}] roughness", side)
                                                                      : std::string("[walls] roughness");
}

}  // namespace

namespace {
double bump_diameter(const Case& c, const Wall& w) {
    const double R = w.roughness, d = c.grains.diameter;
    return w.bump_diameter > 0 ? w.bump_diameter : std::min(d, R * d / (1.0 - R));
}
}  // namespace

BumpLayer moved_bumps(const BumpLayer& b, double shift, double length) {
    BumpLayer m = b;
    for (double& x : m.x) {
        x = std::fmod(x + shift, length);
        if (x < 0) x += length;
        if (x >= length) x -= length;  // a rounding of -0 or of a shift just below a period
    }
    return m;
}

double bump_protrusion(const Case& c, const Wall& w) {
    return w.surface == WallSurface::Bumps && w.roughness > 0 ? 0.5 * bump_diameter(c, w) : 0.0;
}

std::optional<BumpLayer> wall_bumps(const Case& c, const OperatingPoint& p, const Wall& w, const char* side,
                                    const ParticleBox& box) {
    const double R = w.roughness, d = c.grains.diameter;
    if (w.surface != WallSurface::Bumps || R == 0) return std::nullopt;
    auto fail = [&](const std::string& why) {
        throw CaseError(fmt::format("{}: point {}: {} = {:g} with [walls{}] surface = \"bumps\": {}", c.file.string(),
                                    p.id, roughness_key(c, side), R,
                                    c.section(fmt::format("walls.{}", side)).has("surface") ? fmt::format(".{}", side)
                                                                                             : std::string(),
                                    why));
    };
    if (c.cell.ring()) fail("rough walls are built in a slice only ([cell] geometry = \"slice\")");
    BumpLayer b;
    b.diameter = bump_diameter(c, w);
    const double R_min = b.diameter / (b.diameter + d);
    if (R < R_min * (1 - 1e-12))
        fail(fmt::format("bumps of {:g} m touch at R = {:.4g}, the least they can give; a smaller bump_diameter "
                         "(at most {:g} m for R = {:g}), or bump_diameter = 0 (the largest bumps that reach R)",
                         b.diameter, R_min, R * d / (1.0 - R), R));
    // the rows along the flow: a whole number of bumps in the periodic length, as near l as allowed
    const double l = R * (b.diameter + d), L = box.length;
    const auto fits = [&](double n) { return n >= 1 && L / n >= b.diameter * (1 - 1e-12); };
    double n = std::max(1.0, std::round(L / l));
    if (!fits(n)) n = std::floor(L / b.diameter);
    if (!fits(n)) fail(fmt::format("the periodic length {:g} m holds no bump of {:g} m", L, b.diameter));
    // a layer no engine could hold (and no count a size_t holds): refused before any cast or allocation
    const auto too_many = [&](double bumps, const char* along) {
        if (bumps > kMaxBumpsPerLayer)
            fail(fmt::format("{:g} bumps {} ([cell] length {:g} m, width {:g} m): more than {:g} in one layer", bumps,
                             along, L, box.width, kMaxBumpsPerLayer));
    };
    too_many(n, "in a row along the flow");
    b.count_x = static_cast<std::size_t>(n);
    b.spacing = L / n;
    b.roughness = b.spacing / (b.diameter + d);
    if (std::abs(b.roughness - R) > kBumpRoughnessTolerance) {
        const double lo = std::floor(L / l), hi = std::ceil(L / l);
        std::string options;
        for (double m : {lo, hi})
            if (fits(m)) options += fmt::format("{}{:g} bumps (R = {:.4g})", options.empty() ? "" : " or ", m,
                                                L / m / (b.diameter + d));
        fail(fmt::format("bumps {:g} m apart; the periodic length [cell] length = {:g} m holds {} in a row, more than "
                         "{:g} from R: set the roughness to one of these, or change the length",
                         l, L, options, kBumpRoughnessTolerance));
    }
    // rows across the width: between the side walls, or an even count filling the periodic depth
    const double row = b.spacing * std::sqrt(3.0) / 2.0;
    if (box.periodic_z) {
        // rows alternate their offset: an even count keeps the period; stretched, never squeezed
        // (squeezed rows would overlap); one row when two do not fit
        const double fit = std::floor(box.width / row * (1 + 1e-12));
        too_many(n * fit, "in the layer");
        auto rows = static_cast<std::size_t>(fit);
        rows = rows >= 2 ? rows - rows % 2 : 1;
        b.rows = rows;
        b.row_spacing = box.width / static_cast<double>(rows);
    } else {
        const double span = box.width - b.diameter;  // centres from -W/2 + d_w/2 to W/2 - d_w/2
        if (span < 0) fail(fmt::format("bumps of {:g} m are wider than the cell ({:g} m)", b.diameter, box.width));
        const double fit = std::floor(span / row) + 1;
        too_many(n * fit, "in the layer");
        b.rows = static_cast<std::size_t>(fit);
        b.row_spacing = row;
    }
    const double z0 = box.periodic_z ? -0.5 * box.width + 0.5 * b.row_spacing
                                     : -0.5 * static_cast<double>(b.rows - 1) * b.row_spacing;
    for (std::size_t j = 0; j < b.rows; ++j)
        for (std::size_t i = 0; i < b.count_x; ++i) {
            const double shift = b.rows > 1 ? 0.5 * static_cast<double>(j % 2) : 0.0;
            b.x.push_back((static_cast<double>(i) + shift) * b.spacing);
            b.across.push_back(z0 + static_cast<double>(j) * b.row_spacing);
        }
    return b;
}

std::optional<BumpLayer> side_bumps(const Case& c, const OperatingPoint& p, const ParticleBox& box, double y_top) {
    if (c.side_walls != SideWalls::AsBottom || box.periodic_z) return std::nullopt;
    std::optional<BumpLayer> b = wall_bumps(c, p, p.bottom, "bottom", box);
    if (!b) return std::nullopt;
    b->row_spacing = b->spacing * std::sqrt(3.0) / 2.0;
    const double rows = std::floor(y_top / b->row_spacing * (1 + 1e-12));
    if (rows * static_cast<double>(b->count_x) > kMaxBumpsPerLayer)
        c.section("walls").fail("sides", fmt::format("point {}: {:g} rows of bumps up a side wall to its top ({:g} m): "
                                                     "more than {:g} bumps in one layer",
                                                     p.id, rows, y_top, kMaxBumpsPerLayer));
    b->rows = static_cast<std::size_t>(rows);
    if (b->rows == 0)
        c.section("walls").fail("sides", fmt::format("point {}: the side walls' rows of bumps are {:g} m apart; the "
                                                     "cell's top ({:g} m) holds none",
                                                     p.id, b->row_spacing, y_top));
    b->x.clear();
    b->across.clear();
    for (std::size_t j = 1; j <= b->rows; ++j)
        for (std::size_t i = 0; i < b->count_x; ++i) {
            b->x.push_back((static_cast<double>(i) + 0.5 * static_cast<double>(j % 2)) * b->spacing);
            b->across.push_back(static_cast<double>(j) * b->row_spacing);
        }
    return b;
}

nlohmann::json walls_json(const std::optional<BumpLayer>& b) {
    if (!b) return {{"surface", "plane"}};
    return {{"surface", "bumps"},
            {"bump_diameter_m", b->diameter},
            {"bump_spacing_m", b->spacing},
            {"row_spacing_m", b->row_spacing},
            {"bumps_per_row", b->count_x},
            {"rows", b->rows},
            {"roughness_built", b->roughness},
            {"bump_angle_deg", std::asin(std::min(1.0, b->roughness)) * 180.0 / 3.141592653589793}};
}

void check_wall_bumps(const Case& c) {
    const ParticleBox box = particle_box(c);
    if (c.side_walls == SideWalls::AsBottom && (c.cell.ring() || box.periodic_z))
        c.section("walls").fail("sides", c.cell.ring() ? "\"as_bottom\": the whole ring's side walls are its cylinders, "
                                                         "built as planes or meshes only; use \"plane\""
                                                       : "\"as_bottom\" needs side walls ([cell] width > 0; width = 0 "
                                                         "is periodic across the width); use \"plane\"");
    for (const OperatingPoint& p : c.points) {
        const auto bottom = wall_bumps(c, p, p.bottom, "bottom", box);
        const auto top = wall_bumps(c, p, p.top, "top", box);
        const double protrusion = 0.5 * ((bottom ? bottom->diameter : 0.0) + (top ? top->diameter : 0.0));
        if (c.cell.gap - protrusion < 2.0 * c.grains.diameter)
            wall_section(c, bottom ? "bottom" : "top", "bump_diameter")
                .fail("bump_diameter", fmt::format("point {}: the bumps protrude {:g} m into the gap [cell] gap = {:g} "
                                                   "m; at least two grain diameters ({:g} m) must remain between them",
                                                   p.id, protrusion, c.cell.gap, 2.0 * c.grains.diameter));
    }
}

}  // namespace granlub
