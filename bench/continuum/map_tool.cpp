// The continuum's (U, P) map of a case, and its cost: `build/bench/continuum_map CASE [SPEEDS LOADS]`
// writes CASE/results/continuum/map.csv (format: continuum/include/granlub/continuum/map.h) over
// U = 0.4-2.8 m/s x P = 1-8 kPa (default 100 x 100) and prints the wall and CPU time per point.
// Issue target: a 100 x 100 grid in < 1 min on one core. Reported, never asserted.
#include <ctime>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "granlub/case/case.h"
#include "full_schema.h"
#include "granlub/continuum/map.h"
#include "granlub/error.h"

using namespace granlub;

int main(int argc, char** argv) {
    if (argc != 2 && argc != 4) {
        std::fprintf(stderr, "usage: continuum_map CASE [SPEEDS LOADS]\n");
        return 2;
    }
    try {
        const Case c = load_case(argv[1], cli::full_schema());
        continuum::MapGrid g;
        if (argc == 4) {
            g.speeds = std::stoi(argv[2]);
            g.loads = std::stoi(argv[3]);
        }
        continuum::MapStats st;
        const std::clock_t c0 = std::clock();
        const auto path = continuum::write_continuum_map(c, g, c.dir / "results", &st);
        const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
        fmt::print("{}: {} points ({} failed, {} ordered) in {:.2f} s wall, {:.2f} s CPU: {:.3f} ms CPU per point\n",
                   path.string(), st.points, st.failed, st.ordered, st.seconds, cpu, 1e3 * cpu / double(st.points));
        return 0;
    } catch (const CaseError& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 2;
    } catch (const Error& e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
