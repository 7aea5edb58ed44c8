/* ----------------------------------------------------------------------
    granlub: the contacts of model impulse / tangential impulse with
    `iterate on`, handed from the contact models (pair gran, fix wall/gran)
    to the solver (fix impulse/solve, plugins/liggghts/src/fix_impulse_solve.*).

    With `iterate on` the models compute no force: for every touching pair or
    grain-wall contact of the step they append one ImpulseContact (geometry,
    materials, where its history and the wall's stored force live), and fix
    impulse/solve, after all forces of the step are known, solves all of them
    together (doc/fix_impulse_solve.txt). With `iterate off` (default) nothing
    here is used: the models are Sawyer & Tichy's single pass.

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree.
------------------------------------------------------------------------- */

#ifndef GRANLUB_IMPULSE_CONTACTS_H_
#define GRANLUB_IMPULSE_CONTACTS_H_

#include <string>
#include <vector>

namespace LAMMPS_NS {
class FixMeshSurface;
}

namespace LIGGGHTS {
namespace ContactModels {

// Values per contact kept in LIGGGHTS' contact history (pair and wall alike): the accumulated
// normal impulse, the tangential impulse vector (on grain i), the step they were solved at, and the
// normal impulse of the last step the contact was pressed without restitution (its load).
enum ImpulseHistory { kHistPn = 0, kHistPt = 1, kHistStep = 4, kHistLoad = 5, kImpulseHistoryValues = 6 };

// A grain pair's force (fx, fy, fz) on grain i and its opposite on grain j, as both models add
// theirs in the single pass (ForceData's delta_F).
template <class ForceData>
inline void add_pair_force(ForceData & i_forces, ForceData & j_forces, double fx, double fy, double fz)
{
  i_forces.delta_F[0] += fx;
  i_forces.delta_F[1] += fy;
  i_forces.delta_F[2] += fz;
  j_forces.delta_F[0] -= fx;
  j_forces.delta_F[1] -= fy;
  j_forces.delta_F[2] -= fz;
}

// The id of the fix impulse/solve that pair_style gran makes when a deck iterates (the default)
// without one; the fix's messages name the way back to the single pass when they refuse a deck.
static const char* const kMadeSolverId = "granlub_impulse_solve";

struct ImpulseContact {
  // Fields read in every velocity sweep come first, together (one or two cache lines per contact:
  // the sweeps are the solver's hot loop). F: filled by the contact models when the contact is
  // found; S: the solver's state.
  int i;               // F: the grain (owned by this rank)
  int j;               // F: the other grain (owned or ghost); -1 for a wall
  double en[3];        // F: unit normal from j (or the wall) to i
  double ri, rj;       // F: radii; rj = 0 for a wall
  double mu;           // F: coefficientFriction (0 without tangential impulse)
  double mn;           // S: normal effective mass
  double wn;           // S: its inverse, 1/m_i + 1/m_j (0 between two kinematic atoms)
  double kt;           // S: 1 / (tangential inverse mass)
  double tn;           // S: target normal velocity
  double tt[3];        // S: target slip
  double pn, pt[3];    // S: accumulated impulses
  double vwall[3];     // F: a wall's velocity at the contact (0 for grain pairs)
  bool boundary;       // S: a grain pair with j a ghost (periodic image or another rank's)
  bool impact;         // S: restitution acts on this contact this step
  bool separate;       // F: `separate on`: correct the overlap (pseudo-velocities)
  int tri;             // F: the mesh element
  double overlap;      // F: r_i + r_j - |x_i - x_j| (wall: r_i - distance), > 0 or 0
  double gap;          // F: speculative on: the surfaces' distance of a close, not touching contact (> 0), else 0
  double e;            // F: coefficientRestitution of the two types
  double bounce;       // F: bounce_speed: restitution only above this approach speed
  double beta0;        // F: Walton's tangential restitution (tangential impulse)
  double delta[3];     // F: a mesh wall: the contact vector LIGGGHTS hands to the mesh's stress
  double * history;    // F: kImpulseHistoryValues values in the contact history, or NULL
  double * wallforce;  // F: a wall with store_force: the wall's force on grain i this step, or NULL
  LAMMPS_NS::FixMeshSurface * mesh;  // F: a mesh wall: the mesh (per-element forces), or NULL
  double dn, dt[3];    // S: the change of this sweep (boundary contacts: applied after all were computed)
  double b;            // S: target separating pseudo-velocity (overlap correction)
  double q;            // S: accumulated pseudo-impulse
  double trest;        // S: speculative on: Newton's target of an impact, applied after the solve (0: none)
  double mu_close;     // S: speculative on: mu, kept while a close contact's friction waits for the rebound pass

  // Only the fields a model leaves unset for some contacts (friction without tangential impulse, the
  // gap unless close, a wall's fields on a pair); every other F field is written by every collect and
  // every S field by the solver before it is read. Not the whole record: zeroing ~370 bytes per
  // contact per step was a tenth of a resting bed's time (perf, heatTransfer_1 at rest).
  ImpulseContact()
      : i(0), j(-1), mu(0.0), tri(-1), gap(0.0), beta0(0.0), history(NULL), wallforce(NULL), mesh(NULL)
  {
    vwall[0] = vwall[1] = vwall[2] = 0.0;
    delta[0] = delta[1] = delta[2] = 0.0;
  }
};

// The contacts of one step, filled by the models and read by the solver. A model reaches it
// through the solver fix (dynamic_cast of the fix found by style "impulse/solve").
class ImpulseContactSink {
public:
  virtual ~ImpulseContactSink() {}

  // the pair style's pass starts every step's collection (pair gran runs before the walls)
  inline void begin_collection() { contacts_.clear(); speculative_ = false; }

  inline ImpulseContact & add_contact() {
    contacts_.emplace_back();  // built in place; capacity is kept across steps: no allocation once warm
    return contacts_.back();
  }

  // speculative on: a close contact with its gap, just added (the step's solve then applies
  // restitution after the solve: fix_impulse_solve.cpp)
  inline void mark_close(double gap) { contacts_.back().gap = gap; speculative_ = true; }

  // tangential impulse: friction of the contact just added by model impulse
  inline void set_friction(double mu, double beta0) {
    if (contacts_.empty()) return;
    contacts_.back().mu = mu;
    contacts_.back().beta0 = beta0;
  }

protected:
  ImpulseContactSink() : speculative_(false) {}
  std::vector<ImpulseContact> contacts_;
  bool speculative_;  // this step's contacts include close ones (speculative on)
};

// The solver a model hands its contacts to: the deck's own fix impulse/solve if it has one, else
// the one pair_style gran made (kMadeSolverId), which then steps aside. M is LAMMPS' Modify (a
// template, so this header needs neither modify.h nor fix.h).
template <class M>
inline ImpulseContactSink * find_solver(M * modify)
{
  ImpulseContactSink * made = NULL;
  for (int k = 0; k < modify->nfix; k++) {
    if (std::string(modify->fix[k]->style) != "impulse/solve") continue;
    ImpulseContactSink * s = dynamic_cast<ImpulseContactSink *>(modify->fix[k]);
    if (std::string(modify->fix[k]->id) != kMadeSolverId) return s;
    made = s;
  }
  return made;
}

// Physics the rigid contacts cannot give: fix heat/gran (heat/gran/conduction) conducts through
// the contact area of an elastic overlap (LIGGGHTS' contact_area overlap/constant/projection),
// and a rigid contact has none: its overlap is the solver's slop or one step's approach, so the
// heat flow would be a fraction of an elastic contact's and change with the time step (measured on
// LIGGGHTS' heatTransfer_1 tutorial: docs/measurements/impulse-vs-hertz.md). Refused at every
// run (M, E: LAMMPS' Modify and Error; a template, as find_solver).
template <class M, class E>
inline void refuse_contact_area_fixes(M * modify, E * error, const std::string & where)
{
  for (int k = 0; k < modify->nfix; k++)
    if (std::string(modify->fix[k]->style).compare(0, 9, "heat/gran") == 0)
      error->all(__FILE__, __LINE__, ("model impulse (" + where + ") cannot serve fix " + modify->fix[k]->id + " " +
                                      modify->fix[k]->style + ": heat conduction between grains needs a contact "
                                      "area, and a rigid contact has none (its overlap is the solver's slop or one "
                                      "step's approach, so the heat flow would depend on the time step); use an "
                                      "elastic model (hertz, hooke) for heat transfer").c_str());
}

}
}

#endif // GRANLUB_IMPULSE_CONTACTS_H_
