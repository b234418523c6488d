#!/usr/bin/env pvpython
"""Data/demo.pvsm loads from the repository root as it is ("Use File Names From State",
what `paraview --state=Data/demo.pvsm` does: its data file is the relative path
Data/two_hemispheres.xyz) with the plugin auto-loaded from PV_PLUGIN_PATH, and gives the
demo pipeline, read with the plugin's own reader: the reconstruction at the automatic
t_r (about 2.16 here) and, hidden, the one at t_r 2.5, of which it is the part below
its t_r (checked on the exact geometry; the state shows the compact one). Run from
the repository root:
pvpython Testing/ParaView/test_demo_state.py (test_states.py loads every state from
elsewhere).
"""
import os
import sys

from paraview import simple

simple.LoadState("Data/demo.pvsm")
names = sorted(key[0] for key in simple.GetSources())
print("sources:", names)
AUTO = "Reconstruction (automatic t_r)"
expected = ["FlowComplex", AUTO, "Reconstruction t_r 2.5",
            "Simplification", "two_hemispheres.xyz"]
if names != expected:
    sys.exit("FAIL: sources %s, expected %s" % (names, expected))
reader = simple.FindSource("two_hemispheres.xyz")
if reader.GetXMLName() != "FlowReconPointCloudReader":
    sys.exit("FAIL: the reader is %s, not the plugin's FlowReconPointCloudReader"
             % reader.GetXMLName())
files = reader.FileName
files = [files] if isinstance(files, str) else list(files)
if files != ["Data/two_hemispheres.xyz"]:
    sys.exit("FAIL: reader file %s" % files)
# The state's reconstructions show the compact geometry (the default): Delaunay
# simplices on the samples only, about 2 per sample on these surfaces.
auto_source = simple.FindSource(AUTO)
auto_source.UpdatePipeline()
from paraview import servermanager  # noqa: E402

compact = servermanager.Fetch(auto_source)
samples = simple.FindSource("two_hemispheres.xyz")
samples.UpdatePipeline()
n = samples.GetDataInformation().GetNumberOfPoints()
if compact.GetNumberOfPoints() != n or not 0 < compact.GetNumberOfCells() <= 3 * n:
    sys.exit("FAIL: the compact reconstruction has %d points (samples: %d) and %d cells"
             % (compact.GetNumberOfPoints(), n, compact.GetNumberOfCells()))
compact_nodes = {compact.GetCellData().GetArray("NodeId").GetValue(c)
                 for c in range(compact.GetNumberOfCells())}
# The exact geometry is one property away; its nesting in t_r is checked below.
cells = {}
for name in (AUTO, "Reconstruction t_r 2.5"):
    source = simple.FindSource(name)
    source.Geometry = "Exact stable manifolds"
    source.UpdatePipeline()
    cells[name] = source.GetDataInformation().GetNumberOfCells()
print("cells:", cells, "in", os.getcwd())

chosen = servermanager.Fetch(simple.FindSource(AUTO)).GetFieldData().GetArray("ReconstructionThreshold")
t_r = chosen.GetValue(0) if chosen else None
print("automatic t_r:", t_r)
if t_r is None or not 1.5 < t_r < 2.5:
    sys.exit("FAIL: the automatic t_r is %s, not in the chosen range (1.5, 2.5)" % t_r)
if not 0 < cells[AUTO] < cells["Reconstruction t_r 2.5"]:
    sys.exit("FAIL: reconstructions empty or not growing with t_r: %s" % cells)
# Nested: the automatic one's cells are exactly the t_r = 2.5 cells with Threshold < t_r.


def cell_keys(name, below=None):
    grid = servermanager.Fetch(simple.FindSource(name))
    cd = grid.GetCellData()
    node, threshold = cd.GetArray("NodeId"), cd.GetArray("Threshold")
    keys = set()
    for c in range(grid.GetNumberOfCells()):
        if below is None or threshold.GetValue(c) < below:
            ids = grid.GetCell(c).GetPointIds()
            keys.add((node.GetValue(c), tuple(sorted(ids.GetId(k) for k in range(ids.GetNumberOfIds())))))
    return keys


small, large = cell_keys(AUTO), cell_keys("Reconstruction t_r 2.5", below=t_r)
exact_nodes = {node for node, _ in small}
if not compact_nodes <= exact_nodes:
    sys.exit("FAIL: %d compact cells stand for nodes not in the exact reconstruction"
             % len(compact_nodes - exact_nodes))
if small != large:
    sys.exit("FAIL: the automatic reconstruction is not the Threshold < t_r part of the t_r 2.5 one "
             "(%d vs %d cells, %d in common)" % (len(small), len(large), len(small & large)))
print("PASS")
