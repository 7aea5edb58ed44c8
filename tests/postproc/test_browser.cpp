// The report as a reader's browser lays it out: headless Chromium (postproc/docs/measure_report.sh)
// at 1024, 1400 and 1920 px, on a report of small synthetic results shaped like the main job's
// (test::main_job_results): no horizontal scroll, the summary within the first screen, no image
// that does not load, the legend's note exactly once, no figure title past its figure's edge; and
// every link of the page lands on a file of the report or an id in it.
#include <regex>
#include <set>

#include <boost/test/unit_test.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/postproc/command.h"
#include "granlub/run/process.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(browser)

BOOST_AUTO_TEST_CASE(report_at_three_widths) {
    const auto s = test::main_job_results("browser");
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const fs::path report = s.o.results_root / "report";
    const std::string html = test::slurp(report / "index.html");

    // Every link lands: an id of the page, or a file or folder of the report (nothing outside it).
    std::set<std::string> ids;
    const std::regex id(R"re(id="([^"]+)")re"), href(R"re(href="([^"]+)")re");
    for (std::sregex_iterator it(html.begin(), html.end(), id), end; it != end; ++it) ids.insert((*it)[1]);
    int links = 0;
    for (std::sregex_iterator it(html.begin(), html.end(), href), end; it != end; ++it, ++links) {
        const std::string target = (*it)[1];
        if (target.starts_with("#"))
            BOOST_TEST(ids.count(target.substr(1)) == 1u, target);
        else
            BOOST_TEST((!target.starts_with("/") && target.find("..") == std::string::npos && target.find(':') == std::string::npos &&
                        fs::exists(report / target)),
                       target);
    }
    BOOST_TEST(links > 20);

    const auto figures = static_cast<int>(test::count(html, "<figure id="));
    BOOST_TEST(figures > 10);
    const auto chromium = find_executable("chromium");
    BOOST_TEST_REQUIRE(chromium.has_value(), "chromium is not installed (Debian package chromium, .ci/packages)");
    const fs::path script = fs::path(GRANLUB_SOURCE_DIR) / "postproc" / "docs" / "measure_report.sh";
    for (const auto& [width, height] : {std::pair{1024, 768}, {1400, 900}, {1920, 1080}}) {
        const fs::path log = s.dir / fmt::format("measure-{}.log", width);
        fs::remove(log);
        const ProcessResult r = run_process(
            {"/bin/sh", script.string(), report.string(), std::to_string(width), std::to_string(height)}, s.dir, log, 180);
        const std::string out = test::slurp(log);
        BOOST_TEST_REQUIRE(r.exit_code == 0, r.describe() + ": " + out);
        std::smatch m;
        BOOST_TEST_REQUIRE(std::regex_search(out, m, std::regex(R"re(\{"clientWidth".*\})re")), out);
        const auto j = nlohmann::json::parse(m.str());
        BOOST_TEST_MESSAGE(fmt::format("{} px: {}", width, j.dump()));
        BOOST_TEST_CONTEXT(width << " px: " << j.dump()) {
            BOOST_TEST(j["clientWidth"].get<int>() > width / 2);  // the window has the size asked for
            BOOST_TEST(j["scrollWidth"].get<int>() <= j["clientWidth"].get<int>());  // no horizontal scroll
            BOOST_TEST(j["summaryTop"].get<int>() >= 0);
            BOOST_TEST(j["summaryBottom"].get<int>() <= j["innerHeight"].get<int>());  // the summary on the first screen
            BOOST_TEST(j["brokenImages"].get<int>() == 0);
            BOOST_TEST(j["legendNotes"].get<int>() == 1);
            BOOST_TEST(j["titles"].get<int>() == figures);  // every figure's title measured as rendered
            BOOST_TEST(j["titlesCut"].get<int>() == 0);  // none past its figure's edge
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
