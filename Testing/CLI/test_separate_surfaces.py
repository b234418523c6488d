"""The automatic thresholds on closed surfaces that lie apart or are joined
(Benchmarks/Study/separate_surfaces.py, its quick set): isosurface vertices of
seven implicit shapes (a sphere, a torus, a genus-2 surface, two spheres 0.2
apart, a rounded cube, a thick shell's two nested spheres, a flat ellipsoid) on
24^3 and 48^3 grids, and two unit spheres 0.6 and 0.5 apart (Fibonacci and
i.i.d. points), alone and joined by a rod of points. Their Betti numbers are
known by construction; at defaults each must print them. Two spheres apart over
a stable range of t_r and joined by a bridge later (1 0 2, a longer range) are
two surfaces: the rule that took the longest range answered 1 0 2 on three of
these clouds, one of them without a warning.
Usage: test_separate_surfaces.py FLOWRECON WORKDIR
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
import held_out_shapes as ho  # noqa: E402
import separate_surfaces as ss  # noqa: E402

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
failures = []
for k, (name, n, points, truth) in enumerate(ss.clouds(ss.GRIDS[:2], ss.PAIRS[:2], False)):
    cloud = os.path.join(WORK, "cloud%02d.xyz" % k)
    np.savetxt(cloud, points, fmt="%.17g")
    betti, warned, choice = ho.run(FLOWRECON, cloud, [])
    ok = betti == truth
    print("%s (%d points): Betti %s, truth %s%s" % (name, n, betti, truth, "" if ok else "  <- WRONG"))
    if not ok:
        failures.append(name)
if len(failures) > 0:
    raise SystemExit("automatic thresholds wrong on: " + "; ".join(failures))
print("right on all %d clouds" % (k + 1))
