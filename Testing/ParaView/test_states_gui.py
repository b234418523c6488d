#!/usr/bin/python3
"""The example states and the plugin's reader in the real ParaView 5.11 Qt GUI, driven
by QtTesting events as ParaView's own GUI tests (needs an X server: run ctest under
xvfb-run). The GUI runs in a fresh empty working folder, with fresh settings.

    /usr/bin/python3 test_states_gui.py MODE PARAVIEW PLUGIN_DIR DATA_DIR OUTDIR

MODE
  load     File > Load State of DATA_DIR/torus.pvsm, demo.pvsm and bunny.pvsm: the
           Load State Options dialog's directory is already the state's folder; choosing
           "Search files under specified directory" and OK loads the state without an
           error, and the torus's spreadsheet shows its Betti numbers (1, 2, 1).
  cmdline  paraview --state=DATA_DIR/torus.pvsm, which shows no dialog, with the user
           setting LoadStateOptions.LoadStateDataFileOptions = 1 the help recommends:
           loads without an error, Betti numbers (1, 2, 1). (Without that setting
           ParaView 5.11 uses the file names of the state as they are, relative to its
           working folder: "Data/torus.xyz: no such file"; printed, not failed.)
  reader   File > Open of DATA_DIR/torus.xyz: ParaView asks which reader to use; the
           plugin's is the first of 3 and selected. "Set reader as default" stores it
           in the settings, and the next .xyz (two_hemispheres.xyz) opens without the
           question, as polygonal points (the XYZ Reader would give a molecule).
"""
import json
import os
import sys
import tempfile

from flowrecon_testing.paraview_gui import gui_errors, run_paraview, say

MAIN = "pqClientMainWindow"
OPTIONS = "LoadStateOptionsDialog"
OPTION_WIDGETS = OPTIONS + "/scrollArea/qt_scrollarea_viewport/Container/ProxyWidget"
SPREADSHEET = (MAIN + "/centralwidget/MultiViewWidget/CoreWidget/qt_tabwidget_stackedwidget/"
               "MultiViewWidget1/Container/Frame.2/CentralWidgetFrame/Viewport/"
               "1pqSpreadSheetViewWidget0")
INFO = (MAIN + "/informationDock/informationWidgetFrame/informationScrollArea/"
        "qt_scrollarea_viewport/informationWidget")
READER_DIALOG = MAIN + "/pqSelectReaderDialog"


def event(obj, command, arguments=""):
    return '<pqevent object="%s" command="%s" arguments="%s" />' % (obj, command, arguments)


def check(obj, prop, arguments):
    return '<pqcheck object="%s" property="%s" arguments="%s" />' % (obj, prop, arguments)


def torus_betti_checks():
    # the state's spreadsheet shows the field data of "Reconstruction (automatic t_r)":
    # BettiNumbers one row per dimension, in column 7 of ParaView 5.11's model (after
    # the chosen thresholds, their window, warnings and the Topology line; probed cell
    # by cell)
    return [check(SPREADSHEET, "modelRowCount", "3")] + [
        check(SPREADSHEET, "modelItemData", "%d.7,%d" % (row, value))
        for row, value in enumerate((1, 2, 1))]


def load_events(data_dir):
    events = []
    for name in ("torus", "demo", "bunny"):  # the torus first: its layout is MultiViewWidget1
        state = os.path.join(data_dir, name + ".pvsm")
        events += [
            event(MAIN + "/menubar/menu_File", "activate", "actionFileLoadServerState"),
            event(MAIN + "/FileLoadServerStateDialog", "filesSelected", state),
            check(OPTION_WIDGETS + "/DataDirectory/FileChooser/FileLineEdit", "text", data_dir),
            event(OPTION_WIDGETS + "/LoadStateDataFileOptions/ComboBox", "set_string",
                  "Search files under specified directory"),
            event(OPTIONS + "/widget/OKButton", "activate"),
        ]
        if name == "torus":
            events += torus_betti_checks()
    return events


def reader_events(data_dir):
    return [
        event(MAIN + "/menubar/menu_File", "activate", "actionFileOpen"),
        event(MAIN + "/FileOpenDialog", "filesSelected", os.path.join(data_dir, "torus.xyz")),
        check(READER_DIALOG + "/listWidget", "modelRowCount", "3"),
        check(READER_DIALOG + "/listWidget", "modelItemData", "0.0,FlowRecon Point Cloud Reader"),
        check(READER_DIALOG + "/listWidget", "currentRow", "0"),
        # ticking "Set reader as default" accepts the dialog with the selected reader
        event(READER_DIALOG + "/setAsDefault", "set_boolean", "true"),
        event(MAIN + "/propertiesDock/propertiesPanel/Accept", "activate"),
        check(INFO + "/dataType", "text", "Polygonal Mesh"),
        event(MAIN + "/menubar/menu_File", "activate", "actionFileOpen"),
        event(MAIN + "/FileOpenDialog", "filesSelected",
              os.path.join(data_dir, "two_hemispheres.xyz")),  # no question this time
        event(MAIN + "/propertiesDock/propertiesPanel/Accept", "activate"),
        check(INFO + "/dataType", "text", "Polygonal Mesh"),
    ]


def main():
    mode, paraview, plugin_dir, data_dir, outdir = sys.argv[1:6]
    data_dir = os.path.abspath(data_dir)
    os.makedirs(outdir, exist_ok=True)
    work = tempfile.mkdtemp(prefix="flowrecon_gui_", dir=outdir)  # empty working folder
    if mode == "load":
        rc, output = run_paraview(paraview, plugin_dir, outdir, load_events(data_dir), cwd=work)
    elif mode == "cmdline":
        state = "--state=" + os.path.join(data_dir, "torus.pvsm")
        rc0, output0 = run_paraview(paraview, plugin_dir, outdir, torus_betti_checks(),
                                    args=[state], cwd=work)
        say("without the setting (ParaView 5.11's default, %s): exit %d, %s" % (
            "File Names From State", rc0,
            [line for line in output0.splitlines() if "no such file" in line][:1]))
        settings = json.dumps({"options": {"LoadStateOptions": {"LoadStateDataFileOptions": 1}}})
        rc, output = run_paraview(paraview, plugin_dir, outdir, torus_betti_checks(),
                                  args=[state], settings=settings, cwd=work)
    elif mode == "reader":
        rc, output = run_paraview(paraview, plugin_dir, outdir, reader_events(data_dir), cwd=work)
    else:
        raise SystemExit("unknown mode %s" % mode)
    errors = gui_errors(output)
    if rc != 0 or errors or "Success =  true" not in output:
        say(output)
        say("FAIL: %s: paraview exited %d; %s" % (mode, rc, errors[:5]))
        sys.exit(1)
    if mode == "reader":
        path = os.path.join(outdir, "home", ".config", "ParaView", "ParaView-UserSettings.json")
        with open(path) as f:
            details = json.load(f)["settings"]["RepresentedArrayListSettings"]["ReaderDetails"]
        if details[2::3] != ["FlowReconPointCloudReader"]:
            say("FAIL: default readers in the settings: %s" % details)
            sys.exit(1)
        say("default reader stored in the user settings: %s" % details)
    say("%s: done in %s without an error" % (mode, work))
    say("PASS")


if __name__ == "__main__":
    main()
