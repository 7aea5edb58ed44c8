// Robustness envelope of the FV solver (not a timing benchmark): solves 7200 points over
// wall family x g0 x e_p x H/d x R x control x (Pi or mean nu) from scratch and counts the
// failures by cause. Takes a few minutes; numbers are quoted in docs/measurements/continuum.md.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "granlub/continuum/fv_solver.h"
#include "granlub/error.h"

using namespace granlub::continuum;

int main() {
    int total = 0, continued = 0;
    std::map<std::string, int> fails;
    double worst_ms = 0;
    for (const char* wall : {"kinetic", "johnson_jackson"})
        for (const char* g0 : {"ogawa", "lun_savage", "carnahan_starling", "ma_ahmadi", "torquato"})
            for (double ep : {0.5, 0.8, 0.95, 0.99})
                for (double lambda : {2.0, 5.0, 10.0, 20.0, 40.0})
                    for (double R : {0.05, 0.5, 1.0})
                        for (int fill = 0; fill < 2; ++fill)
                            for (int k = 0; k < 6; ++k) {
                                Problem p;
                                p.closures = std::make_shared<Closures>(
                                    ClosureParams{ep, 1.0, true}, std::shared_ptr<const RadialDistribution>(make_g0(g0, 0.65)));
                                p.Lambda = lambda;
                                p.Pi = std::pow(10.0, -2.0 + 0.8 * k);  // 0.01 .. 100
                                p.nu_mean = 0.05 + 0.11 * k;           // 0.05 .. 0.60
                                p.mode = fill ? Mode::Fill : Mode::Load;
                                WallBC w{make_wall_family(wall), WallParams{0.9, R, R, R, R, 0.0}};
                                p.bottom = w;
                                p.top = w;
                                ++total;
                                const auto t0 = std::chrono::steady_clock::now();
                                try {
                                    const Solution s = solve_fv(p, SolverSettings{});
                                    continued += s.continuation_steps > 0;
                                } catch (const granlub::SolverError& e) {
                                    const std::string m = e.what();
                                    const std::string cause = m.find("no uniform-shear") != std::string::npos ? "no uniform state (root beyond the cap)"
                                                              : m.find("empty-channel") != std::string::npos  ? "empty-channel branch (mean nu < 0.01)"
                                                                                                              : "Newton/continuation failed";
                                    ++fails[cause + (ep == 0.5 ? ", e_p = 0.5" : ", e_p >= 0.8")];
                                }
                                worst_ms = std::max(worst_ms, std::chrono::duration<double, std::milli>(
                                                                  std::chrono::steady_clock::now() - t0).count());
                            }
    std::printf("points %d, solved %d, needed continuation %d, slowest %.0f ms\n", total,
                total - [&] { int n = 0; for (auto& [k, v] : fails) n += v; return n; }(), continued, worst_ms);
    for (const auto& [cause, n] : fails) std::printf("  failed: %-60s %d\n", cause.c_str(), n);
}
