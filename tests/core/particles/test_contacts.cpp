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

BOOST_AUTO_TEST_CASE(inertial_number_and_its_class_at_each_boundary) {
    // I = gamma_dot d / sqrt(P / rho): 100/s, 1 mm, 2500 Pa, 2500 kg/m^3 -> 0.1 / 1 = 0.1
    BOOST_TEST(std::abs(*inertial_number(-100.0, 1e-3, 2500.0, 2500.0) - 0.1) < 1e-15);
    BOOST_TEST(!inertial_number(100.0, 1e-3, 0.0, 2500.0));
    // GDR MiDi 2004 / da Cruz et al. 2005: quasi-static < 1e-3 <= dense-inertial <= 0.1 < rapid
    const double lo = kQuasiStaticMaxInertialNumber, hi = kRapidMinInertialNumber;
    BOOST_TEST(to_string(inertial_class(std::nextafter(lo, 0.0))) == "quasi-static");
    BOOST_TEST(to_string(inertial_class(lo)) == "dense-inertial");
    BOOST_TEST(to_string(inertial_class(hi)) == "dense-inertial");
    BOOST_TEST(to_string(inertial_class(std::nextafter(hi, 1.0))) == "rapid");
    BOOST_TEST(to_string(inertial_class(0.0)) == "quasi-static");
}

BOOST_AUTO_TEST_CASE(one_verdict_at_each_boundary_with_the_criterion_that_decided) {
    const double z = kEnduringMinCoordination, p = kEnduringMinPersistence;
    const double z_below = std::nextafter(z, 0.0), p_below = std::nextafter(p, 0.0);
    // both thresholds met exactly: a contact network
    Verdict v = lubrication_verdict(z, p);
    BOOST_TEST((v.lubrication == Lubrication::Contact));
    BOOST_TEST(v.criterion.find(">= 4") != std::string::npos);
    BOOST_TEST(v.criterion.find("50 %") != std::string::npos);
    // Z just below: collisions, whatever the persistence; Z named as the criterion
    v = lubrication_verdict(z_below, 1.0);
    BOOST_TEST((v.lubrication == Lubrication::Collision));
    BOOST_TEST(v.criterion.find("< 4") != std::string::npos);
    BOOST_TEST((lubrication_verdict(z_below, std::nullopt).lubrication == Lubrication::Collision));
    // persistence just below: collisions; the persistence named
    v = lubrication_verdict(z, p_below);
    BOOST_TEST((v.lubrication == Lubrication::Collision));
    BOOST_TEST(v.criterion.find("persist <") != std::string::npos);
    // what would decide was not measured: undetermined, and said which
    v = lubrication_verdict(std::nullopt, 0.9);
    BOOST_TEST((v.lubrication == Lubrication::Undetermined));
    BOOST_TEST(v.criterion.find("not measured") != std::string::npos);
    v = lubrication_verdict(5.0, std::nullopt);
    BOOST_TEST((v.lubrication == Lubrication::Undetermined));
    BOOST_TEST(v.criterion.find("persistence was not measured") != std::string::npos);
    BOOST_TEST(enduring_contacts(z, p));
    BOOST_TEST(!enduring_contacts(z_below, p));
    BOOST_TEST(!enduring_contacts(z, p_below));
    BOOST_TEST(!enduring_contacts(std::nullopt, 0.9));
}

BOOST_AUTO_TEST_CASE(the_record_never_contradicts_itself) {
    // the point: I above 0.1 with an enduring network. Before, "collisional, enduring contacts".
    const auto j = flow_regime_json({0.4, 0.3, 4.6, 0.9});
    BOOST_TEST(j.at("regime") == "contact lubrication");
    BOOST_TEST(j.at("inertial_class") == "rapid");  // the mid-gap number wins over U/H
    BOOST_TEST(j.at("enduring_contacts") == true);
    BOOST_TEST(j.at("verdict_version") == 2);
    const std::string reason = j.at("reason");
    BOOST_TEST(reason.find("collisional") == std::string::npos);
    BOOST_TEST(reason.find("contact lubrication: Z = 4.6 >= 4") == 0u);
    // the label a report prints: the verdict, the class beside it
    const FlowVerdict fv = read_flow_verdict(j);
    BOOST_TEST(fv.label() == "contact lubrication (I rapid)");
    BOOST_TEST(fv.criterion == j.at("criterion").get<std::string>());
    BOOST_TEST(*fv.inertial_mid_gap == 0.3);
    // a network that does not endure: collision lubrication, whatever I
    BOOST_TEST(flow_regime_json({1e-4, 1e-4, 4.6, 0.2}).at("regime") == "collision lubrication");
    // no pressure: no inertial class, the verdict still from the contacts
    const auto none = flow_regime_json({std::nullopt, std::nullopt, 1.0, 0.1});
    BOOST_TEST(none.at("inertial_class").is_null());
    BOOST_TEST(none.at("regime") == "collision lubrication");
}

BOOST_AUTO_TEST_CASE(older_records_are_read_with_todays_thresholds) {
    // a summary written before verdict_version 2: "regime" was the inertial class
    const nlohmann::json old = {{"regime", "collisional"},          {"enduring_contacts", true},
                                {"coordination_number", 4.57},      {"contact_persistence", 0.9},
                                {"inertial_number_nominal", 0.39},  {"inertial_number_mid_gap", 0.079}};
    const FlowVerdict v = read_flow_verdict(old);
    BOOST_TEST((v.lubrication == Lubrication::Contact));
    BOOST_TEST(v.inertial_class == "rapid");
    BOOST_TEST(v.criterion.find("recomputed from an older record") != std::string::npos);
    BOOST_TEST(*v.inertial_nominal == 0.39);
    // YADE's: no persistence
    BOOST_TEST((read_flow_verdict({{"regime", "dense-inertial"}, {"coordination_number", 5.0},
                                   {"contact_persistence", nullptr}})
                    .lubrication == Lubrication::Undetermined));
    BOOST_TEST((read_flow_verdict(nlohmann::json()).lubrication == Lubrication::Undetermined));
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

// The core's coordination number (cases/bulk_shear): a simple cubic packing of 4 touching layers,
// periodic in x and z, has 6 contacts per grain in its two inner layers and 5 in the outer ones.
BOOST_AUTO_TEST_CASE(a_band_counts_the_contacts_of_its_grains_only) {
    const double d = 1e-3;
    const int n = 4;
    const ParticleSet p = cubic(n, d, 0.5 * d);
    const ParticleBox box{n * d, n * d, n * d, true};
    const ContactList pairs = touching_pairs(p, box);
    BOOST_TEST(coordination_number(pairs, p.size()) == 5.5, boost::test_tools::tolerance(1e-12));
    const auto inner = band_coordination(p, pairs, Band{1.0 * d, 3.0 * d});  // layers at 1.5 d and 2.5 d
    BOOST_REQUIRE(inner.has_value());
    BOOST_TEST(*inner == 6.0, boost::test_tools::tolerance(1e-12));
    const auto floor = band_coordination(p, pairs, Band{0.0, 1.0 * d});  // the first layer: no grain below it
    BOOST_TEST(*floor == 5.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(!band_coordination(p, pairs, Band{5.0 * d, 6.0 * d}).has_value());  // no grain in it
    // the series keeps the band's Z per snapshot beside every grain's
    ContactSeries s(box, 0.0, Band{1.0 * d, 3.0 * d});
    s.add(p, 0.0);
    s.add(p, 1.0);
    BOOST_TEST(s.core_coordination().size() == 2u);
    BOOST_TEST(s.core_coordination()[1] == 6.0, boost::test_tools::tolerance(1e-12));
    BOOST_TEST(s.coordination()[1] == 5.5, boost::test_tools::tolerance(1e-12));
}
