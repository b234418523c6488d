#!/usr/bin/python3
"""Whole-process benchmark: what a user of `flowrecon` gets, from reading the
file to the written output, against CGAL's sequential Delaunay triangulation of
the same file (build/bin/DelaunayBaseline) in the same run. Peak memory is the
process's maximum RSS (/usr/bin/time). Prints a Markdown table.

  /usr/bin/python3 Benchmarks/whole_process.py [--sizes 1e5 1e6]
      [--shapes cube sphere torus bunny] [--diagram] [--work DIR]

Clouds (seeded, i.i.d.): uniform in a cube; uniform on a sphere; area-uniform on
a torus surface (R 1, r 0.35); area-uniform on the Stanford bunny's triangles
(npm package `bunny`, a scan-like surface with thin ears). --diagram adds
`flowrecon diagram` against GUDHI's alpha-complex persistence (simplex tree +
compute_persistence over Z/2) of the same points.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.path.join(ROOT, "build", "bin")


def torus(n, rng):
    out, R, r = [], 1.0, 0.35
    while sum(len(o) for o in out) < n:
        u, v, w = rng.uniform(0, 1, (3, 2 * n))
        u, v = 2 * np.pi * u, 2 * np.pi * v
        keep = w < (R + r * np.cos(v)) / (R + r)  # area element of the torus
        out.append(np.c_[(R + r * np.cos(v[keep])) * np.cos(u[keep]),
                         (R + r * np.cos(v[keep])) * np.sin(u[keep]), r * np.sin(v[keep])])
    return np.concatenate(out)[:n]


def bunny_mesh():
    prefix = os.path.join(ROOT, "build", "npm")
    module = os.path.join(prefix, "node_modules", "bunny")
    if not os.path.isdir(module):
        subprocess.run(["npm", "install", "--silent", "--no-audit", "--no-fund", "--prefix",
                        prefix, "bunny"], check=True)
    text = subprocess.run(["node", "-e", "const b = require(process.argv[1]);"
                           "process.stdout.write(JSON.stringify([b.positions, b.cells]))", module],
                          check=True, capture_output=True, text=True).stdout
    positions, cells = json.loads(text)
    return np.array(positions, float), np.array(cells, int)


def surface_sample(vertices, triangles, n, rng):
    a, b, c = (vertices[triangles[:, k]] for k in range(3))
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    pick = rng.choice(len(triangles), size=n, p=area / area.sum())
    s, t = rng.uniform(0, 1, (2, n))
    flip = s + t > 1
    s[flip], t[flip] = 1 - s[flip], 1 - t[flip]
    return a[pick] + s[:, None] * (b[pick] - a[pick]) + t[:, None] * (c[pick] - a[pick])


def cloud(shape, n, seed=2026):
    rng = np.random.default_rng(seed)
    if shape == "cube":
        return rng.uniform(0, 1, (n, 3))
    if shape == "sphere":
        x = rng.normal(size=(n, 3))
        return x / np.linalg.norm(x, axis=1)[:, None]
    if shape == "torus":
        return torus(n, rng)
    if shape == "bunny":
        v, t = bunny_mesh()
        return surface_sample(v, t, n, rng)
    raise SystemExit("unknown shape " + shape)


def timed(command):
    """(seconds, peak KB) of a whole process; exits on failure."""
    with tempfile.NamedTemporaryFile("r") as f:
        p = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", f.name, *command],
                           capture_output=True, text=True)
        if p.returncode != 0:
            return None, None, p.stderr.strip().splitlines()[-1] if p.stderr.strip() else "failed"
        seconds, kb = f.read().split()[-2:]
    return float(seconds), int(kb), None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--sizes", nargs="+", type=float, default=[1e5, 1e6])
    ap.add_argument("--shapes", nargs="+", default=["cube", "sphere", "torus", "bunny"])
    ap.add_argument("--diagram", action="store_true")
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "bench"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    print("| cloud | points | CGAL DT (seq) | flowrecon reconstruct | ratio | peak memory | "
          "output |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for n in (int(s) for s in args.sizes):
        for shape in args.shapes:
            xyz = os.path.join(args.work, "%s_%d.xyz" % (shape, n))
            np.savetxt(xyz, cloud(shape, n), fmt="%.17g")
            base, _, _ = timed([os.path.join(BIN, "DelaunayBaseline"), xyz])
            vtu = xyz[:-4] + ".vtu"
            t, kb, error = timed([os.path.join(BIN, "flowrecon"), "reconstruct", xyz, "-o", vtu,
                                  "--quiet"])
            if error:
                print("| %s | %d | %.2f s | %s | | | |" % (shape, n, base, error))
            else:
                print("| %s | %d | %.2f s | %.2f s | %.1f× | %.2f KB/pt | %d B/pt |" % (
                    shape, n, base, t, t / base, kb * 1024 / n / 1000,
                    os.path.getsize(vtu) // n))
            sys.stdout.flush()
            os.remove(xyz) if n > 2e6 else None
    if args.diagram:
        print("\n| cloud | points | GUDHI alpha persistence | flowrecon diagram | speed-up | "
              "peak memory (GUDHI / ours) |")
        print("|---|---:|---:|---:|---:|---:|")
        for n in (int(s) for s in args.sizes):
            xyz = os.path.join(args.work, "cube_%d.xyz" % n)
            np.savetxt(xyz, cloud("cube", n), fmt="%.17g")
            gudhi = ("import gudhi, numpy, sys; p = numpy.loadtxt(sys.argv[1]); "
                     "st = gudhi.AlphaComplex(points=p).create_simplex_tree(); "
                     "st.compute_persistence(homology_coeff_field=2)")
            tg, kg, eg = timed(["/usr/bin/python3", "-c", gudhi, xyz])
            to, ko, eo = timed([os.path.join(BIN, "flowrecon"), "diagram", xyz, "-o",
                                xyz[:-4] + "_pd.csv", "--quiet"])
            print("| cube | %d | %s | %s | %s | %s |" % (
                n, eg or "%.2f s" % tg, eo or "%.2f s" % to,
                "%.1f×" % (tg / to) if not (eg or eo) else "",
                "%.2f / %.2f KB/pt" % (kg * 1.024 / n, ko * 1.024 / n) if not (eg or eo) else ""))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
