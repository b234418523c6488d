"""`reconstruct --compact` has the Betti numbers of the exact reconstruction.

For each cloud (the bundled torus; generated surfaces, a solid, a curve, a
sphere with a segment, and two spheres whose patches once closed a spurious void),
`reconstruct` runs at the automatic thresholds with and without --compact. The
Betti numbers of the written compact file, computed by GUDHI over its cells
(an oracle written by others), must equal those the exact run prints (from its
Hasse diagram), and the ones the compact run prints for both. The compact file must
be over the input points alone (point k = input point k, no constructed point),
hold only vertices, segments, triangles and tetrahedra with NodeId, Index and a
Threshold below the t_r printed, and have fewer cells than the exact one. From a
stored flow complex (.vtm, written by `complex`), the compact file must have
the same cells as from the cloud.
Usage: test_compact.py FLOWRECON WORKDIR
"""
import os
import re
import sys

import generate_clouds as gc
import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import run as fr
from flowrecon_testing.oracles import gudhi_betti

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
DATA = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
os.makedirs(WORK, exist_ok=True)
failures = []


def check(name, points):
    from vtkmodules.util.numpy_support import vtk_to_numpy
    path = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(path, points)
    exact_out = fr.run(FLOWRECON, "reconstruct", path, "-o", path + ".exact.vtu")
    code, out, err = fr.call(FLOWRECON, "reconstruct", path, "-o", path + ".compact.vtu", "--compact")
    if code != 0:
        failures.append("%s: --compact exit %d: %s" % (name, code, err.strip()))
        return
    exact = fr.printed_betti(exact_out)
    m = re.search(r"^compact output's Betti numbers (\d+) (\d+) (\d+)$", out, re.M)
    printed = tuple(int(x) for x in m.groups()) if m else None
    grid = fr.read_grid(path + ".compact.vtu")
    oracle = gudhi_betti(grid)
    tr = float(re.search(r"steps at t_r (\S+)$", out, re.M).group(1))
    print("%s (%d points): exact %s, compact %s printed, %s by GUDHI; %d cells, exact %d" % (
        name, len(points), exact, printed, oracle, grid.GetNumberOfCells(),
        fr.read_grid(path + ".exact.vtu").GetNumberOfCells()))
    if fr.printed_betti(out) != exact:
        failures.append("%s: the --compact run printed other exact Betti numbers" % name)
    if oracle != exact:
        failures.append("%s: compact file's Betti numbers (GUDHI) %s, exact %s" % (name, oracle, exact))
    if printed != oracle:
        failures.append("%s: compact Betti numbers printed %s, GUDHI %s" % (name, printed, oracle))
    if "compact output's Betti numbers" in err:
        failures.append("%s: warned of a difference: %s" % (name, err))
    pts = vtk_to_numpy(grid.GetPoints().GetData())
    if pts.shape != points.shape or not np.array_equal(pts, np.asarray(points, dtype=float)):
        failures.append("%s: the compact file's points are not the input points" % name)
    types = set(vtk_to_numpy(grid.GetCellTypesArray()).tolist())
    if not types <= {1, 3, 5, 10}:
        failures.append("%s: cell types %s" % (name, sorted(types)))
    cd = grid.GetCellData()
    if any(cd.GetArray(a) is None for a in ("NodeId", "Index", "Threshold")):
        failures.append("%s: missing cell data" % name)
    elif not (vtk_to_numpy(cd.GetArray("Threshold")) < tr).all():
        failures.append("%s: a cell of Threshold >= t_r %g" % (name, tr))
    if grid.GetNumberOfCells() >= fr.read_grid(path + ".exact.vtu").GetNumberOfCells():
        failures.append("%s: not compact" % name)


check("bundled_torus", gc.read_xyz(os.path.join(DATA, "torus.xyz")))
for shape in ("sphere_qu", "genus2_pd", "ball", "trefoil_qu", "sphere_with_segment", "two_spheres"):
    check(shape, gc.make(shape))

# From a stored complex: the same compact cells (the same nodes, walked again).
for name in ("bundled_torus", "ball"):
    path = os.path.join(WORK, name + ".xyz")
    vtm = os.path.join(WORK, name + "_complex.vtm")
    fr.run(FLOWRECON, "complex", path, "-o", vtm)
    fr.run(FLOWRECON, "reconstruct", vtm, "-o", path + ".stored.vtu", "--compact")
    a, b = (fr.cells(path + suffix, ["NodeId"]) for suffix in (".compact.vtu", ".stored.vtu"))
    same = sorted(map(str, zip(a[0], a[1]["NodeId"].tolist()))) == sorted(map(str, zip(b[0], b[1]["NodeId"].tolist())))
    print("%s from a stored complex: %d cells, %s" % (name, len(b[0]), "the same" if same else "DIFFERENT"))
    if not same:
        failures.append("%s: the compact cells from the stored complex differ from the cloud's" % name)

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS")
