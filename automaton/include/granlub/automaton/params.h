// Plain parameters of one CA run, in lattice units (U = 1, cell = one grain diameter).
// A field marked "key" is set by that [automaton] key: its default, range and doc are declared once
// with the key (src/section.cpp, keys.h), and Params() starts from those defaults. The other fields
// come from the case's other sections (case_mapping.h); their initial values are JH06's lattice.
// The switches' case-file names are in variants.h. The tags say where each rule comes from
// (docs/automaton-model.md §1).
#pragma once
#include <cstdint>
#include <optional>
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
    Mode mode{};                // key mode
    double e_p = 0.85;          // grain-grain restitution, JH06 Eqs. 8-9
    double e_w_bottom = 0.65;   // grain-wall restitution, JH06 Eq. 7
    double e_w_top = 0.65;
    double R_bottom = 0.65;     // roughness, JH06 Eq. 6
    double R_top = 0.65;        // [ASSUMPTION] = R unless set
    double p_drag = 0.65;       // key p_drag, else = R_bottom: drag-notch probability at the moving wall
    int tf_max{};               // key tf_max: slowest time factor; slower grains are at rest [ASSUMPTION]
    TfRounding tf_rounding{};   // key tf_rounding
    WallSpeed wall_speed{};     // key wall_speed
    int pp_deflect{};           // key pp_deflect: mover leaves at +-90 (billiard) or +-45 degrees [RECON]
    StruckDir struck_dir{};     // key struck_dir
    double pp_jitter_deg{};     // key pp_jitter: vector mode, spread of the line of centres [ASSUMPTION]
    VecBlocked vec_blocked{};   // key vec_blocked
};

// The lattice's bounds: rows and columns >= 3 (gap and length >= 2.5 grain diameters); the memory
// of the lattice and its grains (a few tens of bytes per cell) and int indices bound the cells.
constexpr int kMinCells = 3;
constexpr double kMaxLatticeCells = 5e7;

// Lattice size and initial state (§2.1, §2.5).
struct LatticeSpec {
    int columns = 100;     // L, periodic along x
    int rows = 10;         // H particle rows between the wall rows y = -1 and y = H
    double fill = 0.85;    // key fill, else from the point: nu0, N = round(fill * L * H)
    double s0_max{};       // key s0_max: initial u_p uniform on (0, s0_max] [ASSUMPTION]
    std::int64_t particles() const;
};

// Run length, sampling and ensemble (§4.4).
struct RunSpec {
    std::int64_t steps{};             // key steps (steps_full with --full)
    std::int64_t t_avg_start{};       // key t_avg_start: the sampling window is [t_avg_start, steps)
    std::int64_t block{};             // key block: for steady-state checks and standard errors
    std::int64_t sample_every{};      // key sample_every
    std::int64_t timeseries_every{};  // key timeseries_every
    int replicas{};                   // key replicas (replicas_full): independent runs, one RNG stream pair each
    int threads{};                    // key threads: 0 = min(replicas, hardware threads)
    std::uint64_t seed{};             // key seed
    double steady_tol_u{};            // key steady_tol_u: block test tolerances (§4.4)
    double steady_tol_nu{};           // key steady_tol_nu
    int steady_pairs = 3;             // consecutive passing block pairs
    double drift_tol = 0.005;         // max |slope| of <u_p>(block) over the last 5 blocks, U/block
    // JH06's literal protocol (§4.5): runs of T_1 = runs_start, T_k = 2 T_(k-1) steps; each run's
    // reading is its average over its second half [ASSUMPTION]; stop when consecutive readings agree.
    SteadyProtocol steady_protocol{};  // key steady_state
    std::int64_t runs_start{};         // key runs_start: T_1, a multiple of 2 x block
    std::int64_t runs_max_steps{};     // key runs_max_steps: fail if T_k would exceed it
    double runs_tol_u{};               // key runs_tol_u: max_y |du| / U between consecutive runs (§4.5)
    double runs_tol_nu{};              // key runs_tol_nu: max_y |dnu| between consecutive runs (§4.5)
    std::int64_t snapshot_every{};     // key snapshot_every, with --vtk only; 0: no lattice snapshots
};

struct Params {
    Params();  // every key at its default (src/section.cpp), JH06's lattice
    LatticeSpec lattice;
    Rules rules;
    RunSpec run;
};

// Throws granlub::Error naming the parameter, its value and what is allowed.
void validate(const Params& p);

// A rule between keys (each key's own range is the schema's): the key to blame and what is
// allowed. The one list of such rules, checked on the case file (section.cpp) and by validate().
struct KeyProblem {
    std::string key;
    std::string allowed;
};
std::optional<KeyProblem> broken_key_rule(const Params& p);

}  // namespace granlub::automaton
