"""The flow complex does not depend on the number of threads.

The core builds CGAL's concurrent Delaunay triangulation and runs its passes and
walks on TBB; any dependence on the schedule (cell order, races, the order in
which slices are merged) would show as different output. Runs
`flowrecon complex --threads N` for N = 1, 2 and the default on clouds large
enough for every parallel part to split (tens of thousands of cells), including a
degenerate one (a grid, which is perturbed and recomputed), and requires every
block, array and field value except timings to be identical.

usage: test_threads.py FLOWRECON WORKDIR
"""

import os
import sys

import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing import run as fr

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)


def clouds():
    rng = np.random.default_rng(20261122)
    yield "cube", rng.random((12000, 3))
    yield "torus", cl.chart_torus(5000, rng)
    g = np.arange(12, dtype=float)
    yield "grid", cl.grid(g, g, g, indexing="ij")


def complex_of(name, points, threads):
    xyz = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(xyz, points)
    out = os.path.join(WORK, "%s_%s.vtm" % (name, threads))
    args = ["complex", xyz, "-o", out, "--quiet"]
    if threads != "default":
        args += ["--threads", threads]
    fr.run(FLOWRECON, *args)
    return fr.read_multiblock(out)


failures = []
for name, points in clouds():
    prints = {t: fio.fingerprint(complex_of(name, points, t)) for t in ("1", "2", "default")}
    for t in ("2", "default"):
        diff = sorted(k for k in set(prints["1"]) | set(prints[t])
                      if prints["1"].get(k) != prints[t].get(k))
        if diff:
            failures.append("%s: --threads 1 and %s differ in %s" % (name, t, diff))
    print("%s (%d points): %d items compared" % (name, len(points), len(prints["1"])), flush=True)

for f in failures:
    print("FAIL " + f)
sys.exit(1 if failures else 0)
