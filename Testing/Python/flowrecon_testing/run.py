"""Run the command-line tool `flowrecon` and read what it writes: the VTK and CSV
files, and the lines it prints."""
import csv
import math
import subprocess

import numpy as np


def call(flowrecon, *args):
    """(exit code, stdout, stderr) of `flowrecon ARGS`."""
    p = subprocess.run([flowrecon, *args], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def run(flowrecon, *args, quiet=False):
    """stdout of `flowrecon ARGS`; stops the test when the run fails or, with quiet,
    writes anything on stderr."""
    code, out, err = call(flowrecon, *args)
    if code != 0 or (quiet and err):
        raise SystemExit("flowrecon %s failed (%d): %s" % (" ".join(args), code, err))
    return out


def printed_betti(stdout):
    """The Betti numbers of reconstruct's one 'Betti numbers: b0 b1 b2' line."""
    lines = [line for line in stdout.splitlines() if line.startswith("Betti numbers: ")]
    if len(lines) != 1:
        raise SystemExit("expected one 'Betti numbers:' line in:\n" + stdout)
    return tuple(int(x) for x in lines[0].split()[2:])


def read_grid(path):
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def read_multiblock(path):
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader
    r = vtkXMLMultiBlockDataReader()
    r.SetFileName(path)
    r.Update()
    return r.GetOutput()


def cells(path, arrays, below=None):
    """The cells of a .vtu (those of Threshold < below, if given): (each one's vertex
    coordinates, as lists; {name: that cell array, as numpy})."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    g = read_grid(path)
    pts = vtk_to_numpy(g.GetPoints().GetData())
    off = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    data = {a: vtk_to_numpy(g.GetCellData().GetArray(a)) for a in arrays}
    if below is None:
        keep = range(g.GetNumberOfCells())
    else:
        keep = np.nonzero(vtk_to_numpy(g.GetCellData().GetArray("Threshold")) < below)[0]
        data = {a: v[keep] for a, v in data.items()}
    return [pts[conn[off[c]:off[c + 1]]].tolist() for c in keep], data


def field(path, name):
    """The first components of the field data array `name` of a .vtu, or None."""
    a = read_grid(path).GetFieldData().GetArray(name)
    return None if a is None else [a.GetComponent(i, 0) for i in range(a.GetNumberOfTuples())]


def read_diagram(path):
    """(header, [(dimension, birth, death)]) of `flowrecon diagram`'s CSV."""
    with open(path) as f:
        header = f.readline().strip()
        rows = [line.strip().split(",") for line in f if line.strip()]
    return header, [(int(d), float(b), math.inf if e == "inf" else float(e)) for d, b, e in rows]


def read_topology_profile(path):
    """[(threshold, (b0, b1, b2))] of `--topology-profile`'s CSV."""
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [(float(r["threshold"]), (int(r["b0"]), int(r["b1"]), int(r["b2"]))) for r in rows]
