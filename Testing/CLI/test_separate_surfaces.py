"""The automatic thresholds on closed surfaces that lie apart or are joined
(Benchmarks/Study/separate_surfaces.py, its quick set): isosurface vertices of
seven implicit shapes (a sphere, a torus, a genus-2 surface, two spheres 0.2
apart, a rounded cube, a thick shell's two nested spheres, a flat ellipsoid) on
24^3 and 48^3 grids, and two unit spheres 0.6 and 0.5 apart (Fibonacci and
i.i.d. points), alone and joined by a rod of points. Their Betti numbers are
known by construction; at defaults each must print them. Two spheres apart over
a stable range of t_r and joined by a bridge later (1 0 2, a longer range) are
two surfaces: the rule that took the longest range answered 1 0 2 on three of
these clouds, one of them without a warning. Two spheres of unequal density
and two nested cube surfaces that join before they close are answered as one
part and must be warned as held together by long edges; two spheres touching at
a point, and every right answer above, must not. Two spheres 0.2 apart with
noise as wide as their gap, answered as one part, must be warned as noisy.
Usage: test_separate_surfaces.py FLOWRECON WORKDIR
"""
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
import held_out_shapes as ho  # noqa: E402
import separate_surfaces as ss  # noqa: E402

FLOWRECON, WORK = sys.argv[1:3]


def held_together(cloud):
    """Whether the defaults' answer on `cloud` is warned as parts held together
    only by long edges."""
    p = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"], capture_output=True, text=True)
    return any(line.startswith("warning:") and "held together only by edges" in line for line in p.stderr.splitlines())


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
    if ok and held_together(cloud):
        failures.append(name + " (right, yet warned as parts joined across a gap)")

# Two closed surfaces that join before they close, so that no t_r has them
# apart: the answer is one part (wrong) and must say that only edges far
# longer than the spacing hold it together. Two spheres touching at a point
# are one part (right) and must not.
JOINED = {"two spheres 0.5 apart, 6000 and 600 points": True,  # True: joined today
          "two nested cube surfaces, sides 2 and 1, 1500 points each": True,
          "two spheres touching at a point": False}
for name, n, points, truth in ss.mixed():
    short = name.replace(", i.i.d.", "")
    if short not in JOINED:
        continue
    cloud = os.path.join(WORK, "joined%d.xyz" % len(points))
    np.savetxt(cloud, points, fmt="%.17g")
    betti, warned, choice = ho.run(FLOWRECON, cloud, [])
    said = held_together(cloud)
    print("%s (%d points): Betti %s, truth %s, %s" % (name, n, betti, truth,
                                                     "warned as joined" if said else "not warned as joined"))
    # Today the joined pairs are answered wrong and must be warned; a right
    # answer must not be (should they ever come out right, that passes too).
    if betti != truth and not said:
        failures.append(name + " (answered %s, truth %s, not warned as joined)" % (betti, truth))
    elif betti == truth and said:
        failures.append(name + " (right, yet warned as joined)")
    elif not JOINED[short] and betti != truth:
        failures.append(name + " (answered %s, truth %s)" % (betti, truth))

# Two spheres 0.2 apart whose samples carry noise (0.3 and 1 times their
# spacing): where the noise is as wide as the gap they are answered as one part
# with two voids, as two spheres touching are, and no edge across the gap is
# long. Such an answer must be warned as noisy voids sharing a part; a right
# answer, and the spheres touching without noise above, must not be.
def noisy_join(cloud):
    p = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"], capture_output=True, text=True)
    b = [int(v) for v in p.stdout.split("Betti numbers:")[1].split()[:3]]
    said = [l for l in p.stderr.splitlines() if l.startswith("warning:")]
    return b, any("the samples are noisy" in l for l in said), said


noisy = 0
for name, n, points, truth in ss.noisy_isosurfaces():
    if not name.startswith("two spheres 0.2 apart"):
        continue
    cloud = os.path.join(WORK, "noisy%d.xyz" % noisy)
    noisy += 1
    np.savetxt(cloud, points, fmt="%.17g")
    betti, said, warnings = noisy_join(cloud)
    print("%s (%d points): Betti %s, truth %s, %s" % (name, n, betti, truth,
                                                     "warned as noisy" if said else "not warned as noisy"))
    if betti != list(truth) and not warnings:
        failures.append(name + " (answered %s, truth %s, not warned)" % (betti, list(truth)))
    elif betti[0] < betti[2] and betti != list(truth) and not said:
        failures.append(name + " (voids sharing a part, not warned as noisy)")
    elif betti == list(truth) and said:
        failures.append(name + " (right, yet warned as noisy)")
for name, n, points, truth in ss.mixed():
    if name.startswith("two spheres touching"):
        cloud = os.path.join(WORK, "touching%d.xyz" % len(points))
        np.savetxt(cloud, points, fmt="%.17g")
        betti, said, warnings = noisy_join(cloud)
        print("%s (%d points): Betti %s, %s" % (name, n, betti, "warned as noisy" if said else "not warned as noisy"))
        if said:
            failures.append(name + " (no noise, yet warned as noisy)")

# Two nested spheres whose shell fills (a solid around a void) are answered by
# the window where they are apart; the same from their stored flow complex
# (which once kept the solid: it looked for a filled surface only without voids).
for name, n, points, truth in ss.mixed():
    if not name.startswith("two nested spheres"):
        continue
    cloud = os.path.join(WORK, "nested.xyz")
    np.savetxt(cloud, points, fmt="%.17g")
    subprocess.run([FLOWRECON, "complex", cloud, "-o", cloud[:-4] + ".vtm"], capture_output=True, check=True)
    said = []
    for source in (cloud, cloud[:-4] + ".vtm"):
        p = subprocess.run([FLOWRECON, "reconstruct", source, "-o", cloud[:-4] + "_answer.vtu"],
                           capture_output=True, text=True)
        said.append([l for l in p.stdout.splitlines() if l.startswith(("Betti numbers:", "t_r "))] +
                    sorted(l for l in p.stderr.splitlines() if l.startswith("warning:")))
        print("%s from %s: %s" % (name, os.path.basename(source), said[-1][:2]))
    if said[0] != said[1] or said[0][:1] != ["Betti numbers: %d %d %d" % tuple(truth)]:
        failures.append(name + " (the stored complex's answer is not the cloud's, or not the truth)")
if len(failures) > 0:
    raise SystemExit("automatic thresholds wrong on: " + "; ".join(failures))
print("right on all %d clouds, joined surfaces warned, nested spheres as on the cloud" % (k + 1))
