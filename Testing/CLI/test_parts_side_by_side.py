"""Parts side by side: a surface sampled far more finely along lines than across
them is read at its finest spacing, each line a closed curve of its own over
every t_r looked at. The unit sphere scanned along parallels 0.06 and 0.03
apart, with points 0.01 apart on each, answers 52 52 0 (and, 0.03 apart, the
sphere, 1 0 1); a tube
around a trefoil knot given as a 1000 x 12 grid of vertices answers 12 12 0.
Each must be warned as parts side by side, with the widest gap from a part to
its nearest other part over the median nearest-sample distance equal (to the
printed digit) to what a k-d tree finds on the written cells' components
(scipy). Controls that must not be warned so: three circles far apart (3 3 0,
right), the sphere's parallels 0.03 apart and the ones 0.06 apart thinned to
an even spacing (both right), a trefoil knot (one part).
Usage: test_parts_side_by_side.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
from part_gaps import widest_gap  # noqa: E402
from scan_artifacts import knot_tube, parallels, trefoil  # noqa: E402

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
ROWS = re.compile(r"^warning: the answer is (\d+) parts side by side, none with a void, each within "
                  r"([\d.]+) times the median sample spacing of another", re.M)


def circles():
    """Three unit circles 4 apart, in planes of their own (all in one plane is bad input)."""
    t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    return np.vstack([np.c_[np.cos(t) + 4 * k, np.sin(t) * np.cos(k), np.sin(t) * np.sin(k)] for k in range(3)])


failures = []
cases = [("sphere scanned along parallels 0.06 apart", parallels(0.06, 0.01), True),
         ("sphere scanned along parallels 0.03 apart (right: 1 0 1)", parallels(0.03, 0.01), False),
         ("tube around a trefoil, 1000 x 12 grid", knot_tube(1000, 12, 0.4), True),
         ("three circles 4 apart", circles(), False),
         ("the parallels 0.06 apart, every sixth point", parallels(0.06, 0.01, 6), False),
         ("trefoil knot", trefoil(np.linspace(0, 2 * np.pi, 1000, endpoint=False)), False)]
for k, (name, points, rows) in enumerate(cases):
    cloud = os.path.join(WORK, "cloud%d.xyz" % k)
    np.savetxt(cloud, points, fmt="%.17g")
    out = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"], capture_output=True, text=True)
    betti = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", out.stdout, re.M)
    warning = ROWS.search(out.stderr)
    print("%s: Betti %s; %s" % (name, betti.groups() if betti else None,
                                 warning.group(0)[9:] if warning else "not warned as parts side by side"))
    if betti is None:
        failures.append(name + ": no Betti numbers (exit %d)" % out.returncode)
        continue
    if bool(warning) != rows:
        failures.append(name + (": not warned" if rows else ": warned") + " as parts side by side")
    if warning:
        parts, gap = widest_gap(cloud[:-4] + ".vtu", points)
        print("  oracle: %d parts, widest gap %.2f spacings" % (parts, gap))
        if int(warning.group(1)) != parts or int(betti.group(1)) != parts or abs(float(warning.group(2)) - gap) > 0.051:
            failures.append("%s: warned %s parts within %s, the oracle %d within %.2f"
                            % (name, warning.group(1), warning.group(2), parts, gap))
if failures:
    raise SystemExit("; ".join(failures))
print("parts side by side warned on the %d row samplings, on none of the %d controls"
      % (sum(c[2] for c in cases), sum(not c[2] for c in cases)))
