# One enduring Hertz-Mindlin contact in YADE, the twin of one_contact.in in LIGGGHTS
# (tests/yade/test_enduring_contact.cpp): the project driver's materials (granlub_yade.py, with its
# wall material mapped to LIGGGHTS' grain-wall stiffness), a sphere on a wall box, free along y
# only, pressed by Fn(t); it slides at V for n_slide steps, stops, and Fn ramps from F0 to 2 F0.
#   yade -n -j1 -x one_contact.py params.json   (keys: driver_dir E nu d rho F0 delta0 V dt
#                                                n_slide n_hold n_ramp out)
import json
import os
import sys

cfg = json.load(open(sys.argv[1]))
sys.path.insert(0, cfg["driver_dir"])
from yade import *  # noqa: F401,F403
import granlub_yade as G

d, r = cfg["d"], 0.5 * cfg["d"]
p = {"model": "hertz",
     "grains": {"youngs_modulus": cfg["E"], "poisson_ratio": cfg["nu"], "density": cfg["rho"], "diameter": d},
     "materials": {n: {"restitution": 0.9, "friction": 0.5} for n in ("grain",) + G.WALLS}}
ids, ip2, law = G.build_materials(p)
wall = O.bodies.append(utils.box(center=(0, -0.5 * d, 0), extents=(100 * d, 0.5 * d, 100 * d), fixed=True,
                                 material=ids["bottom"], color=(0.5, 0.5, 0.5)))
s = O.bodies.append(utils.sphere((0, r - cfg["delta0"], 0), r, material=ids["grain"], color=(0, 0, 1)))
O.bodies[s].state.blockedDOFs = "xzXYZ"
O.bodies[s].state.vel = Vector3(cfg["V"], 0, 0)
dt, F0 = cfg["dt"], cfg["F0"]
n_slide, n_hold, n_ramp = cfg["n_slide"], cfg["n_hold"], cfg["n_ramp"]
out = open(cfg["out"], "w")


def fn_at(k):  # the force program by step, as the LIGGGHTS twin's by time
    x = (k - n_slide - n_hold) / float(n_ramp)
    return F0 * (1 + min(max(x, 0.0), 1.0))


def step():
    k = O.iter
    if k == n_slide:
        v = O.bodies[s].state.vel
        O.bodies[s].state.vel = Vector3(0, v[1], 0)
    O.forces.setPermF(s, Vector3(0, -fn_at(k), 0))
    f = O.forces.f(wall)
    out.write("%.17g %.17g %.17g\n" % (O.time, -f[0], -f[1]))  # the wall's force on the sphere


O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb(), Bo1_Box_Aabb()]),
             InteractionLoop([Ig2_Sphere_Sphere_ScGeom(), Ig2_Box_Sphere_ScGeom()], [ip2], [law]),
             NewtonIntegrator(damping=0.0, gravity=(0, 0, 0)), PyRunner(command="one_contact_step()", iterPeriod=1)]
import __main__
__main__.one_contact_step = step
O.dt = dt
O.forces.setPermF(s, Vector3(0, -F0, 0))
O.run(n_slide + 2 * n_hold + n_ramp, True)
out.close()
