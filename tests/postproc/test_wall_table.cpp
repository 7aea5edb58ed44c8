// The continuum on the trough's cross-section in the report: its maps beside the particle run's on
// one colour scale, each saying what it is, and the wall-stress table listing every wall of every
// solver that has it ("—" and why for those without).
#include <algorithm>

#include <boost/test/unit_test.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "granlub/postproc/command.h"
#include "granlub/results/file_io.h"
#include "granlub/results/results.h"
#include "results/collect.h"
#include "tables/wall_layer_table.h"
#include "tables/wall_table.h"
#include "synthetic.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

// Adds outputs (name -> value, stderr or null) and run keys to a written summary.json.
void add_outputs(const test::SyntheticCase& s, const std::string& solver, const std::string& point,
                 const std::map<std::string, std::pair<double, std::optional<double>>>& outputs) {
    const auto file = result_dir(s.o.results_root, solver, point) / "summary.json";
    auto j = nlohmann::json::parse(test::slurp(file));
    for (const auto& [name, v] : outputs)
        j["outputs"][name] = {{"value", v.first}, {"unit", name == "side_wall_drag_share" ? "" : "Pa"},
                              {"stderr", v.second ? nlohmann::json(*v.second) : nlohmann::json(nullptr)}};
    write_file_atomic(file, j.dump(2));
}

// 3 x 4 cells (k across the gap, m across the width): nu_of(k, m), u_of(k, m)
void write_section(const test::SyntheticCase& s, const std::string& solver, const std::string& point,
                   double (*nu_of)(int, int), double (*u_of)(int, int)) {
    Profile t;
    std::vector<double> y, z, nu, u;
    for (int k = 0; k < 3; ++k)
        for (int m = 0; m < 4; ++m) {
            y.push_back((k + 0.5) / 3.0), z.push_back((m + 0.5) / 4.0 - 0.5);
            nu.push_back(nu_of(k, m)), u.push_back(u_of(k, m));
        }
    t.add("y_over_H", y).add("z_over_W", z).add("solid_fraction", nu).add("u_over_U", u);
    write_file_atomic(result_dir(s.o.results_root, solver, point) / kSectionFile, profile_csv(t, {"synthetic"}));
}

const std::vector<postproc::Cell>* row_of(const postproc::Table& t, const std::string& solver, const std::string& point) {
    for (const auto& r : t.rows)
        if (r[0].text == solver && r[1].text == point) return &r;
    return nullptr;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(wall_table)

BOOST_AUTO_TEST_CASE(every_solver_s_walls_and_the_continuum_s_map_on_the_particle_scale) {
    auto s = test::edited_case("wall_table", "width = 0.0", "width = 0.01");  // a trough 10 mm wide: side walls
    for (const char* solver : {"continuum", "automaton", "dem"}) test::write_solver(s, solver);
    for (const OperatingPoint& p : s.c.points) {
        // the continuum on the cross-section: its own share; the dem: side walls with standard errors
        add_outputs(s, "continuum", p.id,
                    {{"shear_stress_outer", {611.0, std::nullopt}}, {"shear_stress_inner", {587.0, std::nullopt}},
                     {"shear_stress_side", {599.0, std::nullopt}}, {"side_wall_drag_share", {0.262, std::nullopt}}});
        test::patch_run(s, "continuum", p.id, {{"geometry", "cross_section"}});
        add_outputs(s, "dem", p.id,
                    {{"shear_stress_outer", {553.0, 5.0}}, {"shear_stress_inner", {413.0, 4.0}},
                     {"shear_stress_side", {483.0, 3.0}}});
    }
    const OperatingPoint& p0 = s.c.points[0];
    // the dem's nu from 0 to 0.6 and u/U from 0.4 to 1; the continuum's a uniform 0.3 and 0.7
    write_section(s, "dem", p0.id, [](int k, int m) { return k == 2 && m == 3 ? 0.0 : 0.6 - 0.1 * k - 0.05 * m; },
                  [](int k, int) { return 1.0 - 0.3 * k; });
    write_section(s, "continuum", p0.id, [](int, int) { return 0.3; }, [](int, int) { return 0.7; });

    const auto col = postproc::collect(s.c, s.o);
    const postproc::Table t = postproc::wall_stress_table(s.c, col);
    // every wall, named
    for (const char* wall : {"τ floor", "τ top", "τ outer side wall", "τ inner side wall", "side walls' drag"})
        BOOST_TEST(std::count_if(t.header.begin(), t.header.end(),
                                 [&](const std::string& h) { return h.starts_with(wall); }) == 1,
                   wall);
    BOOST_TEST_REQUIRE(t.header.size() == 8u);
    for (const OperatingPoint& p : s.c.points) {
        const auto* c = row_of(t, "continuum", p.id);
        const auto* d = row_of(t, "dem", p.id);
        const auto* a = row_of(t, "automaton", p.id);
        BOOST_TEST_REQUIRE((c && d && a));
        const double U = p.speed;
        BOOST_TEST((*c)[3].text == fmt::format("{:.4g}", 400 * U * U));  // synthetic.h: continuum tau = 400 U^2
        BOOST_TEST((*c)[5].text == "611");
        BOOST_TEST((*c)[6].text == "587");
        BOOST_TEST((*c)[7].text == "0.262");  // the continuum's own share
        BOOST_TEST((*d)[5].text.starts_with("553 ±"), (*d)[5].text);
        BOOST_TEST((*d)[6].text.starts_with("413 ±"), (*d)[6].text);
        // the dem's share from its side and top stresses over the box's areas
        const double share = (553.0 + 413.0) * s.c.cell.gap / (*col.run("dem", p.id).scalar("shear_stress_top") * 0.01);
        BOOST_TEST((*d)[7].text == fmt::format("{:.3g}", share));
        // the automaton has floor and top, no side walls, and says why
        BOOST_TEST(!(*a)[3].text.starts_with("—"));
        for (int k : {5, 6, 7}) BOOST_TEST((*a)[k].text == "— (the lattice has no side walls)");
    }

    BOOST_TEST_REQUIRE(postproc::compare(s.c, s.o) == 0);
    const fs::path plots = s.o.results_root / "report" / "plots";
    const std::string html = test::slurp(s.o.results_root / "report" / "index.html");
    BOOST_TEST(html.find("Every wall&#39;s shear stress</h3>") != std::string::npos);
    BOOST_TEST(html.find("Cross-sections of the trough") != std::string::npos);
    std::string cont_nu, cont_u, dem_nu;
    for (const auto& f : fs::directory_iterator(plots)) {
        const std::string n = f.path().filename().string();
        if (n.starts_with("cross_section_continuum_") && n.ends_with("_nu.svg")) cont_nu = test::slurp(f.path());
        if (n.starts_with("cross_section_continuum_") && n.ends_with("_u.svg")) cont_u = test::slurp(f.path());
        if (n.starts_with("cross_section_dem_") && n.ends_with("_nu.svg")) dem_nu = test::slurp(f.path());
    }
    BOOST_TEST_REQUIRE((!cont_nu.empty() && !cont_u.empty() && !dem_nu.empty()));
    // On the dem's scale [0, 0.6] the continuum's 0.3 is the middle of viridis (#21918c) in all 12
    // cells; on its own scale [0, 0.3] it would be the top (#fde725). u/U: 0.7 on [0, 1] -> 0.7.
    BOOST_TEST(test::count(cont_nu, "fill=\"#21918c\" fill-opacity") + test::count(cont_nu, "fill=\"#21918c\"/>") == 12u);
    BOOST_TEST(test::count(cont_nu, "fill=\"#fde725\"") == 0u);
    BOOST_TEST(test::count(dem_nu, "fill=\"#fde725\"/>") == 1u);  // the dem's 0.6 at the top of the scale
    BOOST_TEST(test::count(cont_u, "fill=\"#fde725\"") == 0u);
    // each map says what it is: the continuum's no time average, the dem's over its steady window
    BOOST_TEST(cont_nu.find("steady solution") != std::string::npos);
    BOOST_TEST(cont_nu.find("steady window") == std::string::npos);
    BOOST_TEST(dem_nu.find("steady window") != std::string::npos);
    // its profile is its mid-width column, and the legend says so
    BOOST_TEST(html.find("continuum (mid-width)") != std::string::npos);
}

// The grains beside each wall (run.wall_layer of the particle runs): a row per run and wall with the record's
// slip, spin part and contact slip, a wall the run did not measure saying why; the continuum (no record) has
// no row; no record anywhere, no table.
BOOST_AUTO_TEST_CASE(the_wall_layer_table_reads_the_particle_runs_records) {
    auto s = test::make_case("wall_layer_table");
    for (const char* solver : {"continuum", "dem"}) test::write_solver(s, solver);
    BOOST_TEST(postproc::wall_layer_table(postproc::collect(s.c, s.o)).rows.empty());
    for (const OperatingPoint& p : s.c.points)
        test::patch_run(s, "dem", p.id,
                        {{"wall_layer",
                          {{"bottom", {{"grains", 290}, {"slip_over_U", 0.26}, {"slip_over_U_stderr", 0.003},
                                       {"rolling_over_U", 0.146}, {"rolling_over_U_stderr", 0.009},
                                       {"contact_slip_over_U", 0.114}, {"contact_slip_over_U_stderr", 0.008},
                                       {"rolling_share", 0.5615}, {"rolling_fraction", 0.33}}},
                           {"top", {{"not_measured", "no grain touches the wall"}}}}}});
    const postproc::Table t = postproc::wall_layer_table(postproc::collect(s.c, s.o));
    BOOST_TEST_REQUIRE(t.rows.size() == 2 * s.c.points.size());  // the dem's floor and top at every point
    for (const auto& r : t.rows) {
        BOOST_TEST(r[0].text == "dem");
        if (r[2].text == "floor") {
            BOOST_TEST(r[3].text == "290");
            BOOST_TEST(r[4].text.starts_with("0.26 ±"), r[4].text);
            BOOST_TEST(r[6].text.starts_with("0.114 ±"), r[6].text);
            BOOST_TEST(r[7].text == "0.56");
        } else {
            BOOST_TEST(r[2].text == "top");
            BOOST_TEST(r[3].text == "not measured (no grain touches the wall)");
        }
    }
}

BOOST_AUTO_TEST_SUITE_END()
