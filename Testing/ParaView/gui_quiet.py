"""What test_quiet_gui.py runs inside the ParaView Qt GUI (paraview --script=...):
with FLOWRECON_STATES (paths joined by os.pathsep), loads each state (File > Load
State's reaction without its dialog, as paraview --state= does: the file names as
stored, relative to the working folder); without, reads FLOWRECON_DATA with the
plugin's reader and applies each of the plugin's filters as the Filters menu and the
Apply button do (Flow Complex, Flow Complex Simplification, Flow Reconstruction,
Persistence Diagram, Reconstruct Point Cloud), with the render view active. Prints "gui_quiet: step ..." before each
step, so that a message on the terminal is placed between two of them, then
"gui_quiet: PASS" and os._exit()s. Whether ParaView wrote a warning is judged by
test_quiet_gui.py from the terminal output (what the Output Messages window shows
is written there too).
"""

import os

from flowrecon_testing.gui_plugin import load_plugin
from flowrecon_testing.gui_qt import Qt, check, run_in_gui, say

from paraview.simple import *  # noqa: F401,F403

FILTERS = ("FlowComplex", "FlowComplexSimplification", "FlowReconstruction",
           "PersistenceDiagram", "PointCloudReconstruction")


def step(what):
    """The marker of a step, after what C++ wrote so far (std::cout, stdio): the
    terminal's order is then the order of the steps."""
    import ctypes
    libstdcxx = ctypes.CDLL("libstdc++.so.6")
    flush = libstdcxx._ZNSo5flushEv
    flush.argtypes = [ctypes.c_void_p]
    for stream in ("_ZSt4cout", "_ZSt4cerr"):
        flush(ctypes.addressof(ctypes.c_char.in_dll(libstdcxx, stream)))
    ctypes.CDLL(None).fflush(None)
    say("gui_quiet: step %s" % what)


def load_state_as_gui(qt, path):
    """pqLoadStateReaction::loadState(path, dialogBlocked=true, active server): what
    paraview --state=PATH does (the file names as stored, relative to the working
    folder, which is the repository's root here)."""
    import ctypes
    f = qt.components["_ZN19pqLoadStateReaction9loadStateERK7QStringbP8pqServer"]
    f.argtypes = [ctypes.c_void_p, ctypes.c_bool, ctypes.c_void_p]
    f.restype = None
    f(qt.qstring(path), True, None)


def apply_from_menu(qt, accept, input_source, name):
    SetActiveSource(input_source)
    qt.process_events()
    check(qt.create_filter("filters", name), "createFilter made no %s" % name)
    qt.process_events()
    check(qt.enabled(accept), "Apply is not enabled after choosing %s" % name)
    qt.click(accept)
    qt.process_events()
    source = GetActiveSource()
    check(source is not None and source.GetXMLName() == name, "%s was not applied" % name)
    return source


def main():
    data = os.environ["FLOWRECON_DATA"]
    load_plugin(globals())
    qt = Qt()
    main_widget = qt.main_widget()
    accept = qt.find(main_widget, "Accept", qt.widgets, "QPushButton")
    check(accept, "the Properties panel has no Apply (Accept) button")

    states = [s for s in os.environ.get("FLOWRECON_STATES", "").split(os.pathsep) if s]
    for state in states:
        step("load state %s" % os.path.basename(state))
        load_state_as_gui(qt, state)
        qt.process_events()
        names = sorted(s[0] for s in GetSources())
        check(any(n.startswith("Reconstruction") for n in names),
              "state %s loaded no reconstruction: %s" % (state, names))
    if states:
        step("done")
        say("gui_quiet: PASS")
        return

    reader = OpenDataFile(data)
    Show(reader, GetActiveViewOrCreate("RenderView"))
    qt.process_events()
    inputs = {"FlowComplex": reader, "PointCloudReconstruction": reader}
    for name in FILTERS:
        step("apply %s" % name)
        source = apply_from_menu(qt, accept, inputs[name], name)
        if name == "FlowComplex":
            inputs.update(FlowComplexSimplification=source, PersistenceDiagram=source)
        elif name == "FlowComplexSimplification":
            inputs["FlowReconstruction"] = source
        # back to the render view, where the next filter's input is shown
        SetActiveView(GetRenderViews()[0])
    qt.process_events()
    step("done")
    say("gui_quiet: PASS")


run_in_gui(main, "gui_quiet")
