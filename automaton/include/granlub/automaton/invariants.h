// The invariants of docs/automaton-model.md §3.5 that hold at any time, checked from outside the
// engine through its accessors: the wall rows intact, every grain's cell holding its index, no cell
// holding two grains, N grains on the grid, and 0 <= u_p <= U. Tests run it after every step; the
// ensemble after a debug run. "" when all hold, else what failed.
#pragma once
#include <cstddef>
#include <string>

#include "granlub/automaton/engine.h"

namespace granlub::automaton {

template <class Rng>
std::string check_invariants(const Engine<Rng>& e) {
    const int L = e.columns(), H = e.rows();
    const std::size_t n = e.size();
    std::size_t found = 0;
    for (int yy = -1; yy <= H; ++yy)
        for (int xx = 0; xx < L; ++xx) {
            const std::int32_t c = e.cell(xx, yy);
            if (yy == -1 && c != kWallBottom) return "bottom wall row damaged";
            if (yy == H && c != kWallTop) return "top wall row damaged";
            if (yy < 0 || yy >= H) continue;
            if (c >= 0) {
                ++found;
                if (static_cast<std::size_t>(c) >= n || e.x(c) != xx || e.y(c) != yy)
                    return "cell (" + std::to_string(xx) + "," + std::to_string(yy) + ") holds grain " +
                           std::to_string(c) + " which is elsewhere";
            } else if (c != kEmpty) {
                return "wall sentinel inside the particle rows";
            }
        }
    if (found != n) return "grain count on the grid " + std::to_string(found) + " != " + std::to_string(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double u = e.up(static_cast<int>(i));
        if (!(u >= 0.0 && u <= 1.0)) return "u_p of grain " + std::to_string(i) + " outside [0, U]";
    }
    return "";
}

}  // namespace granlub::automaton
