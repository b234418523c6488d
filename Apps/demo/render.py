#!/usr/bin/env pvbatch
"""FlowRecon demo: reconstruct a point cloud with the ParaView plugin and render it.

usage (rendering needs an X server, e.g. xvfb-run -a -s "-screen 0 1280x1024x24"):

    pvbatch Apps/demo/render.py PLUGIN INPUT OUTDIR [options]

PLUGIN  the FlowRecon plugin library (build/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so),
        or "auto" when it is already loaded through PV_PLUGIN_PATH
INPUT   a point cloud: .xyz/.txt/.pts (x y z per line, read with ParaView's CSV reader)
        or any file ParaView can open (.ply, .vtp, .vtu, ...; its points are used)
OUTDIR  where everything goes; NAME (default: the input's file name without extension):
        NAME_reconstruction.vtu   the reconstruction at the default thresholds
        NAME_profile.csv          the reconstruction profile (port 1) at t_r = infinity
        NAME_reconstruction.png   the reconstruction coloured by CriticalValue
        NAME_index.png            the reconstruction coloured by Index (0 vertex .. 3 solid)
        NAME_points.png           the input points
        NAME_tr.png               t_r = TR1 beside t_r = TR2 (same t_p)
        NAME_tp.png               t_p = 0 (no simplification) beside t_p = default (same t_r)
        NAME_profile.png          Priority and Threshold against Step (matplotlib if
                                  importable, else ParaView's line chart)

options:
    --name NAME         output file prefix
    --up x|y|z          the cloud's "up" axis for the camera (default z)
    --view DX,DY,DZ     direction from the focal point to the camera (default chosen from --up)
    --tr-compare A,B    the two t_r of NAME_tr.png (default 1.9,2.5)
    --tp-compare A,B    the two t_p of NAME_tp.png (default 0,1.1)
    --size W,H          size of one picture (default 900,700)

Flow Complex -> Flow Complex Simplification (t_p) -> Flow Reconstruction (t_r) run with
the plugin's defaults (t_p = 1.1, t_r = 2.0) unless compared. Prints "render.py done" at
the end; exits non-zero on any failure.
"""

import os
import sys


def say(message):
    sys.stdout.write(message + "\n")
    sys.stdout.flush()


def parse_args(argv):
    if len(argv) < 4 or argv[1] in ("-h", "--help"):
        say(__doc__)
        sys.exit(0 if len(argv) > 1 and argv[1] in ("-h", "--help") else 2)
    args = {"plugin": argv[1], "input": argv[2], "outdir": argv[3], "name": None, "up": "z",
            "view": None, "tr": (1.9, 2.5), "tp": (0.0, 1.1), "size": (900, 700)}
    rest = argv[4:]
    i = 0
    while i < len(rest):
        key = rest[i]
        if i + 1 >= len(rest):
            raise SystemExit("render.py: option %s needs a value" % key)
        value = rest[i + 1]
        if key == "--name":
            args["name"] = value
        elif key == "--up":
            if value not in ("x", "y", "z"):
                raise SystemExit("render.py: --up must be x, y or z")
            args["up"] = value
        elif key == "--view":
            args["view"] = tuple(float(v) for v in value.split(","))
        elif key == "--tr-compare":
            args["tr"] = tuple(float(v) for v in value.split(","))
        elif key == "--tp-compare":
            args["tp"] = tuple(float(v) for v in value.split(","))
        elif key == "--size":
            args["size"] = tuple(int(v) for v in value.split(","))
        else:
            raise SystemExit("render.py: unknown option %s" % key)
        i += 2
    if args["name"] is None:
        args["name"] = os.path.splitext(os.path.basename(args["input"]))[0]
    return args


UP = {"x": (1.0, 0.0, 0.0), "y": (0.0, 1.0, 0.0), "z": (0.0, 0.0, 1.0)}
# a three-quarter view from slightly above, for each up axis
VIEW = {"x": (0.8, 0.35, -1.0), "y": (0.35, 0.55, 1.0), "z": (0.45, -1.0, 0.75)}


def main():
    args = parse_args(sys.argv)
    from paraview import servermanager
    from paraview import simple

    if args["plugin"] != "auto":
        if not os.path.exists(args["plugin"]):
            raise SystemExit("render.py: plugin %s does not exist" % args["plugin"])
        simple.LoadPlugin(args["plugin"], remote=False)  # adds the filters to paraview.simple
    ns = {}
    for proxy in ("FlowComplex", "FlowComplexSimplification", "FlowReconstruction"):
        ns[proxy] = getattr(simple, proxy, None)
        if ns[proxy] is None:
            raise SystemExit("render.py: the plugin did not define %s" % proxy)

    os.makedirs(args["outdir"], exist_ok=True)
    out = lambda suffix: os.path.join(args["outdir"], args["name"] + suffix)  # noqa: E731

    # ---- pipeline ---------------------------------------------------------------
    path = args["input"]
    if os.path.splitext(path)[1].lower() in (".xyz", ".txt", ".pts"):
        reader = simple.CSVReader(registrationName=os.path.basename(path), FileName=[path])
        reader.HaveHeaders = 0
        reader.FieldDelimiterCharacters = " "
        reader.MergeConsecutiveDelimiters = 1
        points = simple.TableToPoints(registrationName="Points", Input=reader,
                                      XColumn="Field 0", YColumn="Field 1", ZColumn="Field 2")
    else:
        reader = simple.OpenDataFile(path)
        if reader is None:
            raise SystemExit("render.py: ParaView cannot read %s" % path)
        points = reader
    fc = ns["FlowComplex"](registrationName="FlowComplex", Input=points)
    simp = ns["FlowComplexSimplification"](registrationName="Simplification", Input=fc)
    recon = ns["FlowReconstruction"](registrationName="Reconstruction", Input=simp)
    recon.UpdatePipeline()
    # t_p and t_r as the filters chose them from the data (their defaults)
    chosen = servermanager.Fetch(recon).GetFieldData()
    t_p = chosen.GetArray("PersistenceThreshold").GetValue(0)
    t_r = chosen.GetArray("ReconstructionThreshold").GetValue(0)
    n_points = points.GetDataInformation().GetNumberOfPoints()
    info = recon.GetDataInformation()
    say("%s: %d points -> reconstruction at t_p %g, t_r %g: %d cells, %d points" % (
        path, n_points, t_p, t_r, info.GetNumberOfCells(), info.GetNumberOfPoints()))
    if n_points < 4 or info.GetNumberOfCells() == 0:
        raise SystemExit("render.py: empty input or reconstruction")
    # the compact geometry (the filter's default): cells on the samples with the
    # node each stands for; the insertion data (Step, Priority) is in the profile
    for name in ("NodeId", "Index", "Threshold"):
        if name not in recon.CellData.keys():
            raise SystemExit("render.py: reconstruction has no cell array %s" % name)

    simple.SaveData(out("_reconstruction.vtu"), proxy=recon)
    say("wrote " + out("_reconstruction.vtu"))

    # the profile: run at t_r = infinity (port 1 of any reconstruction)
    table = servermanager.Fetch(recon, idx=1)
    columns = {}
    for name in ("Step", "Priority", "Threshold", "Index"):
        column = table.GetColumnByName(name)
        if column is None:
            raise SystemExit("render.py: profile has no column %s" % name)
        columns[name] = [column.GetValue(i) for i in range(column.GetNumberOfTuples())]
    with open(out("_profile.csv"), "w") as f:
        f.write("Step,Index,Priority,Threshold\n")
        for row in zip(columns["Step"], columns["Index"], columns["Priority"], columns["Threshold"]):
            f.write("%d,%d,%.17g,%.17g\n" % row)
    say("wrote %s (%d steps)" % (out("_profile.csv"), len(columns["Step"])))

    # ---- pictures -----------------------------------------------------------------
    width, height = args["size"]
    up = UP[args["up"]]
    direction = args["view"] or VIEW[args["up"]]
    bounds = points.GetDataInformation().GetBounds()
    center = [(bounds[2 * k] + bounds[2 * k + 1]) / 2.0 for k in range(3)]
    diagonal = sum((bounds[2 * k + 1] - bounds[2 * k]) ** 2 for k in range(3)) ** 0.5
    norm = sum(d * d for d in direction) ** 0.5

    def new_view(size=(width, height), distance=1.7):
        view = simple.CreateView("RenderView")
        view.ViewSize = list(size)
        view.OrientationAxesVisibility = 0
        view.Background = [1.0, 1.0, 1.0]
        if hasattr(view, "UseColorPaletteForBackground"):
            view.UseColorPaletteForBackground = 0
        view.CameraFocalPoint = center
        view.CameraPosition = [center[k] + distance * diagonal * direction[k] / norm
                               for k in range(3)]
        view.CameraViewUp = list(up)
        view.CameraViewAngle = 30.0
        return view

    def label(view, text, where="Upper Center", size=22):
        caption = simple.Text(Text=text)
        display = simple.Show(caption, view)
        display.Color = [0.0, 0.0, 0.0]
        display.FontSize = size
        display.WindowLocation = where
        return caption

    def show_reconstruction(source, view, color_by, bar=True):
        display = simple.Show(source, view)
        display.Representation = "Surface"
        display.LineWidth = 1.5
        display.PointSize = 2.0
        if color_by == "Index":
            simple.ColorBy(display, ("CELLS", "Index"))
            lut = simple.GetColorTransferFunction("Index")
            lut.InterpretValuesAsCategories = 1
            lut.AnnotationsInitialized = 1
            lut.Annotations = ["0", "0 sample", "1", "1 Gabriel edge", "2", "2 patch",
                               "3", "3 solid"]
            lut.IndexedColors = [0.3, 0.3, 0.3, 0.12, 0.47, 0.71, 0.85, 0.55, 0.2,
                                 0.75, 0.2, 0.2]
        else:
            simple.ColorBy(display, ("CELLS", color_by))
            lut = simple.GetColorTransferFunction(color_by)
            lut.ApplyPreset("Viridis (matplotlib)", True)
            display.RescaleTransferFunctionToDataRange(True, False)
        display.SetScalarBarVisibility(view, bar)
        if not bar:
            return display
        bar = simple.GetScalarBar(lut, view)
        bar.TitleColor = [0.0, 0.0, 0.0]
        bar.LabelColor = [0.0, 0.0, 0.0]
        bar.WindowLocation = "Any Location"
        bar.Orientation = "Vertical"
        bar.Position = [0.88, 0.08]
        bar.ScalarBarLength = 0.4
        return display

    def save(view_or_layout, suffix, size):
        path = out(suffix)
        simple.SaveScreenshot(path, view_or_layout, ImageResolution=list(size),
                              TransparentBackground=0)
        say("wrote %s" % path)

    # the reconstruction, by CriticalValue and by Index
    for color_by, suffix in (("CriticalValue", "_reconstruction.png"), ("Index", "_index.png")):
        view = new_view()
        show_reconstruction(recon, view, color_by)
        label(view, "%s: reconstruction, t_p = %g, t_r = %g" % (args["name"], t_p, t_r))
        simple.Render(view)
        save(view, suffix, (width, height))

    # the input points
    view = new_view()
    display = simple.Show(points, view)
    display.Representation = "Points"
    display.PointSize = 3.0
    display.AmbientColor = display.DiffuseColor = [0.1, 0.1, 0.4]
    display.ColorArrayName = ["POINTS", ""]
    label(view, "%s: %d input points" % (args["name"], n_points))
    simple.Render(view)
    save(view, "_points.png", (width, height))

    # side-by-side comparisons
    def compare(suffix, make_a, make_b, text_a, text_b):
        layout = simple.CreateLayout(args["name"] + suffix)
        view_a = new_view((width // 2, height), 2.2)
        view_b = new_view((width // 2, height), 2.2)
        simple.AssignViewToLayout(view=view_a, layout=layout, hint=0)
        layout.SplitHorizontal(0, 0.5)
        simple.AssignViewToLayout(view=view_b, layout=layout, hint=2)
        for view, make, text in ((view_a, make_a, text_a), (view_b, make_b, text_b)):
            source = make()
            source.UpdatePipeline()
            show_reconstruction(source, view, "Index", bar=False)
            cells = source.GetDataInformation().GetNumberOfCells()
            label(view, "%s (%d cells)" % (text, cells))
        label(view_b, "Index: grey sample, blue Gabriel edge,\norange patch, red solid",
              "Lower Right Corner", 15)
        layout.SetSize(width, height)
        simple.Render(view_a)
        simple.Render(view_b)
        save(layout, suffix, (width, height))

    tr_a, tr_b = args["tr"]
    compare("_tr.png",
            lambda: ns["FlowReconstruction"](Input=simp, ReconstructionThreshold=tr_a,
                                             AutomaticReconstructionThreshold=0),
            lambda: ns["FlowReconstruction"](Input=simp, ReconstructionThreshold=tr_b,
                                             AutomaticReconstructionThreshold=0),
            "t_r = %g" % tr_a, "t_r = %g" % tr_b)
    tp_a, tp_b = args["tp"]
    compare("_tp.png",
            lambda: ns["FlowReconstruction"](
                Input=ns["FlowComplexSimplification"](Input=fc, PersistenceThreshold=tp_a,
                                                      AutomaticPersistenceThreshold=0),
                ReconstructionThreshold=t_r, AutomaticReconstructionThreshold=0),
            lambda: ns["FlowReconstruction"](
                Input=ns["FlowComplexSimplification"](Input=fc, PersistenceThreshold=tp_b,
                                                      AutomaticPersistenceThreshold=0),
                ReconstructionThreshold=t_r, AutomaticReconstructionThreshold=0),
            "t_p = %g, t_r = %g" % (tp_a, t_r), "t_p = %g, t_r = %g" % (tp_b, t_r))

    # the profile plot
    plot_profile(columns, out("_profile.png"), args, t_r, simple, recon, width, height)

    say("render.py done: %s" % args["outdir"])


def plot_profile(columns, path, args, t_r, simple, recon, width, height):
    steps, priority, threshold = columns["Step"], columns["Priority"], columns["Threshold"]
    finite = [p for p in priority if p < 1e300]
    top = max(finite) if finite else 3.0
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        plt = None
    if plt is not None:
        fig, ax = plt.subplots(figsize=(width / 100.0, height / 100.0 * 0.75), dpi=100)
        ax.plot(steps, [min(p, top) for p in priority], ".", markersize=2, color="0.55",
                label="Priority (ratio of the popped stable manifold)")
        ax.plot(steps, threshold, "-", linewidth=1.6, color="C0",
                label="Threshold (running maximum: smallest t_r keeping the step)")
        for value, style in ((t_r, "--"),) + tuple((t, ":") for t in args["tr"] if t != t_r):
            ax.axhline(value, linestyle=style, color="C3", linewidth=1)
            ax.text(0.62, value, "t_r = %g" % value, color="C3", va="bottom", ha="center",
                    fontsize=9, transform=ax.get_yaxis_transform())
        ax.set_ylim(0.97, max(1.1, min(max((top,) + tuple(args["tr"])), 4.0) * 1.04))
        ax.set_xlabel("Step (insertion order)")
        ax.set_ylabel("ratio")
        ax.set_title("%s: reconstruction profile at t_r = infinity (%d steps)" % (
            args["name"], len(steps)))
        ax.legend(loc="upper left", fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
        fig.tight_layout()
        fig.savefig(path)
        plt.close(fig)
    else:  # ParaView's own line chart of output port 1
        view = simple.CreateView("XYChartView")
        view.ViewSize = [width, int(height * 0.75)]
        display = simple.Show(simple.OutputPort(recon, 1), view, "XYChartRepresentation")
        display.UseIndexForXAxis = 0
        display.XArrayName = "Step"
        display.SeriesVisibility = ["Priority", "Threshold"]
        view.ChartTitle = "%s: reconstruction profile at t_r = infinity" % args["name"]
        simple.Render(view)
        simple.SaveScreenshot(path, view, ImageResolution=[width, int(height * 0.75)])
    say("wrote %s" % path)


if __name__ == "__main__":
    main()
