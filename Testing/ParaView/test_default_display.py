#!/usr/bin/env python3
"""What a user sees when pressing Apply on each FlowRecon filter in a render view
(readable defaults), with no X server: every output port shown as
Apply does it (ShowInPreferredView, the input hidden, a colour legend for each
scalar-coloured display), then the colouring array and its association, the
colour legends, the blocks shown and the camera after Reset Camera.

- Flow Reconstruction: output 0 coloured by the cell array Index, output 2
  (sponsor arrows) not shown and empty until Sponsor Arrows is on, output 4 (under-sampling points) not coloured,
  Point Gaussian spheres of radius Spacing: one colour legend in the view;
  output 5 (the topology text) left-justified in the upper left corner.
- Flow Complex and Flow Complex Simplification (the plugin's displays
  FlowReconMultiBlockRepresentation and FlowReconSimplificationRepresentation
  and their initialization helper): the blocks CriticalPoints and GabrielEdges
  shown, for the simplification SurvivingCriticalPoints and
  SurvivingGabrielEdges, coloured by the cell array Index, whose colour map is
  categorical with the four names of FlowComplex.xml; one colour legend.
  Shown after a Flow Complex coloured by Index, the simplification keeps it.
  Index is the active scalars of the critical points (points), StableManifolds
  and the Gabriel edges (cells), and Extract Block of CriticalPoints opens
  coloured by Index.
- Settings: the plugin's colour maps (Index, Extension) sit below the user's
  settings, and a user setting of the display's BlockSelectors wins (in a new
  session, so that the Index colour map is made again).
- Every filter: after Reset Camera the view spans at most twice the cloud (the
  unstable manifolds stop at the cloud's box grown by a quarter of its
  diagonal, at most 1 + sqrt(3)/2 of its size), centred on it.

Usage: pvpython test_default_display.py PLUGIN WORKDIR
"""

import json
import math
import os
import sys

import generate_clouds as gen
import numpy as np
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import (
    vtkSMParaViewPipelineControllerWithRendering, vtkSMPVRepresentationProxy)

from flowrecon_testing import clouds as cl
from flowrecon_testing.checks import check, finish

PLUGIN, WORK = sys.argv[1:3]

controller = vtkSMParaViewPipelineControllerWithRendering()


def apply(source, view, input_source=None):
    """Show every output port of `source` as the GUI's Apply does with `view`
    active: each port in its preferred view, a colour legend for each
    scalar-coloured display, the input hidden. Returns {port: display} for the
    ports shown in `view`."""
    shown = {}
    for port in range(source.GetNumberOfOutputPorts()):
        target = controller.ShowInPreferredView(source.SMProxy, port, view.SMProxy)
        if target is None or target.GetGlobalID() != view.SMProxy.GetGlobalID():
            continue
        rep = target.FindRepresentation(source.SMProxy, port)
        if vtkSMPVRepresentationProxy.GetUsingScalarColoring(rep):
            vtkSMPVRepresentationProxy.SetScalarBarVisibility(rep, view.SMProxy, True)
        shown[port] = servermanager._getPyProxy(rep)
    if input_source is not None:
        controller.SetVisibility(input_source.SMProxy, 0, view.SMProxy, False)
    return shown


def legends(view):
    """Titles of the colour legends (scalar bars) visible in `view`."""
    titles = []
    for rep in view.Representations:
        if rep.GetXMLName() == "ScalarBarWidgetRepresentation" and rep.Visibility:
            titles.append(rep.Title)
    return titles


def colouring(display):
    """(association, array) of a display; a text display has none."""
    if display.GetProperty("ColorArrayName") is None:
        return ("", "")
    return tuple(display.ColorArrayName)


def fresh_view(reader):
    view = simple.CreateRenderView()
    simple.Show(reader, view)
    return view


def check_camera(label, view, cloud_bounds):
    """After Reset Camera, the camera looks at the cloud and the sphere it frames
    (radius: the view's parallel scale) is at most twice the cloud's."""
    view.ResetCamera()
    cam = view.GetActiveCamera()
    lo, hi = np.array(cloud_bounds[0::2]), np.array(cloud_bounds[1::2])
    centre, radius = (lo + hi) / 2, np.linalg.norm(hi - lo) / 2
    framed = cam.GetParallelScale()
    off = np.linalg.norm(np.array(cam.GetFocalPoint()) - centre)
    print("%s: camera frames a radius of %.3g (cloud %.3g), %.3g off the cloud's centre" % (
        label, framed, radius, off), flush=True)
    check(0.5 * radius <= framed <= 2.0 * radius,
          "%s: Reset Camera frames a radius of %.3g, the cloud's is %.3g (expected within "
          "a factor 2)" % (label, framed, radius))
    check(off <= 0.25 * radius,
          "%s: Reset Camera looks %.3g away from the cloud's centre (cloud radius %.3g)" % (
              label, off, radius))


def blocks(mb):
    return {mb.GetMetaData(i).Get(mb.NAME()): mb.GetBlock(i) for i in range(mb.GetNumberOfBlocks())}


def active_name(attributes):
    scalars = attributes.GetScalars()
    return scalars.GetName() if scalars is not None else None


INDEX_NAMES = ["0", "minimum (sample)", "1", "index-1 saddle (Gabriel edge)",
               "2", "index-2 saddle (Gabriel triangle)", "3", "maximum"]
EXTENSION_NAMES = ["0", "initialization", "1", "regularization", "2", "upflow",
                   "3", "horizontal"]


def check_categorical(label, array, names):
    """The colour map of `array` is categorical and names its values."""
    lut = simple.GetColorTransferFunction(array)
    got = (lut.InterpretValuesAsCategories, list(lut.Annotations))
    print("%s: %s colour map categorical %d, annotations %s" % (label, array, got[0], got[1]),
          flush=True)
    check(got == (1, names), "%s: the %s colour map is %s, expected categorical with "
          "annotations %s" % (label, array, got, names))


COMPLEX_DISPLAY = ("FlowReconMultiBlockRepresentation",
                   ["/Root/CriticalPoints", "/Root/GabrielEdges"])
SIMPLIFICATION_DISPLAY = ("FlowReconSimplificationRepresentation",
                          ["/Root/SurvivingCriticalPoints", "/Root/SurvivingGabrielEdges"])


def check_plugin_display(label, display, view, expected=COMPLEX_DISPLAY):
    """What the plugin's display chooses: the display type and blocks of
    `expected`, coloured by the cell array Index (categorical, named), one
    colour legend."""
    check(display.GetXMLName() == expected[0],
          "%s: the display is a %s, expected %s" % (label, display.GetXMLName(), expected[0]))
    check(colouring(display) == ("CELLS", "Index"),
          "%s opens coloured by %s, expected CELLS Index" % (label, colouring(display)))
    check(list(display.BlockSelectors) == expected[1],
          "%s opens with the blocks %s, expected %s" % (
              label, list(display.BlockSelectors), expected[1]))
    check(display.LookupTable is not None and
          display.LookupTable.SMProxy.GetGlobalID() ==
          simple.GetColorTransferFunction("Index").SMProxy.GetGlobalID(),
          "%s: the display does not use the Index colour map" % label)
    check_categorical(label, "Index", INDEX_NAMES)
    check(legends(view) == ["Index"], "%s: colour legends %s, expected Index" % (
        label, legends(view)))
    # The critical points visible, not 1-2 pixel dots: shaded spheres of 6 pixels.
    check(display.PointSize == 6 and display.RenderPointsAsSpheres == 1,
          "%s: critical points drawn %g pixels wide, as spheres %s; expected 6, 1" % (
              label, display.PointSize, display.RenderPointsAsSpheres))


def check_active_scalars(label, source):
    """Index is the active scalars of CriticalPoints and SurvivingCriticalPoints
    (points), StableManifolds, GabrielEdges and SurvivingGabrielEdges (cells); no
    other block has any."""
    out = blocks(servermanager.Fetch(source))
    expected = {"CriticalPoints": ("Index", None), "StableManifolds": (None, "Index"),
                "GabrielEdges": (None, "Index"), "SurvivingCriticalPoints": ("Index", None),
                "SurvivingGabrielEdges": (None, "Index")}
    check("GabrielEdges" in out, "%s: no block GabrielEdges (%s)" % (label, sorted(out)))
    for name, block in out.items():
        got = (active_name(block.GetPointData()), active_name(block.GetCellData()))
        want = expected.get(name, (None, None))
        check(got == want, "%s: block %s has active point/cell scalars %s, expected %s" % (
            label, name, got, want))


def flow_complex(reader, cloud_bounds):
    fc = FlowComplex(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    view = fresh_view(reader)
    shown = apply(fc, view, reader)
    check(sorted(shown) == [0], "Flow Complex: ports shown in the render view %s" % sorted(shown))
    display = shown[0]
    print("Flow Complex: colouring %s, blocks %s, legends %s" % (
        colouring(display), list(display.BlockSelectors), legends(view)), flush=True)
    check_active_scalars("Flow Complex", fc)
    # What FlowComplex.xml's "What Apply shows" paragraph says.
    check_plugin_display("Flow Complex", display, view)
    check_camera("Flow Complex", view, cloud_bounds)

    # The readable picture the documentation recommends: Extract Block of
    # CriticalPoints opens coloured by the point array Index.
    extract = simple.ExtractBlock(Input=fc, Selectors=["/Root/CriticalPoints"])
    eview = fresh_view(reader)
    eshown = apply(extract, eview, reader)
    check(0 in eshown and colouring(eshown[0]) == ("POINTS", "Index"),
          "Extract Block CriticalPoints opens coloured by %s, expected POINTS Index" % (
              colouring(eshown[0]) if 0 in eshown else None,))
    check(legends(eview) == ["Index"], "Extract Block CriticalPoints: colour legends %s, "
          "expected Index" % legends(eview))
    check_camera("Extract Block CriticalPoints", eview, cloud_bounds)
    return fc


def simplification(reader, fc, cloud_bounds):
    simp = FlowComplexSimplification(Input=fc)  # noqa: F821
    view = fresh_view(reader)
    shown = apply(simp, view, reader)
    check(sorted(shown) == [0], "Simplification: ports shown %s" % sorted(shown))
    display = shown[0]
    print("Simplification: colouring %s, blocks %s, legends %s" % (
        colouring(display), list(display.BlockSelectors), legends(view)), flush=True)
    check(colouring(display)[1] != "Ratio",
          "Simplification opens coloured by the Ratio of PersistencePairs only")
    check_plugin_display("Simplification", display, view, SIMPLIFICATION_DISPLAY)
    check_active_scalars("Simplification", simp)
    check_camera("Simplification", view, cloud_bounds)

    # After a Flow Complex coloured by Index (as its documentation recommends),
    # the simplification keeps that colouring: one legend.
    view2 = fresh_view(reader)
    fcd = simple.Show(fc, view2)
    simple.ColorBy(fcd, ("POINTS", "Index"))
    fcd.SetScalarBarVisibility(view2, True)
    shown2 = apply(simp, view2, fc)
    print("Simplification after Flow Complex by Index: colouring %s, legends %s" % (
        colouring(shown2[0]), legends(view2)), flush=True)
    check(colouring(shown2[0])[1] == "Index",
          "Simplification applied after a Flow Complex coloured by Index is coloured by %s" % (
              colouring(shown2[0]),))
    check(legends(view2) == ["Index"],
          "Simplification after Flow Complex by Index: colour legends %s" % legends(view2))
    return simp


def check_direction(arrows):
    """Each sponsor line carries Direction = its end - its start at the start and
    0 at the end, and Priority on both points equals the line's."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    lines = arrows.GetNumberOfCells()
    check(lines > 0, "Flow Reconstruction: no sponsor arrow to check")
    pts = vtk_to_numpy(arrows.GetPoints().GetData())
    direction = arrows.GetPointData().GetArray("Direction")
    priority = arrows.GetPointData().GetArray("Priority")
    vectors = arrows.GetPointData().GetVectors()
    check(vectors is not None and vectors.GetName() == "Direction" and priority is not None,
          "Flow Reconstruction: the sponsor arrows lack the point vectors Direction or the "
          "point copy of Priority")
    if direction is None or priority is None:
        return
    d = vtk_to_numpy(direction)
    p = vtk_to_numpy(priority)
    cell_priority = vtk_to_numpy(arrows.GetCellData().GetArray("Priority"))
    bad = 0
    for c in range(lines):
        ids = arrows.GetCell(c).GetPointIds()
        a, b = ids.GetId(0), ids.GetId(1)
        if not (np.allclose(d[a], pts[b] - pts[a], rtol=0, atol=1e-12 * (1 + np.abs(pts).max()))
                and np.all(d[b] == 0) and p[a] == p[b] == cell_priority[c]):
            bad += 1
    print("Flow Reconstruction: %d sponsor arrows, %d with a wrong Direction or Priority" % (
        lines, bad), flush=True)
    check(bad == 0, "Flow Reconstruction: %d of %d sponsor arrows have a wrong Direction or "
          "point Priority" % (bad, lines))


def reconstruction(work):
    # A sphere whose cap lost half of its points: output 4 has warning points.
    base = gen.make("sphere_qu", size=1500)
    keep = (base[:, 2] <= 0.7) | (np.random.default_rng(3).uniform(size=len(base)) > 0.5)
    xyz = os.path.join(work, "sphere_thinned.xyz")
    cl.write_xyz(xyz, base[keep])
    reader = simple.OpenDataFile(xyz)
    reader.UpdatePipeline()
    cloud_bounds = reader.GetDataInformation().GetBounds()
    # At t_r 2, where this cloud's thinned cap is under-sampled.
    recon = FlowReconstruction(  # noqa: F821
        Input=FlowComplexSimplification(  # noqa: F821
            Input=FlowComplex(Input=reader, ComputeStableManifolds=0),  # noqa: F821
            AutomaticPersistenceThreshold=0),
        AutomaticReconstructionThreshold=0)
    recon.UpdatePipeline()
    warnings = recon.GetDataInformation(4).GetNumberOfPoints()
    check(warnings > 0, "Flow Reconstruction: no under-sampling point to show on this cloud")
    view = fresh_view(reader)
    shown = apply(recon, view, reader)
    print("Flow Reconstruction: ports in the render view %s, colourings %s, legends %s" % (
        sorted(shown), {p: colouring(d) for p, d in shown.items()}, legends(view)), flush=True)
    check(sorted(shown) == [0, 4, 5],
          "Flow Reconstruction: ports shown in the render view %s, expected 0, 4 and 5 "
          "(2, the sponsor arrows, only on request)" % sorted(shown))
    check(view.SMProxy.FindRepresentation(recon.SMProxy, 2) is None,
          "Flow Reconstruction: the sponsor arrows (output 2) are shown on Apply")
    if 0 in shown:
        check(colouring(shown[0]) == ("CELLS", "Index"),
              "Flow Reconstruction: output 0 coloured by %s, expected CELLS Index" % (
                  colouring(shown[0]),))
        check(shown[0].Visibility == 1, "Flow Reconstruction: output 0 hidden")
    if 4 in shown:
        check(colouring(shown[4])[1] == "",
              "Flow Reconstruction: the under-sampling points are coloured by %s (a second "
              "legend)" % (colouring(shown[4]),))
        check(shown[4].Visibility == 1, "Flow Reconstruction: output 4 hidden")
        spheres = (shown[4].Representation, shown[4].ShaderPreset, shown[4].SetScaleArray[1],
                   shown[4].ScaleByArray, shown[4].UseScaleFunction, shown[4].GaussianRadius)
        check(spheres == ("Point Gaussian", "Sphere", "Spacing", 1, 0, 1.0),
              "Flow Reconstruction: the under-sampling points are shown as %s, expected "
              "spheres of radius 1 x Spacing" % (spheres,))
    if 5 in shown:
        check(shown[5].GetXMLName() == "FlowReconTopologyTextRepresentation"
              and shown[5].WindowLocation == "Upper Left Corner"
              and shown[5].Justification == "Left",
              "Flow Reconstruction: the topology text is shown as %s at %s, %s" % (
                  shown[5].GetXMLName(), shown[5].WindowLocation, shown[5].Justification))
    check(legends(view) == ["Index"],
          "Flow Reconstruction: colour legends %s, expected one, Index" % legends(view))
    lut = simple.GetColorTransferFunction("Index")
    rng = lut.RGBPoints[0], lut.RGBPoints[-4]
    check(rng == (0.0, 3.0) or lut.InterpretValuesAsCategories,
          "Flow Reconstruction: the Index colour map spans %s, expected 0 to 3" % (rng,))
    check_categorical("Flow Reconstruction", "Index", INDEX_NAMES)
    check_camera("Flow Reconstruction", view, cloud_bounds)
    # The sponsor arrows are one click away: arrows from sponsor to node
    # (3D Glyphs of the point vector Direction at magnitude x 1), by Priority.
    check(recon.GetDataInformation(2).GetNumberOfCells() == 0,
          "Flow Reconstruction: sponsor arrows made though Sponsor Arrows is off")
    recon.SponsorArrows = 1
    recon.UpdatePipeline()
    arrows = simple.Show(simple.OutputPort(recon, 2), view)
    check(colouring(arrows) == ("POINTS", "Priority"),
          "Flow Reconstruction: shown on request, the sponsor arrows are coloured by %s" % (
              colouring(arrows),))
    glyphs = (arrows.Representation, arrows.Orient, arrows.SelectOrientationVectors,
              arrows.Scaling, arrows.ScaleMode, arrows.SelectScaleArray, arrows.ScaleFactor,
              arrows.GlyphType.GetXMLName())
    check(glyphs == ("3D Glyphs", 1, "Direction", 1, "Magnitude", "Direction", 1.0, "ArrowSource"),
          "Flow Reconstruction: the sponsor arrows are shown as %s, expected arrow glyphs "
          "oriented and scaled by Direction" % (glyphs,))
    check_direction(servermanager.Fetch(recon, idx=2))
    # Colouring them by Extension names how each node entered the reconstruction.
    simple.ColorBy(arrows, ("CELLS", "Extension"))
    check_categorical("Flow Reconstruction", "Extension", EXTENSION_NAMES)


def user_settings(xyz):
    """User settings (priority 1, as ParaView loads the user's file at a
    priority above the plugin's 0) beat the plugin's: the Index colour map is
    not categorical, and the display shows the blocks the user chose. The
    plugin's other keys (the names) stay. A new session makes the colour map
    again; the plugin stays loaded."""
    simple.Disconnect()
    simple.Connect()
    user = {"array_lookup_tables": {"Index": {"PVLookupTable": {"IndexedLookup": 0}}},
            "representations": {"FlowReconMultiBlockRepresentation": {
                "BlockSelectors": ["/Root/CriticalPoints", "/Root/StableManifolds"]}}}
    check(servermanager.vtkSMSettings.GetInstance().AddCollectionFromString(
        json.dumps(user), 1.0), "user settings: not accepted")
    reader = simple.OpenDataFile(xyz)
    fc = FlowComplex(Input=reader)  # noqa: F821
    view = fresh_view(reader)
    shown = apply(fc, view, reader)
    display = shown[0]
    lut = simple.GetColorTransferFunction("Index")
    print("User settings: colouring %s, blocks %s, Index categorical %d, annotations %s" % (
        colouring(display), list(display.BlockSelectors), lut.InterpretValuesAsCategories,
        list(lut.Annotations)), flush=True)
    check(list(display.BlockSelectors) == ["/Root/CriticalPoints", "/Root/StableManifolds"],
          "user settings: the display shows the blocks %s, not the user's" % list(
              display.BlockSelectors))
    check(colouring(display) == ("CELLS", "Index"),
          "user settings: the display is coloured by %s" % (colouring(display),))
    check(lut.InterpretValuesAsCategories == 0,
          "user settings: the Index colour map is still categorical")
    check(list(lut.Annotations) == INDEX_NAMES,
          "user settings: the Index colour map lost its names: %s" % list(lut.Annotations))


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    xyz = os.path.join(WORK, "torus.xyz")
    cl.write_xyz(xyz, gen.torus(300, np.random.default_rng(4)))
    reader = simple.OpenDataFile(xyz)
    reader.UpdatePipeline()
    cloud_bounds = reader.GetDataInformation().GetBounds()
    check(all(math.isfinite(b) for b in cloud_bounds), "the cloud has no bounds")
    fc = flow_complex(reader, cloud_bounds)
    simplification(reader, fc, cloud_bounds)
    reconstruction(WORK)
    user_settings(xyz)
    finish()


if __name__ == "__main__":
    main()
