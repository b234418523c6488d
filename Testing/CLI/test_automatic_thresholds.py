"""The automatic t_r and t_p (`flowrecon reconstruct` without --tr/--tp) on the
study's generators (Apps/Scripts/generate_clouds.py), whose true Betti numbers are
known by construction: quasi-uniform and i.i.d. surfaces, lattices that the
simplification breaks, a solid, a non-manifold union and a curve. At defaults
each must print its truth, a line 't_r X (auto), t_p Y (auto): Betti numbers
..., unchanged for t_r in (a, b]' with a < X <= b, and the reconstruction's
field data must state the same choice, and no warning may say that a surface
was filled in. Closed surfaces sampled too sparsely for their thickness (a
thin plate, two spheres through each other at 1000 i.i.d. points, a thin tube
at 10 000) close only
as solids: wherever the answer is not the truth, the warning that the samples
lie on a surface yet the reconstruction is solid must be printed. Closed
surfaces with noise of 1-2 times their spacing at 1000 points look like volume
samples at every neighbourhood size and also close only as solids: wherever the
answer is not the truth, a warning must say the solid is filled (flat samples)
or shallow (every sample within 2 Delaunay edges of its boundary), the same
with --exact and from the stored flow complex (the torus), while the
volume sample (a ball of 3000 i.i.d. points) is warned of neither. Where such
a surface closes briefly before it fills (a torus with noise of half its
spacing, a sparse genus-4 surface), the surface is taken, with a warning. With explicit
numbers there is no such line and the field data says nothing was chosen.
Every file written (the default output, Delaunay simplices on the samples) must
have the printed Betti numbers by GUDHI, right or wrong.
Usage: test_automatic_thresholds.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys
import zlib

import generate_clouds as gc
import numpy as np

from flowrecon_testing import run as fr
from flowrecon_testing.clouds import noisy_surface
from flowrecon_testing.oracles import default_output_problems

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)

# (shape, size): every class the defaults must get right.
CLOUDS = [
    ("sphere_qu", 4000),        # quasi-uniform surface
    ("torus_qu", 4000),
    ("genus2_qu", 6000),
    ("torus", 20000),           # i.i.d.: t_r 2 leaves holes
    ("latlong_poles", None),    # a lattice that t_p 1.1 breaks
    ("lattice_shell", None),
    ("ball", 3000),             # a solid
    ("two_spheres_qu", 4000),   # non-manifold
    ("trefoil_qu", 1000),       # a curve
    ("two_hemispheres", 1000),  # an open surface: no void, and not filled
]
FILLED = "may have been filled in"
# Closed surfaces whose samples are too sparse for their thickness; the tube's
# walls (0.1 apart, about 0.05 between samples) share neighbourhoods of 30.
THIN = [("thin_plate", 1000), ("two_spheres", 1000), ("thin_tube", 10000)]
SHALLOW = "solid but shallow"
# The topology study's noisy surfaces of 1000 points that no neighbourhood size
# shows flat: (shape, noise in spacings), seeded as the study seeds them.
NOISY = [("torus_pd", 2), ("genus2_pd", 1), ("genus2_pd", 2)]
CHOICE = re.compile(r"^t_r ([0-9.]+) \(auto\), t_p ([0-9.]+) \(auto\): Betti numbers "
                    r"(\d+) (\d+) (\d+), unchanged for t_r in \(([0-9.]+), ([0-9.]+)\]$", re.M)


def latlong_poles():
    """A 30 x 60 latitude-longitude lattice of the sphere of radius 10 with its
    two poles: a sphere, (1, 0, 1); t_p 1.1 cancels its patches into holes."""
    theta = np.linspace(0, np.pi, 32)[1:-1]
    phi = np.linspace(0, 2 * np.pi, 60, endpoint=False)
    t, p = np.meshgrid(theta, phi)
    x = np.c_[np.sin(t.ravel()) * np.cos(p.ravel()), np.sin(t.ravel()) * np.sin(p.ravel()),
              np.cos(t.ravel())]
    return 10 * np.r_[x, [[0, 0, 1], [0, 0, -1]]]


failures = []
for shape, size in CLOUDS:
    base = os.path.join(WORK, "%s_%s" % (shape, size or "default"))
    with open(base + ".xyz", "w") as f:
        f.write(gc.to_xyz_text(latlong_poles() if shape == "latlong_poles" else gc.make(shape, size=size)))
    truth = (1, 0, 1) if shape == "latlong_poles" else tuple(gc.betti(shape))
    p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu"],
                       capture_output=True, text=True)
    problems = []
    m = CHOICE.search(p.stdout)
    printed = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    if p.returncode != 0 or not m or not printed:
        problems.append("exit %d, stdout %r, stderr %r" % (p.returncode, p.stdout, p.stderr))
    else:
        tr, tp = float(m.group(1)), float(m.group(2))
        betti = tuple(int(x) for x in printed.groups())
        lo, hi = float(m.group(6)), float(m.group(7))
        if betti != truth:
            problems.append("Betti %s, truth %s" % (betti, truth))
        if tuple(int(m.group(k)) for k in (3, 4, 5)) != betti:
            problems.append("the choice line names other Betti numbers")
        if not lo < tr <= hi:
            problems.append("t_r %g outside its window (%g, %g]" % (tr, lo, hi))
        if fr.field(base + ".vtu", "ThresholdsChosen") != [1, 1]:
            problems.append("field data ThresholdsChosen %s" % fr.field(base + ".vtu", "ThresholdsChosen"))
        used = fr.field(base + ".vtu", "ReconstructionThreshold")
        if not used or abs(used[0] - tr) > 1e-3 * tr:
            problems.append("field data ReconstructionThreshold %s, printed %g" % (used, tr))
        if fr.field(base + ".vtu", "PersistenceThreshold") != [tp]:
            problems.append("field data PersistenceThreshold %s" % fr.field(base + ".vtu", "PersistenceThreshold"))
        if FILLED in p.stderr:
            problems.append("a right answer warned as filled")
        if SHALLOW in p.stderr:
            problems.append("a right answer warned as a shallow solid")
        window = fr.field(base + ".vtu", "StableWindow")
        if not window or abs(window[0] - lo) > 0.01 or abs(window[1] - hi) > 0.01:
            problems.append("field data StableWindow %s, printed (%g, %g]" % (window, lo, hi))
        problems += default_output_problems(base + ".vtu", p.stdout, p.stderr)
    print("%s (%s points): %s" % (shape, size or "default",
                                  "OK " + m.group(0) if not problems else "WRONG: " + "; ".join(problems)))
    if problems:
        failures.append(shape)

# Wrong answers on surfaces too thin for their sampling are warned.
for shape, size in THIN:
    base = os.path.join(WORK, "%s_%s" % (shape, size))
    with open(base + ".xyz", "w") as f:
        f.write(gc.to_xyz_text(gc.make(shape, size=size)))
    p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu"],
                       capture_output=True, text=True)
    printed = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    betti = tuple(int(x) for x in printed.groups()) if printed else None
    truth = tuple(gc.betti(shape))
    warned = FILLED in p.stderr
    print("%s (%d points): Betti %s, truth %s, %s" % (shape, size, betti, truth,
                                                     "warned as filled" if warned else "no filled warning"))
    if p.returncode != 0 or betti is None or (betti != truth and not warned):
        failures.append(shape + " (a wrong answer without the filled warning)")
    elif default_output_problems(base + ".vtu", p.stdout, p.stderr):
        failures.append(shape + ": " + "; ".join(default_output_problems(base + ".vtu", p.stdout, p.stderr)))

# Noisy closed surfaces whose answer is solid are warned.
for shape, times in NOISY:
    name = "%s_noise%g_n1000" % (shape, times)
    base = os.path.join(WORK, name)
    with open(base + ".xyz", "w") as f:
        f.write(gc.to_xyz_text(noisy_surface(shape, 1000, times, zlib.crc32(name.encode()))))
    p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu"],
                       capture_output=True, text=True)
    printed = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    betti = tuple(int(x) for x in printed.groups()) if printed else None
    truth = tuple(gc.betti(shape))
    warned = FILLED in p.stderr or SHALLOW in p.stderr
    print("%s: Betti %s, truth %s, %s" % (name, betti, truth, "warned" if warned else "not warned"))
    if p.returncode != 0 or betti is None or (betti != truth and not warned):
        failures.append(name + " (a wrong answer without the filled or shallow warning)")
    else:
        a = fr.read_grid(base + ".vtu").GetFieldData().GetAbstractArray("ThresholdWarnings")
        written = [a.GetValue(k) for k in range(a.GetNumberOfValues())] if a else []
        if warned and not any(FILLED in w or SHALLOW in w for w in written):
            failures.append(name + " (the warning is not in the file's field data)")
    if shape == "torus_pd":
        # The same warnings from its stored flow complex, and with --exact.
        subprocess.run([FLOWRECON, "complex", base + ".xyz", "-o", base + ".vtm"],
                       capture_output=True, check=True)
        for source, extra in ((base + ".xyz", ["--exact"]), (base + ".vtm", []), (base + ".vtm", ["--exact"])):
            q = subprocess.run([FLOWRECON, "reconstruct", source, "-o", base + "_again.vtu"] + extra,
                               capture_output=True, text=True)
            again = sorted(l for l in q.stderr.splitlines() if l.startswith("warning:"))
            first = sorted(l for l in p.stderr.splitlines() if l.startswith("warning:"))
            print("  %s %s: %d warning(s)%s" % (os.path.basename(source), " ".join(extra), len(again),
                                               "" if again == first else ", not the cloud's"))
            if q.returncode != 0 or again != first:
                failures.append("%s %s: warnings %s, the cloud's %s" % (source, extra, again, first))

# Closed surfaces whose most stable topology is a solid (the samples lie on a
# surface) and whose surface closes briefly before it fills: the surface is
# the answer, with a warning that names the solid left and the window taken,
# in the file's field data too (the study's clouds, seeded as it seeds them).
TAKEN = "is taken instead"
for name, points in (
        ("torus_pd_noise0.5_n1000", lambda: noisy_surface("torus_pd", 1000, 0.5,
                                                          zlib.crc32(b"torus_pd_noise0.5_n1000"))),
        ("genus4_pd_n1000", lambda: gc.make("genus4_pd", size=1000))):
    base = os.path.join(WORK, name)
    with open(base + ".xyz", "w") as f:
        f.write(gc.to_xyz_text(points()))
    p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu"],
                       capture_output=True, text=True)
    printed = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", p.stdout, re.M)
    betti = tuple(int(x) for x in printed.groups()) if printed else None
    truth = tuple(gc.betti(re.sub(r"_noise[\d.]+", "", name[:name.rindex("_n")])))
    a = fr.read_grid(base + ".vtu").GetFieldData().GetAbstractArray("ThresholdWarnings") \
        if p.returncode == 0 else None
    written = [a.GetValue(k) for k in range(a.GetNumberOfValues())] if a else []
    ok = p.returncode == 0 and betti == truth and TAKEN in p.stderr and FILLED in p.stderr \
        and any(TAKEN in w for w in written)
    print("%s: Betti %s, truth %s, %s" % (name, betti, truth,
                                         "the surface taken, warned" if ok else "WRONG " + p.stderr))
    if not ok:
        failures.append(name + " (the surface not taken over the solid, or not warned)")
    elif default_output_problems(base + ".vtu", p.stdout, p.stderr):
        failures.append(name + ": " + "; ".join(default_output_problems(base + ".vtu", p.stdout, p.stderr)))

# Explicit numbers: the old behaviour, nothing chosen.
base = os.path.join(WORK, "explicit")
with open(base + ".xyz", "w") as f:
    f.write(gc.to_xyz_text(gc.make("sphere_qu", size=2000)))
p = subprocess.run([FLOWRECON, "reconstruct", base + ".xyz", "-o", base + ".vtu", "--tr", "2",
                    "--tp", "1.1"], capture_output=True, text=True)
if p.returncode != 0 or "(auto)" in p.stdout or fr.field(base + ".vtu", "ThresholdsChosen") != [0, 0] \
        or fr.field(base + ".vtu", "ReconstructionThreshold") != [2.0]:
    failures.append("explicit numbers")
    print("explicit --tr 2 --tp 1.1: WRONG", p.stdout, p.stderr)
else:
    print("explicit --tr 2 --tp 1.1: OK, nothing chosen")
if failures:
    raise SystemExit("automatic thresholds wrong on: " + ", ".join(failures))
print("the automatic thresholds give the truth on every cloud")
