// fix impulse/solve: the contacts of model impulse / tangential impulse (`iterate on`) solved
// together, every step, to convergence. Doc: plugins/liggghts/doc/fix_impulse_solve.txt.
//
// The step (velocity Verlet as LIGGGHTS runs it): the grains have moved with u, their velocity
// since the last force evaluation; the contact models have collected every touching pair and
// wall contact (impulse_contacts.h) without computing a force; every other force of the step
// (gravity, body forces, non-granular fixes) is in f when this runs, at pre_final_integrate. The
// velocity the next positions are made with is then u' = u + dt (f + sum of contact impulses / dt)
// / m, and this fix finds the impulses:
//
//  * Time stepping of Moreau and Jean (Moreau 1988, CISM 302:1, Newton's law at each contact;
//    Jean 1999, CMAME 177:235, NSCD; Acary & Brogliato 2008, LNACM 35, ch. 10): the free
//    velocity v_f = u + dt f / m (all non-contact forces of the step), and per contact
//      normal:  P_n >= 0,  v_n' >= t_n,  P_n (v_n' - t_n) = 0,   t_n = -e min(v_n(u), 0)
//      Coulomb: |P_t| <= mu P_n, the slip v_s' = t_s while |P_t| < mu P_n,  t_s = -beta0 v_s(u)
//    with e = 0 below bounce_speed, v(u) the velocities the grains arrived with (Newton's
//    restitution on the pre-step velocity, as Moreau's scheme; a resting contact, v_n(u) = 0,
//    gets t_n = 0 and so rests: that is the difference from the single pass, which applies
//    restitution to whatever approach speed it sees, gravity's too). t_s = -beta0 v_s(u) is
//    Walton's tangential restitution applied the same way (our choice: Walton 1993 defines it
//    for a binary impact; beta0 = 0, the default, is the stick limit of Sawyer & Tichy 2001).
//  * speculative on (the models' setting): contacts within the contact distance that do not touch
//    yet come with their gap g > 0 and the target t_n = -g/dt (the gap may close, not overlap), or
//    Newton's -e v_n(u) if the surfaces meet within the step (prepare).
//  * Projected Gauss-Seidel over the contacts with accumulated, clamped impulses (Jean 1999,
//    the NLGS of LMGC90; Catto 2005, "Iterative dynamics with temporal coherence", GDC, sequential
//    impulses): each contact in turn changes its impulses to meet its law with the others
//    fixed, the accumulated normal impulse clamped to >= 0 and the tangential one to the disc
//    mu P_n, so a later sweep can take back what an earlier one gave. Sweeps repeat until the
//    largest change of any impulse in a sweep is at most `tolerance` times the largest normal
//    impulse of the step (all ranks), or no contact's relative velocity changed beyond its limit
//    (ours: `velocity_tolerance` of g dt, or `impact_tolerance` of the approach speed of an impact
//    whose change reached it; solve_velocities), or `iterations` sweeps. An isolated contact
//    converges in one sweep to the single pass's answer: the collision tests hold to 1e-12 either way.
//  * Active set (ours, switchable: active_set): after a step's first sweep only the contacts of
//    grains the previous sweep moved beyond the stopping rules are solved (build_adjacency).
//  * Warm start (Catto 2005): each contact starts from its impulses of the previous step, kept
//    in LIGGGHTS' contact history, which follows the pair across neighbour rebuilds and ranks.
//  * Overlaps (`separate on`) are corrected with pseudo-velocities (split impulses: Catto 2006,
//    "Fast and simple physics using sequential impulses", GDC; Box2D's position solver): a
//    second projected Gauss-Seidel finds pseudo-impulses Q >= 0 with separating pseudo-velocity
//    >= correction (overlap - slop (r_i + r_j)) / dt, and the positions move by dt times the
//    pseudo-velocities, which are then dropped: no kinetic energy is injected. The slop (our
//    choice; Box2D's linearSlop) keeps a corrected contact touching, so a resting contact is
//    found again next step instead of falling free for a step and bouncing.
//  * Boundary pairs (one grain a ghost: a periodic image or another rank's grain). With newton
//    off both owners resolve such a pair; they must give equal and opposite impulses, as in the
//    single pass. So in every sweep both compute it from the state at the end of the previous
//    sweep (the ghosts are refreshed after every sweep), all boundary pairs of a rank first and
//    at once, then the rest in sequence. A grain with several such pairs would be over-corrected
//    by them at once (a Jacobi step); its mass is split among them (Tonge, Benevolenski &
//    Voroshilov 2012, ACM TOG 31(4):105, mass splitting): each boundary pair sees the grain
//    with 1/n of its mass, n its boundary pairs. Converged answers do not depend on it.
//
// Hot loops: arrays grown only, no allocation once warm; contacts in the order the models found
// them (pair list, then walls in fix order), so the same deck and seed give the same numbers.
#include "fix_impulse_solve.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix_mesh_surface.h"
#include "fix_wall_gran.h"
#include "force.h"
#include "modify.h"
#include "pair_gran_proxy.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;
using LIGGGHTS::ContactModels::kHistPn;
using LIGGGHTS::ContactModels::kHistPt;
using LIGGGHTS::ContactModels::kHistStep;
using LIGGGHTS::ContactModels::kHistLoad;
typedef LIGGGHTS::ContactModels::ImpulseContact Contact;

namespace {

enum CommMode { kCommStart = 0, kCommVelocity = 1, kCommPseudo = 2 };

// Ranges (doc page): a tolerance below ~1e-12 cannot be met in double precision, one above 0.5
// stops before the first change is checked against anything.
const double kMinTolerance = 1e-12, kMaxTolerance = 0.5;
const int kMaxIterations = 100000;
const double kMaxSlop = 0.01;
const double kMaxRestFactor = 100.0;

[[noreturn]] void fail(Error* error, const std::string& msg) {
    error->all(FLERR, ("fix impulse/solve: " + msg).c_str());
    std::abort();  // error->all does not return
}

double number(Error* error, const char* key, const char* text, double lo, double hi, bool lo_open,
              const std::string& range) {
    char* end = NULL;
    const double x = std::strtod(text, &end);
    const bool ok = end != text && *end == '\0' && std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
    if (!ok) fail(error, std::string(key) + " must be a number in " + range + "; got '" + text + "'");
    return x;
}

// A keyword with the values a or b: whether it is b.
bool second(Error* error, const char* key, const char* val, const char* a, const char* b) {
    if (std::strcmp(val, a) != 0 && std::strcmp(val, b) != 0)
        fail(error, std::string(key) + " must be " + a + " or " + b + "; got '" + val + "'");
    return std::strcmp(val, b) == 0;
}

inline void cross(const double* a, const double* b, double* c) {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

}  // namespace

FixImpulseSolve::FixImpulseSolve(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg),
      tolerance_(1e-4),
      iterations_(200),
      warm_start_(true),
      restitution_all_(false),
      rest_factor_(2.0),
      slop_(1e-4),
      correction_(1.0),
      velocity_tolerance_(0.1),
      impact_tolerance_(0.05),
      active_set_(true),
      vlim_(0.0),
      overlap_limit_(0.05),
      overlap_error_(false),
      comm_mode_(kCommStart),
      any_boundary_(false),
      kinematic_bits_(0),
      dynamic_bits_(0),
      setup_pending_(false),
      setup_step_(0),
      last_sweeps_(0),
      last_position_sweeps_(0),
      last_change_(0.0),
      run_steps_(0),
      run_sweeps_(0),
      run_capped_(0),
      run_solved_(0),
      last_overlap_(0.0),
      run_max_overlap_(0.0),
      run_bad_steps_(0),
      run_max_overlap_step_(0),
      run_position_capped_(0),
      warned_at_(0),
      superseded_(false) {
    if (std::strcmp(arg[1], "all") != 0)
        fail(error, std::string("acts on every contact of the impulse models: its group must be 'all'; got '") +
                        arg[1] + "'");
    for (int k = 3; k < narg; k += 2) {
        const std::string key = arg[k];
        if (k + 1 >= narg) fail(error, "keyword '" + key + "' needs a value");
        const char* val = arg[k + 1];
        if (key == "tolerance") {
            tolerance_ = number(error, "tolerance", val, kMinTolerance, kMaxTolerance, false, "[1e-12, 0.5]");
        } else if (key == "iterations") {
            char* end = NULL;
            const long n = std::strtol(val, &end, 10);
            if (end == val || *end != '\0' || n < 1 || n > kMaxIterations)
                fail(error, "iterations must be a whole number in [1, 100000] (the cap on the sweeps per step); "
                            "got '" + std::string(val) + "'");
            iterations_ = static_cast<int>(n);
        } else if (key == "warm_start") {
            warm_start_ = !second(error, "warm_start", val, "yes", "no");
        } else if (key == "slop") {
            slop_ = number(error, "slop", val, 0.0, kMaxSlop, false, "[0, 0.01] (a fraction of r_i + r_j)");
        } else if (key == "restitution") {
            restitution_all_ = second(error, "restitution", val, "new", "all");
        } else if (key == "rest_factor") {
            rest_factor_ = number(error, "rest_factor", val, 0.0, kMaxRestFactor, false, "[0, 100]");
        } else if (key == "correction") {
            correction_ = number(error, "correction", val, 0.0, 1.0, true, "(0, 1]");
        } else if (key == "velocity_tolerance") {
            velocity_tolerance_ = number(error, "velocity_tolerance", val, 0.0, kMaxTolerance, false, "[0, 0.5] (0: off)");
        } else if (key == "impact_tolerance") {
            impact_tolerance_ = number(error, "impact_tolerance", val, 0.0, kMaxTolerance, false, "[0, 0.5] (0: off)");
        } else if (key == "overlap_limit") {
            overlap_limit_ = number(error, "overlap_limit", val, 0.0, 1.0, true, "(0, 1] (a fraction of r_i + r_j)");
        } else if (key == "active_set") {
            active_set_ = !second(error, "active_set", val, "yes", "no");
        } else if (key == "overlaps") {
            overlap_error_ = second(error, "overlaps", val, "warn", "error");
        } else {
            fail(error, "unknown keyword '" + key + "' (tolerance, iterations, warm_start, restitution, rest_factor, slop, "
                        "correction, velocity_tolerance, impact_tolerance, active_set, overlap_limit, overlaps)");
        }
    }
    comm_forward = 7;  // velocity, spin, and kCommStart: boundary-pair count, kCommVelocity: jolt
    vector_flag = 1;
    size_vector = 10;
    global_freq = 1;
    extvector = 0;
}

int FixImpulseSolve::setmask() { return PRE_INITIAL_INTEGRATE | PRE_FINAL_INTEGRATE; }

// A deck that never asked for this fix (model impulse made it: iterate on is the default) is told
// how to do without it.
void FixImpulseSolve::refuse(const std::string& msg) const {
    const bool made = std::strcmp(id, LIGGGHTS::ContactModels::kMadeSolverId) == 0;
    fail(error, msg + (made ? " (this fix was made by model impulse, whose default is 'iterate on'; 'iterate off' on "
                              "the pair style and every impulse wall gives Sawyer & Tichy's single pass, which needs "
                              "no fix)"
                            : ""));
}

void FixImpulseSolve::init() {
    // the fix pair_style gran made (granlub_impulse_solve) steps aside for one the deck wrote
    const bool made = std::strcmp(id, LIGGGHTS::ContactModels::kMadeSolverId) == 0;
    const int n = modify->n_fixes_style("impulse/solve");
    const int made_n = modify->find_fix(LIGGGHTS::ContactModels::kMadeSolverId) >= 0 ? 1 : 0;
    superseded_ = made && n > 1;
    if (superseded_) return;
    if (n - made_n > 1) refuse("only one fix impulse/solve is allowed");
    if (std::strstr(update->integrate_style, "respa")) refuse("does not support run_style respa");
    if (!atom->radius_flag || !atom->rmass_flag || !atom->omega_flag || !atom->torque_flag)
        refuse("needs spheres with per-atom radius, mass, spin and torque (atom_style granular or sphere)");
    if (force->newton_pair)
        refuse("needs newton off (a pair across a periodic or processor boundary is resolved by both "
                    "owners; plugins/liggghts/doc/fix_impulse_solve.txt)");
    if (!comm->ghost_velocity) refuse("needs 'communicate single vel yes'");
}

// What this solver can serve: every granular contact of the run is model impulse with iterate on
// (the models check that each of them agrees with the presence of this fix), and nothing reads
// per-contact forces that the collecting models no longer compute.
void FixImpulseSolve::check_styles() {
    PairGranProxy* pair = dynamic_cast<PairGranProxy*>(force->pair);
    if (!pair || !pair->contact_match("normal", "impulse") || pair->get_history_offset("impulse") < 0)
        refuse("needs 'pair_style gran model impulse ... iterate on' (the solver resolves the contacts that "
                    "model collects)");
    if (pair->cpl() || pair->storeContactForces() || pair->storeContactForcesStress() || pair->store_sum_normal_force())
        refuse("per-contact pair forces (compute pair/gran/local, contact force storage) are not available: the "
                    "contact models hand their contacts to the solver and compute no force");
    if (pair->fr_pair() || modify->n_fixes_style("rigid") > 0 || modify->n_fixes_style("multisphere") > 0)
        refuse("rigid bodies (fix rigid, multisphere) are not supported");
    for (int k = 0; k < modify->nfix; k++) {
        FixWallGran* wall = dynamic_cast<FixWallGran*>(modify->fix[k]);
        if (!wall) continue;
        if (!wall->contact_match("normal", "impulse"))
            refuse(std::string("fix wall/gran ") + wall->id + " uses another contact model; with fix "
                        "impulse/solve every granular wall must be 'model impulse ... iterate on'");
        if (wall->compute_wall_gran_local() || wall->store_force_contact() || wall->store_force_contact_stress() ||
            wall->store_sum_normal_force())
            refuse(std::string("fix wall/gran ") + wall->id + ": per-contact wall forces (compute wall/gran/local, "
                        "contact force storage) are not available; store_force yes is");
    }
}

void FixImpulseSolve::setup(int) {
    if (superseded_) return;
    check_styles();  // here, not in init: computes register with pair gran and the walls in their own init
    // Which atoms the impulses may move: those a time-integrating fix moves by its forces. An atom
    // whose motion is prescribed (fix move, fix freeze) or that no fix integrates (a wall made of
    // atoms) is kinematic: infinite mass, as a wall (contact dynamics' prescribed bodies; Jean 1999).
    kinematic_bits_ = dynamic_bits_ = 0;
    for (int k = 0; k < modify->nfix; k++) {
        const Fix* fix = modify->fix[k];
        if (std::strcmp(fix->style, "move") == 0 || std::strcmp(fix->style, "freeze") == 0)
            kinematic_bits_ |= fix->groupbit;
        else if (fix->time_integrate)
            dynamic_bits_ |= fix->groupbit;
    }
    // The forces of this setup: the models have collected the contacts (pair now, the walls in
    // their own setup, some after this one); their impulses of the last step are applied before
    // the first half kick (pre_initial_integrate), so a run continues the previous one.
    setup_pending_ = true;
    setup_step_ = update->ntimestep;  // the step the previous run ended with
    run_steps_ = run_sweeps_ = run_capped_ = run_solved_ = 0;
    run_bad_steps_ = run_position_capped_ = warned_at_ = 0;
    run_max_overlap_ = 0.0;
    run_max_overlap_step_ = update->ntimestep;
}

void FixImpulseSolve::pre_initial_integrate() {
    if (superseded_ || !setup_pending_) return;
    setup_pending_ = false;
    const double dt = update->dt;
    // the contacts solved at the setup's step (the last of the previous run) get their impulses back
    // (ntimestep has already moved on to the first step of this run)
    const double step = static_cast<double>(setup_step_);
    const int n = static_cast<int>(contacts_.size());
    for (int k = 0; k < n; k++) {
        Contact& c = contacts_[k];
        const bool stored = c.history && c.history[kHistStep] == step;
        c.pn = stored ? c.history[kHistPn] : 0.0;
        for (int d = 0; d < 3; d++) c.pt[d] = stored ? c.history[kHistPt + d] : 0.0;
    }
    apply_forces(dt, atom->nlocal, false);
}

void FixImpulseSolve::pre_final_integrate() {
    if (superseded_) return;
    const double dt = update->dt;
    const int nlocal = atom->nlocal;
    prepare(dt, nlocal);
    const int sweeps = solve_velocities(nlocal);
    last_position_sweeps_ = solve_positions(dt, nlocal);
    apply_forces(dt, nlocal, true);
    last_sweeps_ = sweeps;
    run_steps_++;
    run_sweeps_ += sweeps;
    if (sweeps >= iterations_ && last_change_ > tolerance_) run_capped_++;
    watch_overlaps(last_position_sweeps_ >= iterations_);
}

void FixImpulseSolve::grow(int nall) {
    if (static_cast<int>(im_.size()) >= nall) return;
    const std::size_t n = static_cast<std::size_t>(nall) + nall / 4 + 16;
    vel_.resize(3 * n);
    omg_.resize(3 * n);
    pv_.resize(3 * n);
    im_.resize(n);
    ii_.resize(n);
    split_.resize(n);
    jolt_.resize(n);
}

// Free velocities, the contacts' targets and masses, and the warm start.
void FixImpulseSolve::prepare(double dt, int nlocal) {
    const int nall = nlocal + atom->nghost;
    grow(nall);
    double** const v = atom->v;
    double** const omega = atom->omega;
    double** const f = atom->f;
    double** const torque = atom->torque;
    const double* const rmass = atom->rmass;
    const double* const radius = atom->radius;
    double* const vel = &vel_[0];
    double* const omg = &omg_[0];
    double* const im = &im_[0];
    double* const ii = &ii_[0];
    double* const split = &split_[0];
    const int* const mask = atom->mask;
    for (int k = 0; k < nall; k++) {
        const bool kinematic = (mask[k] & kinematic_bits_) || !(mask[k] & dynamic_bits_);
        im[k] = kinematic ? 0.0 : 1.0 / rmass[k];
        ii[k] = 2.5 * im[k] / (radius[k] * radius[k]);  // I = 2/5 m r^2, as the single pass
        split[k] = 0.0;
        jolt_[k] = 0.0;
    }
    for (int k = 0; k < nlocal; k++)
        for (int d = 0; d < 3; d++) {
            vel[3 * k + d] = v[k][d] + dt * f[k][d] * im[k];
            omg[3 * k + d] = omega[k][d] + dt * torque[k][d] * ii[k];
        }

    const int n = static_cast<int>(contacts_.size());
    boundary_.clear();
    for (int k = 0; k < n; k++) {
        Contact& c = contacts_[k];
        c.boundary = c.j >= nlocal;
        if (c.boundary) {
            boundary_.push_back(k);
            split[c.i] += 1.0;
        }
    }
    int mine = boundary_.empty() ? 0 : 1, any = mine;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    any_boundary_ = any != 0;
    if (any_boundary_) forward(kCommStart);  // the ghosts' free velocities and boundary-pair counts

    static const double zero[3] = {0.0, 0.0, 0.0};
    const double previous = static_cast<double>(update->ntimestep - 1);
    // the velocity rule's scale (velocities_done): the bed's own, what the non-contact forces
    // (gravity, body forces) add to a touching grain's velocity in this step (g dt in a bed at rest);
    // an impact's grains also carry its approach speed (jolt_, impact_tolerance)
    double vbed = 0.0;
    for (int k = 0; k < n; k++) {
        Contact& c = contacts_[k];
        const int i = c.i, j = c.j;
        const bool wall = j < 0;
        const double* const en = c.en;
        // the velocities the grains arrived with (start of the step): restitution's reference
        const double* const ui = v[i];
        const double* const uj = wall ? c.vwall : v[j];
        const double* const wi = omega[i];
        const double* const wj = wall ? zero : omega[j];
        const double vr[3] = {ui[0] - uj[0], ui[1] - uj[1], ui[2] - uj[2]};
        const double vn = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];
        // Newton's law is an impact law; which approaches are impacts is our choice (switchable):
        //  - a contact pressed at the previous step was solved to v_n >= t_n >= 0 then, and the grains
        //    arrive with that solve's velocities: its approach now is the solve's residual or the turn
        //    of its normal, not an impact (restitution new; restitution all: Moreau's law literally);
        //  - an approach no faster than rest_factor times the contact's load speed (its normal impulse
        //    the last time it was pressed without restitution, over its effective mass: what its load
        //    adds in one step) is a resting contact closing again after lifting off for a step or two.
        //    Without it such micro-bounces (e = 0.9) keep a pile chattering at the solver's resolution.
        //    The load speed scales with dt, so both rules vanish as dt -> 0.
        const bool enduring = c.history && c.history[kHistStep] == previous && c.history[kHistPn] > 0.0;
        const double load = c.history ? c.history[kHistLoad] * (im[i] + (wall ? 0.0 : im[j])) : 0.0;
        const bool impact = -vn > c.bounce && (restitution_all_ || (!enduring && -vn > rest_factor_ * load));
        c.tn = vn < 0.0 && impact ? -c.e * vn : 0.0;
        c.trest = 0.0;
        if (speculative_) {
            // speculative on: a close contact has gap g > 0 (impulse_speculative.h). Signorini with the
            // gap at the velocity level (Moreau 1988, CISM 302:1, the index set on y + h ydot; Jean 1999,
            // CMAME 177:235): the next move may close the gap but not overlap, v_n' >= -g/dt. Restitution
            // only if the surfaces, arriving as they are, meet within the step (v_n dt < -g; as the single
            // pass's speculative rule), and not inside the solve: with the gaps as constraints a closed
            // column of grains cannot give every impact its rebound, and the accumulated impulses then
            // grow to the cap (measured: docs/measurements/liggghts.md). The solve stops the impacts
            // (target -g/dt, or 0 touching); one sequential pass after it gives each impact its rebound
            // -e v_n (Catto's speculative contacts; Box2D's restitution after the solve). [ASSUMPTION] the
            // order: ours.
            // Friction acts on a close contact only in the rebound pass, on an impact (as the single pass's
            // speculative impulse): in the solve its surfaces are apart. With friction there too the
            // gaps lock a sheared packing (wedging: the wall-to-wall impulses grew 1000-fold within 100
            // steps on the loaded periodic cell, measured: docs/measurements/liggghts.md). [ASSUMPTION]
            c.mu_close = c.mu;
            if (c.gap > 0.0) c.mu = 0.0;
            const bool meets = c.gap > 0.0 ? vn * dt < -c.gap : true;
            if (c.tn > 0.0 && meets) c.trest = c.tn;
            c.tn = c.gap > 0.0 ? -c.gap / dt : 0.0;
        }
        c.impact = c.tn > 0.0 || c.trest > 0.0;
        const double dv2 = im[i] * im[i] * (f[i][0] * f[i][0] + f[i][1] * f[i][1] + f[i][2] * f[i][2]);
        if (dv2 > vbed) vbed = dv2;  // squared here (no root per contact), the speed after the loop
        if (c.impact) {
            if (-vn > jolt_[i]) jolt_[i] = -vn;
            if (!wall && -vn > jolt_[j]) jolt_[j] = -vn;
        }
        const double ws[3] = {c.ri * wi[0] + c.rj * wj[0], c.ri * wi[1] + c.rj * wj[1], c.ri * wi[2] + c.rj * wj[2]};
        double exw[3];
        cross(en, ws, exw);
        for (int d = 0; d < 3; d++) c.tt[d] = -c.beta0 * (vr[d] - vn * en[d] + exw[d]);
        // masses: a boundary pair sees each grain's mass split among its boundary pairs
        const double ai = c.boundary ? im[i] * split[i] : im[i];
        const double aj = wall ? 0.0 : (c.boundary ? im[j] * split[j] : im[j]);
        c.pn = 0.0;
        c.pt[0] = c.pt[1] = c.pt[2] = 0.0;
        c.q = 0.0;
        if (ai + aj == 0.0) {  // two kinematic atoms (or one against a wall): nothing to solve
            c.mn = c.wn = c.kt = c.tn = c.mu = 0.0;
            c.separate = false;
            continue;
        }
        c.mn = 1.0 / (ai + aj);
        c.wn = ai + aj;
        c.kt = 1.0 / (3.5 * (ai + aj));  // 1/m + r^2/I per grain, I = 2/5 m r^2
        if (!(warm_start_ && c.history && c.history[kHistStep] == previous)) continue;
        // warm start: last step's impulses, the tangential one in the present tangent plane and cone
        const double* const h = c.history;
        c.pn = h[kHistPn] > 0.0 ? h[kHistPn] : 0.0;
        const double* const pt = h + kHistPt;
        const double ptn = pt[0] * en[0] + pt[1] * en[1] + pt[2] * en[2];
        double t[3] = {pt[0] - ptn * en[0], pt[1] - ptn * en[1], pt[2] - ptn * en[2]};
        const double lim = c.mu * c.pn, t2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
        if (t2 > lim * lim) {
            const double s = lim / std::sqrt(t2);
            t[0] *= s;
            t[1] *= s;
            t[2] *= s;
        }
        c.pt[0] = t[0];
        c.pt[1] = t[1];
        c.pt[2] = t[2];
        // on the owned grains (a ghost's owner warm-starts its own copy of the pair)
        double P[3], txp[3];
        for (int d = 0; d < 3; d++) P[d] = c.pn * en[d] + t[d];
        cross(en, t, txp);
        for (int d = 0; d < 3; d++) {
            vel[3 * i + d] += im[i] * P[d];
            omg[3 * i + d] -= c.ri * ii[i] * txp[d];
        }
        if (!wall && !c.boundary)
            for (int d = 0; d < 3; d++) {
                vel[3 * j + d] -= im[j] * P[d];
                omg[3 * j + d] -= c.rj * ii[j] * txp[d];
            }
    }
    vbed = dt * std::sqrt(vbed);
    if (comm->nprocs > 1) {  // one limit for all ranks (the rule and the active set alike)
        double mine = vbed;
        MPI_Allreduce(&mine, &vbed, 1, MPI_DOUBLE, MPI_MAX, world);
    }
    vlim_ = velocity_tolerance_ * vbed;
    if (any_boundary_) forward(kCommVelocity);
}

namespace {

// The change of one contact's impulses that meets its laws with everything else fixed (normal:
// P_n >= 0 and v_n >= t_n; tangential: the slip reaches t_s within the disc mu P_n), computed
// from the velocities given; updates the contact's accumulated impulses and returns the
// largest change. Normal impulses act through the centres and do not change the slip, so both
// rows are computed from the same velocities. Returns the square of the change (no square root
// on the hot path; the sweep compares squares).
inline double contact_change(Contact& c, const double* vi, const double* wi, const double* vj, const double* wj,
                             double& dn, double* dt) {
    const double* const en = c.en;
    const double vr[3] = {vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]};
    const double vn = vr[0] * en[0] + vr[1] * en[1] + vr[2] * en[2];
    double pn = c.pn + c.mn * (c.tn - vn);
    if (pn < 0.0) pn = 0.0;
    dn = pn - c.pn;
    c.pn = pn;
    const double change = dn * dn;
    if (c.mu <= 0.0) {
        dt[0] = dt[1] = dt[2] = 0.0;
        return change;
    }
    const double ws[3] = {c.ri * wi[0] + c.rj * wj[0], c.ri * wi[1] + c.rj * wj[1], c.ri * wi[2] + c.rj * wj[2]};
    double exw[3];
    cross(en, ws, exw);
    double pt[3];
    for (int d = 0; d < 3; d++) pt[d] = c.pt[d] - c.kt * (vr[d] - vn * en[d] + exw[d] - c.tt[d]);
    const double lim = c.mu * pn, p2 = pt[0] * pt[0] + pt[1] * pt[1] + pt[2] * pt[2];
    if (p2 > lim * lim) {
        const double s = lim / std::sqrt(p2);
        pt[0] *= s;
        pt[1] *= s;
        pt[2] *= s;
    }
    for (int d = 0; d < 3; d++) {
        dt[d] = pt[d] - c.pt[d];
        c.pt[d] = pt[d];
    }
    const double m = dt[0] * dt[0] + dt[1] * dt[1] + dt[2] * dt[2];
    return m > change ? m : change;
}

// A contact's impulse change (dn e_n + dt) on grain i (sign +1), or its opposite on grain j
// (sign -1). The contact point is -r_i e_n from i and +r_j e_n from j, so the angular impulse is
// (-r_i e_n) x dt on i and (r_j e_n) x (-dt) on j: -r (e_n x dt) on both (as the single pass).
inline void kick(double* vel, double* omg, double im, double ii, double r, const double* en, double dn,
                 const double* dt, double sign) {
    double txp[3];
    cross(en, dt, txp);
    for (int d = 0; d < 3; d++) {
        vel[d] += sign * im * (dn * en[d] + dt[d]);
        omg[d] -= r * ii * txp[d];
    }
}

}  // namespace

// Velocity sweeps: done when the impulses changed by at most `tolerance` of the largest normal
// impulse, or when no contact's relative velocity changed by more than its limit (`over` false:
// `velocity_tolerance` of the step's own velocity scale, or `impact_tolerance` of the impact that
// reached its grains; all ranks).
bool FixImpulseSolve::velocities_done(double change, double scale, bool over) {
    const double o = over ? 1.0 : 0.0;
    double local[3] = {change, scale, o}, global[3] = {change, scale, o};
    if (comm->nprocs > 1) MPI_Allreduce(local, global, 3, MPI_DOUBLE, MPI_MAX, world);
    last_change_ = global[1] > 0.0 ? global[0] / global[1] : 0.0;
    return global[0] <= tolerance_ * global[1] || global[2] == 0.0;
}

bool FixImpulseSolve::all_done(double change, double scale) {
    double local[2] = {change, scale}, global[2] = {change, scale};
    if (comm->nprocs > 1) MPI_Allreduce(local, global, 2, MPI_DOUBLE, MPI_MAX, world);
    last_change_ = global[1] > 0.0 ? global[0] / global[1] : 0.0;
    return global[0] <= tolerance_ * global[1];
}

// speculative on, after the solve: one sequential pass over the impacts only, each with its
// rebound target and its friction (prepare), the boundary pairs all from the end of the solve (as
// the grain's other owner does), then the others in sequence, each seeing the changes before it.
void FixImpulseSolve::rebound_pass() {
    static const double zero[3] = {0.0, 0.0, 0.0};
    double* const v = &vel_[0];
    double* const w = &omg_[0];
    for (std::size_t b = 0; b < boundary_.size(); b++) {
        Contact& c = contacts_[boundary_[b]];
        if (!(c.trest > 0.0)) continue;
        c.tn = c.trest;
        c.mu = c.mu_close;
        contact_change(c, v + 3 * c.i, w + 3 * c.i, v + 3 * c.j, w + 3 * c.j, c.dn, c.dt);
    }
    for (std::size_t b = 0; b < boundary_.size(); b++) {
        const Contact& c = contacts_[boundary_[b]];
        if (c.trest > 0.0) kick(v + 3 * c.i, w + 3 * c.i, im_[c.i], ii_[c.i], c.ri, c.en, c.dn, c.dt, 1.0);
    }
    for (std::size_t k = 0; k < contacts_.size(); k++) {
        Contact& c = contacts_[k];
        if (c.boundary || !(c.trest > 0.0)) continue;
        c.tn = c.trest;
        c.mu = c.mu_close;
        const bool wall = c.j < 0;
        if (contact_change(c, v + 3 * c.i, w + 3 * c.i, wall ? c.vwall : v + 3 * c.j, wall ? zero : w + 3 * c.j,
                           c.dn, c.dt) == 0.0)
            continue;
        kick(v + 3 * c.i, w + 3 * c.i, im_[c.i], ii_[c.i], c.ri, c.en, c.dn, c.dt, 1.0);
        if (!wall) kick(v + 3 * c.j, w + 3 * c.j, im_[c.j], ii_[c.j], c.rj, c.en, c.dn, c.dt, -1.0);
    }
    if (any_boundary_) forward(kCommVelocity);
}

// The active set (active_set yes; our choice, the "selective" Gauss-Seidel of contact solvers): a
// contact's change depends only on its two grains' velocities, so a contact whose grains did not
// move since it was last solved would not change. After the first sweep, a sweep solves only the
// contacts of the grains that a contact moved in the previous sweep by more than both stopping
// rules allow (an impulse change above `tolerance` of the largest normal impulse and a relative
// velocity change above `velocity_tolerance` of the velocity scale); the others already meet a
// rule. A settling bed's sweeps then follow the grains still moving instead of every contact of the
// bed (measured: docs/measurements/impulse-vs-hertz.md). Boundary pairs are solved in every sweep.
void FixImpulseSolve::build_adjacency(int nlocal) {
    const int n = static_cast<int>(contacts_.size());
    adj_start_.assign(static_cast<std::size_t>(nlocal) + 1, 0);
    for (int k = 0; k < n; k++) {
        const Contact& c = contacts_[k];
        if (c.boundary) continue;
        adj_start_[c.i + 1]++;
        if (c.j >= 0) adj_start_[c.j + 1]++;
    }
    for (int a = 0; a < nlocal; a++) adj_start_[a + 1] += adj_start_[a];
    adj_.resize(adj_start_[nlocal]);
    fill_.assign(adj_start_.begin(), adj_start_.end() - 1);
    for (int k = 0; k < n; k++) {
        const Contact& c = contacts_[k];
        if (c.boundary) continue;
        adj_[fill_[c.i]++] = k;
        if (c.j >= 0) adj_[fill_[c.j]++] = k;
    }
}

int FixImpulseSolve::solve_velocities(int nlocal) {
    static const double zero[3] = {0.0, 0.0, 0.0};
    double* const vel = &vel_[0];
    double* const omg = &omg_[0];
    const double* const im = &im_[0];
    const double* const ii = &ii_[0];
    Contact* const cs = contacts_.empty() ? NULL : &contacts_[0];
    const int n = static_cast<int>(contacts_.size());
    const int nb = static_cast<int>(boundary_.size());
    const int* const bidx = boundary_.empty() ? NULL : &boundary_[0];
    // the first sweep's work list: every contact but the boundary pairs, in order
    work_.clear();
    for (int k = 0; k < n; k++)
        if (!cs[k].boundary) work_.push_back(k);
    if (active_set_) {
        build_adjacency(nlocal);
        moved_.assign(static_cast<std::size_t>(nlocal), 0);
        listed_.assign(contacts_.size(), 0);
        marked_.clear();
    }
    // the largest normal impulse, kept exact as the active contacts change
    double scale = 0.0;
    for (int k = 0; k < n; k++)
        if (cs[k].pn > scale) scale = cs[k].pn;
    // the velocity rule's limits, squared: the bed's (prepare), or impact_tolerance of the fastest
    // impact that reached a contact's grains. Our choice (switchable: impact_tolerance 0 solves an
    // impact's jolt to the bed's limit): an impact's change spreads through a rigid network within the
    // step, and resolving it to g dt where it arrived at 100-1000 g dt cost a settling bed most of its
    // sweeps; 5 % of the approach speed is of the order of how well a coefficient of restitution is
    // known. The jolt travels with the changes that exceed the bed's limit, so grains it did not
    // reach keep the bed's limit (measured: docs/measurements/impulse-vs-hertz.md).
    const double vlim2 = vlim_ * vlim_;
    const double it2 = impact_tolerance_ * impact_tolerance_;
    double* const jolt = jolt_.data();
    // whether a contact's velocity change (squared) is beyond its limit; passes the jolt on
    auto beyond = [&](const Contact& c, double v2, bool owned_only) {
        const bool pair = c.j >= 0;
        const double s = pair && jolt[c.j] > jolt[c.i] ? jolt[c.j] : jolt[c.i];
        if (s > 0.0 && v2 > vlim2) {
            jolt[c.i] = s;
            if (pair && !owned_only) jolt[c.j] = s;
        }
        return v2 > std::max(vlim2, it2 * s * s);
    };
    int sweep = 0;
    last_change_ = 0.0;
    while (sweep < iterations_) {
        ++sweep;
        double change = 0.0;
        bool over = false;  // a relative velocity changed by more than its limit
        const double ilim2 = tolerance_ * tolerance_ * scale * scale;
        double top = 0.0;     // the largest normal impulse of the contacts solved in this sweep
        bool lowered = false;  // a contact at the largest normal impulse went down: find it again
        // a grain moved beyond both rules by a contact: its contacts are solved in the next sweep
        auto mark = [&](int a) {
            if (a < 0 || a >= nlocal || moved_[a] == sweep) return;
            moved_[a] = sweep;
            marked_.push_back(a);
        };
        // boundary pairs: all from the end of the previous sweep, as the grain's other owner does
        for (int b = 0; b < nb; b++) {
            Contact& c = cs[bidx[b]];
            const double m = contact_change(c, vel + 3 * c.i, omg + 3 * c.i, vel + 3 * c.j, omg + 3 * c.j, c.dn, c.dt);
            if (m > change) change = m;
            const bool x = beyond(c, m * c.wn * c.wn, true);  // m wn^2: its relative velocity change, squared
            over = over || x;
            if (c.pn > top) top = c.pn;
            if (c.pn < scale && c.pn - c.dn >= scale) lowered = true;
            if (active_set_ && m > ilim2 && x) mark(c.i);
        }
        for (int b = 0; b < nb; b++) {
            const Contact& c = cs[bidx[b]];
            kick(vel + 3 * c.i, omg + 3 * c.i, im[c.i], ii[c.i], c.ri, c.en, c.dn, c.dt, 1.0);
        }
        // the others in sequence, each seeing the changes before it
        const int nw = static_cast<int>(work_.size());
        for (int w = 0; w < nw; w++) {
            Contact& c = cs[work_[w]];
            const bool wall = c.j < 0;
            double dn, dt[3];
            const double m = contact_change(c, vel + 3 * c.i, omg + 3 * c.i, wall ? c.vwall : vel + 3 * c.j,
                                            wall ? zero : omg + 3 * c.j, dn, dt);
            if (c.pn > top) top = c.pn;
            if (m > change) change = m;
            if (m == 0.0) continue;
            if (c.pn < scale && c.pn - dn >= scale) lowered = true;
            const bool x = beyond(c, m * c.wn * c.wn, false);  // m wn^2: its relative velocity change, squared
            over = over || x;
            kick(vel + 3 * c.i, omg + 3 * c.i, im[c.i], ii[c.i], c.ri, c.en, dn, dt, 1.0);
            if (!wall) kick(vel + 3 * c.j, omg + 3 * c.j, im[c.j], ii[c.j], c.rj, c.en, dn, dt, -1.0);
            if (active_set_ && m > ilim2 && x) {
                mark(c.i);
                mark(c.j);
            }
        }
        run_solved_ += nw + nb;
        if (lowered) {
            scale = 0.0;
            for (int k = 0; k < n; k++)
                if (cs[k].pn > scale) scale = cs[k].pn;
        } else if (top > scale) {
            scale = top;
        }
        if (any_boundary_) forward(kCommVelocity);
        if (velocities_done(std::sqrt(change), scale, over)) break;  // change: the largest, squared
        if (!active_set_) continue;
        // the next sweep's work list: the contacts of the marked grains, grain by grain in the order
        // they were marked (no sort: it cost more than the sweeps it ordered)
        work_.clear();
        for (const int a : marked_)
            for (int e = adj_start_[a]; e < adj_start_[a + 1]; e++) {
                const int k = adj_[e];
                if (listed_[k] == sweep) continue;
                listed_[k] = sweep;
                work_.push_back(k);
            }
        marked_.clear();
    }
    // speculative on: after the solve, one sequential pass gives each impact its rebound, with
    // accumulated, clamped impulses and friction in its Coulomb disc. An isolated impact: the solve
    // stops it, this pass gives -e v_n: the single pass's velocities (test_liggghts_speculative).
    if (speculative_) rebound_pass();
    return sweep;
}

// Pseudo-velocities (split impulses): the same sweeps on the normal rows only, targets from the
// overlaps; positions move by dt pv, velocities are untouched.
int FixImpulseSolve::solve_positions(double dt, int nlocal) {
    const int n = static_cast<int>(contacts_.size());
    Contact* const cs = contacts_.empty() ? NULL : &contacts_[0];
    int mine = 0;
    const double* const vel = &vel_[0];
    for (int k = 0; k < n; k++) {
        Contact& c = cs[k];
        const double excess = c.overlap - slop_ * (c.ri + c.rj);
        c.b = c.separate && excess > 0.0 ? correction_ * excess / dt : 0.0;
        c.q = 0.0;
        if (c.b > 0.0) mine = 1;
        if (!(c.gap > 0.0)) continue;
        // speculative on: a close contact may close what the solved velocities leave of its gap,
        // g + dt v_n' >= 0, but not overlap: pseudo-velocity v_n >= -(g/dt + v_n') (<= 0)
        const double* const vi = vel + 3 * c.i;
        const double* const vj = c.j < 0 ? c.vwall : vel + 3 * c.j;
        const double vn = (vi[0] - vj[0]) * c.en[0] + (vi[1] - vj[1]) * c.en[1] + (vi[2] - vj[2]) * c.en[2];
        c.b = -(c.gap / dt + vn);
        if (c.b > 0.0) c.b = 0.0;
    }
    int any = mine;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (!any) return 0;

    const int nall = nlocal + atom->nghost;
    double* const pv = &pv_[0];
    std::memset(pv, 0, sizeof(double) * 3 * nall);
    const double* const im = &im_[0];
    const int nb = static_cast<int>(boundary_.size());
    const int* const bidx = boundary_.empty() ? NULL : &boundary_[0];
    int sweep = 0;
    while (sweep < iterations_) {
        ++sweep;
        double change = 0.0;
        for (int b = 0; b < nb; b++) {
            Contact& c = cs[bidx[b]];
            if (!c.separate) continue;
            const double* const a = pv + 3 * c.i;
            const double* const o = pv + 3 * c.j;
            const double vn = (a[0] - o[0]) * c.en[0] + (a[1] - o[1]) * c.en[1] + (a[2] - o[2]) * c.en[2];
            double q = c.q + c.mn * (c.b - vn);
            if (q < 0.0) q = 0.0;
            c.dn = q - c.q;
            c.q = q;
            const double moved = std::fabs(c.dn) / (c.mn * (c.ri + c.rj));
            if (moved > change) change = moved;
        }
        for (int b = 0; b < nb; b++) {
            const Contact& c = cs[bidx[b]];
            if (!c.separate) continue;
            for (int d = 0; d < 3; d++) pv[3 * c.i + d] += im[c.i] * c.dn * c.en[d];
        }
        for (int k = 0; k < n; k++) {
            Contact& c = cs[k];
            if (c.boundary || !c.separate) continue;
            const bool wall = c.j < 0;
            double* const a = pv + 3 * c.i;
            double* const o = wall ? NULL : pv + 3 * c.j;
            double vn = a[0] * c.en[0] + a[1] * c.en[1] + a[2] * c.en[2];
            if (o) vn -= o[0] * c.en[0] + o[1] * c.en[1] + o[2] * c.en[2];
            double q = c.q + c.mn * (c.b - vn);
            if (q < 0.0) q = 0.0;
            const double dq = q - c.q;
            c.q = q;
            if (dq == 0.0) continue;
            const double moved = std::fabs(dq) / (c.mn * (c.ri + c.rj));
            if (moved > change) change = moved;
            for (int d = 0; d < 3; d++) a[d] += im[c.i] * dq * c.en[d];
            if (o)
                for (int d = 0; d < 3; d++) o[d] -= im[c.j] * dq * c.en[d];
        }
        if (any_boundary_) forward(kCommPseudo);
        // done when no contact's surfaces moved by more than tolerance (r_i + r_j) in this sweep
        const double keep = last_change_;
        const bool done = all_done(change * dt, 1.0);
        last_change_ = keep;  // the statistics report the velocity solve
        if (done) break;
    }
    double** const x = atom->x;
    for (int k = 0; k < nlocal; k++)
        for (int d = 0; d < 3; d++) x[k][d] += dt * pv[3 * k + d];
    return sweep;
}

// The impulses as one-step forces (velocity Verlet's two half kicks give u' = u + P/m), on the
// owned grains, the walls' stored forces and the meshes' element forces; and into the history.
void FixImpulseSolve::apply_forces(double dt, int nlocal, bool store_history) {
    double** const f = atom->f;
    double** const torque = atom->torque;
    const double step = static_cast<double>(update->ntimestep);
    const int n = static_cast<int>(contacts_.size());
    const double inv = 1.0 / dt;  // impulses to one-step forces
    for (int k = 0; k < n; k++) {
        Contact& c = contacts_[k];
        const int i = c.i, j = c.j;
        double F[3], txp[3];
        for (int d = 0; d < 3; d++) F[d] = (c.pn * c.en[d] + c.pt[d]) * inv;
        cross(c.en, c.pt, txp);
        for (int d = 0; d < 3; d++) {
            f[i][d] += F[d];
            torque[i][d] -= c.ri * txp[d] * inv;
        }
        if (j >= 0 && j < nlocal)
            for (int d = 0; d < 3; d++) {
                f[j][d] -= F[d];
                torque[j][d] -= c.rj * txp[d] * inv;
            }
        if (c.wallforce)
            for (int d = 0; d < 3; d++) c.wallforce[d] += F[d];
        if (c.mesh) c.mesh->add_particle_contribution(i, F, c.delta, c.tri, c.vwall);
        if (store_history && c.history) {
            c.history[kHistPn] = c.pn;
            for (int d = 0; d < 3; d++) c.history[kHistPt + d] = c.pt[d];
            c.history[kHistStep] = step;
            if (c.pn > 0.0 && !c.impact) c.history[kHistLoad] = c.pn;
        }
    }
}

void FixImpulseSolve::forward(int mode) {
    comm_mode_ = mode;
    comm->forward_comm_fix(this);
}

int FixImpulseSolve::pack_comm(int n, int* list, double* buf, int, int*) {
    int m = 0;
    for (int k = 0; k < n; k++) {
        const int a = list[k];
        if (comm_mode_ == kCommPseudo) {
            for (int d = 0; d < 3; d++) buf[m++] = pv_[3 * a + d];
            continue;
        }
        for (int d = 0; d < 3; d++) buf[m++] = vel_[3 * a + d];
        for (int d = 0; d < 3; d++) buf[m++] = omg_[3 * a + d];
        if (comm_mode_ == kCommStart) buf[m++] = split_[a];
        if (comm_mode_ == kCommVelocity) buf[m++] = jolt_[a];
    }
    // values per atom: LIGGGHTS 3.8's Comm::forward_comm_fix sends n times the number of atoms
    return comm_mode_ == kCommPseudo ? 3 : 7;
}

void FixImpulseSolve::unpack_comm(int n, int first, double* buf) {
    int m = 0;
    for (int a = first; a < first + n; a++) {
        if (comm_mode_ == kCommPseudo) {
            for (int d = 0; d < 3; d++) pv_[3 * a + d] = buf[m++];
            continue;
        }
        for (int d = 0; d < 3; d++) vel_[3 * a + d] = buf[m++];
        for (int d = 0; d < 3; d++) omg_[3 * a + d] = buf[m++];
        if (comm_mode_ == kCommStart) split_[a] = buf[m++];
        if (comm_mode_ == kCommVelocity) jolt_[a] = buf[m++];
    }
}

// 1 velocity sweeps of the last step, 2 position sweeps of the last step, 3 mean velocity
// sweeps per step of this run, 4 steps of this run that ended at the cap unconverged, 5
// contacts of the last step (all ranks; a pair across ranks counts on both), 6 the last step's
// final relative change (largest impulse change / largest normal impulse), 7 the last step's
// largest overlap / (r_i + r_j), 8 steps of this run with an overlap beyond overlap_limit, 9 the
// largest overlap of this run / (r_i + r_j), 10 mean contact solves per step of this run (velocity
// sweeps; with the active set fewer than sweeps times contacts).
double FixImpulseSolve::compute_vector(int k) {
    if (superseded_) return active()->compute_vector(k);
    switch (k) {
        case 0: return last_sweeps_;
        case 1: return last_position_sweeps_;
        case 2: return run_steps_ > 0 ? static_cast<double>(run_sweeps_) / static_cast<double>(run_steps_) : 0.0;
        case 3: return static_cast<double>(run_capped_);
        case 4: {
            double mine = static_cast<double>(contacts_.size()), all = mine;
            MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE, MPI_SUM, world);
            return all;
        }
        case 5: return last_change_;
        case 6: return last_overlap_;
        case 7: return static_cast<double>(run_bad_steps_);
        case 8: return run_max_overlap_;
        case 9: return run_steps_ > 0 ? static_cast<double>(run_solved_) / static_cast<double>(run_steps_) : 0.0;
        default: return 0.0;
    }
}

void FixImpulseSolve::post_run() {
    if (superseded_) return;
    report_overlaps();
    if (run_capped_ == 0 || comm->me != 0) return;
    char msg[256];
    std::snprintf(msg, sizeof(msg),
                  "fix impulse/solve: %lld of %lld steps stopped at the cap of %d sweeps before the impulses "
                  "changed by less than tolerance %g (mean %.1f sweeps per step)",
                  static_cast<long long>(run_capped_), static_cast<long long>(run_steps_), iterations_, tolerance_,
                  run_steps_ > 0 ? static_cast<double>(run_sweeps_) / static_cast<double>(run_steps_) : 0.0);
    error->warning(FLERR, msg);
}
