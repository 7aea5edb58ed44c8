// Writes the LIGGGHTS deck of one point (see deck.h). Conventions: docs/architecture.md (x flow,
// y across the gap with the moving wall at y = 0, z across the width) and
// docs/liggghts-notes.md (walls, stress sampling, traps).
#include "deck.h"

#include <numbers>

#include <fmt/format.h>

#include "granlub/error.h"
#include "granlub/statistics/flow_regime.h"
#include "granlub/text.h"

namespace granlub::dem {

DataBounds slice_bounds(const ParticleBox& box, double top) {
    return {0, box.length, 0, top, -0.5 * box.width, 0.5 * box.width};
}

DataBounds bump_bounds(DataBounds b, const Settings& s) {
    if (s.bumps_bottom) b.ylo = -0.5 * s.bumps_bottom->diameter;
    if (s.bumps_top) b.yhi += 0.5 * s.bumps_top->diameter;
    if (s.bumps_side) {  // the side walls' bumps are centred on the planes z = -W/2 and W/2
        b.zlo -= 0.5 * s.bumps_side->diameter;
        b.zhi += 0.5 * s.bumps_side->diameter;
    }
    return b;
}

std::vector<BumpAtoms> bump_atoms(const Settings& s, double U, double t) {
    const double L = s.box.length;
    std::vector<BumpAtoms> bumps;
    if (s.bumps_bottom) bumps.push_back({moved_bumps(*s.bumps_bottom, U * t, L), kBottom, 0.0, U});
    if (s.bumps_top) bumps.push_back({*s.bumps_top, kTop, s.plate_start, 0.0});
    if (s.bumps_side)
        for (double z : {-0.5 * s.box.width, 0.5 * s.box.width})
            bumps.push_back({moved_bumps(*s.bumps_side, U * t, L), kSide, z, U, true});
    return bumps;
}

std::string data_file(const ParticleSet& p, const DataBounds& b, double density, const std::string& title,
                      const std::vector<BumpAtoms>& bumps) {
    std::size_t atoms = p.size();
    for (const auto& w : bumps) atoms += w.layer.size();
    std::string out = fmt::format("LIGGGHTS data file: {}\n\n{} atoms\n4 atom types\n\n", one_line(title), atoms);
    out += fmt::format("{} {} xlo xhi\n{} {} ylo yhi\n{} {} zlo zhi\n\nAtoms\n\n", b.xlo, b.xhi, b.ylo, b.yhi, b.zlo,
                       b.zhi);
    for (std::size_t i = 0; i < p.size(); ++i)
        out += fmt::format("{} 1 {} {} {} {} {}\n", i + 1, 2.0 * p.radius[i], density, p.x[i],
                           p.y[i], p.z[i]);
    std::size_t id = p.size();
    for (const auto& w : bumps)
        for (std::size_t k = 0; k < w.layer.size(); ++k)
            out += fmt::format("{} {} {} {} {} {} {}\n", ++id, static_cast<int>(w.type), w.layer.diameter,
                               kBumpDensityFactor * density, w.layer.x[k], w.y(k), w.z(k));
    out += "\nVelocities\n\n";
    for (std::size_t i = 0; i < p.size(); ++i)
        out += fmt::format("{} {} {} {} {} {} {}\n", i + 1, p.vx[i], p.vy[i], p.vz[i], p.has_spin() ? p.wx[i] : 0.0,
                           p.has_spin() ? p.wy[i] : 0.0, p.has_spin() ? p.wz[i] : 0.0);
    id = p.size();
    for (const auto& w : bumps)
        for (std::size_t k = 0; k < w.layer.size(); ++k) out += fmt::format("{} {} 0 0 0 0 0\n", ++id, w.vx);
    return out;
}

namespace {
// 4 x 4 per-type-pair matrix: grain-grain, grain-bottom/top/side walls; wall-wall pairs never meet.
std::string pair_matrix(double pp, double bottom, double top, double side) {
    const double m[4][4] = {{pp, bottom, top, side}, {bottom, pp, pp, pp}, {top, pp, pp, pp}, {side, pp, pp, pp}};
    std::string s;
    for (const auto& row : m)
        for (double v : row) s += fmt::format(" {}", v);
    return s;
}
}  // namespace

// Contact persistence (granlub's regime diagnostics, flow_regime.h): after the run, with the
// result outputs closed, a few snapshots a small shear strain apart. Costs persistence_run_steps().
void output_block(const Settings& s, const DeckLine& line) {
    line(fmt::format("dump cg {} custom {} {} {}", s.grains_group(), s.snapshot_every, kSnapshots, kSnapshotColumns));
    line("dump_modify cg sort id");
    if (s.vtk) {
        line(fmt::format("# ParaView: one VTK XML file per snapshot; granlub writes the collection {}", kPvdFile));
        line(fmt::format("dump vtk all custom/vtk {} post/particles_*.vtp id type x y z vx vy vz omegax omegay omegaz "
                         "radius",
                         s.snapshot_every));
    }
    line("thermo_style    custom step atoms ke cpu");
    line(fmt::format("thermo          {}", std::max<std::int64_t>(1, s.steps / 20)));
    line("thermo_modify   norm no lost error");
}

void servo_rule_block(const Settings& s, const DeckLine& line, const std::string& force, const std::string& sign,
                      double A, double d) {
    line(fmt::format("fix servoF all ave/time 1 {0} {0} {1}", s.servo_every, force));
    line(fmt::format("fix plate all ave/time {0} 1 {0} v_hplate file {1}", s.servo_every, kPlateFile));
    line(fmt::format("variable ptop equal {}f_servoF/{}", sign, A));
    line(fmt::format("variable err equal (v_ptop-{0})/{0}", s.target_stress));
    line(fmt::format("variable errc equal v_err*(v_err>=-1)*(v_err<={0})+{0}*(v_err>{0})-(v_err<-1)",
                     s.servo_max_error));
    line(fmt::format("variable htry equal v_hplate+{}*v_errc", s.plate_gain * d));
    line(fmt::format("variable hnew equal v_htry*(v_htry>={0})*(v_htry<={1})+{0}*(v_htry<{0})+{1}*(v_htry>{1})",
                     s.gap_min, s.gap_max));
    line(fmt::format("variable update loop {}", s.steps / s.servo_every));
}

std::string weight_plate_words(const Case& c, const Settings& s, const ParticleSet& grains, double area,
                               bool carry_bumps) {
    double volume = 0;  // of the grains, m^3
    for (const double r : grains.radius) volume += 4.0 / 3.0 * std::numbers::pi * r * r * r;
    const double mass = s.plate_mass * c.grains.density * volume;
    return fmt::format("normal_load {:.17g} {:.17g} {:.17g} {:.17g}{}", -s.target_stress * area, mass, s.gap_min,
                       s.gap_max, carry_bumps ? " carry tbump" : "");
}

void weight_plate_run(const Settings& s, const DeckLine& line, const std::string& top_fix) {
    line(fmt::format("# load control: the weighted plate, P = {} Pa; its position every {} steps in {}", s.target_stress,
                     s.servo_every, kPlateFile));
    line(fmt::format("fix plate all ave/time {0} 1 {0} f_{1}[1] file {2}", s.servo_every, top_fix, kPlateFile));
    line(fmt::format("run             {}", s.steps));
    line(fmt::format("variable hplate equal f_{}[1]", top_fix));
}

void persistence_block(const Settings& s, const DeckLine& line) {
    line("");
    line(fmt::format("# contact persistence: {} snapshots {} steps apart (shear strain {:g} at U/H) in {}, after the "
                     "run; the result outputs are closed first",
                     s.persistence_intervals + 1, s.persistence_every, kPersistenceStrain, kContactsFile));
    line("undump cg");
    if (s.vtk) line("undump vtk");
    line("unfix walls");
    if (s.load) line("unfix plate");
    line(fmt::format("dump contacts {} custom {} {} {}", s.grains_group(), s.persistence_every, kContactsFile,
                     kSnapshotColumns));
    line("dump_modify contacts sort id");
    line(fmt::format("run             {}", s.persistence_run_steps()));
}

// The final state at full precision (a warm start for another run, e.g. granlub yade's): positions,
// velocities and spins, and the plate position under load control.
void final_state_block(const Settings& s, const DeckLine& line) {
    line("");
    line(fmt::format("# the final state (17 digits; the starting state of a warm start) in {}", kFinalDump));
    line("undump contacts");
    line(fmt::format("dump final {} custom 1 {} {}", s.grains_group(), kFinalDump, kFinalColumns));
    std::string format = "%d";
    for (int k = 0; k < 10; ++k) format += " %.17g";
    line(fmt::format("dump_modify final sort id format \"{}\"", format));
    line("run             0");
    line("undump final");
    if (s.load) line(fmt::format("print \"${{hplate}}\" file {}", kFinalPlateFile));
}

bool fixed_top_ending(const Settings& s, const DeckLine& line) {
    if (s.load) return false;
    line(fmt::format("run             {}", s.steps));
    persistence_block(s, line);
    final_state_block(s, line);
    return true;
}

ModelText model_text(const Settings& s) {
    if (!s.law->impulse_options) return {s.law->liggghts, ""};
    return {s.law->liggghts,
            fmt::format(" beta0 {} separate {}{}{}{}", s.beta0, s.separate ? "on" : "off",
                        s.bounce_speed > 0 ? fmt::format(" bounce_speed {}", s.bounce_speed) : "",
                        // iterate explicit: the model's default is on
                        s.iterated      ? (s.speculative ? " iterate on speculative on" : " iterate on")
                        : s.impact_time ? " iterate off impact_time on"
                        : s.speculative ? " iterate off speculative on"
                                        : " iterate off",
                        // only when on: the decks of boundary_pairs = 'sequential' stay as they were
                        s.boundary_start ? " boundary_start on" : "")};
}

DeckLine deck_lines(std::string& d) {
    // LIGGGHTS runs every line as a command (`shell` included): a line break inside a line, from
    // whatever text reached it, must never start one. Case text is checked at parse time; this
    // is the guard at the last step.
    return [&d](const std::string& l) {
        if (control_character_offset(l))
            throw Error(fmt::format("internal: deck line holds a control character: {}", one_line(l)));
        d += l + "\n";
    };
}

void engine_block(const Settings& s, const DeckLine& line, const std::string& boundary, const std::string& processors) {
    line("atom_style      granular");
    line("atom_modify     map array");
    line("boundary        " + boundary);
    line("newton          off");
    line("communicate     single vel yes");
    line("units           si");
    line("hard_particles  yes     # glass: Young's modulus above LIGGGHTS' 1 GPa sanity limit");
    line("processors      " + processors);
    line(fmt::format("read_data       {}", kData));
    line(fmt::format("neighbor        {} bin", s.skin_m));
    line("neigh_modify    delay 0");
}

void contact_block(const Case& c, const OperatingPoint& p, const Settings& s, const DeckLine& line) {
    const ModelText m = model_text(s);
    line("# materials; types: 1 grains, 2 bottom wall, 3 top wall, 4 side walls");
    const auto& g = c.grains;
    line(fmt::format("fix m1 all property/global youngsModulus peratomtype {0} {0} {0} {0}",
                     g.youngs_modulus));
    line(fmt::format("fix m2 all property/global poissonsRatio peratomtype {0} {0} {0} {0}",
                     g.poisson_ratio));
    line(fmt::format("fix m3 all property/global coefficientRestitution peratomtypepair 4{}",
                     pair_matrix(g.restitution, p.bottom.restitution, p.top.restitution, p.bottom.restitution)));
    line(fmt::format("fix m4 all property/global coefficientFriction peratomtypepair 4{}",
                     pair_matrix(g.friction, p.bottom.friction, p.top.friction, p.bottom.friction)));
    line("");
    line(fmt::format("pair_style      gran {}{}", m.model, m.settings));
    line("pair_coeff      * *");
    if (s.law->impulse_options && s.iterated) {
        line("# contact_solve = iterated: every impulse contact of a step (pair and walls, `iterate on`) solved together");
        line("# to convergence (plugins/liggghts/doc/fix_impulse_solve.txt); impact_tolerance 0: an impact's");
        line("# jolt solved like any change (the fix's default stops it at 5 % of the approach speed, for settling beds)");
        line(fmt::format("fix solve all impulse/solve tolerance {} iterations {} impact_tolerance 0", s.solve_tolerance,
                         s.solve_iterations));
    }
    line(fmt::format("timestep        {}", s.time_step));
}

namespace {

// Rough walls (core wall_bumps.h): the bumps are atoms of the wall's type (2 floor, 3 top, 4 side
// walls) that no fix integrates; the floor's and the side walls' move along the flow with the
// floor, the top's jump with the plate (servo loop). Bumps never meet each other or the planes,
// which act on the grains only.
void bump_block(const Settings& s, const DeckLine& line, double U) {
    line("# rough walls: a monolayer of bumps (atoms of the wall's type, not integrated, heavy: a wall to");
    line("# the grains); their centres on the wall's plane. Planes, body forces and integration: grains only");
    line("group grains type 1");
    if (s.bumps_bottom) {
        line(fmt::format("group bbump type 2   # {} bumps of {} m, {} m apart along the flow, R = {:.4g}",
                         s.bumps_bottom->size(), s.bumps_bottom->diameter, s.bumps_bottom->spacing,
                         s.bumps_bottom->roughness));
        line(fmt::format("fix bmove bbump move linear {} 0 0", U));
    }
    if (s.bumps_top)
        line(fmt::format("group tbump type 3   # {} bumps of {} m, {} m apart along the flow, R = {:.4g}",
                         s.bumps_top->size(), s.bumps_top->diameter, s.bumps_top->spacing, s.bumps_top->roughness));
    if (s.bumps_side) {
        line(fmt::format("group sbump type 4   # {} bumps on each side wall, {} rows above the floor", s.bumps_side->size(),
                         s.bumps_side->rows));
        line("region zlow block INF INF INF INF INF 0.0 units box");
        line("group zlow region zlow");
        line("group sbump1 intersect sbump zlow   # on the side wall at z = -W/2");
        line("group sbump2 subtract sbump sbump1");
        line(fmt::format("fix smove sbump move linear {} 0 0", U));
    }
    for (const char* pair : {"2 2", "2 3", "3 3"}) line(fmt::format("neigh_modify exclude type {}", pair));
    if (s.bumps_side)
        for (const char* pair : {"2 4", "3 4", "4 4"}) line(fmt::format("neigh_modify exclude type {}", pair));
    line("");
}

// The side walls' columns (x: their drag; y: what they carry of the grains' weight), fx fx fy fy,
// each its plane's force plus its bumps' (as bump_force_columns).
std::string side_force_columns(const Settings& s, const DeckLine& line) {
    if (!s.bumps_side) return " c_fwall[7] c_fwall[10] c_fwall[8] c_fwall[11]";
    line("compute fbumps1 sbump1 reduce sum fx fy fz");
    line("compute fbumps2 sbump2 reduce sum fx fy fz");
    std::string cols;
    for (int k = 0; k < 2; ++k)
        for (int side = 1; side <= 2; ++side) {
            const char axis = "xy"[k];
            line(fmt::format("variable ws{0}{1} equal c_fwall[{2}]-c_fbumps{0}[{3}]", side, axis, 4 + 3 * side + k,
                             k + 1));
            cols += fmt::format(" v_ws{}{}", side, axis);
        }
    return cols;
}

// The wall file's columns with bumps: each wall's force on the grains is its plane's plus its
// bumps', and a bump's force on the grains is minus the grains' force on it (compute reduce of f).
std::string bump_force_columns(const Settings& s, const DeckLine& line) {
    std::string cols;
    const struct {
        const char* wall;
        const char* group;
        int first;  // c_fwall index of the plane's fx
    } walls[] = {{"b", s.bumps_bottom ? "bbump" : nullptr, 1}, {"t", s.bumps_top ? "tbump" : nullptr, 4}};
    for (const auto& w : walls) {
        if (w.group) line(fmt::format("compute fbump{0} {1} reduce sum fx fy fz", w.wall, w.group));
        for (int k = 0; k < 3; ++k) {
            const char axis = "xyz"[k];
            line(w.group ? fmt::format("variable w{0}{1} equal c_fwall[{2}]-c_fbump{0}[{3}]", w.wall, axis, w.first + k,
                                       k + 1)
                         : fmt::format("variable w{0}{1} equal c_fwall[{2}]", w.wall, axis, w.first + k));
            cols += fmt::format("{}v_w{}{}", cols.empty() ? "" : " ", w.wall, axis);
        }
    }
    return cols;
}

// The deck's opening comment: the cell, the walls, the grains and the contact model.
void slice_header(const Case& c, const OperatingPoint& p, const Settings& s, std::size_t grains,
                  const std::string& provenance, const DeckLine& line) {
    const auto& box = s.box;
    const double U = p.speed;
    line(fmt::format("# granlub dem: case {}, point {} ({})", c.name, p.id, provenance));
    line(fmt::format("# Shear cell: x along the flow (periodic, L = {:g} m), y across the gap (H = {:g} m):", box.length,
                     box.gap));
    line(fmt::format("# bottom wall y = 0 sliding at U = {:g} m/s, top wall {}, z across the width{}.", U,
                     s.load ? fmt::format("a plate {} to {:g} Pa (starts at y = {})",
                                          s.weight_plate ? "weighted" : "servo-controlled", s.target_stress,
                                          s.plate_start == box.gap ? std::string("H")
                                                                   : fmt::format("{:g} m", s.plate_start))
                            : std::string("y = H fixed"),
                     box.periodic_z ? fmt::format(" (periodic, {:g} m)", box.width)
                                    : fmt::format(" (side walls at +-{:g} m moving with the bottom)", 0.5 * box.width)));
    line(fmt::format("# {} grains of d = {:g} m (solid fraction {:.4f}); contact model: {}.", grains, c.grains.diameter,
                     s.insert_fill, s.law->title));
    line("# Rerun by hand in this folder: granlub-liggghts -in in.granlub");
}

// The slice's walls: the floor, the top (a plate at ${hplate} under load control) and, without a
// periodic width, the side walls. Returns the top wall's fix line: the window servo's loop remakes it.
std::string slice_walls(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleSet& grains,
                        const DeckLine& line) {
    const auto& box = s.box;
    const double U = p.speed;
    const ModelText mt = model_text(s);
    const std::string& model = mt.model;
    const std::string& settings = mt.settings;
    const std::string g = s.grains_group();
    line("# walls: primitive planes; `shear x U` moves the bottom and side walls along the flow;");
    line("# store_force gives the force of each wall on each grain (f_force_<id>), summed every step");
    line(fmt::format("fix wbot {} wall/gran {} primitive type 2 yplane 0.0 shear x {} store_force yes{}", g, model, U,
                     settings));
    const bool weight = s.load && s.weight_plate;
    const std::string top_wall =
        weight ? fmt::format("fix wtop {} wall/gran/moving {} primitive type 3 yplane {} store_force yes{} {}", g, model,
                             s.plate_start, settings,
                             weight_plate_words(c, s, grains, box.length * box.width, s.bumps_top.has_value()))
               : fmt::format("fix wtop {} wall/gran {} primitive type 3 yplane {} store_force yes{}", g, model,
                             s.load ? std::string("${hplate}") : fmt::format("{}", box.gap), settings);
    if (weight) {
        line(fmt::format("# top wall: a weighted plate (servo_plate = \"weight\"), free along y between {} and {} m, "
                         "pressed by P A;", s.gap_min, s.gap_max));
        line("# its position and velocity are f_wtop[1] and f_wtop[2]");
    } else if (s.load) {
        line(fmt::format("# top wall: a plate at y = hplate, moved by the servo loop at the end (box top {} m)",
                         s.gap_max));
        line(fmt::format("variable hplate equal {}", s.plate_start));
    }
    line(top_wall);
    if (weight && s.bumps_top) {  // the top's bumps ride the plate: one rigid body (normal_load ... carry)
        line("variable vplate equal f_wtop[2]");
        line("fix tmove tbump move variable NULL NULL NULL NULL v_vplate NULL");
    }
    if (!box.periodic_z) {
        line(fmt::format("fix wsid1 {} wall/gran {} primitive type 4 zplane {} shear x {} store_force yes{}", g,
                         model, -0.5 * box.width, U, settings));
        line(fmt::format("fix wsid2 {} wall/gran {} primitive type 4 zplane {} shear x {} store_force yes{}", g,
                         model, 0.5 * box.width, U, settings));
    }
    return top_wall;
}

// Gravity, the centripetal force and the integration of the grains.
void slice_body_forces(const Case& c, const Settings& s, const DeckLine& line) {
    const std::string g = s.grains_group();
    line("# body forces: gravity along -y; centripetal acceleration u_x^2 / (R - z) toward the outer wall (-z),");
    line("# with R the annulus mean radius (Sawyer & Tichy 2001, particle simulation)");
    if (c.gravity > 0) line(fmt::format("fix grav {} gravity {} vector 0 -1 0", g, c.gravity));
    // a compiled fix (plugins/liggghts/doc/fix_centripetal_annulus.txt): the same force, bit for bit, as the
    // atom-style variable + fix addforce it replaced, which took about 7 % of the loop (docs/measurements/liggghts.md)
    if (c.cell.annulus_radius > 0)
        line(fmt::format("fix cent {} centripetal/annulus {}", g, c.cell.annulus_radius));
    line(fmt::format("fix integr {} nve/sphere", g));
}

// The wall-force file: every wall's force on the grains, block means of sample_every steps.
void slice_wall_forces(const Settings& s, const DeckLine& line) {
    const auto& box = s.box;
    line("# wall forces (on the grains), averaged over blocks of sample_every steps, sampled every step");
    line("# (impulse forces last one step). Columns: step, then fx fy fz of bottom, top[, fx fx fy fy of the side walls].");
    // compute wall/gran/force (plugins/liggghts/doc/compute_wall_gran_force.txt): every wall's force in one
    // pass, the same bits as a compute reduce per wall, which took about 10 % of the loop (docs/measurements/liggghts.md)
    // vector: fx fy fz of wbot, wtop[, wsid1, wsid2]
    line(fmt::format("compute fwall all wall/gran/force wbot wtop{}", box.periodic_z ? "" : " wsid1 wsid2"));
    std::string cols = "c_fwall[1] c_fwall[2] c_fwall[3] c_fwall[4] c_fwall[5] c_fwall[6]";
    if (s.bumps()) cols = bump_force_columns(s, line);
    // x: the side walls' drag; y: what they carry of the grains' weight (the vertical balance)
    if (!box.periodic_z) cols += side_force_columns(s, line);
    line(fmt::format("fix walls all ave/time 1 {0} {0} {1} file {2}", s.sample_every, cols, kWallFile));
    line(fmt::format("# wall area A = L W = {} m^2: normal stress bottom = f_y(bottom)/A, top = -f_y(top)/A",
                     box.length * box.width));
}

// Load control (README "Load control"): a plate servo in the deck. Every servo_every steps the
// plate moves by gain d clamp((P_top - P)/P, -1, max_error), P_top the top-wall stress averaged
// over those steps (summed every step: the impulsive force is integrated, not sampled), then
// clamped to [gap_min, gap_max]. An integral controller: at steady state the plate's mean
// drift is zero, so the window-averaged P_top equals P (while the clamps are inactive).
void slice_servo_loop(const Case& c, const Settings& s, const std::string& top_wall, const DeckLine& line) {
    const double A = s.box.length * s.box.width;
    const double d_g = c.grains.diameter;
    line("");
    if (s.weight_plate) return weight_plate_run(s, line, "wtop");
    line(fmt::format("# load control: top plate servo, target normal stress P = {} Pa on A = {} m^2", s.target_stress,
                     A));
    line(fmt::format("# every {} steps: hplate += {} * err, err = clamp((P_top - P)/P, -1, {}),", s.servo_every,
                     s.plate_gain * d_g, s.servo_max_error));
    if (s.plate_gain < s.servo_gain)
        line(fmt::format("# (soft contacts: the gain is capped so that a unit error moves the plate by one grain-plate "
                         "overlap at the load, {} m: a jump must not hammer the loaded contacts)", s.plate_overlap));
    line(fmt::format("# hplate kept in [{}, {}] m; plate position per update in {}", s.gap_min, s.gap_max, kPlateFile));
    servo_rule_block(s, line, s.bumps_top ? "v_wty" : "c_fwall[5]", "-", A, d_g);
    line("label servo");
    line(fmt::format("run             {} post no", s.servo_every));
    if (s.bumps_top) {  // the top's bumps jump with the plate
        line("variable dh equal ${hnew}-${hplate}");
        line("displace_atoms tbump move 0 ${dh} 0 units box");
    }
    line("variable hplate equal ${hnew}");
    line("unfix wtop");
    line(top_wall);
    line("next update");
    line("jump SELF servo");
}

}  // namespace

std::string deck(const Case& c, const OperatingPoint& p, const Settings& s, const ParticleSet& grains,
                 const std::string& provenance) {
    std::string d;
    const DeckLine line = deck_lines(d);
    slice_header(c, p, s, grains.size(), provenance, line);
    line("");
    engine_block(s, line, s.box.periodic_z ? "p f p" : "p f f", "* 1 1   # split along the flow only");
    line("");
    contact_block(c, p, s, line);
    line("");
    if (s.bumps()) bump_block(s, line, p.speed);
    const std::string top_wall = slice_walls(c, p, s, grains, line);
    line("");
    slice_body_forces(c, s, line);
    line("");
    slice_wall_forces(s, line);
    line("");
    line("# particle snapshots for coarse-graining across the gap");
    output_block(s, line);
    if (fixed_top_ending(s, line)) return d;
    slice_servo_loop(c, s, top_wall, line);
    persistence_block(s, line);  // after the last servo window (`next` skips the jump)
    final_state_block(s, line);
    return d;
}

}  // namespace granlub::dem
