#!/usr/bin/python3
"""The pictures of the topology profile in docs/concepts.md: the
Betti numbers against t_r for a clean torus (2 000 quasi-uniform points) and
for a sphere (3 000 quasi-uniform points) whose polar cap z > 0.7 lost half of
its points, and that sphere with the places `flowrecon reconstruct` warns about.

  /usr/bin/python3 Apps/Scripts/topology_pictures.py build/bin/flowrecon OUTDIR
  (docs/concepts.md shows the copies Data/pictures/topology_profiles.png and
  Data/pictures/undersampled_sphere.png)
"""
import csv
import os
import re
import subprocess
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import generate_clouds as gc  # noqa: E402

FLOWRECON, OUT = sys.argv[1], sys.argv[2]
os.makedirs(OUT, exist_ok=True)


def run(name, points):
    base = os.path.join(OUT, name)
    np.savetxt(base + ".xyz", points, fmt="%.17g")
    p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu",
                        "--topology-profile", base + ".csv"], capture_output=True, text=True,
                       check=True)
    with open(base + ".csv") as f:
        rows = [(float(r["threshold"]), int(r["b0"]), int(r["b1"]), int(r["b2"]))
                for r in csv.DictReader(f)]
    warnings = [tuple(float(v) for v in m.group(1).split(","))
                for m in re.finditer(r"under-sampled near \(([^)]*)\)", p.stderr)]
    print(name, p.stdout.strip().splitlines()[-1], "%d warnings" % len(warnings))
    return rows, warnings


def staircase(ax, rows, title, truth):
    t = [r[0] for r in rows] + [4.0]
    for d, colour in ((1, "tab:blue"), (2, "tab:orange"), (3, "tab:green")):
        ax.step(t, [r[d] for r in rows] + [rows[-1][d]], where="post", color=colour,
                label="b%d" % (d - 1))
    ax.axvline(2.0, color="grey", linestyle="--", linewidth=1)
    ax.axvspan(2.0, 2.2, color="red", alpha=0.12, label="warning window [2, 2.2)")
    ax.set_xscale("log")
    ax.set_xlim(1.0, 4.0)
    ax.set_ylim(-0.5, 10.5)
    ax.set_xticks([1, 1.5, 2, 2.5, 3, 4])
    ax.get_xaxis().set_major_formatter(matplotlib.ticker.ScalarFormatter())
    ax.set_xlabel("t_r")
    ax.set_ylabel("Betti number")
    ax.set_title("%s (truth %s)" % (title, truth))
    ax.legend(loc="upper right", fontsize=8)


torus, _ = run("torus_clean", gc.make("torus_qu"))
base = gc.make("sphere_qu", size=3000)
keep = (base[:, 2] <= 0.7) | (np.random.default_rng(3).uniform(size=len(base)) > 0.5)
sphere, warnings = run("sphere_thinned", base[keep])

fig, axes = plt.subplots(1, 2, figsize=(11, 3.8))
staircase(axes[0], torus, "torus, 2 000 quasi-uniform points", "1 2 1")
staircase(axes[1], sphere, "sphere, cap z > 0.7 thinned by half", "1 0 1")
fig.tight_layout()
fig.savefig(os.path.join(OUT, "topology_profiles.png"), dpi=110)

fig = plt.figure(figsize=(5.5, 5))
ax = fig.add_subplot(projection="3d")
pts = base[keep]
cap = pts[:, 2] > 0.7
ax.scatter(*pts[~cap].T, s=1, color="grey", alpha=0.4)
ax.scatter(*pts[cap].T, s=3, color="tab:blue", label="thinned cap z > 0.7")
w = np.array(warnings)
if len(w):
    ax.scatter(w[:, 0], w[:, 1], w[:, 2], s=80, color="red", marker="o", label="warnings")
ax.view_init(elev=55, azim=30)
ax.set_title("warned places (red): inside the thinned cap")
ax.set_box_aspect((1, 1, 1))
ax.legend(loc="lower left")
fig.tight_layout()
fig.savefig(os.path.join(OUT, "undersampled_sphere.png"), dpi=110)
