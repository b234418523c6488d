"""Under-sampling warnings: `flowrecon reconstruct` at the paper's t_r 2, t_p 1.1
prints 'warning: under-sampled near (x, y, z): ...' where the Betti numbers
change for a t_r just above the chosen one. Clean quasi-uniform samples of a
sphere, a torus and a genus-2 surface (Apps/Scripts/generate_clouds.py): the right
Betti numbers and no warning. The same sphere and torus with a known region
thinned (a polar cap, the top of the tube: half or more of its points removed):
a wrong answer, at least one warning, and every warning inside the thinned
region. One of them moved 4*10^6 units away: the same answer, and its places
printed finely enough to be found there. Usage: test_undersampling.py FLOWRECON WORKDIR
"""
import os
import re
import sys

import generate_clouds as gc
import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr

FLOWRECON, WORK = sys.argv[1], sys.argv[2]

failures = []


def reconstruct(name, points):
    path = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(path, points)
    code, out, err = fr.call(FLOWRECON, "reconstruct", path, "-o", os.path.join(WORK, name + ".vtu"),
                             "--tr", "2", "--tp", "1.1")
    if code != 0:
        raise SystemExit("flowrecon failed on %s: %s" % (name, err))
    betti = fr.printed_betti(out)
    places = [tuple(float(v) for v in m.group(1).split(","))
              for m in re.finditer(r"warning: under-sampled near \(([^)]*)\)", err)]
    return betti, places


os.makedirs(WORK, exist_ok=True)
for name, size, truth in (("sphere_qu", 3000, (1, 0, 1)), ("torus_qu", 3000, (1, 2, 1)),
                          ("genus2_qu", 3000, (1, 4, 1))):
    betti, places = reconstruct(name, gc.make(name, size=size))
    ok = betti == truth and not places
    print("%s (clean): Betti %s, %d warnings" % (name, betti, len(places)), "OK" if ok else "WRONG")
    if not ok:
        failures.append(name)

# Thinned: a polar cap of the sphere (z > 0.7), the top of the torus' tube (z > 0.25).
for name, top, removed in (("sphere_qu", 0.7, 0.5), ("sphere_qu", 0.7, 0.7), ("torus_qu", 0.25, 0.5)):
    base = gc.make(name, size=3000)
    rng = np.random.default_rng(3)
    keep = (base[:, 2] <= top) | (rng.uniform(size=len(base)) > removed)
    betti, places = reconstruct("%s_thinned_%g" % (name, removed), base[keep])
    # Inside the region, up to a sample spacing (about 0.05 here) below its edge.
    outside = [p for p in places if p[2] < top - 0.1]
    ok = betti != gc.betti(name) and places and not outside
    print("%s, %d%% of z > %g removed: Betti %s, warnings at z = %s" % (
        name, 100 * removed, top, betti, ", ".join("%.2f" % p[2] for p in places)),
        "OK" if ok else "WRONG")
    if not ok:
        failures.append("%s thinned %g" % (name, removed))
# The same cloud where a georeferenced scan sits (10^6 units from the origin):
# the same answer, and the places printed finely enough to find (6 digits
# would be off by about 5 units there, a hundred times the spacing).
offset = np.array([512345.0, 4123456.0, 105.0])
base = gc.make("sphere_qu", size=3000)
keep = (base[:, 2] <= 0.7) | (np.random.default_rng(3).uniform(size=len(base)) > 0.5)
near = reconstruct("sphere_qu_thinned_near", base[keep])
far = reconstruct("sphere_qu_thinned_far", base[keep] + offset)
moved = [tuple(np.subtract(p, offset)) for p in far[1]]
ok = (far[0] == near[0] and len(moved) == len(near[1]) and near[1] and
      all(np.max(np.abs(np.subtract(a, b))) < 0.005 for a, b in zip(moved, near[1])))
print("thinned sphere moved by %s: Betti %s (at the origin %s), places minus the offset %s" % (
    offset.tolist(), far[0], near[0], ["(%.4f, %.4f, %.4f)" % p for p in moved]), "OK" if ok else "WRONG")
if not ok:
    failures.append("thinned sphere far from the origin")
if failures:
    raise SystemExit("under-sampling warnings wrong on: " + ", ".join(failures))
print("no warning on clean samples, a warning inside every thinned region")
