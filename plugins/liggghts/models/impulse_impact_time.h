/* ----------------------------------------------------------------------
    granlub: `impact_time on` of model impulse / tangential impulse (the
    single pass, iterate off): each impact applied at its time within the
    step.

    The single pass finds a contact only once the surfaces overlap, at the
    end of the step in which they met, and gives the grains their new
    velocities from there: every impact is applied up to one step late, and
    the flight that follows starts late by the time s since the surfaces
    met (a mean of dt/2 per impact; measured: docs/measurements/liggghts.md,
    "Where the time-step error comes from"). With impact_time on, the
    impulse J found at the step's end is applied at the impact's time
    t_c = t - s instead: each grain is moved by s J / m (normal and
    tangential parts), the distance it would have travelled with its new
    velocity since t_c, and `separate` removes only the overlap this leaves.
    A binary collision is then exact in positions as well as velocities at
    every step, whatever the step. The time of impact assumes the grains
    approached at the speed they moved with over the step,

        s = min( overlap / |v_n| , dt ) ,   v_n < 0 the approach speed,

    the contact time of Moreau's time stepping applied backward (Moreau 1988,
    CISM 302:1, contacts activated and impacts applied at their time within
    the step; Jean 1999, CMAME 177:235, the theta-scheme's contact at time
    t + theta dt), and the collision time of event-driven hard spheres. Our
    construction for the single pass: LIGGGHTS 3.8 calls the contact models
    of a grain pair only when they overlap, so a contact cannot be activated
    on its predicted gap before it closes (as Catto's speculative contacts
    do), only replayed once it has.

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree.
------------------------------------------------------------------------- */

#ifndef GRANLUB_IMPULSE_IMPACT_TIME_H_
#define GRANLUB_IMPULSE_IMPACT_TIME_H_

namespace LIGGGHTS {
namespace ContactModels {

// The time since the surfaces met, within the step: overlap over approach speed, at most dt; 0 if
// they did not approach over the step (an older overlap: no impact to replay).
inline double time_since_impact(double overlap, double vn, double dt)
{
  if (!(vn < 0.0) || !(overlap > 0.0)) return 0.0;
  const double s = overlap / -vn;
  return s < dt ? s : dt;
}

}
}

#endif // GRANLUB_IMPULSE_IMPACT_TIME_H_
