"""Betti numbers of reconstructions against GUDHI.

For each cloud, `flowrecon reconstruct CLOUD --tr 2 --tr-max 4 --exact
--topology-profile P.csv` writes the nested family of exact cells below 4, prints 'Betti numbers: b0 b1 b2' at
t_r = 2 and the profile (threshold,b0,b1,b2: row k holds for t_r in
(threshold_k, threshold_k+1]). The oracle is GUDHI: a SimplexTree holding every
written cell with filtration = its Threshold (faces take the least value), and
its persistence over Z/2; the Betti numbers at t count the intervals with
birth < t <= death. Checked: the printed line at 2, the file's field data
BettiNumbers (its cells: the family below 4), and every profile row at the
middle and at the end of its interval. The same run from a saved flow complex
(.vtm, through the VTK filters) must give the same profile. Clouds: surfaces,
a solid, a curve, the paper's non-manifold two hemispheres, a sphere with a
segment, an exact grid (degenerate), a noisy sphere.
Usage: test_topology_profile.py FLOWRECON WORKDIR
"""
import os
import sys

import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.oracles import betti_at, filtered_intervals
from flowrecon_testing.run import printed_betti, read_topology_profile

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
failures = []


def clouds():
    return cl.topology_fixtures(np.random.default_rng(5), 600, 900, 700, 160, 400)


def run(*args):
    return fr.run(FLOWRECON, *args)


def gudhi_intervals(path):
    grid = fr.read_grid(path)
    field = grid.GetFieldData().GetArray("BettiNumbers")
    stored = tuple(int(field.GetValue(k)) for k in range(3)) if field else None
    return filtered_intervals(grid), stored


os.makedirs(WORK, exist_ok=True)
checked = 0
for name, xyz in clouds().items():
    base = os.path.join(WORK, name.replace(" ", "_"))
    cl.write_xyz(base + ".xyz", xyz)
    out = run("reconstruct", base + ".xyz", "-o", base + ".vtu", "--tr", "2", "--tp", "1.1", "--tr-max", "4",
              "--exact", "--topology-profile", base + ".csv")
    intervals, stored = gudhi_intervals(base + ".vtu")
    problems = []
    if printed_betti(out) != betti_at(intervals, 2):
        problems.append("printed %s, GUDHI %s at 2" % (printed_betti(out), betti_at(intervals, 2)))
    if stored != betti_at(intervals, 4):
        problems.append("field data %s, GUDHI %s at 4" % (stored, betti_at(intervals, 4)))
    profile = read_topology_profile(base + ".csv")
    ends = [t for t, _ in profile[1:]] + [4.0]
    for (start, betti), end in zip(profile, ends):
        # (the middle of two adjacent doubles may round onto the start: skip it)
        for t in [x for x in ((start + end) / 2, end) if start < x <= end]:
            checked += 1
            if betti_at(intervals, t) != betti:
                problems.append("row from %.6g: %s, GUDHI %s at %.9g" % (start, betti,
                                                                         betti_at(intervals, t), t))
    if any(a[1] == b[1] for a, b in zip(profile, profile[1:])):
        problems.append("a profile row repeats the previous one")
    # Through the VTK filters, from a saved flow complex: the same profile.
    run("complex", base + ".xyz", "-o", base + ".vtm", "--quiet")
    out2 = run("reconstruct", base + ".vtm", "-o", base + "_filters.vtu", "--tr", "2", "--tp", "1.1",
               "--tr-max", "4", "--exact", "--topology-profile", base + "_filters.csv")
    if read_topology_profile(base + "_filters.csv") != profile or printed_betti(out2) != printed_betti(out):
        problems.append("the VTK filters give another profile")
    label = "%s: %d profile rows, Betti numbers at t_r 2 %s" % (name, len(profile),
                                                                printed_betti(out))
    print(label, "OK" if not problems else "WRONG: " + "; ".join(problems[:5]))
    if problems:
        failures.append(name)
if failures:
    raise SystemExit("Betti numbers differ from GUDHI on: " + ", ".join(failures))
print("Betti numbers equal GUDHI's on every cloud (%d profile points)" % checked)
