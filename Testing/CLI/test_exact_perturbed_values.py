#!/usr/bin/env python3
"""Critical values of perturbed runs come from the unperturbed points.

Degenerate clouds (integer grids, lattice points on a sphere, a cube's corners, an
octahedron) are perturbed to decide which simplices are critical; each critical
point's value must still be the exact radius of its simplex's smallest
circumscribing sphere on the input points (for four coplanar points on one circle:
that circle). Checked, for each cloud:
  - `info` says the cloud was perturbed (for the degenerate ones);
  - every finite node of `complex` has the exact value of its simplex (Python
    fractions), within 1e-12 relative, and none is left at its perturbed value;
  - every pair of GUDHI's exact alpha-complex persistence (square roots of its
    squared radii) of positive persistence has a birth among the values of the
    nodes of index = its dimension and a death among those of index + 1, within
    1e-12 relative;
  - `diagram`'s pairs of positive persistence equal GUDHI's as multisets per
    dimension, within 1e-12 relative, and its other pairs have persistence
    exactly 0;
  - `reconstruct --exact` of the cloud (deferred patches and flow lines)
    equals `reconstruct --exact` of the stored complex, cell for cell.

Run: /usr/bin/python3 test_exact_perturbed_values.py <path to flowrecon> <work dir>
     [--large N]  (also an N^3 grid, checked by hand: 30 takes minutes)
"""

import itertools
import math
import os
import re
import sys
from fractions import Fraction

import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing import run as fr
from flowrecon_testing.checks import Checker

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
LARGE = int(sys.argv[sys.argv.index("--large") + 1]) if "--large" in sys.argv else None
REL = 1e-12
CELL_ARRAYS = ("NodeId", "Threshold", "Priority", "CriticalValue")
CHK = Checker("test_exact_perturbed_values")


def grid(n, spacing=1.0, origin=(0.0, 0.0, 0.0)):
    g = np.arange(n, dtype=float) * spacing
    return cl.grid(g, g, g, indexing="ij") + np.asarray(origin)


def lattice_sphere(r2):
    """The integer points at squared distance r2 from the origin (exactly cospherical)."""
    r = int(math.isqrt(r2))
    return np.array([p for p in itertools.product(range(-r, r + 1), repeat=3)
                     if sum(x * x for x in p) == r2], dtype=float)


def clouds():
    """(name, points, degenerate)"""
    for n in (3, 5, 7, 12):
        yield "grid %d^3" % n, grid(n), True
    # Binary spacing and offset: still exact, at another scale (ScaleExponent).
    yield "grid 6^3 spacing 1/4 at 1000", grid(6, 0.25, (1000.0, -1000.0, 500.0)), True
    yield "grid 4x5x6", cl.grid(np.arange(4.0), np.arange(5.0), np.arange(6.0), indexing="ij"), True
    yield "cube corners", np.array(list(itertools.product((-1.0, 1.0), repeat=3))), True
    yield "octahedron", np.array([[s * (i == k) for k in range(3)] for i in range(3)
                                  for s in (-1.0, 1.0)]), True
    yield "lattice sphere r^2 = 9", lattice_sphere(9), True
    yield "lattice sphere r^2 = 27", lattice_sphere(27), True
    yield "lattice sphere r^2 = 50", lattice_sphere(50), True
    phi = (1 + 5 ** 0.5) / 2
    ico = [(0, s, t * phi) for s in (-1, 1) for t in (-1, 1)]
    ico = [p[i:] + p[:i] for p in ico for i in range(3)]
    yield "icosahedron", np.array(ico, dtype=float), None  # rounded: degenerate or not
    if LARGE:
        yield "grid %d^3" % LARGE, grid(LARGE), True


def run(*args):
    return fr.run(FLOWRECON, *args)


# ----------------------------------------------------------------- exact values

def sub(p, q):
    return [x - y for x, y in zip(p, q)]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def circle_r2(p0, p1, p2):
    a, b = sub(p1, p0), sub(p2, p0)
    w = cross(a, b)
    ww = dot(w, w)
    if ww == 0:
        return None
    ab = sub(p2, p1)
    return dot(a, a) * dot(b, b) * dot(ab, ab) / (4 * ww)


def exact_r2(pts):
    """Squared radius of the smallest sphere through pts (2-4 exact points), centre in
    their affine hull; four coplanar points on one circle: that circle; else None."""
    if len(pts) == 2:
        a = sub(pts[1], pts[0])
        return dot(a, a) / 4
    if len(pts) == 3:
        return circle_r2(*pts)
    a, b, c = (sub(p, pts[0]) for p in pts[1:])
    det = dot(a, cross(b, c))
    if det != 0:
        x = [dot(a, a) * u + dot(b, b) * v + dot(c, c) * w
             for u, v, w in zip(cross(b, c), cross(c, a), cross(a, b))]
        return dot(x, x) / (4 * det * det)
    r2 = circle_r2(*pts[:3])
    if r2 is None:
        return None
    # cocircular iff the fourth point is as far from the circle's centre
    w = cross(a, b)
    y = [dot(a, a) * u + dot(b, b) * v for u, v in zip(cross(b, w), cross(w, a))]
    return r2 if dot(w, w) * dot(c, c) == dot(c, y) else None


def read_nodes(vtm):
    return fio.FlowComplexResult(fr.read_multiblock(vtm))


def rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def contains(values, x):
    """Is x within REL of an element of the sorted array values?"""
    i = np.searchsorted(values, x)
    return any(0 <= j < len(values) and rel(values[j], x) <= REL for j in (i - 1, i))


def check(name, points, degenerate):
    CHK.section(name)
    base = os.path.join(WORK, re.sub(r"[^A-Za-z0-9]+", "_", name))
    xyz = base + ".xyz"
    cl.write_xyz(xyz, points)
    pts = np.loadtxt(xyz)
    exact = [[Fraction(float(x)) for x in p] for p in pts]

    info = run("info", xyz)
    perturbed = re.search(r"perturbed:\s+yes", info) is not None
    if degenerate is not None:
        CHK.check(perturbed == degenerate, "%s: perturbed is %s" % (name, perturbed), info)

    run("complex", xyz, "-o", base + ".vtm", "--quiet", "--no-unstable", "--max-cells", "0")
    res = read_nodes(base + ".vtm")
    CHK.check(res.simplex is not None, "%s: CriticalPoints has a Simplex array" % name)
    CHK.check(int(res.report.get("PerturbedValueCount", 0)) == 0,
              "%s: %s critical values left at the perturbed points"
              % (name, res.report.get("PerturbedValueCount")))
    worst, flat, none = 0.0, 0, 0
    by_index = {k: [] for k in range(4)}
    for row in range(len(res.node_id)):
        k, v = int(res.index[row]), float(res.value[row])
        if not math.isfinite(v):
            continue
        by_index[k].append(v)
        if k == 0:
            CHK.check(v == 0, "%s: index-0 value %g" % (name, v))
            continue
        ids = [int(i) for i in res.simplex[row][:k + 1]]
        r2 = exact_r2([exact[i] for i in ids])
        if r2 is None:
            none += 1
            continue
        if k == 3 and dot(sub(exact[ids[1]], exact[ids[0]]),
                          cross(sub(exact[ids[2]], exact[ids[0]]), sub(exact[ids[3]], exact[ids[0]]))) == 0:
            flat += 1
        worst = max(worst, rel(v, math.sqrt(float(r2))))
    CHK.check(none == 0, "%s: %d critical simplices without a critical point on the input" % (name, none))
    CHK.check(worst <= REL, "%s: a critical value is %.3g (relative) from its exact value" % (name, worst))
    print("  %d nodes (%s by index), %d flat cells, largest relative error %.3g"
          % (len(res.node_id) - 1, " ".join(str(len(by_index[k])) for k in range(4)), flat, worst))

    # GUDHI's exact alpha persistence: each pair's ends are critical values.
    import gudhi
    st = gudhi.AlphaComplex(points=pts, precision="exact").create_simplex_tree()
    ref = [(d, math.sqrt(b), math.sqrt(e) if math.isfinite(e) else math.inf)
           for d, (b, e) in st.persistence(homology_coeff_field=2, min_persistence=-1.0)]
    ref = [p for p in ref if p[2] > p[1]]
    values = {k: np.array(sorted(by_index[k])) for k in range(4)}
    missing = [p for p in ref if not contains(values[p[0]], p[1]) or
               (math.isfinite(p[2]) and not contains(values[p[0] + 1], p[2]))]
    CHK.check(not missing, "%s: %d GUDHI pairs whose ends are no critical values of matching index"
              % (name, len(missing)), str(missing[:5]))

    # The flow complex's own diagram.
    run("diagram", xyz, "-o", base + "_pd.csv", "--quiet")
    mine = fr.read_diagram(base + "_pd.csv")[1]
    zero = [p for p in mine if not p[2] > p[1]]
    CHK.check(all(p[2] == p[1] for p in zero), "%s: a pair of negative persistence" % name)
    mine = [p for p in mine if p[2] > p[1]]
    problems = []
    for d in range(3):
        a = sorted((b, e) for k, b, e in mine if k == d)
        r = sorted((b, e) for k, b, e in ref if k == d)
        if len(a) != len(r):
            problems.append("dimension %d: %d pairs, GUDHI %d" % (d, len(a), len(r)))
            continue
        bad = [(x, y) for x, y in zip(a, r) if rel(x[0], y[0]) > REL or
               (x[1] != y[1] and rel(x[1], y[1]) > REL)]
        if bad:
            problems.append("dimension %d: %s" % (d, bad[:3]))
    CHK.check(not problems, "%s: the diagram differs from GUDHI's" % name, "; ".join(problems))
    print("  %d pairs of positive persistence, %d of persistence 0" % (len(mine), len(zero)))

    # Lazy (deferred patches and flow lines) equals eager.
    if len(points) <= 2000:
        run("complex", xyz, "-o", base + "_eager.vtm", "--quiet", "--max-cells", "inf", "--no-unstable")
        for tp in ("0", "1.1"):
            for tr in ("1.5", "3"):
                run("reconstruct", xyz, "-o", base + "_lazy.vtu", "--tr", tr, "--tp", tp, "--quiet",
                    "--exact")
                run("reconstruct", base + "_eager.vtm", "-o", base + "_eager.vtu", "--tr", tr, "--tp",
                    tp, "--quiet", "--exact")
                lc, la = fr.cells(base + "_lazy.vtu", CELL_ARRAYS)
                ec, ea = fr.cells(base + "_eager.vtu", CELL_ARRAYS)
                differ = [a for a in la if not np.array_equal(la[a], ea[a])]
                if lc != ec:
                    differ.append("cell vertices")
                CHK.check(not differ, "%s, t_p %s, t_r %s: lazy and eager differ in %s"
                          % (name, tp, tr, ", ".join(differ)))


os.makedirs(WORK, exist_ok=True)
for cloud in clouds():
    check(*cloud)
sys.exit(CHK.finish())
