#!/usr/bin/env python3
"""What a user sees of Flow Complex Simplification beside Flow Complex, rendered
(300 torus points, t_p 1.1, each filter shown as Apply does it):

- drawn: the critical points (vertex cells) and Gabriel edges (lines) that each
  display's mapper draws, read from the mapper's input and its block visibility
  after a render. Flow Complex draws every critical point and edge; the
  simplification exactly the nodes whose Cancelled is 0 and the edges whose
  Cancelled is 0, worked out from its complete blocks, and fewer than Flow
  Complex (t_p 1.1 cancels pairs on this cloud);
- on screen: the critical points hardware selection finds over the whole view
  are survivors in the simplification's picture, and include cancelled ones in
  Flow Complex's;
- downstream: Flow Reconstruction at t_r 2 gives the same cells, arrays and
  Betti numbers with and without the blocks the simplification adds for its
  display (removed by Extract Block), and the Betti numbers and cell count of
  `flowrecon reconstruct CLOUD --tp 1.1 --tr 2 --exact` (the exact cells, as the
  filter draws them).

The pictures are written to WORKDIR/flow_complex.png and simplification.png.

Run (needs X): pvpython --force-offscreen-rendering test_simplification_display.py PLUGIN FLOWRECON WORKDIR
"""

import os
import sys

import generate_clouds as gen
import numpy as np
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMParaViewPipelineControllerWithRendering
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl
from flowrecon_testing.checks import check, finish
from flowrecon_testing.run import printed_betti, read_grid, run

PLUGIN, FLOWRECON, WORK = sys.argv[1:4]
TP, TR = 1.1, 2.0
SIZE = [800, 800]
COMPLETE = ["CriticalPoints", "HasseDiagram", "StableManifolds", "UnstableManifolds",
            "GabrielEdges", "PersistencePairs"]


def blocks(mb):
    return {mb.GetMetaData(i).Get(mb.NAME()): mb.GetBlock(i) for i in range(mb.GetNumberOfBlocks())}


def array(attributes, name):
    a = attributes.GetArray(name)
    return None if a is None else vtk_to_numpy(a)


def expected(simplified):
    """From the complete blocks: the NodeIds of the critical points with a vertex
    (finite value: the maximum at infinity has none) and of those with Cancelled 0;
    the number of Gabriel edges and of those with Cancelled 0."""
    out = blocks(simplified)
    cp, ge = out["CriticalPoints"].GetPointData(), out["GabrielEdges"].GetCellData()
    node, cancelled = array(cp, "NodeId"), array(cp, "Cancelled")
    drawn = np.isfinite(array(cp, "CriticalValue"))
    edges = array(ge, "Cancelled")
    return (sorted(node[drawn]), sorted(node[drawn & (cancelled == 0)]),
            len(edges), int((edges == 0).sum()), set(node[cancelled == 1]))


def drawn(display):
    """(sorted NodeIds of the vertices, number of lines) the display's mapper draws:
    the leaves of its input that its block visibility shows (a block without a
    visibility of its own has its parent's; the root is shown by default)."""
    mapper = display.GetClientSideObject().GetActiveRepresentation().GetActor().GetMapper()
    attributes = mapper.GetCompositeDataDisplayAttributes()
    nodes, lines = [], 0

    def walk(data, visible):
        nonlocal lines
        if attributes.HasBlockVisibility(data):
            visible = attributes.GetBlockVisibility(data)
        if data.IsA("vtkMultiBlockDataSet"):
            for i in range(data.GetNumberOfBlocks()):
                if data.GetBlock(i) is not None:
                    walk(data.GetBlock(i), visible)
        elif visible:
            lines += data.GetNumberOfLines()
            if data.GetNumberOfVerts():
                ids = vtk_to_numpy(data.GetVerts().GetConnectivityArray())
                node = array(data.GetPointData(), "NodeId")
                check(node is not None, "a drawn block of vertices has no NodeId")
                nodes.extend([] if node is None else node[ids].tolist())

    walk(mapper.GetInputDataObject(0, 0), True)
    return sorted(nodes), lines


def on_screen(source, view):
    """The NodeIds of the critical points hardware selection finds in the whole view."""
    simple.SetActiveView(view)
    simple.SetActiveSource(source)
    simple.SelectSurfacePoints(Rectangle=[0, 0] + SIZE, View=view)
    selected = servermanager.Fetch(simple.ExtractSelection(Input=source))
    simple.ClearSelection(source)
    nodes = set()
    it = selected.NewIterator()
    it.InitTraversal()
    while not it.IsDoneWithTraversal():
        node = array(it.GetCurrentDataObject().GetPointData(), "NodeId")
        nodes |= set() if node is None else set(node.tolist())
        it.GoToNextItem()
    return nodes


def show(source, name):
    """source shown as Apply shows it in a new render view, rendered and saved."""
    view = simple.CreateRenderView(ViewSize=SIZE)
    vtkSMParaViewPipelineControllerWithRendering().ShowInPreferredView(
        source.SMProxy, 0, view.SMProxy)
    display = simple.GetDisplayProperties(source, view)
    simple.ResetCamera(view)
    simple.SaveScreenshot(os.path.join(WORK, name + ".png"), view, ImageResolution=SIZE)
    return view, display


def displays(fc, simp):
    all_nodes, survivors, edges, surviving_edges, cancelled = expected(servermanager.Fetch(simp))
    print("critical points drawn: %d, with Cancelled 0: %d; Gabriel edges %d, with Cancelled "
          "0: %d" % (len(all_nodes), len(survivors), edges, surviving_edges), flush=True)
    check(0 < len(survivors) < len(all_nodes),
          "t_p %g cancels no critical point of this cloud, or all" % TP)
    fc_view, fc_display = show(fc, "flow_complex")
    simp_view, simp_display = show(simp, "simplification")
    fc_drawn, simp_drawn = drawn(fc_display), drawn(simp_display)
    print("Flow Complex draws %d critical points and %d edges; the simplification %d and %d" % (
        len(fc_drawn[0]), fc_drawn[1], len(simp_drawn[0]), simp_drawn[1]), flush=True)
    check(fc_drawn == (all_nodes, edges),
          "Flow Complex draws %d critical points and %d edges, expected all: %d and %d" % (
              len(fc_drawn[0]), fc_drawn[1], len(all_nodes), edges))
    check(simp_drawn == (survivors, surviving_edges),
          "the simplification draws %d critical points and %d edges, expected those with "
          "Cancelled 0: %d and %d" % (len(simp_drawn[0]), simp_drawn[1], len(survivors),
                                      surviving_edges))
    fc_seen, simp_seen = on_screen(fc, fc_view), on_screen(simp, simp_view)
    print("on screen: Flow Complex %d critical points (%d cancelled), the simplification %d "
          "(%d cancelled)" % (len(fc_seen), len(fc_seen & cancelled), len(simp_seen),
                              len(simp_seen & cancelled)), flush=True)
    check(fc_seen & cancelled, "no cancelled critical point on Flow Complex's screen")
    check(simp_seen and simp_seen <= set(survivors),
          "the simplification's screen shows %d cancelled critical points (%d seen)" % (
              len(simp_seen & cancelled), len(simp_seen)))


def reconstruction(source):
    recon = FlowReconstruction(  # noqa: F821 (defined by LoadPlugin)
        Input=source, AutomaticReconstructionThreshold=0, ReconstructionThreshold=TR,
        Geometry="Exact stable manifolds")
    return servermanager.Fetch(recon)


def arrays(attributes):
    """{name: values} of every array, strings included."""
    values = {}
    for k in range(attributes.GetNumberOfArrays()):
        a = attributes.GetAbstractArray(k)
        values[a.GetName()] = (vtk_to_numpy(a).tolist() if a.IsA("vtkDataArray") else
                               [a.GetValue(i) for i in range(a.GetNumberOfValues())])
    return values


def downstream(xyz, simp):
    with_blocks = reconstruction(simp)
    without = reconstruction(simple.ExtractBlock(Input=simp, Selectors=[
        "/Root/" + name for name in COMPLETE]))
    betti = vtk_to_numpy(with_blocks.GetFieldData().GetArray("BettiNumbers")).tolist()
    print("Flow Reconstruction at t_r %g: %d cells, Betti numbers %s" % (
        TR, with_blocks.GetNumberOfCells(), betti), flush=True)
    same = (vtk_to_numpy(with_blocks.GetPoints().GetData()).tolist() ==
            vtk_to_numpy(without.GetPoints().GetData()).tolist() and
            vtk_to_numpy(with_blocks.GetCells().GetData()).tolist() ==
            vtk_to_numpy(without.GetCells().GetData()).tolist() and
            arrays(with_blocks.GetCellData()) == arrays(without.GetCellData()) and
            arrays(with_blocks.GetFieldData()) == arrays(without.GetFieldData()))
    check(same, "Flow Reconstruction differs with and without the surviving blocks")
    out = os.path.join(WORK, "cli.vtu")
    cli_betti = printed_betti(run(FLOWRECON, "reconstruct", xyz, "-o", out, "--tp", str(TP),
                                  "--tr", str(TR), "--exact"))
    cli_cells = read_grid(out).GetNumberOfCells()
    print("flowrecon reconstruct: %d cells, Betti numbers %s" % (cli_cells, cli_betti), flush=True)
    check((with_blocks.GetNumberOfCells(), tuple(betti)) == (cli_cells, cli_betti),
          "Flow Reconstruction: %d cells, Betti numbers %s; flowrecon reconstruct %d, %s" % (
              with_blocks.GetNumberOfCells(), betti, cli_cells, cli_betti))


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    xyz = cl.write_xyz(os.path.join(WORK, "torus.xyz"), gen.torus(300, np.random.default_rng(4)))
    fc = FlowComplex(Input=simple.OpenDataFile(xyz), ComputeStableManifolds=0)  # noqa: F821
    simp = FlowComplexSimplification(  # noqa: F821
        Input=fc, AutomaticPersistenceThreshold=0, PersistenceThreshold=TP)
    displays(fc, simp)
    downstream(xyz, simp)
    finish()


if __name__ == "__main__":
    main()
