// Deterministic rule tests of docs/automaton-model.md §7.1 with a scripted random source: the exact
// outcome of every rule (move, wrap, time factor, both walls, grain-grain, exhaustion, vector
// mode) and the algebra of JH06 Eqs. 6-9.
#define BOOST_TEST_MODULE automaton_rules
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <random>

#include "granlub/automaton/engine.h"
#include "granlub/automaton/invariants.h"
#include "scripted_rng.h"

using namespace granlub::automaton;
using Eng = Engine<ScriptedRng>;

namespace {

// §7.1 defaults: U = 1, e_p = 0.85, e_w = 0.65, R = 0.65, L = H = 10.
Eng make(const Rules& r = Params().rules) { return Eng(10, 10, r, ScriptedRng{}, ScriptedRng{}); }

// Clock one short of the time factor, so the next update attempts a move.
void arm(Eng& e, int i) { e.set_clock(i, e.tf(e.up(i)) - 1); }

constexpr double tol = 1e-12;

}  // namespace

BOOST_AUTO_TEST_CASE(free_move_wraps_periodically) {
    Eng e = make();
    const int i = e.add(9, 5, E, 1.0);
    e.update(i);
    BOOST_TEST(e.x(i) == 0);
    BOOST_TEST(e.y(i) == 5);
    BOOST_TEST(e.cell(0, 5) == i);
    BOOST_TEST(e.cell(9, 5) == kEmpty);
    BOOST_TEST(e.up(i) == 1.0);
    const int w = e.add(0, 2, W, 1.0);  // and the other way
    e.update(w);
    BOOST_TEST(e.x(w) == 9);
    BOOST_TEST(e.rule_rng().exhausted());
}

BOOST_AUTO_TEST_CASE(time_factor_gates_moves) {
    Eng e = make();
    const int i = e.add(2, 2, E, 0.3, 0);  // TF = round(1/0.3) = 3
    BOOST_TEST(e.tf(0.3) == 3);
    e.update(i);
    BOOST_TEST(e.x(i) == 2);
    e.update(i);
    BOOST_TEST(e.x(i) == 2);
    e.update(i);  // third update: moves
    BOOST_TEST(e.x(i) == 3);
    BOOST_TEST(e.clock(i) == 0.0);
    BOOST_TEST(e.tf(0.4) == 3);   // round half up: 2.5 -> 3
    BOOST_TEST(e.tf(1.0) == 1);
    BOOST_TEST(e.tf(0.02) == 50);
    const int r = e.add(5, 5, E, 0.019, 0);  // below U/TF_max: at rest, never moves
    for (int k = 0; k < 100; ++k) e.update(r);
    BOOST_TEST(e.x(r) == 5);
    BOOST_TEST(e.clock(r) == 0.0);
}

BOOST_AUTO_TEST_CASE(time_factor_ceil_and_accumulate) {
    Rules rc = Params().rules;
    rc.tf_rounding = TfRounding::Ceil;
    Eng c = make(rc);
    BOOST_TEST(c.tf(0.3) == 4);
    BOOST_TEST(c.tf(0.5) == 2);
    Rules ra = Params().rules;
    ra.tf_rounding = TfRounding::Accumulate;
    Eng a = make(ra);
    const int i = a.add(2, 2, E, 0.25, 0.0);  // progress 0.25, 0.5, 0.75, 1.0 -> moves on the 4th
    for (int k = 0; k < 3; ++k) a.update(i);
    BOOST_TEST(a.x(i) == 2);
    a.update(i);
    BOOST_TEST(a.x(i) == 3);
    BOOST_TEST(a.clock(i) == 0.0, boost::test_tools::tolerance(tol));
}

BOOST_AUTO_TEST_CASE(top_wall_reflects_and_slows) {
    const int in[3] = {N, NE, NW}, out[3] = {S, SE, SW}, dx[3] = {0, 1, -1};
    for (int k = 0; k < 3; ++k) {
        Eng e = make();
        const int i = e.add(4, 9, in[k], 0.5);
        arm(e, i);
        e.update(i);
        BOOST_TEST(e.dir(i) == out[k]);
        BOOST_TEST(e.up(i) == 0.5 * 0.65 * 0.35, boost::test_tools::tolerance(tol));  // 0.11375
        BOOST_TEST(e.x(i) == 4 + dx[k]);
        BOOST_TEST(e.y(i) == 8);
        BOOST_TEST(e.counters().wall_top == 1u);
        BOOST_TEST(e.rule_rng().exhausted());  // the top wall draws nothing
    }
}

BOOST_AUTO_TEST_CASE(bottom_wall_drags_with_probability_p_drag) {
    for (double draw : {0.7, 0.1}) {  // >= p_drag: specular N; < p_drag: drag notch NE
        Eng e = make();
        const int i = e.add(4, 0, S, 0.5);
        arm(e, i);
        e.rule_rng().uniforms = {draw};
        e.update(i);
        BOOST_TEST(e.up(i) == 1 - 0.2275 * 0.5, boost::test_tools::tolerance(tol));  // 0.88625
        const bool drag = draw < 0.65;
        BOOST_TEST(e.dir(i) == (drag ? NE : N));
        BOOST_TEST(e.x(i) == (drag ? 5 : 4));
        BOOST_TEST(e.y(i) == 1);
        BOOST_TEST(e.rule_rng().exhausted());
    }
    {  // SW reflects to NW, dragged to N
        Eng e = make();
        const int i = e.add(4, 0, SW, 0.5);
        arm(e, i);
        e.rule_rng().uniforms = {0.3};
        e.update(i);
        BOOST_TEST(e.dir(i) == N);
    }
    {  // SE always leaves NE, without a draw
        Eng e = make();
        const int i = e.add(4, 0, SE, 0.5);
        arm(e, i);
        e.update(i);
        BOOST_TEST(e.dir(i) == NE);
        BOOST_TEST(e.x(i) == 5);
        BOOST_TEST(e.y(i) == 1);
        BOOST_TEST(e.counters().wall_bottom == 1u);
        BOOST_TEST(e.counters().tangential_bottom == e.up(i) - 0.5, boost::test_tools::tolerance(tol));
    }
}

BOOST_AUTO_TEST_CASE(wall_speed_by_incidence) {
    Rules r = Params().rules;  // the keys' defaults
    r.wall_speed = WallSpeed::ByIncidence;
    Eng e = make(r);
    const int a = e.add(2, 9, N, 0.5);  // normal impact: Eq. 7 alone, u = 0 - 0.65 (0 - 0.5)
    arm(e, a);
    e.update(a);
    BOOST_TEST(e.up(a) == 0.65 * 0.5, boost::test_tools::tolerance(tol));
    const int b = e.add(6, 9, NE, 0.5);  // oblique: Eq. 6 alone, u = 0.5 + 0.65 (0 - 0.5)
    arm(e, b);
    e.update(b);
    BOOST_TEST(e.up(b) == 0.5 * 0.35, boost::test_tools::tolerance(tol));
}

BOOST_AUTO_TEST_CASE(grain_grain_billiard_rule) {
    for (bool plus_first : {true, false}) {
        Eng e = make();
        const int i = e.add(5, 5, E, 0.8);
        const int j = e.add(6, 5, W, 0.0);
        arm(e, i);
        e.rule_rng().coins = {plus_first};
        e.update(i);
        BOOST_TEST(e.up(i) == 0.06, boost::test_tools::tolerance(tol));
        BOOST_TEST(e.up(j) == 0.74, boost::test_tools::tolerance(tol));
        BOOST_TEST(e.up(i) + e.up(j) == 0.8, boost::test_tools::tolerance(tol));
        BOOST_TEST(e.up(j) - e.up(i) == 0.85 * 0.8, boost::test_tools::tolerance(tol));
        BOOST_TEST(e.dir(j) == E);  // struck grain moves off along the line of centres
        BOOST_TEST(e.dir(i) == (plus_first ? N : S));
        BOOST_TEST(e.x(i) == 5);
        BOOST_TEST(e.y(i) == (plus_first ? 6 : 4));
        BOOST_TEST(e.x(j) == 6);  // the struck grain does not move in this update
        BOOST_TEST(e.counters().pp == 1u);
        BOOST_TEST(e.rule_rng().exhausted());
    }
}

BOOST_AUTO_TEST_CASE(grain_grain_switches) {
    Rules r = Params().rules;  // the keys' defaults
    r.pp_deflect = 45;
    r.struck_dir = StruckDir::Keep;
    Eng e = make(r);
    const int i = e.add(5, 5, E, 0.8);
    const int j = e.add(6, 5, W, 0.0);
    arm(e, i);
    e.rule_rng().coins = {true};
    e.update(i);
    BOOST_TEST(e.dir(i) == NE);  // d + 1
    BOOST_TEST(e.x(i) == 6);
    BOOST_TEST(e.y(i) == 6);
    BOOST_TEST(e.dir(j) == W);   // keep
}

BOOST_AUTO_TEST_CASE(exhaustion_after_four_collisions) {
    Eng e = make();
    const int i = e.add(5, 5, E, 0.9);
    int nb[8];
    double u0[8];
    for (int d = 0; d < 8; ++d) {
        u0[d] = 0.05 * (d + 1);
        nb[d] = e.add(5 + kDx[d], 5 + kDy[d], (d + 4) & 7, u0[d]);
    }
    arm(e, i);
    // E hit: [N, S] -> N.  N hit: coin false -> [E, W], E tried -> W.  W hit: [S, N] -> S.
    // S hit: [E, W], both tried -> exhausted; the grain keeps C[0] = E and stays.
    e.rule_rng().coins = {true, false, true, true};
    e.update(i);
    BOOST_TEST(e.counters().pp == 4u);
    BOOST_TEST(e.counters().exhausted == 1u);
    BOOST_TEST(e.x(i) == 5);
    BOOST_TEST(e.y(i) == 5);
    BOOST_TEST(e.dir(i) == E);
    BOOST_TEST(e.rule_rng().exhausted());
    // Eq. 8-9 chain, written out independently: u1f = ((1-e)u1 + (1+e)u2)/2, u2f = ((1-e)u2 + (1+e)u1)/2.
    const double ep = 0.85;
    double ui = 0.9;
    const int hits[4] = {E, N, W, S};
    for (int h : hits) {
        const double u1 = ui, u2 = u0[h];
        ui = ((1 - ep) * u1 + (1 + ep) * u2) / 2;
        const double u2f = ((1 - ep) * u2 + (1 + ep) * u1) / 2;
        BOOST_TEST(e.up(nb[h]) == u2f, boost::test_tools::tolerance(tol));
        BOOST_TEST(e.dir(nb[h]) == h);  // each struck neighbour took i's direction at the hit
    }
    BOOST_TEST(e.up(i) == ui, boost::test_tools::tolerance(tol));
    for (int d : {NE, NW, SW, SE}) {  // untouched diagonal neighbours
        BOOST_TEST(e.up(nb[d]) == u0[d]);
        BOOST_TEST(e.dir(nb[d]) == ((d + 4) & 7));
    }
    BOOST_TEST(check_invariants(e) == "");
}

// The direction rules as the step loop calls them (collision_rules.h): Table P and Tables W-T/W-B.
BOOST_AUTO_TEST_CASE(direction_rule_tables) {
    for (int d = 0; d < 8; ++d) {
        const Candidates plus = billiard_deflection(d, 2, 1), minus = billiard_deflection(d, 2, 0);
        BOOST_TEST(plus.first == unsigned((d + 2) & 7));   // +90 degrees first
        BOOST_TEST(plus.second == unsigned((d + 6) & 7));
        BOOST_TEST(minus.first == plus.second);            // the other side first
        BOOST_TEST(minus.second == plus.first);
        BOOST_TEST(billiard_deflection(d, 1, 1).first == unsigned((d + 1) & 7));  // pp_deflect = 45
    }
    int asked = 0;
    auto never = [&] { ++asked; return false; };
    auto always = [&] { ++asked; return true; };
    const int in[3] = {N, NE, NW}, top_out[3] = {S, SE, SW};
    for (int k = 0; k < 3; ++k) BOOST_TEST(wall_reflection(in[k], false, always) == unsigned(top_out[k]));
    BOOST_TEST(asked == 0);  // the top wall never drags
    const int up_in[3] = {S, SW, SE}, specular[3] = {N, NW, NE}, dragged[3] = {NE, N, NE};
    for (int k = 0; k < 3; ++k) {
        BOOST_TEST(wall_reflection(up_in[k], true, never) == unsigned(specular[k]));
        BOOST_TEST(wall_reflection(up_in[k], true, always) == unsigned(dragged[k]));
    }
    BOOST_TEST(asked == 4);  // SE reflects to NE, where no notch can turn it: no draw
}

BOOST_AUTO_TEST_CASE(eq8_9_algebra) {
    std::mt19937_64 gen(7);
    std::uniform_real_distribution<double> U01(0.0, 1.0);
    for (int k = 0; k < 10000; ++k) {
        const double e = U01(gen), u1 = U01(gen), u2 = U01(gen);
        double a = u1, b = u2;
        eq8_9_collide(a, b, e);
        // Absolute differences: these are differences of nearly equal numbers.
        BOOST_TEST(std::abs((a + b) - (u1 + u2)) <= 1e-15);
        BOOST_TEST(std::abs((b - a) - e * (u1 - u2)) <= 1e-15);
        const double loss = (1 - e * e) * (u1 - u2) * (u1 - u2) / 2;
        BOOST_TEST(std::abs((a * a + b * b) - (u1 * u1 + u2 * u2 - loss)) <= 1e-14);
        BOOST_TEST((a >= 0 && a <= 1 && b >= 0 && b <= 1));
        // Walls: U_w - u_f = e_w (1 - R)(U_w - u_i), both walls, any order of Eqs. 6-7.
        const double R = U01(gen), ew = U01(gen);
        for (double Uw : {0.0, 1.0}) {
            const double f = wall_sequential(u1, Uw, R, ew);
            BOOST_TEST(std::abs((Uw - f) - ew * (1 - R) * (Uw - u1)) <= 1e-15);
            BOOST_TEST(std::abs(eq6_roughness(eq7_restitution(u1, Uw, ew), Uw, R) - f) <= 1e-15);  // Eqs. 6, 7 commute
        }
    }
    double a = 1.0, b = 1.0;  // no creep above U
    eq8_9_collide(a, b, 0.85);
    BOOST_TEST(a <= 1.0);
    BOOST_TEST(b <= 1.0);
}

BOOST_AUTO_TEST_CASE(vector_mode_wall) {
    Rules r = Params().rules;  // the keys' defaults
    r.mode = Mode::Vector;
    Eng e = make(r);
    const int i = e.add(4, 0, S, 0.5);
    arm(e, i);
    // v = (0, -0.5) -> Eq. 6 on vx: 0 + 0.65 (1 - 0) = 0.65; Eq. 7 on vy: +0.325.
    // |vx| >= |vy|: dx = +1, dy = +1 with probability 0.325/0.65 = 0.5; draw 0.2 -> NE.
    e.rule_rng().uniforms = {0.2};
    e.update(i);
    BOOST_TEST(e.dir(i) == NE);
    BOOST_TEST(e.up(i) == 0.65, boost::test_tools::tolerance(tol));
    BOOST_TEST(e.x(i) == 5);
    BOOST_TEST(e.y(i) == 1);
    BOOST_TEST(e.rule_rng().exhausted());
}

BOOST_AUTO_TEST_CASE(vector_mode_head_on_and_blocked) {
    Rules r = Params().rules;  // the keys' defaults
    r.mode = Mode::Vector;
    {
        Eng e = make(r);
        const int i = e.add(5, 5, E, 0.8);
        const int j = e.add(6, 5, W, 0.4);
        arm(e, i);
        e.rule_rng().uniforms = {0.5};  // jitter 0: line of centres along +x
        e.update(i);
        // a1 = 0.8, a2 = -0.4 -> a1' = (0.15*0.8 - 1.85*0.4)/2 = -0.31, a2' = (-0.15*0.4 + 1.85*0.8)/2 = 0.71
        BOOST_TEST(e.up(i) == 0.31, boost::test_tools::tolerance(1e-9));
        BOOST_TEST(e.dir(i) == W);
        BOOST_TEST(e.up(j) == 0.71, boost::test_tools::tolerance(1e-9));
        BOOST_TEST(e.dir(j) == E);
        BOOST_TEST(e.x(i) == 4);  // bounced back and moved
        BOOST_TEST(e.rule_rng().exhausted());
    }
    for (VecBlocked vb : {VecBlocked::Deflect, VecBlocked::Wait}) {  // chasing a faster grain
        r.vec_blocked = vb;
        Eng e = make(r);
        const int i = e.add(5, 5, E, 0.5);
        const int j = e.add(6, 5, E, 0.9);
        arm(e, i);
        e.rule_rng().uniforms = {0.5};
        if (vb == VecBlocked::Deflect) e.rule_rng().coins = {false};
        e.update(i);
        BOOST_TEST(e.up(i) == 0.5);  // no impact: speeds unchanged
        BOOST_TEST(e.up(j) == 0.9);
        if (vb == VecBlocked::Deflect) {
            BOOST_TEST(e.dir(i) == SE);  // d - 1 first
            BOOST_TEST(e.x(i) == 6);
            BOOST_TEST(e.y(i) == 4);
        } else {
            BOOST_TEST(e.x(i) == 5);  // the update ends
        }
        BOOST_TEST(e.rule_rng().exhausted());
    }
}
