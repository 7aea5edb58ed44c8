#define BOOST_TEST_MODULE granlub command
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "run_command.h"

using granlub::test::run;
namespace fs = std::filesystem;

namespace {
const std::string exe = GRANLUB_EXE;
const std::string src = GRANLUB_SOURCE_DIR;
}  // namespace

BOOST_AUTO_TEST_CASE(check_prints_the_resolved_default_case) {
    auto o = run(exe + " check " + src + "/cases/sawyer2001");
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("# 3 operating point(s)") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("U2.8") != std::string::npos);
    BOOST_TEST(o.text.find("(default)") != std::string::npos);
    // cases/jasti2006 has an [automaton] section, which exists when that module is built in.
    if (run(exe + " --help").text.find("\n  automaton") != std::string::npos) {
        auto j = run(exe + " check " + src + "/cases/jasti2006");
        BOOST_TEST(j.rc == 0, j.text);
        BOOST_TEST(j.text.find("U2.0_R0.75") != std::string::npos, j.text);
    }
}

BOOST_AUTO_TEST_CASE(every_shipped_case_checks) {
    // cases/ and the plugins' cases: each must validate as shipped, so a key renamed in the
    // schema cannot leave a README's command failing. A section of a module not built in is the
    // one allowed failure (named as unknown, as bad_input below expects).
    const std::string help = run(exe + " --help").text;
    int checked = 0;
    for (const fs::path& root : {fs::path(src) / "cases", fs::path(src) / "plugins/liggghts/cases",
                                fs::path(src) / "plugins/yade/cases"}) {
        if (!fs::is_directory(root)) continue;
        for (const auto& e : fs::directory_iterator(root)) {
            if (!fs::is_regular_file(e.path() / "case.toml")) continue;
            auto o = run(exe + " check " + e.path().string());
            const auto unknown = o.text.find(": unknown section");
            if (o.rc != 0 && unknown != std::string::npos) {
                const auto open = o.text.rfind('[', unknown), close = o.text.find(']', open);
                const std::string module = o.text.substr(open + 1, close - open - 1);
                BOOST_TEST(help.find("\n  " + module + " ") == std::string::npos, e.path() << ": " << o.text);
                continue;
            }
            BOOST_TEST(o.rc == 0, e.path() << ": " << o.text);
            ++checked;
        }
    }
    BOOST_TEST(checked >= 5);
}

BOOST_AUTO_TEST_CASE(bad_input_exits_2_with_the_place_named) {
    auto missing = run(exe + " check /nonexistent/case");
    BOOST_TEST(missing.rc == 2);
    BOOST_TEST(missing.text.find("no such case directory or file") != std::string::npos, missing.text);

    const fs::path dir = fs::temp_directory_path() / "granlub_test_cli_bad";
    fs::create_directories(dir);
    {
        std::ifstream in(src + "/cases/sawyer2001/case.toml");
        std::string text((std::istreambuf_iterator<char>(in)), {});
        text.replace(text.find("restitution = 0.9 "), 18, "restitution = 1.9 ");
        std::ofstream(dir / "case.toml") << text;
    }
    auto bad = run(exe + " check " + dir.string());
    BOOST_TEST(bad.rc == 2);
    BOOST_TEST(bad.text.find("case.toml:12:15: [grains] restitution = 1.9: out of range (allowed: a number (0, 1])") !=
                   std::string::npos,
               bad.text);
    fs::remove_all(dir);

    auto usage = run(exe + " check");
    BOOST_TEST(usage.rc == 2);
    BOOST_TEST(usage.text.find("CASE is required") != std::string::npos, usage.text);
}

BOOST_AUTO_TEST_CASE(version_and_help) {
    auto v = run(exe + " --version");
    BOOST_TEST(v.rc == 0);
    BOOST_TEST(v.text.find('.') != std::string::npos, v.text);
    auto h = run(exe + " --help");
    BOOST_TEST(h.rc == 0);
    BOOST_TEST(h.text.find("check") != std::string::npos);
}

// Every subcommand's --help gives each option its default (and the value's kind), so a reader
// need not look the command up elsewhere.
BOOST_AUTO_TEST_CASE(every_option_says_its_default) {
    const std::string top = run(exe + " --help").text;
    std::vector<std::string> commands;
    std::istringstream lines(top.substr(top.find("Subcommands:")));
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ')
            commands.push_back(line.substr(2, line.find(' ', 2) - 2));
    BOOST_TEST_REQUIRE(commands.size() >= 4u, top);
    for (const auto& c : commands) {
        const auto h = run(exe + " " + c + " --help");
        BOOST_TEST(h.rc == 0, c);
        std::istringstream in(h.text);
        std::vector<std::string> options;
        for (std::string l; std::getline(in, l);) {
            // An option or positional starts at column 2 ("--x", "CASE"); its text may go on below.
            if (l.rfind("  -", 0) == 0 || (l.rfind("  ", 0) == 0 && l.size() > 2 && std::isupper(l[2])))
                options.push_back(l);
            else if (l.rfind("   ", 0) == 0 && !options.empty())
                options.back() += l;
        }
        BOOST_TEST(options.size() >= 2u, c);
        for (const auto& o : options)
            if (o.find("--help") == std::string::npos)
                BOOST_TEST((o.find("default") != std::string::npos || o.find("REQUIRED") != std::string::npos),
                           c << ": " << o);
    }
    // The kinds of values: a count, a folder, not CLI11's bare "INT:INT in [...]".
    const std::string help = run(exe + " run --help").text;
    BOOST_TEST(help.find("--threads N") != std::string::npos, help);
    BOOST_TEST(help.find("--results DIR") != std::string::npos, help);
    BOOST_TEST(help.find("INT:INT") == std::string::npos, help);
    if (top.find("\n  compare") != std::string::npos)
        BOOST_TEST(run(exe + " compare --help").text.find("--point ID") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(keys_are_printed_from_their_declarations) {
    auto o = run(exe + " keys grains");
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("| `diameter` | required | > 0 | m | grain diameter d (with size_spread") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("| `size_spread` | 0 | [0, 0.2] |") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("| `friction` | 0.5 | >= 0 |") != std::string::npos, o.text);
    auto bad = run(exe + " keys nosuchsection");
    BOOST_TEST(bad.rc == 2);
    BOOST_TEST(bad.text.find("no section [nosuchsection]") != std::string::npos, bad.text);
}

BOOST_AUTO_TEST_CASE(key_tables_in_pages_are_checked_and_rewritten_from_the_declarations) {
    const fs::path dir = fs::temp_directory_path() / "granlub_test_cli_key_tables";
    fs::create_directories(dir);
    const fs::path page = dir / "README.md";
    auto write = [&](const std::string& text) { std::ofstream(page) << text; };
    auto read = [&] {
        std::ifstream in(page);
        return std::string((std::istreambuf_iterator<char>(in)), {});
    };
    // A stale table (a key missing, a default changed by hand) between markers: --check names it.
    write("# Grains\n\n<!-- keys:grains -->\n| key | default | allowed | unit | meaning |\n|---|---|---|---|---|\n"
          "| `friction` | 0.3 | >= 0 | | hand-written |\n<!-- /keys -->\n\nText after.\n");
    auto stale = run(exe + " keys --check " + page.string());
    BOOST_TEST(stale.rc == 1, stale.text);
    BOOST_TEST(stale.text.find("README.md:3: the [grains] key table differs from the declarations: line 6 reads") !=
                   std::string::npos,
               stale.text);
    // --update rewrites only what stands between the markers; then --check passes.
    auto update = run(exe + " keys --update " + page.string());
    BOOST_TEST(update.rc == 0, update.text);
    const std::string fixed = read();
    BOOST_TEST(fixed.starts_with("# Grains\n\n<!-- keys:grains -->\n| key | default |"), fixed);
    BOOST_TEST(fixed.find("| `size_spread` | 0 | [0, 0.2] |") != std::string::npos, fixed);
    BOOST_TEST(fixed.ends_with("<!-- /keys -->\n\nText after.\n"), fixed);
    BOOST_TEST(run(exe + " keys grains").text.find(fixed.substr(fixed.find("| key"), 200)) != std::string::npos);
    auto ok = run(exe + " keys --check " + page.string());
    BOOST_TEST(ok.rc == 0, ok.text);
    // A key table outside markers, a section that does not exist and a marker never closed.
    write("| key | default | meaning |\n|---|---|---|\n\n<!-- keys:nosuch -->\n<!-- /keys -->\n"
          "<!-- keys:cell -->\n");
    auto bad = run(exe + " keys --check " + page.string());
    BOOST_TEST(bad.rc == 1, bad.text);
    BOOST_TEST(bad.text.find("README.md:1: a key table outside <!-- keys:SECTION -->") != std::string::npos, bad.text);
    BOOST_TEST(bad.text.find("README.md:4: `<!-- keys:nosuch -->` names no declared section") != std::string::npos,
               bad.text);
    BOOST_TEST(bad.text.find("README.md:6: `<!-- keys:cell -->` has no closing <!-- /keys -->") != std::string::npos,
               bad.text);
    BOOST_TEST(run(exe + " keys --update " + page.string()).rc == 1);  // not mended by --update
    fs::remove_all(dir);
}

namespace {
// cases/sawyer2001_fill (no solver sections) with `from` replaced by `to` (or appended when `from` is
// empty), in a scratch folder.
fs::path edited_case(const std::string& name, const std::string& from, const std::string& to) {
    const fs::path dir = fs::temp_directory_path() / ("granlub_test_cli_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ifstream in(src + "/cases/sawyer2001_fill/case.toml");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    if (from.empty()) text += "\n" + to + "\n";
    else text.replace(text.find(from), from.size(), to);
    std::ofstream(dir / "case.toml") << text;
    return dir;
}
bool built(const std::string& module) { return run(exe + " --help").text.find("\n  " + module) != std::string::npos; }
}  // namespace

// Sizes that used to end in std::bad_alloc or an overflowed count, and a lattice the automaton
// refuses: `granlub check` finds each (exit 2, the key named), before any solver runs.
BOOST_AUTO_TEST_CASE(check_finds_what_the_solvers_would_reject) {
    struct Bad {
        const char* module;
        std::string from, to, expect;
    };
    const std::vector<Bad> cases = {
        {"continuum", "", "[continuum]\ncells = 2000000000", "[continuum] cells = 2000000000: out of range"},
        {"automaton", "", "[automaton]\nsteps = 9223372036854775807", "[automaton] steps = 9223372036854775807"},
        {"automaton", "length = 30.0e-3", "length = 1e9", "at most 5e+07 cells are allowed"},
        {"automaton", "gap = 4.0e-3 ", "gap = 1.6e-3 ", "the lattice has 2 rows"},
        {"dem", "length = 30.0e-3", "length = 1e9", "at most 1e+07 are allowed"},
        {"dem", "", "[dem]\ntime = 1e300", "at most 1e+10 steps are allowed"},
        {"dem", "", "[dem]\nstations = 2000000000", "[dem] stations = 2000000000: out of range"},
        {"yade", "", "[yade]\ntime = 1e300", "at most 1e+10 steps are allowed"},
    };
    for (const auto& b : cases) {
        if (!built(b.module)) continue;
        const fs::path dir = edited_case("sizes", b.from, b.to);
        const auto o = run(exe + " check " + dir.string());
        BOOST_TEST(o.rc == 2, b.to << ": " << o.text);
        BOOST_TEST(o.text.find(b.expect) != std::string::npos, b.to << ": " << o.text);
        BOOST_TEST(o.text.find("bad_alloc") == std::string::npos, o.text);
        fs::remove_all(dir);
    }
}

BOOST_AUTO_TEST_CASE(seed_and_counts_on_the_command_line_are_exact) {
    if (!built("automaton")) return;
    for (const std::string bad : {"-1", "18446744073709551616", "1e23", "3.5", "x"}) {
        const auto o = run(exe + " automaton " + src + "/cases/jasti2006 --point U2.0_R0.5 --results /nonexistent --seed " + bad);
        BOOST_TEST(o.rc == 2, bad << ": " << o.text);
        BOOST_TEST(o.text.find("'" + bad + "' is not a seed (allowed: an integer from 0 to 9223372036854775807)") !=
                       std::string::npos,
                   o.text);
    }
    if (built("dem")) {
        const auto np = run(exe + " dem " + src + "/cases/sawyer2001 --np 0");
        BOOST_TEST(np.rc == 2);
        BOOST_TEST(np.text.find("'0' is not a rank count (allowed: an integer from 1 to 4096)") != std::string::npos,
                   np.text);
    }
}

// --seeds and --seed of the particle engines (granlub/particles/seeds.h): bad input stops before any run,
// naming the flag and what is allowed.
BOOST_AUTO_TEST_CASE(bad_seeds_on_the_command_line_stop_with_what_is_allowed) {
    const std::string allowed = "allowed: a whole number of seeds from 1 to 1000, or a comma-separated list";
    for (const std::string cmd : {"dem", "yade", "run"}) {
        if (cmd != "run" && !built(cmd)) continue;
        if (cmd == "run" && !built("dem")) continue;
        const std::string base = exe + " " + cmd + " " + src + "/cases/sawyer2001 --results /nonexistent ";
        for (const auto& [flags, expect] : std::vector<std::pair<std::string, std::string>>{
                 {"--seeds 0", "--seeds 0: out of range (" + allowed},
                 {"--seeds 1,2,1", "--seeds 1,2,1: 1 appears twice (" + allowed},
                 {"--seeds 2.5", "--seeds 2.5: not a whole number (" + allowed},
                 {"--seeds -3", "--seeds -3: not a whole number"},
                 {"--seeds ''", "an empty set of seeds"},
                 {"--seeds 3 --seed 7", "--seed 7: not one of the seeds [1, 2, 3] (--seeds; allowed: one of them"}}) {
            const auto o = run(base + flags);
            BOOST_TEST(o.rc == 2, cmd << " " << flags << ": " << o.text);
            BOOST_TEST(o.text.find(expect) != std::string::npos, cmd << " " << flags << ": " << o.text);
        }
    }
    if (built("automaton"))  // not a particle engine: no --seeds
        BOOST_TEST(run(exe + " automaton " + src + "/cases/jasti2006 --seeds 3").rc == 2);
}

// The audit's exploit: a case name with a line break became a `shell` command in the LIGGGHTS
// deck. It is refused when the case is read, so no deck, data file or results folder is made.
BOOST_AUTO_TEST_CASE(a_case_file_cannot_run_commands) {
    const fs::path pwned = fs::temp_directory_path() / "granlub_test_PWNED";
    fs::remove(pwned);
    for (const std::string sub : {"check", "dem", "yade", "run"}) {
        if (sub != "check" && sub != "run" && !built(sub)) continue;
        const fs::path dir = edited_case("inject", "name = \"sawyer2001_fill\"",
                                         "name = \"x\\nshell touch " + pwned.string() + " #\"");
        const auto o = run(exe + " " + sub + " " + dir.string());
        BOOST_TEST(o.rc == 2, sub << ": " << o.text);
        BOOST_TEST(o.text.find("[case] name") != std::string::npos, o.text);
        BOOST_TEST(!fs::exists(dir / "results"), sub);
        BOOST_TEST(!fs::exists(pwned), sub);
        fs::remove_all(dir);
    }
}

// A point a solver cannot run is a warning at check time, with the reason (not "try more cells").
BOOST_AUTO_TEST_CASE(check_warns_of_points_a_solver_cannot_run) {
    if (!built("continuum")) return;
    const fs::path dir = edited_case("elastic", "restitution = 0.9          # e_p", "restitution = 1.0 # e_p");
    const auto o = run(exe + " check " + dir.string());
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("continuum  cannot run 3 of 3 point(s)") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("warning: continuum will fail on point U1.4: [grains] restitution = 1: perfectly "
                           "elastic grains") != std::string::npos,
               o.text);
    fs::remove_all(dir);
}

// `granlub continuum-fit CASE --table FILE`: the fit through the command on a two-answer table (the rough case's c
// only), the fragment written to --out; one answer is refused as bad input (exit 2), saying how many are needed, and
// so is the wall constant on a table without the walls' columns.
BOOST_AUTO_TEST_CASE(continuum_fit_route) {
    if (!built("continuum-fit")) return;
    const fs::path dir = fs::temp_directory_path() / "granlub_test_cli_fit";
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string head = "# format granlub-bulk-rheology 1\n"
                             "point,load_Pa,status,core_dt_check,pressure_Pa,pressure_err,I,I_err,mu,mu_err,nu,nu_err,"
                             "T_scaled,T_scaled_err\n";
    const std::string a = "U9.0_P5550,5550,steady,converged,5557.88,66.1,0.08467,0.0006,0.4316,0.0076,0.5788,0.0025,"
                          "0.547,0.013\n";
    const std::string b = "U9.0_P2250,2250,steady,converged,2257.38,42.1,0.1400,0.0014,0.4558,0.0114,0.5709,0.0026,"
                          "0.427,0.010\n";
    std::ofstream(dir / "two.csv") << head << a << b;
    std::ofstream(dir / "one.csv") << head << a;
    const std::string base = exe + " continuum-fit " + src + "/cases/sawyer2001_regimes_rough --out " +
                             (dir / "fit.toml").string() + " --table ";
    const auto o = run(base + (dir / "two.csv").string());
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("chi2 = ") != std::string::npos, o.text);
    std::ifstream f(dir / "fit.toml");
    const std::string toml((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    BOOST_TEST(toml.find("\n[continuum]\ncorrelation_constant = ") != std::string::npos, toml);
    fs::remove(dir / "fit.toml");
    const auto one = run(base + (dir / "one.csv").string());
    BOOST_TEST(one.rc == 2, one.text);
    BOOST_TEST(one.text.find("needs at least 2") != std::string::npos, one.text);
    BOOST_TEST(!fs::exists(dir / "fit.toml"));
    // the wall constant on a table without the walls' columns: bad input, the columns named
    const auto walls = run(base + (dir / "two.csv").string() + " --free slip_dissipation");
    BOOST_TEST(walls.rc == 2, walls.text);
    BOOST_TEST(walls.text.find("no column(s) slip_bottom_over_U, slip_bottom_err") != std::string::npos, walls.text);
    BOOST_TEST(!fs::exists(dir / "fit.toml"));
    fs::remove_all(dir);
}

// `granlub continuum CASE --map`: the (U, P) map through the command, into the results folder (atomic,
// with its provenance lines), one row per grid point; the options it excludes are refused (exit 2).
BOOST_AUTO_TEST_CASE(continuum_map_route) {
    if (!built("continuum")) return;
    const fs::path out = fs::temp_directory_path() / "granlub_test_cli_map";
    fs::remove_all(out);
    const std::string base = exe + " continuum " + src + "/cases/sawyer2001 --results " + out.string();
    const auto o = run(base + " --map --map-grid 3,2");
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("6 points (0 failed") != std::string::npos, o.text);
    std::ifstream f(out / "continuum" / "map.csv");
    std::vector<std::string> lines;
    for (std::string l; std::getline(f, l);) lines.push_back(l);
    BOOST_TEST_REQUIRE(lines.size() == 2u + 1u + 6u);
    BOOST_TEST(lines[0].find("3 speeds x 2 loads") != std::string::npos, lines[0]);
    BOOST_TEST(lines[1].find("case_hash ") != std::string::npos, lines[1]);
    BOOST_TEST(lines[2].starts_with("speed_m_s,normal_stress_Pa,status,"), lines[2]);
    BOOST_TEST(lines[3].starts_with("0.4,1000,steady,"), lines[3]);
    BOOST_TEST(lines[8].starts_with("2.8,8000,steady,"), lines[8]);
    BOOST_TEST(!fs::exists(out / "continuum" / "U1.4"));  // the map, not the case's points
    for (const char* bad : {" --map --point U1.4", " --map --force", " --map-grid 3,2", " --map --map-grid 0,2"})
        BOOST_TEST(run(base + bad).rc == 2, bad);
    fs::remove_all(out);
}

BOOST_AUTO_TEST_CASE(an_unknown_command_is_named) {
    const auto o = run(exe + " frobnicate cases/sawyer2001");
    BOOST_TEST(o.rc == 2);
    BOOST_TEST(o.text.find("unknown command 'frobnicate' (commands: check, keys,") != std::string::npos, o.text);
}

// Allowed but most likely a slip of units: a warning, exit 0.
BOOST_AUTO_TEST_CASE(check_warns_of_implausible_magnitudes) {
    const fs::path dir = edited_case("magnitudes", "gap = 4.0e-3 ", "gap = 5 ");
    const auto o = run(exe + " check " + dir.string());
    BOOST_TEST(o.text.find("warning: [cell] gap = 5 m is 6353 grain diameters (more than 1000): is the unit "
                           "metres?") != std::string::npos,
               o.text);
    fs::remove_all(dir);
    const auto fine = run(exe + " check " + src + "/cases/sawyer2001");
    BOOST_TEST(fine.text.find("warning:") == std::string::npos, fine.text);
}

// Under load control the DEM inserts [dem] fill_for_load when the case gives no solid fraction:
// when that does not fit, the error names that key, not one the user never set.
BOOST_AUTO_TEST_CASE(an_insertion_error_names_the_key_the_fill_came_from) {
    if (!built("dem")) return;
    const fs::path dir = fs::temp_directory_path() / "granlub_test_cli_fill_key";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ifstream in(src + "/tests/cli/tiny/case.toml");
    std::string text((std::istreambuf_iterator<char>(in)), {});
    text.replace(text.find("control = \"fill\""), 16, "control = \"load\"\nnormal_stress = 5000");
    text.replace(text.find("solid_fraction = 0.55"), 21, "");
    std::ofstream(dir / "case.toml") << text;
    const auto o = run(exe + " check " + dir.string());
    BOOST_TEST(o.rc == 2, o.text);
    BOOST_TEST(o.text.find("point U1.0: [dem] fill_for_load (default) = 0.55: particle insertion: 1050 grains") !=
                   std::string::npos,
               o.text);
    fs::remove_all(dir);
}
