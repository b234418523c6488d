#!/usr/bin/python3
"""The automatic thresholds on two kinds of cloud outside the topology study:
- isosurface vertices, the cloud a CT or MRI segmentation gives: the vertices of
  VTK's flying edges at level 0 of an implicit function sampled on an n^3 grid of
  [-1, 1]^3 (n = 24, 48, 96), for a sphere, a torus, a genus-2 surface, two
  spheres 0.2 apart, a rounded cube, the boundary of a thick spherical shell (two
  nested spheres) and a flat ellipsoid: points on the grid's edges, spaced by
  the grid, with no noise;
- two unit spheres a gap apart (Fibonacci points, and i.i.d. points), alone and
  joined by a rod of points along the segment between them at the surface
  spacing: (2 0 2) apart, (1 0 2) joined;
- i.i.d. unions: three spheres of unequal radii, a sphere and a torus, two linked
  tori, a sphere beside a circle (a curve: not a closed surface), two nested
  spheres, two spheres of 10x unequal density, two spheres touching at a point
  (and touching Fibonacci spheres): (1 0 2), joined where they touch; two
  nested cube surfaces (sides 2 and 1) of 1 500 and 5 000 points each;
- the isosurface vertices of the 32^3 and 64^3 grids with Gaussian noise of 0.3
  and 1 times their mean spacing.
`flowrecon reconstruct` runs at its defaults and at `--tp 1.1 --tr 2`; verdicts
as in held_out_shapes.py (right, flagged: wrong with a warning, silent: wrong
without one). Prints a Markdown table, one row per cloud, and the counts.

  /usr/bin/python3 Benchmarks/Study/separate_surfaces.py build/bin/flowrecon WORKDIR [--quick]

--quick: the grids of 24 and 48 and the two smallest pairs of spheres, no union
and no noise (the test py.reconstruction.separate_surfaces).
"""
import os
import sys

import numpy as np
from scipy.spatial import cKDTree
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkFlyingEdges3D

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import held_out_shapes as ho  # noqa: E402


def _torus(x, y, z, cx, r_big, r_small):
    return np.sqrt((np.sqrt((x - cx) ** 2 + y ** 2) - r_big) ** 2 + z ** 2) - r_small


IMPLICIT = [
    ("sphere", lambda x, y, z: np.sqrt(x * x + y * y + z * z) - 0.8, (1, 0, 1)),
    ("torus", lambda x, y, z: _torus(x, y, z, 0, 0.6, 0.25), (1, 2, 1)),
    ("genus-2", lambda x, y, z: np.minimum(_torus(x, y, z, -0.45, 0.4, 0.15),
                                           _torus(x, y, z, 0.45, 0.4, 0.15)), (1, 4, 1)),
    ("two spheres 0.2 apart", lambda x, y, z: np.minimum(
        np.sqrt((x - 0.45) ** 2 + y * y + z * z), np.sqrt((x + 0.45) ** 2 + y * y + z * z)) - 0.35,
     (2, 0, 2)),
    ("rounded cube", lambda x, y, z: (x ** 8 + y ** 8 + z ** 8) ** 0.125 - 0.7, (1, 0, 1)),
    ("thick shell", lambda x, y, z: np.abs(np.sqrt(x * x + y * y + z * z) - 0.6) - 0.2, (2, 0, 2)),
    ("flat ellipsoid", lambda x, y, z: np.sqrt((x / 0.9) ** 2 + (y / 0.5) ** 2 + (z / 0.25) ** 2) - 1,
     (1, 0, 1)),
]
GRIDS = (24, 48, 96)
PAIRS = ((600, 0.6), (1500, 0.5), (1500, 1.0), (4000, 0.3))  # points per sphere, gap


def isosurface_vertices(field, n):
    """The distinct vertices of the level-0 isosurface of `field` on an n^3 grid."""
    mesh = isosurface_mesh(field, n)
    return np.unique(vtk_to_numpy(mesh.GetPoints().GetData()).astype(np.float64), axis=0)


def isosurface_mesh(field, n):
    """VTK's flying edges at level 0 of `field` sampled on an n^3 grid of [-1, 1]^3."""
    g = np.linspace(-1, 1, n)
    z, y, x = np.meshgrid(g, g, g, indexing="ij")
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    image.SetOrigin(-1, -1, -1)
    image.SetSpacing(*(3 * [2 / (n - 1)]))
    image.GetPointData().SetScalars(numpy_to_vtk(field(x, y, z).ravel().astype(np.float64), deep=1))
    edges = vtkFlyingEdges3D()
    edges.SetInputData(image)
    edges.SetValue(0, 0.0)
    edges.Update()
    return edges.GetOutput()


def fibonacci_sphere(n):
    i = np.arange(n) + 0.5
    polar, turn = np.arccos(1 - 2 * i / n), np.pi * (1 + 5 ** 0.5) * i
    return np.c_[np.cos(turn) * np.sin(polar), np.sin(turn) * np.sin(polar), np.cos(polar)]


def iid_sphere(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1)[:, None]


def iid_cube_surface(rng, n, half):
    """n i.i.d. points on the boundary of [-half, half]^3 (the faces have equal areas)."""
    p = rng.uniform(-half, half, size=(n, 3))
    face = rng.integers(0, 6, n)
    p[np.arange(n), face // 2] = np.where(face % 2 == 1, half, -half)
    return p


def sphere_pairs(pairs=PAIRS):
    """Yields (name, points, cloud, truth): two unit spheres `gap` apart, alone and
    joined by a rod along the x axis."""
    for k, (n, gap) in enumerate(pairs):
        spacing = np.sqrt(4 * np.pi / n)
        inside = np.linspace(-gap / 2, gap / 2, max(2, int(gap / spacing)) + 2)[1:-1]
        rod = np.c_[inside, np.zeros_like(inside), np.zeros_like(inside)]
        shift = np.array([1 + gap / 2, 0, 0])
        rng = np.random.default_rng(500 + k)
        for sampling, one in (("Fibonacci", lambda: fibonacci_sphere(n)), ("i.i.d.", lambda: iid_sphere(rng, n))):
            two = np.vstack([one() - shift, one() + shift])
            yield "two spheres %g apart, %s" % (gap, sampling), 2 * n, two, (2, 0, 2)
            yield "two spheres %g apart joined by a rod, %s" % (gap, sampling), 2 * n + len(rod), \
                np.vstack([two, rod]), (1, 0, 2)


def iid_torus(rng, n, big, small, axis=2):
    """Area-uniform on a torus around the z axis (around y with axis=1)."""
    kept = np.empty((0, 3))
    while len(kept) < n:
        u, v = rng.uniform(0, 2 * np.pi, (2, 4 * n))
        keep = rng.uniform(size=4 * n) < (big + small * np.cos(v)) / (big + small)
        u, v = u[keep], v[keep]
        kept = np.vstack([kept, np.c_[(big + small * np.cos(v)) * np.cos(u),
                                      (big + small * np.cos(v)) * np.sin(u), small * np.sin(v)]])
    p = kept[:n]
    return p[:, [0, 2, 1]] if axis == 1 else p


def mixed():
    """Yields (name, points, cloud, truth): i.i.d. unions of closed surfaces of
    unequal sizes and densities, a surface beside a curve, and two spheres
    touching at a point (joined there: the preference for surfaces apart must
    not part them)."""
    rng = np.random.default_rng(9)
    at = np.array
    circle = np.linspace(0, 2 * np.pi, 300, endpoint=False)
    for name, parts, truth in (
        ("three spheres, radii 1, 0.4, 0.2", lambda: [iid_sphere(rng, 3000), 0.4 * iid_sphere(rng, 800) + at([1.8, 0, 0]),
                                                      0.2 * iid_sphere(rng, 300) + at([0, 1.6, 0])], (3, 0, 3)),
        ("a sphere and a torus", lambda: [iid_sphere(rng, 3000), iid_torus(rng, 3000, 0.8, 0.3) + at([2.6, 0, 0])],
         (2, 2, 2)),
        ("two linked tori", lambda: [iid_torus(rng, 4000, 1, 0.25), iid_torus(rng, 4000, 1, 0.25, 1) + at([1, 0, 0])],
         (2, 4, 2)),
        ("a sphere and a circle of 300 points", lambda: [iid_sphere(rng, 3000),
                                                        np.c_[0.8 * np.cos(circle) + 2.5, 0.8 * np.sin(circle), 0 * circle]],
         (2, 1, 1)),
        ("two nested spheres, radii 1 and 0.5", lambda: [iid_sphere(rng, 4000), 0.5 * iid_sphere(rng, 1500)], (2, 0, 2)),
        ("two spheres 0.5 apart, 6000 and 600 points", lambda: [iid_sphere(rng, 6000),
                                                               iid_sphere(rng, 600) + at([2.5, 0, 0])], (2, 0, 2)),
        ("two spheres touching at a point", lambda: [iid_sphere(rng, 4000) - at([1, 0, 0]),
                                                     iid_sphere(rng, 4000) + at([1, 0, 0])], (1, 0, 2)),
        ("two nested cube surfaces, sides 2 and 1, 1500 points each",
         lambda: [iid_cube_surface(rng, 1500, 1), iid_cube_surface(rng, 1500, 0.5)], (2, 0, 2)),
        ("two nested cube surfaces, sides 2 and 1, 5000 points each",
         lambda: [iid_cube_surface(rng, 5000, 1), iid_cube_surface(rng, 5000, 0.5)], (2, 0, 2)),
    ):
        p = np.vstack(parts())
        yield name + ", i.i.d.", len(p), p, truth
    touching = np.vstack([fibonacci_sphere(4000) - at([1, 0, 0]), fibonacci_sphere(4000) + at([1, 0, 0])])
    yield "two spheres touching at a point, Fibonacci", len(touching), touching, (1, 0, 2)


def noisy_isosurfaces():
    """Yields (name, points, cloud, truth): the isosurface vertices on 32^3 and
    64^3 grids with Gaussian noise of 0.3 and 1 times their mean spacing (a
    segmentation's jitter)."""
    rng = np.random.default_rng(3)
    for name, field, truth in IMPLICIT:
        for n in (32, 64):
            p = isosurface_vertices(field, n)
            spacing = cKDTree(p).query(p, k=2)[0][:, 1].mean()
            for noise in (0.3, 1.0):
                yield "%s, isosurface of a %d^3 grid, noise %g" % (name, n, noise), len(p), \
                    p + rng.normal(scale=noise * spacing, size=p.shape), truth


def clouds(grids=GRIDS, pairs=PAIRS, unions=True):
    """Yields (name, points, cloud, truth), the same on every call."""
    for name, field, truth in IMPLICIT:
        for n in grids:
            p = isosurface_vertices(field, n)
            yield "%s, isosurface of a %d^3 grid" % (name, n), len(p), p, truth
    yield from sphere_pairs(pairs)
    if unions:
        yield from mixed()
        yield from noisy_isosurfaces()


def main():
    args = ho.arguments(__doc__, quick=True)
    selection = clouds(GRIDS[:2], PAIRS[:2], False) if args.quick else clouds()
    return ho.compare(args.flowrecon, args.work, ["cloud"], (([name], p, truth) for name, n, p, truth in selection))


if __name__ == "__main__":
    main()
