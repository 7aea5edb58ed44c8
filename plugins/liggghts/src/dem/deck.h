// The LIGGGHTS deck and data file of one operating point: readable, commented, rerunnable by
// hand with `granlub-liggghts -in in.granlub` in the point's folder.
#pragma once
#include <string>

#include "granlub/case.h"
#include "granlub/particles.h"
#include "settings.h"

namespace granlub::dem {

// File names inside the point's folder.
inline constexpr const char* kDeck = "in.granlub";
inline constexpr const char* kData = "grains.data";
inline constexpr const char* kWallFile = "walls.txt";       // fix ave/time: wall forces per block
inline constexpr const char* kSnapshots = "snapshots.txt";  // dump custom: kSnapshotColumns
inline constexpr const char* kContactsFile = "contacts.txt";  // the persistence snapshots after the run
inline constexpr const char* kSnapshotColumns = "id x y z vx vy vz radius";  // both dumps, sorted by id
inline constexpr const char* kRefineDir = "dt_half";  // [dem] refine_dt: the rerun at time_step / 2
inline constexpr const char* kLog = "log.liggghts";
inline constexpr const char* kPlateFile = "plate.txt";      // control = load: plate position per servo update
inline constexpr const char* kPvdFile = "post/particles.pvd";  // --vtk: ParaView collection
// The final state, 17 digits: LIGGGHTS' dump (kFinalColumns) and the plate position under load,
// turned into kFinalState (core particles.h format with spins), another run's starting state.
inline constexpr const char* kFinalDump = "final.txt";
inline constexpr const char* kFinalColumns = "id x y z vx vy vz radius omegax omegay omegaz";
inline constexpr const char* kFinalPlateFile = "final_plate.txt";
inline constexpr const char* kFinalState = "final_state.csv";  // final_state_path() of core particles.h

// Atom types: grains, bottom wall, top wall, side walls (restitution and friction per pair).
enum AtomType { kGrain = 1, kBottom = 2, kTop = 3, kSide = 4 };

// LIGGGHTS data file (atom_style granular: id type diameter density x y z; Velocities with the
// spins when p has them).
std::string data_file(const ParticleSet& p, const ParticleBox& box, double density, const std::string& title);

// The deck: geometry, materials, contact model, walls, body forces, sampling, run.
std::string deck(const Case& c, const OperatingPoint& p, const Settings& s, std::size_t grains,
                 const std::string& provenance);

}  // namespace granlub::dem
