// Seeds: a particle point answered by independent realisations, pooled into one answer, the same for
// `granlub dem` and `granlub yade` (the layout and files: docs/architecture.md, "Seeds").
//  - [particles] seeds (a count N or a list of seeds) and --seeds N|LIST, which overrides it, name the
//    set. N seeds are s, s + 1, ..., s + N - 1 from the base seed s, [particles] seed.
//  - One seed: the point runs as it always did, into <point>/ (the same layout, the same bytes);
//    --seed S then is that seed, as before.
//  - Several: each member S runs into <point>/seed-<S>/ as a point of its own (its own size draw,
//    insertion and packing, its own time-step check and continuation), --seed S only that member
//    (an error names the set when S is none), and the point's own profile.csv and summary.json pool
//    the members that are complete (seed_pool.h). YADE's member S warm-starts from DEM's member S.
#pragma once
#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub {

struct SeedSet {
    std::vector<std::uint64_t> seeds;  // the set, ascending
    std::vector<std::uint64_t> run;    // the members this run computes: all of them, or --seed's
    bool pooled() const { return seeds.size() > 1; }
};

// The set of a run: --seeds (o.seeds) or [particles] seeds, and --seed. Throws CaseError naming the
// key or the flag, the value and what is allowed (0 seeds, a repeated seed, a malformed --seeds, a
// --seed that is no member of a set of several).
SeedSet seed_set(const Case& c, const RunOptions& o);

// The folder of `solver`'s result of point `point` that a run with options o writes or reads:
// <results>/<solver>/<point>/, or with a set of seeds .../<point>/seed-<S>/ with S = o.seed (the
// sweep sets it for each member). YADE's warm start reads DEM's final state there.
std::filesystem::path point_result_dir(const Case& c, const RunOptions& o, const std::string& solver,
                                       const std::string& point);
// The initial configuration's folder below <results>/initial/<point>/ ("" for one seed, else
// seed-<S>): each member keeps its own initial grains.
std::filesystem::path initial_subfolder(const Case& c, const RunOptions& o);

// How a run's lines (progress, continuation) name the point: "U2.0", or "U2.0/seed-3" for a member of
// a set of seeds, read from the run's folder (<point>/seed-<S>/, or a check folder inside it).
std::string point_label(const std::string& point, const std::filesystem::path& dir);

// A particle engine's sweep (`granlub dem`, `granlub yade`): with one seed run_sweep over the points,
// solve() given o as it is; with several, over every point's members (run_sweep's Realisations),
// each pooled into the point's files (pool_seeds) after it completes. Points, or points x members,
// share the machine's slots (points_at_once).
using SeedSolver =
    std::function<PointResult(const OperatingPoint&, const RunOptions&, const std::filesystem::path& dir)>;
int run_particle_sweep(const Case& c, const std::string& solver, const RunOptions& o, const SeedSolver& solve,
                       const std::vector<std::string>& reads = {});

}  // namespace granlub
