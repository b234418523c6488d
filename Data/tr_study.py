#!/usr/bin/python3
"""Where the right topology lies in t_r, and how that moves with the number of
points (issue #9, item 3): for shapes of known Betti numbers sampled i.i.d. and
quasi-uniformly (generate_clouds.py) at several sizes, the t_r window in which
`flowrecon reconstruct` (t_p 1.1) has the true Betti numbers, from one topology
profile up to 3. Prints a Markdown table: the first window (from, to], or none.

  /usr/bin/python3 Data/tr_study.py build/bin/flowrecon WORKDIR [--sizes 1000 4000 16000]
"""
import argparse
import csv
import os
import subprocess

import numpy as np

import generate_clouds as gc

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("flowrecon")
ap.add_argument("work")
ap.add_argument("--sizes", type=int, nargs="+", default=[1000, 4000, 16000])
ap.add_argument("--shapes", nargs="+",
                default=["sphere", "torus", "genus2", "two_spheres", "sphere_with_segment"])
args = ap.parse_args()
os.makedirs(args.work, exist_ok=True)


def window(rows, truth, limit):
    """The first (from, to] of t_r (> 1) whose Betti numbers are the truth."""
    for k, (t, b) in enumerate(rows):
        if b == truth:
            end = rows[k + 1][0] if k + 1 < len(rows) else limit
            return max(t, 1.0), end
    return None


print("| shape | sampling | points | t_r window with the truth | at t_r 2 |")
print("|---|---|---:|---|---|")
for shape in args.shapes:
    truth = gc.betti(shape)
    for sampling in ("i.i.d.", "quasi-uniform"):
        name = shape if sampling == "i.i.d." else shape + "_qu"
        for n in args.sizes:
            base = os.path.join(args.work, "%s_%d" % (name, n))
            np.savetxt(base + ".xyz", gc.make(name, size=n), fmt="%.17g")
            out = subprocess.run([args.flowrecon, "reconstruct", base + ".xyz", "-o", base + ".vtu",
                                  "--tr-max", "3", "--topology-profile", base + ".csv",
                                  "--warn-window", "1"],
                                 capture_output=True, text=True, check=True).stdout
            at2 = [l for l in out.splitlines() if l.startswith("Betti numbers: ")][0][15:]
            with open(base + ".csv") as f:
                rows = [(float(r["threshold"]), (int(r["b0"]), int(r["b1"]), int(r["b2"])))
                        for r in csv.DictReader(f)]
            w = window(rows, truth, 3.0)
            print("| %s %s | %s | %d | %s | %s%s |" % (
                shape, truth, sampling, n, "(%.3f, %.3f]" % w if w else "none below 3", at2,
                "" if tuple(int(x) for x in at2.split()) == truth else " (wrong)"), flush=True)
