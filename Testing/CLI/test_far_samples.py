"""The warning for samples apart from the rest (FarSamples.h): `flowrecon
reconstruct` at defaults on clouds with outliers strewn in their box, and on the
same clouds without them.

The oracle is independent of the flow complex: each sample's nearest sample by
a k-d tree (scipy), and the median of those distances (the upper middle value,
as the product takes it); the product reads the same distances off its Gabriel
edges. On the clouds with outliers the warning must name as many samples as the
oracle finds over 10 times the median, and place the farthest at the oracle's
farthest sample, an outlier (off the surface); the clean clouds must not be
warned, and the oracle must find none there. One cloud is also reconstructed
from its stored flow complex (`complex`, then `reconstruct` of the .vtm), which
must name as many.
Usage: test_far_samples.py FLOWRECON WORKDIR
"""
import os
import re
import sys

import numpy as np
from scipy.spatial import cKDTree

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr

FLOWRECON, WORK = sys.argv[1:3]
FACTOR = 10
WARNING = re.compile(r"^warning: (\d+) samples? lies? apart from the rest .*?near \(([^)]*)\)", re.M)


def spreads(p):
    """Each sample's nearest-sample distance over the median."""
    nearest = cKDTree(p).query(p, k=2)[0][:, 1]
    return nearest / np.sort(nearest)[len(nearest) // 2]


OFF_SURFACE = {  # a place off the shape's surface (an outlier's)
    "sphere": lambda q: abs(np.linalg.norm(q) - 1) > 0.05,
    "torus": lambda q: abs(np.hypot(np.hypot(q[0], q[1]) - 1, q[2]) - 0.35) > 0.05,
}


def clouds():
    """(name, shape, points): each shape clean, then with 1 % and 3 % outliers."""
    rng = np.random.default_rng(21)
    for shape, base in (("sphere", cl.sphere(5000, rng)), ("torus", cl.chart_torus(5000, rng))):
        yield shape, shape, base
        for share in (0.01, 0.03):
            box = rng.uniform(-1.4, 1.4, (int(share * len(base)), 3))
            yield "%s with %g%% outliers" % (shape, 100 * share), shape, np.vstack([base, box])


os.makedirs(WORK, exist_ok=True)
failures = []
for name, shape, points in clouds():
    path = cl.write_xyz(os.path.join(WORK, name.replace(" ", "_").replace("%", "") + ".xyz"), points)
    code, out, err = fr.call(FLOWRECON, "reconstruct", path, "-o", path[:-4] + ".vtu")
    ratio = spreads(points)
    expected = int((ratio > FACTOR).sum())
    m = WARNING.search(err)
    problems = []
    if code != 0:
        problems.append("exit %d: %s" % (code, err.strip()))
    elif expected == 0:
        if m:
            problems.append("warned on a clean cloud: " + m.group(0))
    elif not m:
        problems.append("no warning; the oracle finds %d samples apart" % expected)
    else:
        place = np.array([float(v) for v in m.group(2).split(",")])
        farthest = points[int(np.argmax(ratio))]
        if int(m.group(1)) != expected:
            problems.append("%s samples warned, the oracle finds %d" % (m.group(1), expected))
        if np.max(np.abs(place - farthest)) > 1e-4 or not OFF_SURFACE[shape](place):
            problems.append("farthest printed at %s, the oracle's %s" % (place, farthest))
    if expected and m and name == "sphere with 3% outliers":
        # The same count from the stored flow complex (the filters' path).
        fr.run(FLOWRECON, "complex", path, "-o", path[:-4] + ".vtm", quiet=True)
        stored = WARNING.search(fr.call(FLOWRECON, "reconstruct", path[:-4] + ".vtm", "-o", path[:-4] + "_vtm.vtu")[2])
        if not stored or stored.group(1) != m.group(1):
            problems.append("from the stored complex: %s" % (stored.group(0) if stored else "no warning"))
    print("%s: oracle %d apart (largest %.1f times the median), printed: %s%s" % (
        name, expected, ratio.max(), m.group(0)[:60] + "..." if m else "no warning",
        "" if not problems else "  <- " + "; ".join(problems)))
    if problems:
        failures.append(name)
if failures:
    raise SystemExit("samples apart warned wrongly on: " + ", ".join(failures))
print("outliers warned as the oracle counts them, clean clouds not warned")
