#!/usr/bin/env python3
"""The views the Persistence Diagram filter opens, as ParaView's Apply
does it (ShowInPreferredView): port 0 in a chart of its own
(FlowReconDiagramChartView, birth and death axes) with the pairs as dots in the
colours of their dimension and the diagonal, and in a render view, in 2D, drawing
the pairs, the diagonal and the t_p line; port 1 in a line chart with logarithmic, titled
axes (FlowReconPersistenceChartView) plotted against Ratio from the curve's field
data, with the curves and the t_p mark. Both are rendered to PNG files, and the
pictures must show the data: the diagram's pixels in the colours of its PairType
values, the chart's lines and not the chart's red warning of a value <= 0 on a log
axis (which the same chart from the row data, with its zeros, shows).

Run (needs X): pvpython --force-offscreen-rendering test_persistence_diagram_views.py PLUGIN WORKDIR
"""

import os
import sys

import generate_clouds as gen
import numpy as np
from paraview import simple
from paraview.modules.vtkRemotingViews import vtkSMParaViewPipelineControllerWithRendering

from flowrecon_testing import clouds as cl
from flowrecon_testing.checks import check, finish

PLUGIN, WORK = sys.argv[1:3]


def picture(view, path):
    simple.SaveScreenshot(path, view, ImageResolution=[800, 600],
                          OverrideColorPalette="WhiteBackground")
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    rgb = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3].astype(int)
    return rgb


def check_diagram_chart(pd, view):
    """The diagram's chart: titled axes, the dots of each dimension in their
    colours (at least a few pixels each for H1 and H2, whose pairs exist on a
    torus), the grey diagonal along y = x."""
    rep = simple.GetDisplayProperties(pd, view)
    settings = (rep.GetXMLName(), rep.AttributeType, rep.XArrayName,
                sorted(rep.SeriesVisibility), view.BottomAxisTitle, view.LeftAxisTitle)
    print("diagram chart:", settings, flush=True)
    check(settings == ("PersistenceDiagramChartRepresentation", "Field Data", "Birth",
                       ["Diagonal", "H0", "H1", "H2", "t_p"], "birth", "death"),
          "the diagram's chart is %s" % (settings,))
    colours = list(rep.SeriesColor)
    h, w = 600, 800
    rgb = picture(view, os.path.join(WORK, "diagram_chart.png")).reshape(h, w, 3)[::-1]
    counts = {}
    for name in ("H1", "H2", "Diagonal"):
        k = colours.index(name)
        c = np.array([float(v) * 255 for v in colours[k + 1:k + 4]])
        counts[name] = int((np.linalg.norm(rgb - c, axis=2) < 40).sum())
    print("diagram chart pixels by series colour:", counts, flush=True)
    check(counts["H1"] >= 20 and counts["H2"] >= 20 and counts["Diagonal"] >= 300,
          "the diagram's chart draws %s pixels of the H1, H2 and diagonal colours" % counts)
    # The diagonal goes up to the right: its pixels' rows fall as columns grow.
    k = colours.index("Diagonal")
    c = np.array([float(v) * 255 for v in colours[k + 1:k + 4]])
    rows, cols = np.nonzero(np.linalg.norm(rgb - c, axis=2) < 40)
    if len(cols) > 10:
        slope = np.polyfit(cols, rows, 1)[0]
        check(slope < -0.3, "the diagonal's pixels slope by %.2f (rows per column)" % slope)


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    rng = np.random.default_rng(11)
    xyz = os.path.join(WORK, "torus.xyz")
    cl.write_xyz(xyz, gen.torus(400, rng))
    reader = simple.OpenDataFile(xyz)
    fc = FlowComplex(Input=reader, ComputeStableManifolds=0)  # noqa: F821
    pd = PersistenceDiagram(Input=fc)  # noqa: F821
    pd.UpdatePipeline()

    controller = vtkSMParaViewPipelineControllerWithRendering()
    # As Apply does in an empty layout frame: no view given, the preferred one is made.
    diagram_view = controller.ShowInPreferredView(pd.SMProxy, 0, None)
    curve_view = controller.ShowInPreferredView(pd.SMProxy, 1, None)
    names = [v.GetXMLName() if v else None for v in (diagram_view, curve_view)]
    print("views:", names, flush=True)
    if not check(names == ["FlowReconDiagramChartView", "FlowReconPersistenceChartView"],
                 "ports 0 and 1 open in %s, expected FlowReconDiagramChartView, "
                 "FlowReconPersistenceChartView" % names):
        return
    check_diagram_chart(pd, simple.servermanager._getPyProxy(diagram_view))
    # The grid in a render view, as before: each pair a segment.
    diagram_view = simple.CreateView("RenderView").SMProxy
    controller.Show(pd.SMProxy, 0, diagram_view)
    # Port 1 in an existing render view still opens its own chart.
    check(controller.ShowInPreferredView(pd.SMProxy, 1, diagram_view).GetXMLName()
          == "FlowReconPersistenceChartView",
          "port 1 shown from a render view does not open a chart")

    dview = simple.servermanager._getPyProxy(diagram_view)
    cview = simple.servermanager._getPyProxy(curve_view)

    # The diagram: flat, so the GUI's automatic mode picks 2D; do the same here.
    info = pd.GetDataInformation(0)
    bounds = info.GetBounds()
    check(bounds[4] == bounds[5] == 0.0, "the diagram is not in the plane z = 0: %s" % (bounds,))
    drep = simple.GetDisplayProperties(pd, dview)
    simple.ColorBy(drep, ("CELLS", "PairType"))
    drep.LineWidth = 2.0
    dview.InteractionMode = "2D"
    dview.OrientationAxesVisibility = 0
    simple.ResetCamera(dview)
    rgb = picture(dview, os.path.join(WORK, "diagram.png"))
    background = np.all(rgb == rgb[0], axis=1)
    colours = {tuple(c) for c in rgb[~background][:20000]}
    print("diagram: %d non-background pixels, %d colours" % ((~background).sum(), len(colours)),
          flush=True)
    check((~background).sum() > 2000 and len(colours) >= 4,
          "the diagram picture is (nearly) empty or single-coloured")

    # The curve: against Ratio, with the t_p mark.
    crep = simple.GetDisplayProperties(simple.OutputPort(pd, 1), cview)
    print("chart: UseIndexForXAxis %s, XArrayName %s, visible %s" % (
        crep.UseIndexForXAxis, crep.XArrayName, crep.SeriesVisibility), flush=True)
    check(crep.UseIndexForXAxis == 0 and crep.XArrayName == "Ratio",
          "the curve is not plotted against Ratio by default")
    axes = (cview.BottomAxisLogScale, cview.LeftAxisLogScale, cview.BottomAxisTitle,
            cview.LeftAxisTitle, crep.AttributeType)
    print("chart axes:", axes, flush=True)
    check(axes == (1, 1, "death / birth", "pairs with a larger ratio", "Field Data"),
          "the curve's chart is %s: expected log axes with titles, from the field data" % (axes,))
    # Python lists the names of the visible series.
    check(sorted(crep.SeriesVisibility) == ["PairsH1", "PairsH2", "t_p"],
          "the chart shows %s, expected PairsH1, PairsH2, t_p" % list(crep.SeriesVisibility))
    rgb = picture(cview, os.path.join(WORK, "curve.png"))
    background = np.all(rgb == rgb[0], axis=1)
    check((~background).sum() > 2000, "the curve picture is (nearly) empty")
    # A series with a value <= 0 on a log axis makes the chart cover itself with a
    # red warning box instead of the curve.
    red = (rgb[:, 0] > 150) & (rgb[:, 1] < 90) & (rgb[:, 2] < 90)
    check(red.sum() < 2000, "the curve's chart shows %d red pixels: its log-axis warning"
          % red.sum())
    # The control: the same chart from the row data (with zeros) shows it.
    crep.AttributeType = "Row Data"
    warned = picture(cview, os.path.join(WORK, "curve_row_data.png"))
    crep.AttributeType = "Field Data"
    red = (warned[:, 0] > 150) & (warned[:, 1] < 90) & (warned[:, 2] < 90)
    check(red.sum() >= 2000, "the control (row data on log axes) shows no warning: %d red "
          "pixels; the check above cannot see it" % red.sum())


main()
finish()
