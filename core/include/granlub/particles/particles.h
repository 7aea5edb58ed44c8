// Particle sets shared by the particle solvers (plugins/liggghts, plugins/yade): the box a case
// point gives them, a deterministic non-overlapping insertion to a requested fill, and the
// initial-configuration file both engines start from, so that their differences come from the
// physics alone (docs/architecture.md, "Data flow").
//
// Geometry (docs/architecture.md): x along the flow, periodic with length cell.length; y across the
// gap, moving wall at y = 0, stationary wall at y = H; z across the width, walls at z = +-W/2 or
// periodic when cell.width = 0 (then the particle solvers use a periodic depth, see ParticleBox).
//
// Initial-configuration file: <results_root>/initial/<point>/particles.csv
//   '#' comment lines (provenance: granlub version, case, point, seed, box, N, fill, `key`),
//   then the header "x,y,z,vx,vy,vz,radius" and one row per grain, SI units, 17 significant digits.
//   A state that carries spins (a run's final state, particle_state.h) has the header
//   "x,y,z,vx,vy,vz,radius,wx,wy,wz" (angular velocity, rad/s); the reader takes either.
#pragma once
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/grain_sizes.h"
#include "granlub/case/particle_box.h"

namespace granlub {

struct Case;
struct OperatingPoint;

// Structure of arrays: one contiguous array per quantity, all of size().
struct ParticleSet {
    std::vector<double> x, y, z;     // centre, m
    std::vector<double> vx, vy, vz;  // velocity, m/s
    std::vector<double> radius;      // m
    std::vector<double> wx, wy, wz;  // angular velocity, rad/s; empty (all zero) unless has_spin()

    std::size_t size() const { return x.size(); }
    bool has_spin() const { return !wx.empty(); }
    void reserve(std::size_t n);
    void clear();
    void push_back(double x_, double y_, double z_, double vx_, double vy_, double vz_, double r);
};

// ParticleBox, the box of a case point, and particle_box(): granlub/case/particle_box.h.

// Bounds of a particle run, so that a typo cannot exhaust memory or overflow a count: granlub
// inserts every grain in one process into one file, and counts steps in 64 bits.
inline constexpr double kMaxGrains = 1e7;
inline constexpr double kMaxSteps = 1e10;

// Number of grains of the sizes' mean volume giving mean solid fraction nu in the box (rounded to
// nearest); the second form for equal grains of diameter d. Throws CaseError above kMaxGrains.
std::size_t grains_for_fill(const ParticleBox& box, const GrainSizes& sizes, double solid_fraction);
std::size_t grains_for_fill(const ParticleBox& box, double diameter, double solid_fraction);

struct InsertionOptions {
    std::uint64_t seed = 1;
    double wall_speed = 0;       // U: initial mean velocity is the linear Couette profile U (1 - y/H)
    double velocity_noise = 0.1; // Gaussian noise per component, standard deviation as a fraction of U
    double size_spread = 0;      // diameters drawn around the mean (grain_sizes.h); 0 = equal grains
    // the grains are inserted below `height` (0: the gap H; the plate's start under load control,
    // where the grains need more room than H), in the ring with `wall_sag` (m) clear of the side
    // walls in addition (a meshed wall's facets inside its circle)
    double height = 0;
    double wall_sag = 0;
    // rough walls (wall_bumps.h): the grains are inserted between y = floor and height - ceiling,
    // and `side` clear of each side wall: clear of the bumps' halves (set by initial_particles)
    double floor = 0;
    double ceiling = 0;
    double side = 0;
};

// Deterministic, overlap-free placement of n grains of mean diameter d (sizes drawn with
// opt.size_spread, grain_sizes.h) in the box: sites of a face-centred-cubic lattice (hexagonal
// x-z layers stacked ABC along y) with the largest spacing a >= d_max that still gives at least n
// sites; n sites are drawn at random, and each grain is displaced at random by at most
// (a - d_i)/2 (so no two grains and no grain and wall overlap). Throws CaseError when n grains cannot fit (the message gives the largest fill that
// can be inserted). Same box, n and options = same particles, bit for bit, on every platform.
ParticleSet insert_grains(const ParticleBox& box, double diameter, std::size_t n, const InsertionOptions& opt);

// Smallest centre distance between any two grains (periodic in x, and z when periodic_z) minus
// the sum of their radii; negative means overlap. O(n) with a cell list. For checks and tests.
double min_gap(const ParticleSet& p, const ParticleBox& box);

// Sum of grain volumes / box volume.
double solid_fraction(const ParticleSet& p, const ParticleBox& box);
// Sum of grain volumes, m^3: n pi d^3 / 6 when all grains are equal (exact in the count).
double solids_volume(const ParticleSet& p);

// <results_root>/initial/<point>/particles.csv
std::filesystem::path initial_particles_path(const std::filesystem::path& results_root, const std::string& point);

void write_particles_csv(const std::filesystem::path& path, const ParticleSet& p,
                         const std::vector<std::string>& comments = {});  // atomic
// Throws Error naming the file and line on a malformed file.
ParticleSet read_particles_csv(const std::filesystem::path& path);
// The comment lines of a particles file, without the leading "# ".
std::vector<std::string> read_particles_comments(const std::filesystem::path& path);

// A run's final state: the grains (with spins) and the top wall's position (the plate under load
// control), in <results_root>/<solver>/<point>/final_state.csv: the particles format above with
// the comments "gap: <m>" and "time: <s>". granlub dem writes it; granlub yade can start from it
// (a warm start, plugins/yade/README.md).
struct ParticleState {
    ParticleSet particles;
    double gap = 0;   // m, top wall position
    // s, the simulated time since the grains' cold start: a run that starts from a state counts on
    // from its time (a chain dt_full -> answer -> continued piece, or dem -> yade, adds up), so that
    // the moving walls' bumps, U time from their layout, are where the grains met them (wall_bumps.h
    // moved_bumps; run.wall_layer places them so)
    double time = 0;
};
// A particle engine's state at the end of a point's run, in its point folder: another run's warm
// start (granlub yade from granlub dem's), and the start of a continued run (until_steady.h).
inline constexpr const char* kFinalStateFile = "final_state.csv";
std::filesystem::path final_state_path(const std::filesystem::path& results_root, const std::string& solver,
                                       const std::string& point);
void write_particle_state(const std::filesystem::path& path, const ParticleState& s,
                          std::vector<std::string> comments = {});  // atomic
// Throws Error naming the file for a malformed file or a missing or non-positive gap.
ParticleState read_particle_state(const std::filesystem::path& path);

struct InitialParticles {
    ParticleSet particles;
    ParticleBox box;
    std::filesystem::path file;
    bool reused = false;  // true: an existing file with the same key was read
    double time = 0;      // s, the state's time when the run starts from one (ParticleState), else 0
};

// The initial configuration of a case point ([cell] geometry = "annulus": ring-frame grains from
// insert_ring_grains, as many as the slice frame's box holds at the fill): reads <results_root>/initial/<point>/particles.csv
// when it exists and was made from the same inputs (its "key" comment matches: box, d, N,
// U, noise, seed); otherwise inserts the grains to the point's solid_fraction and writes the file.
// The first particle solver to run a point creates it, the other reuses it.
// `fill_key` names where p.solid_fraction came from, for error messages. `member`: a realisation
// of a set of seeds keeps its own file, in initial/<point>/<member>/ (seeds.h, initial_subfolder).
InitialParticles initial_particles(const Case& c, const OperatingPoint& p, const std::filesystem::path& results_root,
                                   const InsertionOptions& opt, double periodic_depth = 0,
                                   const std::string& fill_key = "[operating] solid_fraction",
                                   const std::filesystem::path& member = {});
// What initial_particles() would reject (too many grains, more than fit without overlaps), found
// without inserting any: the particle solvers' part of `granlub check`. Throws CaseError.
void check_initial_particles(const Case& c, const OperatingPoint& p, double periodic_depth = 0,
                             const std::string& fill_key = "[operating] solid_fraction",
                             const InsertionOptions& opt = {});

}  // namespace granlub
