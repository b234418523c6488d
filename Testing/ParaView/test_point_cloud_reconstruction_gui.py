"""What one click on Reconstruct Point Cloud opens in the ParaView Qt GUI, measured in
the real GUI:

    FLOWRECON_PLUGIN=<build>/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so \\
    FLOWRECON_DATA=<repo>/Data/torus.xyz FLOWRECON_OUT=<prefix> \\
    PYTHONPATH=<repo>/Testing/Python \\
    xvfb-run -a -s "-screen 0 1280x1024x24" paraview --dr --script=test_point_cloud_reconstruction_gui.py

The cloud is opened and shown, then Reconstruct Point Cloud is chosen in the Filters
menu (pqFiltersMenuReaction::createFilter) and applied with the Apply button
(flowrecon_testing/gui_qt.py). After Apply:
  * three views, in one layout: the render view with outputs 0 (coloured by Index,
    one legend), 4 (magenta spheres) and 5 (the text), nothing else of the filter;
    output 2 (the persistence diagram) in a Line Chart View (diagram) and output 3
    (the topology profile) in a Line Chart View (topology); output 1 (the profile)
    in no view; the reader hidden;
  * the render view keeps 0.65 of the layout's width (+-0.03), the two charts share
    the rest, one above the other, at the same abscissa and each about half the
    height;
  * the Betti numbers of the Reconstruction are the torus's (1 2 1) and the text
    drawn is its Topology Text; the diagram's chart shows H1 and H2 pairs;
  * the labels the render view draws ("t_r T: bk +-c", a line per t_r, one label
    per place) tell the changes of output 4;
  * a second Apply (a property changed) opens no other view.
Saves <prefix>_layout.png. Prints "test_point_cloud_reconstruction_gui: PASS"/"FAIL"
with os.write and os._exit()s.
"""

import os

from flowrecon_testing.gui_plugin import load_plugin
from flowrecon_testing.gui_qt import Qt, check, run_in_gui, say
from flowrecon_testing.gui_views import (
    expected_changes, label_changes, label_texts, mark_modified)

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403

NAME = "test_point_cloud_reconstruction_gui"


def displays(source):
    """{(view type, port): display} of the visible displays of `source`."""
    found = {}
    for view in GetViews():
        for r in view.Representations:
            helper = r.SMProxy.GetProperty("Input")
            if helper is None or helper.GetNumberOfProxies() == 0:
                continue
            if helper.GetProxy(0) == source.SMProxy and r.Visibility:
                found[(view.GetXMLName(), helper.GetOutputPortForConnection(0))] = r
    return found


def main():
    data = os.environ["FLOWRECON_DATA"]
    out = os.environ.get("FLOWRECON_OUT", NAME)
    load_plugin(globals(), names=("ReconstructPointCloud",))
    qt = Qt()
    accept = qt.find(qt.main_widget(), "Accept", qt.widgets, "QPushButton")
    check(accept, "the Properties panel has no Apply (Accept) button")
    reader = OpenDataFile(data)
    view = GetActiveViewOrCreate("RenderView")
    Show(reader, view)
    Render(view)
    SetActiveSource(reader)
    qt.process_events()
    check(qt.create_filter("filters", "PointCloudReconstruction"),
          "the Filters menu made no Reconstruct Point Cloud")
    qt.process_events()
    check(qt.enabled(accept), "Apply is not enabled after choosing Reconstruct Point Cloud")
    qt.click(accept)
    qt.process_events()
    one = GetActiveSource()
    check(one is not None and one.GetXMLName() == "PointCloudReconstruction",
          "the active source after Apply is %s" % (one.GetXMLName() if one else None))

    shown = displays(one)
    say("%s: after Apply, shown %s; views %s" % (NAME, sorted(shown), sorted(
        v.GetXMLName() for v in GetViews())))
    check(sorted(shown) == [("FlowReconDiagramChartView", 2), ("FlowReconTopologyChartView", 3),
                            ("RenderView", 0), ("RenderView", 4), ("RenderView", 5)],
          "Apply showed %s" % sorted(shown))
    check(sorted(v.GetXMLName() for v in GetViews()) ==
          ["FlowReconDiagramChartView", "FlowReconTopologyChartView", "RenderView"],
          "Apply opened the views %s" % sorted(v.GetXMLName() for v in GetViews()))
    check(not displays(reader), "the cloud is still shown")
    check(tuple(shown[("RenderView", 0)].ColorArrayName) == ("CELLS", "Index"),
          "the reconstruction is coloured by %s" % (tuple(shown[("RenderView", 0)].ColorArrayName),))

    # The layout: the render view large, the charts stacked beside it.
    qt.process_events()
    views = {v.GetXMLName(): v for v in GetViews()}
    layouts = {GetLayout(v).GetGlobalID() for v in views.values()}
    check(len(layouts) == 1, "the views are in %d layouts" % len(layouts))
    def place(view, name):
        p = view.SMProxy.GetProperty(name)
        return tuple(int(p.GetElement(k)) for k in range(2))

    geometry = {name: (place(v, "ViewPosition"), place(v, "ViewSize")) for name, v in views.items()}
    say("%s: view positions and sizes %s" % (NAME, geometry))
    (rx, ry), (rw, rh) = geometry["RenderView"]
    (dx, dy), (dw, dh) = geometry["FlowReconDiagramChartView"]
    (tx, ty), (tw, th) = geometry["FlowReconTopologyChartView"]
    check(abs(rw / float(rw + dw) - 0.65) < 0.03,
          "the render view has %d of %d pixels' width" % (rw, rw + dw))
    # (each frame has its own title bar: the two charts are a bar shorter)
    check(dx == tx and dx > rx and dw == tw and abs(dh - th) <= 2 and dy != ty and
          0.8 * rh <= dh + th <= rh,
          "the charts are not stacked beside the render view: %s" % geometry)

    # What they show.
    grid = servermanager.Fetch(one, idx=0)
    betti = [int(grid.GetFieldData().GetArray("BettiNumbers").GetValue(k)) for k in range(3)]
    text = servermanager.Fetch(one, idx=5).GetValueByName(0, "Topology").ToString()
    say("%s: Betti numbers %s; text %r" % (NAME, betti, text))
    check(betti == [1, 2, 1], "Betti numbers %s, the torus's are 1 2 1" % betti)
    check(text.startswith("Betti numbers 1 2 1") and "(auto)" in text, "the text is %r" % text)
    diagram = shown[("FlowReconDiagramChartView", 2)]
    visible = [diagram.SeriesVisibility[k] for k in range(len(diagram.SeriesVisibility))]
    check("H1" in visible and "H2" in visible, "the diagram's chart shows %s" % visible)
    Render(views["RenderView"])
    warnings = servermanager.Fetch(one, idx=4)
    drawn = label_texts(views["RenderView"])
    say("%s: %d under-sampling points, labels drawn %s" % (NAME, warnings.GetNumberOfPoints(), drawn))
    told = label_changes(drawn)
    expected = expected_changes(warnings)
    check(len(drawn) >= 1 and told == expected,
          "the labels drawn %s tell %s, output 4 holds %s" % (drawn, told, expected))
    SaveScreenshot(out + "_layout.png", GetLayout(view), ImageResolution=[1600, 900])

    # A second Apply opens nothing more.
    one.UnderSamplingWindow = 1.2
    qt.process_events()
    mark_modified(qt, one)
    check(qt.enabled(accept), "Apply is not enabled after a change")
    qt.click(accept)
    qt.process_events()
    again = sorted(v.GetXMLName() for v in GetViews())
    check(again == ["FlowReconDiagramChartView", "FlowReconTopologyChartView", "RenderView"],
          "after a second Apply the views are %s" % again)
    say("%s: PASS" % NAME)


run_in_gui(main, NAME)
