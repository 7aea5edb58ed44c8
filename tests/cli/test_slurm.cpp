// `granlub slurm CASE` (cli/slurm.h) without a Slurm: the scripts it writes (one array task per
// point, each task's command, the dependencies), the bad options it refuses with the key and what is
// allowed, and --submit where sbatch is missing. The scripts under a real Slurm:
// slurm_one_node.sh.
#define BOOST_TEST_MODULE granlub slurm
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include <boost/test/unit_test.hpp>

#include "granlub/results/file_io.h"
#include "run_command.h"
#ifdef GRANLUB_TEST_ENGINES
#include "tiny_cell_text.h"
#endif

namespace fs = std::filesystem;
using granlub::read_file;
using granlub::test::run;

namespace {

const std::string kCase = std::string(GRANLUB_SOURCE_DIR) + "/tests/cli/tiny";

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("granlub_test_slurm_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

granlub::test::Output slurm(const std::string& args) { return run(std::string(GRANLUB_EXE) + " slurm " + args); }

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A command refused with exit 2, its message holding each of `says`.
void refused(const granlub::test::Output& o, std::initializer_list<const char*> says) {
    BOOST_TEST(o.rc == 2, o.text);
    for (const char* s : says) BOOST_TEST(has(o.text, s), o.text);
}

// The command an array script runs as task `task`: the script with granlub replaced by echo.
std::string task_command(const fs::path& script, int task) {
    std::string text = read_file(script);
    const auto at = text.find("\ngranlub=");
    BOOST_TEST_REQUIRE(at != std::string::npos, text);
    text.replace(at + 1, text.find('\n', at + 1) - at - 1, "granlub=/bin/echo");
    const fs::path echo = script.parent_path() / "echo.sh";
    std::ofstream(echo) << text;
    const auto o = run("SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " bash " + echo.string());
    BOOST_TEST(o.rc == 0, o.text);
    return o.text;
}

}  // namespace

BOOST_AUTO_TEST_CASE(the_last_job_runs_the_other_solvers_then_compare) {
    const fs::path root = scratch("last");
    const auto o = slurm(kCase + " --solvers continuum,automaton --seed 5 --results " + root.string());
    BOOST_TEST_REQUIRE(o.rc == 0, o.text);
    BOOST_TEST(has(o.text, "submit with: bash " + (root / "slurm" / "submit.sh").string()), o.text);
    const std::string last = read_file(root / "slurm" / "compare.sbatch");
    BOOST_TEST(has(last, "\"$granlub\" continuum \"$case\" --results \"$results\" || rc=1\n"), last);
    BOOST_TEST(has(last, "\"$granlub\" automaton \"$case\" --results \"$results\" --seed 5 || rc=1\n"), last);
    BOOST_TEST(has(last, "\"$granlub\" compare \"$case\" --results \"$results\" || rc=1\n"), last);
    BOOST_TEST(has(last, "results='" + root.string() + "'\n"), last);
    BOOST_TEST(has(last, "# Written by granlub "), last);  // provenance: version, time, case and its hash
    BOOST_TEST(has(last, "# by: " + std::string(GRANLUB_EXE) + " slurm "), last);
    const std::string submit = read_file(root / "slurm" / "submit.sh");
    BOOST_TEST(has(submit, "last=$(sbatch --parsable"), submit);
    BOOST_TEST(!has(submit, "--dependency"), submit);  // no array to wait for
    BOOST_TEST(fs::is_directory(root / "slurm" / "logs"));
    // one point: each solver and the report on that point only
    BOOST_TEST_REQUIRE(slurm(kCase + " --solvers continuum --point U2.0 --results " + root.string()).rc == 0);
    const std::string one = read_file(root / "slurm" / "compare.sbatch");
    BOOST_TEST(has(one, "continuum \"$case\" --results \"$results\" --point 'U2.0' || rc=1"), one);
    BOOST_TEST(has(one, "compare \"$case\" --results \"$results\" --point 'U2.0' || rc=1"), one);
    BOOST_TEST(!has(one, "automaton"), one);
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(bad_options_stop_with_the_key_and_what_is_allowed) {
    const fs::path root = scratch("bad");
    const std::string base = kCase + " --results " + root.string();
    refused(slurm(base + " --np 0"), {"--np", "allowed: an integer from 1 to 4096"});
    refused(slurm(base + " --solvers continuum,dom"), {"dom", "continuum"});  // continuum: the allowed names
    refused(slurm(base + " --solvers continuum --point U1.0,U9.9"), {"no operating point 'U9.9' (points: U1.0, U2.0)"});
    refused(slurm(base + " --time 2h"), {"--time", "'2h' is not a Slurm time limit (allowed: minutes"});
    refused(slurm(base + " --partition 'a b'"), {"is not a partition name (allowed: letters"});
    BOOST_TEST(!fs::exists(root / "slurm"));  // nothing written
    fs::remove_all(root);
}

BOOST_AUTO_TEST_CASE(submit_without_sbatch_says_what_is_missing_and_what_to_do) {
    const fs::path root = scratch("no_sbatch");
    const auto o = run("PATH=/nonexistent " + std::string(GRANLUB_EXE) + " slurm " + kCase +
                       " --solvers continuum --submit --results " + root.string());
    refused(o, {"sbatch", "was not found on PATH", "apt-get install slurm-wlm", "run without --submit"});
    BOOST_TEST(fs::exists(root / "slurm" / "submit.sh"));  // to copy to a machine that has Slurm
    fs::remove_all(root);
}

#ifdef GRANLUB_TEST_ENGINES
// The particle engines: an array each, a task per point; YADE's warm start waits task by task.
BOOST_AUTO_TEST_CASE(each_engine_is_an_array_of_one_task_per_point) {
    const fs::path dir = scratch("engines");
    std::string text = granlub::test::tiny_cell("tiny_slurm", "", "time = 0.02\nsample_every = 20\n") + "[yade]\nstart = \"warm\"\n";
    text.replace(text.find("speed = [1.0]"), 13, "speed = [1.0, 2.0]");
    std::ofstream(dir / "case.toml") << text;
    const fs::path root = dir / "results";
    const auto o = slurm(dir.string() + " --solvers dem,yade --np 2 --partition short --time 30 --results " +
                         root.string());
    BOOST_TEST_REQUIRE(o.rc == 0, o.text);
    const std::string dem = read_file(root / "slurm" / "dem.sbatch");
    BOOST_TEST(has(dem, "#SBATCH --array=0-1\n"), dem);
    BOOST_TEST(has(dem, "#SBATCH --ntasks=2\n"), dem);  // the MPI ranks
    BOOST_TEST(has(dem, "#SBATCH --partition=short\n#SBATCH --time=30\n"), dem);
    BOOST_TEST(has(dem, "points=('U1.0' 'U2.0')\n"), dem);
    const std::string yade = read_file(root / "slurm" / "yade.sbatch");
    BOOST_TEST(has(yade, "#SBATCH --ntasks=1\n"), yade);
    const std::string case_file = (dir / "case.toml").string();
    BOOST_TEST(task_command(root / "slurm" / "dem.sbatch", 1) ==
               "dem " + case_file + " --results " + root.string() + " --point U2.0 --np 2\n");
    BOOST_TEST(task_command(root / "slurm" / "yade.sbatch", 0) ==
               "yade " + case_file + " --results " + root.string() + " --point U1.0\n");
    const std::string submit = read_file(root / "slurm" / "submit.sh");
    BOOST_TEST(has(submit, "--dependency=aftercorr:$dem --kill-on-invalid-dep=yes \"$here/yade.sbatch\""), submit);
    BOOST_TEST(has(submit, "--dependency=afterany:$dem:$yade \"$here/compare.sbatch\""), submit);
    // a cold YADE reads nothing of DEM's: its array does not wait for it
    text.replace(text.find("start = \"warm\""), 14, "start = \"cold\"");
    std::ofstream(dir / "case.toml") << text;
    BOOST_TEST_REQUIRE(slurm(dir.string() + " --solvers dem,yade --results " + root.string()).rc == 0);
    BOOST_TEST(!has(read_file(root / "slurm" / "submit.sh"), "aftercorr"));
    fs::remove_all(dir);
}
#endif

#ifdef GRANLUB_TEST_ENGINES
BOOST_AUTO_TEST_CASE(a_set_of_seeds_is_one_task_per_point_and_member) {
    const fs::path dir = scratch("seeds");
    std::string text = granlub::test::tiny_cell("tiny_slurm_seeds", "", "time = 0.02\nsample_every = 20\n");
    text.replace(text.find("speed = [1.0]"), 13, "speed = [1.0, 2.0]");
    std::ofstream(dir / "case.toml") << text;
    const fs::path root = dir / "results";
    const auto o = slurm(dir.string() + " --solvers dem --seeds 1,2,7 --results " + root.string());
    BOOST_TEST_REQUIRE(o.rc == 0, o.text);
    const std::string dem = read_file(root / "slurm" / "dem.sbatch");
    BOOST_TEST(has(dem, "#SBATCH --array=0-5\n"), dem);  // 2 points x 3 members
    const std::string case_file = (dir / "case.toml").string();
    // task i: point i / 3, member i % 3
    BOOST_TEST(task_command(root / "slurm" / "dem.sbatch", 4) ==
               "dem " + case_file + " --results " + root.string() + " --point U2.0 --seeds 1,2,7 --seed 2\n");
    BOOST_TEST(task_command(root / "slurm" / "dem.sbatch", 2) ==
               "dem " + case_file + " --results " + root.string() + " --point U1.0 --seeds 1,2,7 --seed 7\n");
    // a set with a repeated seed stops before anything is written, naming the flag
    const auto bad = slurm(dir.string() + " --solvers dem --seeds 1,1 --results " + (dir / "bad").string());
    refused(bad, {"--seeds"});
    BOOST_TEST(!fs::exists(dir / "bad" / "slurm" / "dem.sbatch"));
    fs::remove_all(dir);
}
#endif
