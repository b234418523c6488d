#!/usr/bin/python3
"""The parts of `flowrecon reconstruct`'s answer and how far apart they lie,
measured independently of the product: the components of the written cells
(the compact output's Delaunay simplices on the samples, joined through shared
samples; scipy's connected components), and for each component the distance
to the nearest sample of another (scipy's k-d tree), over the median
nearest-sample distance of the cloud and over the larger one's extent. Prints, for each cloud whose answer has
three parts or more and no void, the parts and the widest such gap, and
whether the answer was warned as parts side by side (Data/EXPERIMENTS.md,
"Parts side by side").

  /usr/bin/python3 Benchmarks/Study/part_gaps.py build/bin/flowrecon WORKDIR CLOUD.xyz...
"""
import os
import re
import subprocess
import sys

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def part_gaps(vtu, samples):
    """(parts, gap, span): the components of the cells written to `vtu` (the
    samples they use, joined through the cells), the largest over them of the
    distance to the nearest other component over the median nearest-sample
    distance of `samples`, and the largest of that distance over the extent
    (bounding-box diagonal) of the larger of the two components."""
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(vtu)
    reader.Update()
    grid = reader.GetOutput()
    points = vtk_to_numpy(grid.GetPoints().GetData())
    conn = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    offsets = vtk_to_numpy(grid.GetCells().GetOffsetsArray())
    rows, cols = [], []
    for k in range(len(offsets) - 1):
        ids = conn[offsets[k]:offsets[k + 1]]
        rows += [ids[0]] * (len(ids) - 1)
        cols += list(ids[1:])
    used = np.unique(conn)
    points = points[used]
    index = np.full(len(vtk_to_numpy(grid.GetPoints().GetData())), -1)
    index[used] = np.arange(len(used))
    n = len(points)
    count, label = connected_components(
        coo_matrix((np.ones(len(rows)), (index[rows], index[cols])), shape=(n, n)), directed=False)
    spacing = np.median(cKDTree(samples).query(samples, k=2)[0][:, 1])
    if count < 2:
        return count, 0.0, 0.0
    extent = [np.linalg.norm(np.ptp(points[label == c], axis=0)) for c in range(count)]
    widest = span = 0.0
    for c in range(count):
        others = np.flatnonzero(label != c)
        d, i = cKDTree(points[others]).query(points[label == c])
        nearest = label[others[i[np.argmin(d)]]]
        widest = max(widest, d.min())
        span = max(span, d.min() / max(extent[c], extent[nearest]))
    return count, widest / spacing, span


def widest_gap(vtu, samples):
    """(parts, gap) of part_gaps."""
    return part_gaps(vtu, samples)[:2]


def main():
    flowrecon, work, clouds = sys.argv[1], sys.argv[2], sys.argv[3:]
    os.makedirs(work, exist_ok=True)
    for k, cloud in enumerate(clouds):
        vtu = os.path.join(work, "answer%03d.vtu" % k)
        out = subprocess.run([flowrecon, "reconstruct", cloud, "-o", vtu], capture_output=True, text=True)
        m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", out.stdout, re.M)
        if not m or int(m.group(1)) < 3 or int(m.group(3)) > 0:
            continue
        parts, gap, span = part_gaps(vtu, np.loadtxt(cloud, comments="#")[:, :3])
        warned = "side by side" in out.stderr
        print("%s: Betti %s %s %s, %d parts, widest gap %.2f spacings, %.3f of the extent, %s" % (
            cloud, *m.groups(), parts, gap, span, "warned as side by side" if warned else "not warned so"),
            flush=True)


if __name__ == "__main__":
    main()
