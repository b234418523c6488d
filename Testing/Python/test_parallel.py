"""The plugin in ParaView's parallel settings gives the serial answer.

    pvbatch test_parallel.py PLUGIN FLOWRECON CLOUD WORKDIR [--server HOST:PORT]

Computes Flow Complex -> Simplification -> Reconstruction (defaults) on CLOUD through
ParaView proxies and compares the number of reconstruction cells and the Euler
characteristic of the flow complex with the serial command-line tool FLOWRECON run
on the same file (an independent process). Run under `mpiexec -n 2 pvbatch` it
checks the MPI path (the flow complex is computed on rank 0); with --server it
connects to a running pvserver and loads the plugin there (client/server).
"""
import os
import subprocess
import sys

from paraview.simple import Connect, LoadPlugin
from paraview import servermanager


def serial(flowrecon, cloud, work):
    out = os.path.join(work, "serial.vtu")
    subprocess.run([flowrecon, "reconstruct", cloud, "-o", out, "--quiet"], check=True)
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(out)
    r.Update()
    cells = r.GetOutput().GetNumberOfCells()
    info = subprocess.run([flowrecon, "info", cloud], check=True, capture_output=True, text=True).stdout
    euler = [l for l in info.splitlines() if l.startswith("Euler characteristic")][0].split()[2]
    return cells, int(euler)


def main():
    plugin, flowrecon, cloud, work = sys.argv[1:5]
    os.makedirs(work, exist_ok=True)
    remote = "--server" in sys.argv
    if remote:
        host, port = sys.argv[sys.argv.index("--server") + 1].split(":")
        Connect(host, int(port))
    LoadPlugin(plugin, remote=remote, ns=globals())
    ns = globals()
    from paraview.simple import CSVReader
    # .xyz through ParaView's CSV reader (a vtkTable, which the filter accepts):
    # whitespace separated, no header.
    reader = CSVReader(FileName=[cloud], HaveHeaders=0, FieldDelimiterCharacters=" ",
                       MergeConsecutiveDelimiters=1)
    fc = ns["FlowComplex"](Input=reader)
    simplified = ns["FlowComplexSimplification"](Input=fc)
    recon = ns["FlowReconstruction"](Input=simplified)
    recon.UpdatePipeline()
    cells = recon.GetDataInformation().GetNumberOfCells()
    fc.UpdatePipeline()
    fd = servermanager.Fetch(fc).GetFieldData()
    euler = int(fd.GetArray("EulerCharacteristic").GetValue(0))
    expected_cells, expected_euler = serial(flowrecon, cloud, work)
    mode = "client/server" if remote else "pvbatch (%s)" % os.environ.get("OMPI_COMM_WORLD_SIZE", "1 rank")
    print("%s: %d cells (serial %d), Euler characteristic %d (serial %d)"
          % (mode, cells, expected_cells, euler, expected_euler))
    assert cells == expected_cells > 0, (cells, expected_cells)
    assert euler == expected_euler == 1, (euler, expected_euler)
    print("PASS")


main()
