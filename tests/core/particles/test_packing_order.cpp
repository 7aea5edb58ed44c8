// The packing's order measures (packing_order.h) against the values of ideal structures
// (Steinhardt, Nelson & Ronchetti 1983, table I; Lechner & Dellago 2008, J. Chem. Phys. 129:114707,
// table I): q6 = 0.575 (FCC), 0.485 (HCP), 0.354 (simple cubic); and the layering of profiles
// made by hand.
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <boost/test/unit_test.hpp>

#include "granlub/particles/packing_order.h"

using namespace granlub;
namespace tt = boost::test_tools;
using Bonds = std::vector<std::array<double, 3>>;

namespace {

Bonds fcc_shell() {  // the 12 nearest neighbours of FCC: (+-1, +-1, 0) and permutations
    Bonds b;
    for (int s1 : {-1, 1})
        for (int s2 : {-1, 1}) {
            b.push_back({double(s1), double(s2), 0});
            b.push_back({double(s1), 0, double(s2)});
            b.push_back({0, double(s1), double(s2)});
        }
    return b;
}

Bonds hcp_shell() {  // 6 in the basal plane, 3 above and 3 below, rotated by 60 degrees to each other
    Bonds b;
    const double pi = 3.141592653589793, h = std::sqrt(2.0 / 3.0), r = 1.0 / std::sqrt(3.0);
    for (int k = 0; k < 6; ++k) b.push_back({std::cos(k * pi / 3), std::sin(k * pi / 3), 0});
    for (int k = 0; k < 3; ++k) {
        b.push_back({r * std::cos(pi / 6 + k * 2 * pi / 3), r * std::sin(pi / 6 + k * 2 * pi / 3), h});
        b.push_back({r * std::cos(pi / 6 + k * 2 * pi / 3), r * std::sin(pi / 6 + k * 2 * pi / 3), -h});
    }
    return b;
}

Profile profile(const std::vector<double>& nu) {
    Profile p;
    std::vector<double> y(nu.size());
    for (std::size_t k = 0; k < nu.size(); ++k) y[k] = (static_cast<double>(k) + 0.5) / static_cast<double>(nu.size());
    p.add("y_over_H", y);
    p.add("solid_fraction", nu);
    return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(q6_of_ideal_neighbour_shells) {
    BOOST_TEST(local_q6(fcc_shell()) == 0.57452, tt::tolerance(1e-4));
    BOOST_TEST(local_q6(hcp_shell()) == 0.48476, tt::tolerance(1e-4));
    BOOST_TEST(local_q6({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}) == 0.35355,
               tt::tolerance(1e-4));
    BOOST_TEST(local_q6({{0.3, -0.2, 0.9}}) == 1.0, tt::tolerance(1e-12));  // one bond: why few bonds are skipped
    // rotation invariant: the FCC shell turned about an arbitrary axis
    Bonds turned;
    const double c = std::cos(0.7), s = std::sin(0.7);
    for (const auto& b : fcc_shell()) turned.push_back({c * b[0] - s * b[1], s * b[0] + c * b[1], b[2]});
    BOOST_TEST(local_q6(turned) == local_q6(fcc_shell()), tt::tolerance(1e-9));
}

BOOST_AUTO_TEST_CASE(a_crystal_is_ordered_and_a_gas_is_not) {
    // an FCC crystal of touching grains (d = 1), periodic in x and z, 8 cubic cells deep in y
    const double d = 1.0, a = d * std::sqrt(2.0);
    const int nc = 6, ny = 8;
    ParticleBox box{.length = nc * a, .gap = ny * a, .width = nc * a, .periodic_z = true};
    ParticleSet crystal;
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    for (int i = 0; i < nc; ++i)
        for (int j = 0; j < ny; ++j)
            for (int k = 0; k < nc; ++k)
                for (const auto& b : basis)
                    crystal.push_back((i + b[0]) * a, (j + b[1]) * a + 0.5, (k + b[2]) * a - 0.5 * box.width, 0, 0, 0,
                                      0.5 * d);
    const BondOrder o = bond_order(crystal, box);
    BOOST_TEST(o.Q6 == 0.57452, tt::tolerance(0.02));  // every bond of an FCC direction
    BOOST_TEST(o.q6 > 0.50);                           // the bulk 0.575; the two free faces lower it
    BOOST_TEST(o.neighbours > 11.0);
    // an ideal gas of as many grains (overlaps allowed: positions at random)
    std::mt19937_64 g(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    ParticleSet gas;
    for (std::size_t n = 0; n < crystal.size(); ++n)
        gas.push_back(u(g) * box.length, u(g) * box.gap, (u(g) - 0.5) * box.width, 0, 0, 0, 0.5 * d);
    BOOST_TEST(bond_order(gas, box).Q6 < 0.2);
    // layers: the crystal's (001) planes are a/2 = 0.707 d apart along y, away from its two faces
    const LayerOrder layers = layer_order(crystal, 1.0, box.gap - 1.0, d);
    BOOST_TEST(layers.order == 1.0, tt::tolerance(0.01));
    BOOST_TEST(layers.spacing == 0.5 * a, tt::tolerance(0.01));
    BOOST_TEST(layer_order(gas, 1.0, box.gap - 1.0, d).order < 0.15);  // ~1/sqrt(N): 0.03 for N = 1300
    BOOST_TEST(layer_order(gas, 100.0, 200.0, d).grains == 0u);        // none in range: nothing measured
}

BOOST_AUTO_TEST_CASE(layering_of_hand_made_profiles) {
    // 20 stations over H = 5 d: the stations 0.5 d from the walls are 2 .. 17
    std::vector<double> layered(20), flat(20, 0.6);
    for (std::size_t k = 0; k < 20; ++k) layered[k] = k % 4 < 2 ? 0.9 : 0.3;  // dense layers, sparse gaps
    const double H = 5.0, d = 1.0;
    BOOST_TEST(*layering_amplitude(profile(layered), H, d) == 0.5, tt::tolerance(1e-12));  // std 0.3 / mean 0.6
    BOOST_TEST(*layering_amplitude(profile(flat), H, d) == 0.0, tt::tolerance(1e-12));
    flat.front() = flat.back() = 0.05;  // the walls' own depletion is left out
    BOOST_TEST(*layering_amplitude(profile(flat), H, d) == 0.0, tt::tolerance(1e-12));
    BOOST_TEST(!layering_amplitude(profile(flat), 1.0, d));  // a gap of one grain: nothing to measure
}
