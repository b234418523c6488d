"""The displays a user gets in the ParaView Qt GUI by choosing each FlowRecon filter
in the Filters menu and pressing Apply, measured in
the real GUI:

    FLOWRECON_PLUGIN=<build>/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so \\
    FLOWRECON_DATA=<repo>/Data/torus.xyz FLOWRECON_OUT=<prefix> \\
    PYTHONPATH=<repo>/Testing/Python \\
    xvfb-run -a -s "-screen 0 1280x1024x24" paraview --dr --script=test_apply_gui.py

The filters are made by pqFiltersMenuReaction::createFilter (what the menu does) and
applied by a click on the Properties panel's Apply button (pqApplyBehavior), both
reached through ctypes (flowrecon_testing/gui_qt.py). test_default_display.py checks the same defaults
through Python's Show(); this is the GUI's own path:
  * Flow Complex and Flow Complex Simplification: shown in the render view with the
    blocks CriticalPoints and GabrielEdges (the simplification: their surviving
    parts, SurvivingCriticalPoints and SurvivingGabrielEdges), coloured by the
    cell array Index, one legend (Index);
  * Flow Reconstruction: outputs 0 (coloured by Index), 4 and 5 in the render view,
    one legend; 2 (sponsor arrows) and 1 (the reconstruction profile, whose chart
    opens on request) not shown; 3 (the topology profile) in a line chart beside the
    render view, which keeps 0.65 of the layout's width. In the picture of the
    render view, output 5 (the topology text) draws in the upper left corner and
    nowhere else (the pixels that change when it is hidden), and output 4 (the
    under-sampling places, two on this torus) draws magenta spheres (at least 300
    pixels change from magenta when it is hidden, most of those that change), each
    place with its label: the labels drawn in the view, "t_r T: bk +-c" (a line
    per t_r), tell the changes of output 4 (its Threshold, Dimension and Change,
    summed), and turning Warning Label Visibility off changes pixels of the text's
    colour.
Then the sponsor arrows, empty until Sponsor Arrows is turned on (ParaView's
default is off), are turned on and shown (the eye: Show() in the render view): 3D Glyphs
oriented and scaled by Direction, and the picture must have clearly more drawn pixels
than the same lines drawn as a wireframe (the arrows have heads and a width).
Saves <prefix>_layout.png (the GUI's layout after Apply), <prefix>_render.png (the
render view after Apply) and <prefix>_arrows.png.
Prints "test_apply_gui: PASS"/"FAIL" with os.write and os._exit()s.
"""

import os

import numpy as np

from flowrecon_testing.gui_plugin import load_plugin
from flowrecon_testing.gui_qt import Qt, check, run_in_gui, say
from flowrecon_testing.gui_views import expected_changes, label_changes, label_texts

from paraview import servermanager
from paraview.simple import *  # noqa: F401,F403


def legends(view):
    """Titles of the colour legends visible in `view`."""
    titles = []
    for rep in view.Representations:
        if rep.GetXMLName() == "ScalarBarWidgetRepresentation" and rep.Visibility:
            titles.append(rep.Title)
    return sorted(titles)


def colouring(display):
    return tuple(display.ColorArrayName)


def displays_in(view, source):
    """{port: display} of `source` in `view` that are visible."""
    found = {}
    for r in view.Representations:
        prop = r.GetProperty("Input")
        if prop is None or r.GetXMLName() == "ScalarBarWidgetRepresentation":
            continue
        helper = r.SMProxy.GetProperty("Input")
        if helper.GetNumberOfProxies() == 0 or helper.GetProxy(0) != source.SMProxy:
            continue
        if r.Visibility:
            found[helper.GetOutputPortForConnection(0)] = r
    return found


def views_of(source):
    """(view type, port) of every view showing a port of `source`."""
    out = []
    for view in GetViews():
        for port in displays_in(view, source):
            out.append((view.GetXMLName(), port))
    return sorted(out)


def apply_from_menu(qt, accept, input_source, name):
    SetActiveSource(input_source)
    qt.process_events()
    made = qt.create_filter("filters", name)
    check(made, "pqFiltersMenuReaction::createFilter made no %s" % name)
    qt.process_events()
    check(accept and qt.enabled(accept), "the Apply button is not enabled after choosing %s" % name)
    qt.click(accept)
    qt.process_events()
    source = GetActiveSource()
    check(source is not None and source.GetXMLName() == name,
          "after Apply the active source is %s, not %s" % (
              source.GetXMLName() if source else None, name))
    return source


def drawn_mask(view, path):
    """The picture of `view` saved at 800 x 600: True where something is drawn."""
    SaveScreenshot(path, view, ImageResolution=[800, 600],
                   OverrideColorPalette="WhiteBackground")
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    w, h, _ = r.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].reshape(h, w, 3)
    return ~(rgb == rgb[0, 0]).all(axis=2)


def picture(view, path):
    """The render view at its size in the GUI as an (h, w, 3) int array, row 0 at
    the top (a larger picture would scale the text)."""
    SaveScreenshot(path, view, ImageResolution=list(view.ViewSize))
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.util.numpy_support import vtk_to_numpy
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    w, h, _ = r.GetOutput().GetDimensions()
    rgb = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars())[:, :3].reshape(h, w, 3)
    return rgb[::-1].astype(int)


def changed_when_hidden(view, display, path):
    """Pixels that differ clearly between the picture with `display` and without."""
    shown = picture(view, path)
    display.Visibility = 0
    hidden = picture(view, path.replace(".png", "_hidden.png"))
    display.Visibility = 1
    picture(view, path)
    # beyond rounding: translucent geometry nudges other pixels by a few levels
    return shown, (np.abs(shown - hidden) > 24).any(axis=2)


def check_text_and_spheres(view, recon, shown, out):
    text, spheres = shown[5], shown[4]
    say("test_apply_gui: output 4 as %s (radius %s x %s, opacity %s, colour %s); output 5 as %s "
        "at %s" % (spheres.Representation, spheres.GaussianRadius, spheres.SetScaleArray[1],
                   spheres.Opacity, list(spheres.DiffuseColor), text.GetXMLName(),
                   text.WindowLocation))
    check(spheres.Representation == "Point Gaussian" and spheres.SetScaleArray[1] == "Spacing",
          "output 4 is shown as %s scaled by %s" % (spheres.Representation, spheres.SetScaleArray))
    check(text.WindowLocation == "Upper Left Corner", "the text is at %s" % text.WindowLocation)
    # The text: changed pixels, all in the upper left quarter, a few rows from the top.
    rgb, diff = changed_when_hidden(view, text, out + "_render.png")
    rows, cols = np.nonzero(diff)
    say("test_apply_gui: the topology text changes %d pixels, rows %s-%s, columns %s-%s" % (
        len(rows), rows.min() if len(rows) else None, rows.max() if len(rows) else None,
        cols.min() if len(cols) else None, cols.max() if len(cols) else None))
    h, w = diff.shape
    check(len(rows) > 500, "the topology text draws %d pixels" % len(rows))
    check(len(rows) == 0 or (rows.max() < h / 3 and cols.min() < w / 10 and cols.max() < 0.8 * w),
          "the topology text draws outside the upper left corner of the %d x %d view" % (w, h))
    # The spheres: a few hundred magenta pixels at least (red and blue above
    # green; part of them is behind the torus), most of what they change, where
    # the same pixels without them are not (the torus, the background).
    spheres.WarningLabelVisibility = 0  # their text is checked by check_labels
    rgb, diff = changed_when_hidden(view, spheres, out + "_spheres.png")
    spheres.Visibility = 0
    hidden = picture(view, out + "_spheres_hidden.png")
    spheres.Visibility = 1
    spheres.WarningLabelVisibility = 1

    def magenta(pixels):
        return int(((pixels[:, 0] > pixels[:, 1] + 20) & (pixels[:, 2] > pixels[:, 1] + 20)).sum())

    with_spheres, without = magenta(rgb[diff]), magenta(hidden[diff])
    say("test_apply_gui: the spheres change %d pixels, %d magenta (without them: %d)" % (
        int(diff.sum()), with_spheres, without))
    check(with_spheres >= 300, "the spheres draw %d magenta pixels" % with_spheres)
    # the rest is their shading, dark towards their outline
    check(with_spheres >= 0.5 * diff.sum() and without <= 0.1 * diff.sum(),
          "the spheres are not magenta: %d of %d pixels (%d without them)"
          % (with_spheres, diff.sum(), without))


def check_labels(view, spheres, recon, out):
    """The labels drawn tell the changes of output 4 (a label per place, a line per
    t_r: "t_r T: bk +-c"), and they draw text-coloured pixels."""
    drawn = label_texts(view)
    told, expected = label_changes(drawn), expected_changes(servermanager.Fetch(recon, idx=4))
    say("test_apply_gui: labels drawn %s, expected changes %s" % (drawn, expected))
    check(len(drawn) >= 1 and told == expected,
          "the warnings' labels %s tell %s, output 4 holds %s" % (drawn, told, expected))
    shown = picture(view, out + "_labels.png")
    spheres.WarningLabelVisibility = 0
    hidden = picture(view, out + "_labels_hidden.png")
    spheres.WarningLabelVisibility = 1
    picture(view, out + "_labels.png")
    text = np.array([float(c) * 255 for c in spheres.WarningLabelColor])
    changed = (np.abs(shown - hidden) > 24).any(axis=2)
    near_text = (np.abs(shown - text) < 40).all(axis=2) & changed
    say("test_apply_gui: the labels change %d pixels, %d of the text's colour"
        % (int(changed.sum()), int(near_text.sum())))
    check(near_text.sum() >= 100 * len(drawn),
          "the labels draw %d pixels of their colour" % near_text.sum())


def look_along_longest_arrow(view, recon):
    """Parallel projection on the longest sponsor arrow, its sponsor on the left and
    its node on the right, 500 of the 800 pixels long, centred. Returns its length."""
    import numpy as np
    from vtkmodules.util.numpy_support import vtk_to_numpy
    data = servermanager.Fetch(recon, idx=2)
    pts = vtk_to_numpy(data.GetPoints().GetData())
    d = vtk_to_numpy(data.GetPointData().GetArray("Direction"))
    k = int(np.argmax(np.linalg.norm(d, axis=1)))
    a, b = pts[k], pts[k] + d[k]
    length = float(np.linalg.norm(b - a))
    u = (b - a) / length
    v = np.cross(u, [0.0, 0.0, 1.0] if abs(u[2]) < 0.9 else [1.0, 0.0, 0.0])
    v /= np.linalg.norm(v)
    w = np.cross(u, v)  # the screen's right is dop x up = (-w) x v = u
    mid = (a + b) / 2
    view.CameraParallelProjection = 1
    view.CameraFocalPoint = list(mid)
    view.CameraPosition = list(mid + 10 * length * w)
    view.CameraViewUp = list(v)
    view.CameraParallelScale = 0.6 * length  # 1.6 lengths across 800 pixels
    view.OrientationAxesVisibility = 0
    return length


def runs_through_axis(mask, x0, x1, row=300, slack=2):
    """Per column of [x0, x1): the length of the drawn vertical run through the
    axis (`row`, or the drawn pixel nearest to it within `slack`: a one-pixel line
    on the axis may be rasterised a row off), 0 where none is drawn, sorted: the
    arrow's own thickness there, whatever else is in the picture."""
    import numpy as np
    out = []
    for x in range(x0, x1):
        column = mask[:, x]
        near = [r for r in sorted(range(row - slack, row + slack + 1), key=lambda r: abs(r - row))
                if column[r]]
        if not near:
            out.append(0)
            continue
        top = bottom = near[0]
        while top > 0 and column[top - 1]:
            top -= 1
        while bottom + 1 < len(column) and column[bottom + 1]:
            bottom += 1
        out.append(bottom - top + 1)
    return np.sort(out)


def main():
    data = os.environ["FLOWRECON_DATA"]
    out = os.environ.get("FLOWRECON_OUT", "apply_gui")
    load_plugin(globals())
    qt = Qt()
    main_widget = qt.main_widget()
    check(main_widget, "no pqCoreUtilities::MainWidget")
    accept = qt.find(main_widget, "Accept", qt.widgets, "QPushButton")
    check(accept, "the Properties panel has no Apply (Accept) button")

    reader = OpenDataFile(data)
    check(reader.GetXMLName() == "FlowReconPointCloudReader",
          "OpenDataFile chose %s" % reader.GetXMLName())
    view = GetActiveViewOrCreate("RenderView")
    Show(reader, view)
    Render(view)

    fc = simp = None
    for name, prefix in (("FlowComplex", ""), ("FlowComplexSimplification", "Surviving")):
        source = apply_from_menu(qt, accept, fc or reader, name)
        fc, simp = (source, None) if fc is None else (fc, source)
        shown = displays_in(view, source)
        check(sorted(shown) == [0], "%s: ports shown in the render view %s" % (name, sorted(shown)))
        d = shown[0]
        say("test_apply_gui: %s after Apply: colouring %s, blocks %s, legends %s" % (
            name, colouring(d), list(d.BlockSelectors), legends(view)))
        check(colouring(d) == ("CELLS", "Index"), "%s is coloured by %s" % (name, colouring(d)))
        check(list(d.BlockSelectors) == ["/Root/%sCriticalPoints" % prefix,
                                         "/Root/%sGabrielEdges" % prefix],
              "%s shows the blocks %s" % (name, list(d.BlockSelectors)))
        check(legends(view) == ["Index"], "%s: legends %s" % (name, legends(view)))

    recon = apply_from_menu(qt, accept, simp, "FlowReconstruction")
    shown = displays_in(view, recon)
    where = views_of(recon)
    say("test_apply_gui: Flow Reconstruction after Apply: render view ports %s, colouring %s, "
        "legends %s, views %s" % (sorted(shown), colouring(shown[0]) if 0 in shown else None,
                                  legends(view), where))
    check(sorted(shown) == [0, 4, 5],
          "Flow Reconstruction: render view ports %s, expected 0, 4 and 5" % sorted(shown))
    check(colouring(shown[0]) == ("CELLS", "Index"),
          "Flow Reconstruction is coloured by %s" % (colouring(shown[0]),))
    check(legends(view) == ["Index"], "Flow Reconstruction: legends %s" % legends(view))
    check(("FlowReconTopologyChartView", 3) in where,
          "Flow Reconstruction: output 3 is not in a FlowReconTopologyChartView (%s)" % where)
    check(all(p not in (1, 2) for _, p in where),
          "the profile or the sponsor arrows are shown on Apply (%s)" % where)
    check(sorted(v.GetXMLName() for v in GetViews()) == ["FlowReconTopologyChartView", "RenderView"],
          "Apply opened the views %s" % sorted(v.GetXMLName() for v in GetViews()))
    qt.process_events()
    chart = [v for v in GetViews() if v.GetXMLName() == "FlowReconTopologyChartView"][0]
    widths = (view.ViewSize[0], chart.ViewSize[0])
    say("test_apply_gui: widths of the render view and the chart %s" % (widths,))
    check(abs(widths[0] / float(sum(widths)) - 0.65) < 0.03,
          "the render view has %d of the %d pixels' width" % (widths[0], sum(widths)))
    layout = GetLayout(view)
    SaveScreenshot(out + "_layout.png", layout, ImageResolution=[1200, 700])
    check_text_and_spheres(view, recon, shown, out)
    check_labels(view, shown[4], recon, out)

    # The sponsor arrows, one click away, alone in the render view.
    for d in displays_in(view, recon).values():
        d.Visibility = 0
    for src in (reader, fc, simp):
        Hide(src, view)
    check(recon.GetDataInformation(2).GetNumberOfCells() == 0,
          "sponsor arrows made though Sponsor Arrows is off (ParaView's default)")
    recon.SponsorArrows = 1
    recon.UpdatePipeline()
    arrows = Show(OutputPort(recon, 2), view)
    glyphs = (arrows.Representation, arrows.SelectOrientationVectors,
              arrows.SelectScaleArray, arrows.ScaleFactor)
    say("test_apply_gui: sponsor arrows shown as %s" % (glyphs,))
    check(glyphs == ("3D Glyphs", "Direction", "Direction", 1.0),
          "the sponsor arrows are shown as %s" % (glyphs,))
    arrows.SetScalarBarVisibility(view, False)
    # Side view of the longest arrow (pixels 150 to 650 along the row 300): an
    # arrow glyph has a shaft a few pixels thick and, at the node's end, a head
    # (vtkArrowSource: the last 35 %, radius 0.1 of the length = 50 pixels); the
    # plain line is a pixel or two thick all along.
    look_along_longest_arrow(view, recon)
    glyph = drawn_mask(view, out + "_arrows.png")
    arrows.Representation = "Wireframe"
    line = drawn_mask(view, out + "_lines.png")
    arrows.Representation = "3D Glyphs"
    # Medians over the head's widest part (pixels 490-540: 90 to 70 high) and
    # the shaft (250-420: 30 high); arrows that cross the axis only add.
    heads = [int(np.median(runs_through_axis(m, 490, 540))) for m in (glyph, line)]
    shafts = [int(np.median(runs_through_axis(m, 250, 420))) for m in (glyph, line)]
    tips = [int(np.median(runs_through_axis(m, 655, 665))) for m in (glyph, line)]
    say("test_apply_gui: the longest sponsor arrow from the side, median thickness in pixels "
        "(glyph, line): head %s, shaft %s, past the node %s" % (heads, shafts, tips))
    check(heads[0] >= 50 and heads[0] >= 2 * shafts[0] and shafts[0] >= 10,
          "no arrow from sponsor to node: %d pixels thick at the head, %d along the shaft"
          % (heads[0], shafts[0]))
    # The control: the same arrows as plain lines are drawn (a line, not nothing)
    # and thin where the glyph has its head.
    check(1 <= min(heads[1], shafts[1]) and max(heads[1], shafts[1]) <= 4,
          "the plain line is %d/%d pixels thick" % (heads[1], shafts[1]))
    say("test_apply_gui: PASS")


run_in_gui(main, "test_apply_gui")
