"""The FlowRecon plugin inside the ParaView Qt GUI: run with

    FLOWRECON_PLUGIN=<build>/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so \\
    FLOWRECON_DATA=<repo>/Data/two_hemispheres.xyz FLOWRECON_OUT=<prefix> \\
    PYTHONPATH=<repo>/Testing/Python \\
    xvfb-run -a -s "-screen 0 1280x1024x24" paraview --dr --script=gui_pipeline.py

The GUI's own Python loads the plugin (unless PV_PLUGIN_PATH already did), reads the
cloud with the CSV reader, applies Flow Complex -> Flow Complex Simplification ->
Flow Reconstruction with their defaults, checks the outputs (non-empty, block and array
names, profile columns), colours the reconstruction by Threshold in the GUI's render
view and saves <prefix>.png. Prints (to the terminal, with os.write: print() would go to
the Output Messages window) "gui_pipeline: PASS" and os._exit(0)s, or the traceback and
os._exit(1): the GUI has no quit from Python. FLOWRECON_EXIT=0 keeps
the GUI open (interactive use).
"""

import os

from flowrecon_testing.gui_plugin import load_plugin
from flowrecon_testing.gui_qt import check, run_in_gui, say

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403


def block_names(proxy):
    info = proxy.GetDataInformation().DataInformation
    hierarchy = info.GetHierarchy() if hasattr(info, "GetHierarchy") else None
    names = set()
    if hierarchy is not None:
        from vtkmodules.vtkCommonDataModel import vtkDataAssembly  # noqa: F401
        for node in hierarchy.GetChildNodes(0, False):
            names.add(hierarchy.GetAttributeOrDefault(node, "label", ""))
    return names


def main():
    data = os.environ["FLOWRECON_DATA"]
    out = os.environ.get("FLOWRECON_OUT", "gui_pipeline")
    ns = globals()
    load_plugin(ns, ("FlowComplex", "FlowComplexSimplification", "FlowReconstruction"))

    reader = CSVReader(registrationName="two_hemispheres.xyz", FileName=[data])
    reader.HaveHeaders = 0
    reader.FieldDelimiterCharacters = " "
    reader.MergeConsecutiveDelimiters = 1
    points = TableToPoints(registrationName="Points", Input=reader,
                           XColumn="Field 0", YColumn="Field 1", ZColumn="Field 2")
    fc = ns["FlowComplex"](registrationName="FlowComplex", Input=points)
    simp = ns["FlowComplexSimplification"](registrationName="Simplification", Input=fc)
    recon = ns["FlowReconstruction"](registrationName="Reconstruction", Input=simp)
    check(simp.AutomaticPersistenceThreshold == 1,
          "default t_p not automatic: %s" % simp.AutomaticPersistenceThreshold)
    check(recon.AutomaticReconstructionThreshold == 1,
          "default t_r not automatic: %s" % recon.AutomaticReconstructionThreshold)

    points.UpdatePipeline()
    n = points.GetDataInformation().GetNumberOfPoints()
    check(n == 3000, "%d input points, expected 3000" % n)

    # Flow Complex / Simplification: multiblocks with named blocks and arrays
    fc.UpdatePipeline()
    simp.UpdatePipeline()
    fc_blocks = block_names(fc)
    simp_blocks = block_names(simp)
    say("gui_pipeline: FlowComplex blocks %s" % sorted(fc_blocks))
    say("gui_pipeline: Simplification blocks %s" % sorted(simp_blocks))
    expected = {"CriticalPoints", "HasseDiagram", "StableManifolds", "UnstableManifolds"}
    check(expected <= fc_blocks, "FlowComplex blocks %s" % sorted(fc_blocks))
    check(expected | {"PersistencePairs"} <= simp_blocks,
          "Simplification blocks %s" % sorted(simp_blocks))
    for proxy, where, arrays in (
            (fc, "PointData", ("NodeId", "Index", "CriticalValue")),
            (fc, "CellData", ("Multiplicity", "Ratio")),
            (simp, "PointData", ("Cancelled",)),
            (simp, "CellData", ("Owner",))):
        keys = getattr(proxy, where).keys()
        for a in arrays:
            check(a in keys, "%s %s has no %s (has %s)" % (proxy.GetXMLName(), where, a, keys))
    check(fc.GetDataInformation().GetNumberOfCells() > 0, "empty flow complex")

    # Flow Reconstruction: port 0 unstructured grid, port 1 profile table, port 2 arrows
    recon.UpdatePipeline()
    info = recon.GetDataInformation()
    say("gui_pipeline: reconstruction %s, %d points, %d cells" % (
        info.GetDataSetTypeAsString(), info.GetNumberOfPoints(), info.GetNumberOfCells()))
    check(info.GetDataSetTypeAsString() == "vtkUnstructuredGrid", "reconstruction type")
    check(info.GetNumberOfCells() > 1000, "reconstruction has %d cells" % info.GetNumberOfCells())
    # the compact geometry (the default): Delaunay simplices on the samples only
    keys = recon.CellData.keys()
    for a in ("Threshold", "NodeId", "Index", "Claims"):
        check(a in keys, "reconstruction has no cell array %s (has %s)" % (a, keys))
    samples = servermanager.Fetch(recon).GetNumberOfPoints()
    check(info.GetNumberOfPoints() == samples and info.GetNumberOfCells() <= 4 * samples,
          "compact reconstruction: %d points, %d cells" % (samples, info.GetNumberOfCells()))
    threshold = recon.CellData["Threshold"].GetRange()
    t_r = servermanager.Fetch(recon).GetFieldData().GetArray("ReconstructionThreshold").GetValue(0)
    check(1.5 < t_r <= 5 and threshold[1] < t_r, "Threshold range %s at t_r %s" % (threshold, t_r))
    profile = servermanager.Fetch(recon, idx=1)
    columns = [profile.GetColumnName(i) for i in range(profile.GetNumberOfColumns())]
    for c in ("Step", "NodeId", "Index", "Priority", "Threshold"):
        check(c in columns, "profile has no column %s (has %s)" % (c, columns))
    check(profile.GetNumberOfRows() > 1000, "profile has %d rows" % profile.GetNumberOfRows())
    # The sponsor arrows are made on request only: at most one line per step
    # up to t_r (profile rows below t_r).
    arrows = OutputPort(recon, 2)
    check(arrows.GetDataInformation().GetNumberOfCells() == 0,
          "sponsor arrows made though Sponsor Arrows is off (ParaView's default)")
    recon.SponsorArrows = 1
    recon.UpdatePipeline()
    steps = sum(1 for i in range(profile.GetNumberOfRows())
                if profile.GetColumnByName("Threshold").GetValue(i) <= t_r)
    lines = arrows.GetDataInformation().GetNumberOfCells()
    say("gui_pipeline: %d sponsor arrows on request, %d profile steps up to t_r" % (lines, steps))
    check(0 < lines <= steps, "%d sponsor arrows for %d steps up to t_r" % (lines, steps))

    # render in the GUI's view, coloured by Threshold (every cell's is below t_r)
    view = GetActiveViewOrCreate("RenderView")
    display = Show(recon, view)
    ColorBy(display, ("CELLS", "Threshold"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    lut = GetColorTransferFunction("Threshold")
    rng = lut.RGBPoints[0], lut.RGBPoints[-4]
    check(0.0 <= rng[0] < rng[1] < t_r, "Threshold colour range %s at t_r %s" % (rng, t_r))
    view.CameraPosition = [1.5, -3.5, 2.6]
    view.CameraFocalPoint = [0.0, 0.0, 0.4]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.ResetCamera()
    Render(view)
    SaveScreenshot(out + ".png", view, ImageResolution=[800, 600])
    check(os.path.getsize(out + ".png") > 10000, "screenshot %s too small" % (out + ".png"))
    say("gui_pipeline: wrote %s.png (Threshold %.3g..%.3g)" % (out, rng[0], rng[1]))
    say("gui_pipeline: PASS")


run_in_gui(main, "gui_pipeline")
