// The whole ring's walls as ASCII STL meshes (geometry = annulus; ring_deck.h): the floor and
// the top as flat annuli, the side walls as cylinders, each circle cut into `facets` chords. The
// chords lie inside their circle by at most r (1 - cos(pi / facets)) (Settings::wall_sag).
#pragma once
#include <cstddef>
#include <filesystem>

#include "granlub/particles/annulus.h"

namespace granlub::dem {

// Writes kRingMeshes into dir (atomically each): floor at y = 0, top at y = top, the cylinders
// from y = 0 to y = height.
void write_ring_meshes(const std::filesystem::path& dir, const Annulus& a, double top, double height,
                       std::size_t facets);

}  // namespace granlub::dem
