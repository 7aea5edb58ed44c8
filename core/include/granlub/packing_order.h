// How ordered a particle packing is: the two measures every particle summary carries (run.order,
// outputs "q6" and "layering"), shared by both engines through the particle pipeline.
//
// Bond-orientational order q6 (Steinhardt, Nelson & Ronchetti 1983, Phys. Rev. B 28:784, eqs. 1-3):
// for grain i with N_i neighbours j,
//   q6m(i) = (1/N_i) sum_j Y6m(r_ij / |r_ij|),   q6(i) = sqrt(4 pi / 13 sum_{m=-6..6} |q6m(i)|^2),
// averaged over the grains with at least kOrderMinNeighbours neighbours; and the global
//   Q6 = sqrt(4 pi / 13 sum_m |<Y6m>|^2), the mean over every bond of the snapshot.
// Ideal FCC gives q6 = Q6 = 0.575, HCP 0.485, a dense liquid q6 of about 0.35-0.45 and Q6 near 0
// (its bonds point every way). Neighbours: centres closer than kOrderNeighbourCutoff (r_i + r_j),
// our choice [ASSUMPTION], between FCC's first shell (1.0) and its second (sqrt 2).
//
// Layer order: how sharply the grain centres stack in layers parallel to the walls, the height of
// the one-dimensional structure factor's peak,
//   Lambda = max over lambda in [kLayerSpacingMin, kLayerSpacingMax] d of |<exp(2 pi i y_j / lambda)>|,
// over the grains at least one mean diameter clear of both walls (of a rough wall's bumps): 1 for
// grains in flat layers lambda apart, about 1/sqrt(N) without layers. Our measure [ASSUMPTION], the
// translational order parameter of confined layered fluids; unlike the profile below it does not
// smear each grain over its diameter, so it tells sharp crystal layers from the looser layering
// any wall imposes.
//
// Layering: the relative amplitude of the solid-fraction profile across the gap, std(nu_k) / mean(nu_k)
// over the stations whose centres are at least half a mean diameter from both walls (where a wall
// alone shapes nu). Our measure [ASSUMPTION]: grains ordered in layers give a large value
// (alternating dense layers and sparse gaps between them), a disordered bed a small one; it needs
// stations finer than the layer spacing (about 0.8 d), which the default 20 across 5 d are.
#pragma once
#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "granlub/particles.h"
#include "granlub/results.h"

namespace granlub {

inline constexpr double kOrderNeighbourCutoff = 1.2;  // centre distance / (r_i + r_j)
inline constexpr std::size_t kOrderMinNeighbours = 4;  // fewer bonds make q6 meaningless (one bond gives 1)
inline constexpr double kLayerSpacingMin = 0.6, kLayerSpacingMax = 1.0;  // in mean diameters; FCC (111): 0.816

struct BondOrder {
    double q6 = 0;               // mean local q6 over the grains counted
    double Q6 = 0;               // global
    std::size_t grains = 0;      // with at least kOrderMinNeighbours neighbours
    double neighbours = 0;       // mean neighbours per grain (all grains)
};
// q6 of one grain from its bond vectors (any length; the direction counts); 0 for no bond.
double local_q6(const std::vector<std::array<double, 3>>& bonds);

// The order of one snapshot; periodic images as contacts.h (x always, z when box.periodic_z).
BondOrder bond_order(const ParticleSet& p, const ParticleBox& box);

struct LayerOrder {
    double order = 0;    // Lambda
    double spacing = 0;  // the lambda of the peak, m
    std::size_t grains = 0;
};
// Lambda of the grains with centres in [lo, hi] (mean diameter d); nothing counted: order 0.
LayerOrder layer_order(const ParticleSet& p, double lo, double hi, double d);

// q6, Q6 and Lambda (grains in [lo, hi]) of each snapshot from t_start on, collected as the
// snapshots are read.
class OrderSeries {
public:
    OrderSeries(const ParticleBox& box, double t_start, double lo, double hi, double d)
        : box_(box), t_start_(t_start), lo_(lo), hi_(hi), d_(d) {}
    void add(const ParticleSet& p, double time);
    const std::vector<double>& q6() const { return q6_; }
    const std::vector<double>& Q6() const { return Q6_; }
    const std::vector<double>& layer_order() const { return layer_; }
    double mean_neighbours() const;
    double mean_layer_spacing() const;

private:
    ParticleBox box_;
    double t_start_, lo_, hi_, d_;
    std::vector<double> q6_, Q6_, neighbours_, layer_, spacing_;
};

// std / mean of the profile's solid_fraction over the stations at least d/2 from both walls
// (y_over_H times `gap` gives y); nothing when fewer than 3 stations qualify or the mean is 0.
std::optional<double> layering_amplitude(const Profile& profile, double gap, double diameter);

}  // namespace granlub
