#!/usr/bin/env pvpython
"""Write the example ParaView states of Data/: demo.pvsm (the paper's two hemispheres),
torus.pvsm and bunny.pvsm. Each reads its cloud with the plugin's own reader
(FlowRecon Point Cloud Reader) and runs Flow Complex -> Flow Complex Simplification
(automatic t_p) -> Flow Reconstruction twice: at the automatic t_r (shown) and at a
given t_r (hidden, for comparison).

    pvpython Apps/Scripts/make_states.py build/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so [NAME...]

(NAME: demo, torus, bunny; default all; no X server needed, nothing is rendered).

File names in a state. ParaView 5.11 stores a reader's FileName as given and, on
loading, passes it to the reader unchanged: a relative name is relative to ParaView's
working folder, never to the state file. The states store "Data/<cloud>.xyz" (relative
to the repository root), so:
  - from the repository root they load as they are (paraview --state=Data/demo.pvsm);
  - from anywhere, File > Load State, "Search files under specified directory": the
    directory is filled in with the state file's own folder (Data/), where ParaView
    finds each file by its name; in Python
    LoadState(".../Data/demo.pvsm", data_directory=".../Data");
  - paraview --state=.../Data/demo.pvsm from anywhere (no dialog) with the user setting
    "options": {"LoadStateOptions": {"LoadStateDataFileOptions": 1}} in
    ~/.config/ParaView/ParaView-UserSettings.json, which makes that search the default.
Tested by Testing/ParaView/test_states.py and test_states_gui.py (pv./gui.example_states).
"""

import os
import sys

from paraview import simple

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DATA_DIR = os.path.join(ROOT, "Data")

# name: cloud, (t_r shown: None = automatic, t_r hidden for comparison), up axis,
# view direction
STATES = {
    "demo": dict(cloud="two_hemispheres.xyz", tr=(None, 2.5), up=(0.0, 0.0, 1.0),
                 view=None, spreadsheet="profile"),
    "torus": dict(cloud="torus.xyz", tr=(None, 1.8), up=(0.0, 0.0, 1.0),
                  view=(0.45, -1.0, 1.1), spreadsheet="betti"),
    "bunny": dict(cloud="bunny.xyz", tr=(None, 1.5), up=(0.0, 1.0, 0.0),
                  view=(0.35, 0.55, 1.0), spreadsheet=None),
}


def label(t_r):
    return "Reconstruction (automatic t_r)" if t_r is None else "Reconstruction t_r %g" % t_r


def reconstruction(make_filter, simp, t_r):
    if t_r is None:
        return make_filter(registrationName=label(t_r), Input=simp)
    return make_filter(registrationName=label(t_r), Input=simp, AutomaticReconstructionThreshold=0,
                       ReconstructionThreshold=t_r)


def make(name, spec, plugin):
    # a fresh session per state: nothing (colour maps, layouts) left over from the last one
    simple.ResetSession()
    simple.LoadPlugin(plugin, remote=False)
    ns = {proxy: getattr(simple, proxy) for proxy in
          ("FlowReconPointCloudReader", "FlowComplex", "FlowComplexSimplification",
           "FlowReconstruction")}
    relative = "Data/" + spec["cloud"]  # relative to the repository root (see above)
    reader = ns["FlowReconPointCloudReader"](registrationName=spec["cloud"], FileName=[relative])
    fc = ns["FlowComplex"](registrationName="FlowComplex", Input=reader)
    simp = ns["FlowComplexSimplification"](registrationName="Simplification", Input=fc)
    shown_tr, hidden_tr = spec["tr"]
    recon = reconstruction(ns["FlowReconstruction"], simp, shown_tr)
    other = reconstruction(ns["FlowReconstruction"], simp, hidden_tr)
    recon.UpdatePipeline()
    other.UpdatePipeline()
    if recon.GetDataInformation().GetNumberOfCells() == 0:
        raise SystemExit("make_states.py: empty reconstruction for %s" % name)

    layout = simple.CreateLayout("FlowRecon " + name)
    view = simple.CreateView("RenderView")
    simple.AssignViewToLayout(view=view, layout=layout, hint=0)
    view.OrientationAxesVisibility = 1
    points_display = simple.Show(reader, view)
    points_display.Representation = "Points"
    points_display.PointSize = 2.0
    points_display.ColorArrayName = ["POINTS", ""]
    simple.Hide(reader, view)
    for source, visible in ((recon, True), (other, False)):
        display = simple.Show(source, view)
        display.Representation = "Surface"
        simple.ColorBy(display, ("CELLS", "CriticalValue"))
        if visible:
            simple.GetColorTransferFunction("CriticalValue").ApplyPreset(
                "Viridis (matplotlib)", True)
            display.RescaleTransferFunctionToDataRange(True, False)
            display.SetScalarBarVisibility(view, True)
            # the answer in words (Topology Text) and the under-sampled places
            simple.Show(simple.OutputPort(source, 5), view)
            simple.Show(simple.OutputPort(source, 4), view)
        else:
            simple.Hide(source, view)
    if spec["view"] is None:  # the camera of the original demo state
        view.CameraFocalPoint = [0.0, 0.0, 0.45]
        view.CameraPosition = [2.1, -4.7, 3.9]
    else:
        bounds = reader.GetDataInformation().GetBounds()
        center = [(bounds[2 * k] + bounds[2 * k + 1]) / 2.0 for k in range(3)]
        diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
        d = spec["view"]
        norm = sum(x * x for x in d) ** 0.5
        view.CameraFocalPoint = center
        view.CameraPosition = [center[k] + 1.7 * diagonal * d[k] / norm for k in range(3)]
    view.CameraViewUp = list(spec["up"])
    view.CameraViewAngle = 30.0

    if spec["spreadsheet"]:
        layout.SplitHorizontal(0, 0.7)
        sheet = simple.CreateView("SpreadSheetView")
        simple.AssignViewToLayout(view=sheet, layout=layout, hint=2)
        if spec["spreadsheet"] == "profile":  # the reconstruction profile (output port 1)
            simple.Show(simple.OutputPort(recon, 1), sheet)
        else:  # the Betti numbers of the reconstruction shown (its field data)
            simple.Show(recon, sheet)
            sheet.FieldAssociation = "Field Data"
    simple.SetActiveView(view)
    simple.SetActiveSource(recon)

    out = os.path.join(DATA_DIR, name + ".pvsm")
    simple.SaveState(out)
    with open(out) as f:
        text = f.read()
    if 'value="%s"' % relative not in text or ROOT in text:
        raise SystemExit("make_states.py: %s does not store the relative path %s alone"
                         % (out, relative))
    print("wrote %s (%s, %s shown, %s hidden)" % (out, relative, label(shown_tr),
                                                 label(hidden_tr)))


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    names = sys.argv[2:] or list(STATES)
    for name in names:
        if name not in STATES:
            raise SystemExit("make_states.py: unknown state %s (%s)" % (name, ", ".join(STATES)))
    plugin = os.path.abspath(sys.argv[1])
    os.chdir(ROOT)  # the readers' file names are relative to the repository root
    for name in names:
        make(name, STATES[name], plugin)


if __name__ == "__main__":
    main()
