#!/usr/bin/python3
"""The compact output (the default of `reconstruct`: Delaunay simplices on the
samples) against the exact one (`reconstruct --exact`), on the test clouds: their
Betti numbers, cells per sample, file sizes and times.

  PYTHONPATH=Apps/Scripts /usr/bin/python3 Benchmarks/Study/compact_study.py OUTDIR
      [--flowrecon build/bin/flowrecon] [--only REGEX] [--large] [--args "--tp 1.1 --tr 2"]
      [--sweep]

For each cloud (Data/*.xyz; generate_clouds.make with its fixed seeds; noisy ones
are Poisson-disk samples plus Gaussian noise of standard deviation `noise` x their
mean nearest-neighbour spacing, from a seed of the cloud's id) the script writes
OUTDIR/clouds/ID.xyz and runs, at the automatic thresholds,

  flowrecon reconstruct ID.xyz -o ID.exact.vtu --exact
  flowrecon reconstruct ID.xyz -o ID.compact.vtu

under /usr/bin/time (wall seconds, peak RSS), both with the --args given (e.g. fixed
thresholds instead of the automatic ones). The exact run's Betti numbers are its
'Betti numbers: b0 b1 b2' line; the compact run's its "compact output's Betti
numbers" line (the homology of the cells it wrote), and GUDHI's Betti numbers of
the compact file (flowrecon_testing.oracles.gudhi_betti, an oracle written by
others; "–" when GUDHI is missing). The report OUTDIR/study.md (also
printed) has one row per cloud; OUTDIR/results.json every run. With --large, the
i.i.d. 10^5-point clouds too. For the compact file's triangles it also counts the
border edges (in one triangle), the non-manifold edges (in more than two) and the
singular vertices (whose triangles do not make one disc or sphere around them):
all 0 for a closed surface.

With --sweep, only `reconstruct ID.xyz -o OUT --tp P --tr T` runs (it prints the
exact Betti numbers beside the compact ones, and GUDHI's of the file are computed),
for t_p in 0, 1.1 and t_r in 1.2, 1.5, 3, 5, inf; the report OUTDIR/sweep.md has one
row per cloud: the configurations where the three agree, and the voids without a
maximum filled (every run in OUTDIR/sweep.json).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
import zlib

import generate_clouds as gc
import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "Testing", "Python"))


def gudhi(vtu):
    """GUDHI's Betti numbers of the cells of a .vtu, or None without GUDHI."""
    try:
        from flowrecon_testing.oracles import gudhi_betti
        from flowrecon_testing.run import read_grid
        return gudhi_betti(read_grid(vtu))
    except ImportError:
        return None

# (id, source, size or None, noise or None, class); source: a Data file or a shape.
CLOUDS = [
    ("data_torus", "Data/torus.xyz", None, None, "bundled"),
    ("data_two_hemispheres", "Data/two_hemispheres.xyz", None, None, "bundled"),
    ("data_bunny", "Data/bunny.xyz", None, None, "bundled"),
] + [(s, s, None, None, "i.i.d.") for s in (
    "sphere", "torus", "genus2", "genus3", "trefoil", "circle", "ball", "cube", "two_spheres",
    "two_hemispheres", "sphere_with_segment", "thin_plate")
] + [(s, s, None, None, "quasi-uniform") for s in (
    "sphere_qu", "torus_qu", "genus2_qu", "trefoil_qu", "ball_qu", "two_spheres_qu",
    "sphere_with_segment_qu", "vase_qu", "plate3_qu", "tree")
] + [(s, s, None, None, "Poisson disk") for s in (
    "sphere_pd", "torus_pd", "genus2_pd", "cube_pd", "two_hemispheres_pd")
] + [(s, s, None, None, "lattice") for s in ("lattice_shell", "latlong_sphere", "grid5_jittered")
] + [("%s_noise%g" % (s, z), s, None, z, "noisy") for s in ("sphere_pd", "torus_pd")
     for z in (0.1, 0.3)
] + [("%s_n%d" % (s, n), s, n, None, "i.i.d. large") for s, n in (
    ("sphere", 10000), ("torus", 10000), ("genus2", 10000), ("ball", 10000))
] + [("%s_n%d" % (s, n), s, n, None, "i.i.d. 10^5") for s, n in (
    ("sphere", 100000), ("torus", 100000))]


def truth(source):
    return None if source.startswith("Data/") else tuple(gc.betti(source))


def make_cloud(cid, source, size, noise, path):
    if os.path.exists(path):
        return
    if source.startswith("Data/"):
        points = gc.read_xyz(os.path.join(ROOT, source))
    else:
        points = gc.make(source, size)
        if noise is not None:
            from scipy.spatial import cKDTree
            d, _ = cKDTree(points).query(points, k=2)
            rng = np.random.default_rng(zlib.crc32(cid.encode()))
            points = points + rng.normal(0.0, noise * float(np.mean(d[:, 1])), points.shape)
    with open(path + ".tmp", "w") as f:
        f.write(gc.to_xyz_text(points))
    os.replace(path + ".tmp", path)


def run(cmd):
    """(exit code, stdout, stderr, wall s, peak MB) of cmd under /usr/bin/time."""
    with tempfile.NamedTemporaryFile("r", suffix=".time", delete=False) as tf:
        timefile = tf.name
    p = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", timefile] + cmd,
                       capture_output=True, text=True)
    with open(timefile) as f:
        fields = f.read().split()
    os.remove(timefile)
    return p.returncode, p.stdout, p.stderr, float(fields[-2]), int(fields[-1]) / 1024.0


def numbers(pattern, text):
    m = re.search(pattern, text, re.M)
    return None if not m else tuple(int(x) for x in m.groups())


def surface_stats(vtu):
    """(edges in one triangle, edges in more than two, vertices whose triangles do
    not make one disc or sphere around them) of the compact file's triangles."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(vtu)
    r.Update()
    g = r.GetOutput()
    types = vtk_to_numpy(g.GetCellTypesArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    off = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    idx = np.nonzero(types == 5)[0]
    if not len(idx):
        return (0, 0, 0)
    t = np.sort(np.stack([conn[off[idx] + j] for j in range(3)], axis=1), axis=1)
    e = np.concatenate([t[:, [0, 1]], t[:, [0, 2]], t[:, [1, 2]]])
    _, counts = np.unique(e, axis=0, return_counts=True)
    # a vertex is regular when its link (the opposite edges) is one path or cycle
    link = {}
    for a, b, c in t.tolist():
        for v, x, y in ((a, b, c), (b, a, c), (c, a, b)):
            link.setdefault(v, []).append((x, y))
    singular = 0
    for v, edges in link.items():
        adj = {}
        for x, y in edges:
            adj.setdefault(x, []).append(y)
            adj.setdefault(y, []).append(x)
        if any(len(n) > 2 for n in adj.values()):
            singular += 1
            continue
        seen, stack = {edges[0][0]}, [edges[0][0]]
        while stack:
            for w in adj[stack.pop()]:
                if w not in seen:
                    seen.add(w)
                    stack.append(w)
        singular += len(seen) != len(adj)
    return (int((counts == 1).sum()), int((counts > 2).sum()), singular)


def study(cid, source, size, noise, cls, opts):
    path = os.path.join(opts.outdir, "clouds", cid + ".xyz")
    make_cloud(cid, source, size, noise, path)
    n = sum(1 for _ in open(path))
    row = {"id": cid, "class": cls, "points": n, "truth": truth(source)}
    for kind, extra in (("exact", ["--exact"]), ("compact", [])):
        out = os.path.join(opts.outdir, "runs", "%s.%s.vtu" % (cid, kind))
        code, so, se, wall, peak = run([opts.flowrecon, "reconstruct", path, "-o", out] +
                                       opts.args.split() + extra)
        r = {"exit": code, "wall_s": wall, "peak_mb": round(peak, 1),
             "size_bytes": os.path.getsize(out) if code == 0 else None,
             "cells": numbers(r"^\S+: (\d+) cells,", so),
             "betti": numbers(r"^Betti numbers: (\d+) (\d+) (\d+)$", so),
             "warnings": [l for l in se.splitlines() if l.startswith("warning:")]}
        if kind == "compact":
            r["compact_betti"] = numbers(r"^compact output's Betti numbers (\d+) (\d+) (\d+)$", so)
            r["counts"] = numbers(r"^compact output: (\d+) triangles, (\d+) tetrahedra, (\d+) edges, "
                                  r"(\d+) samples, \S+ cells per sample; (\d+) triangles shared by two "
                                  r"patches, (\d+) crossed twice by one walk, (\d+) voids", so)
        if kind == "compact" and code == 0:
            r["surface"] = surface_stats(out)
            r["gudhi"] = gudhi(out)
        if code != 0:
            r["error"] = se.strip().splitlines()[-1:] or ["?"]
        row[kind] = r
        if not opts.keep_vtu and os.path.exists(out):
            os.remove(out)
    return row


SWEEP = [(tp, tr) for tp in ("0", "1.1") for tr in ("1.2", "1.5", "3", "5", "inf")]


def sweep(cid, source, size, noise, cls, opts):
    path = os.path.join(opts.outdir, "clouds", cid + ".xyz")
    make_cloud(cid, source, size, noise, path)
    out = os.path.join(opts.outdir, "runs", cid + ".sweep.vtu")
    row = {"id": cid, "class": cls, "runs": []}
    for tp, tr in SWEEP:
        code, so, se, wall, peak = run([opts.flowrecon, "reconstruct", path, "-o", out,
                                        "--tp", tp, "--tr", tr])
        counts = numbers(r"(\d+) voids without a maximum filled", so)
        row["runs"].append({"tp": tp, "tr": tr, "exit": code,
                            "exact": numbers(r"^Betti numbers: (\d+) (\d+) (\d+)$", so),
                            "compact": numbers(r"^compact output's Betti numbers (\d+) (\d+) (\d+)$", so),
                            "gudhi": gudhi(out) if code == 0 else None,
                            "filled": counts[0] if counts else None})
    if os.path.exists(out):
        os.remove(out)
    return row


def sweep_report(rows):
    lines = ["| cloud | configurations agreeing | voids filled (sum) | where they differ |",
             "|---|---:|---:|---|"]
    agree = total = 0
    for r in rows:
        ok = [x for x in r["runs"] if x["exit"] == 0 and x["exact"] is not None]
        same = [x for x in ok if x["exact"] == x["compact"] == (x["gudhi"] or x["compact"])]
        differ = ["t_p %s t_r %s: %s vs %s (GUDHI %s)" % (x["tp"], x["tr"], btext(x["exact"]),
                                                          btext(x["compact"]), btext(x["gudhi"]))
                  for x in ok if x not in same]
        agree += len(same)
        total += len(ok)
        lines.append("| %s | %d of %d | %d | %s |" % (r["id"], len(same), len(ok),
                                                   sum(x["filled"] or 0 for x in ok), "; ".join(differ)))
    lines.append("")
    lines.append("Betti numbers of the compact output (printed and by GUDHI) equal the exact "
                 "output's in %d of %d runs (t_p 0 and 1.1 x t_r 1.2, 1.5, 3, 5, inf)." % (agree, total))
    return "\n".join(lines)


def btext(b):
    return "–" if b is None else " ".join(str(x) for x in b)


def report(rows):
    lines = ["| cloud | n | truth | exact | compact | GUDHI | agree | cells/sample exact → compact | "
             "file (KB) exact → compact | time (s) exact → compact | triangles shared, "
             "revisited | voids filled | compact edges, tetrahedra | border, non-manifold edges, singular vertices |",
             "|---|---:|---|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    agree = total = 0
    for r in rows:
        e, c = r["exact"], r["compact"]
        if e["exit"] != 0 or c["exit"] != 0:
            lines.append("| %s | %d | %s | error | error | | | | | | | | | |" % (r["id"], r["points"], btext(r["truth"])))
            continue
        same = c["compact_betti"] == e["betti"] == (c.get("gudhi") or c["compact_betti"])
        total += 1
        agree += same
        counts = c["counts"] or (0,) * 7
        lines.append("| %s | %d | %s | %s | %s | %s | %s | %.2f → %.2f | %d → %d | %.2f → %.2f | %d, %d | %d | %d, %d | %d, %d, %d |" % ((
            r["id"], r["points"], btext(r["truth"]), btext(e["betti"]), btext(c["compact_betti"]),
            btext(c.get("gudhi")),
            "yes" if same else "**no**", e["cells"][0] / r["points"], c["cells"][0] / r["points"],
            e["size_bytes"] / 1024, c["size_bytes"] / 1024, e["wall_s"], c["wall_s"],
            counts[4], counts[5], counts[6], counts[2], counts[1]) + tuple(c["surface"])))
    lines.append("")
    lines.append("Betti numbers of the compact output (printed and by GUDHI) equal the exact "
                 "output's on %d of %d clouds." % (agree, total))
    return "\n".join(lines)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--flowrecon", default=os.path.join(ROOT, "build", "bin", "flowrecon"))
    ap.add_argument("--only", default=None)
    ap.add_argument("--large", action="store_true")
    ap.add_argument("--keep-vtu", action="store_true")
    ap.add_argument("--args", default="", help="more arguments of both runs")
    ap.add_argument("--sweep", action="store_true", help="t_p x t_r sweep of the default output")
    opts = ap.parse_args(argv)
    for sub in ("clouds", "runs"):
        os.makedirs(os.path.join(opts.outdir, sub), exist_ok=True)
    rows = []
    for cid, source, size, noise, cls in CLOUDS:
        if opts.only and not re.search(opts.only, cid):
            continue
        if cls == "i.i.d. 10^5" and not opts.large:
            continue
        start = time.time()
        rows.append((sweep if opts.sweep else study)(cid, source, size, noise, cls, opts))
        print("%s: %.1f s" % (cid, time.time() - start), file=sys.stderr, flush=True)
        with open(os.path.join(opts.outdir, "sweep.json" if opts.sweep else "results.json"), "w") as f:
            json.dump(rows, f, indent=1)
    text = sweep_report(rows) if opts.sweep else report(rows)
    with open(os.path.join(opts.outdir, "sweep.md" if opts.sweep else "study.md"), "w") as f:
        f.write(text + "\n")
    print(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
