#!/usr/bin/python3
"""The under-sampling warnings against the truth, on every shape of
generate_clouds.py (two seeds each) at the defaults (t_p 1.1, t_r 2): for each
window F, how many answers are right and unflagged, right but flagged (a false
alarm), wrong and flagged, wrong and silent. A cloud is flagged when the Betti
numbers change for some t_r in [2, 2F) (what `flowrecon reconstruct
--warn-window F` warns about); the 'both sides' rows count changes in [2/F, 2F)
instead. Prints a Markdown table (Data/EXPERIMENTS.md, "Under-sampling
warnings").

  PYTHONPATH=Apps/Scripts /usr/bin/python3 Benchmarks/Study/warning_study.py build/bin/flowrecon WORKDIR [T_R]

T_R (default 2) evaluates another default t_r the same way.
"""
import csv
import os
import subprocess
import sys

import numpy as np

import generate_clouds as gc

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
TR = float(sys.argv[3]) if len(sys.argv) > 3 else 2.0
WINDOWS = (1.03, 1.05, 1.1, 1.2)
os.makedirs(WORK, exist_ok=True)
runs = []
# The 21 shapes of the study as published (EXPERIMENTS.md); the shapes added to
# generate_clouds.py later serve the t_r study.
STUDY = ("sphere", "torus", "genus2", "trefoil", "ball", "two_spheres", "two_hemispheres",
         "sphere_with_segment", "grid5_jittered", "grid4_exact", "sphere_qu", "torus_qu",
         "genus2_qu", "trefoil_qu", "ball_qu", "two_spheres_qu", "two_hemispheres_qu",
         "sphere_with_segment_qu", "vase_qu", "plate3_qu", "tree")
for name in STUDY:
    for seed in (0, 1):
        base = os.path.join(WORK, "%s_%d" % (name, seed))
        np.savetxt(base + ".xyz", gc.make(name, seed_offset=seed), fmt="%.17g")
        out = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu",
                              "--topology-profile", base + ".csv", "--warn-window", "1", "--tr", repr(TR)],
                             capture_output=True, text=True, check=True).stdout
        line = [l for l in out.splitlines() if l.startswith("Betti numbers: ")][0]
        betti = tuple(int(x) for x in line.split()[2:])
        with open(base + ".csv") as f:
            changes = [float(r["threshold"]) for r in csv.DictReader(f)][1:]
        right = betti == gc.betti(name)
        print("%-24s seed %d: %s %s, nearest change above %g: %s" % (
            name, seed, betti, "right" if right else "WRONG (truth %s)" % (gc.betti(name),), TR,
            min([t for t in changes if t >= TR], default="none")), file=sys.stderr)
        runs.append((right, changes))

print("| window | changes counted | right, no warning | right, warned (false alarm) "
      "| wrong, warned | wrong, silent |")
print("|---|---|---:|---:|---:|---:|")
for both in (False, True):
    for f in WINDOWS:
        low = TR / f if both else TR
        flagged = [any(low <= t < TR * f for t in changes) for _, changes in runs]
        count = lambda r, w: sum(1 for (right, _), fl in zip(runs, flagged) if right == r and fl == w)
        print("| %g | %s | %d | %d | %d | %d |" % (
            f, "[2/F, 2F)" if both else "[2, 2F)", count(True, False), count(True, True),
            count(False, True), count(False, False)))
