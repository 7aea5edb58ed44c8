/* ----------------------------------------------------------------------
    granlub: `speculative on` of model impulse / tangential impulse:
    contacts activated on their predicted gap. Below, the single pass's rule
    (iterate off); with iterate on the close contacts go to fix impulse/solve
    with their gap (normal_model_impulse.h collect_close; the solve's rule:
    fix_impulse_solve.cpp, prepare).

    The single pass finds a contact only once the surfaces overlap, after
    the step's move, and `separate` pushes the grains apart afterwards; in a
    loaded packing the enduring contacts are then overlapped (up to 0.015 d
    at the main job's step) and the network is denser at a larger step
    (docs/measurements/liggghts.md, "Where the time-step error comes from").
    With speculative on, the models also see the pairs (and wall contacts)
    that are close but not yet touching: LIGGGHTS 3.8 calls the contact
    models' surfacesClose for pairs within contactDistanceFactor times the
    sum of the radii (walls: a gap below (contactDistanceFactor - 1) times
    the radius), a factor a model widens with
    neighbor->register_contact_dist_factor (as cohesion and Hooke's elastic
    energy do). For such a contact with gap g >= 0 the next move changes the
    gap by v_n' dt, v_n' the normal velocity after this step's impulse; an
    impulse acts only if the surfaces would meet within the step, v_n dt <
    -g, and then

        v_n' = -e v_n      a real impact (approach speed above bounce_speed):
                           S&T's impulse m_eff (1 + e) |v_n|, given in the
                           step in which the surfaces meet, not the one after
        v_n' = -g / dt     otherwise (e = 0): the surfaces just touch at the
                           step's end, no overlap made

    the speculative contact of Catto (2005-2007, GDC talks "Iterative
    dynamics", "Speculative contacts"; restitution only when the surfaces
    meet within the step) and the contact activated on the predicted gap of
    Moreau (1988, CISM 302:1, index set on y + h ydot) and Jean (1999, CMAME
    177:235). Friction (tangential impulse) acts on the same normal impulse
    with its Coulomb bound, as on a touching contact. Pairs that overlap all
    the same (missed by the contact distance, or made by the sequential
    sweep) keep the single pass and `separate`. [ASSUMPTION] the contact
    distance factor kSpeculativeDistance below: ours.

    Contributing author: granlub (plugins/liggghts), GPL-2.0-or-later like
    LIGGGHTS. Drops unchanged into a LIGGGHTS 3.8 source tree.
------------------------------------------------------------------------- */

#ifndef GRANLUB_IMPULSE_SPECULATIVE_H_
#define GRANLUB_IMPULSE_SPECULATIVE_H_

namespace LIGGGHTS {
namespace ContactModels {

// The contact distance factor registered with speculative on: pairs closer than 1.1 (r_i + r_j),
// walls closer than 0.1 r_i, are handed to the models. A gap closes within a step only if the
// approach speed exceeds g / dt: 0.1 d in 5.48 us is 14 m/s for the slice's grains (walls 7 m/s),
// several times the shear speed. A faster approach is caught one step later by the overlap path.
static const double kSpeculativeDistance = 1.1;

// The normal impulse over the effective mass (m/s) of a contact with gap g >= 0 and normal
// velocity vn (< 0 approaching), e the restitution that applies to this approach: 0 if the surfaces
// do not meet within the step (vn dt >= -g); else (1 + e) |vn| for e > 0, -g/dt - vn for e = 0.
inline double speculative_dv(double gap, double vn, double dt, double e)
{
  if (!(vn * dt < -gap)) return 0.0;
  if (e > 0.0) return (1.0 + e) * -vn;
  return -gap / dt - vn;
}

}
}

#endif // GRANLUB_IMPULSE_SPECULATIVE_H_
