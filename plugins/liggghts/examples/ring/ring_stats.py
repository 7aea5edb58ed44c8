#!/usr/bin/env python3
"""Reduces an in.ring run (in its folder): the walls' stresses per 2000-step window and their means
over the steady part with standard errors (of the window means), the plate's gap and the mean solid
fraction, the balances, and, when the run dumped the grains (-var dump_every N), the radial profile
across the trough and the profile of the angular velocity across the gap.

Stresses from the mesh forces and torques about the axis (y), on the annulus r_i < r < r_o of the
floor and top (area A = pi (r_o^2 - r_i^2)) and on the cylinders of height h (the plate's gap):
  P_top = F_y(top) / A,  P_bottom = -F_y(floor) / A,
  tau_top = T(top) / J,  tau_bottom = -T(floor) / J,  J = 2 pi (r_o^3 - r_i^3) / 3  (uniform tau),
  tau_inner = -T(inner) / (2 pi r_i^2 h),  tau_outer = -T(outer) / (2 pi r_o^2 h),
  side support = -(F_y(inner) + F_y(outer)) / A  (the weight the cylinders carry, per floor area).
Velocities as omega / Omega (omega = (z v_x - x v_z) / r^2, the walls turn at Omega): the slice's
u / U for a bed turning with the floor.

    python3 ring_stats.py [--from T] [--dt 5e-6] [--bins 12] [--slabs 10]
(--from: steady from T seconds; default: the second half of the windows)."""
import argparse
import glob
import math
import re


def ring_vars(path="ring.vars"):
    v = {}
    for line in open(path):
        m = re.match(r"variable\s+(\w+)\s+equal\s+(\S+)", line)
        if m:
            v[m.group(1)] = float(m.group(2))
    return v


def rows(path):
    return [list(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]


def mean_se(values):
    m = sum(values) / len(values)
    if len(values) < 2:
        return m, float("nan")
    return m, math.sqrt(sum((x - m) ** 2 for x in values) / (len(values) - 1) / len(values))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--from", dest="start", type=float, default=None, help="steady from this time (s)")
    ap.add_argument("--dt", type=float, default=5e-6, help="in.ring's time step (s)")
    ap.add_argument("--bins", type=int, default=12, help="radial bins across the trough")
    ap.add_argument("--slabs", type=int, default=10, help="slabs across the gap")
    a = ap.parse_args()
    v = ring_vars()
    d, R, W, n = v["d"], v["R"], v["W"], v["grains"]
    ri, ro = R - W / 2, R + W / 2
    area = math.pi * (ro ** 2 - ri ** 2)
    J = 2 * math.pi / 3 * (ro ** 3 - ri ** 3)
    vg = math.pi / 6 * d ** 3
    plate = rows("plate.txt")

    def gap(s0, s1):
        h = [p[1] for p in plate if s0 < p[0] <= s1]
        return sum(h) / len(h) if h else float("nan")

    keys = ["P_top", "P_bottom", "tau_top", "tau_bottom", "tau_inner", "tau_outer", "side_support", "gap_d", "nu",
            "torque_balance"]
    print("t_end_s " + " ".join(keys))
    series = []
    for r in rows("torques.txt"):
        step = r[0]
        h = gap(step - 2000, step)
        f_floor, t_floor, f_in, t_in, f_out, t_out, f_top, t_top = r[1:9]
        w = {"t": step * a.dt, "P_top": f_top / area, "P_bottom": -f_floor / area, "tau_top": t_top / J,
             "tau_bottom": -t_floor / J, "tau_inner": -t_in / (2 * math.pi * ri ** 2 * h),
             "tau_outer": -t_out / (2 * math.pi * ro ** 2 * h), "side_support": -(f_in + f_out) / area,
             "gap_d": h / d, "nu": n * vg / (area * h), "torque_balance": (t_floor + t_in + t_out + t_top) / t_top}
        series.append(w)
        print("%.3f " % w["t"] + " ".join("%.5g" % w[k] for k in keys))
    start = a.start if a.start is not None else series[len(series) // 2 - 1]["t"]
    steady = [w for w in series if w["t"] > start]
    print("\nsteady from %.3f s: %d windows of 2000 steps (stresses Pa)" % (start, len(steady)))
    for k in keys:
        m, se = mean_se([w[k] for w in steady])
        print("  %-14s %.5g +- %.2g" % (k, m, se))
    half = len(steady) // 2
    print("  gap, first / second half of the steady part: %.4f / %.4f d" %
          (mean_se([w["gap_d"] for w in steady[:half]])[0], mean_se([w["gap_d"] for w in steady[half:]])[0]))

    dumps = sorted(glob.glob("prof.*.txt"), key=lambda f: int(f.split(".")[1]))
    dumps = [f for f in dumps if int(f.split(".")[1]) * a.dt > start]
    if not dumps:
        print("\nno grain dumps in the steady part (run with -var dump_every N for the profiles)")
        return
    h = mean_se([w["gap_d"] for w in steady])[0] * d
    omega = v["Omega"]
    count = [0] * a.bins
    w_r = [[0.0, 0] for _ in range(a.bins)]
    w_y = [[0.0, 0] for _ in range(a.slabs)]
    for f in dumps:
        for line in open(f):
            p = line.split()
            if len(p) != 7 or not p[0].isdigit():
                continue
            x, y, z, vx, vy, vz = map(float, p[1:])
            r = math.hypot(x, z)
            w = (z * vx - x * vz) / (r * r) / omega
            i = min(a.bins - 1, max(0, int((r - ri) / W * a.bins)))
            count[i] += 1
            w_r[i][0] += w
            w_r[i][1] += 1
            j = min(a.slabs - 1, max(0, int(y / h * a.slabs)))
            w_y[j][0] += w
            w_y[j][1] += 1
    print("\n%d dumps; across the trough: (r - R)/W, solid fraction (centres binned, over the mean gap), omega/Omega"
          % len(dumps))
    for i in range(a.bins):
        r0, r1 = ri + i * W / a.bins, ri + (i + 1) * W / a.bins
        nu = count[i] * vg / len(dumps) / (math.pi * (r1 ** 2 - r0 ** 2) * h)
        print("  %+.3f  %.4f  %.3f" % (((r0 + r1) / 2 - R) / W, nu, w_r[i][0] / max(1, w_r[i][1])))
    print("across the gap: y/h, omega/Omega")
    for j in range(a.slabs):
        print("  %.2f  %.3f" % ((j + 0.5) / a.slabs, w_y[j][0] / max(1, w_y[j][1])))


if __name__ == "__main__":
    main()
