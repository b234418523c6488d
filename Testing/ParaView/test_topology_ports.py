"""ParaView shows what the CLI prints: in pvpython, Flow Complex ->
Simplification -> Reconstruction (defaults, Maximum Threshold 4) on a sphere
sample with a thinned polar cap and on the clean sample. The filter's field
data BettiNumbers equals the CLI's 'Betti numbers:' line, its Topology Profile
port equals `--topology-profile` row by row, and its Under Sampling port holds
a point at every place the CLI warns about, all inside the thinned cap (z > 0.7,
up to a sample spacing), and none for the clean sample. The t_r and t_p
sliders span their useful ranges, and Every Step shows the reconstruction at
Maximum Threshold whatever t_r says. The Profile port's field data lists the
Number Of Jumps (default 5) largest jumps as `--jumps 5 --tr-max inf` prints
them (the cloud's run is then complete, as the filter's), none for 0.
Usage: pvpython test_topology_ports.py PLUGIN FLOWRECON WORKDIR
"""
import csv
import os
import re
import subprocess
import sys

import generate_clouds as gc
import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, OpenDataFile
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl

PLUGIN, FLOWRECON, WORK = sys.argv[1:4]

LoadPlugin(PLUGIN, remote=False, ns=globals())
os.makedirs(WORK, exist_ok=True)
failures = []


def cli(path):
    p = subprocess.run([FLOWRECON, "reconstruct", path, "-o", path + ".vtu", "--tr-max", "4", "--exact",
                        "--tr", "2", "--tp", "1.1",
                        "--topology-profile", path + ".csv"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    betti = tuple(int(x) for x in re.search(r"Betti numbers: (\d+) (\d+) (\d+)", p.stdout).groups())
    # (x, y, z, t_r) of each warning: the place and the t_r of its change.
    places = [np.array([float(v) for v in m.group(1).split(",")] + [float(m.group(2))])
              for m in re.finditer(r"warning: under-sampled near \(([^)]*)\): .* at t_r ([0-9.e+-]+)",
                                   p.stderr)]
    with open(path + ".csv") as f:
        rows = [(float(r["threshold"]), int(r["b0"]), int(r["b1"]), int(r["b2"]))
                for r in csv.DictReader(f)]
    return betti, places, rows


def paraview(path):
    reader = OpenDataFile(path)
    fc = FlowComplex(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    # Given thresholds, as the CLI's --tp 1.1 --tr 2.
    simplified = FlowComplexSimplification(Input=fc, AutomaticPersistenceThreshold=0)  # noqa: F821
    recon = FlowReconstruction(Input=simplified, MaximumThreshold=4.0,  # noqa: F821
                               AutomaticReconstructionThreshold=0)
    recon.UpdatePipeline()
    grid = servermanager.Fetch(recon, idx=0)
    b = grid.GetFieldData().GetArray("BettiNumbers")
    betti = tuple(int(b.GetValue(k)) for k in range(3))
    table = servermanager.Fetch(recon, idx=3)
    col = {table.GetColumnName(k): vtk_to_numpy(table.GetColumn(k))
           for k in range(table.GetNumberOfColumns())}
    rows = [(float(col["Threshold"][i]), int(col["b0"][i]), int(col["b1"][i]), int(col["b2"][i]))
            for i in range(table.GetNumberOfRows())]
    under = servermanager.Fetch(recon, idx=4)
    pts = vtk_to_numpy(under.GetPoints().GetData()) if under.GetNumberOfPoints() else np.zeros((0, 3))
    global pthresholds
    pthresholds = list(vtk_to_numpy(under.GetPointData().GetArray("Threshold"))) \
        if under.GetNumberOfPoints() else []
    for name in ("Threshold", "Dimension", "Change", "Spacing", "NodeId"):
        if under.GetNumberOfPoints() and under.GetPointData().GetArray(name) is None:
            failures.append("%s: Under Sampling has no %s array" % (path, name))
    return betti, pts, rows, recon, simplified


def cli_jumps(path):
    p = subprocess.run([FLOWRECON, "reconstruct", path, "-o", path + "_all.vtu", "--tr-max", "inf", "--exact",
                        "--tr", "2", "--tp", "1.1", "--no-betti", "--jumps", "5"], capture_output=True, text=True)
    assert p.returncode == 0, p.stderr
    return [l for l in p.stdout.splitlines() if l.startswith("  step ")]


def paraview_jumps(recon):
    """The Profile port's jumps in the CLI's words (C++ prints doubles as %g)."""
    fd = servermanager.Fetch(recon, idx=1).GetFieldData()
    if fd.GetArray("JumpStep") is None:
        return []
    a = {n: vtk_to_numpy(fd.GetArray(n)) for n in (
        "JumpStep", "JumpThresholdBefore", "JumpThresholdAfter", "JumpNodeId", "JumpIndex",
        "JumpCriticalValue", "JumpLocation")}
    return ["  step %d: %g -> %g, node %d, index %d, value %g, at (%g, %g, %g)" % (
        a["JumpStep"][r], a["JumpThresholdBefore"][r], a["JumpThresholdAfter"][r],
        a["JumpNodeId"][r], a["JumpIndex"][r], a["JumpCriticalValue"][r], *a["JumpLocation"][r])
        for r in range(len(a["JumpStep"]))]


def slider(proxy, name):
    d = proxy.GetProperty(name).SMProperty.FindDomain("vtkSMDoubleRangeDomain")
    return d.GetMinimum(0), d.GetMaximum(0)


base = gc.make("sphere_qu", size=3000)
rng = np.random.default_rng(3)
thinned = base[(base[:, 2] <= 0.7) | (rng.uniform(size=len(base)) > 0.6)]
for name, points in (("clean", base), ("thinned", thinned)):
    path = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(path, points)
    cb, cplaces, crows = cli(path)
    pb, ppts, prows, recon, simplified = paraview(path)
    print("%s: CLI Betti %s, %d warnings, %d profile rows; ParaView Betti %s, %d under-sampled "
          "points, %d profile rows" % (name, cb, len(cplaces), len(crows), pb, len(ppts), len(prows)))
    if cb != pb:
        failures.append("%s: Betti numbers CLI %s, ParaView %s" % (name, cb, pb))
    if len(crows) != len(prows) or any(
            c[1:] != p[1:] or abs(c[0] - p[0]) > 1e-9 * max(1.0, abs(c[0]))
            for c, p in zip(crows, prows)):
        failures.append("%s: topology profiles differ:\n CLI %s\n PV  %s" % (name, crows, prows))
    # A change at a threshold that several cells share (the queue's running
    # maximum) is placed at one of them: the CLI (the Hasse diagram's order)
    # and the filter (the drawn cells' order) may name different ones, so a
    # warning must match an Under Sampling point by its t_r.
    pthr = np.array(pthresholds)
    for q in cplaces:
        if not len(pthr) or np.min(np.abs(pthr - q[3]) / q[3]) > 1e-5:
            failures.append("%s: CLI warning at t_r %s has no Under Sampling point" % (name, q[3]))
    if len(cplaces) > len(ppts) or (len(ppts) > 0) != (len(cplaces) > 0):
        failures.append("%s: %d CLI warnings, %d Under Sampling points" % (name, len(cplaces), len(ppts)))
    cjumps, pjumps = cli_jumps(path), paraview_jumps(recon)
    print("%s: largest jump%s" % (name, pjumps[:1]))
    if recon.NumberOfJumps != 5 or len(cjumps) != 5 or pjumps != cjumps:
        failures.append("%s: Number Of Jumps %s, jumps:\n ParaView %s\n CLI %s"
                        % (name, recon.NumberOfJumps, pjumps, cjumps))
    recon.NumberOfJumps = 0
    recon.UpdatePipeline()
    if paraview_jumps(recon):
        failures.append("%s: jumps listed with Number Of Jumps 0" % name)
    recon.NumberOfJumps = 5
    if name == "clean" and (len(ppts) or cplaces or cb != (1, 0, 1)):
        failures.append("clean: expected Betti (1, 0, 1) and no warning")
    if name == "thinned":
        if not len(ppts) or cb == (1, 0, 1):
            failures.append("thinned: expected a wrong answer and warnings")
        elif np.any(ppts[:, 2] < 0.6):
            failures.append("thinned: Under Sampling points outside the cap: z = %s" % ppts[:, 2])

# Sliders and Every Step, on the thinned sample (its family changes between 2 and 4).
# t_r: 1 to the default Maximum Threshold (the automatic t_r's range)
if slider(recon, "ReconstructionThreshold") != (1.0, 5.0):
    failures.append("t_r slider spans %s" % (slider(recon, "ReconstructionThreshold"),))
if slider(simplified, "PersistenceThreshold") != (1.0, 1.5):
    failures.append("t_p slider spans %s" % (slider(simplified, "PersistenceThreshold"),))
counts = {}
for every, tr in ((0, 2.0), (0, 4.0), (1, 2.0)):
    recon.EveryStep = every
    recon.ReconstructionThreshold = tr
    recon.UpdatePipeline()
    counts[(every, tr)] = recon.GetDataInformation().GetNumberOfCells()
print("cells: t_r 2 %d, t_r 4 %d, Every Step (t_r 2) %d" % (
    counts[(0, 2.0)], counts[(0, 4.0)], counts[(1, 2.0)]))
if not (counts[(1, 2.0)] == counts[(0, 4.0)] > counts[(0, 2.0)]):
    failures.append("Every Step does not show the reconstruction at Maximum Threshold")

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS")
