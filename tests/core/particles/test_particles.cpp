// Overlap-free deterministic insertion and the particles file.
#define BOOST_TEST_MODULE core_particles
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "granlub/error.h"
#include "granlub/particles/particles.h"

using namespace granlub;

namespace {
// The Sawyer & Tichy 2001 cell: d = 0.787 mm, 30 x 4 x 19 mm.
const double kD = 0.787e-3;
ParticleBox sawyer_box() { return {30e-3, 4e-3, 19e-3, false}; }
}  // namespace

BOOST_AUTO_TEST_CASE(fill_gives_the_requested_count_without_overlaps) {
    const ParticleBox box = sawyer_box();
    const std::size_t n = grains_for_fill(box, kD, 0.595);
    const double vg = std::numbers::pi * kD * kD * kD / 6.0;
    BOOST_TEST(std::abs(static_cast<double>(n) * vg / box.volume() - 0.595) < vg / box.volume());
    InsertionOptions opt;
    opt.seed = 12345;
    opt.wall_speed = 2.0;
    const ParticleSet p = insert_grains(box, kD, n, opt);
    BOOST_TEST(p.size() == n);
    BOOST_TEST(min_gap(p, box) > 0.0);
    BOOST_TEST(std::abs(solid_fraction(p, box) - 0.595) < 1e-3);
    for (std::size_t i = 0; i < p.size(); ++i) {
        BOOST_TEST_REQUIRE(p.x[i] >= 0.0);
        BOOST_TEST_REQUIRE(p.x[i] < box.length);
        BOOST_TEST_REQUIRE(p.y[i] > p.radius[i]);
        BOOST_TEST_REQUIRE(p.y[i] < box.gap - p.radius[i]);
        BOOST_TEST_REQUIRE(std::abs(p.z[i]) < 0.5 * box.width - p.radius[i]);
    }
}

BOOST_AUTO_TEST_CASE(velocities_follow_the_couette_profile_with_noise) {
    const ParticleBox box = sawyer_box();
    InsertionOptions opt;
    opt.seed = 7;
    opt.wall_speed = 2.0;
    opt.velocity_noise = 0.1;
    const ParticleSet p = insert_grains(box, kD, 3000, opt);
    double sx = 0, syy = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double dev = p.vx[i] - 2.0 * (1.0 - p.y[i] / box.gap);
        sx += dev;
        syy += p.vy[i] * p.vy[i];
    }
    const double n = static_cast<double>(p.size());
    BOOST_TEST(std::abs(sx / n) < 4 * 0.2 / std::sqrt(n));          // mean of the noise ~ 0
    BOOST_TEST(std::abs(std::sqrt(syy / n) - 0.2) < 0.02);          // sigma = 0.1 U
}

BOOST_AUTO_TEST_CASE(same_seed_same_particles_other_seed_other_particles) {
    const ParticleBox box = sawyer_box();
    InsertionOptions opt;
    opt.seed = 99;
    opt.wall_speed = 1.4;
    const ParticleSet a = insert_grains(box, kD, 2000, opt);
    const ParticleSet b = insert_grains(box, kD, 2000, opt);
    BOOST_TEST(a.x == b.x);
    BOOST_TEST(a.vz == b.vz);
    opt.seed = 100;
    const ParticleSet c = insert_grains(box, kD, 2000, opt);
    BOOST_TEST(a.x != c.x);
}

BOOST_AUTO_TEST_CASE(periodic_depth_has_no_overlaps_across_the_boundary) {
    const ParticleBox box{100 * kD, 10 * kD, 10 * kD, true};
    const std::size_t n = grains_for_fill(box, kD, 0.55);
    const ParticleSet p = insert_grains(box, kD, n, {});
    BOOST_TEST(p.size() == n);
    BOOST_TEST(min_gap(p, box) > 0.0);
    for (double z : p.z) BOOST_TEST_REQUIRE(std::abs(z) <= 0.5 * box.width);
}

BOOST_AUTO_TEST_CASE(too_dense_a_fill_is_a_clear_error) {
    const ParticleBox box = sawyer_box();
    const std::size_t n = grains_for_fill(box, kD, 0.80);
    try {
        insert_grains(box, kD, n, {});
        BOOST_FAIL("expected a CaseError");
    } catch (const CaseError& e) {
        const std::string w = e.what();
        BOOST_TEST(w.find("do not fit") != std::string::npos);
        BOOST_TEST(w.find("at most") != std::string::npos);
    }
}

BOOST_AUTO_TEST_CASE(particles_file_round_trips_exactly) {
    const ParticleBox box = sawyer_box();
    InsertionOptions opt;
    opt.wall_speed = 2.8;
    const ParticleSet p = insert_grains(box, kD, 500, opt);
    const auto dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "core_particles_tmp";
    const auto file = initial_particles_path(dir, "U2.8");
    BOOST_TEST(file.filename() == "particles.csv");
    write_particles_csv(file, p, {"made by a test", "key: abc"});
    const ParticleSet q = read_particles_csv(file);
    BOOST_TEST(q.x == p.x);
    BOOST_TEST(q.y == p.y);
    BOOST_TEST(q.vx == p.vx);
    BOOST_TEST(q.radius == p.radius);
    const auto comments = read_particles_comments(file);
    BOOST_TEST(comments.size() == 2u);
    BOOST_TEST(comments[1] == "key: abc");
    std::filesystem::remove_all(dir);
}

// A run's final state (another run's warm start): spins and the top wall's position survive the
// file to the last bit; a file without a gap is rejected.
BOOST_AUTO_TEST_CASE(particle_state_keeps_spins_and_gap) {
    ParticleState st;
    st.particles.push_back(0.1, 0.2, 0.3, 1.0 / 3.0, -2.0, 0.5, 0.4e-3);
    st.particles.push_back(0.4, 0.5, -0.3, 0.0, 1e-9, 7.0, 0.4e-3);
    st.particles.wx = {12.5, -1.0 / 7.0};
    st.particles.wy = {0.0, 3e5};
    st.particles.wz = {-233.07131826781301, 1.0};
    st.gap = 0.0040467433352456;
    st.time = 0.30028;
    const auto dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "core_particles_state";
    const auto file = final_state_path(dir, "dem", "U2.0");
    BOOST_TEST(file.filename() == "final_state.csv");
    write_particle_state(file, st, {"made by a test"});
    const ParticleState q = read_particle_state(file);
    BOOST_TEST(q.particles.has_spin());
    BOOST_TEST(q.particles.x == st.particles.x);
    BOOST_TEST(q.particles.vx == st.particles.vx);
    BOOST_TEST(q.particles.wx == st.particles.wx);
    BOOST_TEST(q.particles.wy == st.particles.wy);
    BOOST_TEST(q.particles.wz == st.particles.wz);
    BOOST_TEST(q.gap == st.gap);
    BOOST_TEST(q.time == st.time);
    // a plain initial file has no spins and no gap: read as particles, refused as a state
    const auto plain = dir / "plain.csv";
    ParticleSet p = st.particles;
    p.wx.clear(), p.wy.clear(), p.wz.clear();
    write_particles_csv(plain, p, {"no state"});
    BOOST_TEST(!read_particles_csv(plain).has_spin());
    try {
        read_particle_state(plain);
        BOOST_FAIL("expected an Error");
    } catch (const Error& e) {
        BOOST_TEST(std::string(e.what()).find("gap") != std::string::npos);
        BOOST_TEST(std::string(e.what()).find("plain.csv") != std::string::npos);
    }
    std::filesystem::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(malformed_particles_file_names_file_and_line) {
    const auto dir = std::filesystem::path(GRANLUB_BINARY_DIR) / "tests" / "core_particles_bad";
    std::filesystem::create_directories(dir);
    const auto file = dir / "particles.csv";
    {
        std::FILE* f = std::fopen(file.c_str(), "w");
        std::fputs("# c\nx,y,z,vx,vy,vz,radius\n0,1,2,3,4,5,0.1\n0,1,2,x,4,5,0.1\n", f);
        std::fclose(f);
    }
    try {
        read_particles_csv(file);
        BOOST_FAIL("expected an Error");
    } catch (const Error& e) {
        BOOST_TEST(std::string(e.what()).find("particles.csv:4") != std::string::npos);
    }
    std::filesystem::remove_all(dir);
}
