// Plain parameters of one CA run, in lattice units (U = 1, cell = one grain diameter).
// Names and defaults are the [automaton] keys (automaton/README.md); the switches' case-file names
// are in variants.h. The tags say where each rule comes from (docs/automaton-model.md §1).
#pragma once
#include <cstdint>
#include <string>

namespace granlub::automaton {

enum class Mode { JH, Vector };                   // jh: JH06 as specified (§3); vector: §5 [ASSUMPTION]
enum class TfRounding { Round, Ceil, Accumulate };  // §2.4 [ASSUMPTION]
enum class WallSpeed { Sequential, ByIncidence };   // §3.3 [ASSUMPTION]
enum class StruckDir { Line, Keep };                 // §3.4 [ASSUMPTION]
enum class VecBlocked { Deflect, Wait };             // §5 [ASSUMPTION]
enum class SteadyProtocol { Blocks, Runs };          // §4.4 block test, or JH06's literal runs (§4.5)

// The collision rules and their switches.
struct Rules {
    Mode mode = Mode::JH;
    double e_p = 0.85;          // grain-grain restitution, JH06 Eqs. 8-9
    double e_w_bottom = 0.65;   // grain-wall restitution, JH06 Eq. 7
    double e_w_top = 0.65;
    double R_bottom = 0.65;     // roughness, JH06 Eq. 6
    double R_top = 0.65;        // [ASSUMPTION] = R unless set
    double p_drag = 0.65;       // drag-notch probability at the moving wall [ASSUMPTION] = R
    int tf_max = 50;            // slowest time factor; slower grains are at rest [ASSUMPTION]
    TfRounding tf_rounding = TfRounding::Round;
    WallSpeed wall_speed = WallSpeed::Sequential;
    int pp_deflect = 90;        // mover leaves at +-90 (billiard) or +-45 degrees [RECON]
    StruckDir struck_dir = StruckDir::Line;
    double pp_jitter_deg = 22.5;  // vector mode: spread of the line of centres [ASSUMPTION]
    VecBlocked vec_blocked = VecBlocked::Deflect;
};

// Lattice size and initial state (§2.1, §2.5).
struct LatticeSpec {
    int columns = 100;     // L, periodic along x
    int rows = 10;         // H particle rows between the wall rows y = -1 and y = H
    double fill = 0.85;    // nu0: N = round(fill * L * H)
    double s0_max = 0.1;   // initial u_p uniform on (0, s0_max] [ASSUMPTION: the value of "much smaller"]
    std::int64_t particles() const;
};

// Run length, sampling and ensemble (§4.4).
struct RunSpec {
    std::int64_t steps = 10000;
    std::int64_t t_avg_start = 2000;  // the sampling window is [t_avg_start, steps)
    std::int64_t block = 500;         // block length for steady-state checks and standard errors
    std::int64_t sample_every = 1;
    std::int64_t timeseries_every = 10;
    int replicas = 1;                 // independent runs, one RNG stream pair each
    int threads = 0;                  // 0: min(replicas, hardware threads)
    std::uint64_t seed = 1;
    double steady_tol_u = 0.02;       // block test tolerances (§4.4)
    double steady_tol_nu = 0.02;
    int steady_pairs = 3;             // consecutive passing block pairs
    double drift_tol = 0.005;         // max |slope| of <u_p>(block) over the last 5 blocks, U/block
    // JH06's literal protocol (§4.5): runs of T_1 = runs_start, T_k = 2 T_(k-1) steps; each run's
    // reading is its average over its second half [ASSUMPTION]; stop when consecutive readings agree.
    SteadyProtocol steady_protocol = SteadyProtocol::Blocks;
    std::int64_t runs_start = 1000;      // T_1, a multiple of 2 x block
    std::int64_t runs_max_steps = 16000; // step limit: fail if T_k would exceed it
    double runs_tol_u = 0.01;            // max_y |du| / U between consecutive runs (§4.5)
    double runs_tol_nu = 0.01;           // max_y |dnu| between consecutive runs (§4.5)
    std::int64_t snapshot_every = 0;  // 0: no lattice snapshots
};

struct Params {
    LatticeSpec lattice;
    Rules rules;
    RunSpec run;
};

// Throws granlub::Error naming the parameter, its value and what is allowed.
void validate(const Params& p);

}  // namespace granlub::automaton
