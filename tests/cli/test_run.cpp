#define BOOST_TEST_MODULE granlub run end to end
#include <filesystem>
#include <fstream>
#include <sstream>

#include <boost/test/unit_test.hpp>

#include "granlub/results/results.h"
#include "run_command.h"
#include "xml_check.h"

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
