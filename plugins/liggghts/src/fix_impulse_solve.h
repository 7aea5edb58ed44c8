// fix ID all impulse/solve [keyword value ...]: solves all contacts of model impulse / tangential
// impulse with `iterate on` together, every step, until the impulses converge (projected
// Gauss-Seidel with accumulated, clamped impulses; overlaps corrected with pseudo-velocities).
// Doc: plugins/liggghts/doc/fix_impulse_solve.txt; the rules and their sources: the .cpp.
// The FixStyle line lets the pair of files drop into a LIGGGHTS 3.8 src/ with the model headers
// (not checked by tools/check-in-tree-build, which copies the model headers only); the plugin
// registers the style itself (register_fix_compute.cpp).
#ifdef FIX_CLASS
FixStyle(impulse/solve,FixImpulseSolve)
#else

#ifndef GRANLUB_FIX_IMPULSE_SOLVE_H
#define GRANLUB_FIX_IMPULSE_SOLVE_H

#include <string>
#include <vector>

#include "fix.h"
#include "impulse_contacts.h"

namespace LAMMPS_NS {

class FixImpulseSolve : public Fix, public LIGGGHTS::ContactModels::ImpulseContactSink {
public:
    FixImpulseSolve(class LAMMPS* lmp, int narg, char** arg);
    int setmask();
    void init();
    void setup(int vflag);
    void pre_initial_integrate();
    void pre_final_integrate();
    void post_run();
    double compute_vector(int n);
    int pack_comm(int n, int* list, double* buf, int pbc_flag, int* pbc);
    void unpack_comm(int n, int first, double* buf);

private:
    typedef LIGGGHTS::ContactModels::ImpulseContact Contact;

    void check_styles();
    [[noreturn]] void refuse(const std::string& msg) const;
    void grow(int nall);
    void prepare(double dt, int nlocal);
    int solve_velocities(int nlocal);
    void build_adjacency(int nlocal);
    void rebound_pass();
    int solve_positions(double dt, int nlocal);
    void apply_forces(double dt, int nlocal, bool store_history);
    void forward(int mode);
    bool all_done(double change, double scale);
    bool velocities_done(double change, double scale, bool over);
    void watch_overlaps(bool positions_capped);  // fix_impulse_solve_watch.cpp
    void report_overlaps() const;
    FixImpulseSolve* active();                   // the fix that solves (the deck's, if this is superseded)

    // settings (doc/fix_impulse_solve.txt)
    double tolerance_;    // largest impulse change / largest impulse of the step, to stop
    int iterations_;      // cap on the sweeps, for the velocities and for the positions each
    bool warm_start_;     // start from the impulses of the contact's previous step
    bool restitution_all_;  // restitution also for contacts pressed at the previous step
    double rest_factor_;    // approaches below this times the contact's load velocity: no restitution
    double slop_;         // overlap left uncorrected, fraction of r_i + r_j
    double correction_;   // fraction of the rest removed per step
    double velocity_tolerance_;  // ... or the largest velocity change / the bed's velocity scale (g dt), to stop
    double impact_tolerance_;    // ... or / the approach speed of the impact that reached its grains (jolt_), if larger
    bool active_set_;            // after the first sweep, solve only contacts whose grains moved
    double vlim_;                // velocity_tolerance's limit of this step (all ranks; prepare)
    double overlap_limit_;  // an overlap beyond this fraction of r_i + r_j was not removed: warn
    bool overlap_error_;    // ... or stop (keyword overlaps warn|error)

    // per atom (owned and ghost), grown only: velocities being solved, inverse mass and inertia,
    // boundary-contact counts (mass splitting), pseudo-velocities
    std::vector<double> vel_, omg_, im_, ii_, split_, pv_;
    // per atom: the fastest impact that reached the grain in this step (its approach speed; prepare,
    // carried along by the sweeps: impact_tolerance)
    std::vector<double> jolt_;
    // active set (solve_velocities): each owned grain's contacts (CSR: adj_start_, adj_), the sweep
    // that last moved a grain beyond the stopping rules, the grains it moved, the sweep that listed a
    // contact, and the sweep's work list (contact indices, in order)
    std::vector<int> adj_start_, adj_, fill_, moved_, marked_, listed_, work_;
    std::vector<int> boundary_;  // indices of the boundary contacts of this step
    int comm_mode_;
    bool any_boundary_;          // on any rank: then ghosts are refreshed after every sweep
    int kinematic_bits_;         // groups of fix move / freeze: atoms whose motion is prescribed
    int dynamic_bits_;           // groups of the other time-integrating fixes
    bool setup_pending_;         // a run's setup collected contacts: apply their stored impulses
    bigint setup_step_;          // the step of that setup

    // statistics (compute_vector, post_run)
    int last_sweeps_, last_position_sweeps_;
    double last_change_;
    bigint run_steps_, run_sweeps_, run_capped_, run_solved_;
    // overlaps (fix_impulse_solve_watch.cpp): the largest of the last step (fraction of r_i + r_j),
    // steps of this run with overlaps not removed, the largest of the run and its step, warnings
    double last_overlap_, run_max_overlap_;
    bigint run_bad_steps_, run_max_overlap_step_, run_position_capped_, warned_at_;
    bool superseded_;  // the made fix, when the deck has its own (init): inert, reports the deck's
};

}  // namespace LAMMPS_NS

#endif
#endif
