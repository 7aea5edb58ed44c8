// granlub: one command, one subcommand per job. Exit codes: 0 done, 1 a solver failed on some
// point, 2 bad input (case file, options) or, with --no-wait, results in use by another run.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "full_schema.h"
#include "key_tables.h"
#include "granlub/case/case.h"
#include "granlub/error.h"
#include "granlub/particles/bulk_rheology_table.h"
#include "granlub/results/file_io.h"
#include "granlub/case/plausibility.h"
#include "granlub/results/results.h"
#include "granlub/run/run_lock.h"
#include "granlub/run/sweep.h"
#include "granlub/text.h"
#include "modules.h"
#include "run_all.h"
#include "slurm.h"

namespace {

struct Args {
    std::string case_path;
    std::int64_t seed = -1;  // -1: not given
    granlub::RunOptions opt;
    std::string results;
    std::vector<std::string> solvers;
    bool map = false;                        // granlub continuum --map
    std::vector<int> map_grid{100, 100};     // --map-grid SPEEDS,LOADS
    std::string out;                         // granlub bulk-rheology --out, continuum-fit --out
    granlub::cli::ContinuumFitArgs fit;      // granlub continuum-fit
    granlub::cli::SlurmOptions slurm;        // granlub slurm
};

// `granlub <solver> CASE --map` of a solver with a map (its kSolver.map; the continuum's: continuum/command.h).
void add_map_options(CLI::App* sub, Args& a) {
    auto* map = sub->add_flag("--map", a.map,
                              "instead of the case's points, solve its (U, P) map: U 0.4-2.8 m/s x P 1-8 kPa with the "
                              "first point's walls, into results/continuum/map.csv (the report draws it; default: off)");
    for (const char* other : {"--point", "--full", "--vtk", "--force"}) map->excludes(sub->get_option(other));
    sub->add_option("--map-grid", a.map_grid, "grid of the map: speeds,loads (default: 100,100)")
        ->type_name("S,L")
        ->delimiter(',')
        ->expected(2)
        ->check(CLI::Range(1, 1000))
        ->needs(map);
}

void add_case(CLI::App* sub, Args& a) {
    sub->add_option("CASE", a.case_path, "case directory (holding case.toml) or a case .toml file")
        ->required()
        ->type_name("DIR|FILE");
    sub->add_option("--results", a.results, "results folder (default: CASE/results)")->type_name("DIR");
}

// An integer option in [lo, hi], parsed exactly: no wrap-around of -1 into 2^64 - 1, no 1e23.
// `shown` is the range as --help prints it (default "lo to hi").
CLI::Validator integer_in(std::int64_t lo, std::int64_t hi, std::string what, std::string shown = "") {
    return CLI::Validator(
        [lo, hi, what](std::string& text) -> std::string {
            std::int64_t v = 0;
            const char* end = text.data() + text.size();
            const auto [ptr, ec] = std::from_chars(text.data(), end, v);
            if (ec != std::errc() || ptr != end || v < lo || v > hi)
                return fmt::format("'{}' is not {} (allowed: an integer from {} to {})", text, what, lo, hi);
            return "";
        },
        shown.empty() ? fmt::format("{} to {}", lo, hi) : shown);
}

void add_point(CLI::App* sub, Args& a) {
    sub->add_option("--point", a.opt.point,
                    "only this operating point, e.g. U2.0 (default: every point; `granlub check CASE` lists the ids)")
        ->type_name("ID");
}

// Another run holding the same results (granlub/run/run_lock.h): wait for it, or fail at once.
void add_wait(CLI::App* sub, Args& a) {
    sub->add_flag("--wait,!--no-wait", a.opt.wait,
                  "when another run is using the same results: wait for it, saying which run (default), or with "
                  "--no-wait fail at once with exit code 2");
}

void add_run_options(CLI::App* sub, Args& a, bool stochastic, bool mpi, bool particles) {
    add_point(sub, a);
    add_wait(sub, a);
    sub->add_flag("--force", a.opt.force,
                  "recompute points whose results are complete and current (default: off, such results are kept)");
    sub->add_flag("--full", a.opt.full,
                  "full-fidelity run lengths from the case's *_full keys, e.g. [dem] time_full in s of simulated "
                  "time (default: off, the quick lengths: [dem] time, [automaton] steps ...)");
    sub->add_flag("--vtk", a.opt.vtk, "also write ParaView (VTK) files where the solver supports it (default: off)");
    if (stochastic) {
        sub->add_option("--seed", a.seed,
                        "random seed, a whole number (default: the case's seed key: [particles] seed for dem and yade, [automaton] seed)")
            ->type_name("N")
            ->check(integer_in(0, std::numeric_limits<std::int64_t>::max(), "a seed", "0 to 2^63 - 1"));
        sub->add_option("--threads", a.opt.threads, "worker threads, a count (default: 0 = all cores)")
            ->type_name("N")
            ->check(integer_in(0, 1024, "a thread count"));
    }
    if (particles)  // granlub/particles/seeds.h
        sub->add_option("--seeds", a.opt.seeds,
                        "independent realisations of every particle point, pooled into one answer (mean ± the seeds' "
                        "standard error): a count N, the seeds seed .. seed+N-1, or a comma-separated list, e.g. "
                        "1,2,7; with several, --seed S runs only member S (default: [particles] seeds, 1)")
            ->type_name("N|LIST")
            ->check(CLI::Validator([](std::string& t) { return t.empty() ? std::string("an empty set of seeds (allowed: a whole number of seeds from 1 to 1000, or a comma-separated list of distinct whole numbers)") : std::string(); }, "N|LIST"));
    if (mpi)
        sub->add_option("--np", a.opt.np, "MPI ranks for LIGGGHTS, a count (default: 1)")
            ->type_name("N")
            ->check(integer_in(1, 4096, "a rank count"));
}

// `granlub slurm CASE`: which runs go into the job scripts, and what Slurm is asked for (slurm.h).
void add_slurm_options(CLI::App* sub, Args& a, const std::vector<std::string>& solvers) {
    auto& s = a.slurm;
    sub->add_option("--solvers", s.solvers,
                    fmt::format("solvers, comma-separated: the particle engines get a job array each, the others run "
                                "in the last job before compare (default: all: {})",
                                fmt::join(solvers, ",")))
        ->type_name("LIST")
        ->delimiter(',')
        ->check(CLI::IsMember(solvers));
    sub->add_option("--point", s.points,
                    "only these operating points, comma-separated, e.g. U1.4,U2.0 (default: every point; `granlub "
                    "check CASE` lists the ids)")
        ->type_name("IDS")
        ->delimiter(',');
    sub->add_option("--seed", a.seed, "random seed of every run, a whole number (default: the case's seed keys)")
        ->type_name("N")
        ->check(integer_in(0, std::numeric_limits<std::int64_t>::max(), "a seed", "0 to 2^63 - 1"));
    sub->add_option("--seeds", a.opt.seeds,
                    "independent realisations of every particle point, one task each, pooled into one answer: a count "
                    "N or a comma-separated list, as `granlub dem --seeds` (default: [particles] seeds, 1)")
        ->type_name("N|LIST");
    sub->add_option("--np", a.opt.np, "MPI ranks of each dem task (Slurm tasks of its job), a count (default: 1)")
        ->type_name("N")
        ->check(integer_in(1, 4096, "a rank count"));
    sub->add_flag("--full", a.opt.full, "full-fidelity run lengths, as `granlub dem --full` (default: off)");
    sub->add_flag("--force", a.opt.force, "recompute complete points, as `granlub dem --force` (default: off)");
    const auto slurm_check = [](std::string (*error)(const std::string&), std::string shown) {
        return CLI::Validator([error](std::string& v) { return error(v); }, std::move(shown));
    };
    sub->add_option("--partition", s.partition,
                    "Slurm partition of every job, or several comma-separated (default: the cluster's default)")
        ->type_name("NAME")
        ->check(slurm_check(granlub::cli::slurm_partition_error, ""));
    sub->add_option("--time", s.time,
                    "time limit of each particle task in Slurm's format, e.g. 90 (minutes) or 1-12:00:00 (default: the "
                    "partition's)")
        ->type_name("LIMIT")
        ->check(slurm_check(granlub::cli::slurm_time_error, "[D-]HH:MM:SS or minutes"));
    sub->add_flag("--submit", s.submit,
                  "submit the scripts with sbatch once written (default: off, only write them into "
                  "RESULTS/slurm/ with submit.sh to run by hand)");
}

// `granlub keys [SECTION] [--check FILE...] [--update FILE...]`.
struct KeysCommand {
    CLI::App* sub = nullptr;
    std::string section;
    std::vector<std::string> check, update;

    void add(CLI::App& app) {
        sub = app.add_subcommand("keys", "print every case key (type, default, range, unit, meaning) as Markdown");
        auto* section_opt =
            sub->add_option("SECTION", section, "only this section, e.g. continuum (default: every section)")
                ->type_name("NAME");
        auto* check_opt = sub->add_option("--check", check,
                                          "check the key tables between <!-- keys:SECTION --> and <!-- /keys --> in these "
                                          "Markdown files against the declarations; exit 1 naming each that differs (default: none; print the "
                                          "tables)")
            ->type_name("FILE...")
            ->excludes(section_opt);
        sub->add_option("--update", update, "rewrite those tables from the declarations (default: none)")
            ->type_name("FILE...")
            ->excludes(section_opt)
            ->excludes(check_opt);
    }

    int run() const {
        const granlub::Schema schema = granlub::cli::case_schema();
        if (!check.empty() || !update.empty()) {
            try {
                const bool updating = !update.empty();
                return granlub::cli::check_key_tables(updating ? update : check, updating, schema);
            } catch (const granlub::Error& e) {  // a file that cannot be read or written
                fmt::print(stderr, "error: {}\n", e.what());
                return 2;
            }
        }
        bool any = false;
        for (const auto& spec : schema.sections()) {
            if (!section.empty() && spec.name != section) continue;
            fmt::print("{}\n", granlub::key_table_markdown(spec));
            any = true;
        }
        if (!any) {
            fmt::print(stderr, "error: no section [{}]\n", section);
            return 2;
        }
        return 0;
    }
};

// The subcommands that read a case: check, each solver, compare, run.
struct CaseCommands {
    CLI::App* check = nullptr;
    std::vector<std::pair<CLI::App*, const granlub::cli::SolverModule*>> solvers;
    CLI::App* compare = nullptr;
    CLI::App* run = nullptr;
    CLI::App* bulk = nullptr;
    CLI::App* fit = nullptr;
    CLI::App* slurm = nullptr;
};

// `granlub bulk-rheology CASE`: the core's rheology of every point of the solver declared for it
// (SolverInfo::bulk_rheology: the DEM; bulk_rheology_table.h), written atomically beside case.toml
// (or to --out), read while no run writes that solver's results.
int bulk_rheology(const granlub::Case& c, const Args& a) {
    const granlub::cli::SolverModule* from = nullptr;
    for (const auto& m : granlub::cli::solver_modules())
        if (m.info.bulk_rheology && !from) from = &m;
    if (!from) throw granlub::Error("granlub was built without a solver whose results make the bulk-rheology table");
    const auto root = granlub::results_root(c, a.opt);
    const granlub::ResultsLock lock(granlub::point_locks(root, from->name, c.select(""), granlub::LockMode::Shared),
                                    a.opt.wait);  // every point's: the table reads them all
    const granlub::BulkTable t = granlub::bulk_rheology_table(c, root, from->name);
    const std::filesystem::path out = a.out.empty() ? c.dir / granlub::kBulkTableFile : std::filesystem::path(a.out);
    granlub::write_file_atomic(out, t.csv);
    for (const auto& n : t.notes) fmt::print(stderr, "note: {}\n", n);
    fmt::print("{}: {} row(s)\n", out.string(), t.rows);
    return 0;
}

// Runs the parsed case subcommand; the exit code, errors printed.
int run_case_command(const CaseCommands& cmd, const Args& a) {
    try {
        const granlub::Case c = granlub::load_case(a.case_path, granlub::cli::case_schema());
        for (const auto& w : c.warnings) fmt::print(stderr, "warning: {}\n", w);
        if (cmd.check->parsed()) {
            fmt::print("{}", granlub::describe(c));
            std::fflush(stdout);
            for (const auto& w : granlub::plausibility_warnings(c)) fmt::print(stderr, "warning: {}\n", w);
            return granlub::cli::check_solvers(c, a.opt);
        }
        for (const auto& [sub, m] : cmd.solvers)
            if (sub->parsed()) {
                granlub::cli::check_input(*m, c, a.opt);  // bad input fails here, exit 2, before any point runs
                if (a.map) return m->info.map(c, a.opt, a.map_grid[0], a.map_grid[1]);
                return m->run(c, a.opt);
            }
        if (cmd.compare && cmd.compare->parsed()) return granlub::cli::compare(c, a.opt);
        if (cmd.bulk->parsed()) return bulk_rheology(c, a);
        if (cmd.fit && cmd.fit->parsed()) {
            granlub::cli::ContinuumFitArgs f = a.fit;
            f.out = a.out;
            return granlub::cli::continuum_fit(c, f);
        }
        if (cmd.run->parsed()) return granlub::cli::run_all(c, a.opt, a.solvers);
        if (cmd.slurm->parsed()) return granlub::cli::slurm_jobs(c, a.opt, a.slurm);
    } catch (const granlub::CaseError& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 2;
    } catch (const granlub::ResultsInUse& e) {  // --no-wait: like bad input, nothing was run
        fmt::print(stderr, "error: {}\n", e.what());
        return 2;
    } catch (const granlub::Error& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        fmt::print(stderr, "error: {}\n", e.what());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"granlub: granular flow lubrication by particle, continuum and cellular-automaton solvers, "
                 "compared on the same case"};
    app.require_subcommand(1);
    app.set_version_flag("--version", granlub::version());
    Args a;
    CaseCommands cmd;

    cmd.check = app.add_subcommand("check", "validate a case and print it resolved, with its operating points");
    add_case(cmd.check, a);

    KeysCommand keys;
    keys.add(app);

    for (const auto& m : granlub::cli::solver_modules()) {
        auto* sub = app.add_subcommand(m.name, m.info.description);
        add_case(sub, a);
        add_run_options(sub, a, m.info.seeded, m.info.ranks, m.info.kind == granlub::SolverKind::Particles);
        if (m.info.map) add_map_options(sub, a);
        cmd.solvers.emplace_back(sub, &m);
    }

    if (granlub::cli::have_compare()) {
        cmd.compare = app.add_subcommand("compare", "compare every solver's results for a case: results/report/");
        add_case(cmd.compare, a);
        add_point(cmd.compare, a);  // the report of one point (README: compare cases/jasti2006 --point U2.0_R0.25)
        add_wait(cmd.compare, a);
    }

    cmd.bulk = app.add_subcommand("bulk-rheology", "the bulk rheology of a wide plane-shear case from its DEM "
                                                    "results, read in the core: CASE/bulk_rheology.csv "
                                                    "(cases/bulk_shear/README.md)");
    add_case(cmd.bulk, a);
    add_wait(cmd.bulk, a);
    cmd.bulk->add_option("--out", a.out, "the table's file (default: CASE/bulk_rheology.csv)")->type_name("FILE");

    if (granlub::cli::have_continuum()) {
        cmd.fit = app.add_subcommand("continuum-fit", "fit the free constants of a case's continuum closures on a "
                                                      "bulk-rheology table (continuum/README.md, \"Fitting the closures' "
                                                      "constants\")");
        cmd.fit->add_option("CASE", a.case_path, "the case whose [continuum] closures are fitted (directory or .toml)")
            ->required()
            ->type_name("DIR|FILE");
        cmd.fit->add_option("--table", a.fit.table, "the bulk-rheology table (`granlub bulk-rheology`'s "
                                                    "bulk_rheology.csv) whose answer rows the fit is made on")
            ->required()
            ->type_name("FILE");
        cmd.fit->add_option("--free", a.fit.free,
                            "the [continuum] constants to fit, comma-separated, started from the case's values "
                            "(default: every constant of the branches the case chooses: correlation_constant with "
                            "correlation_length = \"jenkins_berzi\", the contact_* constants with contact_stress = "
                            "\"johnson_jackson\"; max_solid_fraction may be added; slip_dissipation fits the wall "
                            "constant f_t on the table's walls' columns, see --bulk-case)")
            ->type_name("KEYS")
            ->delimiter(',');
        cmd.fit->add_option("--bulk-case", a.fit.bulk_case,
                            "with slip_dissipation in --free: the bulk case whose walls the table measured, solved in "
                            "1-D with CASE's [continuum] (default: the case the table's '# case NAME (PATH)' line "
                            "names, PATH relative to the working directory)")
            ->type_name("DIR|FILE");
        cmd.fit->add_flag("--temperature", a.fit.temperature,
                          "fit T/(d gdot)^2 as well as mu and nu (default: off, T printed beside the fit)");
        cmd.fit->add_option("--out", a.out, "the TOML fragment with the fitted constants (default: CASE/continuum_fit.toml)")
            ->type_name("FILE");
    }

    cmd.run = app.add_subcommand("run", "run the solvers on a case, then compare (the main job)");
    add_case(cmd.run, a);
    add_run_options(cmd.run, a, true, true, true);
    std::vector<std::string> names;
    for (const auto& m : granlub::cli::solver_modules()) names.push_back(m.name);
    cmd.run->add_option("--solvers", a.solvers,
                        fmt::format("solvers to run, comma-separated (default: all: {})", fmt::join(names, ",")))
        ->type_name("LIST")
        ->delimiter(',')
        ->check(CLI::IsMember(names));

    cmd.slurm = app.add_subcommand("slurm", "write the case's particle runs as Slurm job arrays (one task per point and "
                                            "seed) and a dependent compare job into RESULTS/slurm/; --submit submits "
                                            "them (cli/README.md, \"On a cluster\")");
    add_case(cmd.slurm, a);
    add_slurm_options(cmd.slurm, a, names);

    // CLI11 reports an unknown first word only as "A subcommand is required": name it and the commands.
    std::vector<std::string> commands;
    for (const auto* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    if (argc > 1 && argv[1][0] != '-' && std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
        fmt::print(stderr, "error: unknown command '{}' (commands: {}; `granlub --help` says what each does)\n",
                   granlub::clipped(granlub::one_line(argv[1])), fmt::join(commands, ", "));
        return 2;
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;
    }
    a.opt.results_root = a.results;
    a.slurm.command = granlub::one_line(fmt::format("{}", fmt::join(argv, argv + argc, " ")));
    if (a.seed >= 0) a.opt.seed = static_cast<std::uint64_t>(a.seed);

    if (keys.sub->parsed()) return keys.run();
    return run_case_command(cmd, a);
}
