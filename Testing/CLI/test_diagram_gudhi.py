#!/usr/bin/env python3
"""`flowrecon diagram` writes the alpha-complex persistence diagram.

For a few clouds, `flowrecon diagram CLOUD.xyz -o PD.csv` must equal, per
dimension as multisets, GUDHI's alpha-complex persistence (square roots of its
squared radii), after dropping pairs shorter than 1e-9 x diameter on both sides,
within 1e-7 x diameter. The same diagram must come out of a stored flow complex
(`flowrecon complex` then `diagram` on the .vtm), and the .vtu output must follow
TTK's layout (segments (b, b, 0)-(b, d, 0), cell data PairIdentifier, PairType,
Persistence, Birth, IsFinite, a diagonal with PairIdentifier -1).

Run: /usr/bin/python3 test_diagram_gudhi.py <path to flowrecon> <work dir>
"""

import math
import os
import sys

import generate_clouds as gen
import numpy as np

from flowrecon_testing import clouds as cl
from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing import run as fr
from flowrecon_testing.checks import Checker

CHK = Checker("test_diagram_gudhi")
DROP = 1e-9
TOL = 1e-7


def clouds():
    rng = np.random.default_rng(5)
    yield "cube", rng.uniform(0.0, 1.0, (120, 3))
    yield "shell", cl.shell(150, rng)
    yield "torus", gen.torus(200, rng)


def check_cloud(flowrecon, work, name, points):
    xyz = os.path.join(work, name + ".xyz")
    cl.write_xyz(xyz, points)
    csv = os.path.join(work, name + "_pd.csv")
    code, out, err = fr.call(flowrecon, "diagram", xyz, "-o", csv, "--quiet")
    CHK.check(code == 0 and err == "", "%s: diagram exits %d" % (name, code), err)
    if code != 0:
        return
    header, mine = fr.read_diagram(csv)
    CHK.check(header == "dimension,birth,death", "%s: CSV header is '%s'" % (name, header))
    diam = fio.diameter(points)
    ref = fio.significant(fio.gudhi_alpha_diagram(points), DROP * diam)
    ok, msg = fio.compare_diagrams(fio.significant(mine, DROP * diam), ref, TOL * diam,
                                   ("flowrecon diagram", "GUDHI alpha"))
    CHK.check(ok, "%s: diagram differs from GUDHI's alpha persistence" % name, msg)
    CHK.check(sum(1 for d, b, e in mine if math.isinf(e)) == 1,
              "%s: exactly one essential class (H0 of a connected cloud)" % name)

    # Through a stored flow complex.
    vtm = os.path.join(work, name + ".vtm")
    code, _, err = fr.call(flowrecon, "complex", xyz, "-o", vtm, "--quiet")
    CHK.check(code == 0, "%s: complex exits %d" % (name, code), err)
    csv2 = os.path.join(work, name + "_pd_stored.csv")
    code, _, err = fr.call(flowrecon, "diagram", vtm, "-o", csv2, "--quiet")
    CHK.check(code == 0 and fr.read_diagram(csv2)[1] == mine,
              "%s: the diagram of the stored complex differs" % name, err)

    # TTK layout.
    vtu = os.path.join(work, name + "_pd.vtu")
    code, _, err = fr.call(flowrecon, "diagram", xyz, "-o", vtu, "--quiet")
    CHK.check(code == 0, "%s: diagram .vtu exits %d" % (name, code), err)
    from vtkmodules.util.numpy_support import vtk_to_numpy
    g = fr.read_grid(vtu)
    cd = g.GetCellData()
    arrays = {n: cd.GetArray(n) for n in ("PairIdentifier", "PairType", "Persistence", "Birth",
                                          "IsFinite")}
    CHK.check(all(a is not None for a in arrays.values()), "%s: .vtu misses TTK arrays" % name)
    if not all(a is not None for a in arrays.values()):
        return
    a = {n: vtk_to_numpy(v) for n, v in arrays.items()}
    CHK.check(g.GetNumberOfCells() == len(mine) + 1, "%s: .vtu has %d cells for %d pairs"
              % (name, g.GetNumberOfCells(), len(mine)))
    CHK.check(a["PairIdentifier"][-1] == -1, "%s: the last cell is not the diagonal" % name)
    pts = vtk_to_numpy(g.GetPoints().GetData())
    for i, (d, b, e) in enumerate(mine):
        ids = [g.GetCell(i).GetPointId(k) for k in range(2)]
        p0, p1 = pts[ids[0]], pts[ids[1]]
        ok = (a["PairType"][i] == d and abs(a["Birth"][i] - b) <= 1e-12 * diam
              and p0[0] == p0[1] == p1[0] and abs(p0[0] - b) <= 1e-12 * diam
              and a["IsFinite"][i] == (0 if math.isinf(e) else 1)
              and (math.isinf(e) or abs(p1[1] - e) <= 1e-12 * diam))
        if not CHK.check(ok, "%s: .vtu pair %d does not match the CSV" % (name, i)):
            break


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        return 2
    flowrecon, work = sys.argv[1], sys.argv[2]
    os.makedirs(work, exist_ok=True)
    for name, points in clouds():
        CHK.run(name, check_cloud, flowrecon, work, name, points)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
