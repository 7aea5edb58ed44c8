#define BOOST_TEST_MODULE granlub run end to end
#include <filesystem>
#include <fstream>
#include <sstream>

#include <boost/test/unit_test.hpp>
#include <nlohmann/json.hpp>

#include "granlub/particles/particles.h"
#include "granlub/results/results.h"
#include "granlub/statistics/flow_regime.h"
#include "run_command.h"
#include "xml_check.h"
#ifdef GRANLUB_TEST_ENGINES
#include "tiny_cell_text.h"
#endif

using granlub::test::run;
namespace fs = std::filesystem;

namespace {
std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}
}  // namespace

BOOST_AUTO_TEST_CASE(run_writes_results_and_a_well_formed_report) {
    const fs::path out = fs::temp_directory_path() / "granlub_test_run";
    fs::remove_all(out);
    const std::string cmd = std::string(GRANLUB_EXE) + " run " + GRANLUB_SOURCE_DIR +
                            "/tests/cli/tiny --solvers continuum,automaton --results " + out.string();
    auto o = run(cmd);
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("== [1/3] continuum") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("== [3/3] compare") != std::string::npos, o.text);
    BOOST_TEST(o.text.find("automaton  U2.0") != std::string::npos, o.text);  // closing table

    for (const char* solver : {"continuum", "automaton"})
        for (const char* point : {"U1.0", "U2.0"}) {
            const auto dir = out / solver / point;
            BOOST_TEST_CONTEXT(dir) {
                const auto s = granlub::read_summary(dir / "summary.json");
                BOOST_TEST(s.value("mean_solid_fraction") > 0.0);
                const auto p = granlub::read_profile(dir / "profile.csv");
                BOOST_TEST(p.rows() >= 3u);
            }
        }

    const fs::path report = out / "report";
    BOOST_REQUIRE(fs::exists(report / "index.html"));
    BOOST_TEST(fs::exists(report / "report.md"));
    BOOST_TEST(fs::exists(report / "metrics.csv"));
    const std::string html = slurp(report / "index.html");
    BOOST_TEST(granlub::test::xml_error(html).empty(), granlub::test::xml_error(html));
    BOOST_TEST(html.find("<svg") != std::string::npos);
    // The particle solvers were not run: the report must say they are missing.
    BOOST_TEST(slurp(report / "report.md").find("dem") != std::string::npos);
    int svgs = 0;
    for (const auto& e : fs::recursive_directory_iterator(report))
        if (e.path().extension() == ".svg") {
            ++svgs;
            BOOST_TEST(granlub::test::xml_error(slurp(e.path())).empty(), e.path());
        }
    BOOST_TEST_MESSAGE(svgs << " SVG files checked");

    // A second run resumes: every solver point is skipped.
    auto again = run(cmd);
    BOOST_TEST(again.text.find("continuum U1.0           complete, skipped") != std::string::npos, again.text);
    fs::remove_all(out);
}

#ifdef GRANLUB_TEST_ENGINES
// The engines as one stage (cli/run_all.cpp, granlub/run/pipeline.h): DEM and a warm-started YADE
// side by side on a cell of 220 grains, each YADE point from its own DEM point's final state; with
// --threads (a core budget) they are two stages, one after the other.
BOOST_AUTO_TEST_CASE(dem_and_a_warm_yade_run_side_by_side) {
    const fs::path dir = fs::temp_directory_path() / "granlub_test_run_engines";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string text = granlub::test::tiny_cell("tiny_engines", "", "time = 0.02\nsample_every = 20\n") +
                       "[yade]\nstart = \"warm\"\ntime = 0.004\n";
    text.replace(text.find("speed = [1.0]"), 13, "speed = [1.0, 2.0]");
    std::ofstream(dir / "case.toml") << text;
    const std::string cmd = std::string(GRANLUB_EXE) + " run " + dir.string() + " --solvers dem,yade";
    auto o = run(cmd);
    BOOST_TEST(o.rc == 0, o.text);
    BOOST_TEST(o.text.find("== [1/2] dem and yade on tiny_engines (2 point(s) each, side by side") != std::string::npos,
               o.text);
    BOOST_TEST(o.text.find("== [2/2] compare") != std::string::npos, o.text);
    for (const char* point : {"U1.0", "U2.0"}) {
        BOOST_TEST_CONTEXT(point) {
            const auto dem = granlub::read_summary(dir / "results" / "dem" / point / "summary.json");
            const auto yade = granlub::read_summary(dir / "results" / "yade" / point / "summary.json");
            // each YADE point started from its DEM point's final state, written before it
            BOOST_TEST(yade.run.at("start").get<std::string>().starts_with("warm, from granlub dem's final state"));
            BOOST_TEST(yade.value("mean_solid_fraction") > 0.0);
            BOOST_TEST(dem.value("mean_solid_fraction") > 0.0);
        }
    }
    // a core budget: the engines one after the other, as two stages
    auto budget = run(cmd + " --point U1.0 --threads 1 --force");
    BOOST_TEST(budget.rc == 0, budget.text);
    BOOST_TEST(budget.text.find("== [1/3] dem on tiny_engines (1 point(s)),") != std::string::npos, budget.text);
    BOOST_TEST(budget.text.find("== [2/3] yade on tiny_engines") != std::string::npos, budget.text);
    fs::remove_all(dir);
}

// A set of seeds through both engines (granlub/particles/seeds.h): each seed its own size draw and
// insertion (its own initial grains, its own LIGGGHTS data file), each YADE member warm-started from
// DEM's member of the same seed, and both points' files pooled over the two seeds.
BOOST_AUTO_TEST_CASE(seeds_reach_both_engines_and_are_pooled) {
    const fs::path dir = fs::temp_directory_path() / "granlub_test_run_seeds";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string text = granlub::test::tiny_cell("tiny_seeds", "", "time = 0.02\nsample_every = 20\n") +
                       "[yade]\nstart = \"warm\"\ntime = 0.004\n[particles]\nseeds = [3, 5]\n";
    // sizes drawn (a spread), at a fill the widest lattice takes
    text.replace(text.find("friction = 0.5\n"), 15, "friction = 0.5\nsize_spread = 0.05\n");
    text.replace(text.find("solid_fraction = 0.4"), 20, "solid_fraction = 0.35");
    std::ofstream(dir / "case.toml") << text;
    auto o = run(std::string(GRANLUB_EXE) + " run " + dir.string() + " --solvers dem,yade");
    BOOST_TEST(o.rc == 0, o.text);
    for (const char* line : {"dem U1.0/seed-3", "dem U1.0/seed-5", "yade U1.0/seed-3", "yade U1.0/seed-5"})
        BOOST_TEST(o.text.find(line) != std::string::npos, line << ": " << o.text);
    const fs::path res = dir / "results";
    const std::string grains3 = slurp(res / "initial" / "U1.0" / "seed-3" / "particles.csv");
    const std::string grains5 = slurp(res / "initial" / "U1.0" / "seed-5" / "particles.csv");
    BOOST_TEST(grains3.find("seed=3") != std::string::npos);
    BOOST_TEST(grains5.find("seed=5") != std::string::npos);
    // the size draw: the radii differ, not only the positions
    const fs::path initial = res / "initial" / "U1.0";
    BOOST_TEST((granlub::read_particles_csv(initial / "seed-3" / "particles.csv").radius !=
                granlub::read_particles_csv(initial / "seed-5" / "particles.csv").radius));
    // the engine ran each seed's grains: the LIGGGHTS data files differ
    BOOST_TEST(slurp(res / "dem" / "U1.0" / "seed-3" / "grains.data") != slurp(res / "dem" / "U1.0" / "seed-5" / "grains.data"));
    for (const int seed : {3, 5}) {
        const std::string member = "seed-" + std::to_string(seed);
        const auto dem = granlub::read_summary(res / "dem" / "U1.0" / member / "summary.json");
        const auto yade = granlub::read_summary(res / "yade" / "U1.0" / member / "summary.json");
        BOOST_TEST(dem.provenance.seed.value_or(0) == static_cast<unsigned>(seed));
        BOOST_TEST(yade.provenance.seed.value_or(0) == static_cast<unsigned>(seed));
        const std::string from = yade.provenance.settings.at("warm_start").at("from").get<std::string>();
        BOOST_TEST(from.find("dem/U1.0/" + member + "/final_state.csv") != std::string::npos, from);
    }
    for (const char* solver : {"dem", "yade"}) {
        const auto pooled = granlub::read_summary(res / solver / "U1.0" / "summary.json");
        BOOST_TEST(pooled.run.at("seeds").at("pooled") == nlohmann::json({3, 5}), solver);
        BOOST_TEST(pooled.outputs.at("shear_stress_bottom").block_stderr.has_value(), solver);
        // the flow regime's Z pooled too, its verdict the pooled Z's (seed_pool.h)
        const nlohmann::json& fr = pooled.run.at("flow_regime");
        double z = 0;
        for (const int seed : {3, 5})
            z += granlub::read_summary(res / solver / "U1.0" / ("seed-" + std::to_string(seed)) / "summary.json")
                     .run.at("flow_regime").at("coordination_number").get<double>() / 2;
        BOOST_TEST(fr.at("coordination_number").get<double>() == z, boost::test_tools::tolerance(1e-12));
        BOOST_TEST(fr.contains("coordination_number_block_stderr"), solver);
        BOOST_TEST(fr.at("regime").get<std::string>() ==
                       granlub::to_string(granlub::lubrication_verdict(z, fr.at("contact_persistence").get<double>()).lubrication),
                   solver);
    }
    fs::remove_all(dir);
}
#endif
