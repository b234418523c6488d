#!/usr/bin/python3
"""ParaView's "?" button shows the plugin's page for each of its filters and its reader,
in the real Qt GUI (needs an X server: run ctest under xvfb-run).

    /usr/bin/python3 test_help_gui.py PARAVIEW PLUGIN_DIR DATA_DIR OUTDIR QCH
    (QCH NO_HELP when the build has no help: skipped, exit 77)

Runs `paraview --script=<creates the pipeline> --test-script=<events> --exit` with
PV_PLUGIN_PATH=PLUGIN_DIR and a fresh settings folder in OUTDIR (no welcome dialog).
The pipeline: FlowRecon Point Cloud Reader (DATA_DIR/torus.xyz) -> Flow Complex ->
Flow Complex Simplification -> Flow Reconstruction, and Persistence Diagram on the
Flow Complex. The events (QtTesting XML, as ParaView's own GUI tests) select each
source in the Pipeline Browser, press the Properties panel's "?" and check the help
window's page: its title is the proxy's label and its address
qthelp://flowrecon.org/FlowRecon/<group>.<proxy>.html (Qt writes the host in lower case).
"""
import os
import sys

from flowrecon_testing.paraview_gui import gui_errors, run_paraview, say

HELP_BROWSER = "pqClientMainWindow/pqHelpWindow/1QTextBrowser0"
PIPELINE = "pqClientMainWindow/pipelineBrowserDock/pipelineBrowser"
HELP_BUTTON = "pqClientMainWindow/propertiesDock/propertiesPanel/Help"

# (pipeline browser path /row:column/..., group, proxy, label); builtin: is /0:0
SOURCES = [
    ("/0:0/0:0", "sources", "FlowReconPointCloudReader", "FlowRecon Point Cloud Reader"),
    ("/0:0/0:0/0:0", "filters", "FlowComplex", "Flow Complex"),
    ("/0:0/0:0/0:0/0:0", "filters", "FlowComplexSimplification", "Flow Complex Simplification"),
    ("/0:0/0:0/0:0/0:0/0:0", "filters", "FlowReconstruction", "Flow Reconstruction"),
    ("/0:0/0:0/0:0/1:0", "filters", "PersistenceDiagram", "Persistence Diagram"),
]

CREATE = '''
from paraview import simple
reader = simple.FlowReconPointCloudReader(registrationName="torus.xyz", FileName=[%r])
fc = simple.FlowComplex(Input=reader)
simp = simple.FlowComplexSimplification(Input=fc)
simple.FlowReconstruction(Input=simp)
simple.PersistenceDiagram(Input=fc)
simple.SetActiveSource(fc)
'''


def main():
    paraview, plugin_dir, data_dir, outdir, qch = sys.argv[1:6]
    if qch in ("", "NO_HELP"):
        say("the plugin was built without its help (see the configure warning): skipped")
        sys.exit(77)
    os.makedirs(outdir, exist_ok=True)
    script = os.path.join(outdir, "create_pipeline.py")
    with open(script, "w") as f:
        f.write(CREATE % os.path.join(os.path.abspath(data_dir), "torus.xyz"))
    events = []
    for path, group, name, label in SOURCES:
        events += [
            '<pqevent object="%s" command="mousePress" arguments="1,1,0,20,8,%s" />' % (PIPELINE, path),
            '<pqevent object="%s" command="mouseRelease" arguments="1,0,0,20,8,%s" />' % (PIPELINE, path),
            '<pqevent object="%s" command="activate" arguments="" />' % HELP_BUTTON,
            '<pqcheck object="%s" property="documentTitle" arguments="%s" />' % (HELP_BROWSER, label),
            '<pqcheck object="%s" property="source" arguments="qthelp://flowrecon.org/FlowRecon/%s.%s.html" />'
            % (HELP_BROWSER, group, name),
        ]
    rc, output = run_paraview(paraview, plugin_dir, outdir, events, args=["--script=" + script])
    errors = gui_errors(output)
    if rc != 0 or errors or "Success =  true" not in output:
        say(output)
        say("FAIL: paraview exited %d; %s" % (rc, errors[:5]))
        sys.exit(1)
    for path, group, name, label in SOURCES:
        say("? on %s (%s) shows qthelp://flowrecon.org/FlowRecon/%s.%s.html, titled %r" % (
            label, path, group, name, label))
    say("PASS")


if __name__ == "__main__":
    main()
