"""The automatic thresholds on shapes outside the topology study the rule was
designed on (Benchmarks/Study/held_out_shapes.py): a cube's boundary, a capped
cylinder, a cube with a cylindrical hole through it (sharp edges), a flat
ellipsoid, an open cylinder, a hemisphere and a disk (boundaries), 3 000 i.i.d.
points each, whose Betti numbers are known by construction. At defaults, each
clean cloud must print its truth; with Gaussian noise of 0.3 and 1 times the
spacing an answer may be wrong, but then with a warning line (none silent).
Usage: test_held_out_shapes.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
import held_out_shapes as ho  # noqa: E402

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
failures = []
for name, n, noise, points, truth in ho.clouds(sizes=(3000,)):
    cloud = os.path.join(WORK, "%s_%g.xyz" % (name.replace(" ", "_"), noise))
    np.savetxt(cloud, points, fmt="%.9g")
    p = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"],
                       capture_output=True, text=True)
    m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    betti = tuple(int(x) for x in m.groups()) if m else None
    warned = any(line.startswith("warning:") for line in p.stderr.splitlines())
    ok = p.returncode == 0 and betti is not None and (betti == truth or (noise > 0 and warned))
    print("%s, noise %g: Betti %s, truth %s%s%s" % (name, noise, betti, truth,
                                                   "" if betti == truth else (", warned" if warned else ", SILENT"),
                                                   "" if ok else "  <- WRONG"))
    if not ok:
        failures.append("%s noise %g" % (name, noise))
if failures:
    raise SystemExit("automatic thresholds wrong on: " + ", ".join(failures))
print("right on every clean cloud, and every wrong answer warned")
