#!/usr/bin/env python3
"""The FlowRecon ParaView plugin from pvpython / pvbatch: load it, create the
"Flow Complex" filter (proxy FlowComplex) on a Point Source, update it, save the
result as .vtm, read the file back with plain VTK and check the four blocks, their
arrays and the Euler characteristic of the critical points.

Run: pvpython test_paraview.py PLUGIN_PATH [OUTPUT_PREFIX]
(PLUGIN_PATH: the FlowRecon plugin library; OUTPUT_PREFIX: where to write
OUTPUT_PREFIX.vtm, default a temporary folder.)
"""

import math
import os
import sys
import tempfile

from flowrecon_testing.checks import fail

BLOCKS = {
    "CriticalPoints": ("vtkPolyData", "point", ("NodeId", "Index", "CriticalValue")),
    "HasseDiagram": ("vtkPolyData", "cell", ("Multiplicity", "Ratio")),
    "StableManifolds": ("vtkUnstructuredGrid", "cell", ("NodeId", "Index", "CriticalValue")),
    "UnstableManifolds": ("vtkPolyData", "cell", ("NodeId", "TargetNodeId")),
    "GabrielEdges": ("vtkPolyData", "cell", ("NodeId", "Index", "CriticalValue")),
}


def main():
    if len(sys.argv) < 2:
        fail("usage: pvpython test_paraview.py PLUGIN_PATH [OUTPUT_PREFIX]")
    plugin = sys.argv[1]
    prefix = sys.argv[2] if len(sys.argv) > 2 else os.path.join(tempfile.mkdtemp(), "flowcomplex_pv")
    if not os.path.exists(plugin):
        fail("plugin %s does not exist" % plugin)

    from paraview import simple
    simple.LoadPlugin(plugin, remote=False, ns=globals())
    if "FlowComplex" not in globals():
        fail("LoadPlugin did not define FlowComplex; names with 'Flow': %s" % sorted(
            k for k in globals() if "flow" in k.lower()))
    src = simple.PointSource(NumberOfPoints=200, Radius=1.0, Center=[0.0, 0.0, 0.0])
    fc = globals()["FlowComplex"](Input=src)  # defined by LoadPlugin
    label = fc.GetXMLLabel()
    if label != "Flow Complex" or fc.GetXMLName() != "FlowComplex":
        fail("proxy %r labelled %r, expected FlowComplex / 'Flow Complex'" % (fc.GetXMLName(), label))
    for prop in ("ComputeStableManifolds", "ComputeUnstableManifolds", "PerturbationSeed"):
        if prop not in fc.ListProperties():
            fail("property %s missing; properties: %s" % (prop, fc.ListProperties()))
    fc.UpdatePipeline()
    info = fc.GetDataInformation()
    print("data information: %s, %d points, %d cells" % (
        info.GetDataSetTypeAsString(), info.GetNumberOfPoints(), info.GetNumberOfCells()))

    os.makedirs(os.path.dirname(os.path.abspath(prefix)), exist_ok=True)
    path = prefix + ".vtm"
    simple.SaveData(path, proxy=fc)
    if not os.path.exists(path):
        fail("SaveData did not write %s" % path)
    print("wrote %s" % path)

    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader
    reader = vtkXMLMultiBlockDataReader()
    reader.SetFileName(path)
    reader.Update()
    mb = reader.GetOutput()
    names = {}
    for i in range(mb.GetNumberOfBlocks()):
        md = mb.GetMetaData(i) if mb.HasMetaData(i) else None
        name = md.Get(vtkCompositeDataSet.NAME()) if md is not None else None
        names[name] = mb.GetBlock(i)
    if set(names) != set(BLOCKS):
        fail("blocks read back: %s, expected %s" % (sorted(map(str, names)), sorted(BLOCKS)))
    for name, (cls, where, arrays) in BLOCKS.items():
        b = names[name]
        if b is None or not b.IsA(cls):
            fail("block %s is %s, expected %s" % (name, b.GetClassName() if b else None, cls))
        data = b.GetPointData() if where == "point" else b.GetCellData()
        for a in arrays:
            if data.GetArray(a) is None:
                fail("block %s has no %s array %s after the round trip" % (name, where, a))

    cp = names["CriticalPoints"]
    index = cp.GetPointData().GetArray("Index")
    value = cp.GetPointData().GetArray("CriticalValue")
    counts = [0, 0, 0, 0]
    infinite = 0
    for i in range(cp.GetNumberOfPoints()):
        v = value.GetValue(i)
        if math.isinf(v):
            infinite += 1
            continue
        counts[int(index.GetValue(i))] += 1
    chi = counts[0] - counts[1] + counts[2] - counts[3]
    print("counts %s, maxima at infinity %d, Euler characteristic %d" % (counts, infinite, chi))
    if counts[0] != 200:
        fail("%d index-0 nodes for 200 points" % counts[0])
    if infinite != 1:
        fail("%d nodes with value +inf after the round trip (the maximum at infinity must "
             "survive the file)" % infinite)
    if chi != 1:
        fail("n0 - n1 + n2 - n3 = %d != 1" % chi)
    print("PASS")


if __name__ == "__main__":
    main()
