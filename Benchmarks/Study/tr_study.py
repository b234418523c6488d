#!/usr/bin/python3
"""Where the right topology lies in t_r, and how that moves with the number of
points: for shapes of known Betti numbers sampled i.i.d. and
quasi-uniformly (generate_clouds.py) at several sizes, the t_r window in which
`flowrecon reconstruct` (t_p 1.1) has the true Betti numbers, from one topology
profile up to 3. Prints a Markdown table: the first window (from, to], or none.

  PYTHONPATH=Apps/Scripts /usr/bin/python3 Benchmarks/Study/tr_study.py build/bin/flowrecon WORKDIR [--sizes 1000 4000 16000]

Options (the defaults give the first table of Data/EXPERIMENTS.md, "The t_r
window and the number of points", unchanged):
  --shapes NAME ...      base shapes of generate_clouds.py (sphere, torus, genus2,
                         two_spheres, sphere_with_segment; also trefoil, ball,
                         thin_tube, thin_plate, genus4, ...)
  --samplings KIND ...   iid (NAME), qu (NAME_qu: farthest points), pd (NAME_pd:
                         Poisson disk, the quasi-uniform sampling for large n), dv
                         (NAME_dv: i.i.d., density x10 along x), dvqu (NAME_dvqu:
                         Poisson disk graded x10 along x); default iid qu. A
                         variant missing from generate_clouds.SHAPES is skipped.
  --tr-max T             profile up to T (3)
  --tp P                 persistence threshold passed to flowrecon (its default 1.1)
  --betti-max-cells N    passed to flowrecon (its default 4e6; 'inf')
  --all-windows          list every window with the truth, not only the first
  --resources            run flowrecon under /usr/bin/time -v and add its wall
                         time and peak resident memory
  --tp-table             instead: the Betti numbers at t_r 2 and the first
                         window for t_p in --tp-values (0 1.02 1.05 1.1 1.2) on
                         regular lattices (integer points near a sphere, a
                         latitude-longitude lattice exact and jittered by 1e-3, a
                         planar grid with 1e-12 jitter and without, exact and
                         jittered 3D grids) and two quasi-uniform references

Large quasi-uniform clouds: farthest_points costs O(n x candidates) in Python
(1-2 min for 16 000 points, about an hour for 10^5), so for 10^5-10^6 points use the
Poisson-disk variants (--samplings pd: generate_clouds.poisson_disk, a greedy
dart throwing over 20 i.i.d. candidates per point, at most 10^7, with a grid of
cells; exactly n points, >= 0.85 r apart, every candidate within r of one; about
20-30 s for 10^5 points, 2.5 min for 10^6). They are less regular than farthest
points (covering radius / smallest spacing about 1.45 instead of 1.2), and their
windows start later (by up to 0.2 at the same n). A window runs over consecutive
profile rows with the same Betti numbers (the profile may repeat a row).
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import time

import numpy as np

import generate_clouds as gc

SAMPLINGS = {  # kind -> (label, suffix of the generate_clouds shape)
    "iid": ("i.i.d.", ""),
    "qu": ("quasi-uniform", "_qu"),
    "pd": ("quasi-uniform (Poisson disk)", "_pd"),
    "dv": ("i.i.d., density x10 along x", "_dv"),
    "dvqu": ("Poisson disk, density x10 along x", "_dvqu"),
}

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("flowrecon")
ap.add_argument("work")
ap.add_argument("--sizes", type=int, nargs="+", default=[1000, 4000, 16000])
ap.add_argument("--shapes", nargs="+",
                default=["sphere", "torus", "genus2", "two_spheres", "sphere_with_segment"])
ap.add_argument("--samplings", nargs="+", default=["iid", "qu"], choices=list(SAMPLINGS))
ap.add_argument("--tr-max", type=float, default=3.0)
ap.add_argument("--tp", default=None)
ap.add_argument("--betti-max-cells", default=None)
ap.add_argument("--all-windows", action="store_true")
ap.add_argument("--resources", action="store_true")
ap.add_argument("--tp-table", action="store_true")
ap.add_argument("--tp-values", nargs="+", default=["0", "1.02", "1.05", "1.1", "1.2"])
args = ap.parse_args()
os.makedirs(args.work, exist_ok=True)


def window(rows, truth, limit):
    """The first (from, to] of t_r (> 1) whose Betti numbers are the truth."""
    ws = windows(rows, truth, limit)
    return ws[0] if ws else None


def windows(rows, truth, limit):
    """Every (from, to] of t_r (> 1) whose Betti numbers are the truth (consecutive
    rows with the same Betti numbers, which the profile may hold, are merged)."""
    out = []
    for k, (t, b) in enumerate(rows):
        end = rows[k + 1][0] if k + 1 < len(rows) else limit
        if b == truth and end > 1.0:
            if out and out[-1][1] == t:
                out[-1] = (out[-1][0], end)
            else:
                out.append((max(t, 1.0), end))
    return out


def run(base, points, tp=None):
    """Write the cloud, run flowrecon; (Betti line or None, profile rows or None,
    wall seconds, peak GB) (the last two None without --resources)."""
    np.savetxt(base + ".xyz", points, fmt="%.17g")
    cmd = [args.flowrecon, "reconstruct", base + ".xyz", "-o", base + ".vtu",
           "--tr-max", "%g" % args.tr_max, "--topology-profile", base + ".csv",
           "--warn-window", "1"]
    if tp is not None:
        cmd += ["--tp", str(tp)]
    if args.betti_max_cells is not None:
        cmd += ["--betti-max-cells", args.betti_max_cells]
    if args.resources:
        cmd = ["/usr/bin/time", "-v"] + cmd
    if os.path.exists(base + ".csv"):
        os.remove(base + ".csv")
    proc = subprocess.run(cmd, capture_output=True, text=True, check=True)
    lines = [l for l in proc.stdout.splitlines() if l.startswith("Betti numbers: ")]
    at2 = lines[0][15:] if lines else None
    rows = None
    if os.path.exists(base + ".csv"):
        with open(base + ".csv") as f:
            rows = [(float(r["threshold"]), (int(r["b0"]), int(r["b1"]), int(r["b2"])))
                    for r in csv.DictReader(f)]
    wall = peak = None
    if args.resources:
        m = re.search(r"Elapsed \(wall clock\) time .*: (?:(\d+):)?(\d+):([\d.]+)", proc.stderr)
        wall = int(m.group(1) or 0) * 3600 + int(m.group(2)) * 60 + float(m.group(3))
        peak = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                             proc.stderr).group(1)) / 1024.0 ** 2
    return at2, rows, wall, peak


def betti_text(at2, truth):
    if at2 is None:
        return "skipped"
    return at2 + ("" if tuple(int(x) for x in at2.split()) == truth else " (wrong)")


def window_text(rows, truth):
    if rows is None:
        return "no profile"
    if args.all_windows:
        ws = windows(rows, truth, args.tr_max)
        return " ∪ ".join("(%.3f, %.3f]" % w for w in ws) if ws else \
            "none below %g" % args.tr_max
    w = window(rows, truth, args.tr_max)
    return "(%.3f, %.3f]" % w if w else "none below %g" % args.tr_max


def tp_table():
    """Betti numbers at t_r 2 and the first window, per t_p, on regular lattices."""
    clouds = [
        ("integer points with abs(norm(p) - 15) < 0.5", "lattice_shell", 15),
        ("30 x 60 latitude-longitude lattice, unit sphere", "latlong_sphere", 30),
        ("the same, jitter 1e-3", "latlong_jittered", 30),
        ("25 x 40 planar grid, jitter 1e-12", "plane_grid_jittered", 1000),
        ("25 x 40 planar grid, exact", None, 1000),
        ("exact 10 x 10 x 10 grid", "grid4_exact", 10),
        ("10 x 10 x 10 grid, jitter 1e-3", "grid5_jittered", 10),
        ("reference: sphere_qu", "sphere_qu", 2000),
        ("reference: torus_qu", "torus_qu", 2000),
    ]
    results = []
    for label, name, size in clouds:
        if name is None:
            points, truth, tag = gc.plane_grid_jittered(size, None, jitter=0.0), (1, 0, 0), "plane_grid_exact"
        elif name == "latlong_jittered":  # is it the degeneracy or the anisotropy at the poles?
            points = gc.make("latlong_sphere", size=size)
            points = points + np.random.default_rng(1).uniform(-1e-3, 1e-3, points.shape)
            truth, tag = gc.betti("latlong_sphere"), name
        else:
            points, truth, tag = gc.make(name, size=size), gc.betti(name), name
        cells = []
        for tp in args.tp_values:
            base = os.path.join(args.work, "tp_%s_%s" % (tag, tp))
            try:
                at2, rows, _, _ = run(base, points, tp)
                cells.append((betti_text(at2, truth), window_text(rows, truth)))
            except subprocess.CalledProcessError as e:
                msg = (e.stderr or "").strip().splitlines()
                cells.append(("error: %s" % (msg[-1].split(": ")[-1] if msg else e.returncode),
                              "error"))
            print("%s t_p %s: %s" % (tag, tp, cells[-1]), file=sys.stderr, flush=True)
        results.append((label, len(points), truth, cells))
    head = "| cloud | points | truth | " + " | ".join("t_p %s" % tp for tp in args.tp_values) + " |"
    rule = "|---|---:|---|" + "---|" * len(args.tp_values)
    print("Betti numbers at t_r 2:\n")
    print(head)
    print(rule)
    for label, n, truth, cells in results:
        print("| %s | %d | %s | %s |" % (label, n, " ".join(map(str, truth)),
                                         " | ".join(c[0] for c in cells)))
    print("\nt_r window with the truth (profile up to %g):\n" % args.tr_max)
    print(head)
    print(rule)
    for label, n, truth, cells in results:
        print("| %s | %d | %s | %s |" % (label, n, " ".join(map(str, truth)),
                                         " | ".join(c[1] for c in cells)))


if args.tp_table:
    tp_table()
    sys.exit(0)

print("| shape | sampling | points | t_r window with the truth | at t_r 2 |" +
      (" flowrecon wall (s) | peak memory (GB) |" if args.resources else ""))
print("|---|---|---:|---|---|" + ("---:|---:|" if args.resources else ""))
for shape in args.shapes:
    for kind in args.samplings:
        sampling, suffix = SAMPLINGS[kind]
        name = shape + suffix
        if name not in gc.SHAPES:
            print("no %s in generate_clouds.SHAPES: skipped" % name, file=sys.stderr)
            continue
        truth = gc.betti(name)
        for n in args.sizes:
            base = os.path.join(args.work, "%s_%d" % (name, n))
            start = time.time()
            points = gc.make(name, size=n)
            print("%s %d: %d points generated in %.1f s" % (name, n, len(points),
                                                           time.time() - start),
                  file=sys.stderr, flush=True)
            at2, rows, wall, peak = run(base, points, args.tp)
            print("| %s %s | %s | %d | %s | %s |" % (
                shape, truth, sampling, n, window_text(rows, truth), betti_text(at2, truth)) +
                (" %.1f | %.2f |" % (wall, peak) if args.resources else ""), flush=True)
