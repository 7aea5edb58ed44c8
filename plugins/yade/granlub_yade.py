# granlub's YADE driver: the only YADE-side code of the project (plugins/yade/README.md).
#
#   yade -n -j1 -x granlub_yade.py params.json
#
# params.json is written by `granlub yade` (plugins/yade/src/driver.cpp); this script never
# generates code from it. Two tasks:
#   "couette"   the plane Couette cell of `granlub dem`: grains from the shared initial file,
#               flat walls at y = 0 (moving at +U along x) and y = H, side walls at z = +-W/2
#               (or periodic z), gravity along -y, centripetal body force v_x^2/(R_a - z) along -z.
#               Side walls slide with the bottom wall, as in `granlub dem`.
#               Writes wallforce.csv, samples.bin and, last, driver_summary.json.
#               With a "servo" object (control = "load"): the top wall is a plate moved every
#               servo.every steps by the servo of `granlub dem` (core/include/granlub/particles/servo.h);
#               its position after each window goes to plate.csv.
#               With a "bumps" object ({"bottom"|"top": {"diameter", "x": [...], "z": [...]}}): rough
#               walls, fixed spheres centred on the wall's plane (core/include/granlub/case/wall_bumps.h);
#               the top's bumps move with the plate, under a weight plate as one rigid body with it.
#               "start_time" (s, default 0): the starting state's time since the grains' cold
#               start; the bumps come placed for it (the floor's moved U start_time), and the final
#               state's time counts on from it (core particles.h ParticleState::time).
#   "collision" binary collisions (grain-grain and grain-wall for every wall material): the
#               measured normal restitution of the contact law as run, in collision.json.
#
# Geometry inside YADE: YADE's cell is periodic in all three directions, so the gap is placed
# inside a taller y period (docs/yade-notes.md §2): YADE y = y + Y0 with walls outside [Y0, Y0 + H].
# Walls are thin boxes, much longer than the x period, with allowBiggerThanPeriod and the
# collider sorting along y, the wall-normal axis (docs/yade-notes.md §5: utils.wall hangs a periodic
# collider; sorting along x loses wall contacts). Outputs use granlub's coordinates.
#
# Exit codes: 0 done, 2 bad parameters (message on stderr), 1 any other failure.
import json
import math
import os
import random
import struct
import sys
import time

_RUN_AS_SCRIPT = __name__ == "__main__"  # `from yade import *` rebinds __name__ to "yade"
from yade import *  # noqa: F401,F403  (O, engines, materials, utils: the launcher's namespace)
import yade

FORMAT = "granlub-yade/1"
WALLS = ("bottom", "top", "side")


class ParamError(Exception):
    pass


def need(d, key, where, kind=float, positive=False, non_negative=False):
    if key not in d:
        raise ParamError("%s: missing key '%s'" % (where, key))
    v = d[key]
    try:
        v = kind(v)
    except (TypeError, ValueError):
        raise ParamError("%s.%s = %r: not a %s" % (where, key, d[key], kind.__name__))
    if kind is float and not math.isfinite(v):
        raise ParamError("%s.%s = %r: not finite" % (where, key, v))
    if positive and not v > 0:
        raise ParamError("%s.%s = %r: must be > 0" % (where, key, v))
    if non_negative and not v >= 0:
        raise ParamError("%s.%s = %r: must be >= 0" % (where, key, v))
    return v


def load_params(path):
    try:
        with open(path) as f:
            p = json.load(f)
    except (OSError, ValueError) as e:
        raise ParamError("cannot read parameter file %s: %s" % (path, e))
    if p.get("format") != FORMAT:
        raise ParamError("%s: format is %r, this driver reads %r" % (path, p.get("format"), FORMAT))
    if p.get("task") not in ("couette", "collision"):
        raise ParamError("%s: task = %r (allowed: couette, collision)" % (path, p.get("task")))
    if p.get("model") not in LAWS:
        raise ParamError("%s: model = %r (allowed: %s)" % (path, p.get("model"), ", ".join(LAWS)))
    g = p.get("grains", {})
    for k in ("diameter", "density", "youngs_modulus"):
        need(g, k, "grains", positive=True)
    need(g, "poisson_ratio", "grains")
    mats = p.get("materials", {})
    for name in ("grain",) + WALLS:
        m = mats.get(name)
        if m is None:
            raise ParamError("materials: missing '%s'" % name)
        e = need(m, "restitution", "materials." + name)
        if not 0 < e <= 1:
            raise ParamError("materials.%s.restitution = %r: allowed (0, 1]" % (name, e))
        need(m, "friction", "materials." + name, non_negative=True)
    c = p.get("contact", {})
    need(c, "dt", "contact", positive=True)
    LAWS[p["model"]].check(c)
    if p["task"] == "couette":
        cell = p.get("cell", {})
        for k in ("gap", "length", "width"):
            need(cell, k, "cell", positive=True)
        need(p, "wall_speed", "(top level)")
        need(p, "gravity", "(top level)")
        need(p, "annulus_radius", "(top level)", non_negative=True)
        r = p.get("run", {})
        steps = need(r, "steps", "run", int, positive=True)
        for k in ("sample_every", "snapshot_every"):
            every = need(r, k, "run", int, positive=True)
            if steps % every:
                raise ParamError("run.steps = %d is not a multiple of run.%s = %d" % (steps, k, every))
        need(r, "body_force_every", "run", int, positive=True)
        need(r, "verlet_distance", "run", positive=True)
        if "start_time" in p:
            need(p, "start_time", "(top level)", non_negative=True)
        sv = p.get("servo")
        if sv is not None:
            for k in ("target_stress", "step", "max_error", "gap_min", "gap_max"):
                need(sv, k, "servo", positive=True)
            if sv.get("plate", "window") not in ("window", "weight"):
                raise ParamError("servo.plate = %r (allowed: window, weight)" % sv.get("plate"))
            if sv.get("plate") == "weight":
                need(sv, "plate_mass_ratio", "servo", positive=True)
            every = need(sv, "every", "servo", int, positive=True)
            if every % r["sample_every"] or steps % every:
                raise ParamError("servo.every = %d must be a multiple of run.sample_every = %d and divide "
                                 "run.steps = %d" % (every, r["sample_every"], steps))
            if not sv["gap_min"] < cell["gap"] <= sv["gap_max"]:
                raise ParamError("servo: the plate limits [%g, %g] m must hold the initial gap %g m"
                                 % (sv["gap_min"], sv["gap_max"], cell["gap"]))
        for side, layer in p.get("bumps", {}).items():
            if side not in ("bottom", "top", "sides"):
                raise ParamError("bumps.%s: allowed bottom, top, sides" % side)
            need(layer, "diameter", "bumps." + side, positive=True)
            across = "y" if side == "sides" else "z"
            if len(layer.get("x", [])) != len(layer.get(across, [])) or not layer.get("x"):
                raise ParamError("bumps.%s: x and %s must be lists of the same, non-zero length" % (side, across))
            if side == "sides" and cell.get("periodic_z"):
                raise ParamError("bumps.sides with cell.periodic_z: there are no side walls")
        if not os.path.isfile(p.get("initial_file", "")):
            raise ParamError("initial_file %r: no such file" % p.get("initial_file"))
    return p


# ---------------------------------------------------------------------------------------------
# Contact laws.


def hertz_wall_material(E, nu):
    """Young's modulus and Poisson ratio of the wall material for which YADE's Hertz-Mindlin
    grain-wall contact has LIGGGHTS' grain-wall stiffness.

    LIGGGHTS hertz/history (normal_model_hertz.h, tangential_model_history.h) treats a wall as a
    body of infinite radius: R* = r, Y* = 1/((1-nu^2)/E + (1-nu_w^2)/E_w), G* = 1/(2(2-nu)(1+nu)/E
    + 2(2-nu_w)(1+nu_w)/E_w), kn = 4/3 Y* sqrt(R* delta), kt = 8 G* sqrt(R* delta). The walls
    are the grains' material (assumption shared with plugins/liggghts).
    YADE 2023.02a (Ip2_FrictMat_FrictMat_MindlinPhys, Ig2_Box_Sphere_ScGeom) gives a box the
    sphere's radius, so R = r/2, with kno = 4/3 E' sqrt(R), 1/E' = (1-va^2)/Ea + (1-vb^2)/Eb, and
    kso = 8 G' sqrt(R), 1/G' = (2-va)/Ga + (2-vb)/Gb, Gi = Ei/(2(1+vi)): the same effective moduli
    as LIGGGHTS (measured: kso of a grain-grain pair is LIGGGHTS' to 1e-9; an earlier mapping that
    assumed the older averaged form 2 sqrt(4R) (Ga+Gb)/2 / (2 - (va+vb)/2) left the grain-wall
    kt 7 % low, tests/yade/test_enduring_contact.cpp). Solve kno(Ew, vw) and kso(Ew, vw) =
    LIGGGHTS' values (bisection on vw)."""
    Ystar = 1.0 / (2.0 * (1 - nu * nu) / E)
    Gstar = 1.0 / (4.0 * (2 - nu) * (1 + nu) / E)
    Rb = 0.5  # YADE's box-sphere equivalent radius for r = 1; LIGGGHTS' is 1
    Ep_target = Ystar / math.sqrt(Rb)  # 4/3 E' sqrt(Rb) = 4/3 Y* sqrt(1)
    Gp_target = Gstar / math.sqrt(Rb)  # 8 G' sqrt(Rb) = 8 G* sqrt(1)

    def Ew_for(vw):
        inv = 1.0 / Ep_target - (1 - nu * nu) / E
        if inv <= 0:
            return None
        return (1 - vw * vw) / inv

    def kt_err(vw):
        Ew = Ew_for(vw)
        G, Gw = E / (2 * (1 + nu)), Ew / (2 * (1 + vw))
        return 1.0 / ((2 - nu) / G + (2 - vw) / Gw) - Gp_target

    lo, hi = -0.99, 0.499
    if Ew_for(lo) is None or kt_err(lo) * kt_err(hi) > 0:
        raise ParamError("no wall material reproduces LIGGGHTS' grain-wall Hertz-Mindlin stiffness "
                         "for E = %g, nu = %g" % (E, nu))
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if kt_err(lo) * kt_err(mid) <= 0:
            hi = mid
        else:
            lo = mid
    vw = 0.5 * (lo + hi)
    return Ew_for(vw), vw


def viscel_restitution(p, en, wall):
    """Measured restitution of a ViscElMat contact with parameter en (one binary collision)."""
    return collide(p, {"grain": en, "bottom": en, "top": en, "side": en}, "bottom" if wall else None)[0]


def calibrate_viscel(p):
    """ViscElMat's linear spring-dashpot (Pournin 2001) with the attractive part of the force
    clipped gives e slightly off en (docs/yade-notes.md §3: en 0.9 -> 0.9003, 0.6 -> 0.6250). The
    restitution of the model is velocity-independent, so en is found once per pair by a secant
    search on the measured e of one binary collision. Returns en per material."""
    en = {}
    cache = {}
    for name in ("grain",) + WALLS:
        target = p["materials"][name]["restitution"]
        wall = name != "grain"
        key = (target, wall)
        if key in cache:
            en[name] = cache[key]
            continue
        if target >= 1.0:
            en[name] = cache[key] = 1.0
            continue
        x0, x1 = target, max(1e-3, target - 0.02)
        f0 = viscel_restitution(p, x0, wall) - target
        f1 = viscel_restitution(p, x1, wall) - target
        for _ in range(30):
            if abs(f1) < 1e-6 or f1 == f0:
                break
            x2 = min(0.9999, max(1e-4, x1 - f1 * (x1 - x0) / (f1 - f0)))
            x0, f0 = x1, f1
            x1, f1 = x2, viscel_restitution(p, x2, wall) - target
        if abs(f1) > 1e-4:
            raise RuntimeError("restitution calibration failed for %s: target %g, reached %g"
                               % (name, target, f1 + target))
        en[name] = cache[key] = x1
    return en


class ViscEl:
    """YADE's ViscElMat linear spring-dashpot (Pournin et al. 2001) with small e_t: the closest to
    the impulse operator."""

    @staticmethod
    def check(c):
        need(c, "contact_time", "contact", positive=True)
        et = need(c, "tangential_restitution", "contact")
        if not 0 < et <= 1:
            raise ParamError("contact.tangential_restitution = %r: allowed (0, 1]" % et)
        need(c, "wall_mass", "contact", positive=True)

    @staticmethod
    def calibrate(p):
        return calibrate_viscel(p) if p["contact"].get("calibrate", True) else None

    @staticmethod
    def material(p, name):
        c = p["contact"]
        return ViscElMat(tc=c["contact_time"], en=0.9, et=c["tangential_restitution"], frictionAngle=0.0,
                         density=p["grains"]["density"], label=name)

    @staticmethod
    def functors(p, pairs, fric, en_override):
        # Law2_ScGeom_ViscElPhys_Basic: kn = m*(pi^2 + ln^2 en)/tc^2, cn = -2 m* ln(en)/tc
        # (Pournin et al. 2001); the tangential dashpot with et -> 0 stops sliding at zero slip,
        # as in Walton's operator with beta0 = 0 (docs/yade-notes.md §3).
        mats = p["materials"]
        en = en_override if en_override is not None else {n: mats[n]["restitution"] for n in mats}
        ip2 = Ip2_ViscElMat_ViscElMat_ViscElPhys(en=MatchMaker(matches=pairs(lambda n: en[n]), algo="avg"),
                                                 frictAngle=MatchMaker(matches=pairs(fric), algo="avg"))
        return ip2, Law2_ScGeom_ViscElPhys_Basic()

    @staticmethod
    def wall_mass(p):
        # ViscElMat needs a wall mass: with mass 0 the reduced mass becomes m/2 and e is wrong
        # (docs/yade-notes.md §3: 0.9285 instead of 0.9).
        return p["contact"]["wall_mass"]


class Hertz:
    """Hertz-Mindlin with Tsuji damping, the LIGGGHTS hertz/history form."""

    @staticmethod
    def check(c):
        pass

    @staticmethod
    def calibrate(p):
        return None

    @staticmethod
    def material(p, name):
        g = p["grains"]
        E, nu = g["youngs_modulus"], g["poisson_ratio"]
        Ew, vw = hertz_wall_material(E, nu)
        return FrictMat(young=E if name == "grain" else Ew, poisson=nu if name == "grain" else vw,
                        frictionAngle=0.0, density=g["density"], label=name)

    @staticmethod
    def functors(p, pairs, fric, en_override):
        # Hertz-Mindlin with Tsuji et al. (1992) damping, the LIGGGHTS hertz/history form:
        # alpha = -sqrt(5/6) 2 ln e / sqrt(ln^2 e + pi^2) sqrt(2 E* sqrt(R*)), cn = alpha sqrt(m*) delta^1/4.
        mats = p["materials"]
        e = lambda n: mats[n]["restitution"]
        ip2 = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(matches=pairs(e), algo="avg"),
                                                es=MatchMaker(matches=pairs(e), algo="avg"),
                                                frictAngle=MatchMaker(matches=pairs(fric), algo="avg"))
        return ip2, Law2_ScGeom_MindlinPhys_Mindlin()

    @staticmethod
    def wall_mass(p):
        return None


# The laws, by their YADE spelling in granlub's contact-law table (core/src/particles/contact_laws.cpp,
# .yade), which `granlub yade` writes as params.json's "model"; the repo_doc_file_lists test checks
# that these are the table's YADE laws.
LAWS = {"viscel": ViscEl, "hertz": Hertz}


def build_materials(p, en_override=None):
    """Materials grain/bottom/top/side and the engines' InteractionLoop functors."""
    law = LAWS[p["model"]]
    ids = {}
    for name in ("grain",) + WALLS:
        ids[name] = O.materials.append(law.material(p, name))
    gid = ids["grain"]
    mats = p["materials"]

    def pairs(value_of):
        m = [(gid, gid, value_of("grain"))]
        for w in WALLS:
            m.append((gid, ids[w], value_of(w)))
        return m

    def fric(name):
        return math.atan(mats[name]["friction"])

    ip2, law2 = law.functors(p, pairs, fric, en_override)
    return ids, ip2, law2


def wall_box(center, half, mat, p):
    b = utils.box(center=center, extents=half, fixed=True, material=mat, color=(0.5, 0.5, 0.5))
    give_wall_mass(b, p)
    return O.bodies.append(b)


def give_wall_mass(b, p):
    """A fixed wall body's mass, where its law needs one (ViscEl.wall_mass)."""
    mass = LAWS[p["model"]].wall_mass(p)
    if mass is not None:
        b.state.mass = mass


# ---------------------------------------------------------------------------------------------
# Binary collisions.


def collide(p, en, wall_name, vn=1.0):
    """One head-on collision, no gravity, in a fresh scene; returns e = -v_n'/v_n and the
    contact duration (steps with overlap times dt)."""
    O.reset()
    d = p["grains"]["diameter"]
    r = 0.5 * d
    ids, ip2, law = build_materials(p, en)
    gap = 0.05 * d
    if wall_name is None:
        a = O.bodies.append(utils.sphere((0, 0, 0), r, material=ids["grain"], color=(0, 0, 1)))
        b = O.bodies.append(utils.sphere((d + gap, 0, 0), r, material=ids["grain"], color=(0, 0, 1)))
        O.bodies[a].state.vel = Vector3(0.5 * vn, 0, 0)
        O.bodies[b].state.vel = Vector3(-0.5 * vn, 0, 0)
        measure = lambda: (O.bodies[b].state.vel[0] - O.bodies[a].state.vel[0]) / vn
    else:
        a = O.bodies.append(utils.sphere((0, r + gap, 0), r, material=ids["grain"], color=(0, 0, 1)))
        wall_box((0, -0.5 * d, 0), (10 * d, 0.5 * d, 10 * d), ids[wall_name], p)
        O.bodies[a].state.vel = Vector3(0, -vn, 0)
        measure = lambda: O.bodies[a].state.vel[1] / vn
    O.engines = [ForceResetter(),
                 InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
                 InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [ip2], [law]),
                 NewtonIntegrator(damping=0.0, gravity=(0, 0, 0))]
    O.dt = p["contact"]["dt"]  # the run's time step, so a calibration includes its discretisation
    # approach, contact, separation: step until the contact is gone after having existed
    t_on = None
    for _ in range(1000000):
        O.step()
        touching = any(i.isReal and i.geom.penetrationDepth > 0 for i in O.interactions)
        if touching and t_on is None:
            t_on = O.time
        elif not touching and t_on is not None:
            return measure(), O.time - t_on
    raise RuntimeError("binary collision did not end")


def run_collision(p):
    out = p["output_dir"]
    result = {"format": FORMAT, "task": "collision", "model": p["model"], "yade_version": yade.config.version}
    en = LAWS[p["model"]].calibrate(p)
    if en is not None:
        result["en"] = en
    vn = float(p.get("impact_speed", 1.0))
    e, tc = {}, {}
    e["grain"], tc["grain"] = collide(p, en, None, vn)
    for w in WALLS:
        e[w], tc[w] = collide(p, en, w, vn)
    result["restitution"] = e
    result["contact_duration"] = tc
    result["impact_speed"] = vn
    write_json(os.path.join(out, "collision.json"), result)


# ---------------------------------------------------------------------------------------------
# The Couette cell.


GRAIN_COLUMNS = ["x", "y", "z", "vx", "vy", "vz", "radius"]
SPIN_COLUMNS = GRAIN_COLUMNS + ["wx", "wy", "wz"]


def read_initial(path):
    """x,y,z,vx,vy,vz,radius[,wx,wy,wz] rows after '#' comments (core/include/granlub/particles/particles.h);
    rows of 10 values (spins zero when the file has none)."""
    rows = []
    header = None
    with open(path) as f:
        for n, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if header is None:
                header = line.split(",")
                if header not in (GRAIN_COLUMNS, SPIN_COLUMNS):
                    raise ParamError("%s:%d: header %r, expected %s or %s"
                                     % (path, n, line, ",".join(GRAIN_COLUMNS), ",".join(SPIN_COLUMNS)))
                continue
            try:
                v = [float(t) for t in line.split(",")]
            except ValueError:
                raise ParamError("%s:%d: not a row of numbers" % (path, n))
            if len(v) != len(header):
                raise ParamError("%s:%d: %d values, expected %d" % (path, n, len(v), len(header)))
            rows.append(v + [0.0] * (10 - len(v)))
    if not rows:
        raise ParamError("%s: no grains" % path)
    return rows


def write_json(path, obj):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(obj, f, indent=1, sort_keys=True)
        f.write("\n")
    os.replace(tmp, path)


BUMPS_APART = 16 | 32 | 64  # the bump layers' own bits: a bump never meets a bump of its wall


class Couette:
    """The plane Couette cell of one run. run_couette() calls its parts in order: the walls, the
    grains, the bumps, the loaded plate, the outputs, the engines; then the run, the contact
    persistence after it, and the summary. The PyRunners call the hooks in __main__."""

    def __init__(self, p):
        self.t_start = time.time()
        self.p = p
        self.out = p["output_dir"]
        cell = p["cell"]
        self.H, self.L, self.W = cell["gap"], cell["length"], cell["width"]
        self.periodic_z = bool(cell.get("periodic_z", False))
        self.U, self.g, self.Ra = p["wall_speed"], p["gravity"], p["annulus_radius"]
        self.d = p["grains"]["diameter"]
        self.run = p["run"]
        self.en = LAWS[p["model"]].calibrate(p)
        self.grains = read_initial(p["initial_file"])
        self.servo = p.get("servo")
        self.top_max = self.servo["gap_max"] if self.servo else self.H  # highest top-wall position
        self.weight = bool(self.servo) and self.servo.get("plate", "window") == "weight"

    # -- walls ----------------------------------------------------------------------------------

    def build_walls(self):
        H, L, W, d = self.H, self.L, self.W, self.d
        O.reset()
        t = self.t = d  # wall half thickness
        # granlub y = 0 sits at YADE y = Y0; the y period is H + top_max + H (docs/yade-notes.md §2)
        Y0 = self.Y0 = H
        Ly = 2 * H + self.top_max
        if self.periodic_z:
            Lz, self.Z0 = W, 0.5 * W
            wall_z = 1000 * W
        else:
            Lz, self.Z0 = W + 4 * t + 2 * d, 0.5 * W + 2 * t + d
            wall_z = 0.5 * W + 2 * t
        Z0 = self.Z0
        O.periodic = True
        O.cell.setBox(L, Ly, Lz)
        self.ids, self.ip2, self.law = build_materials(self.p, self.en)
        ids = self.ids
        big = 1000 * L
        self.bottom = wall_box((0.5 * L, Y0 - t, Z0), (big, t, wall_z), ids["bottom"], self.p)
        self.top = wall_box((0.5 * L, Y0 + H + t, Z0), (big, t, wall_z), ids["top"], self.p)
        self.moving = [self.bottom]
        self.sides = []
        if not self.periodic_z:
            # side walls slide with the bottom wall, as in the annular cell (cases/sawyer2001) and
            # `granlub dem` (fix wall/gran ... zplane ... shear x U)
            for sgn in (-1, 1):
                self.sides.append(wall_box((0.5 * L, Y0 + 0.5 * self.top_max, Z0 + sgn * (0.5 * W + t)),
                                           (big, 0.5 * self.top_max + 2 * t, t), ids["side"], self.p))
            self.moving += self.sides
        for w in self.moving:
            O.bodies[w].state.vel = Vector3(self.U, 0, 0)  # kinematic: NewtonIntegrator moves it

    def place_grains(self):
        H, L, W, Y0, Z0 = self.H, self.L, self.W, self.Y0, self.Z0
        first = len(O.bodies)
        for (x, y, z, vx, vy, vz, r, wx, wy, wz) in self.grains:
            # a warm start's grains may touch a wall: overlaps up to initial_overlap x the radius pass
            # (1 %; a continued run's own soft contacts under load: 10 %)
            tol = self.p.get("initial_overlap", 0.01) * r
            if not (r > 0 and r - tol <= y <= H - r + tol):
                raise ParamError("initial grain at y = %g (radius %g) is not between the walls" % (y, r))
            if not self.periodic_z and not (-0.5 * W + r - tol <= z <= 0.5 * W - r + tol):
                raise ParamError("initial grain at z = %g (radius %g) is not between the side walls" % (z, r))
            b = utils.sphere((x % L, y + Y0, z + Z0), r, material=self.ids["grain"], color=(0, 0, 1))
            b.state.vel = Vector3(vx, vy, vz)
            b.state.angVel = Vector3(wx, wy, wz)
            O.bodies.append(b)
        self.n = len(self.grains)
        self.gids = range(first, first + self.n)
        self.masses = [O.bodies[i].state.mass for i in self.gids]

    # -- bumps ----------------------------------------------------------------------------------

    def place_bumps(self):
        # Rough walls (core wall_bumps.h): fixed spheres with their centres on the wall's plane, the
        # floor's moving with it, the top's with the plate (the window servo's moves, or a weight
        # plate's dynamics: carry_top_bumps). Collision masks (two bodies meet when their masks
        # share a bit, unless the masks are equal and share a bit with the collider's
        # avoidSelfInteractionMask, BUMPS_APART): grains (1|2|4|8) meet the wall boxes (1) and every
        # layer; a layer (2|16, 4|32, side walls 8|64) meets neither the boxes, nor another layer,
        # nor itself. The side walls' bumps (both walls, one layout at z = -W/2 and W/2) move with
        # the floor.
        H, W, U, Y0, Z0 = self.H, self.W, self.U, self.Y0, self.Z0
        self.bumps = bumps = {"bottom": [], "top": [], "side1": [], "side2": []}
        layers = self.p.get("bumps", {})
        if layers:
            masks = {"bottom": 2 | 16, "top": 4 | 32, "side1": 8 | 64, "side2": 8 | 64}
            material = {"bottom": "bottom", "top": "top", "side1": "side", "side2": "side"}
            for i in self.gids:
                O.bodies[i].groupMask = 1 | 2 | 4 | 8
            placed = []  # (wall, layer, centre(x, across), vx)
            for side, y0, vx in (("bottom", 0.0, U), ("top", H, 0.0)):
                if side in layers:
                    placed.append((side, layers[side], lambda x, z, y0=y0: (x, Y0 + y0, z + Z0), vx))
            if "sides" in layers:
                for side, zw in (("side1", -0.5 * W), ("side2", 0.5 * W)):
                    placed.append((side, layers["sides"], lambda x, y, zw=zw: (x, Y0 + y, zw + Z0), U))
            for side, layer, centre, vx in placed:
                across = layer["y"] if side.startswith("side") else layer["z"]
                for x, a in zip(layer["x"], across):
                    b = utils.sphere(centre(x, a), 0.5 * layer["diameter"], material=self.ids[material[side]],
                                     fixed=True, color=(0.5, 0.5, 0.5))
                    b.groupMask = masks[side]
                    give_wall_mass(b, self.p)  # as the wall boxes (reduced mass m)
                    b.state.vel = Vector3(vx, 0, 0)
                    bumps[side].append(O.bodies.append(b))

    # -- the loaded plate -----------------------------------------------------------------------

    def load_plate(self):
        self.A = self.L * self.W
        self.f_load = 0.0  # the permanent force on a weight plate (N, along y); O.forces.f() includes it
        if self.weight:
            # A loaded plate, as the experiment's weighted upper disc: a body of mass M free along y
            # only, pressed by P A in all (its weight M g under the cell's gravity, the rest a
            # constant force); no controller. At steady state its mean acceleration is zero, so the
            # mean force of the grains on it is P A. M = plate_mass_ratio x the grains' mass is a
            # numerical choice (the disc's mass is not reported); a plate as heavy as the grains
            # follows the bed's dilation within a millisecond, a dead weight (M = P A / g)
            # oscillates for tens of ms.
            M = self.servo["plate_mass_ratio"] * sum(self.masses)
            pb = O.bodies[self.top]
            pb.dynamic = True
            pb.state.blockedDOFs = "xzXYZ"
            pb.state.mass = M
            pb.state.inertia = Vector3(1.0, 1.0, 1.0)  # rotations are blocked; YADE needs a value
            pb.state.vel = Vector3(0, 0, 0)
            self.f_load = -(self.servo["target_stress"] * self.A - M * self.g)
            O.forces.setPermF(self.top, Vector3(0, self.f_load, 0))
        # A weight plate with bumps: plate and bumps are one rigid body. The bumps stay fixed
        # (non-dynamic) spheres; before NewtonIntegrator the force of the grains on them is added to
        # the plate (plate_force), after it they are put back on the plate's lower face with its
        # velocity (carry_top_bumps). The plate's mass M is the body's; rotations are blocked, so
        # the bumps' torques do not matter. [ASSUMPTION] slaving instead of a YADE clump: a clump
        # would take its mass and inertia from the 1000-period box and its members.
        self.carried = self.weight and bool(self.bumps["top"])

    def plate_force(self):
        f = Vector3(0, 0, 0)
        for i in self.bumps["top"]:
            f += O.forces.f(i, sync=True)
        O.forces.addF(self.top, f)

    def carry_top_bumps(self):
        b = O.bodies[self.top].state
        y, v = b.pos[1] - self.t, Vector3(0, b.vel[1], 0)
        for i in self.bumps["top"]:
            q = O.bodies[i].state
            q.pos = Vector3(q.pos[0], y, q.pos[2])
            q.vel = v

    def plate_update(self, k):
        servo, state, Y0, t = self.servo, self.state, self.Y0, self.t
        if self.weight:
            # the plate's position at the window's end; kept in [gap_min, gap_max] (stopped there)
            state["f_servo"] = 0.0
            b = O.bodies[self.top].state
            h = b.pos[1] - Y0 - t
            if not servo["gap_min"] <= h <= servo["gap_max"]:
                h = min(max(h, servo["gap_min"]), servo["gap_max"])
                b.pos = Vector3(b.pos[0], Y0 + h + t, b.pos[2])
                b.vel = Vector3(0, 0, 0)
                if self.carried:
                    self.carry_top_bumps()
            self.fplate.write("%d,%.17g\n" % (k, h))
            state["h"] = h
            return
        # The servo of `granlub dem` (core/include/granlub/particles/servo.h): P_top is the top-wall
        # stress averaged over the window (the force summed every step), the commanded position
        # moves by step * clamp((P_top - P)/P, -1, max_error) and stays in [gap_min, gap_max]. The
        # plate travels there at constant speed over the next window instead of jumping: a jump of
        # 0.05 d onto resting grains would be an overlap of 0.05 d with stiff contacts.
        P = servo["target_stress"]
        p_top = state["f_servo"] / servo["every"] / self.A
        state["f_servo"] = 0.0
        err = min(max((p_top - P) / P, -1.0), servo["max_error"])
        b = O.bodies[self.top].state
        b.pos = Vector3(b.pos[0], Y0 + state["h"] + t, b.pos[2])  # no drift from the integration
        self.fplate.write("%d,%.17g\n" % (k, state["h"]))
        h = min(max(state["h"] + servo["step"] * err, servo["gap_min"]), servo["gap_max"])
        b.vel = Vector3(0, (h - state["h"]) / (servo["every"] * O.dt), 0)
        for i in self.bumps["top"]:  # the top's bumps travel with the plate
            q = O.bodies[i].state
            q.pos = Vector3(q.pos[0], Y0 + state["h"], q.pos[2])
            q.vel = b.vel
        state["h"] = h

    # -- outputs --------------------------------------------------------------------------------

    def open_outputs(self):
        out, every, servo = self.out, self.run["sample_every"], self.servo
        self.state = {"f": [0.0] * 8, "steps": 0, "rows": 0, "snapshots": 0, "run_steps": 0, "persisting": False}
        self.fcsv = open(os.path.join(out, "wallforce.csv"), "w")
        self.fcsv.write("# force of the grains on the walls (N), mean over each interval of %d steps; "
                        "side: x force on each side wall\n" % every)
        self.fcsv.write("step,fx_bottom,fy_bottom,fz_bottom,fx_top,fy_top,fz_top,fx_side1,fx_side2\n")
        self.fbin = open(os.path.join(out, "samples.bin"), "wb")
        # top-wall force summed over the servo window; plate position
        self.state["f_servo"], self.state["h"] = 0.0, self.H
        self.fplate = None
        if servo:
            self.fplate = open(os.path.join(out, "plate.csv"), "w")
            self.fplate.write("# plate (top wall) position after each servo window of %d steps, m\n" % servo["every"])
            self.fplate.write("step,gap\n")

    def close_outputs(self):
        self.fcsv.close()
        self.fbin.close()
        if self.fplate:
            self.fplate.close()

    def averaging(self):
        # After NewtonIntegrator, every step: the force of the grains on each wall is summed
        # every step (contacts last a few steps) and its mean written every sample_every steps;
        # a snapshot of the grains every snapshot_every steps.
        if self.carried:
            self.carry_top_bumps()
        state, bumps = self.state, self.bumps
        if state["persisting"]:  # the result outputs are closed
            return
        fb = O.forces.f(self.bottom)
        ft = O.forces.f(self.top) - Vector3(0, self.f_load, 0)  # the grains' force alone
        for i in bumps["bottom"]:  # a rough wall: its plane's force plus its bumps'
            fb += O.forces.f(i)
        if not self.carried:  # a carried layer's force is in the plate's already (plate_force)
            for i in bumps["top"]:
                ft += O.forces.f(i)
        f = state["f"]
        f[0] += fb[0]; f[1] += fb[1]; f[2] += fb[2]
        f[3] += ft[0]; f[4] += ft[1]; f[5] += ft[2]
        if self.sides:
            f[6] += O.forces.f(self.sides[0])[0] + sum(O.forces.f(i)[0] for i in bumps["side1"])
            f[7] += O.forces.f(self.sides[1])[0] + sum(O.forces.f(i)[0] for i in bumps["side2"])
        state["steps"] += 1
        state["run_steps"] += 1
        k = state["run_steps"]
        every = self.run["sample_every"]
        if state["steps"] == every:
            self.fcsv.write("%d,%s\n" % (k, ",".join("%.17g" % (v / every) for v in f)))
            state["f"], state["steps"] = [0.0] * 8, 0
            state["rows"] += 1
        if self.servo:
            state["f_servo"] += ft[1]
            if k % self.servo["every"] == 0:
                self.plate_update(k)
        if k % self.run["snapshot_every"] == 0:
            self.snapshot()

    def snapshot(self, f=None):
        # granlub coordinates; columns x (wrapped into the period), y, z, vx, vy, vz: the slab
        # coarse-graining, the y x z cross-section, and the contact and order measures
        L, Y0, Z0 = self.L, self.Y0, self.Z0
        buf = []
        for i in self.gids:
            s = O.bodies[i].state
            v = s.vel
            buf.extend((s.pos[0] % L, s.pos[1] - Y0, s.pos[2] - Z0, v[0], v[1], v[2]))
        if f is not None:
            f.write(struct.pack("<%dd" % len(buf), *buf))
            return
        self.fbin.write(struct.pack("<%dd" % len(buf), *buf))
        self.state["snapshots"] += 1

    def housekeeping(self):
        # keep the moving walls within a few periods of the cell (their extent is 1000 periods). Not the
        # moving bumps: a sphere jumped by 10 periods keeps its interactions' periodic cell offsets, so
        # its contacts are computed against the wrong image and grains pass between the bumps (found by
        # run.wall_layer's bump check); a sphere needs no extent, and its unwrapped x loses nothing of
        # note in double precision over any run here.
        for w in self.moving:
            q = O.bodies[w].state.pos
            if q[0] > 10 * self.L:
                O.bodies[w].state.pos = Vector3(q[0] - 10 * self.L, q[1], q[2])
        total = self.run["steps"]  # the persistence steps after the run show as 100 %
        write_text(os.path.join(self.out, "progress"), "%d %d\n" % (min(O.iter, total), total))

    def centripetal(self):
        # Sawyer & Tichy 2001: a grain moving at v_x around the annulus (mean radius R_a) feels
        # m v_x^2 / (R_a - z) toward the outer wall, -z here; as `granlub dem` (fix centripetal/annulus).
        # A permanent force, refreshed every body_force_every steps: setting ~5000 forces from
        # Python costs about as much as 10 steps of the cell.
        Ra, Z0, masses = self.Ra, self.Z0, self.masses
        if Ra <= 0:
            return
        for k, i in enumerate(self.gids):
            s = O.bodies[i].state
            vx = s.vel[0]
            O.forces.setPermF(i, Vector3(0, 0, -masses[k] * vx * vx / (Ra - (s.pos[2] - Z0))))

    # -- engines --------------------------------------------------------------------------------

    def install_engines(self):
        run = self.run
        # The collider's Verlet distance (run.verlet_distance smallest radii): the interaction loop
        # visits every pair within it each step, the collider reruns once a grain has moved
        # further. Exact at any value; 0.2 was the cheapest on sawyer2001 (YADE's default 0.5: +25 %).
        # A weight plate carrying bumps: their force joins the plate's before it is integrated.
        before_newton = [PyRunner(command="granlub_plate_force()", iterPeriod=1, initRun=True)] if self.carried else []
        O.engines = [ForceResetter(),
                     InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()], allowBiggerThanPeriod=True,
                                           sortAxis=1, verletDist=-run["verlet_distance"],
                                           avoidSelfInteractionMask=BUMPS_APART),
                     InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [self.ip2], [self.law])] + \
            before_newton + \
            [NewtonIntegrator(damping=0.0, gravity=(0, -self.g, 0)),
             PyRunner(command="granlub_averaging()", iterPeriod=1, initRun=True),
             PyRunner(command="granlub_centripetal()", iterPeriod=run["body_force_every"]),
             PyRunner(command="granlub_housekeeping()", iterPeriod=1000)]
        # PyRunner commands run in the launcher's __main__ namespace
        import __main__
        __main__.granlub_averaging = self.averaging
        __main__.granlub_centripetal = self.centripetal
        __main__.granlub_housekeeping = self.housekeeping
        __main__.granlub_plate_force = self.plate_force
        O.dt = self.p["contact"]["dt"]
        self.centripetal()

    # -- the run and after it -------------------------------------------------------------------

    def simulate(self):
        total = self.run["steps"]
        t_run = time.time()
        O.run(total, True)  # total > 0 is checked: O.run(0, True) never returns (docs/yade-notes.md §5)
        self.wall_clock_run = time.time() - t_run
        self.run_time = O.time
        self.close_outputs()

    def persistence(self):
        # Contact persistence (core flow_regime.h), as granlub dem measures it: after the run, with
        # the result outputs closed, persistence_intervals + 1 snapshots persistence_every steps
        # apart (a shear strain of 0.1 each) in contacts.bin. The window servo's plate stays where
        # its last window left it (granlub dem's deck ends its servo loop likewise); a weight plate
        # stays free.
        self.p_every, self.p_intervals = self.run.get("persistence_every", 0), self.run.get("persistence_intervals", 0)
        self.state["persisting"] = True
        if self.p_every > 0 and self.p_intervals > 0:
            if self.servo and not self.weight:
                O.bodies[self.top].state.vel = Vector3(0, 0, 0)
                for i in self.bumps["top"]:
                    O.bodies[i].state.vel = Vector3(0, 0, 0)
            with open(os.path.join(self.out, "contacts.bin"), "wb") as fcon:
                self.snapshot(fcon)
                for _ in range(self.p_intervals):
                    O.run(self.p_every, True)
                    self.snapshot(fcon)

    def write_summary(self):
        total, every, snap_every = self.run["steps"], self.run["sample_every"], self.run["snapshot_every"]
        state = self.state
        if state["rows"] != total // every or state["snapshots"] != total // snap_every:
            raise RuntimeError("wrote %d wall-force rows and %d snapshots, expected %d and %d"
                               % (state["rows"], state["snapshots"], total // every, total // snap_every))
        write_final_state(os.path.join(self.out, "final_raw.csv"), self.gids, self.L, self.Y0, self.Z0,
                          O.bodies[self.top].state.pos[1] - self.Y0 - self.t if self.servo else self.H,
                          self.p.get("start_time", 0.0) + O.time)
        max_overlap = 0.0
        for i in O.interactions:
            if i.isReal:
                max_overlap = max(max_overlap, i.geom.penetrationDepth)
        persisted = self.p_every > 0 and self.p_intervals > 0
        summary = {
            "format": FORMAT, "task": "couette", "model": self.p["model"],
            "yade_version": yade.config.version, "grains": self.n, "dt": O.dt,
            "steps": total, "simulated_time": self.run_time,
            "persistence_every": self.p_every, "persistence_snapshots": self.p_intervals + 1 if persisted else 0,
            "sample_every": every, "wall_rows": state["rows"],
            "snapshot_every": snap_every, "snapshots": state["snapshots"],
            "snapshot_columns": ["x", "y", "z", "vx", "vy", "vz"],
            "max_overlap_over_d": max_overlap / self.d,
            "wall_clock_s": time.time() - self.t_start, "wall_clock_run_s": self.wall_clock_run,
        }
        if self.en is not None:
            summary["en"] = self.en
        if self.bumps["top"]:  # the top's bumps against the plate's lower face: 0 when they moved with it
            face = O.bodies[self.top].state.pos[1] - self.t
            summary["top_bumps_off_plate_m"] = max(abs(O.bodies[i].state.pos[1] - face) for i in self.bumps["top"])
        write_json(os.path.join(self.out, "driver_summary.json"), summary)


def run_couette(p):
    c = Couette(p)
    c.build_walls()
    c.place_grains()
    c.place_bumps()
    c.load_plate()
    c.open_outputs()
    c.install_engines()
    c.simulate()
    c.persistence()
    c.write_summary()


def write_final_state(path, gids, L, Y0, Z0, gap, sim_time):
    """The grains at the run's end in granlub coordinates, in the initial file's order and columns,
    with the top wall's position: `granlub yade` makes it the point's final_state.csv, from which a
    run not yet steady is continued ([yade] time_max)."""
    rows = ["# gap: %.17g" % gap, "# time: %.17g" % sim_time, ",".join(SPIN_COLUMNS)]
    for i in gids:
        s = O.bodies[i].state
        v, w = s.vel, s.angVel
        rows.append(",".join("%.17g" % q for q in (s.pos[0] % L, s.pos[1] - Y0, s.pos[2] - Z0, v[0], v[1], v[2],
                                                    O.bodies[i].shape.radius, w[0], w[1], w[2])))
    write_text(path, "\n".join(rows) + "\n")


def write_text(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main(argv):
    if len(argv) != 2:
        sys.stderr.write("usage: yade -n -j1 -x granlub_yade.py params.json\n")
        return 2
    try:
        p = load_params(argv[1])
        os.makedirs(p["output_dir"], exist_ok=True)
        random.seed(p.get("seed", 1))  # nothing here draws random numbers; keep any later use fixed
        if p["task"] == "collision":
            run_collision(p)
        else:
            run_couette(p)
    except ParamError as e:
        sys.stderr.write("granlub_yade.py: bad parameters: %s\n" % e)
        return 2
    return 0


if _RUN_AS_SCRIPT:
    rc = main(sys.argv)
    sys.stdout.flush()
    sys.stderr.flush()
    if rc:
        sys.exit(rc)
