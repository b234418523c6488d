"""The largest jumps of the reconstruction profile in Flow Reconstruction's
output (the profile's field data, Number Of Jumps of them) against two
independent answers:
- `flowrecon reconstruct CLOUD --jumps K` on the same cloud and thresholds,
  which reconstructs the cloud through the core directly (CloudReconstruction,
  not the VTK filters) and prints one line per jump: the filter's numbers,
  printed as C++ prints doubles (%g), must be those lines;
- the profile table itself: the K largest positive differences of its
  Threshold column taken with numpy (ties: the earlier step), with the node
  of that row, whose critical value and location come from the CriticalPoints
  block of the flow complex.
Number Of Jumps 0 gives no jump arrays; a K above the number of rises lists
every rise. `--tr-max inf`: the cloud's run is then complete, as the filter's.
Usage: test_profile_jumps.py FLOWRECON WORKDIR
"""
import os
import re
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.flowcomplex_io import array, get_block, reconstruction_pipeline

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
TP, TR, K = 1.1, 2.0, 7
JUMP = re.compile(r"^  step (\d+): (\S+) -> (\S+), node (\d+), index (\d), value (\S+), "
                  r"at \((\S+), (\S+), (\S+)\)$")
failures = []


def clouds():
    rng = np.random.default_rng(11)
    torus = cl.chart_torus(900, rng, 0.4)
    sphere = cl.sphere(700, rng)
    return {
        "thinned torus": torus[(torus[:, 0] < 0.6) | (rng.uniform(size=len(torus)) < 0.25)],
        "noisy sphere": cl.noisy(sphere, rng, 0.03),
        "two hemispheres": cl.two_hemispheres(),
    }


def cli_jumps(path):
    out = fr.run(FLOWRECON, "reconstruct", path, "-o", path + ".vtu", "--tp", str(TP),
                 "--tr", str(TR), "--tr-max", "inf", "--jumps", str(K), "--quiet")
    lines = [l for l in out.splitlines() if l.startswith("  step ")]
    if not all(JUMP.match(l) for l in lines):
        raise SystemExit("unexpected jump lines:\n" + out)
    return lines


def jump_arrays(profile):
    fd = profile.GetFieldData()
    names = ["JumpStep", "JumpThresholdBefore", "JumpThresholdAfter", "JumpNodeId",
             "JumpIndex", "JumpCriticalValue", "JumpLocation"]
    present = [n for n in names if fd.GetArray(n) is not None]
    if not present:
        return None
    if present != names:
        raise SystemExit("jump arrays %s of %s" % (present, names))
    return {n: vtk_to_numpy(fd.GetArray(n)) for n in names}


def as_lines(j):
    """The filter's jumps in the CLI's words and number format (C++ << double: %g)."""
    return ["  step %d: %g -> %g, node %d, index %d, value %g, at (%g, %g, %g)" % (
        j["JumpStep"][r], j["JumpThresholdBefore"][r], j["JumpThresholdAfter"][r],
        j["JumpNodeId"][r], j["JumpIndex"][r], j["JumpCriticalValue"][r],
        *j["JumpLocation"][r]) for r in range(len(j["JumpStep"]))]


def numpy_jumps(profile, critical_points, k):
    """The k largest rises of Threshold and their rows' nodes, from the table alone."""
    threshold = array(profile.GetRowData(), "Threshold")
    node = array(profile.GetRowData(), "NodeId")
    index = array(profile.GetRowData(), "Index")
    rise = np.diff(threshold)
    steps = sorted(np.nonzero(rise > 0)[0] + 1, key=lambda s: (-rise[s - 1], s))[:k]
    row_of = {int(n): r for r, n in enumerate(array(critical_points.GetPointData(), "NodeId"))}
    value = array(critical_points.GetPointData(), "CriticalValue")
    location = vtk_to_numpy(critical_points.GetPoints().GetData())
    rows = [row_of[int(node[s])] for s in steps]
    return {"JumpStep": np.array(steps), "JumpThresholdBefore": threshold[np.array(steps) - 1],
            "JumpThresholdAfter": threshold[steps], "JumpNodeId": node[steps],
            "JumpIndex": index[steps], "JumpCriticalValue": value[rows],
            "JumpLocation": location[rows]}, int(np.count_nonzero(rise > 0))


os.makedirs(WORK, exist_ok=True)
for name, xyz in clouds().items():
    path = os.path.join(WORK, name.replace(" ", "_") + ".xyz")
    cl.write_xyz(path, xyz)
    problems = []
    fc, reconstruction = reconstruction_pipeline(xyz, TP, TR)
    reconstruction.SetNumberOfJumps(K)
    reconstruction.Update()
    profile = reconstruction.GetOutputDataObject(1)
    jumps = jump_arrays(profile)
    expected, rises = numpy_jumps(profile, get_block(fc.GetOutput(), "CriticalPoints"), K)
    if rises < K:
        problems.append("only %d rises: the cloud does not test %d jumps" % (rises, K))
    if jumps is None:
        problems.append("no jump arrays with Number Of Jumps %d" % K)
    else:
        for key, want in expected.items():
            if not np.array_equal(jumps[key], want):
                problems.append("%s %s, from the table %s" % (key, jumps[key], want))
        printed = cli_jumps(path)
        if as_lines(jumps) != printed:
            problems.append("filter:\n%s\nCLI:\n%s" % ("\n".join(as_lines(jumps)),
                                                      "\n".join(printed)))
    # 0: none; more than there are rises: every rise.
    reconstruction.SetNumberOfJumps(0)
    reconstruction.Update()
    if jump_arrays(reconstruction.GetOutputDataObject(1)) is not None:
        problems.append("jump arrays with Number Of Jumps 0")
    reconstruction.SetNumberOfJumps(rises + 5)
    reconstruction.Update()
    every = jump_arrays(reconstruction.GetOutputDataObject(1))
    if every is None or len(every["JumpStep"]) != rises:
        problems.append("Number Of Jumps %d lists %s of the %d rises"
                        % (rises + 5, None if every is None else len(every["JumpStep"]), rises))
    print("%s: %d points, %d rises, largest at step %s: %s" % (
        name, len(xyz), rises, expected["JumpStep"][:1], "OK" if not problems else
        "WRONG: " + "; ".join(problems)))
    if problems:
        failures.append(name)
if failures:
    raise SystemExit("the filter's jumps are not the profile's largest on: " + ", ".join(failures))
print("Flow Reconstruction's jumps equal the CLI's and the profile's largest rises")
