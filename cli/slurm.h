// `granlub slurm CASE`: the case's particle runs as Slurm job arrays, for a cluster whose nodes share
// the results folder (issue 76). granlub schedules nothing itself: it writes the job scripts, and
// with --submit hands them to `sbatch`.
//
// One array per particle engine selected (dem, yade), one task per point and seed, each task one
// `granlub dem|yade CASE --point <id> [--seeds <set> --seed <S>] [--np R]` (its MPI ranks as Slurm
// tasks). The runs share the case's results through the per-point locks (run_lock.h), so tasks on
// different points never wait for each other. YADE's task i warm-starts from DEM's task i (the same
// point and seed), so with [yade] start = "warm" yade's array depends on dem's task by task
// (--dependency=aftercorr); DEM's task that failed takes its YADE task with it
// (--kill-on-invalid-dep). A last job runs the other solvers selected (continuum, automaton: seconds
// to minutes, no array) and `granlub compare` once every task has ended, whatever its exit
// (afterany): a failed point is a row of the report that says why, not a reason to have no report.
//
// The files, written atomically into <results>/slurm/ (kSlurmDir) with their provenance:
//   <engine>.sbatch   the array of one engine
//   compare.sbatch    the last job
//   submit.sh         the sbatch commands with their dependencies: `bash submit.sh` submits them
//   logs/             where the jobs write (Slurm's --output)
#pragma once
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "granlub/case/case.h"
#include "granlub/run/sweep.h"

namespace granlub::cli {

struct SlurmOptions {
    std::vector<std::string> solvers;  // empty: every solver compiled in
    std::vector<std::string> points;   // empty: every point of the case
    std::string partition;             // empty: the cluster's default
    std::string time;                  // a task's time limit in Slurm's format; empty: the partition's
    bool submit = false;               // run submit.sh (sbatch) after writing
    std::string command;               // the granlub command line that asked, for the provenance
};

// Slurm's time formats (sbatch --time), for --time: "" when `t` is one, else what is allowed.
std::string slurm_time_error(const std::string& t);
// A partition name or comma-separated list (sbatch --partition): "" when `p` is one, else what is allowed.
std::string slurm_partition_error(const std::string& p);

// Writes the scripts (and submits them with s.submit); returns the exit code: 0, 1 when sbatch
// failed, 2 for bad input (an unknown point or solver) or, with --submit, no sbatch on PATH (the
// scripts are written all the same, to copy to a machine that has Slurm).
int slurm_jobs(const Case& c, const RunOptions& o, const SlurmOptions& s);

}  // namespace granlub::cli
