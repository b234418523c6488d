#!/usr/bin/env python3
"""The paper's experiments (Cazals & Cohen-Steiner 2009, §5 and §7.3-7.4) on clouds
made by generate_clouds.py, the committed Data/two_hemispheres.xyz and the Stanford
bunny of the npm package `bunny`.

For every model: the flow complex once, then for t_p = 0, 1.1 and the paper's
choices the simplification and the reconstruction at t_r = infinity (its profile:
priority of every popped node), the Betti numbers over Z/2 (GUDHI) of the
reconstruction at (t_p, t_r) = (1.1, 2) and at the paper's parameter choices,
compared with the true ones, and the time of each stage. Written into OUTDIR:

- ``MODEL.xyz``                 the cloud
- ``MODEL_tpX_profile.csv``     profile at t_r = inf (Step, NodeId, Index, Priority,
                                Threshold) for each t_p used
- ``MODEL_profile.png``         the profiles at t_p = 0 and 1.1 (as the paper's
                                Figs. 9-16), log-scaled priorities, t_r = 2 marked
- ``MODEL_recon_tpX_trY.vtu``   the reconstructions at the parameter choices
- ``results.json``, ``results.md`` the table (Betti obtained vs expected, times)

Run (the Debian interpreter, the build-tree package)::

    PYTHONPATH=build/lib/python3/dist-packages:Apps/Scripts /usr/bin/python3 \\
        Benchmarks/Study/experiments.py \\
        [OUTDIR] [--only NAME,...] [--png-dir Data/experiments] [--npm-prefix build/npm]

OUTDIR defaults to build/experiments. The bunny needs the npm package, installed
with ``npm install --prefix build/npm bunny`` (and ``node``); without it the script
stops with a message saying so (use ``--only`` to leave the bunny out).
"""

import argparse
import json
import os
import shutil
import subprocess
import sys
import time

import numpy as np

import generate_clouds as gc

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

INF = float("inf")
TR_SCAN = [round(1.0 + 0.05 * k, 2) for k in range(1, 61)]  # 1.05 .. 4.0

# name -> (title, cloud source, expected Betti or None (from the mesh), runs
#          [(t_p, t_r, why)])
EXPERIMENTS = [
    ("two_hemispheres", "Two intersecting hemispheres (Data/two_hemispheres.xyz, i.i.d.)",
     ("file", os.path.join(REPO, "Data", "two_hemispheres.xyz")), (1, 0, 0),
     [(1.1, 2.0, "defaults"), (0.0, 1.9, "paper Fig. 3(a), 4(a)"), (0.0, 2.1, "paper Fig. 4(b)"),
      (1.05, 2.5, "paper Fig. 3(c,d)")]),
    ("two_hemispheres_qu", "Two intersecting hemispheres, quasi-uniform (3,000 pts)",
     ("gen", "two_hemispheres_qu"), (1, 0, 0),
     [(1.1, 2.0, "defaults"), (0.0, 1.9, "paper Fig. 3(a), 4(a)"), (0.0, 2.1, "paper Fig. 4(b)"),
      (1.05, 2.5, "paper Fig. 3(c,d)")]),
    ("vase", "Vase: surface of revolution + 2 handles (curves)",
     ("gen", "vase_qu"), (1, 2, 0),
     [(1.1, 2.0, "defaults"), (0.0, 1.7, "paper Fig. 5(a)"), (1.02, 2.0, "paper Fig. 5(b)")]),
    ("plate3", "Mechanical-like genus-3 part (plate with 3 holes, 8,000 pts)",
     ("gen", "plate3_qu"), (1, 6, 1),
     [(1.1, 2.0, "defaults"), (1.1, 2.1, "paper Fig. 7")]),
    ("tree", "Tree of thin branches (depth 5)",
     ("gen", "tree"), (1, 0, 0),
     [(1.1, 2.0, "defaults"), (1.1, 2.2, "paper Fig. 8")]),
    ("bunny", "Stanford bunny (npm `bunny`: mesh vertices)",
     ("bunny", "vertices"), None,
     [(1.1, 2.0, "defaults"), (0.0, 2.0, "no persistence")]),
    ("bunny_resampled", "Stanford bunny (npm `bunny`: 8,000 pts quasi-uniform on the mesh)",
     ("bunny", "resampled"), None,
     [(1.1, 2.0, "defaults"), (0.0, 2.0, "no persistence")]),
]


# --------------------------------------------------------------------------- clouds


def load_bunny(npm_prefix):
    """positions (n, 3) and cells (m, 3) of the npm package `bunny`."""
    node = shutil.which("node")
    pkg = os.path.join(npm_prefix, "node_modules", "bunny")
    if node is None or not os.path.isdir(pkg):
        sys.exit("experiments.py: the Stanford bunny needs node and the npm package `bunny` "
                 "in %s (missing %s); install it with\n    npm install --prefix %s bunny\n"
                 "or leave the bunny out with --only"
                 % (npm_prefix, "node" if node is None else pkg, npm_prefix))
    out = subprocess.run(
        [node, "-e", "process.stdout.write(JSON.stringify(require(process.argv[1])))", pkg],
        check=True, capture_output=True, text=True).stdout
    data = json.loads(out)
    return np.asarray(data["positions"], dtype=float), np.asarray(data["cells"], dtype=np.int64)


def mesh_betti(cells, n_vertices):
    """Betti numbers over Z/2 of a triangle mesh (GUDHI), and its boundary loops."""
    import gudhi
    st = gudhi.SimplexTree()
    for t in cells:
        st.insert([int(v) for v in t], 0.0)
    st.compute_persistence(persistence_dim_max=True)
    b = (list(st.betti_numbers()) + [0, 0, 0])[:3]
    edges = {}
    for t in cells:
        for i in range(3):
            e = tuple(sorted((int(t[i]), int(t[(i + 1) % 3]))))
            edges[e] = edges.get(e, 0) + 1
    boundary = [e for e, c in edges.items() if c == 1]
    parent = {}

    def find(x):
        while parent.setdefault(x, x) != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x
    for a, c in boundary:
        parent[find(a)] = find(c)
    loops = len({find(v) for e in boundary for v in e})
    return tuple(b), loops, n_vertices - len(edges) + len(cells)


def sample_mesh(points, cells, n, rng):
    """Quasi-uniform sample of a triangle mesh: area-uniform i.i.d., then farthest points."""
    a, b, c = points[cells[:, 0]], points[cells[:, 1]], points[cells[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    m = gc.QU_FACTOR * n
    tri = rng.choice(len(cells), size=m, p=area / area.sum())
    u, v = rng.uniform(0.0, 1.0, m), rng.uniform(0.0, 1.0, m)
    flip = u + v > 1.0
    u[flip], v[flip] = 1.0 - u[flip], 1.0 - v[flip]
    p = a[tri] + u[:, None] * (b[tri] - a[tri]) + v[:, None] * (c[tri] - a[tri])
    return gc.farthest_points(p, n)


def make_cloud(source, npm_prefix):
    kind, what = source
    if kind == "file":
        return gc.read_xyz(what), None
    if kind == "gen":
        return gc.make(what), None
    positions, cells = load_bunny(npm_prefix)
    truth, loops, chi = mesh_betti(cells, len(positions))
    note = "mesh: %d vertices, %d triangles, Euler characteristic %d, %d boundary loop(s)" % (
        len(positions), len(cells), chi, loops)
    if what == "vertices":
        return positions, (truth, note)
    return sample_mesh(positions, cells, 8000, np.random.default_rng(301)), (truth, note)


# --------------------------------------------------------------------------- pipeline


def polydata(points):
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkPolyData
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=True))
    pd = vtkPolyData()
    pd.SetPoints(pts)
    return pd


def cells_of(grid):
    """The output cells as lists of point ids (vertices, edges, triangles, tetrahedra)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    ca = grid.GetCells()
    offsets = vtk_to_numpy(ca.GetOffsetsArray())
    conn = vtk_to_numpy(ca.GetConnectivityArray())
    return [conn[offsets[c]:offsets[c + 1]].tolist() for c in range(len(offsets) - 1)]


def betti_of(grid):
    """Betti numbers over Z/2 (b0, b1, b2) of the output cells and all their faces
    (GUDHI SimplexTree, filtration 0)."""
    import gudhi
    st = gudhi.SimplexTree()
    for cell in cells_of(grid):
        st.insert(cell, 0.0)
    st.compute_persistence(persistence_dim_max=True)
    return tuple((list(st.betti_numbers()) + [0, 0, 0])[:3])


def betti_scan(grid, trs):
    """{t_r: Betti numbers of the cells of Threshold < t_r} for a run at t_r = inf,
    from one persistence computation over the filtration by Threshold (nestedness)."""
    import gudhi
    from vtkmodules.util.numpy_support import vtk_to_numpy
    thr = vtk_to_numpy(grid.GetCellData().GetArray("Threshold"))
    st = gudhi.SimplexTree()
    for cell, t in zip(cells_of(grid), thr):
        st.insert(cell, float(t))  # faces already present with a higher value are lowered
    st.make_filtration_non_decreasing()
    st.compute_persistence(persistence_dim_max=True)
    out = {}
    for tr in trs:
        b = [0, 0, 0]
        for d in range(3):
            for birth, death in st.persistence_intervals_in_dimension(d):
                if birth < tr <= death:
                    b[d] += 1
        out[tr] = tuple(b)
    return out


def table_column(table, name):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    return vtk_to_numpy(table.GetColumnByName(name))


def write_profile_csv(table, path):
    cols = ["Step", "NodeId", "Index", "Priority", "Threshold"]
    data = [table_column(table, c) for c in cols]
    with open(path, "w") as f:
        f.write(",".join(cols) + "\n")
        for row in zip(*data):
            f.write("%d,%d,%d,%r,%r\n" % (int(row[0]), int(row[1]), int(row[2]),
                                          float(row[3]), float(row[4])))


def write_vtu(grid, path):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter
    w = vtkXMLUnstructuredGridWriter()
    w.SetFileName(path)
    w.SetInputData(grid)
    w.SetDataModeToAppended()
    w.SetCompressorTypeToZLib()
    w.Write()


def run_experiment(name, title, points, truth, runs, outdir, pngdir, log):
    import flowrecon
    from vtkmodules.vtkCommonDataModel import vtkTable, vtkUnstructuredGrid
    result = {"name": name, "title": title, "points": int(len(points)), "expected": list(truth),
              "runs": []}
    with open(os.path.join(outdir, name + ".xyz"), "w") as f:
        f.write(gc.to_xyz_text(points))
    t0 = time.perf_counter()
    fc = flowrecon.vtkFlowComplex()
    fc.SetInputData(polydata(points))
    fc.Update()
    result["time_complex"] = time.perf_counter() - t0
    log("%s: %d points, flow complex %.2f s" % (name, len(points), result["time_complex"]))

    profiles = {}
    tps = sorted({0.0, 1.1} | {tp for tp, _, _ in runs})
    for tp in tps:
        t0 = time.perf_counter()
        simp = flowrecon.vtkFlowComplexSimplification()
        simp.SetInputConnection(fc.GetOutputPort())
        simp.SetPersistenceThreshold(tp)
        simp.Update()
        t_simp = time.perf_counter() - t0
        t0 = time.perf_counter()
        rec = flowrecon.vtkFlowReconstruction()
        rec.SetInputConnection(simp.GetOutputPort())
        rec.SetReconstructionThreshold(1e300)
        rec.Update()
        t_inf = time.perf_counter() - t0
        at_inf = vtkUnstructuredGrid()
        at_inf.DeepCopy(rec.GetOutput())
        table = vtkTable()
        table.DeepCopy(rec.GetOutputDataObject(1))
        profiles[tp] = table
        write_profile_csv(table, os.path.join(outdir, "%s_tp%g_profile.csv" % (name, tp)))
        # which t_r of the scan give the truth (nested: Threshold < t_r selects them)
        scan = betti_scan(at_inf, TR_SCAN)
        good = [tr for tr in TR_SCAN if scan[tr] == tuple(truth)]
        for rtp, rtr, why in runs:
            if rtp != tp:
                continue
            t0 = time.perf_counter()
            rec.SetReconstructionThreshold(rtr)
            rec.Update()
            t_rec = time.perf_counter() - t0
            grid = rec.GetOutput()
            t0 = time.perf_counter()
            b = betti_of(grid)
            t_betti = time.perf_counter() - t0
            write_vtu(grid, os.path.join(outdir, "%s_recon_tp%g_tr%g.vtu" % (name, rtp, rtr)))
            run = {"tp": rtp, "tr": rtr, "why": why, "betti": list(b), "ok": b == tuple(truth),
                   "cells": int(grid.GetNumberOfCells()), "time_simplification": t_simp,
                   "time_reconstruction": t_rec, "time_reconstruction_inf": t_inf,
                   "time_betti": t_betti, "tr_scan_ok": good}
            result["runs"].append(run)
            log("  t_p %-4g t_r %-4g (%s): Betti %s, expected %s %s; cells %d; simplification "
                "%.2f s, reconstruction %.2f s, Betti %.2f s; truth at t_r in %s"
                % (rtp, rtr, why, b, tuple(truth), "ok" if run["ok"] else "DIFFERS",
                   run["cells"], t_simp, t_rec, t_betti, ranges(good)))
        result.setdefault("tr_scan_ok", {})["%g" % tp] = good
    plot_profiles(name, title, profiles, os.path.join(outdir, name + "_profile.png"))
    if pngdir:
        plot_profiles(name, title, profiles, os.path.join(pngdir, name + "_profile.png"),
                      small=True)
    return result


def ranges(values, step=0.05):
    """[1.1, 1.15, 1.2, 1.5] -> '1.1-1.2, 1.5' (runs of the scan grid)."""
    if not values:
        return "none of 1.05..4"
    out, start, prev = [], values[0], values[0]
    for v in values[1:] + [None]:
        if v is not None and abs(v - prev - step) < 1e-9:
            prev = v
            continue
        out.append("%g" % start if start == prev else "%g-%g" % (start, prev))
        if v is not None:
            start = prev = v
    return ", ".join(out)


def plot_profiles(name, title, profiles, path, small=False):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tps = [tp for tp in (0.0, 1.1) if tp in profiles]
    fig, axes = plt.subplots(1, len(tps), figsize=(8, 2.8) if small else (12, 4.5),
                             squeeze=False)
    for ax, tp in zip(axes[0], tps):
        table = profiles[tp]
        prio = table_column(table, "Priority")
        index = table_column(table, "Index")
        steps = np.arange(1, len(prio) + 1)
        colors = np.array(["0.5", "gold", "darkorange", "red"])[np.clip(index, 0, 3)]
        ax.scatter(steps, prio, s=2 if small else 4, c=colors, linewidths=0, rasterized=True)
        ax.axhline(2.0, color="tab:blue", lw=0.8, ls="--")
        ax.set_yscale("log")
        ax.set_xlabel("step")
        ax.set_ylabel("priority")
        ax.set_title("t_p = %g, t_r = inf" % tp, fontsize=9)
        ax.tick_params(labelsize=7)
    fig.suptitle("%s: reconstruction profile (index 0/1/2/3 grey/yellow/orange/red)" % name,
                 fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=70 if small else 100)
    plt.close(fig)


# --------------------------------------------------------------------------- report


def markdown(results):
    lines = ["| model | points | t_p | t_r | parameters | Betti obtained | Betti expected | "
             "ok | flow complex (s) | simplification (s) | reconstruction (s) | "
             "t_r giving the truth (scan 1.05..4, step 0.05) |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results:
        for run in r["runs"]:
            lines.append("| %s | %d | %g | %g | %s | %s | %s | %s | %.2f | %.2f | %.2f | %s |" % (
                r["name"], r["points"], run["tp"], run["tr"], run["why"], tuple(run["betti"]),
                tuple(r["expected"]), "yes" if run["ok"] else "**no**", r["time_complex"],
                run["time_simplification"], run["time_reconstruction_inf"],
                ranges(run["tr_scan_ok"])))
    return "\n".join(lines) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default=os.path.join(REPO, "build", "experiments"))
    ap.add_argument("--only", default="", help="comma-separated model names (default: all: %s)"
                    % ", ".join(e[0] for e in EXPERIMENTS))
    ap.add_argument("--png-dir", default="", help="also write small profile PNGs here")
    ap.add_argument("--npm-prefix", default=os.path.join(REPO, "build", "npm"))
    args = ap.parse_args(argv)
    try:
        import flowrecon  # noqa: F401
        import gudhi  # noqa: F401
        import matplotlib  # noqa: F401
    except ImportError as e:
        sys.exit("experiments.py: %s (run with /usr/bin/python3 and "
                 "PYTHONPATH=<build>/lib/python3/dist-packages:Apps/Scripts)" % e)
    names = [n for n in args.only.split(",") if n] or [e[0] for e in EXPERIMENTS]
    known = {e[0]: e for e in EXPERIMENTS}
    unknown = [n for n in names if n not in known]
    if unknown:
        ap.error("unknown model(s): %s" % ", ".join(unknown))
    os.makedirs(args.outdir, exist_ok=True)
    if args.png_dir:
        os.makedirs(args.png_dir, exist_ok=True)
    results = []

    def log(msg):
        print(msg, flush=True)
    for name in names:
        _, title, source, truth, runs = known[name]
        points, mesh = make_cloud(source, args.npm_prefix)
        if mesh is not None:
            truth = mesh[0]
            log("%s: %s -> true Betti %s" % (name, mesh[1], truth))
        r = run_experiment(name, title, points, truth, runs, args.outdir, args.png_dir, log)
        if mesh is not None:
            r["note"] = mesh[1]
        results.append(r)
    with open(os.path.join(args.outdir, "results.json"), "w") as f:
        json.dump(results, f, indent=1)
    with open(os.path.join(args.outdir, "results.md"), "w") as f:
        f.write(markdown(results))
    print(markdown(results))
    return 0


if __name__ == "__main__":
    sys.exit(main())
