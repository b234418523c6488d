"""GUI benchmark: how long the ParaView Qt GUI takes to show a new t_r, from the
click on Apply to idle (every view rendered, nothing pending), on a cloud:

    FLOWRECON_PLUGIN=build/lib/paraview-5.11/plugins/FlowRecon/FlowRecon.so \\
    FLOWRECON_DATA=CLOUD.xyz FLOWRECON_OUT=PREFIX \\
    PYTHONPATH=Testing/Python \\
    xvfb-run -a -s "-screen 0 1600x1000x24" paraview --dr --script=Benchmarks/gui_tr_latency.py

The pipeline is made as a user makes it (flowrecon_testing.gui_qt): the cloud opened
and shown, then Flow Complex, Flow Complex Simplification and Flow Reconstruction,
each chosen from the Filters menu and applied with the Apply button, every property
at its default; then Automatic Reconstruction Threshold is turned off and t_r set to
each of FLOWRECON_TR (default "3 2.5 3.5 2.8 3.2"), each applied with the Apply
button (with FLOWRECON_GEOMETRY=exact, Geometry is set to the exact stable manifolds
with Automatic Reconstruction Threshold; the default shows the compact geometry). For every Apply the script prints the seconds from the click to idle, and
where they went: in the click (the pipeline's update), in the filter's own
RequestData, and in the renders of each view (render windows' Start/End events).
Idle is the last render's end once nothing has been drawn for FLOWRECON_QUIET s
(default 1.5; not counted). FLOWRECON_MODE=one applies Reconstruct Point Cloud
instead of the three filters (and moves no t_r). With FLOWRECON_OUT=PREFIX the
layout is saved as PREFIX_layout.png.

Prints lines "gui_tr_latency: ..." with os.write (print() goes to the GUI's Output
Messages window), ends with "gui_tr_latency: done" and os._exit()s.
"""

import os
import time

from paraview.simple import *  # noqa: F401,F403

from flowrecon_testing.gui_plugin import load_plugin
from flowrecon_testing.gui_qt import Qt, check, run_in_gui, say
from flowrecon_testing.gui_views import mark_modified


class Renders:
    """Start/end times of every render window's renders (client side)."""

    def __init__(self):
        self.events = []  # (view name, start, end)
        self._open = {}
        self._watched = set()

    def watch(self):
        for view in GetViews():
            window = view.GetRenderWindow()
            key = view.GetGlobalID()
            if window is None or key in self._watched:
                continue
            self._watched.add(key)
            name = "%s#%d" % (view.GetXMLName(), key)
            window.AddObserver("StartEvent", lambda o, e, n=name: self._open.__setitem__(n, time.time()))
            window.AddObserver("EndEvent", lambda o, e, n=name: self.events.append(
                (n, self._open.pop(n, time.time()), time.time())))

    def since(self, t0):
        return [e for e in self.events if e[2] >= t0]


def wait_idle(qt, renders, t0, quiet):
    """Processes events until nothing renders for `quiet` s; the last render's end."""
    last = time.time()
    seen = len(renders.events)
    while time.time() - last < quiet:
        qt.process_events()
        if len(renders.events) != seen:
            seen = len(renders.events)
            last = time.time()
        time.sleep(0.005)
    ends = [e[2] for e in renders.since(t0)]
    return max(ends) if ends else last


def measured_apply(qt, accept, renders, label, quiet, algorithms):
    check(qt.enabled(accept), "%s: the Apply button is not enabled" % label)
    runs = []
    observers = []
    for algorithm in algorithms:
        state = {}
        observers.append((algorithm, algorithm.AddObserver(
            "StartEvent", lambda o, e, s=state: s.__setitem__("start", time.time()))))
        observers.append((algorithm, algorithm.AddObserver(
            "EndEvent", lambda o, e, s=state: runs.append(time.time() - s.get("start", time.time())))))
    t0 = time.time()
    qt.click(accept)
    clicked = time.time()
    renders.watch()  # views the Apply opened
    end = wait_idle(qt, renders, t0, quiet)
    for algorithm, tag in observers:
        algorithm.RemoveObserver(tag)
    per_view = {}
    for name, start, stop in renders.since(t0):
        n, s = per_view.get(name, (0, 0.0))
        per_view[name] = (n + 1, s + stop - start)
    total = max(end, clicked) - t0
    say("gui_tr_latency: %s: %.2f s from Apply to idle; click %.2f s (filter %.2f s); renders %s"
        % (label, total, clicked - t0, sum(runs),
           ", ".join("%s %dx %.2f s" % (k, n, s) for k, (n, s) in sorted(per_view.items()))))
    return total


def apply_from_menu(qt, accept, renders, input_source, name, quiet):
    SetActiveSource(input_source)
    qt.process_events()
    check(qt.create_filter("filters", name), "the Filters menu made no %s" % name)
    qt.process_events()
    source = GetActiveSource()
    measured_apply(qt, accept, renders, "Apply %s" % name, quiet, [source.GetClientSideObject()])
    return source


def main():
    data = os.environ["FLOWRECON_DATA"]
    quiet = float(os.environ.get("FLOWRECON_QUIET", "1.5"))
    values = [float(v) for v in os.environ.get("FLOWRECON_TR", "3 2.5 3.5 2.8 3.2").split()]
    one = os.environ.get("FLOWRECON_MODE", "") == "one"
    load_plugin(globals())
    qt = Qt()
    accept = qt.find(qt.main_widget(), "Accept", qt.widgets, "QPushButton")
    check(accept, "the Properties panel has no Apply (Accept) button")
    renders = Renders()
    t0 = time.time()
    reader = OpenDataFile(data)
    view = GetActiveViewOrCreate("RenderView")
    Show(reader, view)
    renders.watch()
    Render(view)
    wait_idle(qt, renders, t0, quiet)
    say("gui_tr_latency: %s opened and shown in %.2f s" % (data, time.time() - t0))
    if one:
        recon = apply_from_menu(qt, accept, renders, reader, "PointCloudReconstruction", quiet)
    else:
        fc = apply_from_menu(qt, accept, renders, reader, "FlowComplex", quiet)
        simp = apply_from_menu(qt, accept, renders, fc, "FlowComplexSimplification", quiet)
        recon = apply_from_menu(qt, accept, renders, simp, "FlowReconstruction", quiet)
    say("gui_tr_latency: views %s" % sorted(v.GetXMLName() for v in GetViews()))
    out = os.environ.get("FLOWRECON_OUT")
    if one:  # no t_r to move
        if out:
            SaveScreenshot(out + "_layout.png", GetLayout(view), ImageResolution=[1600, 900])
        say("gui_tr_latency: done")
        return
    algorithm = recon.GetClientSideObject()
    SetActiveSource(recon)
    qt.process_events()
    recon.AutomaticReconstructionThreshold = 0
    if os.environ.get("FLOWRECON_GEOMETRY") == "exact":
        recon.Geometry = "Exact stable manifolds"
    mark_modified(qt, recon)
    measured_apply(qt, accept, renders, "Automatic t_r off", quiet, [algorithm])
    mark = os.environ.get("FLOWRECON_MARK")
    if mark:  # for a profiler to attach to the t_r changes only
        open(mark, "w").write(str(os.getpid()))
        time.sleep(float(os.environ.get("FLOWRECON_MARK_WAIT", "5")))
    times = []
    for value in values:
        recon.ReconstructionThreshold = value
        mark_modified(qt, recon)
        times.append(measured_apply(qt, accept, renders, "t_r -> %g" % value, quiet, [algorithm]))
    cells = recon.GetDataInformation().GetNumberOfCells()
    times.sort()
    say("gui_tr_latency: t_r changes: median %.2f s, min %.2f s, max %.2f s over %d; %d cells shown"
        % (times[len(times) // 2], times[0], times[-1], len(times), cells))
    if out:
        SaveScreenshot(out + "_layout.png", GetLayout(view), ImageResolution=[1600, 900])
    say("gui_tr_latency: done")


run_in_gui(main, "gui_tr_latency")
