#!/usr/bin/python3
"""Whole-process benchmark: what a user of `flowrecon` gets, from reading the
file to the written output, against two CGAL processes on the same file in the
same run: its sequential Delaunay triangulation (build/bin/DelaunayBaseline)
and its advancing front surface reconstruction at its defaults, written as OFF
(build/bin/AdvancingFrontBaseline). `reconstruct` runs at its defaults, so it
writes the default, compact output (Delaunay simplices on the samples); --exact
times `reconstruct --exact` (the exact stable manifolds) instead, the default
until the compact output became it. Each cloud runs the three in turn, --warmup
rounds then --runs measured rounds; times are min-max (median), peaks the
largest maximum RSS (/usr/bin/time), ratios the medians of the rounds' paired
ratios. Prints a Markdown table.

  /usr/bin/python3 Benchmarks/whole_process.py [--sizes 1e5 1e6]
      [--shapes cube sphere torus bunny] [--runs 3] [--warmup 1]
      [--timeout 1800] [--diagram] [--exact] [--work DIR]

Clouds (seeded, i.i.d.): uniform in a cube; uniform on a sphere; area-uniform on
a torus surface (R 1, r 0.35); area-uniform on the Stanford bunny's triangles
(npm package `bunny`, a scan-like surface with thin ears). "answer" is the
Betti numbers `reconstruct` prints with the thresholds it chose (marked
"compact output ≠" when the compact output's printed beside them differ), and for the
advancing front its surface's Euler characteristic, components and boundary
edges; "Betti numbers" is the time of `--timings`' "Betti numbers from the Hasse
diagram" (both t_p candidates), "share" its part of the run's phases. An
advancing front or `reconstruct` run past --timeout is stopped, shown as "–" and
not run again on that cloud.
--diagram adds `flowrecon diagram` against GUDHI's alpha-complex persistence
(simplex tree + compute_persistence over Z/2) of the same points.
"""
import argparse
import json
import os
import re
import signal
import subprocess
import sys
import tempfile
from statistics import median

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components

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


def timed(command, timeout=None):
    """(seconds, peak KB, stdout, error) of a whole process; error is None, or its
    last line of stderr, or "timeout" (the process group is then killed)."""
    with tempfile.NamedTemporaryFile("r") as f:
        p = subprocess.Popen(["/usr/bin/time", "-f", "%e %M", "-o", f.name, *command],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                             start_new_session=True)
        try:
            out, err = p.communicate(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.communicate()
            return None, None, "", "timeout"
        if p.returncode != 0:
            return None, None, out, err.strip().splitlines()[-1] if err.strip() else "failed"
        seconds, kb = f.read().split()[-2:]
    return float(seconds), int(kb), out, None


def off_answer(shape, path):
    """Euler characteristic, components and boundary edges of the facets of an OFF
    file (the vertices no facet uses are left out); "(right)" when it is one closed
    surface of the shape's Euler characteristic."""
    with open(path) as f:
        assert f.readline().strip() == "OFF"
        nv, nf = (int(w) for w in f.readline().split()[:2])
        data = np.fromstring(f.read(), sep=" ")
    if nf == 0:
        return "no facets"
    faces = data[3 * nv:].reshape(nf, 4)[:, 1:].astype(np.int64)
    used = np.unique(faces)
    e = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    edges, count = np.unique(e, axis=0, return_counts=True)
    graph = coo_matrix((np.ones(len(edges)), (edges[:, 0], edges[:, 1])), shape=(nv, nv))
    components = connected_components(graph, directed=False)[0] - (nv - len(used))
    chi = len(used) - len(edges) + nf
    boundary, singular = int((count == 1).sum()), int((count > 2).sum())
    text = "χ %d, %d component%s" % (chi, components, "" if components == 1 else "s")
    text = text.replace("-", "−") + (", closed" if boundary == 0 else
                                     ", %d boundary edges" % boundary)
    text += ", %d non-manifold edges" % singular if singular else ""
    if shape in SURFACE_CHI:
        right = (components, chi, boundary, singular) == (1, SURFACE_CHI[shape], 0, 0)
        text += " (right)" if right else " (wrong)"
    return text


# Betti numbers of the sampled shapes (the npm bunny is one closed surface, χ 2),
# and the Euler characteristic of the surfaces.
EXPECTED = {"cube": "1 0 0", "sphere": "1 0 1", "torus": "1 2 1", "bunny": "1 0 1"}
SURFACE_CHI = {"sphere": 2, "torus": 0, "bunny": 2}


def flowrecon_answer(shape, out):
    m = re.search(r"^t_r ([0-9.e+-]+) \(auto\), t_p ([0-9.e+-]+) \(auto\): Betti numbers ([0-9 ]+)",
                  out, re.M)
    if not m:
        return "?"
    betti = m.group(3).strip()
    right = (" (right)" if betti == EXPECTED[shape] else " (wrong)") if shape in EXPECTED else ""
    compact = re.search(r"^compact output's Betti numbers ([0-9 ]+)$", out, re.M)
    differ = ", compact output ≠ %s" % compact.group(1) if compact and compact.group(1) != betti else ""
    return "%s%s, t_r %.3g, t_p %s%s" % (betti, right, float(m.group(1)), m.group(2), differ)


def betti_seconds(out):
    """(Betti-number seconds, their share of the phases) from --timings' lines."""
    m = re.search(r"^Betti numbers from the Hasse diagram \(s\):(.*)$", out, re.M)
    phases = re.search(r"^timings \(s\):(.*)$", out, re.M)
    if not (m and phases):
        return None, None
    betti = sum(float(x) for x in re.findall(r": ([0-9.]+)", m.group(1)))
    total = sum(float(x) for x in re.findall(r" ([0-9.]+);", phases.group(1)))
    return betti, betti / total if total else None


def span(values, unit=" s", digits=3):
    values = [v for v in values if v is not None]
    if not values:
        return "–"
    g = lambda v: "%.*g" % (digits, v)
    if len(values) == 1 or g(min(values)) == g(max(values)):
        return g(values[0]) + unit
    return "%s–%s%s (median %s)" % (g(min(values)), g(max(values)), unit, g(median(values)))


def memory(kbs):
    kbs = [k for k in kbs if k is not None]
    if not kbs:
        return "–"
    k = max(kbs)
    return "%.2f GiB" % (k / 2**20) if k >= 2**20 else "%d MiB" % round(k / 2**10)


def ratio(a, b):
    pairs = [x / y for x, y in zip(a, b) if x is not None and y is not None]
    return "%.1f" % median(pairs) if pairs else "–"


def stopped(error, timeout):
    return "– (%s after %g s)" % (error, timeout) if error == "timeout" else "– (%s)" % error


def whole_process(shape, n, xyz, args):
    """One cloud: the three processes in turn, round after round; a peer that fails
    or runs past --timeout is left out of the later rounds."""
    delaunay, afsr, ours, betti, share = [], [], [], [], []
    peaks = {"delaunay": [], "afsr": [], "ours": []}
    answer, afsr_error, error = "?", None, None
    off, vtu = xyz[:-4] + "_afsr.off", xyz[:-4] + ".vtu"
    for round_ in range(args.warmup + args.runs):
        keep = round_ >= args.warmup
        t, kb, _, _ = timed([os.path.join(BIN, "DelaunayBaseline"), xyz])
        if keep:
            delaunay.append(t)
            peaks["delaunay"].append(kb)
        if afsr_error is None:
            t, kb, _, afsr_error = timed([os.path.join(BIN, "AdvancingFrontBaseline"), xyz, off],
                                         timeout=args.timeout)
            if keep:
                afsr.append(t)
                peaks["afsr"].append(kb)
        if error is None:
            t, kb, out, error = timed([os.path.join(BIN, "flowrecon"), "reconstruct", xyz, "-o",
                                       vtu, "--timings"] + (["--exact"] if args.exact else []),
                                      timeout=args.timeout)
            if keep and error is None:
                ours.append(t)
                peaks["ours"].append(kb)
                b, s = betti_seconds(out)
                betti.append(b)
                share.append(s)
                answer = flowrecon_answer(shape, out)
    if afsr_error is None:
        afsr_answer = off_answer(shape, off)
    else:
        afsr_answer, afsr, peaks["afsr"] = stopped(afsr_error, args.timeout), [], []
    if error is not None:
        answer, ours, peaks["ours"], betti, share = stopped(error, args.timeout), [], [], [], []
    for path in (off, vtu):
        os.remove(path) if os.path.exists(path) and n > 2e6 else None
    return "| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s / %s / %s | %s | %s |" % (
        shape, n, answer, afsr_answer, span(delaunay), span(afsr), span(ours),
        ratio(ours, delaunay), ratio(ours, afsr),
        memory(peaks["delaunay"]), memory(peaks["afsr"]), memory(peaks["ours"]),
        span(betti), span([100 * s for s in share if s is not None], unit=" %", digits=2))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--sizes", nargs="+", type=float, default=[1e5, 1e6])
    ap.add_argument("--shapes", nargs="+", default=["cube", "sphere", "torus", "bunny"])
    ap.add_argument("--runs", type=int, default=3, help="measured rounds per cloud")
    ap.add_argument("--warmup", type=int, default=1, help="rounds run first and not counted")
    ap.add_argument("--timeout", type=float, default=1800,
                    help="seconds after which an advancing front or reconstruct run is stopped")
    ap.add_argument("--diagram", action="store_true")
    ap.add_argument("--exact", action="store_true",
                    help="time reconstruct --exact (the exact stable manifolds), not the default")
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "bench"))
    args = ap.parse_args()
    os.makedirs(args.work, exist_ok=True)
    ours = "`reconstruct --exact`" if args.exact else "`reconstruct` (compact output)"
    print("| cloud | points | `reconstruct` answer at defaults | advancing front answer | "
          "CGAL Delaunay | advancing front | " + ours + " | ratio to Delaunay | "
          "ratio to advancing front | peak (Delaunay / advancing front / `reconstruct`) | "
          "Betti numbers | share |")
    print("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|")
    for n in (int(s) for s in args.sizes):
        for shape in args.shapes:
            xyz = os.path.join(args.work, "%s_%d.xyz" % (shape, n))
            np.savetxt(xyz, cloud(shape, n), fmt="%.17g")
            print(whole_process(shape, n, xyz, args))
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
            tg, kg, _, eg = timed(["/usr/bin/python3", "-c", gudhi, xyz])
            to, ko, _, eo = timed([os.path.join(BIN, "flowrecon"), "diagram", xyz, "-o",
                                xyz[:-4] + "_pd.csv", "--quiet"])
            print("| cube | %d | %s | %s | %s | %s |" % (
                n, eg or "%.2f s" % tg, eo or "%.2f s" % to,
                "%.1f×" % (tg / to) if not (eg or eo) else "",
                "%.2f / %.2f KB/pt" % (kg * 1.024 / n, ko * 1.024 / n) if not (eg or eo) else ""))
            sys.stdout.flush()


if __name__ == "__main__":
    main()
