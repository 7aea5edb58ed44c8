// The answer of a point pooled over its seeds (seeds.h), one reduction for both particle engines:
// from the members complete in <point>/seed-<S>/, taken in ascending seed order, the point's own
// profile.csv and summary.json (docs/architecture.md, "Seeds"):
//   - each output and each profile column: the mean over the members; stderr (<column>_stderr) the
//     seeds' standard error, the sample standard deviation over the members / sqrt(n); block_stderr
//     (<column>_block_stderr) the members' own block errors combined, sqrt(sum se_i^2) / n, what they
//     alone would claim. An output the same in every member and without an error (max_solid_fraction)
//     stays so. dt_error: the mean of the members' [ASSUMPTION] (a bound on the mean's: the members
//     record |differences| only, and |mean of differences| <= mean of |differences|). One member
//     alone keeps its own errors.
//   - run.status: steady only if every member is (its Δt check included); otherwise the status of the
//     first member in seed order that is not, the reason naming each; while a member of the set is
//     missing, "incomplete" ("k of N seeds"), never an answer.
//   - run.flow_regime and run.order (two or more members): every number with a <name>_stderr partner
//     and the measured means without one (kPooledRunBlocks in seed_pool.cpp) pooled as the outputs,
//     the block errors combined as <name>_block_stderr; the flow-regime verdict recomputed from the
//     pooled numbers by flow_regime_json (flow_regime.h); a number missing in some member null.
//     Counts and settings there, and the rest of run (walls, load control, the Δt check record), are
//     the lowest member's; run.seeds.run_facts_from names each fact: pooled, recomputed, the lowest's.
//   - run.seeds: the set, the seeds pooled and those missing with why, the error used, each
//     member's status and outputs, run_facts_from; run.wall_clock_s the members' sum.
//   - provenance: the lowest member's, with no single seed, the latest member's time and a run id
//     made from the members' (seeds-<hash>): the files are a function of the members' files alone,
//     so the same seeds give the same bytes in any order of completion.
// With no member complete the point's files are removed. Throws Error when the members' profiles
// do not share their columns and stations.
#pragma once
#include <cstdint>
#include <filesystem>
#include <vector>

#include "granlub/results/results.h"

namespace granlub {

void pool_seeds(const std::filesystem::path& point_dir, const std::vector<std::uint64_t>& seeds,
                const ResultKey& key);

}  // namespace granlub
