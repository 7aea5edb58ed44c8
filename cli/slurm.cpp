// `granlub slurm CASE`: job scripts for Slurm, written and optionally submitted (slurm.h).
#include "slurm.h"

#include <algorithm>
#include <cstdio>
#include <regex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "granlub/error.h"
#include "granlub/particles/seeds.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "granlub/run/process.h"
#include "granlub/text.h"
#include "modules.h"

namespace granlub::cli {

namespace fs = std::filesystem;

std::string slurm_time_error(const std::string& t) {
    static const std::regex forms(R"(\d+|\d+:\d+|\d+:\d+:\d+|\d+-\d+|\d+-\d+:\d+|\d+-\d+:\d+:\d+)");
    if (std::regex_match(t, forms)) return "";
    return fmt::format("'{}' is not a Slurm time limit (allowed: minutes, minutes:seconds, hours:minutes:seconds, "
                       "days-hours, days-hours:minutes or days-hours:minutes:seconds, e.g. 90 or 1-12:00:00)",
                       t);
}

std::string slurm_partition_error(const std::string& p) {
    static const std::regex name(R"([A-Za-z0-9_.\-]+(,[A-Za-z0-9_.\-]+)*)");
    if (std::regex_match(p, name)) return "";
    return fmt::format("'{}' is not a partition name (allowed: letters, digits, '_', '.', '-'; several separated by "
                       "commas; `sinfo` lists the cluster's)",
                       p);
}

namespace {

// A word for bash, single-quoted: nothing in it is expanded.
std::string sh(const std::string& s) {
    std::string out = "'";
    for (const char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
    return out + "'";
}

// The realisations each point's task runs: empty for one seed (one task per point, with the case's
// seed or --seed, the layout of today); with a set of more than one seed ([particles] seeds,
// --seeds), its members, one task each.
std::vector<std::uint64_t> task_seeds(const Case& c, const RunOptions& o) {
    const SeedSet set = seed_set(c, o);  // bad input (0 seeds, repeats, --seed outside the set) stops here
    return set.pooled() ? set.run : std::vector<std::uint64_t>{};
}

// What runs where: the engines as arrays over points x seeds, the other solvers in the last job.
struct Plan {
    std::vector<const SolverModule*> engines, others;
    std::vector<const OperatingPoint*> points;
    bool every_point = true;
    std::vector<std::uint64_t> seeds;
    std::size_t seeds_per_point() const { return std::max<std::size_t>(1, seeds.size()); }
    std::size_t tasks() const { return points.size() * seeds_per_point(); }
    bool runs(const std::string& solver) const {
        return std::any_of(engines.begin(), engines.end(), [&](const auto* m) { return m->name == solver; });
    }
};

// A job after the arrays: the other solvers, the report.
bool last_job(const Plan& p) { return !p.others.empty() || have_compare(); }

Plan plan_of(const Case& c, const RunOptions& o, const SlurmOptions& s) {
    Plan p;
    for (const auto& m : solver_modules())
        if (s.solvers.empty() || std::find(s.solvers.begin(), s.solvers.end(), m.name) != s.solvers.end())
            (m.info.engine ? p.engines : p.others).push_back(&m);
    if (p.engines.empty() && p.others.empty()) throw CaseError("--solvers: no solver selected (and none compiled in)");
    for (const auto& id : s.points)
        for (const OperatingPoint* q : c.select(id))  // an unknown id: CaseError naming the case's ids
            if (std::find(p.points.begin(), p.points.end(), q) == p.points.end()) p.points.push_back(q);
    if (p.points.empty()) p.points = c.select("");
    p.every_point = p.points.size() == c.points.size();
    if (!p.engines.empty()) p.seeds = task_seeds(c, o);
    return p;
}

// What each script says first: what it is, where it came from.
std::string header(const Case& c, const SlurmOptions& s, const std::string& what) {
    return fmt::format("#!/bin/bash\n"
                       "# {}\n"
                       "# Written by granlub {} at {} from the case {} ({}, hash {})\n"
                       "# by: {}\n",
                       what, version(), utc_now(), c.name, one_line(c.file.string()), c.file_hash,
                       one_line(s.command));
}

// The paths every job uses, as variables a user can edit when the cluster's nodes see them elsewhere.
std::string paths(const fs::path& granlub, const Case& c, const fs::path& results) {
    return fmt::format("# granlub, the case and its results as the cluster's nodes see them (edit if they differ)\n"
                       "granlub={}\ncase={}\nresults={}\n",
                       sh(granlub.string()), sh(fs::absolute(c.file).lexically_normal().string()),
                       sh(results.string()));
}

std::string sbatch_lines(const SlurmOptions& s) {
    std::string out;
    if (!s.partition.empty()) out += fmt::format("#SBATCH --partition={}\n", s.partition);
    return out;
}

// The options every run of `solver` passes on from `granlub slurm`.
std::string common_args(const SolverModule& m, const RunOptions& o, const Plan& p) {
    std::string out;
    if (o.full) out += " --full";
    if (o.force) out += " --force";
    if (o.seed && m.info.seeded && (p.seeds.size() <= 1 || !m.info.engine)) out += fmt::format(" --seed {}", *o.seed);
    if (o.np > 1 && m.info.ranks) out += fmt::format(" --np {}", o.np);
    return out;
}

std::string array_script(const SolverModule& m, const Case& c, const RunOptions& o, const SlurmOptions& s,
                         const Plan& p, const fs::path& granlub, const fs::path& results) {
    std::vector<std::string> ids, seeds;
    for (const auto* q : p.points) ids.push_back(sh(q->id));
    for (const auto v : p.seeds) seeds.push_back(std::to_string(v));
    const int ranks = m.info.ranks ? std::max(1, o.np) : 1;
    std::string out = header(c, s, fmt::format("The {} runs of the case {} as a Slurm job array: {} point(s) x {} seed(s) = "
                                               "{} task(s), task i runs point i / seeds with seed i % seeds.",
                                               m.name, c.name, p.points.size(), p.seeds_per_point(), p.tasks()));
    out += "# Submit it with submit.sh beside it (the dependencies, the log files), or by hand with sbatch.\n";
    out += fmt::format("#SBATCH --job-name=granlub-{}\n#SBATCH --array=0-{}\n", m.name, p.tasks() - 1);
    out += fmt::format("#SBATCH --ntasks={}\n#SBATCH --cpus-per-task=1\n", ranks);  // MPI ranks as Slurm tasks
    out += sbatch_lines(s);
    if (!s.time.empty()) out += fmt::format("#SBATCH --time={}\n", s.time);
    out += "set -euo pipefail\n" + paths(granlub, c, results);
    out += fmt::format("points=({})\nseeds=({})\n", fmt::join(ids, " "), fmt::join(seeds, " "));
    out += "n=$(( ${#seeds[@]} > 0 ? ${#seeds[@]} : 1 ))\n"
           "i=${SLURM_ARRAY_TASK_ID:?submit this script with sbatch: it is a job array}\n";
    out += fmt::format("args=({} \"$case\" --results \"$results\" --point \"${{points[i / n]}}\"{})\n", m.name,
                       common_args(m, o, p));
    if (!p.seeds.empty())
        out += fmt::format("args+=(--seeds {} --seed \"${{seeds[i % n]}}\")\n", fmt::join(seeds, ","));
    out += "exec \"$granlub\" \"${args[@]}\"\n";
    return out;
}

std::string last_script(const Case& c, const RunOptions& o, const SlurmOptions& s, const Plan& p,
                        const fs::path& granlub, const fs::path& results) {
    std::string out = header(c, s, fmt::format("The last job of the case {}, once every particle task has ended: {}.",
                                               c.name, p.others.empty() ? "the report" : "the other solvers, then the report"));
    out += "# Submit it with submit.sh beside it (the dependencies), or by hand with sbatch.\n";
    out += "#SBATCH --job-name=granlub-compare\n#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n" + sbatch_lines(s);
    out += "set -uo pipefail\n" + paths(granlub, c, results) + "rc=0\n";
    for (const auto* m : p.others) {
        if (p.every_point) {
            out += fmt::format("\"$granlub\" {} \"$case\" --results \"$results\"{} || rc=1\n", m->name, common_args(*m, o, p));
            continue;
        }
        for (const auto* q : p.points)
            out += fmt::format("\"$granlub\" {} \"$case\" --results \"$results\" --point {}{} || rc=1\n", m->name,
                               sh(q->id), common_args(*m, o, p));
    }
    if (have_compare())
        out += fmt::format("\"$granlub\" compare \"$case\" --results \"$results\"{} || rc=1\n",
                           p.points.size() == 1 ? " --point " + sh(p.points.front()->id) : "");
    out += "exit $rc\n";
    return out;
}

std::string submit_script(const Case& c, const SlurmOptions& s, const Plan& p) {
    std::string out = header(c, s, "Submits the jobs of this folder with their dependencies and prints one line a job: "
                                   "<name> <job id>.");
    out += "set -euo pipefail\nhere=$(cd \"$(dirname \"${BASH_SOURCE[0]}\")\" && pwd)\nmkdir -p \"$here/logs\"\n";
    std::vector<std::string> ended;  // the arrays the last job waits for
    for (const auto* m : p.engines) {
        std::string dep;
        // a warm start (SolverInfo::warm_from): each task starts from the final state of the same task of
        // the solver it starts from
        const char* from = m->info.warm_from;
        if (from && p.runs(from) && c.sections.contains(m->name) && c.section(m->name).string("start") == "warm")
            dep = fmt::format(" --dependency=aftercorr:${} --kill-on-invalid-dep=yes", from);
        out += fmt::format("{0}=$(sbatch --parsable --output=\"$here/logs/{0}-%A_%a.out\"{1} \"$here/{0}.sbatch\")\n"
                           "{0}=${{{0}%%;*}}\necho \"{0} ${0}\"\n",
                           m->name, dep);
        ended.push_back("$" + m->name);
    }
    if (last_job(p))
        out += fmt::format("last=$(sbatch --parsable --output=\"$here/logs/compare-%j.out\"{} \"$here/compare.sbatch\")\n"
                           "echo \"compare ${{last%%;*}}\"\n",
                           ended.empty() ? "" : fmt::format(" --dependency=afterany:{}", fmt::join(ended, ":")));
    return out;
}

}  // namespace

int slurm_jobs(const Case& c, const RunOptions& o, const SlurmOptions& s) {
    const Plan p = plan_of(c, o, s);
    // bad input stops here, before a job is queued (CaseError, exit 2); a point a solver cannot run
    // is left to its task, which says why in its log and the report
    for (const auto& list : {p.engines, p.others})
        for (const auto* m : list) check_input(*m, c, o);
    const fs::path results = fs::absolute(results_root(c, o)).lexically_normal();
    const fs::path dir = results / kSlurmDir;
    const fs::path granlub = fs::read_symlink("/proc/self/exe");
    fs::create_directories(dir / "logs");
    for (const auto& m : solver_modules())  // the folder holds this plan only
        if (m.info.engine && !p.runs(m.name)) fs::remove(dir / (m.name + ".sbatch"));
    for (const auto* m : p.engines)
        write_file_atomic(dir / (m->name + ".sbatch"), array_script(*m, c, o, s, p, granlub, results));
    const bool last = last_job(p);
    if (last)
        write_file_atomic(dir / "compare.sbatch", last_script(c, o, s, p, granlub, results));
    else
        fs::remove(dir / "compare.sbatch");
    write_file_atomic(dir / "submit.sh", submit_script(c, s, p));
    std::vector<std::string> jobs;
    for (const auto* m : p.engines) jobs.push_back(fmt::format("{}.sbatch ({} tasks)", m->name, p.tasks()));
    if (last) jobs.push_back("compare.sbatch");
    fmt::print("granlub slurm: wrote {}: {} and submit.sh\n", dir.string(), fmt::join(jobs, ", "));
    if (!s.submit) {
        fmt::print("submit with: bash {}  (or copy the folder to a machine with Slurm whose nodes see the same paths)\n",
                   (dir / "submit.sh").string());
        return 0;
    }
    if (!find_executable("sbatch")) {
        fmt::print(stderr,
                   "error: --submit: sbatch (Slurm's command to submit a job) was not found on PATH. Install Slurm's "
                   "client (Debian: apt-get install slurm-wlm; on a cluster, its module), or run without --submit "
                   "and run {} on a machine that has Slurm (the scripts are written)\n",
                   (dir / "submit.sh").string());
        return 2;
    }
    const fs::path log = dir / "submit.log";
    fs::remove(log);
    const ProcessResult r = run_process({"/bin/bash", (dir / "submit.sh").string()}, dir, log, 300);
    const std::string said = read_file(log);
    if (r.exit_code != 0) {
        fmt::print(stderr, "error: submitting with sbatch failed ({}):\n{}", r.describe(), said);
        return 1;
    }
    fmt::print("{}follow with `squeue --me`; each task's log: {}; the report, once job compare has ended: {}\n", said,
               (dir / "logs").string(), (results / "report" / "index.html").string());
    return 0;
}

}  // namespace granlub::cli
