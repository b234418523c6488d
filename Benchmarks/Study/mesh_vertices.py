#!/usr/bin/python3
"""The automatic thresholds on clouds that are the vertices of meshes, a kind of
cloud outside the topology study: many public point sets are a mesh's vertices,
spaced as the mesher left them, not as a scanner samples.
- parametric grids (VTK's parametric sources): a torus (R 1, r 0.35) at 48x24,
  96x48 and 200x100, denser on its inner side; an ellipsoid (1, 0.6, 0.35) at
  64x64 and VTK's latitude-longitude sphere at 48 and 100, dense at the poles; a
  superquadric torus with flattened sides;
- a coarse parametric torus (24x12) twice Loop-subdivided: old vertices beside
  new ones;
- decimated meshes (VTK's quadric decimation, 90 % and 97 % of the triangles
  removed) of the flying-edges isosurfaces of separate_surfaces.py's seven
  implicit shapes on a 96^3 grid, and of the 200x100 parametric torus: the
  vertices thin out where the surface is flat and stay dense where it bends;
- open surfaces: a Moebius strip, a latitude-longitude hemisphere and a
  Loop-subdivided open cylinder (VTK's sources);
- the Stanford bunny's closed mesh (npm package `bunny`, fetched with npm into
  build/npm), Loop-subdivided once and twice, and decimated by 50 % and 80 %.
The truth is the mesh's own: each mesh, its seams merged, must be a 2-manifold
(no non-manifold edge, VTK's feature edges); closed, its Betti numbers are
(c, 2c - chi, c) for c components and Euler characteristic chi, and connected
with a boundary (1, 1 - chi, 0); a mesh that is neither is left out and said so. The cloud is the mesh's
distinct vertices. `flowrecon reconstruct` runs at its defaults and at `--tp 1.1
--tr 2`; verdicts as in held_out_shapes.py (right, flagged: wrong with a
warning, silent: wrong without one). Prints a Markdown table and the counts.

  /usr/bin/python3 Benchmarks/Study/mesh_vertices.py build/bin/flowrecon WORKDIR [--quick]

--quick: the decimated meshes of the sphere, the torus and the two spheres 0.2
apart only (the test py.reconstruction.mesh_vertices).
"""
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkCommonComputationalGeometry import (vtkParametricEllipsoid, vtkParametricMobius,
                                                       vtkParametricTorus)
from vtkmodules.vtkFiltersCore import (vtkCleanPolyData, vtkFeatureEdges, vtkPolyDataConnectivityFilter,
                                       vtkQuadricDecimation, vtkTriangleFilter)
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter
from vtkmodules.vtkFiltersSources import (vtkCylinderSource, vtkParametricFunctionSource, vtkSphereSource,
                                          vtkSuperquadricSource)

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import held_out_shapes as ho  # noqa: E402
import separate_surfaces as ss  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
import whole_process as wp  # noqa: E402


def _output(algorithm):
    algorithm.Update()
    return algorithm.GetOutput()


def triangles(poly):
    """`poly`'s polygons as triangles, coincident points merged (a parametric
    grid repeats its seam), vertices and lines dropped."""
    c = vtkCleanPolyData()
    c.SetInputData(poly)
    c.SetTolerance(1e-9)
    t = vtkTriangleFilter()
    t.SetInputConnection(c.GetOutputPort())
    t.PassVertsOff()
    t.PassLinesOff()
    return _output(t)


def _edges_of_kind(poly, boundary):
    """How many boundary edges (`boundary`) or non-manifold edges `poly` has."""
    f = vtkFeatureEdges()
    f.SetInputData(poly)
    f.SetBoundaryEdges(boundary)
    f.SetNonManifoldEdges(not boundary)
    f.FeatureEdgesOff()
    f.ManifoldEdgesOff()
    return _output(f).GetNumberOfCells()


def truth_of(poly):
    """(b0, b1, b2) of a triangulated 2-manifold: (c, 2c - chi, c) when it is
    closed (every closed surface in R^3 is orientable), (c, c - chi, 0) when
    every component has a boundary (each then has b2 = 0 and chi = 1 - b1);
    None with a non-manifold edge, or with closed and bounded components mixed."""
    if _edges_of_kind(poly, False) > 0 or poly.GetNumberOfPolys() == 0:
        return None
    conn = vtkPolyDataConnectivityFilter()
    conn.SetInputData(poly)
    conn.SetExtractionModeToAllRegions()
    conn.Update()
    c = conn.GetNumberOfExtractedRegions()
    tri = vtk_to_numpy(poly.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    edges = np.unique(np.sort(np.r_[tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]], axis=1), axis=0)
    chi = len(np.unique(tri)) - len(edges) + len(tri)
    if _edges_of_kind(poly, True) == 0:
        return (c, 2 * c - chi, c)
    return (c, c - chi, 0) if c == 1 else None


def vertices(poly):
    return np.unique(vtk_to_numpy(poly.GetPoints().GetData()).astype(np.float64), axis=0)


def parametric(function, u, v):
    s = vtkParametricFunctionSource()
    s.SetParametricFunction(function)
    s.SetUResolution(u)
    s.SetVResolution(v)
    return triangles(_output(s))


def isosurface(field, n):
    return triangles(ss.isosurface_mesh(field, n))


def decimated(poly, reduction):
    d = vtkQuadricDecimation()
    d.SetInputData(poly)
    d.SetTargetReduction(reduction)
    return triangles(_output(d))


def subdivided(poly, levels):
    s = vtkLoopSubdivisionFilter()
    s.SetInputData(poly)
    s.SetNumberOfSubdivisions(levels)
    return triangles(_output(s))


def torus():
    t = vtkParametricTorus()
    t.SetRingRadius(1)
    t.SetCrossSectionRadius(0.35)
    return t


def parametric_meshes():
    for u, v in ((48, 24), (96, 48), (200, 100)):
        yield "parametric torus %dx%d" % (u, v), parametric(torus(), u, v)
    e = vtkParametricEllipsoid()
    e.SetXRadius(1)
    e.SetYRadius(0.6)
    e.SetZRadius(0.35)
    yield "parametric ellipsoid 64x64", parametric(e, 64, 64)
    for r in (48, 100):
        s = vtkSphereSource()
        s.SetThetaResolution(r)
        s.SetPhiResolution(r)
        yield "latitude-longitude sphere %d" % r, triangles(_output(s))
    q = vtkSuperquadricSource()
    q.SetToroidal(1)
    q.SetThickness(0.3)
    q.SetThetaResolution(96)
    q.SetPhiResolution(48)
    q.SetThetaRoundness(0.3)
    q.SetPhiRoundness(0.3)
    yield "superquadric torus", triangles(_output(q))
    yield "parametric torus 24x12, Loop-subdivided twice", subdivided(parametric(torus(), 24, 12), 2)


def open_meshes():
    """Surfaces with a boundary: VTK's Moebius strip at three resolutions, the
    upper half of its latitude-longitude sphere, and its open cylinder (radius
    0.5, height 2; only two rings of vertices) Loop-subdivided three times, rings
    0.25 apart with 20 and 64 times closer points along them."""
    for u in (48, 96, 192):
        m = vtkParametricMobius()
        m.SetRadius(1)
        yield "Moebius strip %dx%d" % (u, u // 8 + 2), parametric(m, u, u // 8 + 2)
    for r in (24, 64):
        s = vtkSphereSource()
        s.SetThetaResolution(r)
        s.SetPhiResolution(r)
        s.SetEndPhi(90)
        yield "latitude-longitude hemisphere %d" % r, triangles(_output(s))
    for r in (32, 100):
        c = vtkCylinderSource()
        c.SetResolution(r)
        c.CappingOff()
        c.SetHeight(2)
        c.SetRadius(0.5)
        yield "open cylinder %d, Loop-subdivided three times" % r, subdivided(triangles(_output(c)), 3)


def decimated_meshes(names=None):
    for name, field, _ in ss.IMPLICIT:
        if names is None or name in names:
            mesh = isosurface(field, 96)
            for reduction in (0.9, 0.97):
                yield "%s, 96^3 isosurface decimated %g" % (name, reduction), decimated(mesh, reduction)
    if names is None:
        yield "parametric torus 200x100 decimated 0.9", decimated(parametric(torus(), 200, 100), 0.9)


def bunny_meshes():
    """The Stanford bunny of the npm package `bunny` (a closed mesh of 1 839
    vertices, fetched with npm as the whole-process benchmark does), Loop-subdivided
    and decimated."""
    positions, cells = wp.bunny_mesh()
    poly = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(positions, deep=1))
    poly.SetPoints(points)
    polys = vtkCellArray()
    polys.SetData(numpy_to_vtkIdTypeArray(np.arange(0, 3 * len(cells) + 1, 3), deep=1),
                  numpy_to_vtkIdTypeArray(cells.astype(np.int64).ravel(), deep=1))
    poly.SetPolys(polys)
    bunny = triangles(poly)
    yield "bunny (npm)", bunny
    for levels, times in ((1, "once"), (2, "twice")):
        yield "bunny, Loop-subdivided %s" % times, subdivided(bunny, levels)
    for reduction in (0.5, 0.8):
        yield "bunny decimated %g" % reduction, decimated(bunny, reduction)


def meshes(quick=False):
    """Yields (name, mesh as vtkPolyData), deterministic."""
    if quick:
        yield from decimated_meshes(("sphere", "torus", "two spheres 0.2 apart"))
        return
    yield from parametric_meshes()
    yield from open_meshes()
    yield from decimated_meshes()
    yield from bunny_meshes()


def rows(quick=False):
    """(name, vertices, truth) of each mesh that is a closed 2-manifold; the
    others are said on stderr."""
    for name, poly in meshes(quick):
        truth = truth_of(poly)
        if truth is None:
            print("%s: not a closed 2-manifold, left out" % name, file=sys.stderr)
            continue
        yield [name], vertices(poly), truth


def main():
    args = ho.arguments(__doc__, quick=True)
    return ho.compare(args.flowrecon, args.work, ["mesh"], rows(args.quick))


if __name__ == "__main__":
    main()
