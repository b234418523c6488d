"""The reconstruction does not depend on the order of the input lines.

`flowrecon reconstruct --exact` runs on a cloud and on random permutations of its lines
(a random cube sample, a sphere sample, a torus sample, the exact integer grid
6 x 6 x 5, which is degenerate and gets perturbed, and a sphere sample with
duplicated lines), at the defaults (t_p 1.1, t_r 2) and at t_p 0. The outputs
must be the same reconstruction:
- per node, matched by its Simplex (input ids of its nearest samples, read from
  `flowrecon complex` of the same file, mapped back through the permutation;
  duplicated lines count as one sample): the same Index, CriticalValue and
  number of cells;
- cell by cell, after sorting: cells keyed by their vertices (samples by input
  id mapped back through the permutation, constructed points by coordinates
  rounded to 1e-9 of the cloud's diagonal), with their node, Index,
  CriticalValue, Step, Priority, Threshold, Extension, Sponsor and Multiplicity.
A difference is reported with the first cells that differ.

`--duplicates` runs the second check instead: 10^6 input lines holding only 5
distinct points reconstruct to a .vtu of a handful of points (not 10^6).

Usage: test_permutation.py FLOWRECON WORKDIR [--duplicates]
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
CELL_ARRAYS = ("Index", "CriticalValue", "Step", "Priority", "Threshold", "Extension")
failures = []


def clouds():
    rng = np.random.default_rng(2026)
    out = cl.basic_clouds(rng, 400, 500, 600, indexing="ij")
    base = out["sphere"][:300]
    out["duplicates"] = np.r_[base, base[rng.integers(0, 300, 100)]]
    return out


def write(path, points):
    with open(path, "w") as f:
        f.write("".join("%r %r %r\n" % tuple(p) for p in points.tolist()))


def run(*args):
    fr.run(FLOWRECON, *args, "--quiet", quiet=True)


def canonical_ids(points):
    """canon[i] = the smallest line holding the same coordinates as line i."""
    canon = np.arange(len(points))
    first = {}
    for i, p in enumerate(map(tuple, points.tolist())):
        canon[i] = first.setdefault(p, i)
    return canon


def nodes(vtm, to_original, canon):
    """NodeId -> (sorted canonical original ids of its Simplex, Index, CriticalValue)."""
    mb = fr.read_multiblock(vtm)
    cp = next(mb.GetBlock(i) for i in range(mb.GetNumberOfBlocks())
              if mb.GetMetaData(i).Get(mb.NAME()) == "CriticalPoints")
    pd = cp.GetPointData()
    ids = vtk_to_numpy(pd.GetArray("NodeId"))
    index = vtk_to_numpy(pd.GetArray("Index"))
    value = vtk_to_numpy(pd.GetArray("CriticalValue"))
    simplex = vtk_to_numpy(pd.GetArray("Simplex")).reshape(len(ids), -1)
    out = {}
    for n, i, v, s in zip(ids.tolist(), index.tolist(), value.tolist(), simplex.tolist()):
        key = tuple(sorted(int(canon[to_original[x]]) for x in s if x >= 0)) or ("infinity",)
        out[n] = (key, i, v)
    return out


def cells(vtu, node_of, to_original, canon, unit):
    """Sorted cells: (type, vertex keys, node key, arrays..., sponsor key, multiplicity)."""
    g = fr.read_grid(vtu)
    n = g.GetNumberOfCells()
    if n == 0:
        return []
    pts = vtk_to_numpy(g.GetPoints().GetData())
    original = vtk_to_numpy(g.GetPointData().GetArray("vtkOriginalPointIds"))
    keys = []
    for p, o in zip(pts.tolist(), original.tolist()):
        keys.append(("s", int(canon[to_original[o]])) if o >= 0 else
                    ("c",) + tuple(int(round(x / unit)) for x in p))
    cd = g.GetCellData()
    node_id = vtk_to_numpy(cd.GetArray("NodeId")).tolist()
    sponsor = vtk_to_numpy(cd.GetArray("Sponsor")).tolist()
    arrays = [vtk_to_numpy(cd.GetArray(a)).tolist() for a in CELL_ARRAYS]
    mult = cd.GetArray("Multiplicity")
    mult = vtk_to_numpy(mult).tolist() if mult else [0] * n
    offsets = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    types = vtk_to_numpy(g.GetCellTypesArray())
    out = []
    for c in range(n):
        verts = tuple(sorted(keys[v] for v in conn[offsets[c]:offsets[c + 1]]))
        out.append((int(types[c]), verts, node_of[node_id[c]][0]) +
                   tuple(a[c] for a in arrays) +
                   (node_of[sponsor[c]][0] if sponsor[c] >= 0 else None, mult[c]))
    out.sort(key=repr)
    return out


def describe(a, b, what):
    only_a = sorted(set(map(repr, a)) - set(map(repr, b)))
    only_b = sorted(set(map(repr, b)) - set(map(repr, a)))
    return "%s: %d vs %d; %d only in the original, %d only in the permuted; e.g. %s | %s" % (
        what, len(a), len(b), len(only_a), len(only_b), only_a[:2], only_b[:2])


def reconstruct(name, points, order, tp, tag):
    """(nodes by key, cells per node key, sorted cells) of the cloud in `order`."""
    base = os.path.join(WORK, "%s_%s" % (name.replace(" ", "_"), tag))
    write(base + ".xyz", points[order])
    run("complex", base + ".xyz", "-o", base + ".vtm", "--no-stable", "--no-unstable")
    run("reconstruct", base + ".xyz", "-o", base + "_tp%g.vtu" % tp, "--tp", str(tp), "--exact")
    canon = canonical_ids(points)
    node_of = nodes(base + ".vtm", order, canon)
    lo, hi = points.min(axis=0), points.max(axis=0)
    unit = 1e-9 * float(np.linalg.norm(hi - lo))
    cs = cells(base + "_tp%g.vtu" % tp, node_of, order, canon, unit)
    per_node = {}
    for c in cs:
        per_node[c[2]] = per_node.get(c[2], 0) + 1
    by_key = {k: (i, v) for k, i, v in node_of.values()}
    return by_key, per_node, cs


def check_permutations():
    rng = np.random.default_rng(12)
    for name, points in clouds().items():
        n = len(points)
        for tp in (1.1, 0.0):
            ref_nodes, ref_count, ref_cells = reconstruct(name, points, np.arange(n), tp, "ref")
            for k in range(3):
                perm = rng.permutation(n)
                got_nodes, got_count, got_cells = reconstruct(name, points, perm, tp, "perm%d" % k)
                label = "%s, t_p %g, permutation %d" % (name, tp, k)
                problems = []
                if got_nodes != ref_nodes:
                    problems.append(describe(list(ref_nodes.items()), list(got_nodes.items()),
                                             "nodes (Simplex -> Index, CriticalValue)"))
                if got_count != ref_count:
                    problems.append(describe(list(ref_count.items()), list(got_count.items()),
                                             "cells per node"))
                if got_cells != ref_cells:
                    problems.append(describe(ref_cells, got_cells, "cells"))
                print("%-40s %6d cells, %4d nodes drawn: %s" % (
                    label, len(got_cells), len(got_count), "same" if not problems else "DIFFERENT"))
                for p in problems:
                    print("    " + p)
                if problems:
                    failures.append(label)


def check_duplicates():
    """10^6 lines, 5 distinct points: the output keeps a handful of points."""
    rng = np.random.default_rng(5)
    distinct = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1], [0.9, 0.8, 0.7]])
    lines = ["%r %r %r\n" % tuple(p) for p in distinct.tolist()]
    pick = rng.integers(0, 5, 10 ** 6)
    pick[:5] = np.arange(5)
    path = os.path.join(WORK, "million_duplicates.xyz")
    with open(path, "w") as f:
        f.write("".join(lines[i] for i in pick.tolist()))
    out = os.path.join(WORK, "million_duplicates.vtu")
    run("reconstruct", path, "-o", out, "--tr", "inf", "--tp", "0", "--exact")
    g = fr.read_grid(out)
    points, ncells = g.GetNumberOfPoints(), g.GetNumberOfCells()
    original = vtk_to_numpy(g.GetPointData().GetArray("vtkOriginalPointIds"))
    samples = sorted(set(int(o) for o in original if o >= 0))
    print("10^6 lines, 5 distinct points: %d points (%d samples, input ids %s), %d cells, %d bytes"
          % (points, len(samples), samples, ncells, os.path.getsize(out)))
    # The samples (5) and the constructed points of the few patches and cones.
    if points > 50 or len(samples) != 5 or samples != sorted(set(pick[:5].tolist())):
        failures.append("the output of 10^6 lines with 5 distinct points has %d points" % points)
    if os.path.getsize(out) > 100000:
        failures.append("the output of 10^6 lines with 5 distinct points has %d bytes"
                        % os.path.getsize(out))


if "--duplicates" in sys.argv[3:]:
    check_duplicates()
else:
    check_permutations()
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("PASS")
