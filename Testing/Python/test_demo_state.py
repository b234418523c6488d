#!/usr/bin/env pvpython
"""Data/demo.pvsm loads from the repository root (its data file is the relative path
Data/two_hemispheres.xyz) with the plugin auto-loaded from PV_PLUGIN_PATH, and gives the
demo pipeline. Run from the repository root: pvpython Testing/Python/test_demo_state.py
"""
import os
import sys

from paraview import simple

simple.LoadState("Data/demo.pvsm")
names = sorted(key[0] for key in simple.GetSources())
print("sources:", names)
expected = ["FlowComplex", "Points", "Reconstruction t_r 2", "Reconstruction t_r 2.5",
            "Simplification", "two_hemispheres.xyz"]
if names != expected:
    sys.exit("FAIL: sources %s, expected %s" % (names, expected))
reader = simple.FindSource("two_hemispheres.xyz")
if list(reader.FileName) != ["Data/two_hemispheres.xyz"]:
    sys.exit("FAIL: reader file %s" % list(reader.FileName))
cells = {}
for name in ("Reconstruction t_r 2", "Reconstruction t_r 2.5"):
    source = simple.FindSource(name)
    source.UpdatePipeline()
    cells[name] = source.GetDataInformation().GetNumberOfCells()
print("cells:", cells, "in", os.getcwd())
if not 0 < cells["Reconstruction t_r 2"] < cells["Reconstruction t_r 2.5"]:
    sys.exit("FAIL: reconstructions not nested/non-empty: %s" % cells)
print("PASS")
