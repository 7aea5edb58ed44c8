/* ----------------------------------------------------------------------
    granlub: normal part of the Sawyer & Tichy (2001) impulse operator for
    LIGGGHTS 3.8 (pair gran and fix wall/gran).

    Sawyer, W.G. & Tichy, J.A. 2001, "Lubrication with grain flow: continuum
    theory, particle simulations, comparison with experiment", J. Tribol.
    123:777-784, Eqs. 18-24 (wall), same construction between grains.

    When two surfaces overlap and approach (v_n < 0), a time-averaged impulsive
    force acts along the line of centres for one time step:

        F_n = m_eff (1 + e) |v_n| / dt            (S&T 2001, Eq. 19)

    m_eff = m_i m_j / (m_i + m_j) between grains, m_i against a wall, e from
    `coefficientRestitution`. With velocity Verlet the impulse F_n dt reaches
    the velocities as two half kicks, and the next force evaluation sees
    v_n' = -e v_n exactly. There is no stiffness: kn = kt = 0.

    Simultaneous contacts are resolved one after the other, as Sawyer & Tichy
    do: v_n is taken from the velocities plus the impulses of the contacts
    already resolved in this step (the forces accumulated so far in f and
    torque, times dt/m). This Gauss-Seidel sweep never raises the kinetic
    energy (each step is a binary collision with e <= 1); resolving all
    contacts from the old velocities at once (Jacobi) overshoots in dense
    packings and blows up. An isolated collision is unaffected. (Our choice
    of implementation of S&T's sequential resolution.) A pair across a
    periodic or processor boundary (one grain a ghost) is resolved from the
    velocities at the start of the step: under newton off both owners compute
    it, each seeing only its own grain's impulses so far, and sequential
    impulses would differ between the two sides, so momentum would not be
    conserved (measured: docs/measurements/enduring-contacts.md, "The recorded wall
    forces balance the grains' momentum"). From the same start-of-step state
    both sides give the same impulse, equal and opposite in the velocities.
    Their positions agree only with boundary_start on (below).

    What Sawyer & Tichy state and what we add. S&T define the operator for
    a collision (Eq. 19) and resolve overlaps one after the other; they say
    nothing about grains that stay in contact. We add, as settings:

    separate on|off (default on; our assumption). Also removes each overlap
    by moving the two grains apart along e_n, in inverse proportion to their
    masses (a wall stays), without touching the velocities: a position
    projection kept apart from the momentum, as split-impulse and
    contact-dynamics solvers do (Catto 2005; Acary 2013, CMAME 256:224).
    Contacts are found by overlap only, so without it grains pressed
    together by gravity, a load or the shear stay overlapped, are re-hit
    every step and sink into each other (measured on a resting bed and on
    the sawyer2001 cell under load: docs/measurements/enduring-contacts.md, "Rigid
    contacts under a load").

    bounce_speed V (default 0; our assumption). Restitution only for
    approach speeds above V, e = 0 below, as Chrono, Bullet and Box2D do for
    resting contacts. It neither changes the answer nor speeds up its
    convergence in dt (measured: the same page), so it is off by default.

    boundary_start on|off (default off; ours). With iterate off and
    separate (or impact_time) on, a pair across a periodic or processor
    boundary takes its geometry from the positions as the pair pass began:
    `separate` moves the owned grain during the pass, not its image on the
    other side, so without it the two owners see two geometries and
    momentum is made (impulse_boundary.h). Off keeps the sequential
    geometry of every earlier result; on costs about a quarter more per step.

    iterate on|off (default on; ours). With iterate on this model computes no
    force: it hands every contact it finds (geometry, e, bounce_speed,
    separate, where its history and the wall's stored force live;
    impulse_contacts.h) to fix impulse/solve, which solves all contacts of
    the step together by projected Gauss-Seidel with accumulated, clamped
    impulses and corrects overlaps with pseudo-velocities (Moreau 1988; Jean
    1999; Catto 2005; doc/fix_impulse_solve.txt). The contact history then
    keeps each contact's impulses (warm start). iterate off is Sawyer &
    Tichy's single pass above. The default is on because only the solved
    contacts let a pile, a hopper or a packing come to rest (the single pass
    keeps grains under gravity jittering: docs/measurements/enduring-contacts.md,
    "Piles at rest"); the single pass is about 9x cheaper
    and gives the same stresses in sheared cells, so granlub's cases choose
    it there (`[dem] contact_solve`). Without a fix impulse/solve in the
    deck, pair_style gran makes one with its defaults (id
    granlub_impulse_solve, at the pair_style command, so thermo_style can
    name it; a fix the deck writes later takes over). A pair style and every wall
    with model impulse must agree: all iterate on with one fix
    impulse/solve, or all off without one (checked at each run).

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree (with
    impulse_contacts.h, and fix_impulse_solve.* for iterate on, the default).
------------------------------------------------------------------------- */

#if defined(GRANLUB_COMBINATIONS)
// The combinations the plugin registers, in the form of LIGGGHTS' style_contact_model_user.whitelist
// (the plugin's registration and an in-tree build read these lines: README.md of the plugin).
GRAN_MODEL(IMPULSE, TANGENTIAL_IMPULSE, COHESION_OFF, ROLLING_OFF, SURFACE_DEFAULT)
GRAN_MODEL(IMPULSE, TANGENTIAL_OFF, COHESION_OFF, ROLLING_OFF, SURFACE_DEFAULT)
#elif defined(NORMAL_MODEL)
NORMAL_MODEL(IMPULSE,impulse,50)
#else
#ifndef NORMAL_MODEL_IMPULSE_H_
#define NORMAL_MODEL_IMPULSE_H_

#include "contact_models.h"
#include "normal_model_base.h"
#include "global_properties.h"
#include "force.h"
#include "update.h"
#include "error.h"
#include "atom.h"
#include "modify.h"
#include "fix.h"
#include "fix_wall_gran.h"
#include "comm.h"
#include <cstdio>
#include "impulse_boundary.h"
#include "impulse_contacts.h"
#include "impulse_impact_time.h"
#include "impulse_speculative.h"
#include "neighbor.h"
#include <cmath>
#include <string>

namespace LIGGGHTS {
namespace ContactModels
{
  template<>
  class NormalModel<IMPULSE> : public NormalModelBase
  {
  public:
    NormalModel(LAMMPS * lmp, IContactHistorySetup * hsetup, class ContactModelBase * c) :
      NormalModelBase(lmp, hsetup, c),
      coeffRest(NULL),
      separate(true),
      bounceSpeed(0.0),
      iterate(true),
      impactTime(false),
      speculative(false),
      historyOffset(-1),
      wall(dynamic_cast<LAMMPS_NS::FixWallGran *>(hsetup)),
      sink(NULL),
      boundaryStartOn(false),
      startRecorded(false),
      warnedBeyond(false)
    {}

    // separate on (default): also remove the overlap (see above); off: velocities only.
    // bounce_speed V: restitution only for approach speeds above V (below, e = 0)
    // iterate on (default): hand the contacts to fix impulse/solve (above); off: single pass
    inline void registerSettings(Settings & settings)
    {
      settings.registerOnOff("separate", separate, true);
      settings.registerDoubleSetting("bounce_speed", bounceSpeed, 0.0);
      settings.registerOnOff("iterate", iterate, true);
      settings.registerOnOff("impact_time", impactTime, false);
      settings.registerOnOff("speculative", speculative, false);  // impulse_speculative.h
      settings.registerOnOff("boundary_start", boundaryStartOn, false);  // impulse_boundary.h
    }
    inline void postSettings(IContactHistorySetup * hsetup, ContactModelBase * cmb)
    {
      if (!(bounceSpeed >= 0.0))
        error->all(FLERR, "model impulse: bounce_speed must be >= 0 (m/s; 0 = restitution at every speed)");
      if (impactTime && iterate)
        error->all(FLERR, "model impulse: impact_time on is an option of the single pass: it needs 'iterate off' "
                          "(allowed: impact_time off with iterate on or off, impact_time on with iterate off)");
      if (boundaryStartOn && iterate)
        error->all(FLERR, "model impulse: boundary_start on is an option of the single pass (the iterated solve "
                          "resolves boundary pairs from one state already): it needs 'iterate off' (allowed: "
                          "boundary_start off with iterate on or off, boundary_start on with iterate off)");
      if (speculative && impactTime)
        error->all(FLERR, "model impulse: speculative on and impact_time on are two alternatives of the single pass "
                          "(allowed: at most one of them on)");
      if (!iterate) return;
      // the solver's accumulated impulses per contact (warm start, and the force of a run's setup)
      historyOffset = hsetup->add_history_value("impulse_n", "0");
      hsetup->add_history_value("impulse_tx", "1");
      hsetup->add_history_value("impulse_ty", "1");
      hsetup->add_history_value("impulse_tz", "1");
      hsetup->add_history_value("impulse_step", "0");
      hsetup->add_history_value("impulse_load", "0");
      cmb->add_history_offset("impulse", historyOffset);
      // the solver exists from the pair style on, so thermo_style can name it before a run
      if (!wall && !find_sink()) make_sink();
    }

    inline void connectToProperties(PropertyRegistry & registry)
    {
      registry.registerProperty("coeffRest", &MODEL_PARAMS::createCoeffRest);
      registry.connect("coeffRest", coeffRest, "model impulse");
      // the operator works on the real grains' masses; coarse-graining would rescale them
      if (force->cg_active())
        error->cg(FLERR, "model impulse");
      refuse_contact_area_fixes(modify, error, where());
      // every run: the solver fix may have been made or removed since the last one. The pair
      // style (its init runs before the fixes' init) makes one with the defaults if the deck has
      // none; a wall model's init comes later and finds it.
      sink = find_sink();
      // speculative on: pairs and walls that are close but not touching reach surfacesClose
      if (speculative) neighbor->register_contact_dist_factor(kSpeculativeDistance);
      // the single pass moving positions: boundary pairs that touched as the pass began (impulse_boundary.h)
      if (moves_in_pass()) neighbor->register_contact_dist_factor(kBoundaryDistance);
      warnedBeyond = false;
      if (iterate && !sink && !wall) sink = make_sink();
      if (iterate && !sink)
        error->all(FLERR, ("model impulse (" + where() + ") iterates ('iterate on', the default) but the run has no "
                           "fix impulse/solve: the solver needs pair_style gran model impulse at iterate on, which "
                           "makes one; with another pair model, or the pair style at 'iterate off', give every "
                           "impulse wall 'iterate off' too (Sawyer & Tichy's single pass)").c_str());
      if (!iterate && sink)
        error->all(FLERR, ("model impulse (" + where() + ") has 'iterate off', but fix impulse/solve solves every "
                           "impulse contact of the run: every pair gran and fix wall/gran with model impulse needs "
                           "'iterate on' (the default), or none of them and no fix impulse/solve").c_str());
    }

    // no elastic law; only fix heat/gran/conduction asks for this
    inline double stressStrainExponent() { return 1.; }

    inline void surfacesIntersect(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
      if (sidata.contact_flags)
        *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
      if (iterate) {
        collect(sidata);
        return;
      }
      if (start_geometry(sidata)) resolve_boundary(sidata, i_forces, j_forces, false);
      else single_pass(sidata, i_forces, j_forces);
    }

    // Sawyer & Tichy's single pass on a touching contact (iterate off)
    inline void single_pass(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
      // approaching only: v_n = (v_i - v_j).e_n < 0 (e_n points from j to i), with the
      // impulses of the contacts resolved earlier in this step (sequential resolution) -- except
      // across a periodic or processor boundary (see boundary_pair)
      const double dt = update->dt;
      const double vn = with_resolved_impulses(sidata, sidata.vn);
      double Fn = 0.0;
      if (vn < 0.0) {
        const double e = -vn > bounceSpeed ? coeffRest[sidata.itype][sidata.jtype] : 0.0;
        Fn = sidata.meff * (1.0 + e) * (-vn) / dt;   // S&T 2001, Eq. 19
      }
      if (impactTime && Fn > 0.0) replay_impact(sidata, Fn);
      else if (separate) remove_overlap(sidata);
      sidata.Fn = Fn;
      sidata.kn = 0.0;
      sidata.kt = 0.0;
      sidata.gamman = 0.0;
      sidata.gammat = 0.0;
      if (Fn == 0.0) return;
      add_normal_force(sidata, Fn, i_forces, j_forces);
    }

    inline void surfacesClose(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
      if (scdata.contact_flags)
        *scdata.contact_flags &= ~CONTACT_NORMAL_MODEL;
      if (boundaryStartOn) {
        static_cast<SurfacesIntersectData &>(scdata).Fn = 0.0;  // tangential impulse may read it
        if (start_geometry(scdata)) {
          resolve_boundary(static_cast<SurfacesIntersectData &>(scdata), i_forces, j_forces, true);
          return;
        }
      }
      if (!speculative) return;
      if (iterate) collect_close(scdata);
      else speculate(scdata, i_forces, j_forces);
    }

    // iterate on: the pair style's pass (once per step, before the walls') starts the step's contacts
    inline void beginPass(SurfacesIntersectData & sidata, ForceData &, ForceData &)
    {
      if (iterate && sidata.computeflag && !sidata.is_wall) sink->begin_collection();
      // the single pass: where the owned grains were as the pass began (impulse_boundary.h)
      startRecorded = moves_in_pass() && sidata.computeflag && !sidata.is_wall;
      if (startRecorded) boundaryStart.record(atom->x, atom->nlocal);
    }
    inline void endPass(SurfacesIntersectData &, ForceData &, ForceData &)
    {
      if (!startRecorded) return;
      startRecorded = false;
      const int moved = boundaryStart.beyond(atom->x, atom->radius, atom->nlocal);
      if (moved == 0 || warnedBeyond) return;
      warnedBeyond = true;
      char msg[320];
      std::snprintf(msg, sizeof(msg), "model impulse: at step %lld separate moved %d grains by more than %g of their "
                    "radius within one pass: a pair of theirs across a periodic or processor boundary may have been "
                    "resolved on one side only (impulse_boundary.h; a smaller time step keeps the moves small; warned "
                    "once per run)", static_cast<long long>(update->ntimestep), moved, kBoundaryDistance - 1.0);
      error->warning(FLERR, msg);
    }

    // One grain a ghost: resolved from the start-of-step velocities alone, identically by both
    // owners (newton off) or once (newton on), so the two grains get equal and opposite impulses.
    inline bool boundary_pair(const SurfacesIntersectData & sidata) const
    {
      return !sidata.is_wall && sidata.j >= atom->nlocal;
    }

  private:
    // boundary_start on and the single pass moves grains during the pass (separate, impact_time's replay)
    inline bool moves_in_pass() const
    {
      return boundaryStartOn && !iterate && !wall && (separate || impactTime);
    }

    // a boundary pair of a force pass whose start positions were recorded: its geometry is theirs
    // (impulse_boundary.h), both in the overlap path and in the close one
    inline bool start_geometry(const SurfacesCloseData & scdata) const
    {
      const SurfacesIntersectData & sidata = static_cast<const SurfacesIntersectData &>(scdata);
      return startRecorded && sidata.computeflag && boundary_pair(sidata);
    }

    // A boundary pair from the positions as the pass began: the single pass if it touched then, the
    // speculative rule if it was close (speculative on), else nothing. From surfacesClose (close:
    // pair gran has not set the masses and spins) or from surfacesIntersect.
    inline void resolve_boundary(SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces,
                                 bool close)
    {
      sidata.Fn = sidata.kn = sidata.kt = sidata.gamman = sidata.gammat = 0.0;
      const double reach = speculative ? kSpeculativeDistance : 1.0;
      if (!boundaryStart.geometry(sidata, atom->x, reach)) return;
      if (close) {
        sidata.mi = atom->rmass[sidata.i];
        sidata.mj = atom->rmass[sidata.j];
        sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
        sidata.omega_i = atom->omega[sidata.i];
        sidata.omega_j = atom->omega[sidata.j];
      }
      if (sidata.r < sidata.radsum) {
        single_pass(sidata, i_forces, j_forces);
        if (sidata.Fn > 0.0) sidata.has_force_update = true;
      } else if (speculative) {
        speculate(sidata, i_forces, j_forces);
      }
    }

    // v_n plus the impulses of the contacts resolved earlier in this step (the forces accumulated so
    // far in f, times dt/m) -- except across a periodic or processor boundary (see boundary_pair)
    inline double with_resolved_impulses(const SurfacesIntersectData & sidata, double vn) const
    {
      if (boundary_pair(sidata)) return vn;
      const double dt = update->dt;
      const double * const fi = atom->f[sidata.i];
      vn += dt / sidata.mi * (fi[0] * sidata.en[0] + fi[1] * sidata.en[1] + fi[2] * sidata.en[2]);
      if (!sidata.is_wall) {
        const double * const fj = atom->f[sidata.j];
        vn -= dt / sidata.mj * (fj[0] * sidata.en[0] + fj[1] * sidata.en[1] + fj[2] * sidata.en[2]);
      }
      return vn;
    }

    // the normal force Fn along e_n on grain i, its opposite on grain j (a wall: times the area ratio)
    inline void add_normal_force(const SurfacesIntersectData & sidata, double Fn, ForceData & i_forces,
                                 ForceData & j_forces) const
    {
      if (sidata.is_wall) {
        const double Fa = Fn * sidata.area_ratio;
        i_forces.delta_F[0] += Fa * sidata.en[0];
        i_forces.delta_F[1] += Fa * sidata.en[1];
        i_forces.delta_F[2] += Fa * sidata.en[2];
      } else {
        add_pair_force(i_forces, j_forces, Fn * sidata.en[0], Fn * sidata.en[1], Fn * sidata.en[2]);
      }
    }

    // speculative on: a close, not touching pair or wall contact (impulse_speculative.h). Both callers
    // of surfacesClose (pair gran's loop, fix wall/gran's compute_force) pass a SurfacesIntersectData;
    // fix wall/gran has filled its geometry and masses (r, e_n, m_i), pair gran has not: set here. Fn
    // is always written: tangential impulse reads it next (a stale value would be another pair's).
    inline void speculate(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
      SurfacesIntersectData & sidata = static_cast<SurfacesIntersectData &>(scdata);
      sidata.Fn = 0.0;
      if (!sidata.computeflag) return;  // compute pair/gran/local's re-run: no impulse twice
      const double gap = close_geometry(sidata);
      // the approach speed with the impulses resolved so far this step (as surfacesIntersect)
      const double dt = update->dt;
      double vn = 0.0;
      for (int d = 0; d < 3; d++) vn += (sidata.v_i[d] - sidata.v_j[d]) * sidata.en[d];
      vn = with_resolved_impulses(sidata, vn);
      sidata.vn = vn;
      const double e = -vn > bounceSpeed ? coeffRest[sidata.itype][sidata.jtype] : 0.0;
      const double dv = speculative_dv(gap, vn, dt, e);
      if (!(dv > 0.0)) return;
      const double Fn = sidata.meff * dv / dt;
      sidata.Fn = Fn;
      sidata.kn = sidata.kt = sidata.gamman = sidata.gammat = 0.0;
      sidata.has_force_update = true;
      add_normal_force(sidata, Fn, i_forces, j_forces);
    }

    // A close, not touching contact (surfacesClose): a pair's geometry and masses, which pair gran
    // has not set (fix wall/gran has); returns the surfaces' gap (>= 0).
    inline double close_geometry(SurfacesIntersectData & sidata) const
    {
      double gap;
      if (sidata.is_wall) {
        gap = sidata.r - sidata.radi;
      } else {
        const int i = sidata.i, j = sidata.j;
        const double r = std::sqrt(sidata.rsq);
        sidata.r = r;
        sidata.rinv = 1.0 / r;
        for (int d = 0; d < 3; d++) sidata.en[d] = sidata.delta[d] / r;
        sidata.mi = atom->rmass[i];
        sidata.mj = atom->rmass[j];
        sidata.meff = sidata.mi * sidata.mj / (sidata.mi + sidata.mj);
        sidata.omega_i = atom->omega[i];
        sidata.omega_j = atom->omega[j];
        gap = r - sidata.radi - sidata.radj;
      }
      return gap > 0.0 ? gap : 0.0;
    }

    // speculative on with iterate on: a close pair or wall contact goes to fix impulse/solve with its
    // gap, every one within the contact distance (whether it closes is the solve's answer: the
    // other contacts' impulses may push the grains together). Its history is kept across neighbour
    // rebuilds like a touching contact's (the flag, as LIGGGHTS' capillary cohesion models do), so a
    // contact pressed at a gap warm-starts.
    inline void collect_close(SurfacesCloseData & scdata)
    {
      SurfacesIntersectData & sidata = static_cast<SurfacesIntersectData &>(scdata);
      sidata.Fn = 0.0;
      if (!sidata.computeflag) return;
      const double gap = close_geometry(sidata);
      if (sidata.contact_flags) *sidata.contact_flags |= CONTACT_NORMAL_MODEL;
      collect(sidata);
      sink->mark_close(gap);
    }

    // iterate on: the contact, for fix impulse/solve; no force here. Only a real force pass
    // (computeflag) collects: compute pair/gran/local re-runs the loops with computeflag 0.
    inline void collect(SurfacesIntersectData & sidata)
    {
      sidata.Fn = 0.0;
      sidata.kn = 0.0;
      sidata.kt = 0.0;
      sidata.gamman = 0.0;
      sidata.gammat = 0.0;
      if (!sidata.computeflag) return;
      ImpulseContact & c = sink->add_contact();
      c.i = sidata.i;
      c.en[0] = sidata.en[0];
      c.en[1] = sidata.en[1];
      c.en[2] = sidata.en[2];
      c.ri = sidata.radi;
      c.e = coeffRest[sidata.itype][sidata.jtype];
      c.bounce = bounceSpeed;
      c.separate = separate;
      c.gap = 0.0;
      c.history = sidata.contact_history ? sidata.contact_history + historyOffset : NULL;
      if (sidata.is_wall) {
        c.j = -1;
        c.rj = 0.0;
        c.overlap = sidata.radi - sidata.r;
        c.vwall[0] = sidata.v_j[0];
        c.vwall[1] = sidata.v_j[1];
        c.vwall[2] = sidata.v_j[2];
        c.wallforce = wall && wall->store_force() ? wall->fix_wallforce()->array_atom[sidata.i] : NULL;
        c.mesh = sidata.fix_mesh;
        c.tri = sidata.j;
        // LIGGGHTS hands the mesh's stress module the negated contact vector (fix_wall_gran_base.h)
        c.delta[0] = -sidata.delta[0];
        c.delta[1] = -sidata.delta[1];
        c.delta[2] = -sidata.delta[2];
      } else {
        c.j = sidata.j;
        c.rj = sidata.radj;
        c.overlap = sidata.radi + sidata.radj - sidata.r;
      }
      if (c.overlap < 0.0) c.overlap = 0.0;
    }

    inline ImpulseContactSink * find_sink() const
    {
      return find_solver(modify);
    }

    // iterate on without a fix impulse/solve in the deck: the solver with its defaults. Made at
    // the pair_style command, or else from the pair style's init (before the fixes' init, as
    // LIGGGHTS' pair gran makes its contact history fix), so the run's fix lists include it; it
    // stays for later runs.
    inline ImpulseContactSink * make_sink()
    {
      std::string id(kMadeSolverId), group("all"), style("impulse/solve");
      char * args[] = {&id[0], &group[0], &style[0]};
      modify->add_fix(3, args);
      if (comm->me == 0) {
        const std::string msg = "model impulse: iterate on (the default): made 'fix " + id + " all impulse/solve' "
                                "with its defaults (thermo_style can read its state as f_" + id + "[1..10]; a fix "
                                "impulse/solve the deck writes takes over); 'iterate off' is Sawyer & Tichy's single "
                                "pass\n";
        if (screen) fputs(msg.c_str(), screen);
        if (logfile) fputs(msg.c_str(), logfile);
      }
      return find_sink();
    }

    // the command this model belongs to, for messages
    inline std::string where() const
    {
      return wall ? std::string("fix wall/gran ") + wall->id : std::string("pair_style gran");
    }

    // Moves the surfaces apart along e_n until they touch, in inverse proportion to the masses
    // (a wall does not move). Only local grains are moved; with newton off each owner moves
    // its own grain of a pair that straddles processors.
    inline void remove_overlap(const SurfacesIntersectData & sidata)
    {
      double ** const x = atom->x;
      const int i = sidata.i;
      if (sidata.is_wall) {
        const double d = sidata.radi - sidata.r;
        if (d <= 0.0) return;
        x[i][0] += d * sidata.en[0];
        x[i][1] += d * sidata.en[1];
        x[i][2] += d * sidata.en[2];
        return;
      }
      const double d = sidata.radi + sidata.radj - sidata.r;
      if (d <= 0.0) return;
      const double wi = sidata.mj / (sidata.mi + sidata.mj), wj = 1.0 - wi;
      x[i][0] += wi * d * sidata.en[0];
      x[i][1] += wi * d * sidata.en[1];
      x[i][2] += wi * d * sidata.en[2];
      const int j = sidata.j;
      if (j < atom->nlocal) {
        x[j][0] -= wj * d * sidata.en[0];
        x[j][1] -= wj * d * sidata.en[1];
        x[j][2] -= wj * d * sidata.en[2];
      }
    }

    // impact_time on: the impact is applied at its time within the step (impulse_impact_time.h)
    inline void replay_impact(const SurfacesIntersectData & sidata, double Fn)
    {
      const double overlap = sidata.is_wall ? sidata.radi - sidata.r : sidata.radi + sidata.radj - sidata.r;
      const double s = time_since_impact(overlap, sidata.vn, update->dt);
      const double J = Fn * update->dt * (sidata.is_wall ? sidata.area_ratio : 1.0);
      double ** const x = atom->x;
      const int i = sidata.i;
      const double wi = s * J / sidata.mi;  // how far grain i has moved with its new velocity
      const double wj = sidata.is_wall ? 0.0 : s * J / sidata.mj;
      const double left = separate ? overlap - wi - wj : 0.0;  // overlap the replay leaves: removed as `separate`
      double di = wi, dj = wj;
      if (left > 0.0) {
        if (sidata.is_wall) di += left;
        else {
          di += left * sidata.mj / (sidata.mi + sidata.mj);
          dj += left * sidata.mi / (sidata.mi + sidata.mj);
        }
      }
      for (int d = 0; d < 3; d++) x[i][d] += di * sidata.en[d];
      if (!sidata.is_wall && sidata.j < atom->nlocal)
        for (int d = 0; d < 3; d++) x[sidata.j][d] -= dj * sidata.en[d];
    }

    double ** coeffRest;
    bool separate;
    double bounceSpeed;
    bool iterate;
    bool impactTime;                  // impact_time on: the single pass applies each impact at its time
    bool speculative;                 // speculative on: the single pass acts on predicted gaps too
    int historyOffset;                // iterate on: kImpulseHistoryValues values from here
    LAMMPS_NS::FixWallGran * wall;    // the wall this model belongs to; NULL in pair gran
    ImpulseContactSink * sink;        // fix impulse/solve (iterate on)
    bool boundaryStartOn;             // boundary_start on: boundary pairs from the pass's start positions
    BoundaryStart boundaryStart;      // ... the owned grains' positions as the pass began
    bool startRecorded;               // ... recorded for the pass under way
    bool warnedBeyond;                // a grain moved beyond kBoundaryDistance: warned (once per run)
  };
}
}

#endif // NORMAL_MODEL_IMPULSE_H_
#endif
