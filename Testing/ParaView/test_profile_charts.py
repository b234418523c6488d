#!/usr/bin/env python3
"""The charts Flow Reconstruction's profiles open in, with no X server: port 3
(Topology Profile) as ParaView's Apply opens it (ShowInPreferredView), in a
FlowReconTopologyChartView; port 1 (Profile) on request only (its preferred view
is None: Apply opens no chart for it, whose rows the GUI would draw again at every
t_r), shown as a user does, in a Line Chart View (log) (FlowReconLogChartView,
log left axis) made first. Their axes are titled (Step and Priority, Threshold;
t_r and Betti number), with their own representations: Priority, Threshold and
the t_r line against Step (Priority one pixel wide); b0, b1, b2 drawn as steps and the t_r
mark against Threshold, from the table's field data.

Checked against `flowrecon reconstruct CLOUD --tr T --tr-max 4 --profile P.csv
--topology-profile B.csv` of the same cloud: the profile rows below 4 (the CLI's
cap: its run is exact below it and its profile stops there) equal P.csv, the
topology rows equal B.csv, the field data steps are exactly B.csv's intervals
from t_r / 1.25 on (each row from its Threshold to the next, the last to 4; the
rows ending before left out, the one across starting there: the chart's height is
that of the Betti numbers around t_r), and the mark is two points at x = t_r, from
0 to the largest Betti number drawn, whose Betti numbers are those the CLI prints
at t_r. Changing Reconstruction Threshold moves the marks and the steps' start and
no row; Every Step puts the marks at Maximum Threshold.

Usage: pvpython test_profile_charts.py PLUGIN FLOWRECON WORKDIR
"""

import csv
import os
import re
import subprocess
import sys

import numpy as np
from paraview import servermanager, simple
from paraview.modules.vtkRemotingViews import vtkSMParaViewPipelineControllerWithRendering
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing.checks import check, finish
from flowrecon_testing.paraview_pipeline import torus_profiles

PLUGIN, FLOWRECON, WORK = sys.argv[1:4]
TMAX = 4.0


def cli(xyz, tr):
    """The CLI's profile, topology profile and printed Betti numbers at tr."""
    base = os.path.join(WORK, "cli_%g" % tr)
    p = subprocess.run([FLOWRECON, "reconstruct", xyz, "-o", base + ".vtu", "--tr", str(tr), "--tp", "1.1",
                        "--tr-max", str(TMAX), "--exact", "--profile", base + "_P.csv",
                        "--topology-profile", base + "_B.csv"], capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit("FAIL flowrecon reconstruct: " + p.stderr)
    betti = tuple(int(x) for x in re.search(r"Betti numbers: (\d+) (\d+) (\d+)", p.stdout).groups())
    with open(base + "_P.csv") as f:
        profile = [(int(r["Step"]), int(r["NodeId"]), int(r["Index"]), float(r["Priority"]),
                    float(r["Threshold"])) for r in csv.DictReader(f)]
    with open(base + "_B.csv") as f:
        topology = [(float(r["threshold"]), int(r["b0"]), int(r["b1"]), int(r["b2"]))
                    for r in csv.DictReader(f)]
    return profile, topology, betti


def columns(data, names):
    return {n: vtk_to_numpy(data.GetArray(n)).astype(float) for n in names
            if data.GetArray(n) is not None}


def outputs(recon):
    """Port 1's rows, port 3's rows and its field data (the chart's steps)."""
    profile = servermanager.Fetch(recon, idx=1)
    topology = servermanager.Fetch(recon, idx=3)
    p = columns(profile.GetRowData(), ("Step", "NodeId", "Index", "Priority", "Threshold",
                                       "Extension", "Sponsor", "t_r"))
    t = columns(topology.GetRowData(), ("Threshold", "b0", "b1", "b2"))
    s = columns(topology.GetFieldData(), ("Threshold", "b0", "b1", "b2", "t_r"))
    return p, t, s


def check_marks(label, tr, cli_run, p, t, s):
    """The t_r marks of both ports at tr, against the CLI run at tr."""
    profile, topology, betti = cli_run
    # Port 1: the profile rows, and t_r on every row.
    rows = list(zip(*(p[n] for n in ("Step", "NodeId", "Index", "Priority", "Threshold"))))
    below = [r for r in rows if r[4] < TMAX]
    check(len(below) == len(profile) and len(below) < len(rows) and
          all(a[:3] == b[:3] and a[3] == b[3] and a[4] == b[4] for a, b in zip(below, profile)),
          "%s: port 1 differs from the CLI's --profile (%d and %d rows)" % (
              label, len(rows), len(profile)))
    check("t_r" in p and len(p["t_r"]) == len(rows) and np.all(p["t_r"] == tr),
          "%s: port 1's t_r column is not %g on every row: %s" % (
              label, tr, np.unique(p.get("t_r", []))[:5]))
    # Port 3: one row per change, as the CLI writes them.
    rows3 = list(zip(*(t[n] for n in ("Threshold", "b0", "b1", "b2"))))
    check(rows3 == topology, "%s: port 3's rows differ from the CLI's --topology-profile "
          "(%d and %d rows)" % (label, len(rows3), len(topology)))
    # Its field data: the steps of B.csv and the mark at tr.
    if not check(sorted(s) == ["Threshold", "b0", "b1", "b2", "t_r"] and
                 len({len(a) for a in s.values()}) == 1,
                 "%s: port 3's field data is %s" % (label, {k: len(a) for k, a in s.items()})):
        return
    x = s["Threshold"]
    marked = ~np.isnan(s["t_r"])
    check(np.all(np.diff(x) >= 0), "%s: the steps go back in Threshold" % label)
    # B.csv's intervals from t_r / 1.25 on: the ones ending before are left out,
    # the one across starts there.
    start_at = max(1.0, tr / 1.25)
    expected, top = [], 1
    for k, (start, *b) in enumerate(topology):
        end = topology[k + 1][0] if k + 1 < len(topology) else TMAX
        if end > start_at:
            expected += [(max(start, start_at), *b), (end, *b)]
            top = max(top, *b)
    steps = list(zip(x[~marked], *(s[n][~marked] for n in ("b0", "b1", "b2"))))
    check(steps == expected, "%s: the steps are not B.csv's intervals from %g (%d and %d points)"
          % (label, start_at, len(steps), len(expected)))
    check(len(expected) < 2 * len(topology), "%s: no interval of B.csv ends before %g: the test "
          "shows nothing" % (label, start_at))
    mark = list(zip(x[marked], s["t_r"][marked], *(s[n][marked] for n in ("b0", "b1", "b2"))))
    check(len(mark) == 2 and all(m[0] == tr for m in mark) and
          sorted(m[1] for m in mark) == [0, top],
          "%s: the mark is %s, expected x = %g from 0 to %d" % (label, mark, tr, top))
    check(all(tuple(m[2:]) == betti for m in mark),
          "%s: the Betti numbers at the mark are %s, the CLI prints %s at t_r %g" % (
              label, [m[2:] for m in mark], betti, tr))
    print("%s: %d profile rows, %d topology rows, mark %s" % (label, len(rows), len(rows3), mark),
          flush=True)
    # Where the mark is, the steps read the same Betti numbers.
    row = max(k for k, r in enumerate(topology) if r[0] < tr)
    check(topology[row][1:] == betti, "%s: B.csv reads %s at %g, the CLI prints %s" % (
        label, topology[row][1:], tr, betti))


def representation(view, recon, port):
    return simple.GetDisplayProperties(simple.OutputPort(recon, port),
                                       servermanager._getPyProxy(view))


def chart_settings(rep):
    return (rep.GetXMLName(), rep.AttributeType, rep.UseIndexForXAxis, rep.XArrayName,
            sorted(rep.SeriesVisibility))


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    # Given thresholds (t_p 1.1, t_r set below), as the CLI's --tp 1.1 --tr T.
    xyz, recon = torus_profiles(globals(), WORK, TMAX)

    controller = vtkSMParaViewPipelineControllerWithRendering()
    preferred = [controller.GetPreferredViewType(recon.SMProxy, k) for k in range(5)]
    print("preferred views:", preferred, flush=True)
    check(preferred[1] == "None" and preferred[3] == "FlowReconTopologyChartView",
          "ports 1 and 3 prefer %s and %s, expected None (no chart on Apply) and "
          "FlowReconTopologyChartView" % (preferred[1], preferred[3]))
    check(controller.ShowInPreferredView(recon.SMProxy, 1, None) is None,
          "port 1 opens a view on Apply")
    # Port 3 as Apply does in an empty layout frame (no view given, the preferred
    # one is made); port 1 as a user asks for it: a Line Chart View (log), then its eye.
    views = {3: controller.ShowInPreferredView(recon.SMProxy, 3, None),
             1: simple.CreateView("FlowReconLogChartView").SMProxy}
    check(controller.Show(recon.SMProxy, 1, views[1]) is not None,
          "port 1 cannot be shown in a Line Chart View (log)")
    names = {k: v.GetXMLName() if v else None for k, v in views.items()}
    if not check(names == {1: "FlowReconLogChartView", 3: "FlowReconTopologyChartView"},
                 "ports 1 and 3 open in %s" % names):
        return
    log_axis = [views[k].GetProperty("LeftAxisLogScale").GetElement(0) for k in (1, 3)]
    check(log_axis == [1, 0], "Left Axis Log Scale of the two charts: %s, expected on for "
          "the reconstruction profile only" % log_axis)
    titles = {k: (views[k].GetProperty("BottomAxisTitle").GetElement(0),
                  views[k].GetProperty("LeftAxisTitle").GetElement(0)) for k in (1, 3)}
    print("axis titles:", titles, flush=True)
    check(titles == {1: ("Step", "Priority, Threshold (ratio)"), 3: ("t_r", "Betti number")},
          "the charts' axis titles are %s" % titles)
    render_view = simple.CreateView("RenderView")
    again = controller.ShowInPreferredView(recon.SMProxy, 3, render_view.SMProxy)
    check(again is not None and again.GetXMLName() == "FlowReconTopologyChartView",
          "port 3 shown from a render view does not open a chart")

    settings = {k: chart_settings(representation(v, recon, k)) for k, v in views.items()}
    print("charts:", settings, flush=True)
    check(settings[1] == ("ReconstructionProfileRepresentation", "Row Data", 0, "Step",
                          ["Priority", "Threshold", "t_r"]),
          "port 1's chart is %s: expected Priority, Threshold and t_r against Step" % (
              settings[1],))
    widths = dict(zip(*[iter(representation(views[1], recon, 1).SeriesLineThickness)] * 2))
    check(widths.get("Priority") == "1" and widths.get("Threshold") == "2" and widths.get("t_r") == "2",
          "port 1's series are %s pixels wide, expected Priority 1, Threshold and t_r 2" % widths)
    check(settings[3] == ("TopologyProfileRepresentation", "Field Data", 0, "Threshold",
                          ["b0", "b1", "b2", "t_r"]),
          "port 3's chart is %s: expected b0, b1, b2 and t_r against Threshold, from the "
          "field data" % (settings[3],))

    p0, t0, s0 = outputs(recon)
    check_marks("t_r 2", 2.0, cli(xyz, 2.0), p0, t0, s0)
    for tr in (1.5, 3.0):
        recon.ReconstructionThreshold = tr
        recon.UpdatePipeline()
        for v in views.values():
            v.Update()
        p, t, s = outputs(recon)
        check_marks("t_r %g" % tr, tr, cli(xyz, tr), p, t, s)
        # Only the marks move.
        check(all(np.array_equal(p[n], p0[n]) for n in p0 if n != "t_r"),
              "t_r %g: a column of port 1 other than t_r changed" % tr)
        check(all(np.array_equal(t[n], t0[n]) for n in t0),
              "t_r %g: the rows of port 3 changed" % tr)
        now = {k: chart_settings(representation(v, recon, k)) for k, v in views.items()}
        check(now == settings, "t_r %g: the charts' settings changed to %s" % (tr, now))

    # Every Step shows the reconstruction at Maximum Threshold: the marks go there.
    recon.EveryStep = 1
    recon.UpdatePipeline()
    p, t, s = outputs(recon)
    x = s["Threshold"][~np.isnan(s["t_r"])]
    check(np.all(p["t_r"] == TMAX) and len(x) == 2 and np.all(x == TMAX),
          "Every Step: the marks are at %s and %s, not at Maximum Threshold %g" % (
              np.unique(p["t_r"]), x, TMAX))
    # Maximum Threshold 1e308, the GUI's "every step": the last interval ends
    # at the mark; with Every Step too, t_r is 1e308, which no mark could show
    # on a readable scale: no marks, and the steps end at the last change.
    recon.EveryStep = 0
    recon.ReconstructionThreshold = 2.0
    recon.MaximumThreshold = 1e308
    recon.UpdatePipeline()
    p, t, s = outputs(recon)
    x = s["Threshold"]
    check(x[-1] == max(2.0, t["Threshold"][-1]) and np.all(p["t_r"] == 2.0) and
          list(x[~np.isnan(s["t_r"])]) == [2.0, 2.0],
          "Maximum Threshold 1e308, t_r 2: the steps end at %s, the marks are at %s and %s" % (
              x[-1], np.unique(p["t_r"]), x[~np.isnan(s["t_r"])]))
    recon.EveryStep = 1
    recon.UpdatePipeline()
    p, t, s = outputs(recon)
    x = s["Threshold"]
    check(np.all(np.isnan(p["t_r"])) and np.all(np.isnan(s["t_r"])) and
          x[-1] == t["Threshold"][-1] and len(x) == 2 * len(t["Threshold"]),
          "Every Step at Maximum Threshold 1e308: marks %s and %s, steps ending at %s" % (
              np.unique(p["t_r"]), s["t_r"][~np.isnan(s["t_r"])], x[-1]))

main()
finish()
