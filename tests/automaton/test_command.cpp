// `granlub automaton` end to end on small cases written in the test: result files, VTK output,
// determinism of the written numbers, and clear errors for bad input.
#define BOOST_TEST_MODULE automaton_command
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "granlub/automaton/case_mapping.h"
#include "granlub/automaton/command.h"
#include "granlub/error.h"
#include "granlub/results/results.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

Schema schema() { return Schema::common().add(automaton::section()); }

// A JH06-like case: 10 rows x 40 columns, short runs.
std::string case_text(const std::string& extra_operating = "", const std::string& automaton = "") {
    return R"(
[case]
name = "catest"
title = "automaton test"
[grains]
diameter = 1.0e-3
density = 2550.0
restitution = 0.85
[walls]
restitution = 0.65
roughness = 0.65
[cell]
gap = 10.0e-3
length = 40.0e-3
width = 0.0
max_solid_fraction = 0.65
[operating]
speed = 2.0
control = "fill"
solid_fraction = 0.5525
normal_stress = 5.5e3
)" + extra_operating + R"(
[body_forces]
gravity = 0.0
[automaton]
steps = 3000
t_avg_start = 1000
block = 500
replicas = 2
snapshot_every = 500
)" + automaton;
}

fs::path fresh_dir(const std::string& name) {
    const fs::path d = fs::path(GRANLUB_BINARY_DIR) / "test-output" / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p);
    std::stringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string error_of(const std::string& text) {
    try {
        const Case c = parse_case(text, "test.toml", schema());
        RunOptions o;
        for (const auto& p : c.points) automaton::resolve_settings(c, p, o);
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

BOOST_AUTO_TEST_CASE(writes_results_for_every_point) {
    const Case c = parse_case(case_text("roughness = [0.25, 1.0]\n"), "test.toml", schema());
    RunOptions o;
    o.results_root = fresh_dir("sweep");
    o.seed = 5;
    o.vtk = true;
    BOOST_TEST(automaton::run(c, o) == 0);
    double slip_prev = 2;
    for (const auto& p : c.points) {
        const fs::path dir = o.results_root / "automaton" / p.id;
        const Profile prof = read_profile(dir / "profile.csv");
        const Summary s = read_summary(dir / "summary.json");
        BOOST_TEST(prof.rows() == 10u);
        for (const char* col : {"y_over_H", "u_over_U", "u_over_U_stderr", "solid_fraction", "solid_fraction_stderr",
                                "temperature_over_U2", "solid_fraction_scaled", "ux_over_U", "ukin_over_U"})
            BOOST_TEST(prof.has(col), col);
        // occupancy averages to the fill; the scaled column is occupancy x nu_max
        double mean_nu = 0;
        for (double v : prof.column("solid_fraction")) mean_nu += v / 10;
        BOOST_TEST(mean_nu == 0.85, boost::test_tools::tolerance(1e-9));
        BOOST_TEST(prof.column("solid_fraction_scaled")[3] == 0.65 * prof.column("solid_fraction")[3],
                   boost::test_tools::tolerance(1e-12));
        BOOST_TEST(s.value("max_solid_fraction") == 1.0);
        BOOST_TEST(s.value("slip_bottom") == 2.0 * s.value("slip_bottom_over_U"), boost::test_tools::tolerance(1e-12));
        BOOST_TEST(s.outputs.at("slip_bottom").stderr_.has_value());
        BOOST_TEST(s.value("shear_stress_bottom") > 0);
        BOOST_TEST(s.run.at("lattice").at("rows") == 10);
        BOOST_TEST(s.run.at("lattice").at("columns") == 40);
        BOOST_TEST(s.run.at("lattice").at("particles") == 340);
        BOOST_TEST(s.provenance.seed.value() == 5u);
        BOOST_TEST(s.run.at("steady_state").at("reached") == true);
        BOOST_TEST(s.value("slip_bottom_over_U") < slip_prev);  // rougher: less slip
        slip_prev = s.value("slip_bottom_over_U");
        // ParaView: a .pvd naming every .vti snapshot, which exists and is ImageData.
        const std::string pvd = slurp(dir / "lattice.pvd");
        BOOST_TEST(pvd.find("lattice_00000000.vti") != std::string::npos);
        BOOST_TEST(pvd.find("lattice_00003000.vti") != std::string::npos);
        const std::string vti = slurp(dir / "vtk" / "lattice_00003000.vti");
        BOOST_TEST(vti.find("<ImageData WholeExtent=\"0 40 0 12 0 1\"") != std::string::npos);
        BOOST_TEST(fs::exists(dir / "timeseries.csv"));
    }
}

BOOST_AUTO_TEST_CASE(keys_set_their_fields_and_an_old_name_still_reads) {
    RunOptions o;
    o.vtk = true;
    // the key's default when the case does not set it; the case's value when it does
    std::string t = case_text();
    t.replace(t.find("snapshot_every = 500\n"), 21, "");
    const Case plain = parse_case(t, "test.toml", schema());
    BOOST_TEST(automaton::resolve_settings(plain, plain.points[0], o).params.run.snapshot_every == 100);
    const Case c = parse_case(case_text(), "test.toml", schema());
    BOOST_TEST(c.warnings.empty());
    automaton::Params p = automaton::resolve_settings(c, c.points[0], o).params;
    BOOST_TEST(p.run.snapshot_every == 500);
    BOOST_TEST(p.run.steps == 3000);
    BOOST_TEST(p.run.replicas == 2);
    BOOST_TEST(automaton::resolve_settings(c, c.points[0], RunOptions{}).params.run.snapshot_every == 0);  // no --vtk
    o.full = true;
    p = automaton::resolve_settings(c, c.points[0], o).params;
    BOOST_TEST(p.run.steps == 50000);  // steps_full's default
    BOOST_TEST(p.run.replicas == 16);
    // the old name vtk_every: read as snapshot_every, with a warning naming both
    t = case_text();
    t.replace(t.find("snapshot_every"), 14, "vtk_every");
    const Case old = parse_case(t, "test.toml", schema());
    BOOST_TEST_REQUIRE(old.warnings.size() == 1u);
    BOOST_TEST(old.warnings[0].find("vtk_every is the old name of snapshot_every") != std::string::npos, old.warnings[0]);
    BOOST_TEST(old.warnings[0].find("test.toml:") != std::string::npos, old.warnings[0]);
    BOOST_TEST(automaton::resolve_settings(old, old.points[0], o).params.run.snapshot_every == 500);
    // both names: refused, naming both
    try {
        parse_case(case_text("", "vtk_every = 200\n"), "test.toml", schema());
        BOOST_FAIL("both names accepted");
    } catch (const CaseError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.find("vtk_every is the old name of snapshot_every, which is also given") != std::string::npos, m);
    }
}

BOOST_AUTO_TEST_CASE(same_seed_same_files) {
    const Case c = parse_case(case_text(), "test.toml", schema());
    RunOptions o;
    o.seed = 11;
    o.results_root = fresh_dir("seed_a");
    o.threads = 1;
    BOOST_TEST(automaton::run(c, o) == 0);
    const fs::path a = o.results_root;
    o.results_root = fresh_dir("seed_b");
    o.threads = 2;
    BOOST_TEST(automaton::run(c, o) == 0);
    const std::string id = c.points.front().id;
    BOOST_TEST(slurp(a / "automaton" / id / "profile.csv") ==
               slurp(o.results_root / "automaton" / id / "profile.csv"));
    const Summary sa = read_summary(a / "automaton" / id / "summary.json");
    const Summary sb = read_summary(o.results_root / "automaton" / id / "summary.json");
    for (const auto& [name, v] : sa.outputs) BOOST_TEST(v.value == sb.outputs.at(name).value, name);
}

BOOST_AUTO_TEST_CASE(bad_inputs_give_clear_errors) {
    // fill > 1 from the solid fraction: core already rejects solid_fraction >= max_solid_fraction
    std::string t = case_text();
    t.replace(t.find("solid_fraction = 0.5525"), 23, "solid_fraction = 0.7");
    std::string e = error_of(t);
    BOOST_TEST(e.find("solid_fraction = 0.7") != std::string::npos, e);
    // fill key out of range: rejected by the schema, naming the key
    e = error_of(case_text("", "fill = 1.2\n"));
    BOOST_TEST(e.find("fill") != std::string::npos, e);
    // fewer than 3 rows
    t = case_text();
    t.replace(t.find("gap = 10.0e-3"), 13, "gap = 2.0e-3");
    e = error_of(t);
    BOOST_TEST(e.find("gap") != std::string::npos, e);
    BOOST_TEST(e.find("at least 3 rows") != std::string::npos, e);
    // load control without a fill
    t = case_text();
    t.replace(t.find("control = \"fill\""), 16, "control = \"load\"");
    e = error_of(t);
    BOOST_TEST(e.find("load") != std::string::npos, e);
    // switches
    e = error_of(case_text("", "pp_deflect = 60\n"));
    BOOST_TEST(e.find("pp_deflect") != std::string::npos, e);
    e = error_of(case_text("", "tf_rounding = \"floor\"\n"));
    BOOST_TEST(e.find("tf_rounding") != std::string::npos, e);
    e = error_of(case_text("", "t_avg_start = 600\n"));
    BOOST_TEST(e.find("t_avg_start") != std::string::npos, e);
    // steady-state protocol keys (docs/automaton-model.md §4.5): file, key, value and what is allowed
    e = error_of(case_text("", "steady_state = \"forever\"\n"));
    BOOST_TEST(e.find("test.toml") != std::string::npos, e);
    BOOST_TEST(e.find("steady_state") != std::string::npos, e);
    BOOST_TEST(e.find("forever") != std::string::npos, e);
    BOOST_TEST(e.find("runs") != std::string::npos, e);
    e = error_of(case_text("", "steady_state = \"runs\"\nruns_start = 1500\n"));
    BOOST_TEST(e.find("test.toml") != std::string::npos, e);
    BOOST_TEST(e.find("runs_start = 1500") != std::string::npos, e);
    BOOST_TEST(e.find("multiple of 2 x block = 1000") != std::string::npos, e);
    e = error_of(case_text("", "steady_state = \"runs\"\nruns_max_steps = 1000\n"));
    BOOST_TEST(e.find("runs_max_steps = 1000") != std::string::npos, e);
    BOOST_TEST(e.find("at least 2 x runs_start = 2000") != std::string::npos, e);
    e = error_of(case_text("", "runs_tol_u = 0.0\n"));
    BOOST_TEST(e.find("runs_tol_u") != std::string::npos, e);
    BOOST_TEST(e.find("0") != std::string::npos, e);
    e = error_of(case_text("", "runs_start = 0\n"));
    BOOST_TEST(e.find("runs_start") != std::string::npos, e);
    e = error_of(case_text("", "nonsense = 1\n"));
    BOOST_TEST(e.find("nonsense") != std::string::npos, e);
    BOOST_TEST(error_of(case_text()) == "");
}

BOOST_AUTO_TEST_CASE(runs_protocol_is_recorded_and_its_failure_writes_nothing) {
    // JH06's literal protocol (§4.5): run lengths and final differences in run{}.
    const Case c = parse_case(case_text("", "steady_state = \"runs\"\n"), "test.toml", schema());
    RunOptions o;
    o.results_root = fresh_dir("runs");
    BOOST_TEST(automaton::run(c, o) == 0);
    const fs::path dir = o.results_root / "automaton" / c.points.front().id;
    const Summary s = read_summary(dir / "summary.json");
    const auto& st = s.run.at("steady_state");
    BOOST_TEST(st.at("protocol") == "runs");
    BOOST_TEST(st.at("reached") == true);
    const auto lengths = st.at("run_lengths").get<std::vector<std::int64_t>>();
    BOOST_REQUIRE(lengths.size() >= 2u);
    BOOST_TEST(lengths.front() == 1000);
    BOOST_TEST(s.run.at("steps").get<std::int64_t>() == lengths.back());
    BOOST_TEST(st.at("from_step").get<std::int64_t>() == lengths.back() / 2);
    BOOST_TEST(st.at("max_du_over_U").size() == lengths.size() - 1);
    BOOST_TEST(st.at("final_max_du_over_U").get<double>() < 0.01);
    BOOST_TEST(st.at("final_max_dnu").get<double>() < 0.01);
    BOOST_TEST(st.at("tol_u").get<double>() == 0.01);
    BOOST_TEST(read_profile(dir / "profile.csv").rows() == 10u);

    // A step limit too tight for the transient: the point fails and writes no result.
    std::string text = case_text("", "steady_state = \"runs\"\nruns_start = 20\nruns_max_steps = 80\n");
    text.replace(text.find("t_avg_start = 1000"), 18, "t_avg_start = 0");
    text.replace(text.find("block = 500"), 11, "block = 10");
    const Case t = parse_case(text, "test.toml", schema());
    o.results_root = fresh_dir("runs_fail");
    BOOST_TEST(automaton::run(t, o) == 1);
    BOOST_TEST(!fs::exists(o.results_root / "automaton" / t.points.front().id / "summary.json"));
}
