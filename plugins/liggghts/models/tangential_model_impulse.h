/* ----------------------------------------------------------------------
    granlub: tangential part of the Sawyer & Tichy (2001) impulse operator
    for LIGGGHTS 3.8, with Walton's tangential restitution as an option.

    Sawyer & Tichy 2001, J. Tribol. 123:777, Eqs. 20-23: Coulomb friction
    mu |F_n| opposes the contact-point slip only until the slip is gone. Over
    one step this is the tangential impulse

        J_t = min( mu F_n dt ,  (1 + beta0) |v_s| / k )
        k   = 1/m_i + 1/m_j + r_i^2/I_i + r_j^2/I_j ,   I = (2/5) m r^2

    applied against the slip direction, with v_s the slip velocity of the
    contact points (translation plus spin x radius, grains as rigid spheres
    touching at r_i and r_j from their centres; 1/m_j = r_j^2/I_j = 0 for a
    wall). The second term is the impulse that makes the slip
    v_s' = -beta0 v_s: beta0 = 0 (default) stops the slip exactly (S&T's
    "until the slip vanishes", the stick limit); beta0 in [-1, 1] is Walton's
    tangential restitution for sticking impacts (Walton 1993, in "Particulate
    Two-Phase Flow", ch. 25; Foerster et al. 1994, Phys. Fluids 6:1108).
    For a sphere hitting a wall with spin 0 the stick limit gives 5/7 of the
    tangential velocity; the Coulomb limit gives v_t - mu (1 + e) |v_n|.

    As in model impulse, the slip includes the impulses (forces and torques
    accumulated in f and torque) of the contacts resolved earlier in the step.

    Setting:  beta0 value  (keyword after the model names, default 0)

    With `iterate on` (the default; a setting of model impulse, shared by both) this
    model computes no force either: it gives the contact that model impulse has
    just handed to fix impulse/solve its mu and beta0, and the solver applies
    the same law to accumulated impulses (doc/fix_impulse_solve.txt).

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree.
------------------------------------------------------------------------- */

#ifdef TANGENTIAL_MODEL
TANGENTIAL_MODEL(TANGENTIAL_IMPULSE,impulse,50)
#else
#ifndef TANGENTIAL_MODEL_IMPULSE_H_
#define TANGENTIAL_MODEL_IMPULSE_H_

#include "contact_models.h"
#include "tangential_model_base.h"
#include "global_properties.h"
#include "update.h"
#include "error.h"
#include "atom.h"
#include "modify.h"
#include "fix.h"
#include "impulse_contacts.h"
#include "impulse_impact_time.h"
#include "impulse_speculative.h"
#include <cmath>

namespace LIGGGHTS {
namespace ContactModels
{
  template<>
  class TangentialModel<TANGENTIAL_IMPULSE> : public TangentialModelBase
  {
  public:
    static const int MASK = CM_CONNECT_TO_PROPERTIES | CM_SURFACES_INTERSECT;

    TangentialModel(LAMMPS * lmp, IContactHistorySetup * hsetup, class ContactModelBase * cmb) :
      TangentialModelBase(lmp, hsetup, cmb),
      coeffFrict(NULL),
      beta0(0.0),
      iterate(true),
      impactTime(false),
      speculative(false),
      boundaryStart(false),
      sink(NULL)
    {}

    // iterate: the same setting as model impulse's (LIGGGHTS hands one value to both)
    inline void registerSettings(Settings & settings)
    {
      settings.registerDoubleSetting("beta0", beta0, 0.0);
      settings.registerOnOff("iterate", iterate, true);
      settings.registerOnOff("impact_time", impactTime, false);  // model impulse checks it
      settings.registerOnOff("speculative", speculative, false);  // model impulse checks it
      settings.registerOnOff("boundary_start", boundaryStart, false);  // model impulse checks it
    }

    inline void postSettings(IContactHistorySetup *, ContactModelBase *)
    {
      if (!(beta0 >= -1.0 && beta0 <= 1.0))
        error->all(FLERR, "tangential impulse: beta0 must lie in [-1, 1] (0 = stick limit)");
    }

    inline void connectToProperties(PropertyRegistry & registry)
    {
      registry.registerProperty("coeffFrict", &MODEL_PARAMS::createCoeffFrict);
      registry.connect("coeffFrict", coeffFrict, "tangential_model impulse");
      // model impulse checks that the solver exists when iterate is on
      sink = iterate ? find_solver(modify) : NULL;
    }

    inline void surfacesIntersect(const SurfacesIntersectData & sidata, ForceData & i_forces, ForceData & j_forces)
    {
      if (sidata.contact_flags)
        *sidata.contact_flags |= CONTACT_TANGENTIAL_MODEL;
      if (iterate) {  // the contact model impulse has just collected (a real force pass only)
        if (sidata.computeflag && sink) sink->set_friction(coeffFrict[sidata.itype][sidata.jtype], beta0);
        return;
      }
      const double Fn = sidata.Fn;
      if (Fn <= 0.0) return;  // no normal impulse this step: no friction impulse

      const double enx = sidata.en[0], eny = sidata.en[1], enz = sidata.en[2];
      const double ri = sidata.radi;
      const double rj = sidata.is_wall ? 0.0 : sidata.radj;

      // velocities including the impulses of contacts resolved earlier in this step
      // (sequential resolution, see model impulse); I = 2/5 m r^2. A pair with a ghost grain
      // (across a periodic or processor boundary) uses the start-of-step velocities alone, so
      // both owners compute the same, equal and opposite impulse (momentum; see model impulse).
      const double dt = update->dt;
      const int i = sidata.i;
      const bool boundary = !sidata.is_wall && sidata.j >= atom->nlocal;
      static const double none[3] = {0.0, 0.0, 0.0};  // a ghost's f and torque are not read
      const double * const fi = boundary ? none : atom->f[i];
      const double * const ti = boundary ? none : atom->torque[i];
      const double ci = dt / sidata.mi, cwi = 2.5 * dt / (sidata.mi * ri * ri);
      double vr1 = sidata.v_i[0] + ci * fi[0], vr2 = sidata.v_i[1] + ci * fi[1], vr3 = sidata.v_i[2] + ci * fi[2];
      double w1 = ri * (sidata.omega_i[0] + cwi * ti[0]);
      double w2 = ri * (sidata.omega_i[1] + cwi * ti[1]);
      double w3 = ri * (sidata.omega_i[2] + cwi * ti[2]);
      vr1 -= sidata.v_j[0];
      vr2 -= sidata.v_j[1];
      vr3 -= sidata.v_j[2];
      if (!sidata.is_wall) {
        const int j = sidata.j;
        const double * const fj = boundary ? none : atom->f[j];
        const double * const tj = boundary ? none : atom->torque[j];
        const double cj = dt / sidata.mj, cwj = 2.5 * dt / (sidata.mj * rj * rj);
        vr1 -= cj * fj[0];
        vr2 -= cj * fj[1];
        vr3 -= cj * fj[2];
        w1 += rj * (sidata.omega_j[0] + cwj * tj[0]);
        w2 += rj * (sidata.omega_j[1] + cwj * tj[1]);
        w3 += rj * (sidata.omega_j[2] + cwj * tj[2]);
      }
      // slip of the contact points: v_i - v_j - (v_n) e_n + e_n x (r_i w_i + r_j w_j)
      const double vn = vr1 * enx + vr2 * eny + vr3 * enz;
      const double vs1 = vr1 - vn * enx + (eny * w3 - enz * w2);
      const double vs2 = vr2 - vn * eny + (enz * w1 - enx * w3);
      const double vs3 = vr3 - vn * enz + (enx * w2 - eny * w1);
      const double vs = std::sqrt(vs1 * vs1 + vs2 * vs2 + vs3 * vs3);
      if (vs <= 0.0) return;

      // impulse per unit slip change: translation plus rotation (I = 2/5 m r^2 -> r^2/I = 5/(2m))
      double k = 1.0 / sidata.mi + 2.5 / sidata.mi;
      if (!sidata.is_wall) k += 1.0 / sidata.mj + 2.5 / sidata.mj;

      const double J_coulomb = coeffFrict[sidata.itype][sidata.jtype] * Fn * dt;  // S&T Eq. 20
      const double J_stick = (1.0 + beta0) * vs / k;                            // S&T Eqs. 21-22
      const double Ft = (J_coulomb < J_stick ? J_coulomb : J_stick) / dt;        // S&T Eq. 23
      const double s = -Ft / vs;
      const double Ft1 = s * vs1, Ft2 = s * vs2, Ft3 = s * vs3;
      if (impactTime) replay_impact(sidata, Ft1, Ft2, Ft3);

      // torque on i: (-r_i e_n) x F_t ; on j: (r_j e_n) x (-F_t), the same sign
      const double tor1 = eny * Ft3 - enz * Ft2;
      const double tor2 = enz * Ft1 - enx * Ft3;
      const double tor3 = enx * Ft2 - eny * Ft1;

      if (sidata.is_wall) {
        const double a = sidata.area_ratio;
        i_forces.delta_F[0] += Ft1 * a;
        i_forces.delta_F[1] += Ft2 * a;
        i_forces.delta_F[2] += Ft3 * a;
        i_forces.delta_torque[0] += -ri * tor1 * a;
        i_forces.delta_torque[1] += -ri * tor2 * a;
        i_forces.delta_torque[2] += -ri * tor3 * a;
      } else {
        add_pair_force(i_forces, j_forces, Ft1, Ft2, Ft3);
        i_forces.delta_torque[0] += -ri * tor1;
        i_forces.delta_torque[1] += -ri * tor2;
        i_forces.delta_torque[2] += -ri * tor3;
        j_forces.delta_torque[0] += -rj * tor1;
        j_forces.delta_torque[1] += -rj * tor2;
        j_forces.delta_torque[2] += -rj * tor3;
      }
    }

    inline void surfacesClose(SurfacesCloseData & scdata, ForceData & i_forces, ForceData & j_forces)
    {
      if (scdata.contact_flags)
        *scdata.contact_flags &= ~CONTACT_TANGENTIAL_MODEL;
      // boundary_start on: a pair across a boundary that touched as the pass began reaches the single
      // pass here too, with model impulse's normal impulse (impulse_boundary.h); model impulse writes
      // Fn for every pair it sees here with boundary_start on
      const bool boundary = boundaryStart && !iterate && !scdata.is_wall && scdata.j >= atom->nlocal;
      if (!speculative && !boundary) return;
      if (iterate) {  // model impulse has just collected this close contact (a real force pass only)
        if (scdata.computeflag && sink) sink->set_friction(coeffFrict[scdata.itype][scdata.jtype], beta0);
        return;
      }
      // speculative on, or a boundary pair: model impulse has just given this close pair a normal
      // impulse (Fn > 0) or none (Fn = 0); friction on it as on a touching contact
      // (impulse_speculative.h, impulse_boundary.h). Its contact flag stays cleared.
      SurfacesIntersectData & sidata = static_cast<SurfacesIntersectData &>(scdata);
      if (!(sidata.Fn > 0.0)) return;
      int * const flags = sidata.contact_flags;
      sidata.contact_flags = NULL;
      surfacesIntersect(sidata, i_forces, j_forces);
      sidata.contact_flags = flags;
    }

    inline void beginPass(SurfacesIntersectData &, ForceData &, ForceData &) {}
    inline void endPass(SurfacesIntersectData &, ForceData &, ForceData &) {}

  private:
    // impact_time on: grain i (and a local j) moved by s J_t / m, as model impulse does with the
    // normal impulse (impulse_impact_time.h)
    inline void replay_impact(const SurfacesIntersectData & sidata, double F1, double F2, double F3)
    {
      const double overlap = sidata.is_wall ? sidata.radi - sidata.r : sidata.radi + sidata.radj - sidata.r;
      const double s = time_since_impact(overlap, sidata.vn, update->dt);
      if (s <= 0.0) return;
      const double J = s * update->dt * (sidata.is_wall ? sidata.area_ratio : 1.0);
      double ** const x = atom->x;
      const double ci = J / sidata.mi;
      x[sidata.i][0] += ci * F1;
      x[sidata.i][1] += ci * F2;
      x[sidata.i][2] += ci * F3;
      if (sidata.is_wall || sidata.j >= atom->nlocal) return;
      const double cj = J / sidata.mj;
      x[sidata.j][0] -= cj * F1;
      x[sidata.j][1] -= cj * F2;
      x[sidata.j][2] -= cj * F3;
    }

    double ** coeffFrict;
    double beta0;
    bool iterate;
    bool impactTime;            // impact_time on (a setting of model impulse, shared by both)
    bool speculative;           // speculative on (a setting of model impulse, shared by both)
    bool boundaryStart;         // boundary_start on (a setting of model impulse, shared by both)
    ImpulseContactSink * sink;  // fix impulse/solve (iterate on)
  };
}
}

#endif // TANGENTIAL_MODEL_IMPULSE_H_
#endif
