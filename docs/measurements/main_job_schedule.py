#!/usr/bin/env python3
"""Dry model of the main job's engine stage (`granlub run cases/sawyer2001`, cli/run_all.cpp):
the wall time of its runs on 2 cores under a schedule, from each run's CPU seconds alone.

Runs: per DEM point a coarse run and its answer at half that step (cold, each from the initial grains;
U1.4, dense, at half and a quarter of the case's step), then a YADE point from the answer's final
state; YADE's U2.8 is continued from 8 to 16 ms. The kernel shares the cores: every ready run gets a
share by its nice weight (Linux: 1024 at nice 0, 110 at nice 10), at most one core; no cost for
sharing is modelled. Usage: main_job_schedule.py [u_s y_s continuation_s]
  u_s  CPU seconds of a DEM run of 54 800 steps (the coarse run of U2.0 and U2.8; every other run
       a multiple by its steps), y_s one YADE point (8 ms), continuation_s YADE U2.8 from 8 to 16 ms.
Defaults: 821 s of CPU in the run of 2026-11-29 (docs/measurements/build-and-run.md) less YADE's
3 x 60 + 60 s (58-63 s a point) over the DEM's 12 such units: u = 48 s.
"""
import sys

NICE = {0: 1024, 10: 110}


def runs(u, y, cont):
    """name -> (CPU seconds, runs it waits for)"""
    return {'dem U1.4 dt/2': (2 * u, []), 'dem U1.4 dt/4': (4 * u, []),
            'dem U2.0 dt': (u, []), 'dem U2.0 dt/2': (2 * u, []),
            'dem U2.8 dt': (u, []), 'dem U2.8 dt/2': (2 * u, []),
            'yade U1.4': (y, ['dem U1.4 dt/2', 'dem U1.4 dt/4']),
            'yade U2.0': (y, ['dem U2.0 dt', 'dem U2.0 dt/2']),
            'yade U2.8': (y, ['dem U2.8 dt', 'dem U2.8 dt/2']),
            'yade U2.8 continued': (cont, ['yade U2.8'])}


def share(T, pairs_side_by_side, cores=2, dt=0.01):
    deps = {k: list(d) for k, (c, d) in T.items()}
    if not pairs_side_by_side:  # before: a point's answer after its coarse run, in one thread
        deps['dem U1.4 dt/4'] = ['dem U1.4 dt/2']
        deps['dem U2.0 dt/2'] = ['dem U2.0 dt']
        deps['dem U2.8 dt/2'] = ['dem U2.8 dt']
    left = {k: c for k, (c, d) in T.items() if c > 0}
    done = {k: 0.0 for k in T if k not in left}
    t = idle = 0.0
    while len(done) < len(T):
        ready = [k for k in left if k not in done and all(x in done for x in deps[k])]
        weight = {k: NICE[10 if k.startswith('yade') else 0] for k in ready}
        rate, free, pool = {}, float(cores), list(ready)
        while pool and free > 1e-12:  # shares by weight, at most one core each
            total = sum(weight[k] for k in pool)
            full = [k for k in pool if free * weight[k] / total >= 1]
            if not full:
                rate.update({k: free * weight[k] / total for k in pool})
                free = 0.0
                break
            for k in full:
                rate[k] = 1.0
                free -= 1
                pool.remove(k)
        idle += free * dt
        t += dt
        for k, r in rate.items():
            left[k] -= r * dt
            if left[k] <= 1e-9:
                done[k] = t
    return t, idle, done


def gate(T, cores=2):
    """Never more engines than cores; a free core takes the waiting run with the longest chain of
    estimated CPU ahead of it (its own and its readers'), the continuation not foreseen (it is decided
    when YADE's first 8 ms end)."""
    est = {k: (0.0 if k.endswith('continued') else c) for k, (c, d) in T.items()}
    readers = {k: [j for j, (c, d) in T.items() if k in d] for k in T}
    chain = {}

    def ahead(k):
        if k not in chain:
            chain[k] = est[k] + max((ahead(j) for j in readers[k]), default=0.0)
        return chain[k]
    done, started, running, t = {}, set(), [], 0.0
    while len(done) < len(T):
        ready = sorted((k for k, (c, d) in T.items() if k not in started and all(x in done for x in d)),
                       key=lambda k: -ahead(k))
        while len(running) < cores and ready:
            k = ready.pop(0)
            started.add(k)
            running.append((t + T[k][0], k))
        running.sort()
        t, k = running.pop(0)
        done[k] = t
    return t, 2 * t - sum(c for c, _ in T.values()), done


def main():
    u, y, cont = (float(a) for a in sys.argv[1:4]) if len(sys.argv) > 3 else (48.0, 60.0, 60.0)
    T = runs(u, y, cont)
    cpu = sum(c for c, _ in T.values())
    print(f"{cpu:.0f} s of CPU: at best {cpu / 2:.0f} s on 2 cores")
    for name, side in (('shipped: a point\'s runs one after the other', False),
                       ('tried: a point\'s cold runs side by side (measured slower, 2026-12-06)', True)):
        t, idle, done = share(T, side)
        last = sorted(done, key=done.get)[-2:]
        print(f"{name}: {t:.0f} s, {idle:.0f} core-s idle; ends with {last[0]} at {done[last[0]]:.0f} s, "
              f"{last[1]} at {done[last[1]]:.0f} s")
    t, idle, done = gate(T)
    print(f"not built: two engines at a time, the longest estimated chain first: {t:.0f} s, {idle:.0f} core-s idle")


if __name__ == '__main__':
    main()
