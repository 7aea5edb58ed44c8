// The case model: cases/NAME/case.toml parsed, validated and resolved into operating points.
// Contract: docs/architecture.md ("The case file"). SI units everywhere.
#pragma once
#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "granlub/case/grain_sizes.h"
#include "granlub/case/schema.h"

namespace granlub {

enum class Control { Fill, Load };
std::string to_string(Control c);

struct Grains {
    double diameter = 0;        // m, the number mean d of the particle solvers' sizes
    double density = 0;         // kg/m^3
    double restitution = 0;     // e_p, grain-grain
    double friction = 0;        // Coulomb coefficient, grain-grain (particle solvers)
    double youngs_modulus = 0;  // Pa (soft-sphere reference models only)
    double poisson_ratio = 0;
    double size_spread = 0;     // standard deviation / mean of the diameters (grain_sizes.h); 0 = equal
    GrainSizes sizes() const { return {diameter, size_spread}; }
    double mass() const;        // of a grain of the mean diameter, kg
    // Rayleigh time (Li et al. 2005 form) t_R = pi r sqrt(rho/G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)), of
    // the smallest grain (the shortest contact): the soft-sphere time-step scale (as LIGGGHTS'
    // check/timestep/gran), shared by both particle engines.
    double rayleigh_time() const;
};

// What the particle solvers build as a wall (granlub/case/wall_bumps.h): a plane, or bumps on it.
enum class WallSurface { Plane, Bumps };
std::string to_string(WallSurface s);  // "plane", "bumps"

struct Wall {
    double restitution = 0;  // e_w
    double friction = 0;     // grain-wall Coulomb coefficient
    double roughness = 0;    // R in [0, 1]
    // what the particle solvers build (wall_bumps.h): a plane, or bumps on it that give R
    WallSurface surface = WallSurface::Plane;
    double bump_diameter = 0;  // m; 0 = the largest bumps that give R
};

// The trough's side walls ([walls] sides; a slice with [cell] width > 0), which move with the
// bottom wall: smooth frictional planes, or the bottom wall's surface (wall_bumps.h: with bumps on
// the floor, the same bumps on each side wall, moving with it).
enum class SideWalls { Plane, AsBottom };

// slice: a periodic stretch of the trough (the curvature, if any, as a centripetal body force);
// annulus: the whole ring trough, run by granlub dem (granlub/particles/annulus.h).
enum class Geometry { Slice, Annulus };

// Fewest inner-wall radii, in grain diameters, a ring may have: grains must roll along the inner
// cylinder and the facets of a meshed wall must stay small against a grain. Our choice.
inline constexpr double kMinRingInnerRadiusDiameters = 3.0;

struct Cell {
    Geometry geometry = Geometry::Slice;
    double gap = 0;                 // H, m
    double length = 0;              // periodic length along the flow, m
    double width = 0;               // trough width, m; 0 = periodic
    double annulus_radius = 0;      // mean radius: the slice's centripetal force (0 = none), the ring's R
    bool ring() const { return geometry == Geometry::Annulus; }
    double max_solid_fraction = 0;  // nu_max of the continuum closures
};

// One resolved operating point. `id` is stable: it is made only from the keys given as lists
// (plus the speed), so adding a value to one list does not rename the other points.
struct OperatingPoint {
    std::string id;
    std::size_t index = 0;
    double speed = 0;           // U of the bottom wall, m/s
    Control control = Control::Fill;
    double solid_fraction = 0;  // target mean solid fraction (used with control = fill)
    double normal_stress = 0;   // Pa, target normal stress (used with control = load)
    Wall bottom;                // wall data with this point's roughness
    Wall top;
};

// Bounds on what a case may ask for, so that a typo cannot exhaust memory or overflow a count.
inline constexpr std::size_t kMaxOperatingPoints = 10000;
// The longest list an integer key takes ([particles] seeds), and the largest count of seeds.
inline constexpr std::size_t kMaxIntegerList = 1000;
inline constexpr std::size_t kMaxCaseFileBytes = 1u << 20;
inline constexpr std::size_t kMaxTitleBytes = 200;

class Schema;

struct Case {
    std::shared_ptr<const Schema> schema;  // owns the declarations the sections point into
    std::filesystem::path file;  // .../case.toml
    std::filesystem::path dir;   // its directory
    std::string name;
    std::string title;
    Grains grains;
    Wall bottom;  // as declared (before any roughness sweep)
    Wall top;
    SideWalls side_walls = SideWalls::Plane;
    Cell cell;
    double gravity = 0;  // m/s^2 along -y
    std::vector<OperatingPoint> points;
    std::map<std::string, Section> sections;  // every declared section, resolved
    // [case] base: the files read under this one, nearest first (src/case/case_base.h)
    std::vector<std::filesystem::path> bases;
    std::string file_hash;  // hash of the file's bytes and its bases' (provenance)
    std::vector<std::string> warnings;        // accepted but to be changed: old spellings of values, old key names

    const Section& section(std::string_view name) const;
    // Points selected by --point (all when `id` is empty); throws naming the valid ids.
    std::vector<const OperatingPoint*> select(std::string_view id) const;
    // Hash of everything a solver's results depend on: the common sections plus the solver's own
    // section. Results whose hash differs are stale.
    std::string inputs_hash(std::string_view solver_section) const;
    // The same inputs as "[section] key" -> value text, kept in summary.json so that a stale
    // result can name the keys that changed.
    std::map<std::string, std::string> inputs(std::string_view solver_section) const;
};

// Load cases/NAME (a directory holding case.toml) or a .toml file directly.
Case load_case(const std::filesystem::path& dir_or_file, const Schema& schema);
// Parse TOML text; `source` names it in error messages. Used by load_case, tests and the fuzzer.
Case parse_case(std::string_view text, const std::string& source, const Schema& schema);

// The resolved case as text: every key with its value, "(default)" where not given, then the
// operating points. What `granlub check` prints.
std::string describe(const Case& c);

// True for the common sections (case, grains, walls, walls.bottom, walls.top, cell, operating,
// body_forces, report): not [particles], which only the solvers that `use` it depend on.
bool common_sections_contains(std::string_view name);

// [particles]: what both particle engines share (the initial grains, the cell's depth), declared
// with the common sections because a case may hold it whichever solvers run; what the engines do
// with it: granlub/particles/particle_section.h.
inline constexpr const char* kParticlesSection = "particles";
SectionSpec particles_section();

// Stable 64-bit FNV-1a of bytes, as 16 hex digits.
std::string hash_hex(std::string_view bytes);

}  // namespace granlub
