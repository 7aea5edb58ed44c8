// The eight lattice directions of the CA (docs/automaton-model.md §2.2), numbered k = 0..7 counter-clockwise
// from +x (E). JH06's "1-direction" is +x, the direction of the moving bottom wall; we assume the
// paper's Fig. 4 numbers them the same way (paper number = k + 1) [ASSUMPTION].
#pragma once
#include <array>
#include <cstdint>

namespace granlub::automaton {

enum Dir : std::uint8_t { E = 0, NE = 1, N = 2, NW = 3, W = 4, SW = 5, S = 6, SE = 7 };

inline constexpr std::array<int, 8> kDx = {+1, +1, 0, -1, -1, -1, 0, +1};
inline constexpr std::array<int, 8> kDy = {0, +1, +1, +1, 0, -1, -1, -1};

// Specular reflection at a horizontal wall: (dx, dy) -> (dx, -dy)  [RECON, §3.3].
inline constexpr std::array<std::uint8_t, 8> kReflect = {E, SE, S, SW, W, NW, N, NE};
// The drag notch at the moving wall: turn 45 degrees toward +x, never past NE  [ASSUMPTION, §3.3].
// Only used on reflected (upward) directions: NW -> N, N -> NE, NE -> NE.
inline constexpr std::array<std::uint8_t, 8> kDrag = {E, NE, NE, N, W, SW, S, SE};

constexpr std::uint8_t rotate(int d, int by) { return static_cast<std::uint8_t>((d + by) & 7); }

// Direction of a king move (dx, dy) in {-1,0,1}^2 \ {(0,0)}; index (dx+1) + 3 (dy+1).
inline constexpr std::array<std::uint8_t, 9> kFromStep = {SW, S, SE, W, 0xff, E, NW, N, NE};
constexpr std::uint8_t from_step(int dx, int dy) { return kFromStep[(dx + 1) + 3 * (dy + 1)]; }

const char* dir_name(int d);

}  // namespace granlub::automaton
