"""The default output of `reconstruct` against independent answers, on every
cloud the command-line tests read (Testing/Data: the regular tetrahedron and a
31-point cloud) and the bundled ones (Data: torus, two hemispheres, bunny).

- The default file (Delaunay simplices on the samples) has the Betti numbers of
  the exact reconstruction: GUDHI's Betti numbers of its cells (an oracle
  written by others) equal the printed 'Betti numbers:' line (from the Hasse
  diagram) and the compact ones printed beside it, with no warning that they
  differ; at the automatic thresholds and at t_p 0 or 1.1 with t_r 1.1, 2 and
  inf, from the cloud and from its stored flow complex (.vtm).
- `--exact` writes what the exact path writes: the grid of the VTK filters
  (vtkFlowComplex, vtkFlowComplexSimplification, vtkFlowReconstruction at the
  same t_p and t_r), which have no compact output, point for point, cell for
  cell and array for array; so its cell count is theirs.
Usage: test_default_output.py FLOWRECON WORKDIR
"""
import os
import sys

import generate_clouds as gc
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.flowcomplex_io import reconstruction_pipeline
from flowrecon_testing.oracles import default_output_problems

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
HERE = os.path.dirname(os.path.abspath(__file__))
CLOUDS = [os.path.join(HERE, "..", "Data", c) for c in ("tetrahedron.xyz", "small_cloud.xyz")] + \
    [os.path.join(HERE, "..", "..", "Data", c) for c in ("torus.xyz", "two_hemispheres.xyz", "bunny.xyz")]
THRESHOLDS = [[], ["--tp", "0", "--tr", "1.1"], ["--tp", "0", "--tr", "2"],
              ["--tp", "1.1", "--tr", "2"], ["--tp", "0", "--tr", "inf"]]
os.makedirs(WORK, exist_ok=True)
failures = []


def grid_state(g):
    """Points, cells and every point and cell array of an unstructured grid."""
    state = {"points": vtk_to_numpy(g.GetPoints().GetData()),
             "cells": vtk_to_numpy(g.GetCells().GetConnectivityArray()),
             "types": vtk_to_numpy(g.GetCellTypesArray())}
    for kind, data in (("cell", g.GetCellData()), ("point", g.GetPointData())):
        for k in range(data.GetNumberOfArrays()):
            state[kind + " " + data.GetArrayName(k)] = vtk_to_numpy(data.GetArray(k))
    return state


runs = 0
for cloud in CLOUDS:
    name = os.path.splitext(os.path.basename(cloud))[0]
    base = os.path.join(WORK, name)
    points = gc.read_xyz(cloud)
    cl.write_xyz(base + ".xyz", points)
    fr.run(FLOWRECON, "complex", base + ".xyz", "-o", base + ".vtm", "--quiet")
    for source in (base + ".xyz", base + ".vtm"):
        for thresholds in THRESHOLDS:
            label = "%s, %s" % (os.path.basename(source), " ".join(thresholds) or "automatic")
            code, out, err = fr.call(FLOWRECON, "reconstruct", source, "-o", base + "_default.vtu",
                                     *thresholds)
            problems = ["exit %d: %s" % (code, err.strip())] if code else \
                default_output_problems(base + "_default.vtu", out, err)
            runs += 1
            print("%s: Betti numbers %s, %s" % (label, fr.printed_betti(out) if not code else "-",
                                                "right" if not problems else "; ".join(problems)))
            failures.extend("%s: %s" % (label, p) for p in problems)
    # --exact against the filters.
    for tp, tr in ((1.1, 2.0), (0.0, 1.5)):
        fr.run(FLOWRECON, "reconstruct", base + ".xyz", "-o", base + "_exact.vtu", "--exact",
               "--tp", str(tp), "--tr", str(tr), "--quiet")
        a, b = grid_state(fr.read_grid(base + "_exact.vtu")), grid_state(reconstruction_pipeline(points, tp, tr)[1].GetOutput(0))
        differ = [k for k in sorted(set(a) | set(b)) if k not in a or k not in b or
                  a[k].shape != b[k].shape or not np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f")]
        print("%s, --exact --tp %g --tr %g: %d cells, the filters %d: %s" % (
            name, tp, tr, len(a["types"]), len(b["types"]),
            "the same" if not differ else "DIFFERENT in " + ", ".join(differ)))
        if differ:
            failures.append("%s, t_p %g, t_r %g: --exact differs from the filters in %s"
                            % (name, tp, tr, ", ".join(differ)))

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS: %d runs of the default output right by GUDHI" % runs)
