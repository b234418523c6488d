#!/usr/bin/env python3
"""The persistence diagram of the flow-complex filtration equals the alpha-complex
persistence diagram computed by GUDHI (docs/algorithm.md §8.2).

Flow-complex side (computed here, not by the filter): the finite Hasse nodes
ordered by (value, index), the Z/2 boundary matrix from the arc multiplicities
mod 2 (arcs to the maximum at infinity excluded), the standard column reduction.
GUDHI side: gudhi.AlphaComplex(points).create_simplex_tree().persistence(), whose
filtration values are squared radii (square roots taken here). Pairs shorter than
1e-9 (relative to the cloud diameter) are dropped on both sides; the diagrams must
agree per dimension as multisets within 1e-7 (relative).

Before that, the reduction itself is checked against GUDHI on GUDHI's own alpha
filtration, so a failure below points at the filter, not at this test.

Run: PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Python:Apps/Scripts /usr/bin/python3 test_persistence_gudhi.py
"""

import math
import sys
import time

import generate_clouds as gen

from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing.clouds import random_cloud
from flowrecon_testing.checks import Checker

CHK = Checker("test_persistence_gudhi")
DROP = 1e-9   # pairs shorter than DROP * diameter are ignored
TOL = 1e-7    # births and deaths must agree within TOL * diameter


def alpha_diagram_by_reduction(points):
    """Our reduction applied to GUDHI's alpha filtration (oracle self-check)."""
    import gudhi
    st = gudhi.AlphaComplex(points=points).create_simplex_tree()
    filt = list(st.get_filtration())
    pos = {tuple(sorted(s)): i for i, (s, _) in enumerate(filt)}
    dims, values, bnd = [], [], []
    for s, f in filt:
        s = tuple(sorted(s))
        dims.append(len(s) - 1)
        values.append(math.sqrt(max(f, 0.0)))
        bnd.append([pos[s[:i] + s[i + 1:]] for i in range(len(s))] if len(s) > 1 else [])
    return fio.diagram_from_filtration(dims, values, bnd)


def check_reduction_self(label, P):
    diam = fio.diameter(P)
    mine = fio.significant(alpha_diagram_by_reduction(P), DROP * diam)
    ref = fio.significant(fio.gudhi_alpha_diagram(P), DROP * diam)
    ok, msg = fio.compare_diagrams(mine, ref, 1e-12 * diam, ("our reduction", "GUDHI"))
    CHK.check(ok, "oracle self-check on %s: our Z/2 reduction of GUDHI's alpha filtration "
              "differs from GUDHI's persistence" % label, msg)


def check_filter(label, P):
    diam = fio.diameter(P)
    t0 = time.time()
    res = fio.run(P)
    t1 = time.time()
    fc = fio.significant(fio.flow_complex_diagram(res), DROP * diam)
    t2 = time.time()
    ref = fio.significant(fio.gudhi_alpha_diagram(P), DROP * diam)
    t3 = time.time()
    counts = {}
    for d, _, _ in fc:
        counts[d] = counts.get(d, 0) + 1
    print("  %s: %s; %d significant pairs %s (filter %.2fs, reduction %.2fs, GUDHI %.2fs)" % (
        label, res.summary(), len(fc), dict(sorted(counts.items())), t1 - t0, t2 - t1, t3 - t2),
        flush=True)
    ok, msg = fio.compare_diagrams(fc, ref, TOL * diam, ("flow complex", "GUDHI alpha"))
    CHK.check(ok, "%s: flow-complex persistence differs from the alpha-complex persistence "
              "(GUDHI)" % label, msg)


def main():
    CHK.section("oracle self-check: our reduction vs GUDHI on the alpha filtration")
    for label, P in (("cube n=80", random_cloud("cube", 80, 1)),
                     ("torus n=300", random_cloud("torus", 300, 2)),
                     ("jittered 4x4x4 grid", random_cloud("grid", 64, 3))):
        CHK.run("self-check %s" % label, check_reduction_self, label, P)
    cases = []
    for kind, sizes in (("cube", (50, 200, 800)), ("sphere", (60, 300, 1500)),
                        ("torus", (100, 500, 1500))):
        for i, n in enumerate(sizes):
            cases.append(("%s n=%d" % (kind, n), random_cloud(kind, n, 7000 + 31 * i + n)))
    cases.append(("cube n=120 seed 2", random_cloud("cube", 120, 99)))
    cases.append(("unit sphere n=300 (near-cospherical)", random_cloud("unit sphere", 300, 5)))
    cases.append(("jittered 5x5x5 grid (Data generator)", gen.make("grid5_jittered")))
    cases.append(("jittered 6x6x6 grid", random_cloud("grid", 216, 11)))
    for label, P in cases:
        CHK.run("filter vs GUDHI: %s" % label, check_filter, label, P)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
