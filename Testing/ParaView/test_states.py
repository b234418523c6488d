#!/usr/bin/env pvpython
"""Every example state Data/*.pvsm loads from any working folder the way ParaView's
File > Load State does, with the plugin's own reader.

    pvpython Testing/ParaView/test_states.py DATA_DIR            (plugin from PV_PLUGIN_PATH)
    pvpython Testing/ParaView/test_states.py --reader DATA_DIR   (the preferred reader)

Copies nothing: works in a fresh temporary folder (so the states' relative file names
"Data/<cloud>.xyz" do not resolve from the working folder) and loads each state as
pqLoadStateReaction does in ParaView 5.11: a LoadStateOptions proxy whose DataDirectory
is the state file's folder, PrepareToLoad, then the one choice a user makes in the
"Load State Options" dialog, "Search files under specified directory"; then Load.
Checks: each reader is the plugin's FlowReconPointCloudReader with a file found in
DATA_DIR, no CSV reader is left, every reconstruction has points and cells, and the
torus state shows the known Betti numbers (1, 2, 1) at the automatic t_r
(at t_r 1.8, the hidden one, holes remain where the sampling is sparse).

With --reader: OpenDataFile (paraview.simple, which uses the reader factory's first
reader that can read a file) gives the plugin's FlowReconPointCloudReader for the .xyz
clouds of DATA_DIR and a .pts file; the reader factory lists it first among the
readers of .xyz (the one ParaView's "choose a reader" dialog selects); and ParaView
5.11's only way to skip that dialog, the default-reader setting that its "Set reader as
default" box writes (RepresentedArrayListSettings.ReaderDetails), exists.
"""
import glob
import os
import sys
import tempfile

from paraview import servermanager, simple
from paraview.modules.vtkRemotingServerManager import vtkSMParaViewPipelineController

from flowrecon_testing.checks import fail

EXPECTED_STATES = {"demo", "torus", "bunny"}
CLOUDS = {"demo": "two_hemispheres.xyz", "torus": "torus.xyz", "bunny": "bunny.xyz"}
BETTI = {"torus": {"Reconstruction (automatic t_r)": (1, 2, 1)}}
USE_DATA_DIRECTORY = 1  # "Search files under specified directory"


def load_like_the_gui(state):
    """pqLoadStateReaction::loadState (ParaView 5.11), with the dialog's second option."""
    simple.RemoveViewsAndLayouts()  # clearViewsForLoadingState
    for proxy in list(simple.GetSources().values()):
        simple.Delete(proxy)
    pxm = servermanager.ActiveConnection.Session.GetSessionProxyManager()
    options = pxm.NewProxy("options", "LoadStateOptions")
    options.GetProperty("DataDirectory").SetElement(0, os.path.dirname(state))
    if not options.PrepareToLoad(state):
        fail("PrepareToLoad(%s)" % state)
    vtkSMParaViewPipelineController().InitializeProxy(options)
    directory = options.GetProperty("DataDirectory").GetElement(0)
    if directory != os.path.dirname(state):
        fail("the dialog's data directory is %r, not the state's folder" % directory)
    if not options.HasDataFiles():
        fail("%s names no data file" % state)
    options.GetProperty("LoadStateDataFileOptions").SetElement(0, USE_DATA_DIRECTORY)
    options.UpdateVTKObjects()
    if not options.Load():
        fail("Load(%s)" % state)
    options.UnRegister(None)


def field_betti(source):
    grid = servermanager.Fetch(source)
    array = grid.GetFieldData().GetArray("BettiNumbers")
    if array is None:
        fail("%s has no BettiNumbers field data" % source.GetXMLLabel())
    return tuple(int(array.GetValue(k)) for k in range(3))


def check_preferred_reader(data_dir):
    work = tempfile.mkdtemp(prefix="flowrecon_reader_")
    pts = os.path.join(work, "cloud.pts")  # a .pts cloud: the torus's first 500 points
    with open(os.path.join(data_dir, "torus.xyz")) as src, open(pts, "w") as dst:
        dst.writelines(line for k, line in enumerate(src) if k < 500)
    clouds = sorted(glob.glob(os.path.join(data_dir, "*.xyz"))) + [pts]
    factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
    if factory.GetNumberOfRegisteredPrototypes() == 0:  # filled lazily, as OpenDataFile does
        factory.UpdateAvailableReaders()
    session = servermanager.ActiveConnection.Session
    for path in clouds:
        listed = factory.GetReaders(path, session)
        readers = [(listed.GetString(k), listed.GetString(k + 1), listed.GetString(k + 2))
                   for k in range(0, listed.GetLength(), 3)]
        if not readers or readers[0][1] != "FlowReconPointCloudReader":
            fail("%s: the readers are %s, the plugin's is not the first" % (path, readers))
        source = simple.OpenDataFile(path)
        if source is None or source.GetXMLName() != "FlowReconPointCloudReader":
            fail("OpenDataFile(%s) gives %s" % (path, source and source.GetXMLName()))
        source.UpdatePipeline()
        n_points = source.GetDataInformation().GetNumberOfPoints()
        if n_points < 4:
            fail("%s: %d points" % (path, n_points))
        print("%s: OpenDataFile -> %s, %d points; readers offered: %s" % (
            os.path.basename(path), source.GetXMLName(), n_points,
            ", ".join(label for _, _, label in readers)))
        simple.Delete(source)
    settings = servermanager.ActiveConnection.Session.GetSessionProxyManager().GetProxy(
        "settings", "RepresentedArrayListSettings")
    if settings is None or settings.GetProperty("ReaderDetails") is None:
        fail("no RepresentedArrayListSettings.ReaderDetails (the default-reader setting)")
    print("PASS")


def main():
    if sys.argv[1] == "--reader":
        if not hasattr(simple, "FlowReconPointCloudReader"):
            fail("the plugin is not loaded (PV_PLUGIN_PATH)")
        check_preferred_reader(os.path.abspath(sys.argv[2]))
        return
    data_dir = os.path.abspath(sys.argv[1])
    states = sorted(glob.glob(os.path.join(data_dir, "*.pvsm")))
    names = {os.path.splitext(os.path.basename(s))[0] for s in states}
    if not EXPECTED_STATES <= names:
        fail("missing states: %s" % sorted(EXPECTED_STATES - names))
    if not hasattr(simple, "FlowReconPointCloudReader"):
        fail("the plugin is not loaded (PV_PLUGIN_PATH)")

    work = tempfile.mkdtemp(prefix="flowrecon_states_")
    os.chdir(work)
    for state in states:
        name = os.path.splitext(os.path.basename(state))[0]
        with open(state) as f:
            text = f.read()
        if 'type="CSVReader"' in text or 'type="TableToPoints"' in text:
            fail("%s still reads its cloud with the CSV reader" % state)
        load_like_the_gui(state)
        sources = {key[0]: proxy for key, proxy in simple.GetSources().items()}
        readers = [p for p in sources.values() if p.GetXMLGroup() == "sources"]
        if len(readers) != 1 or readers[0].GetXMLName() != "FlowReconPointCloudReader":
            fail("%s: readers %s, expected one FlowReconPointCloudReader" % (
                name, [(p.GetXMLGroup(), p.GetXMLName()) for p in readers]))
        reader = readers[0]
        files = reader.FileName
        files = [files] if isinstance(files, str) else list(files)
        if name in CLOUDS and files != [os.path.join(data_dir, CLOUDS[name])]:
            fail("%s: reader file %s, expected %s" % (name, files,
                                                       os.path.join(data_dir, CLOUDS[name])))
        if not all(os.path.isabs(f) and os.path.exists(f) for f in files):
            fail("%s: reader file %s not found" % (name, files))
        reader.UpdatePipeline()
        n_points = reader.GetDataInformation().GetNumberOfPoints()
        recons = {n: p for n, p in sources.items() if p.GetXMLName() == "FlowReconstruction"}
        if n_points < 4 or not recons:
            fail("%s: %d points, reconstructions %s" % (name, n_points, sorted(recons)))
        summary = []
        for label, recon in sorted(recons.items()):
            recon.UpdatePipeline()
            info = recon.GetDataInformation()
            if info.GetNumberOfPoints() == 0 or info.GetNumberOfCells() == 0:
                fail("%s: %s is empty" % (name, label))
            betti = field_betti(recon)
            expected = BETTI.get(name, {}).get(label)
            if expected is not None and betti != expected:
                fail("%s: %s has Betti numbers %s, expected %s" % (name, label, betti, expected))
            summary.append("%s: %d cells, Betti %s%s" % (label, info.GetNumberOfCells(), betti,
                                                         " (expected)" if expected else ""))
        if name in BETTI and set(BETTI[name]) - set(recons):
            fail("%s: no %s" % (name, sorted(set(BETTI[name]) - set(recons))))
        print("%s.pvsm from %s: reader %s on %s (%d points); %s" % (
            name, work, reader.GetXMLName(), files[0], n_points, "; ".join(summary)))
    print("PASS")


if __name__ == "__main__":
    main()
