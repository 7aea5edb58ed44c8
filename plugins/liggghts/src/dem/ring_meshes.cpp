// ASCII STL of the ring's walls (ring_meshes.h).
#include "ring_meshes.h"

#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "deck.h"
#include "granlub/results/results.h"

namespace granlub::dem {

namespace {

struct Point {
    double x, y, z;
};

// A point at radius r, angle t (the ring's theta = atan2(-z, x), annulus.h) and height y.
Point at(double r, double t, double y) { return {r * std::cos(t), y, -r * std::sin(t)}; }

void facet(std::string& out, const Point& a, const Point& b, const Point& c) {
    out += "facet normal 0 0 0\n outer loop\n";  // LIGGGHTS orients facets itself
    for (const Point& p : {a, b, c}) out += fmt::format("  vertex {:.17g} {:.17g} {:.17g}\n", p.x, p.y, p.z);
    out += " endloop\nendfacet\n";
}

template <class Quad>
std::string solid(const char* name, std::size_t n, Quad quad) {
    std::string out = fmt::format("solid {}\n", name);
    for (std::size_t k = 0; k < n; ++k) {
        const double t0 = 2.0 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
        const double t1 = 2.0 * std::numbers::pi * static_cast<double>(k + 1) / static_cast<double>(n);
        quad(out, t0, t1);
    }
    return out + fmt::format("endsolid {}\n", name);
}

std::string annulus_disc(const char* name, double ri, double ro, double y, std::size_t n) {
    return solid(name, n, [&](std::string& out, double t0, double t1) {
        facet(out, at(ri, t0, y), at(ro, t0, y), at(ro, t1, y));
        facet(out, at(ri, t0, y), at(ro, t1, y), at(ri, t1, y));
    });
}

std::string cylinder(const char* name, double r, double height, std::size_t n) {
    return solid(name, n, [&](std::string& out, double t0, double t1) {
        facet(out, at(r, t0, 0.0), at(r, t1, 0.0), at(r, t1, height));
        facet(out, at(r, t0, 0.0), at(r, t1, height), at(r, t0, height));
    });
}

}  // namespace

void write_ring_meshes(const std::filesystem::path& dir, const Annulus& a, double top, double height,
                       std::size_t facets) {
    write_file_atomic(dir / kRingMeshes[0], annulus_disc("floor", a.inner(), a.outer(), 0.0, facets));
    write_file_atomic(dir / kRingMeshes[1], annulus_disc("top", a.inner(), a.outer(), top, facets));
    write_file_atomic(dir / kRingMeshes[2], cylinder("outer", a.outer(), height, facets));
    write_file_atomic(dir / kRingMeshes[3], cylinder("inner", a.inner(), height, facets));
}

}  // namespace granlub::dem
