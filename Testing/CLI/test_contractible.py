"""The reconstruction at t_r = inf without simplification is contractible.

Known answer: every finite node is then inserted, so the output is the union of
the stable manifolds of all finite critical points, the complement of the
stable manifold of the maximum at infinity, an open cell: by Alexander duality
its Betti numbers are (1, 0, 0). TestCoreInvariants asserts the same of the
Hasse diagram; this asserts it of the exact cells (`reconstruct --exact`),
where an index-3 cone over a boundary that meets itself at a point or along an
edge used to enclose voids (12 on the 6000-point torus below, 2 on the
10000-point one).
The printed Betti numbers are checked against GUDHI on the smallest cloud.
Usage: test_contractible.py FLOWRECON WORKDIR
"""
import os
import re
import sys

import generate_clouds as gc
import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.oracles import gudhi_betti

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
failures = []


def torus(n, seed):
    # i.i.d. area-uniform on a torus surface (R 1, r 0.35): tubes, where cells
    # wrap around the core and meet themselves.
    rng = np.random.default_rng(seed)
    R, r = 1.0, 0.35
    u, v = rng.uniform(0, 2 * np.pi, (2, 3 * n))
    keep = rng.uniform(0, 1, 3 * n) < (R + r * np.cos(v)) / (R + r)
    u, v = u[keep][:n], v[keep][:n]
    return np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def clouds():
    rng = np.random.default_rng(5)
    sphere = cl.sphere(3000, rng)
    ball = gc.ball(4000, rng)
    return {"sphere": sphere,
            "cube": rng.uniform(0, 1, (3000, 3)),
            "ball": ball,
            "torus": torus(6000, 7),
            # Cells here also meet themselves along Gabriel edges (2 voids
            # before the cones were split there by sides).
            "torus_edge_pinched": torus(10000, 7)}


def betti_of(path):
    code, out, err = fr.call(FLOWRECON, "reconstruct", path, "-o", path + ".vtu", "--exact", "--tp", "0",
                             "--tr", "inf", "--betti-max-cells", "inf")
    if code != 0:
        failures.append("%s: exit %d: %s" % (path, code, err.strip()))
        return None
    m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", out + err, re.M)
    if not m:
        failures.append("%s: no Betti line" % path)
        return None
    return tuple(int(x) for x in m.groups())


for name, pts in clouds().items():
    path = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(path, pts)
    b = betti_of(path)
    print("%s (%d points): Betti %s" % (name, len(pts), b))
    if b is not None and b != (1, 0, 0):
        failures.append("%s: Betti %s at t_r = inf, t_p = 0; expected (1, 0, 0)" % (name, b))
    if name == "sphere" and b is not None:
        g = gudhi_betti(fr.read_grid(path + ".vtu"))
        print("  GUDHI on the written cells: %s" % (g,))
        if g != b:
            failures.append("%s: printed %s, GUDHI %s" % (name, b, g))

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS")
