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

from paraview.simple import Connect, Disconnect, LoadPlugin
from paraview import servermanager


def serial(flowrecon, cloud, work):
    out = os.path.join(work, "serial.vtu")
    # both at their defaults: t_p and t_r chosen from the data, and the compact
    # output (the command line's default, and the filter's Geometry in ParaView)
    subprocess.run([flowrecon, "reconstruct", cloud, "-o", out, "--quiet"], check=True)
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(out)
    r.Update()
    cells = r.GetOutput().GetNumberOfCells()
    info = subprocess.run([flowrecon, "info", cloud], check=True, capture_output=True, text=True).stdout
    counts = [l for l in info.splitlines() if l.startswith("nodes by index")][0].split()[3:7]
    return cells, [int(c) for c in counts]


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
    counts_array = fd.GetArray("NodeCountByIndex")
    counts = [int(counts_array.GetComponent(0, k)) for k in range(4)]
    expected_cells, expected_counts = serial(flowrecon, cloud, work)
    mode = "client/server" if remote else "pvbatch (%s)" % os.environ.get("OMPI_COMM_WORLD_SIZE", "1 rank")
    print("%s: %d cells (serial %d), nodes by index %s (serial %s)"
          % (mode, cells, expected_cells, counts, expected_counts))
    assert cells == expected_cells > 0, (cells, expected_cells)
    assert counts == expected_counts and counts[0] > 0, (counts, expected_counts)
    print("PASS")
    sys.stdout.flush()
    if remote:
        Disconnect()  # lets the server end its session before the client exits


main()
