"""The reconstruction at t_r = inf without simplification is contractible.

Known answer: every finite node is then inserted, so the output is the union of
the stable manifolds of all finite critical points, the complement of the
stable manifold of the maximum at infinity, an open cell: by Alexander duality
its Betti numbers are (1, 0, 0). TestCoreInvariants asserts the same of the
Hasse diagram; this asserts it of the written cells, where an index-3 cone over
a boundary that meets itself at a point or along an edge used to enclose voids
(12 on the 6000-point torus below, 2 on the 10000-point one).
The printed Betti numbers are checked against GUDHI on the smallest cloud.
Usage: test_contractible.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

FLOWRECON, WORK = sys.argv[1], sys.argv[2]
os.makedirs(WORK, exist_ok=True)
failures = []


def torus(n, seed):
    # i.i.d. area-uniform on a torus surface (R 1, r 0.35): tubes, where cells
    # wrap around the core and meet themselves.
    rng = np.random.default_rng(seed)
    R, r = 1.0, 0.35
    u, v = rng.uniform(0, 2 * np.pi, (2, 3 * n))
    keep = rng.uniform(0, 1, 3 * n) < (R + r * np.cos(v)) / (R + r)
    u, v = u[keep][:n], v[keep][:n]
    return np.c_[(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def clouds():
    rng = np.random.default_rng(5)
    s = rng.normal(size=(3000, 3))
    b = rng.normal(size=(4000, 3))
    b /= np.linalg.norm(b, axis=1)[:, None]
    b *= rng.uniform(0, 1, (4000, 1)) ** (1 / 3)
    return {"sphere": s / np.linalg.norm(s, axis=1)[:, None],
            "cube": rng.uniform(0, 1, (3000, 3)),
            "ball": b,
            "torus": torus(6000, 7),
            # Cells here also meet themselves along Gabriel edges (2 voids
            # before the cones were split there by sides).
            "torus_edge_pinched": torus(10000, 7)}


def betti_of(path):
    out = subprocess.run([FLOWRECON, "reconstruct", path, "-o", path + ".vtu", "--tp", "0",
                          "--tr", "inf", "--betti-max-cells", "inf"],
                         capture_output=True, text=True)
    if out.returncode != 0:
        failures.append("%s: exit %d: %s" % (path, out.returncode, out.stderr.strip()))
        return None
    m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", out.stdout + out.stderr, re.M)
    if not m:
        failures.append("%s: no Betti line" % path)
        return None
    return tuple(int(x) for x in m.groups())


def gudhi_betti(vtu):
    import gudhi
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(vtu)
    r.Update()
    g = r.GetOutput()
    types = vtk_to_numpy(g.GetCellTypesArray())
    conn = vtk_to_numpy(g.GetCells().GetConnectivityArray())
    off = vtk_to_numpy(g.GetCells().GetOffsetsArray())
    st = gudhi.SimplexTree()
    for vtk_type, k in ((10, 4), (5, 3), (3, 2), (1, 1)):
        idx = np.nonzero(types == vtk_type)[0]
        if len(idx):
            st.insert_batch(np.stack([conn[off[idx] + j] for j in range(k)]), np.zeros(len(idx)))
    st.compute_persistence(persistence_dim_max=True)
    b = st.betti_numbers() + [0, 0, 0]
    return tuple(b[:3])


for name, pts in clouds().items():
    path = os.path.join(WORK, name + ".xyz")
    np.savetxt(path, pts, fmt="%.17g")
    b = betti_of(path)
    print("%s (%d points): Betti %s" % (name, len(pts), b))
    if b is not None and b != (1, 0, 0):
        failures.append("%s: Betti %s at t_r = inf, t_p = 0; expected (1, 0, 0)" % (name, b))
    if name == "sphere" and b is not None:
        g = gudhi_betti(path + ".vtu")
        print("  GUDHI on the written cells: %s" % (g,))
        if g != b:
            failures.append("%s: printed %s, GUDHI %s" % (name, b, g))

if failures:
    print("FAIL\n" + "\n".join(failures))
    sys.exit(1)
print("PASS")
