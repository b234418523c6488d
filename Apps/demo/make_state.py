#!/usr/bin/env pvpython
"""Write Data/demo.pvsm, the ParaView state of the demo pipeline.

Run from the repository root (no X server needed: nothing is rendered):

    pvpython Apps/demo/make_state.py build/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so

The state holds: Data/two_hemispheres.xyz read with the CSV reader, Table To Points,
Flow Complex -> Flow Complex Simplification (t_p 1.1) -> Flow Reconstruction (t_r 2),
a second Flow Reconstruction at t_r 2.5 (hidden, for comparison), a render view with
the reconstruction coloured by CriticalValue, and the reconstruction profile (output
port 1) in a spreadsheet view. The data file name is stored as the relative path
"Data/two_hemispheres.xyz": ParaView passes it to the reader unchanged, so the state
loads when ParaView's working folder is the repository root:

    PV_PLUGIN_PATH=build/lib/paraview-5.11/plugins/FlowRecon paraview --state=Data/demo.pvsm

(from elsewhere: File > Load State, "Search files under specified directory" = the
repository's Data folder; in Python LoadState(path, data_directory=".../Data")).
"""

import os
import sys

from paraview import simple

DATA = "Data/two_hemispheres.xyz"


def main():
    if len(sys.argv) < 2:
        raise SystemExit(__doc__)
    if not os.path.exists(DATA):
        raise SystemExit("make_state.py: run from the repository root (%s not found)" % DATA)
    out = sys.argv[2] if len(sys.argv) > 2 else "Data/demo.pvsm"
    simple.LoadPlugin(sys.argv[1], remote=False)  # adds the filters to paraview.simple
    ns = {name: getattr(simple, name) for name in
          ("FlowComplex", "FlowComplexSimplification", "FlowReconstruction")}

    reader = simple.CSVReader(registrationName="two_hemispheres.xyz", FileName=[DATA])
    reader.HaveHeaders = 0
    reader.FieldDelimiterCharacters = " "
    reader.MergeConsecutiveDelimiters = 1
    points = simple.TableToPoints(registrationName="Points", Input=reader,
                                  XColumn="Field 0", YColumn="Field 1", ZColumn="Field 2")
    fc = ns["FlowComplex"](registrationName="FlowComplex", Input=points)
    simp = ns["FlowComplexSimplification"](registrationName="Simplification", Input=fc)
    recon = ns["FlowReconstruction"](registrationName="Reconstruction t_r 2", Input=simp)
    recon25 = ns["FlowReconstruction"](registrationName="Reconstruction t_r 2.5", Input=simp,
                                        ReconstructionThreshold=2.5)
    recon.UpdatePipeline()
    recon25.UpdatePipeline()

    layout = simple.CreateLayout("FlowRecon demo")
    view = simple.CreateView("RenderView")
    simple.AssignViewToLayout(view=view, layout=layout, hint=0)
    view.OrientationAxesVisibility = 1
    points_display = simple.Show(points, view)
    points_display.Representation = "Points"
    points_display.PointSize = 2.0
    points_display.ColorArrayName = ["POINTS", ""]
    simple.Hide(points, view)
    display = simple.Show(recon, view)
    simple.ColorBy(display, ("CELLS", "CriticalValue"))
    simple.GetColorTransferFunction("CriticalValue").ApplyPreset("Viridis (matplotlib)", True)
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    display25 = simple.Show(recon25, view)
    simple.ColorBy(display25, ("CELLS", "CriticalValue"))
    simple.Hide(recon25, view)
    view.CameraFocalPoint = [0.0, 0.0, 0.45]
    view.CameraPosition = [2.1, -4.7, 3.9]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30.0

    layout.SplitHorizontal(0, 0.7)
    sheet = simple.CreateView("SpreadSheetView")
    simple.AssignViewToLayout(view=sheet, layout=layout, hint=2)
    simple.Show(simple.OutputPort(recon, 1), sheet)
    simple.SetActiveView(view)
    simple.SetActiveSource(recon)

    simple.SaveState(out)
    with open(out) as f:
        text = f.read()
    if DATA not in text or os.path.abspath(DATA) in text:
        raise SystemExit("make_state.py: %s does not store the relative path %s" % (out, DATA))
    print("wrote %s (data file %s, relative to the working folder)" % (out, DATA))


if __name__ == "__main__":
    main()
