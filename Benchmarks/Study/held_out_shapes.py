#!/usr/bin/python3
"""The automatic thresholds on shapes the rule was not designed on: surfaces with
sharp edges (a cube's boundary, a capped cylinder, a cube with a cylindrical
hole through it), open surfaces with a boundary (an open cylinder, a
hemisphere, a flat disk) and a flat ellipsoid, none of them in the topology
study (Data/EXPERIMENTS.md, "Automatic thresholds"). Each is sampled i.i.d. by
area with 3 000 and 30 000 points, and again with Gaussian noise of 0.3 and 1
times the mean nearest-neighbour spacing on each coordinate (numpy, fixed
seeds). `flowrecon reconstruct` runs at its defaults and at `--tp 1.1 --tr 2`
(the old fixed thresholds); an answer is right when its Betti numbers are the
shape's, flagged when wrong with a warning, silent when wrong without one
(an error when no Betti numbers are printed). Prints a Markdown
table, one row per cloud, and the counts.

  /usr/bin/python3 Benchmarks/Study/held_out_shapes.py build/bin/flowrecon WORKDIR
"""
import argparse
import os
import re
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree


def cube_surface(rng, n):
    """Area-uniform on the boundary of [-1, 1]^3: six faces, equally likely."""
    face = rng.integers(0, 6, n)
    p = rng.uniform(-1, 1, (n, 3))
    axis, side = face // 2, np.where(face % 2 == 0, -1.0, 1.0)
    p[np.arange(n), axis] = side
    return p


def cylinder(rng, n, caps, r=0.5, h=2.0):
    """Area-uniform on a cylinder of radius r and height h, with or without its two
    flat caps (sharp rims)."""
    side, cap = 2 * np.pi * r * h, np.pi * r * r
    m = rng.binomial(n, side / (side + 2 * cap)) if caps else n
    t, z = rng.uniform(0, 2 * np.pi, m), rng.uniform(-h / 2, h / 2, m)
    parts = [np.c_[r * np.cos(t), r * np.sin(t), z]]
    if caps:
        k = n - m
        rr, t = r * np.sqrt(rng.uniform(0, 1, k)), rng.uniform(0, 2 * np.pi, k)
        parts.append(np.c_[rr * np.cos(t), rr * np.sin(t), np.where(rng.uniform(size=k) < 0.5, -h / 2, h / 2)])
    return np.vstack(parts)


def cube_with_hole(rng, n, r=0.4):
    """Area-uniform on the boundary of [-1, 1]^3 minus the solid cylinder x^2 + y^2
    < r^2 (a genus-1 surface with sharp edges)."""
    faces, wall = 24 - 2 * np.pi * r * r, 4 * np.pi * r
    m = rng.binomial(n, faces / (faces + wall))
    kept = np.empty((0, 3))
    while len(kept) < m:
        q = cube_surface(rng, m)
        kept = np.vstack([kept, q[~((np.abs(q[:, 2]) == 1) & (q[:, 0] ** 2 + q[:, 1] ** 2 < r * r))]])
    k = n - m
    t, z = rng.uniform(0, 2 * np.pi, k), rng.uniform(-1, 1, k)
    return np.vstack([kept[:m], np.c_[r * np.cos(t), r * np.sin(t), z]])


def ellipsoid(rng, n, axes=(1.0, 0.3, 0.15)):
    """Area-uniform on a flat ellipsoid: directions mapped onto it, kept with
    probability proportional to the area element of that map."""
    a = np.array(axes)
    kept = np.empty((0, 3))
    while len(kept) < n:
        v = rng.normal(size=(4 * n, 3))
        v /= np.linalg.norm(v, axis=1)[:, None]
        w = np.linalg.norm(v / a, axis=1) * np.prod(a)  # |grad| of the implicit form, scaled
        kept = np.vstack([kept, (v * a)[rng.uniform(size=len(v)) < w / w.max()]])
    return kept[:n]


def hemisphere(rng, n):
    v = rng.normal(size=(n, 3))
    v /= np.linalg.norm(v, axis=1)[:, None]
    v[:, 2] = np.abs(v[:, 2])
    return v


def disk(rng, n):
    """The unit disk of z = 0, each point moved off the plane by about 1e-9 (a plane
    of points is all cospherical ties)."""
    r, t = np.sqrt(rng.uniform(0, 1, n)), rng.uniform(0, 2 * np.pi, n)
    return np.c_[r * np.cos(t), r * np.sin(t), 1e-9 * rng.normal(size=n)]


SHAPES = [
    ("cube boundary", lambda g, n: cube_surface(g, n), (1, 0, 1)),
    ("capped cylinder", lambda g, n: cylinder(g, n, True), (1, 0, 1)),
    ("cube with a hole", lambda g, n: cube_with_hole(g, n), (1, 2, 1)),
    ("flat ellipsoid", lambda g, n: ellipsoid(g, n), (1, 0, 1)),
    ("open cylinder", lambda g, n: cylinder(g, n, False), (1, 1, 0)),
    ("hemisphere", lambda g, n: hemisphere(g, n), (1, 0, 0)),
    ("disk", lambda g, n: disk(g, n), (1, 0, 0)),
]
SIZES = (3000, 30000)
NOISE = (0, 0.3, 1.0)


def run(flowrecon, cloud, extra):
    p = subprocess.run([flowrecon, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"] + extra,
                       capture_output=True, text=True)
    m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    betti = tuple(int(x) for x in m.groups()) if m else None
    warned = any(line.startswith("warning:") for line in p.stderr.splitlines())
    choice = re.search(r"^t_r .*\(auto\).*$", p.stdout, re.M)
    return betti, warned, choice.group(0) if choice else ""


def verdict(betti, warned, truth):
    if betti is None:
        return "error"
    return "right" if betti == truth else ("flagged" if warned else "silent")


def clouds(sizes=SIZES, noises=NOISE):
    """Yields (shape, points, noise, cloud as an n x 3 array, true Betti numbers),
    the same for the same arguments (seeded by shape, size and noise)."""
    for k, (name, make, truth) in enumerate(SHAPES):
        for n in sizes:
            clean = make(np.random.default_rng(1000 * k + n % 997), n)
            spacing = cKDTree(clean).query(clean, k=2)[0][:, 1].mean()
            for noise in noises:
                j = NOISE.index(noise)
                rng = np.random.default_rng(7919 * (k + 1) + 31 * j + n % 991)
                p = clean + rng.normal(scale=noise * spacing, size=clean.shape) if noise else clean
                yield name, n, noise, p, truth


def arguments(doc, quick=False):
    """FLOWRECON WORKDIR [--quick]: a comparison script's command line."""
    ap = argparse.ArgumentParser(description=doc, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("flowrecon")
    ap.add_argument("work")
    if quick:
        ap.add_argument("--quick", action="store_true")
    return ap.parse_args()


def compare(flowrecon, work, columns, rows):
    """Runs `flowrecon reconstruct` at its defaults and at `--tp 1.1 --tr 2` on each
    of `rows` ((leading cells, cloud as an n x 3 array, true Betti numbers)),
    written to WORK/cloudNN.xyz; prints a Markdown table (the `columns` named
    first, then the points, the truth, both verdicts and the automatic choice)
    and the counts, which it returns."""
    os.makedirs(work, exist_ok=True)
    counts = {"auto": {}, "fixed": {}}
    print("| %s | points | truth | automatic | fixed t_p 1.1, t_r 2 | automatic choice |" % " | ".join(columns))
    print("|%s---:|---|---|---|---|" % ("---|" * len(columns)))
    for k, (cells, p, truth) in enumerate(rows):
        cloud = os.path.join(work, "cloud%02d.xyz" % k)
        np.savetxt(cloud, p, fmt="%.17g")
        auto = run(flowrecon, cloud, [])
        fixed = run(flowrecon, cloud, ["--tp", "1.1", "--tr", "2"])
        answers = []
        for label, (betti, warned, _) in (("auto", auto), ("fixed", fixed)):
            v = verdict(betti, warned, truth)
            counts[label][v] = counts[label].get(v, 0) + 1
            answers.append("%s %s" % (v, " ".join(map(str, betti)) if betti else "none"))
        print("| %s | %d | %s | %s | %s | %s |" % (" | ".join(cells), len(p), " ".join(map(str, truth)),
                                                  answers[0], answers[1], auto[2]), flush=True)
    for label in ("auto", "fixed"):
        c = counts[label]
        print("%s: %d right, %d flagged, %d silent, %d errors" % (
            label, c.get("right", 0), c.get("flagged", 0), c.get("silent", 0), c.get("error", 0)))
    return counts


def main():
    compare(sys.argv[1], sys.argv[2], ["shape", "noise"],
            (([name, "%g" % noise], p, truth) for name, n, noise, p, truth in clouds()))


if __name__ == "__main__":
    main()
