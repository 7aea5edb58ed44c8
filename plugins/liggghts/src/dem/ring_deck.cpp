// The whole ring's deck (ring_deck.h). Checked by hand first in plugins/liggghts/examples/ring,
// whose README section ("The whole ring") has the measurements behind each choice.
#include "ring_deck.h"

#include <fmt/format.h>

namespace granlub::dem {

namespace {

struct WallText {
    std::string columns;  // the wall file's kRingWallColumns values, in RingWallLoads' order
    std::string top;      // the grains' force on the top along the axis (the servo's input)
};

// Under load control the top moves along the axis at v_vtop, which the servo loop sets after each
// window (servo() below); hplate is where the window takes it.
void top_velocity(const Settings& s, const DeckLine& line) {
    line(fmt::format("# the top moves along the axis at v_vtop, set by the servo loop at the end (box top {} m)",
                     s.gap_max));
    line(fmt::format("variable hplate equal {}", s.plate_start));
    line("variable vtop equal 0");
}

// The four walls as STL meshes (ring_meshes.h) turning by LIGGGHTS' surface_ang_vel; loads from
// fix mesh/surface/stress (of the grains on each mesh; torque about its reference point, the origin).
WallText mesh_walls(const Settings& s, const ModelText& m, const std::string& turn, const DeckLine& line) {
    line("# walls: meshes; the floor (type 2) and the side walls (type 4) turn about the axis; the top is type 3");
    line(fmt::format("fix floor all mesh/surface/stress file {} type 2 {}", kRingMeshes[0], turn));
    line(fmt::format("fix top all mesh/surface/stress file {} type 3", kRingMeshes[1]));
    line(fmt::format("fix outer all mesh/surface/stress file {} type 4 {}", kRingMeshes[2], turn));
    line(fmt::format("fix inner all mesh/surface/stress file {} type 4 {}", kRingMeshes[3], turn));
    line(fmt::format("fix wgran all wall/gran {} mesh n_meshes 4 meshes floor top outer inner{}", m.model, m.settings));
    if (s.load) {
        top_velocity(s, line);
        line("variable zero equal 0");
        line("fix lift all move/mesh mesh top linear/variable v_zero v_vtop v_zero");
    }
    return {"f_floor[2] f_floor[5] f_top[2] f_top[5] f_outer[2] f_outer[5] f_inner[2] f_inner[5]", "f_top[2]"};
}

// All four walls as exact primitives (plugins/liggghts/doc/fix_wall_gran_moving.txt): the floor and
// both cylinders turning in place, the top a plane that the servo moves along the axis at v_vtop,
// as the mesh top. Their loads from compute wall/gran/force, the torque about the axis taken at the
// contact points (the walls' on the grains: negated here, so that the wall file means what the
// meshes' does). A plain primitive top could only be re-made where the servo puts it: in a small
// ring at 1 kPa those jumps left a fifth of the grains' weight out of the walls' forces (2026-11-26).
// `motion`: the top's fix wall/gran/moving words under load (normal_velocity, or a weighted plate's
// normal_load).
WallText primitive_walls(const Settings& s, const ModelText& m, const std::string& turn, const std::string& motion,
                         const DeckLine& line) {
    const Annulus& an = s.annulus;
    line("# walls: exact primitives; the floor (type 2) and the cylinders (type 4) turn about the axis, the top");
    line("# (type 3) is a plane over the trough; store_force gives each wall's force on each grain");
    line(fmt::format("fix floor all wall/gran/moving {} primitive type 2 yplane 0.0 store_force yes{} {}", m.model,
                     m.settings, turn));
    line(fmt::format("fix outer all wall/gran/moving {} primitive type 4 ycylinder {} 0 0 store_force yes{} {}", m.model,
                     an.outer(), m.settings, turn));
    line(fmt::format("fix inner all wall/gran/moving {} primitive type 4 ycylinder {} 0 0 store_force yes{} {}", m.model,
                     an.inner(), m.settings, turn));
    if (s.load) {
        if (!s.weight_plate) top_velocity(s, line);
        line(fmt::format("fix top all wall/gran/moving {} primitive type 3 yplane {} store_force yes{} {}", m.model,
                         s.plate_start, m.settings, motion));
    } else {
        line(fmt::format("fix top all wall/gran {} primitive type 3 yplane {} store_force yes{}", m.model, s.plate_start,
                         m.settings));
    }
    line("# each wall's force on the grains and torque about the axis: fx fy fz torque of floor, top, outer, inner");
    line("compute fwall all wall/gran/force floor top outer inner torque 0 0 0 0 1 0");
    std::string cols;
    const char* names[] = {"floor", "top", "outer", "inner"};
    for (int w = 0; w < 4; ++w) {
        line(fmt::format("variable {0}_fy equal -c_fwall[{1}]", names[w], 4 * w + 2));
        line(fmt::format("variable {0}_torque equal -c_fwall[{1}]", names[w], 4 * w + 4));
        cols += fmt::format("{0}v_{1}_fy v_{1}_torque", w ? " " : "", names[w]);
    }
    return {cols, "v_top_fy"};
}

// The slice's servo rule (deck.cpp) with the plate moved, not re-made: re-making the top mesh at
// each window left 14 % of the grains' weight out of the walls' recorded forces (plugin README,
// "The whole ring"); a top moving at a steady speed keeps the books. `top`: the grains' force on it.
void servo(const Settings& s, const DeckLine& line, double A, double d_g, const std::string& top) {
    line(fmt::format("# every {} steps: the next position hplate + {} * err, err = clamp((P_top - P)/P, -1, {}),",
                     s.servo_every, s.plate_gain * d_g, s.servo_max_error));
    line(fmt::format("# kept in [{}, {}] m and reached at a steady speed over the next {} steps; positions in {}",
                     s.gap_min, s.gap_max, s.servo_every, kPlateFile));
    servo_rule_block(s, line, top, "", A, d_g);
    line("label servo");
    line(fmt::format("run             {} post no", s.servo_every));
    line("next update");
    line("jump SELF move  # skipped after the last window");
    line("jump SELF done");
    line("label move");
    line(fmt::format("variable vtop equal (${{hnew}}-${{hplate}})/({}*dt)", s.servo_every));
    line("variable hplate equal ${hnew}");
    line("jump SELF servo");
    line("label done");
    line("variable vtop equal 0  # the plate stays where the last window took it");
}

}  // namespace

DataBounds ring_bounds(const Settings& s, double d) {
    const double half = s.annulus.outer() + 2.0 * d;
    return {-half, half, -d, ring_wall_height(s, d) + 2.0 * d, -half, half};
}

double ring_wall_height(const Settings& s, double d) { return s.box_top() + d; }

std::string ring_deck(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleSet& grains,
                      const std::string& provenance) {
    const Annulus& an = s.annulus;
    const double U = p.speed, omega = U / an.R, A = an.area(), d_g = c.grains.diameter;
    const ModelText m = model_text(s);
    std::string d;
    const DeckLine line = deck_lines(d);

    line(fmt::format("# granlub dem: case {}, point {} ({})", c.name, p.id, provenance));
    line(fmt::format("# The whole ring: y is the axis; a trough of mean radius R = {:g} m between the cylinders r = {:g} "
                     "and {:g} m,",
                     an.R, an.inner(), an.outer()));
    line(fmt::format("# floor at y = 0; the floor and both cylinders turn at Omega = U/R = {:g} rad/s (U = {:g} m/s at "
                     "R); the annular top {}.",
                     omega, U,
                     s.load ? fmt::format("is a plate {} to {:g} Pa (starts at y = {:g} m)",
                                          s.weight_plate ? "weighted" : "servo-controlled", s.target_stress,
                                          s.plate_start)
                            : fmt::format("is still at y = H = {:g} m", s.box.gap)));
    line(fmt::format("# {} grains of d = {:g} m; contact model: {}. No centripetal body force: the curvature makes it.",
                     grains.size(), d_g,
                     s.law->title));
    if (s.ring_mesh)
        line(fmt::format("# Meshes ({} facets per circle): {}, {}, {}, {}. Rerun by hand in this folder: "
                         "granlub-liggghts -in in.granlub",
                         s.ring_facet_count, kRingMeshes[0], kRingMeshes[1], kRingMeshes[2], kRingMeshes[3]));
    else
        line("# Walls: exact primitives (planes and cylinders). Rerun by hand in this folder: granlub-liggghts -in "
             "in.granlub");
    line("");
    engine_block(s, line, "f f f", "* 1 *   # split across the ring's plane, never along its axis");
    line("");
    contact_block(c, p, s, line);
    line("");
    const std::string turn = fmt::format("surface_ang_vel origin 0 0 0 axis 0 1 0 omega {}", omega);
    const std::string motion = s.weight_plate ? weight_plate_words(c, s, grains, A, false) : "normal_velocity v_vtop";
    const WallText walls = s.ring_mesh ? mesh_walls(s, m, turn, line) : primitive_walls(s, m, turn, motion, line);
    line("");
    line("# body forces: gravity along -y (the axis)");
    if (c.gravity > 0) line(fmt::format("fix grav all gravity {} vector 0 -1 0", c.gravity));
    line("fix integr all nve/sphere");
    line("");
    line("# wall loads (of the grains on each wall), averaged over blocks of sample_every steps, sampled every step");
    line("# (impulse forces last one step). Columns: step, then for floor, top, outer, inner: force along y (N) and");
    line("# torque about y (N m)");
    line(fmt::format("fix walls all ave/time 1 {0} {0} {1} file {2}", s.sample_every, walls.columns, kWallFile));
    line(fmt::format("# floor area A = pi (r_o^2 - r_i^2) = {} m^2: normal stress on the top = f_y(top)/A; shear stress "
                     "= torque / {} m^3",
                     A, an.polar_moment()));
    line("");
    line("# particle snapshots for coarse-graining (granlub maps them onto the slice's frame, granlub/particles/annulus.h)");
    output_block(s, line);
    if (fixed_top_ending(s, line)) return d;
    line("");
    if (s.weight_plate) {
        weight_plate_run(s, line, "top");
    } else {
        line(fmt::format("# load control: top plate servo, target normal stress P = {} Pa on A = {} m^2", s.target_stress,
                         A));
        servo(s, line, A, d_g, walls.top);
    }
    persistence_block(s, line);
    final_state_block(s, line);
    return d;
}

}  // namespace granlub::dem
