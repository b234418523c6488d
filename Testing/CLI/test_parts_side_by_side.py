"""Parts side by side: a surface sampled far more finely along lines than across
them is read at its finest spacing, each line a closed curve of its own over
every t_r looked at. The unit sphere scanned along parallels 0.06 and 0.03
apart, with points 0.01 apart on each, answers 52 52 0 (and, 0.03 apart, the
sphere, 1 0 1); a tube
around a trefoil knot given as a 1000 x 12 grid of vertices answers 12 12 0;
the nine rings of an open cylinder's mesh (radius 0.5, 0.25 apart, 256 or 800
points on each) answer 9 9 0. Each must be warned as parts side by side, with
the widest gap from a part to its nearest other part over the median
nearest-sample distance (and, for the rings, over the larger one's extent)
equal, to the printed digits, to what a k-d tree finds on the written cells'
components (scipy), and the same from a stored flow complex (`flowrecon
complex`, then `reconstruct` of the .vtm). Controls that must not be warned so: three circles far
apart (3 3 0, right), five rings a diameter apart (5 5 0, right), the sphere's
parallels 0.03 apart and the ones 0.06 apart thinned to an even spacing (both
right), a trefoil knot (one part).
Usage: test_parts_side_by_side.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
from part_gaps import part_gaps  # noqa: E402
from scan_artifacts import knot_tube, parallels, trefoil  # noqa: E402

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
ROWS = re.compile(r"^warning: the answer is (\d+) (?:parts side by side, none with a void, each within "
                  r"([\d.]+) times the median sample spacing of another|closed curves side by side, none with "
                  r"a void, each within ([\d.]+) times its extent of another \(the widest gap ([\d.]+) times the "
                  r"median sample spacing)", re.M)


def circles():
    """Three unit circles 4 apart, in planes of their own (all in one plane is bad input)."""
    t = np.linspace(0, 2 * np.pi, 200, endpoint=False)
    return np.vstack([np.c_[np.cos(t) + 4 * k, np.sin(t) * np.cos(k), np.sin(t) * np.sin(k)] for k in range(3)])


def rings(count, per, gap):
    """`count` circles of radius 0.5 on one axis, `gap` apart, `per` points each."""
    t = np.linspace(0, 2 * np.pi, per, endpoint=False)
    return np.vstack([np.c_[0.5 * np.cos(t), 0.5 * np.sin(t), np.full(per, gap * k)] for k in range(count)])


failures = []
cases = [("sphere scanned along parallels 0.06 apart", parallels(0.06, 0.01), True),
         ("sphere scanned along parallels 0.03 apart (right: 1 0 1)", parallels(0.03, 0.01), False),
         ("tube around a trefoil, 1000 x 12 grid", knot_tube(1000, 12, 0.4), True),
         ("nine rings 0.25 apart, 256 points each", rings(9, 256, 0.25), True),
         ("nine rings 0.25 apart, 800 points each", rings(9, 800, 0.25), True),
         ("three circles 4 apart", circles(), False),
         ("five rings 1 apart", rings(5, 256, 1.0), False),
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
        parts, gap, span = part_gaps(cloud[:-4] + ".vtu", points)
        print("  oracle: %d parts, widest gap %.2f spacings, %.3f of the extent" % (parts, gap, span))
        # The message gives the spacings, or the extent's share and the gap in spacings.
        said_gap = float(warning.group(2) or warning.group(4))
        said_span = warning.group(3)
        if int(warning.group(1)) != parts or int(betti.group(1)) != parts or abs(said_gap - gap) > 0.051 or \
                (said_span is not None and abs(float(said_span) - span) > 0.0051):
            failures.append("%s: warned %s parts within %s (%s of the extent), the oracle %d within %.2f (%.3f)"
                            % (name, warning.group(1), said_gap, said_span, parts, gap, span))
        # From a stored flow complex, the same warning (its cells are numbered
        # as the stored samples, not as the input), but for the place: the
        # rows' gaps tie to the last digit, and the stored values to the last bit.
        stored = cloud[:-4] + ".vtm"
        made = subprocess.run([FLOWRECON, "complex", cloud, "-o", stored], capture_output=True, text=True)
        again = subprocess.run([FLOWRECON, "reconstruct", stored, "-o", cloud[:-4] + "_stored.vtu"],
                               capture_output=True, text=True)
        def unplaced(text):
            found = re.search(r"^warning: the answer is .* side by side.*$", text, re.M)
            return re.sub(r"near \([^)]*\)", "near (...)", found.group(0)) if found else None
        line, whole = unplaced(again.stderr), unplaced(out.stderr)
        if made.returncode or line != whole:
            failures.append("%s: from the stored complex %s, the cloud's %r" % (
                name, repr(line) if line else "no side-by-side warning (exit %d)" % again.returncode, whole))
if failures:
    raise SystemExit("; ".join(failures))
print("parts side by side warned on the %d row samplings, on none of the %d controls"
      % (sum(c[2] for c in cases), sum(not c[2] for c in cases)))
