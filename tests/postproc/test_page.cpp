// The page as a researcher reads it: a navigation bar whose every link lands on a part, the
// per-point parts folded (the first one open), and provenance as a table (case hash, version,
// seed per run; settings per solver as key = value) instead of raw JSON.
#include <regex>
#include <set>

#include <boost/test/unit_test.hpp>

#include "granlub/postproc/command.h"
#include "granlub/results/results.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

BOOST_AUTO_TEST_SUITE(page)

BOOST_AUTO_TEST_CASE(navigation_folds_and_readable_provenance) {
    auto s = test::make_case("page");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::compare(s.c, s.o) == 0);
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");

    // Every nav link has its target id, and every part (h2) is in the nav.
    const auto nav_begin = html.find("<nav>"), nav_end = html.find("</nav>");
    BOOST_TEST_REQUIRE(nav_end != std::string::npos);
    const std::string nav = html.substr(nav_begin, nav_end - nav_begin);
    std::set<std::string> links, ids;
    const std::regex href(R"re(href="#([a-z0-9-]+)")re"), h2(R"re(<h2 id="([a-z0-9-]+)">)re");
    for (std::sregex_iterator it(nav.begin(), nav.end(), href), end; it != end; ++it) links.insert((*it)[1]);
    for (std::sregex_iterator it(html.begin(), html.end(), h2), end; it != end; ++it) ids.insert((*it)[1]);
    BOOST_TEST(links.size() >= 8u);
    BOOST_TEST((links == ids));
    BOOST_TEST(links.count("s-provenance-of-every-run") == 1u);

    // Three points: profiles and differences fold per point; only the first point's profiles open (the
    // summary says who differs, the difference tables are one click away).
    const std::regex fold(R"re(<details( open="open")?>\s*<summary>Point (U[0-9.]+)</summary>)re");
    std::vector<std::pair<bool, std::string>> folds;
    for (std::sregex_iterator it(html.begin(), html.end(), fold), end; it != end; ++it)
        folds.emplace_back((*it)[1].matched, (*it)[2]);
    BOOST_TEST_REQUIRE(folds.size() == 6u);
    BOOST_TEST((folds[0] == std::pair(true, std::string("U1.0"))));
    BOOST_TEST((folds[1] == std::pair(false, std::string("U2.0"))));
    BOOST_TEST((folds[3] == std::pair(false, std::string("U1.0"))));

    // Provenance: the case hash and version of each run in a cell, the DEM's seed (7), no JSON object text.
    const Summary dem = read_summary(s.o.results_root / "dem" / "U1.0" / "summary.json");
    const auto prov = html.substr(html.find("id=\"s-provenance-of-every-run\""));
    const std::string row_start = "<tr><td>dem</td><td>U1.0</td>";
    const auto row = prov.substr(prov.find(row_start), prov.find("</tr>", prov.find(row_start)) - prov.find(row_start));
    BOOST_TEST(row.find("<td class=\"code\">" + dem.provenance.case_hash + "</td>") != std::string::npos, row);
    BOOST_TEST(row.find("<td>" + dem.provenance.version + "</td>") != std::string::npos, row);
    BOOST_TEST(row.find("<td>7</td>") != std::string::npos, row);
    const auto files = prov.find("id=\"s-files\"");
    BOOST_TEST(prov.substr(0, files).find("{&quot;") == std::string::npos);  // no raw JSON before the next part
    BOOST_TEST(prov.find("<summary>Settings of dem") < files);
}

BOOST_AUTO_TEST_SUITE_END()
