// The one particle pipeline (particle_pipeline.h) on a hand-made run: what it writes beside the
// result, the contact measures it takes when positions are recorded (and says so when they are
// not), the wall layer from the final state, and its errors naming the engine's file.
#include <filesystem>
#include <string>

#include <unistd.h>

#include <boost/test/unit_test.hpp>

#include "granlub/error.h"
#include "granlub/particles/particle_pipeline.h"
#include "granlub/results/results.h"
#include "granlub/results/run_status.h"
#include "granlub/results/table.h"

using namespace granlub;
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kRows = 40;  // wall-force blocks of 10 steps of 1 ms
constexpr double kTimeStep = 1e-3;

WallForceSeries steady_forces() {
    WallForceSeries w;
    for (std::size_t i = 0; i < kRows; ++i) {
        w.step.push_back(10.0 * static_cast<double>(i + 1));
        w.fy_bottom.push_back(-100), w.fy_top.push_back(90);
        w.fx_bottom.push_back(i % 2 ? -9.0 : -11.0), w.fx_top.push_back(20);
        w.fz_bottom.push_back(0), w.fz_top.push_back(0);
    }
    return w;
}

// Two grains of radius 0.1 m 0.001 m apart along x at mid-gap (touching within the tolerance), one snapshot every 40 steps; `shift`
// moves the second grain away (no contact) from snapshot `from` on.
SnapshotReader pair_of_grains(std::size_t n, double shift = 0, std::size_t from = 0, double every = 0.04) {
    return {"pair.txt", [=](const SnapshotVisitor& each) {
                for (std::size_t k = 0; k < n; ++k) {
                    ParticleSet p;
                    p.push_back(0.5, 0.5, 0, 1.0, 0, 0, 0.1);
                    p.push_back(0.701 + (k >= from ? shift : 0.0), 0.5, 0, 0.5, 0, 0, 0.1);
                    each(p, static_cast<double>(k + 1) * every);
                }
                return n;
            }};
}

struct Fixture {
    Case c;
    OperatingPoint p;
    ServoSettings servo;
    fs::path dir;
    Fixture() {
        c.name = "hand";
        c.cell.max_solid_fraction = 0.64;
        c.grains.diameter = 0.2;
        c.grains.density = 2500;
        p.id = "U2.0";
        p.speed = 2.0;
        dir = fs::temp_directory_path() / ("granlub_pipeline_" + std::to_string(::getpid()));
        fs::create_directories(dir);
    }
    ~Fixture() { fs::remove_all(dir); }
    ParticlePipeline pipeline(bool contacts) const {
        ParticlePipeline pl{.c = c,
                            .p = p,
                            .box = ParticleBox{.length = 2.0, .gap = 1.0, .width = 0.5, .periodic_z = true},
                            .servo = servo,
                            .time_step = kTimeStep,
                            .sample_every = 10,
                            .stations = 2,
                            .blocks = 5,
                            .grains = 2,
                            .simulated_s = 0.4,
                            .persistence_every = 5,
                            .what = "case hand point U2.0 (test)"};
        if (contacts) pl.contact_box = pl.box;
        return pl;
    }
};

}  // namespace

BOOST_FIXTURE_TEST_SUITE(particle_pipeline, Fixture)

BOOST_AUTO_TEST_CASE(writes_the_tables_beside_the_result_with_the_run_named) {
    ParticleRecord rec{.forces = steady_forces(), .snapshots = pair_of_grains(10)};
    const ParticleReduction r = run_particle_pipeline(pipeline(false), rec, dir);
    BOOST_TEST(r.outputs.at("normal_stress_bottom").value == 100.0 / 1.0);  // A = L W = 1 m^2
    BOOST_TEST((read_regime(r.run).status == RegimeStatus::Steady));
    for (const char* f : {kSectionFile, kWidthProfileFile}) {
        BOOST_TEST_REQUIRE(fs::exists(dir / f), f);
        BOOST_TEST(read_file(dir / f).find("# case hand point U2.0 (test)") == 0u, f);
    }
    BOOST_TEST(!fs::exists(dir / kGapFile));  // no plate: no plate history
    // both grains sit in the upper slab's lower half and the lower slab's upper half: the width
    // profile holds both (over the whole gap), u/U the volume-weighted mean of 1/2 and 1/4
    const Table w = read_table(dir / kWidthProfileFile);
    double u = 0, nu = 0;
    for (std::size_t i = 0; i < w.rows(); ++i) nu += w.column("solid_fraction")[i];
    for (double v : w.column("u_over_U")) u = std::max(u, v);
    BOOST_TEST(nu > 0.0);
    BOOST_TEST(std::abs(u - 0.375) < 1e-12);
}

BOOST_AUTO_TEST_CASE(contacts_are_measured_when_positions_are_recorded) {
    // touching for the whole run; the persistence snapshots 5 steps apart, the pair parted in the last
    ParticleRecord rec{.forces = steady_forces(),
                       .snapshots = pair_of_grains(10),
                       .persistence = pair_of_grains(3, 0.5, 2, 5 * kTimeStep)};
    const nlohmann::json fr = run_particle_pipeline(pipeline(true), rec, dir).run.at("flow_regime");
    BOOST_TEST(fr.at("coordination_number").get<double>() == 1.0);  // one pair, two grains
    BOOST_TEST(fr.at("contact_persistence").get<double>() == 0.5);  // kept, then lost
    BOOST_TEST(fr.at("persistence_snapshots").get<std::size_t>() == 3u);
    BOOST_TEST(fr.at("max_overlap").get<double>() == 0.0);
    BOOST_TEST(!fr.contains("contacts_not_measured"));
    // the same run without positions to search: said, not guessed
    rec.persistence = {};
    const nlohmann::json none = run_particle_pipeline(pipeline(false), rec, dir).run.at("flow_regime");
    BOOST_TEST(none.at("coordination_number").is_null());
    BOOST_TEST(none.contains("contacts_not_measured"));
    BOOST_TEST(!none.at("enduring_contacts").get<bool>());
}

BOOST_AUTO_TEST_CASE(the_wall_layer_is_measured_from_the_final_state_and_kept_in_the_summary) {
    ParticleRecord rec{.forces = steady_forces(), .snapshots = pair_of_grains(10)};
    BOOST_TEST(run_particle_pipeline(pipeline(false), rec, dir).run.at("wall_layer").contains("not_measured"));
    ParticleState end;  // a grain of radius 0.1 m on the floor (U = 2 m/s) at 1.4 m/s, half its lag rolled back
    end.gap = 1.0, end.time = 0.4;
    end.particles.push_back(0.5, 0.1, 0, 1.4, 0, 0, 0.1);
    end.particles.wx = {0.0}, end.particles.wy = {0.0}, end.particles.wz = {3.0};
    rec.final_state = end;
    Summary s;
    s.solver = "dem", s.case_name = c.name, s.point = p.id;
    ParticleReduction r = run_particle_pipeline(pipeline(false), rec, dir);
    s.outputs = r.outputs, s.run = r.run;
    const nlohmann::json bottom = summary_from_json(summary_json(s), "test").run.at("wall_layer").at("bottom");
    BOOST_TEST(bottom.at("grains").get<std::size_t>() == 1u);
    BOOST_TEST(std::abs(bottom.at("slip_over_U").get<double>() - 0.3) < 1e-12);
    BOOST_TEST(std::abs(bottom.at("rolling_share").get<double>() - 0.5) < 1e-12);
}

BOOST_AUTO_TEST_CASE(errors_name_the_engines_file) {
    ParticleRecord rec{.forces = steady_forces(), .snapshots = pair_of_grains(1)};
    BOOST_CHECK_EXCEPTION(run_particle_pipeline(pipeline(false), rec, dir), SolverError, [](const SolverError& e) {
        return std::string(e.what()).find("pair.txt: fewer than 2 particle snapshots") != std::string::npos;
    });
    rec.snapshots = pair_of_grains(10);
    rec.persistence = pair_of_grains(3, 0, 0, 7 * kTimeStep);  // 7 steps apart, 5 expected
    BOOST_CHECK_EXCEPTION(run_particle_pipeline(pipeline(true), rec, dir), SolverError, [](const SolverError& e) {
        return std::string(e.what()).find("expected 5 steps") != std::string::npos;
    });
}

BOOST_AUTO_TEST_SUITE_END()
