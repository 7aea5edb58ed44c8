#!/usr/bin/env python3
"""Wall stresses of LIGGGHTS (`granlub dem`) and YADE (`granlub yade`) window by window.

Both engines start from the same initial grains (results/initial/<point>/particles.csv), so
when neither run reaches a steady state their *transients* can still be compared: the same
physics from the same state must give the same stress history up to chaotic noise. This reads
the raw wall-force series each engine keeps in its point folder,

  results/dem/<point>/walls.txt       LIGGGHTS fix ave/time: force of the walls on the grains
  results/yade/<point>/wallforce.csv  YADE PyRunner: force of the grains on the walls

both averaged over blocks of `sample_every` steps, converts them to granlub's signed stresses
(positive for a compressed, sheared layer, as in summary.json), cuts the run into equal windows
of simulated time, and prints per window the mean and its standard error from block averaging
(`--blocks` contiguous blocks inside each window) for both engines, and the difference in
combined standard errors.

Usage: transient_agreement.py A B --length L --width W --gap H [--windows 8] [--blocks 5]
A and B are point folders, each prefixed by its engine: dem:cases/X/results/dem/U2.0 or
yade:cases/X/results/yade/U2.0 (two dem: folders compare e.g. 1 and 2 MPI ranks: the spread of
one engine's trajectories from the same state). L, W, H in metres: the cell's periodic length,
trough width and gap. Standard library only.
"""
import argparse
import math
import pathlib
import sys


def read_dem(path):
    """(step, fx_bot, fy_bot, fx_top, fy_top, fx_side_mean) as force of the GRAINS on the walls."""
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = [float(t) for t in line.split()]
        # LIGGGHTS columns: step, fbot xyz, ftop xyz, fsid x (two side walls): walls on grains.
        rows.append((v[0], -v[1], -v[2], -v[4], -v[5], -(v[7] + v[8]) / 2))
    return rows


def read_yade(path):
    rows = []
    for line in open(path):
        if line.startswith("#") or line.startswith("step") or not line.strip():
            continue
        v = [float(t) for t in line.split(",")]
        rows.append((v[0], v[1], v[2], v[4], v[5], (v[7] + v[8]) / 2))
    return rows


def stresses(rows, L, W, H):
    """granlub's signs: P = normal force of the grains pushing the wall outward, tau = drag
    along +x on the bottom wall's reaction, as in summary.json (see plugins/*/README.md)."""
    out = []
    for step, fxb, fyb, fxt, fyt, fxs in rows:
        out.append((step,
                    -fyb / (L * W),   # P_bot: grains push the bottom wall down (-y)
                    fyt / (L * W),    # P_top: grains push the top wall up (+y)
                    -fxb / (L * W),   # tau_bot: grains hold the moving bottom wall back (-x)
                    fxt / (L * W),    # tau_top: grains drag the fixed top wall along (+x)
                    -fxs / (L * H)))  # tau_side: side walls move with the bottom
    return out


def window_stats(series, blocks):
    n = len(series)
    mean = sum(series) / n
    if n < blocks or blocks < 2:
        return mean, float("nan")
    b = [sum(series[i * n // blocks:(i + 1) * n // blocks]) / ((i + 1) * n // blocks - i * n // blocks)
         for i in range(blocks)]
    mb = sum(b) / blocks
    var = sum((x - mb) ** 2 for x in b) / (blocks - 1)
    return mean, math.sqrt(var / blocks)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("a", help="ENGINE:POINT_FOLDER, ENGINE = dem or yade")
    ap.add_argument("b", help="ENGINE:POINT_FOLDER")
    ap.add_argument("--length", type=float, required=True)
    ap.add_argument("--width", type=float, required=True)
    ap.add_argument("--gap", type=float, required=True)
    ap.add_argument("--windows", type=int, default=8)
    ap.add_argument("--blocks", type=int, default=5)
    a = ap.parse_args()
    series, labels = [], []
    for spec in (a.a, a.b):
        engine, _, folder = spec.partition(":")
        if engine not in ("dem", "yade") or not folder:
            sys.exit(f"transient_agreement: '{spec}': expected dem:FOLDER or yade:FOLDER")
        f = pathlib.Path(folder) / ("walls.txt" if engine == "dem" else "wallforce.csv")
        if not f.is_file():
            sys.exit(f"transient_agreement: missing {f} (run granlub {engine} first)")
        rows = read_dem(f) if engine == "dem" else read_yade(f)
        series.append(stresses(rows, a.length, a.width, a.gap))
        labels.append(spec)
    dem, yade = series
    n = min(len(dem), len(yade))  # the engines round the run length differently
    names = ["P_bot", "P_top", "tau_bot", "tau_top", "tau_side"]
    print(f"# A = {labels[0]}, B = {labels[1]}: {len(dem)} / {len(yade)} wall blocks, "
          f"compared over the first {n}, {a.windows} windows, {a.blocks} blocks each")
    print("| window (steps) | quantity | A (Pa) | B (Pa) | (B - A) / combined stderr |")
    print("|---|---|---|---|---|")
    for w in range(a.windows):
        lo, hi = w * n // a.windows, (w + 1) * n // a.windows
        for q, name in enumerate(names, start=1):
            md, sd = window_stats([r[q] for r in dem[lo:hi]], a.blocks)
            my, sy = window_stats([r[q] for r in yade[lo:hi]], a.blocks)
            z = (my - md) / math.hypot(sd, sy) if sd + sy > 0 else float("nan")
            span = f"{int(dem[lo][0]) - 100}-{int(dem[hi - 1][0])}" if q == 1 else ""
            print(f"| {span} | {name} | {md:.4g} ± {sd:.2g} | {my:.4g} ± {sy:.2g} | {z:+.1f} |")


if __name__ == "__main__":
    main()
