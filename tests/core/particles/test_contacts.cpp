// Contacts (coordination number, persistence, periodic images) and the flow-regime verdict on
// hand-made configurations with known answers.
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <vector>

#include "granlub/particles/contacts.h"
#include "granlub/statistics/flow_regime.h"

using namespace granlub;

namespace {

// n^3 sites of a simple cubic lattice of spacing a filling a periodic box in x and z.
ParticleSet cubic(int n, double a, double r) {
    ParticleSet p;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                p.push_back((i + 0.5) * a, (j + 0.5) * a, -0.5 * n * a + (k + 0.5) * a, 0, 0, 0, r);
    return p;
}

// FCC: 4 sites per cubic cell of side a, nearest neighbours at a / sqrt(2).
ParticleSet fcc(int n, double a, double r) {
    ParticleSet p;
    const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                for (const auto& b : basis)
                    p.push_back((i + b[0]) * a, (j + b[1] + 0.25) * a, -0.5 * n * a + (k + b[2]) * a, 0, 0, 0, r);
    return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(lattices_have_their_coordination_numbers) {
    const double d = 1e-3;
    // simple cubic, touching, periodic in x and z, walls in y: 6 inside, 5 on the two y faces
    const int n = 6;
    const ParticleSet sc = cubic(n, d, 0.5 * d);
    const ParticleBox box{n * d, n * d, n * d, true};
    const double expect = (6.0 * (n - 2) + 5.0 * 2) / n;
    BOOST_TEST(std::abs(coordination_number(touching_pairs(sc, box), sc.size()) - expect) < 1e-12);
    // FCC, touching: 12 inside; periodic in x and z so only y faces lose neighbours
    const double a = d * std::sqrt(2.0);
    const ParticleSet f = fcc(4, a, 0.5 * d);
    const ParticleBox fbox{4 * a, 4 * a, 4 * a, true};
    // per (y) layer of sites: layers at y = 0.25a (bottom) and 0.75a ... each site has 4 in-layer and 4+4 in the
    // layers above and below; the bottom and top layers miss 4 each
    const double layers = 8;
    BOOST_TEST(std::abs(coordination_number(touching_pairs(f, fbox), f.size()) - (12.0 - 2 * 4.0 / layers)) < 1e-12);
    // grains 2 % of a diameter apart are not touching (tolerance 1 %); 0.5 % apart they are
    BOOST_TEST(touching_pairs(cubic(n, 1.02 * d, 0.5 * d), ParticleBox{n * 1.02 * d, n * d, n * 1.02 * d, true})
                   .empty());
    BOOST_TEST(coordination_number(touching_pairs(cubic(n, 1.005 * d, 0.5 * d),
                                                  ParticleBox{n * 1.005 * d, n * d, n * 1.005 * d, true}),
                                   n * n * n) == expect);
}

BOOST_AUTO_TEST_CASE(a_periodic_image_pair_counts) {
    const double d = 1e-3, L = 10 * d, W = 10 * d;
    ParticleSet p;
    p.push_back(0.2 * d, 5 * d, 0, 0, 0, 0, 0.5 * d);
    p.push_back(L - 0.8 * d, 5 * d, 0, 0, 0, 0, 0.5 * d);  // 1 d away through x = 0
    BOOST_TEST(touching_pairs(p, ParticleBox{L, L, W, true}).size() == 1u);
    ParticleSet q;
    q.push_back(3 * d, 5 * d, -0.5 * W + 0.3 * d, 0, 0, 0, 0.5 * d);
    q.push_back(3 * d, 5 * d, 0.5 * W - 0.7 * d, 0, 0, 0, 0.5 * d);  // 1 d away through z = +-W/2
    BOOST_TEST(touching_pairs(q, ParticleBox{L, L, W, true}).size() == 1u);
    BOOST_TEST(touching_pairs(q, ParticleBox{L, L, W, false}).empty());  // side walls: no image
}

BOOST_AUTO_TEST_CASE(overlaps_measure_interpenetration_through_periodic_images) {
    const double d = 1e-3, L = 10 * d, W = 10 * d;
    ParticleSet p;
    p.push_back(0.2 * d, 5 * d, 0, 0, 0, 0, 0.5 * d);
    p.push_back(L - 0.7 * d, 5 * d, 0, 0, 0, 0, 0.5 * d);  // 0.9 d apart through x = 0: overlap 0.1 d
    p.push_back(5 * d, 5 * d, 0, 0, 0, 0, 0.5 * d);
    p.push_back(5 * d, 5.97 * d, 0, 0, 0, 0, 0.5 * d);  // 0.97 d apart: overlap 0.03 d
    p.push_back(5 * d, 7.0 * d, 0, 0, 0, 0, 0.5 * d);   // 1.03 d from the one below: touching, not overlapping
    const ParticleBox box{L, L, W, true};
    const ContactList pairs = touching_pairs(p, box, 0.05);
    BOOST_TEST_REQUIRE(pairs.size() == 3u);
    const OverlapStats o = overlaps(p, box, pairs);
    BOOST_TEST(o.overlapping == 2u);
    BOOST_TEST(std::abs(o.max - 0.1) < 1e-12);
    BOOST_TEST(std::abs(o.mean - 0.065) < 1e-12);
    BOOST_TEST(overlaps(p, box, {}).max == 0.0);
}

BOOST_AUTO_TEST_CASE(persistence_counts_the_pairs_that_stay) {
    const ContactList before = {{0, 1}, {0, 2}, {1, 3}, {2, 3}};
    const ContactList after = {{0, 1}, {1, 2}, {2, 3}, {4, 5}};
    BOOST_TEST(*contact_persistence(before, after) == 0.5);
    BOOST_TEST(*contact_persistence(before, before) == 1.0);
    BOOST_TEST(*contact_persistence(before, {}) == 0.0);
    BOOST_TEST(!contact_persistence({}, after));
    BOOST_TEST(coordination_number(before, 4) == 2.0);
}

BOOST_AUTO_TEST_CASE(inertial_number_and_regime) {
    // I = gamma_dot d / sqrt(P / rho): 100/s, 1 mm, 2500 Pa, 2500 kg/m^3 -> 0.1 / 1 = 0.1
    BOOST_TEST(std::abs(*inertial_number(-100.0, 1e-3, 2500.0, 2500.0) - 0.1) < 1e-15);
    BOOST_TEST(!inertial_number(100.0, 1e-3, 0.0, 2500.0));
    BOOST_TEST(to_string(flow_regime(0.5)) == "collisional");
    BOOST_TEST(to_string(flow_regime(0.01)) == "dense-inertial");
    BOOST_TEST(to_string(flow_regime(1e-4)) == "quasi-static");
    BOOST_TEST(enduring_contacts(4.5, 0.8));
    BOOST_TEST(!enduring_contacts(3.0, 0.8));
    BOOST_TEST(!enduring_contacts(4.5, 0.1));
    BOOST_TEST(!enduring_contacts(std::nullopt, 0.9));
    const auto j = flow_regime_json({0.3, 0.05, 5.0, 0.9});
    BOOST_TEST(j.at("regime") == "dense-inertial");  // the mid-gap number wins over U/H
    BOOST_TEST(j.at("enduring_contacts") == true);
    BOOST_TEST(flow_regime_json({std::nullopt, std::nullopt, 1.0, 0.1}).at("regime").is_null());
}

BOOST_AUTO_TEST_CASE(mid_gap_shear_rate_is_the_central_slope) {
    // u = 3 - 100 y, except near the walls (slip layers) which must not count
    std::vector<double> y, u;
    for (int k = 0; k < 10; ++k) {
        y.push_back((k + 0.5) * 1e-3);
        u.push_back(3.0 - 100.0 * y.back() + (k == 0 || k == 9 ? 0.5 : 0.0));
    }
    BOOST_TEST(std::abs(mid_gap_shear_rate(y, u, 10e-3) - 100.0) < 1e-9);
    // two stations: their slope
    BOOST_TEST(std::abs(mid_gap_shear_rate(std::vector<double>{1e-3, 3e-3}, std::vector<double>{2.0, 1.0}, 4e-3) -
                        500.0) < 1e-9);
}
