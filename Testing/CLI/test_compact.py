"""The default output of `reconstruct` (Delaunay simplices on the samples) has
the Betti numbers of the exact reconstruction, which `--exact` writes.

For each cloud (the bundled torus; generated surfaces, a solid, a curve, a
sphere with a segment, and two spheres whose patches once closed a spurious void),
`reconstruct` runs at the automatic thresholds by default and with --exact. The
Betti numbers of the default file, computed by GUDHI over its cells (an oracle
written by others), must equal those both runs print for the reconstruction
(from its Hasse diagram), the compact ones the default run prints, and GUDHI's
of the --exact file. The default file must be over the input points alone
(point k = input point k, no constructed point), hold only vertices, segments,
triangles and tetrahedra with NodeId, Index and a Threshold below the t_r
printed, have fewer cells than the exact one, and state the answer in its field
data as the exact file does (Topology, the thresholds, their warnings).
`--compact`, kept for compatibility, writes the same file byte for byte. From a
stored flow complex (.vtm, written by `complex`), the default file must have the
same cells as from the cloud.
Usage: test_compact.py FLOWRECON WORKDIR
"""
import filecmp
import os
import re
import sys

import generate_clouds as gc
import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.oracles import default_output_problems, gudhi_betti

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
os.makedirs(WORK, exist_ok=True)
failures = []
# The answer the file states, as the exact file does.
ANSWER = ("Topology", "ReconstructionThreshold", "PersistenceThreshold", "ThresholdsChosen",
          "StableWindow", "ThresholdWarnings")


def field_values(grid, name):
    a = grid.GetFieldData().GetAbstractArray(name)
    return None if a is None else [a.GetVariantValue(k).ToString() for k in range(a.GetNumberOfValues())]


def check(name, points):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    path = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(path, points)
    exact_out = fr.run(FLOWRECON, "reconstruct", path, "-o", path + ".exact.vtu", "--exact")
    code, out, err = fr.call(FLOWRECON, "reconstruct", path, "-o", path + ".compact.vtu")
    if code != 0:
        failures.append("%s: exit %d: %s" % (name, code, err.strip()))
        return
    grid, exact_grid = fr.read_grid(path + ".compact.vtu"), fr.read_grid(path + ".exact.vtu")
    exact = fr.printed_betti(exact_out)
    tr = float(re.search(r"steps at t_r (\S+)$", out, re.M).group(1))
    print("%s (%d points): exact %s, default by GUDHI %s; %d cells, exact %d" % (
        name, len(points), exact, gudhi_betti(grid), grid.GetNumberOfCells(),
        exact_grid.GetNumberOfCells()))
    failures.extend("%s: %s" % (name, p) for p in default_output_problems(path + ".compact.vtu", out, err))
    if fr.printed_betti(out) != exact:
        failures.append("%s: the default run printed other exact Betti numbers" % name)
    if gudhi_betti(exact_grid) != exact:
        failures.append("%s: the --exact file's Betti numbers by GUDHI %s, printed %s"
                        % (name, gudhi_betti(exact_grid), exact))
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    if pts.shape != points.shape or not np.array_equal(pts, np.asarray(points, dtype=float)):
        failures.append("%s: the default file's points are not the input points" % name)
    types = set(vtk_to_numpy(grid.GetCellTypesArray()).tolist())
    if not types <= {1, 3, 5, 10}:
        failures.append("%s: cell types %s" % (name, sorted(types)))
    cd = grid.GetCellData()
    if any(cd.GetArray(a) is None for a in ("NodeId", "Index", "Threshold")):
        failures.append("%s: missing cell data" % name)
    elif not (vtk_to_numpy(cd.GetArray("Threshold")) < tr).all():
        failures.append("%s: a cell of Threshold >= t_r %g" % (name, tr))
    if grid.GetNumberOfCells() >= exact_grid.GetNumberOfCells():
        failures.append("%s: not compact" % name)
    differ = [a for a in ANSWER if field_values(grid, a) != field_values(exact_grid, a)]
    if differ or field_values(grid, "Topology") is None:
        failures.append("%s: the default file's field data %s are not the exact file's" % (name, differ))


check("bundled_torus", gc.read_xyz(os.path.join(DATA, "torus.xyz")))
for shape in ("sphere_qu", "genus2_pd", "ball", "trefoil_qu", "sphere_with_segment", "two_spheres"):
    check(shape, gc.make(shape))

# --compact: the default, byte for byte.
path = os.path.join(WORK, "two_spheres.xyz")
fr.run(FLOWRECON, "reconstruct", path, "-o", path + ".alias.vtu", "--compact")
same = filecmp.cmp(path + ".alias.vtu", path + ".compact.vtu", shallow=False)
print("--compact: %s file" % ("the same" if same else "ANOTHER"))
if not same:
    failures.append("--compact wrote another file than the default")

# From a stored complex: the same compact cells (the same nodes, walked again).
for name in ("bundled_torus", "ball"):
    path = os.path.join(WORK, name + ".xyz")
    vtm = os.path.join(WORK, name + "_complex.vtm")
    fr.run(FLOWRECON, "complex", path, "-o", vtm)
    fr.run(FLOWRECON, "reconstruct", vtm, "-o", path + ".stored.vtu")
    a, b = (fr.cells(path + suffix, ["NodeId"]) for suffix in (".compact.vtu", ".stored.vtu"))
    same = sorted(map(str, zip(a[0], a[1]["NodeId"].tolist()))) == sorted(map(str, zip(b[0], b[1]["NodeId"].tolist())))
    print("%s from a stored complex: %d cells, %s" % (name, len(b[0]), "the same" if same else "DIFFERENT"))
    if not same:
        failures.append("%s: the compact cells from the stored complex differ from the cloud's" % name)

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS")
