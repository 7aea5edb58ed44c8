// The LIGGGHTS deck and data file of one operating point: readable, commented, rerunnable by
// hand with `granlub-liggghts -in in.granlub` in the point's folder.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/particles/particles.h"
#include "settings.h"

namespace granlub::dem {

// File names inside the point's folder.
inline constexpr const char* kDeck = "in.granlub";
inline constexpr const char* kData = "grains.data";
inline constexpr const char* kWallFile = "walls.txt";       // fix ave/time: wall forces per block
inline constexpr const char* kSnapshots = "snapshots.txt";  // dump custom: kSnapshotColumns
inline constexpr const char* kContactsFile = "contacts.txt";  // the persistence snapshots after the run
inline constexpr const char* kSnapshotColumns = "id x y z vx vy vz radius";  // both dumps, sorted by id
inline constexpr const char* kLog = "log.liggghts";
inline constexpr const char* kPlateFile = "plate.txt";      // control = load: plate position per servo update
inline constexpr const char* kPvdFile = "post/particles.pvd";  // --vtk: ParaView collection
// The final state, 17 digits: LIGGGHTS' dump (kFinalColumns) and the plate position under load,
// turned into kFinalState (core particles.h format with spins), another run's starting state.
inline constexpr const char* kFinalDump = "final.txt";
inline constexpr const char* kFinalColumns = "id x y z vx vy vz radius omegax omegay omegaz";
inline constexpr const char* kFinalPlateFile = "final_plate.txt";
inline constexpr const char* kFinalState = kFinalStateFile;  // core particles.h

// Atom types: grains, bottom wall, top wall, side walls (restitution and friction per pair).
enum AtomType { kGrain = 1, kBottom = 2, kTop = 3, kSide = 4 };

// The ring's meshes (geometry = annulus, ring_deck.h), ASCII STL beside the deck.
inline constexpr const char* kRingMeshes[] = {"floor.stl", "top.stl", "outer.stl", "inner.stl"};

// The simulation box of a data file.
struct DataBounds {
    double xlo, xhi, ylo, yhi, zlo, zhi;
};
// The slice's: [0, L) x [0, top] x [-W/2, W/2].
DataBounds slice_bounds(const ParticleBox& box, double top);

// A rough wall's bumps in the data file (core wall_bumps.h): atoms after the grains, of the
// wall's type, at height y in the wall's plane, moving at vx. Their density is the grains' times
// kBumpDensityFactor: LIGGGHTS' pair styles take m_eff = m_i m_j / (m_i + m_j), the impulse model
// moves both atoms of an overlap in inverse proportion to their masses and counts the impulses so
// far through f / m; a bump this heavy is a wall to all of them (m_eff within 1e-6 of the grain's).
inline constexpr double kBumpDensityFactor = 1e6;
// A floor's or top's layer lies in the plane y = `plane`, a side wall's in z = `plane`.
struct BumpAtoms {
    BumpLayer layer;  // where the run starts them
    AtomType type;
    double plane;
    double vx;
    bool side = false;
    double y(std::size_t k) const { return side ? layer.across[k] : plane; }
    double z(std::size_t k) const { return side ? plane : layer.across[k]; }
};
// The point's bumps (floor at speed U, top at the plate's start, side walls at U) for a run that
// starts at time t (InitialParticles::time, 0 from the initial grains): the moving ones U t along
// from their layout (wall_bumps.h moved_bumps), where the starting state's grains met them.
std::vector<BumpAtoms> bump_atoms(const Settings& s, double U, double t);
// The data file's box below the floor and above the box top: room for the bumps' halves.
DataBounds bump_bounds(DataBounds b, const Settings& s);

// LIGGGHTS data file (atom_style granular: id type diameter density x y z; Velocities with the
// spins when p has them), the grains first, then the bumps.
std::string data_file(const ParticleSet& p, const DataBounds& b, double density, const std::string& title,
                      const std::vector<BumpAtoms>& bumps = {});

// The slice's deck: geometry, materials, contact model, walls, body forces, sampling, run.
std::string deck(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleSet& grains,
                 const std::string& provenance);

// Pieces both decks (the slice's and the ring's, ring_deck.h) share.
using DeckLine = std::function<void(const std::string&)>;
// A line writer appending to d that refuses a line holding a control character.
DeckLine deck_lines(std::string& d);
struct ModelText {
    std::string model;     // "model impulse tangential impulse" / "model hertz tangential history"
    std::string settings;  // the impulse model's options, with a leading space
};
ModelText model_text(const Settings& s);
// atom style, boundaries (`boundary`, e.g. "p f f"), units, the rank grid (`processors` with its
// comment), the grains' data file and the neighbour lists
void engine_block(const Settings& s, const DeckLine& line, const std::string& boundary, const std::string& processors);
// materials per atom type, pair style, time step
void contact_block(const Case& c, const OperatingPoint& p, const Settings& s, const DeckLine& line);
// after the run: contact-persistence snapshots (result outputs closed: fixes `walls`, `plate`, dump `cg`)
void persistence_block(const Settings& s, const DeckLine& line);
// The particle snapshots (and VTK dumps) and the thermo output both decks write before their runs.
void output_block(const Settings& s, const DeckLine& line);
// The servo's rule, both decks': the top's window force `force` (a fix output, `sign` "-" when it
// is the wall's force on the grains) over A gives P_top, the clamped relative error moves the
// plate to hnew = hplate + gain d err within [gap_min, gap_max]; `update` counts the windows.
void servo_rule_block(const Settings& s, const DeckLine& line, const std::string& force, const std::string& sign,
                      double A, double d);
// servo_plate = "weight": the top plane's words for fix wall/gran/moving, `normal_load F M lo hi`
// (F = -P A along y, M = plate_mass x the grains' mass, lo hi = gap_min gap_max) and, for a rough
// top, `carry tbump`; the plate's position and velocity are the fix's f_<id>[1], f_<id>[2].
std::string weight_plate_words(const Case& c, const Settings& s, const ParticleSet& grains, double area,
                               bool carry_bumps);
// The weighted plate's run: its position every servo_every steps into the plate file, one run of
// s.steps, and hplate = where it ended (the final state prints it).
void weight_plate_run(const Settings& s, const DeckLine& line, const std::string& top_fix);
// the final state at 17 digits (and the plate position under load)
void final_state_block(const Settings& s, const DeckLine& line);
// Both decks' ending without load control (a fixed top): the run, then the persistence snapshots
// and the final state. Returns false, writing nothing, under load control (the servo loop ends it).
bool fixed_top_ending(const Settings& s, const DeckLine& line);

}  // namespace granlub::dem
