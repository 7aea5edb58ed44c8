// The shared particle reduction (particle_reduction.h) on a hand-made run with known answers:
// wall forces with a transient first MSER batch, then steady; two grains in two slabs.
#include <cmath>
#include <numbers>
#include <string>

#include <boost/test/unit_test.hpp>

#include "granlub/particles/particle_reduction.h"
#include "granlub/results/run_status.h"

using namespace granlub;

namespace {

constexpr std::size_t kRows = 40;       // wall-force blocks of 10 steps
constexpr std::size_t kTransient = 5;   // one MSER-5 batch
constexpr double kTimeStep = 1e-3;      // s

// f(i) in the transient rows, g(i) after
template <class F, class G>
std::vector<double> series(F f, G g) {
    std::vector<double> v(kRows);
    for (std::size_t i = 0; i < kRows; ++i) v[i] = i < kTransient ? f(i) : g(i);
    return v;
}

WallForceSeries forces() {
    WallForceSeries w;
    for (std::size_t i = 0; i < kRows; ++i) w.step.push_back(10.0 * static_cast<double>(i + 1));
    auto constant = [](double c) { return [c](std::size_t) { return c; }; };
    // forces of the grains on the walls (A = L W = 1 m^2): bottom pushed to -y and dragged to -x
    w.fy_bottom = series(constant(-500), constant(-100));
    w.fy_top = series(constant(400), constant(90));
    w.fx_bottom = series(constant(0), [](std::size_t i) { return -(10.0 + ((i - kTransient) % 2 == 0 ? 1 : -1)); });
    w.fx_top = series(constant(0), constant(20));
    w.fz_bottom = w.fz_top = std::vector<double>(kRows, 0.0);
    w.fx_side1 = w.fx_side2 = std::vector<double>(kRows, -4.0);  // side area L H = 2 m^2
    w.fy_side1 = std::vector<double>(kRows, -3.0), w.fy_side2 = std::vector<double>(kRows, -2.0);  // pushed down
    return w;
}

// two grains of radius 0.1 m, one inside each of the two slabs; vx = 0 before the steady state
SliceCoarseGrainer snapshots(double U) {
    SliceCoarseGrainer cg(Stations{0.0, 1.0, 2}, 1.0);
    for (int k = 1; k <= 10; ++k) {
        const double t = static_cast<double>(k) * 0.01;
        const bool steady = t > 0.05 - 1e-12;
        ParticleSet p;
        p.push_back(0, 0.25, 0, steady ? 0.8 * U : 0.0, 0, 0, 0.1);
        p.push_back(0, 0.75, 0, steady ? 0.1 * U : 0.0, 0, 0, 0.1);
        cg.add_snapshot(p, t);
    }
    return cg;
}

}  // namespace

BOOST_AUTO_TEST_CASE(wall_stresses_are_positive_for_a_sheared_compressed_layer) {
    const ParticleBox box{.length = 2.0, .gap = 1.0, .width = 0.5};
    const WallStresses s = wall_stresses(forces(), box);
    BOOST_TEST(s.normal_bottom.back() == 100.0);
    BOOST_TEST(s.normal_top.back() == 90.0);
    BOOST_TEST(s.shear_top.back() == 20.0);
    BOOST_TEST(s.shear_side.back() == 2.0);  // -(fx1 + fx2) / 2 / (L H)
    WallForceSeries periodic = forces();
    periodic.fx_side1.clear(), periodic.fx_side2.clear();
    BOOST_TEST(wall_stresses(periodic, box).shear_side.empty());
}

BOOST_AUTO_TEST_CASE(reduction_of_a_known_run) {
    const double U = 2.0;
    Case c;
    c.cell.max_solid_fraction = 0.64;
    c.grains.diameter = 0.2;
    const ParticleBox box{.length = 2.0, .gap = 1.0, .width = 0.5};
    const WallForceSeries f = forces();
    const WallStresses st = wall_stresses(f, box);
    const SteadyWindow win = wall_steady_window(st, f, 10, kTimeStep, nullptr, 0);
    BOOST_TEST(win.wall_start == kTransient);  // the transient batch cut, nothing more
    BOOST_TEST(win.steady);
    BOOST_TEST(win.t_start == 50 * kTimeStep);
    const SliceCoarseGrainer cg = snapshots(U);
    const ServoSettings servo;
    const ParticleReduction r = reduce_particles({.c = c,
                                                  .speed = U,
                                                  .box = box,
                                                  .forces = f,
                                                  .stresses = st,
                                                  .cg = cg,
                                                  .window = win,
                                                  .plate = nullptr,
                                                  .servo = servo,
                                                  .blocks = 5,
                                                  .grains = 2,
                                                  .solids_volume = 2 * 4.0 / 3.0 * std::numbers::pi * 1e-3,
                                                  .simulated_s = 0.4});
    const auto& o = r.outputs;
    BOOST_TEST(o.at("normal_stress_bottom").value == 100.0);
    BOOST_TEST(*o.at("normal_stress_bottom").stderr_ == 0.0);
    BOOST_TEST(o.at("normal_stress_bottom").unit == "Pa");
    BOOST_TEST(o.at("normal_stress_top").value == 90.0);
    BOOST_TEST(o.at("shear_stress_top").value == 20.0);
    BOOST_TEST(o.at("shear_stress_side").value == 2.0);
    // the side walls, pushed down by 3 + 2 N, hold the grains up by 5 N over the floor area L W = 1 m^2
    BOOST_TEST(o.at("side_wall_support").value == 5.0);
    // 35 steady rows of 10 +- 1 alternating, 5 blocks of 7: block means 10 + 1/7, 10 - 1/7, ...
    // mean 10 + 1/35, standard error sqrt(6) / 35
    const double tol = 1e-12;
    BOOST_TEST(std::abs(o.at("shear_stress_bottom").value - (10.0 + 1.0 / 35)) < tol);
    BOOST_TEST(std::abs(*o.at("shear_stress_bottom").stderr_ - std::sqrt(6.0) / 35) < tol);
    // slips from the slabs next to the walls, only the snapshots from t = 0.05 s on
    BOOST_TEST(std::abs(o.at("slip_bottom").value - U * 0.2) < tol);
    BOOST_TEST(std::abs(o.at("slip_top").value - U * 0.1) < tol);
    BOOST_TEST(o.at("slip_top").unit == "m/s");
    const double grain = 4.0 / 3.0 * std::numbers::pi * 1e-3;
    BOOST_TEST(std::abs(o.at("mean_solid_fraction").value - grain / 0.5) < tol);
    BOOST_TEST(o.at("max_solid_fraction").value == 0.64);
    BOOST_TEST(!o.contains("gap"));
    BOOST_TEST(r.run.at("wall_samples").get<std::size_t>() == kRows);
    BOOST_TEST(r.run.at("wall_samples_used").get<std::size_t>() == kRows - kTransient);
    BOOST_TEST(r.run.at("snapshots").get<std::size_t>() == 10u);
    BOOST_TEST(r.run.at("snapshots_used").get<std::size_t>() == 6u);
    BOOST_TEST((read_regime(r.run).status == RegimeStatus::Steady));
    const std::string line = "P_bot=100 P_top=90 tau_bot=10.03 tau_top=20 Pa slip=0.200/0.100 U (steady from 0.05 s)";
    BOOST_TEST(r.line.find(line) != std::string::npos, r.line);
    BOOST_TEST(r.profile.column("u_over_U").size() == 2u);
}
