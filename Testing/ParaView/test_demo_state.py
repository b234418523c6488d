#!/usr/bin/env pvpython
"""Data/demo.pvsm loads from the repository root as it is ("Use File Names From State",
what `paraview --state=Data/demo.pvsm` does: its data file is the relative path
Data/two_hemispheres.xyz) with the plugin auto-loaded from PV_PLUGIN_PATH, and gives the
demo pipeline, read with the plugin's own reader. Run from the repository root:
pvpython Testing/ParaView/test_demo_state.py (test_states.py loads every state from
elsewhere).
"""
import os
import sys

from paraview import simple

simple.LoadState("Data/demo.pvsm")
names = sorted(key[0] for key in simple.GetSources())
print("sources:", names)
expected = ["FlowComplex", "Reconstruction t_r 2", "Reconstruction t_r 2.5",
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
cells = {}
for name in ("Reconstruction t_r 2", "Reconstruction t_r 2.5"):
    source = simple.FindSource(name)
    source.UpdatePipeline()
    cells[name] = source.GetDataInformation().GetNumberOfCells()
print("cells:", cells, "in", os.getcwd())
if not 0 < cells["Reconstruction t_r 2"] < cells["Reconstruction t_r 2.5"]:
    sys.exit("FAIL: reconstructions empty or not growing with t_r: %s" % cells)
# Nested: the t_r = 2 cells are exactly the t_r = 2.5 cells with Threshold < 2.
from paraview import servermanager


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


small, large = cell_keys("Reconstruction t_r 2"), cell_keys("Reconstruction t_r 2.5", below=2)
if small != large:
    sys.exit("FAIL: the t_r 2 reconstruction is not the Threshold < 2 part of the t_r 2.5 one "
             "(%d vs %d cells, %d in common)" % (len(small), len(large), len(small & large)))
print("PASS")
