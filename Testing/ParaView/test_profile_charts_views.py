#!/usr/bin/env python3
"""The charts Flow Reconstruction's profiles open in, rendered: port
3 (Topology Profile) shown as Apply does it (ShowInPreferredView), port 1
(Profile) as a user asks for it (a Line Chart View (log), then its eye: Apply
opens no chart for it), and saved as PNG files. The pictures must show the data
and the t_r marks where t_r is: in the profile, a horizontal line whose height
follows t_r on the chart's scale (linear by default, logarithmic with the
view's Left Axis Log Scale); in the topology profile, a vertical line whose
abscissa follows t_r. Marks are found by their series colour, as lines spanning
a third of the picture (the legend's samples are shorter).

Run (needs X): pvpython --force-offscreen-rendering test_profile_charts_views.py PLUGIN WORKDIR
"""

import math
import os
import sys

import numpy as np
from paraview import simple
from paraview.modules.vtkRemotingViews import vtkSMParaViewPipelineControllerWithRendering

from flowrecon_testing.checks import check, failures, finish
from flowrecon_testing.paraview_pipeline import torus_profiles

PLUGIN, WORK = sys.argv[1:3]
SIZE = [800, 600]


def picture(view, name):
    """The view saved as WORK/name.png, as an (height, width, 3) array, top row first."""
    path = os.path.join(WORK, name + ".png")
    simple.SaveScreenshot(path, view, ImageResolution=SIZE,
                          OverrideColorPalette="WhiteBackground")
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    rgb = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3].astype(int)
    return rgb.reshape(h, w, 3)[::-1]


def series_colour(rep, name):
    values = list(rep.SeriesColor)
    k = values.index(name)
    return np.array([float(v) * 255 for v in values[k + 1:k + 4]])


def mark_line(rgb, colour, axis):
    """Centre and thickness (pixels) of the line of `colour` spanning a third of
    the picture: axis 1 a horizontal line (a row index), 0 a vertical one."""
    near = np.linalg.norm(rgb - colour, axis=2) < 60
    counts = near.sum(axis=axis)
    long = np.nonzero(counts > rgb.shape[axis] / 3)[0]
    if len(long) == 0:
        return None, 0
    return long.mean(), long.max() - long.min() + 1


def drawn(rgb):
    background = np.all(rgb == rgb[0, 0], axis=2)
    return int((~background).sum())


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    recon = torus_profiles(globals(), WORK, 4.0)[1]

    controller = vtkSMParaViewPipelineControllerWithRendering()
    views = {3: controller.ShowInPreferredView(recon.SMProxy, 3, None),
             1: simple.CreateView("FlowReconLogChartView").SMProxy}
    controller.Show(recon.SMProxy, 1, views[1])
    names = {k: v.GetXMLName() if v else None for k, v in views.items()}
    print("views:", names, flush=True)
    if not check(names == {1: "FlowReconLogChartView", 3: "FlowReconTopologyChartView"},
                 "ports 1 and 3 open in %s, expected FlowReconLogChartView and "
                 "FlowReconTopologyChartView"
                 % names):
        return
    pview, tview = (simple.servermanager._getPyProxy(views[k]) for k in (1, 3))
    check(pview.LeftAxisLogScale == 1 and tview.LeftAxisLogScale == 0,
          "the profile's chart opens with Left Axis Log Scale %d, the topology's with %d" % (
              pview.LeftAxisLogScale, tview.LeftAxisLogScale))
    prep = simple.GetDisplayProperties(simple.OutputPort(recon, 1), pview)
    trep = simple.GetDisplayProperties(simple.OutputPort(recon, 3), tview)
    check(prep.GetXMLName() == "ReconstructionProfileRepresentation" and
          trep.GetXMLName() == "TopologyProfileRepresentation",
          "the charts use %s and %s" % (prep.GetXMLName(), trep.GetXMLName()))
    pcolour, tcolour = series_colour(prep, "t_r"), series_colour(trep, "t_r")
    priority = recon.GetDataInformation(1).GetRowDataInformation().GetArrayInformation(
        "Priority").GetComponentRange(0)
    # The marks must stay inside the data's range, so that the axes do not move.
    trs = (1.5, 2.0, 3.0)
    check(priority[0] <= min(trs) and max(trs) <= priority[1],
          "the priorities %s do not span t_r %s" % (priority, trs))

    # The topology steps start at t_r / 1.25, which moves the automatic range of
    # the bottom axis with t_r: fix it to measure where the mark is.
    tview.BottomAxisUseCustomRange = 1
    tview.BottomAxisRangeMinimum, tview.BottomAxisRangeMaximum = 1.0, 4.0
    rows = {"linear": {}, "log": {}}
    columns = {}
    for tr in trs:
        recon.ReconstructionThreshold = tr
        for scale in ("linear", "log"):
            pview.LeftAxisLogScale = int(scale == "log")
            rgb = picture(pview, "profile_%s_%g" % (scale, tr))
            if tr == 2.0:
                check(drawn(rgb) > 5000, "the %s profile picture is (nearly) empty" % scale)
            rows[scale][tr], thickness = mark_line(rgb, pcolour, 1)
            check(rows[scale][tr] is not None and thickness <= 6,
                  "profile (%s), t_r %g: no horizontal t_r line (thickness %d)" % (
                      scale, tr, thickness))
        rgb = picture(tview, "topology_%g" % tr)
        if tr == 2.0:
            check(drawn(rgb) > 5000, "the topology picture is (nearly) empty")
        columns[tr], thickness = mark_line(rgb, tcolour, 0)
        check(columns[tr] is not None and thickness <= 6,
              "topology, t_r %g: no vertical t_r mark (thickness %d)" % (tr, thickness))
    print("profile t_r line rows:", rows, "; topology t_r mark columns:", columns, flush=True)
    if failures:
        return
    # Heights on the chart's scale: rows count downwards from the top.
    for scale, f in (("linear", lambda t: t), ("log", math.log)):
        y = rows[scale]
        measured = (y[1.5] - y[2.0]) / (y[2.0] - y[3.0])
        expected = (f(2.0) - f(1.5)) / (f(3.0) - f(2.0))
        check(y[1.5] > y[2.0] > y[3.0] and abs(measured - expected) < 0.06,
              "profile (%s): the t_r line moves by %.3f, expected %.3f of the next move" % (
                  scale, measured, expected))
    x = columns
    measured = (x[3.0] - x[2.0]) / (x[2.0] - x[1.5])
    check(x[1.5] < x[2.0] < x[3.0] and abs(measured - 2.0) < 0.1,
          "topology: the t_r mark moves by %.3f, expected 2 times the previous move" % measured)


main()
finish()
