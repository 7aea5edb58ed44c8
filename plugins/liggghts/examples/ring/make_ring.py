#!/usr/bin/env python3
"""Writes the meshes and grains of a small annular shear cell (the whole ring, not a slice) for
in.ring: floor.stl, inner.stl, outer.stl, top.stl (ASCII STL), grains.data and ring.vars.

Geometry (y is the ring's axis, gravity along -y): a trough of mean radius R and width W between
the cylinders r = R - W/2 and r = R + W/2, floor at y = 0, a flat annular top at y = H. The floor
and both cylinders turn at Omega = U / R about the y axis: in.ring gives them LIGGGHTS'
`surface_ang_vel` (the surface moves, the mesh stays put: exact for walls of revolution up to
the facets). Each circle has N facets; the chord lies inside the circle by R (1 - cos(pi/N)).

Grains: layers one diameter apart, each a triangular lattice (spacing 1.02 d), inside the trough;
a random subset of the sites for the asked solid fraction (the lattice caps it near 0.4); moving with the floor's rotation scaled by
(1 - y/H) (Couette), seeded.

Load: the top is held at a normal stress P (in.ring's servo; P = 5.5 kPa as cases/sawyer2001); the
plate moves between h_min, the height of the grains at closest packing (0.7405), and 1.4 H (the
cylinders reach 1.5 H).

    python3 make_ring.py [--d 0.787e-3] [--R 10] [--W 4] [--H 4] [--fill 0.4] [--U 2.0] [--P 5500]
                         [--N 256] [--seed 1]
(R, W, H in grain diameters)."""
import argparse
import math
import random

DENSITY = 2550.0  # kg/m^3, glass beads as cases/sawyer2001


def facet(f, a, b, c):
    f.write("facet normal 0 0 0\n outer loop\n")
    for p in (a, b, c):
        f.write("  vertex %.9e %.9e %.9e\n" % p)
    f.write(" endloop\nendfacet\n")


def point(r, t, y):
    return (r * math.cos(t), y, r * math.sin(t))


def write_annulus(name, rin, rout, y, n):
    with open(name, "w") as f:
        f.write("solid %s\n" % name)
        for k in range(n):
            t0, t1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
            facet(f, point(rin, t0, y), point(rout, t0, y), point(rout, t1, y))
            facet(f, point(rin, t0, y), point(rout, t1, y), point(rin, t1, y))
        f.write("endsolid %s\n" % name)


def write_cylinder(name, r, y1, n):
    with open(name, "w") as f:
        f.write("solid %s\n" % name)
        for k in range(n):
            t0, t1 = 2 * math.pi * k / n, 2 * math.pi * (k + 1) / n
            facet(f, point(r, t0, 0.0), point(r, t1, 0.0), point(r, t1, y1))
            facet(f, point(r, t0, 0.0), point(r, t1, y1), point(r, t0, y1))
        f.write("endsolid %s\n" % name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--d", type=float, default=0.787e-3, help="grain diameter (m)")
    ap.add_argument("--R", type=float, default=10.0, help="mean radius of the trough (d)")
    ap.add_argument("--W", type=float, default=4.0, help="trough width (d)")
    ap.add_argument("--H", type=float, default=4.0, help="gap, floor to top (d)")
    ap.add_argument("--fill", type=float, default=0.4, help="solid fraction of the trough")
    ap.add_argument("--U", type=float, default=2.0, help="floor speed at the mean radius (m/s)")
    ap.add_argument("--P", type=float, default=5500.0, help="normal stress on the top (Pa)")
    ap.add_argument("--N", type=int, default=256, help="facets per circle")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    d = a.d
    R, W, H = a.R * d, a.W * d, a.H * d
    if not (a.W < 2 * a.R and a.W >= 1.5 and a.H >= 1.5 and 0 < a.fill < 0.74 and a.N >= 16 and a.P > 0):
        ap.error("need W < 2R, W and H >= 1.5 d, 0 < fill < 0.74, N >= 16, P > 0")
    rin, rout, ybox = R - W / 2, R + W / 2, 1.5 * H

    # layers one diameter apart (touching, no overlap) from the floor to the top; in each, a
    # triangular lattice of spacing 1.02 d: together they cap the fill near 0.4
    s, sites = 1.02 * d, []
    layers = int((H - d) / d + 1e-9) + 1
    rows = int(2 * rout / (s * math.sqrt(3) / 2)) + 2
    for j in range(layers):
        y = 0.5 * d + j * d
        for i in range(rows):
            z = -rout + i * s * math.sqrt(3) / 2
            x = -rout + (0.5 * s if (i + j) % 2 else 0.0)
            while x < rout:
                if rin + 0.55 * d < math.hypot(x, z) < rout - 0.55 * d:
                    sites.append((x, y, z))
                x += s
    want = int(round(a.fill * 2 * math.pi * R * W * H / (math.pi / 6 * d ** 3)))
    random.seed(a.seed)
    random.shuffle(sites)
    grains = sites[:want]
    area = 2 * math.pi * R * W  # of the annular top, pi (r_out^2 - r_in^2)
    hmin = len(grains) * math.pi / 6 * d ** 3 / (0.7405 * area)
    write_annulus("floor.stl", rin, rout, 0.0, a.N)
    write_annulus("top.stl", rin, rout, H, a.N)
    write_cylinder("inner.stl", rin, ybox, a.N)
    write_cylinder("outer.stl", rout, ybox, a.N)
    omega = a.U / R
    box = rout + 2 * d
    with open("grains.data", "w") as f:
        f.write("make_ring.py: %d grains, R %g d, W %g d, H %g d\n\n%d atoms\n1 atom types\n\n" %
                (len(grains), a.R, a.W, a.H, len(grains)))
        f.write("%.9e %.9e xlo xhi\n%.9e %.9e ylo yhi\n%.9e %.9e zlo zhi\n\nAtoms\n\n" %
                (-box, box, -d, ybox + d, -box, box))
        for i, (x, y, z) in enumerate(grains):
            f.write("%d 1 %.9e %g %.9e %.9e %.9e\n" % (i + 1, d, DENSITY, x, y, z))
        f.write("\nVelocities\n\n")
        for i, (x, y, z) in enumerate(grains):
            w = omega * (1 - y / H)  # (0, w, 0) x (x, y, z) = (w z, 0, -w x)
            f.write("%d %.9e 0 %.9e 0 0 0\n" % (i + 1, w * z, -w * x))
    with open("ring.vars", "w") as f:
        f.write("# make_ring.py\nvariable Omega equal %.12g\nvariable R equal %.12g\nvariable H equal %.12g\n"
                "variable grains equal %d\nvariable d equal %.12g\nvariable W equal %.12g\n" % (omega, R, H, len(grains), d, W))
        f.write("# load control: target stress (Pa), top area (m^2), plate limits (m)\nvariable P equal %.12g\n"
                "variable A equal %.12g\nvariable hmin equal %.12g\nvariable hmax equal %.12g\n"
                % (a.P, area, hmin, 1.4 * H))
    if len(grains) < want:
        print("note: the lattice holds %d grains, fewer than the %d asked" % (len(grains), want))
    print("%d grains (%d asked, %d lattice sites), Omega %.6g rad/s" % (len(grains), want, len(sites), omega))


if __name__ == "__main__":
    main()
