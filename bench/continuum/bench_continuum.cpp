// Throughput of the continuum solver (issue targets: < 2 ms per point, < 0.5 s per 100-point
// sweep on one core; extended kinetic theory with the gap unknown: <= 5 ms per point; the 100 x 100
// map of a case: build/bench/continuum_map). Reported, never asserted. The Time/CPU columns are per point, or per
// 100-point sweep for BM_sweep_100 (items_per_second = points per second).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "granlub/continuum/cross_section_solver.h"
#include "granlub/continuum/fv_solver.h"
#include "granlub/continuum/shooting_solver.h"
#include "granlub/continuum/walls/flat_wall.h"
#include "granlub/continuum/walls/flat_wall_impacts.h"

using namespace granlub::continuum;

namespace {

Problem sawyer(double U, double P, Mode mode = Mode::Load, const char* wall = "kinetic") {
    Problem p;
    p.closures = std::make_shared<Closures>(ClosureParams{0.9, 1.0, true},
                                            std::shared_ptr<const RadialDistribution>(make_g0("ogawa", 0.65)));
    p.Lambda = 4e-3 / 0.787e-3;
    p.Pi = 2550 * U * U / P;
    p.mode = mode;
    p.nu_mean = 0.595;
    WallBC w{make_wall_family(wall), WallParams{0.9, 0.5, 0.5, 0.5, 0.5, 0.0}};
    p.bottom = w;
    p.top = w;
    return p;
}

// One S&T point (U = 2 m/s, P = 5.5 kPa) from the uniform guess; range(0) = cells.
void BM_point_fv_load(benchmark::State& state) {
    const Problem p = sawyer(2.0, 5.5e3);
    SolverSettings st;
    st.cells = static_cast<int>(state.range(0));
    int its = 0;  // Newton iterations of the last solve
    for (auto _ : state) {
        Solution s = solve_fv(p, st);
        its = s.iterations;
        benchmark::DoNotOptimize(s.nu.data());
    }
    state.counters["newton_iterations"] = its;
}
BENCHMARK(BM_point_fv_load)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond);

// The same point between plane walls whose impacts stick and slide (walls/flat_wall_impacts.h: family K's stick limit
// times h(xi), g(xi) from the law's table), and the table's construction, once per wall law.
void BM_point_fv_sliding_walls(benchmark::State& state) {
    Problem p = sawyer(2.0, 5.5e3);
    const FlatWallFactors f = flat_wall_from_impact_law(0.9, 1.0);
    for (WallBC* w : {&p.bottom, &p.top}) {
        w->params = WallParams{0.9, f.r5, f.r6, f.r7, f.r8, f.slip_dissipation, WallEnergy::SlipWork};
        w->params.impacts = flat_wall_impacts(0.9, 0.5, kFlatWallBeta0);
    }
    SolverSettings st;
    int its = 0;
    for (auto _ : state) {
        Solution s = solve_fv(p, st);
        its = s.iterations;
        benchmark::DoNotOptimize(s.nu.data());
    }
    state.counters["newton_iterations"] = its;
}
BENCHMARK(BM_point_fv_sliding_walls)->Unit(benchmark::kMillisecond);

void BM_flat_wall_impacts_table(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(FlatWallImpacts(0.9, 0.5, kFlatWallBeta0).xi_max());
}
BENCHMARK(BM_flat_wall_impacts_table)->Unit(benchmark::kMillisecond);

void BM_point_fv_fill(benchmark::State& state) {
    const Problem p = sawyer(2.0, 5.5e3, Mode::Fill);
    SolverSettings st;
    for (auto _ : state) benchmark::DoNotOptimize(solve_fv(p, st).Pi);
}
BENCHMARK(BM_point_fv_fill)->Unit(benchmark::kMillisecond);

void BM_point_shooting(benchmark::State& state) {
    const Problem p = sawyer(2.0, 5.5e3);
    SolverSettings st;
    for (auto _ : state) benchmark::DoNotOptimize(solve_shooting(p, st).Pi);
}
BENCHMARK(BM_point_shooting)->Unit(benchmark::kMillisecond);

// A rough-case point with extended kinetic theory and the gap solved from the grain inventory
// (cases/sawyer2001_regimes_rough's [continuum] set).
Problem rough_inventory(double U, double P) {
    Problem p = sawyer(U, P);
    ClosureParams cp;
    cp.restitution = 0.9;
    cp.dissipation_restitution = 0.9 - 1.5 * 0.5 * std::exp(-1.5);  // Chialvo & Sundaresan 2013, mu_p = 0.5
    cp.correlation_length = CorrelationLength::JenkinsBerzi;
    cp.correlation_constant = 0.44;
    p.closures = std::make_shared<Closures>(cp, std::shared_ptr<const RadialDistribution>(make_g0("chialvo_sundaresan", 0.587)),
                                            make_closure_family("garzo_dufty"));
    p.mode = Mode::Inventory;
    p.inventory = 0.595 * 4e-3 / 0.787e-3;
    p.Lambda = (4e-3 - 0.787e-3) / 0.787e-3;
    return p;
}

// One of them: U = 1.4 m/s, P = 2250 Pa. Issue target: <= 5 ms.
void BM_point_ekt_inventory(benchmark::State& state) {
    const Problem p = rough_inventory(1.4, 2250);
    SolverSettings st;
    int its = 0;
    for (auto _ : state) {
        Solution s = solve_fv(p, st);
        its = s.iterations;
        benchmark::DoNotOptimize(s.Lambda);
    }
    state.counters["newton_iterations"] = its;
}
BENCHMARK(BM_point_ekt_inventory)->Unit(benchmark::kMillisecond);

// rough_inventory(U, P) with the contact stress (docs/continuum-model.md §2.9) and Johnson & Jackson's constants
// (Fr = 0.05 Pa, n = 2, m = 5, nu_min = 0.5; mu_c = 0.36, illustrative, not fitted; docs/measurements/continuum.md),
// Fr over this point's load as `granlub continuum` divides it (case_setup.cpp, problem_for).
Problem rough_contact(double U, double P) {
    Problem p = rough_inventory(U, P);
    const ContactStress jj{0.05 / P, 0.5, 0.587, 2, 5, 0.36};  // Fr/P_y, nu_min, nu_c (g0's nu_max), n, m, mu_c
    p.closures = std::make_shared<Closures>(p.closures->with_contact(jj));
    return p;
}

// BM_point_ekt_inventory's point with the contact stress on, at a slow dense point and a fast one of the rough
// cases (regimes_rough U0.4_P5550, U2.8_P2250). Issue 73 item 6's target: <= 5 ms.
void BM_point_ekt_contact(benchmark::State& state, double U, double P) {
    const Problem p = rough_contact(U, P);
    SolverSettings st;
    Solution s;
    for (auto _ : state) {
        s = solve_fv(p, st);
        benchmark::DoNotOptimize(s.Lambda);
    }
    state.counters["newton_iterations"] = s.iterations;
    state.counters["continuation_steps"] = s.continuation_steps;
}
BENCHMARK_CAPTURE(BM_point_ekt_contact, U0.4_P5550, 0.4, 5550.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_point_ekt_contact, U2.8_P2250, 2.8, 2250.0)->Unit(benchmark::kMillisecond);

// 100 points: U in [0.5, 3] m/s x P_y in [1, 20] kPa (log-spaced), each solved from scratch
// with N = 200, as `granlub continuum` does.
void BM_sweep_100(benchmark::State& state) {
    SolverSettings st;
    std::vector<Problem> points;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j)
            points.push_back(sawyer(0.5 + 2.5 * i / 9.0, 1e3 * std::pow(20.0, j / 9.0)));
    int continued = 0;
    for (auto _ : state) {
        continued = 0;
        for (const Problem& p : points) {
            Solution s = solve_fv(p, st);
            continued += s.continuation_steps > 0;
            benchmark::DoNotOptimize(s.nu.data());
        }
    }
    state.counters["points_needing_continuation"] = continued;
    state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(points.size()));  // points/s
}
BENCHMARK(BM_sweep_100)->Unit(benchmark::kMillisecond);

}  // namespace

// One point on the trough's cross-section (issue target: <= 2 s on one core on a 40 x 100 grid): S&T's cell at
// U = 2 m/s, P = 5.5 kPa, W = 19 mm, the side walls as the floor; from the 1-D guess, range(0) x range(1) cells.
CrossSectionProblem sawyer_trough() {
    CrossSectionProblem p;
    p.gap = sawyer(2.0, 5.5e3);
    p.outer = p.inner = p.gap.bottom;
    p.width = 19e-3 / 0.787e-3;
    return p;
}

// Solves `p` once per iteration and reports the Newton iterations.
void solve_trough(benchmark::State& state, const CrossSectionProblem& p, const CrossSectionSettings& st) {
    int its = 0;
    for (auto _ : state) {
        const CrossSectionSolution s = solve_cross_section(p, st);
        its = s.iterations;
        benchmark::DoNotOptimize(s.nu.data());
    }
    state.counters["newton_iterations"] = its;
}

void BM_cross_section_point(benchmark::State& state) {
    const CrossSectionProblem p = sawyer_trough();
    CrossSectionSettings st;
    st.cells_y = static_cast<int>(state.range(0));
    st.cells_z = static_cast<int>(state.range(1));
    solve_trough(state, p, st);
}
BENCHMARK(BM_cross_section_point)->Args({40, 100})->Args({80, 200})->Unit(benchmark::kMillisecond);

// The same with the body forces on (gravity, the centripetal force of S&T's annulus): Picard passes on the pressure.
void BM_cross_section_point_body_forces(benchmark::State& state) {
    CrossSectionProblem p = sawyer_trough();
    p.body.gravity = 2550 * 9.81 * 0.787e-3 / 5.5e3;
    p.body.radius = (76.2e-3 + 9.5e-3) / 0.787e-3;
    solve_trough(state, p, CrossSectionSettings{});
}
BENCHMARK(BM_cross_section_point_body_forces)->Unit(benchmark::kMillisecond);

// The same trough with rough_contact's closures (the rough cases' extended kinetic theory and the contact stress
// with Johnson & Jackson's constants) at U = 1.4 m/s, P = 2250 Pa, the gap from the inventory; range(0) x range(1)
// cells; range(2) = 1: with the body forces (gravity, the centripetal force of S&T's annulus; §2.9a).
void BM_cross_section_point_contact(benchmark::State& state) {
    CrossSectionProblem p = sawyer_trough();
    p.gap = rough_contact(1.4, 2250);
    p.outer = p.inner = p.gap.bottom;
    p.gap.inventory = 0.595 * 4e-3 / 0.787e-3;  // grains per length / (d W): the 1-D inventory over the width
    if (state.range(2) == 1) {
        p.body.gravity = 2550 * 9.81 * 0.787e-3 / 2250;
        p.body.radius = (76.2e-3 + 9.5e-3) / 0.787e-3;
    }
    CrossSectionSettings st;
    st.cells_y = static_cast<int>(state.range(0));
    st.cells_z = static_cast<int>(state.range(1));
    int continued = 0;
    for (auto _ : state) {
        const CrossSectionSolution s = solve_cross_section(p, st);
        continued = s.continuation_steps;
        benchmark::DoNotOptimize(s.nu.data());
        state.counters["newton_iterations"] = s.iterations;
    }
    state.counters["continuation_steps"] = continued;
}
BENCHMARK(BM_cross_section_point_contact)->Args({40, 100, 0})->Args({40, 100, 1})->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
