// The wall layer's kinematics (wall_layer.h) on grains placed by hand: rolling without sliding and
// sliding without spin at the moving floor, the still top's signs, which grains count as touching,
// the bumps of a rough wall as they move with it, and the record's refusals.
#include <cmath>
#include <optional>

#include <boost/test/unit_test.hpp>

#include "granlub/particles/wall_layer.h"

using namespace granlub;
namespace tt = boost::test_tools;

namespace {

constexpr double kU = 2.0, kA = 0.1, kGap = 1.0;  // floor speed m/s, grain radius m, gap m
const ParticleBox kBox{.length = 2.0, .gap = kGap, .width = 1.0, .periodic_z = true};

void add(ParticleSet& p, double x, double y, double z, double vx, double vz, double wx, double wz) {
    p.push_back(x, y, z, vx, 0.0, vz, kA);
    p.wx.push_back(wx), p.wy.push_back(0.0), p.wz.push_back(wz);
}

const WallLayerWall kFloor{.side = WallSide::Bottom, .plane = 0.0, .speed = kU};
const WallLayerWall kTop{.side = WallSide::Top, .plane = kGap, .speed = 0.0};

}  // namespace

BOOST_AUTO_TEST_CASE(grains_rolling_without_sliding_on_the_floor_carry_all_their_slip_back) {
    ParticleSet p;
    for (double lag : {0.2, 0.4}) {  // v_x = (1 - lag) U and g_x = v_x - U + a w_z = 0
        const double vx = (1.0 - lag) * kU;
        add(p, 0.5 + lag, kA, 0.0, vx, 0.0, 0.0, (kU - vx) / kA);
    }
    const WallLayer r = wall_layer(p, kBox, kFloor, kU);
    BOOST_TEST(r.grains == 2u);
    BOOST_TEST(r.contacts == 2u);
    BOOST_TEST(r.slip == 0.3, tt::tolerance(1e-12));
    BOOST_TEST(r.rolling == 0.3, tt::tolerance(1e-12));
    BOOST_TEST(std::abs(r.contact_slip) < 1e-12);
    BOOST_TEST_REQUIRE(r.rolling_share.has_value());
    BOOST_TEST(*r.rolling_share == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(r.rolling_fraction == 1.0);
    BOOST_TEST(r.slip_stderr == 0.1, tt::tolerance(1e-12));  // samples 0.2, 0.4: std 0.1 sqrt(2), over sqrt(2)
}

BOOST_AUTO_TEST_CASE(grains_sliding_without_spin_carry_none_back) {
    ParticleSet p;  // a state without spins: no spin
    p.push_back(0.5, kA, 0.0, 0.7 * kU, 0.0, 0.0, kA);
    p.push_back(1.0, kA, 0.0, 0.7 * kU, 0.0, 0.0, kA);
    const WallLayer r = wall_layer(p, kBox, kFloor, kU);
    BOOST_TEST(r.slip == 0.3, tt::tolerance(1e-12));
    BOOST_TEST(r.rolling == 0.0);
    BOOST_TEST(r.contact_slip == 0.3, tt::tolerance(1e-12));
    BOOST_TEST(std::abs(*r.rolling_share) < 1e-12);
    BOOST_TEST(r.rolling_fraction == 0.0);
}

BOOST_AUTO_TEST_CASE(the_still_top_counts_slip_positive_for_grains_it_holds_back) {
    // the top: g_x = v_x - a w_z; a grain at 0.2 U rolling on it has w_z = v_x / a > 0, the same
    // sense as the floor's rolling grains (the shear's vorticity)
    ParticleSet p;
    add(p, 0.5, kGap - kA, 0.0, 0.2 * kU, 0.0, 0.0, 0.2 * kU / kA);
    WallLayer r = wall_layer(p, kBox, kTop, kU);
    BOOST_TEST(r.slip == 0.2, tt::tolerance(1e-12));
    BOOST_TEST(r.rolling == 0.2, tt::tolerance(1e-12));
    BOOST_TEST(std::abs(r.contact_slip) < 1e-12);
    BOOST_TEST(*r.rolling_share == 1.0, tt::tolerance(1e-12));
    // spun against the shear: the contact point slides faster than the centre
    p.wz[0] = -p.wz[0];
    r = wall_layer(p, kBox, kTop, kU);
    BOOST_TEST(r.rolling == -0.2, tt::tolerance(1e-12));
    BOOST_TEST(r.contact_slip == 0.4, tt::tolerance(1e-12));
    BOOST_TEST(*r.rolling_share == -1.0, tt::tolerance(1e-12));
    BOOST_TEST(r.rolling_fraction == 0.0);
    BOOST_TEST(wall_layer(p, kBox, kFloor, kU).contacts == 0u);  // it does not touch the floor
}

BOOST_AUTO_TEST_CASE(only_grains_touching_the_wall_count) {
    ParticleSet p;
    add(p, 0.2, kA * (1.0 + 0.5 * kWallContactTolerance), 0.0, 0.5 * kU, 0.0, 0.0, 0.0);  // touching
    add(p, 0.6, kA * (1.0 + 2.0 * kWallContactTolerance), 0.0, 0.0, 0.0, 0.0, 0.0);       // just clear
    add(p, 1.0, 0.5 * kGap, 0.0, 0.0, 0.0, 0.0, 0.0);                                      // mid-gap
    const WallLayer r = wall_layer(p, kBox, kFloor, kU);
    BOOST_TEST(r.grains == 1u);
    BOOST_TEST(r.slip == 0.5, tt::tolerance(1e-12));
    BOOST_TEST(wall_layer(p, kBox, kTop, kU).grains == 0u);
}

BOOST_AUTO_TEST_CASE(a_grain_rolls_only_when_its_contact_point_sticks_across_the_flow_too) {
    // at the floor g_z = v_z - a w_x: sliding across the flow is slip, rolling across it is not
    ParticleSet p;
    add(p, 0.5, kA, 0.0, kU, 0.1 * kU, 0.0, 0.0);            // slides along z at 0.1 U
    add(p, 1.0, kA, 0.0, kU, 0.1 * kU, 0.1 * kU / kA, 0.0);  // rolls along z
    const WallLayer r = wall_layer(p, kBox, kFloor, kU);
    BOOST_TEST(r.contacts == 2u);
    BOOST_TEST(r.rolling_fraction == 0.5);
    BOOST_TEST(std::abs(r.contact_slip) < 1e-12);  // along the flow neither slips
}

BOOST_AUTO_TEST_CASE(bumps_are_met_where_their_wall_has_carried_them) {
    BumpLayer b;
    b.diameter = 2.0 * kA;
    b.spacing = 0.5, b.count_x = 4, b.rows = 1;
    for (double x : {0.0, 0.5, 1.0, 1.5}) b.x.push_back(x), b.across.push_back(0.0);
    // one grain resting on top of a bump that moved 0.3 m: its contact normal is the floor's
    ParticleSet p;
    const double on_top = 2.0 * kA;  // grain radius + bump radius
    add(p, 1.0 + 0.3 + 4.0 * kBox.length, on_top, 0.0, 0.5 * kU, 0.0, 0.0, 0.0);  // any periodic image
    WallLayerWall w = kFloor;
    w.bumps = &b;
    w.bump_shift = 0.3;
    WallLayer r = wall_layer(p, kBox, w, kU);
    BOOST_TEST(r.grains == 1u);
    BOOST_TEST(r.bump_contacts == 1u);
    BOOST_TEST(r.slip == 0.5, tt::tolerance(1e-12));
    BOOST_TEST(r.tangential_slip == 0.5, tt::tolerance(1e-12));
    BOOST_TEST(r.max_bump_overlap < 1e-12);
    // on the bump's upstream flank: the part of the grain's lag along the contact normal is its
    // approach to the bump, no slip
    p.y[0] = 1.5 * kA;  // clear of the plane
    p.x[0] = 0.3 + 1.0 - std::sqrt(on_top * on_top - p.y[0] * p.y[0]);
    r = wall_layer(p, kBox, w, kU);
    BOOST_TEST(r.bump_contacts == 1u);
    BOOST_TEST(r.contacts == 1u);
    BOOST_TEST(r.slip == 0.5, tt::tolerance(1e-12));
    const double nx = (p.x[0] - 1.3) / on_top;  // part of the lag is along the normal
    BOOST_TEST(r.tangential_slip == 0.5 * (1.0 - nx * nx), tt::tolerance(1e-12));
    // without the shift the grain is nowhere near a bump
    w.bump_shift = 0.0;
    BOOST_TEST(wall_layer(p, kBox, w, kU).bump_contacts == 0u);
}

BOOST_AUTO_TEST_CASE(the_record_says_what_it_did_not_measure) {
    ParticleState st;
    st.gap = kGap, st.time = 0.25;
    add(st.particles, 0.5, kA, 0.0, 0.7 * kU, 0.0, 0.0, 0.3 * kU / kA);  // rolls on the floor
    add(st.particles, 1.0, kGap - kA, 0.0, 0.1 * kU, 0.0, 0.0, 0.0);     // slides on the top
    const nlohmann::json j = wall_layer_record(st, kBox, kU, nullptr, nullptr, false);
    BOOST_TEST(j.at("time_s").get<double>() == 0.25);
    BOOST_TEST(j.at("bottom").at("rolling_share").get<double>() == 1.0, tt::tolerance(1e-12));
    BOOST_TEST(j.at("top").at("rolling_share").get<double>() == 0.0, tt::tolerance(1e-12));
    BOOST_TEST(j.at("top").at("slip_over_U").get<double>() == 0.1, tt::tolerance(1e-12));
    BOOST_TEST(j.at("bottom").at("surface").get<std::string>() == "plane");
    BOOST_TEST(!j.contains("sides"));  // periodic across z
    ParticleBox trough = kBox;
    trough.periodic_z = false;
    BOOST_TEST(wall_layer_record(st, trough, kU, nullptr, nullptr, false).contains("sides"));
    BOOST_TEST(wall_layer_record(st, kBox, kU, nullptr, nullptr, true).contains("not_measured"));  // the ring
    BOOST_TEST(wall_layer_record(std::nullopt, kBox, kU, nullptr, nullptr, false).contains("not_measured"));
    st.particles.wx.clear(), st.particles.wy.clear(), st.particles.wz.clear();
    BOOST_TEST(wall_layer_record(st, kBox, kU, nullptr, nullptr, false).contains("not_measured"));
}

BOOST_AUTO_TEST_CASE(bumps_misplaced_against_the_grains_are_not_measured) {
    BumpLayer b;
    b.diameter = 2.0 * kA;
    b.spacing = 2.0, b.count_x = 1, b.rows = 1;
    b.x = {1.0}, b.across = {0.0};
    ParticleState st;
    st.gap = kGap, st.time = 0.1;  // the floor's bumps moved U t = 0.2 m
    add(st.particles, 1.2, 2.0 * kA, 0.0, 0.5 * kU, 0.0, 0.0, 0.0);  // on the moved bump
    nlohmann::json j = wall_layer_record(st, kBox, kU, &b, nullptr, false);
    BOOST_TEST(!j.at("bottom").contains("not_measured"));
    BOOST_TEST(j.at("bottom").at("grains").get<std::size_t>() == 1u);
    st.particles.x[0] = 1.25, st.particles.y[0] = 1.5 * kA;  // deep in the moved bump
    j = wall_layer_record(st, kBox, kU, &b, nullptr, false);
    BOOST_TEST(j.at("bottom").contains("not_measured"));
    BOOST_TEST(j.at("bottom").at("max_bump_overlap_over_radius").get<double>() > kBumpOverlapLimit);
}
