#!/usr/bin/python3
"""The plugin makes ParaView 5.11's Qt GUI write no warning: no Output Messages
window opens when a user loads an example state or applies a FlowRecon filter
(needs an X server: run ctest under xvfb-run).

    /usr/bin/python3 test_quiet_gui.py PARAVIEW PLUGIN ROOT OUTDIR

Runs the GUI twice with gui_quiet.py (fresh settings in OUTDIR, working folder ROOT,
the repository's root, where the states find Data/*.xyz): once applying Flow Complex,
Flow Complex Simplification, Flow Reconstruction, Persistence Diagram and
Reconstruct Point Cloud to ROOT/Data/torus.xyz from the Filters menu, once loading ROOT/Data/*.pvsm. Two runs,
because the GUI warns of a missing Pipeline Browser icon only the first time it meets
the view type. Every message the Output Messages window shows is also written to the
terminal, as "warning: ..." or "critical: ..." (ParaView's Qt message format) or in
VTK's "ERR|"/"WARN|" form; any such line fails the test, and is reported with the
step it came after (a state or a filter). Prints PASS or FAIL.
"""
import glob
import os
import sys

from flowrecon_testing.paraview_gui import fresh_home, run_gui, say

HERE = os.path.dirname(os.path.abspath(__file__))
MARKERS = ("warning:", "critical:", "ERR|", "WARN|", "Could not find icon")


def run(paraview, plugin, root, outdir, states):
    env = fresh_home(outdir)
    env.update(FLOWRECON_EXIT="1", FLOWRECON_PLUGIN=plugin,
               FLOWRECON_DATA=os.path.join(root, "Data", "torus.xyz"),
               FLOWRECON_STATES=os.pathsep.join(states))
    env.pop("PV_PLUGIN_PATH", None)  # the script loads the plugin
    cmd = [paraview, "--dr", "--script=" + os.path.join(HERE, "gui_quiet.py")]
    return run_gui(cmd, env, root, 400)


def messages(output):
    """[(step, line)] of the lines that ParaView's message output wrote."""
    step, found = "start-up", []
    for line in output.splitlines():
        if line.startswith("gui_quiet: step "):
            step = line[len("gui_quiet: step "):]
        elif any(m in line for m in MARKERS) and "QStandardPaths" not in line:
            found.append((step, line.strip()))
    return found


def main():
    paraview, plugin, root, outdir = sys.argv[1:5]
    root = os.path.abspath(root)
    os.makedirs(outdir, exist_ok=True)
    states = sorted(os.path.relpath(p, root) for p in glob.glob(os.path.join(root, "Data", "*.pvsm")))
    if len(states) < 3:
        say("FAIL: expected the example states demo, torus and bunny in Data/, found %s" % states)
        sys.exit(1)
    failed = False
    for what, run_states in (("the filters from the menu", []), ("the example states", states)):
        rc, output = run(paraview, plugin, root, outdir, run_states)
        found = messages(output)
        if rc != 0 or "gui_quiet: PASS" not in output:
            say(output)
            say("FAIL: %s: paraview exited %d without gui_quiet: PASS" % (what, rc))
            failed = True
            continue
        for step, line in found:
            say("FAIL: %s: after '%s' ParaView wrote: %s" % (what, step, line))
        failed = failed or bool(found)
        if not found:
            say("%s: no message written (%d steps)" % (
                what, output.count("gui_quiet: step ")))
    if failed:
        sys.exit(1)
    say("PASS")


if __name__ == "__main__":
    main()
