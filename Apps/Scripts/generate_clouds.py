#!/usr/bin/env python3
"""Deterministic synthetic point clouds with known topology, written as ``.xyz``.

Every cloud is drawn with ``numpy.random.default_rng(seed)`` from a fixed seed per
shape, so the files are reproducible bit for bit. Each line is ``x y z`` with
Python's shortest round-trip ``repr`` of the doubles.

Shapes (file ``NAME.xyz``; default size; true Betti numbers (b0, b1, b2) of the
sampled compact set):

=====================  =====  ===========  ==============================================
name                   size   (b0,b1,b2)   what
=====================  =====  ===========  ==============================================
sphere                 2000   (1, 0, 1)    uniform on the unit sphere
torus                  2000   (1, 2, 1)    torus R=1, r=0.35 in the plane z=0, uniform
                                           w.r.t. area (rejection on the (u, v) chart)
genus2                 3000   (1, 4, 1)    boundary of the union of two solid tori
                                           (R=1, r=0.35, centres (+-1.2,0,0)): a genus-2
                                           surface, uniform w.r.t. area (rejection)
trefoil                1000   (1, 1, 0)    trefoil knot (sin t + 2 sin 2t, cos t - 2 cos 2t,
                                           -sin 3t)/3, uniform w.r.t. arc length: a curve
ball                   2000   (1, 0, 0)    uniform in the volume of the unit ball
two_spheres            3000   (1, 0, 3)    two unit spheres centred at (+-0.5,0,0),
                                           intersecting along a circle (non-manifold)
two_hemispheres        3000   (1, 0, 0)    the paper's example: upper hemispheres (z>=0) of
                                           the unit spheres centred at (+-0.5,0,0), half of
                                           the points on each (1500 + 1500); they cross
                                           along an arc (non-manifold, with boundary)
sphere_with_segment    2000   (1, 0, 1)    unit sphere plus the segment (1,0,0)-(2,0,0)
                                           sticking out, sampled at the sphere's spacing
                                           (surface + curve); size = sphere points
grid5_jittered          125   (1, 0, 0)    5x5x5 grid of spacing 1 jittered uniformly by
                                           +-1e-3 (a solid cube)
grid4_exact              64   (1, 0, 0)    exact 4x4x4 integer grid: degenerate on purpose
                                           (cospherical and right-angled everywhere)
=====================  =====  ===========  ==============================================

The shapes above are i.i.d. samples: they have clusters and gaps, so a reconstruction
may punch holes in them (the paper's guarantee assumes a roughly uniform sampling).
The quasi-uniform shapes below are made by greedy farthest-point subsampling
(``farthest_points``) of a dense i.i.d. sample of the same set (``QU_FACTOR`` = 30
times the size, 4 times for the larger experiment models), or by an even spacing
with a small jitter for curves; consecutive points are about the same distance
apart everywhere, which is the paper's rho-uniform sampling:

=======================  =====  ===========  ============================================
name                     size   (b0,b1,b2)   what
=======================  =====  ===========  ============================================
sphere_qu                1000   (1, 0, 1)    unit sphere
torus_qu                 2000   (1, 2, 1)    torus R=1, r=0.35
genus2_qu                3000   (1, 4, 1)    the genus-2 surface of ``genus2``
trefoil_qu                600   (1, 1, 0)    trefoil knot, evenly spaced in arc length,
                                             each point moved by <= 0.1 spacing along it
ball_qu                  2000   (1, 0, 0)    solid unit ball (volume sample)
two_spheres_qu           3000   (1, 0, 3)    the union of ``two_spheres``: H1 = 0 and
                                             three chambers (lens + two outer parts)
two_hemispheres_qu       3000   (1, 0, 0)    ``two_hemispheres``: two disks glued along
                                             an arc, contractible
sphere_with_segment_qu   2000   (1, 0, 1)    sphere_qu(2000) + the segment of
                                             ``sphere_with_segment``; size = sphere points
vase_qu                  3000   (1, 2, 0)    the paper's vase (§5): surface of revolution
                                             r(z) = 0.55 + 0.25 sin(1.5 pi z / 2 + 0.3),
                                             0 <= z <= 2, closed by a flat bottom, open at
                                             the top (a disk), plus 2 thin solid handles
                                             sampled as curves (arcs bulging 0.5 out of the
                                             wall at angles 0 and pi, each with both ends
                                             on the wall): disk + 2 arcs; size = vase points
plate3_qu                8000   (1, 6, 1)    a mechanical-like genus-3 part: surface of the
                                             box [-2,2]x[-0.8,0.8]x[-0.25,0.25] with 3
                                             through holes of radius 0.4 at x = -1.3, 0, 1.3
                                             (sharp edges on purpose)
tree                    5       (1, 0, 0)    a random branching tree (depth 5, 2-3 children
                                             per branch) of thin cylinders (radius 0.012 at
                                             the trunk, x0.7 per level), points on the
                                             cylinder surfaces every 0.02 along the axis at
                                             random angles: a noisy sample of a tree of
                                             curves, contractible; size = depth
=======================  =====  ===========  ============================================

Shapes added for the t_r / t_p study (``Benchmarks/Study/tr_study.py``).
``_qu``: farthest points of 30x i.i.d. candidates as above; ``_pd``: a Poisson-disk
(dart-throwing) subsample of 20x i.i.d. candidates (at most 10^7), quasi-uniform like
``_qu`` but linear in the candidates, for 10^5-10^6 points (``poisson_disk``); ``_dv``:
i.i.d. whose density grows linearly along x, 10 times from one side to the other
(each point kept with probability (1 + 9 t) / 10, t = (x - xmin) / (xmax - xmin));
``_dvqu``: a Poisson-disk sample with the same density (radius ~ density^(-1/2)),
locally even. The Betti numbers of genus4 and of the thin tube were also checked on
a voxelization of the solids (GUDHI cubical complex: (1, 4, 0) and (1, 1, 0)):

=======================  =====  ===========  ============================================
name                     size   (b0,b1,b2)   what
=======================  =====  ===========  ============================================
thin_tube, _qu           4000   (1, 2, 1)    thin-walled tube with rounded rims: the
                                             offset at 0.05 of the cylinder rho = 0.95,
                                             abs(z) <= 1 (walls rho = 0.9 and 1, half-torus
                                             rims): wall 0.1 thick, smooth, a torus
thin_plate, _qu          2000   (1, 0, 1)    thin round plate: the offset at 0.05 of the
                                             unit disk of z = 0 (faces z = +-0.05, a
                                             half-torus rim): 0.1 thick, a sphere
genus4, _qu              4000   (1, 8, 1)    boundary of a row of 4 solid tori (R=1,
                                             r=0.35, centres 2.4 apart on the x axis,
                                             neighbours meeting in one lens like genus2,
                                             the others disjoint): a genus-4 handlebody's
                                             boundary
sphere_dv, torus_dv      2000   as sphere,   density x10 along x (x from -1 to 1, from
                                torus        -1.35 to 1.35), i.i.d.
sphere_dvqu, torus_dvqu  2000   as sphere,   density x10 along x, Poisson disk
                                torus
sphere_pd, torus_pd,     2000,  as sphere,   Poisson-disk quasi-uniform samples
thin_tube_pd             4000   torus,
                                thin_tube
lattice_shell              15   (1, 0, 1)    the integer points p with
                                             abs(norm(p) - 15) < 0.5 (2 622 points);
                                             size = the radius
latlong_sphere             30   (1, 0, 1)    latitude-longitude lattice on the unit
                                             sphere: 30 latitudes (no pole) x 60
                                             longitudes; size = the latitudes
plane_grid_jittered      1000   (1, 0, 0)    25 x 40 planar grid of spacing 1 in z = 0,
                                             every coordinate moved by +-1e-12: a square
=======================  =====  ===========  ============================================

Shapes added for the topology study (``Benchmarks/Study/topology_study.py``: right / flagged /
silent answers by class, a class being a sampling x a shape family). ``_qu`` and
``_pd`` as above; the Poisson-disk radius of the tori rows is first guessed from an
approximate area (``torus_row_area``), then rescaled as for every ``_pd`` shape:

=======================  =====  ===========  ============================================
name                     size   (b0,b1,b2)   what
=======================  =====  ===========  ============================================
genus3, _qu, _pd         3000   (1, 6, 1)    torus_row of 3 solid tori (as genus4)
genus2_pd, genus4_pd     3000,  as genus2,   Poisson-disk samples
                         4000   genus4
circle, circle_qu        1000   (1, 1, 0)    unit circle of z = 0, i.i.d. / evenly spaced
                                             (moved <= 0.1 spacing along it); z moved by
                                             +-1e-3 spacing (an exactly planar cloud is
                                             refused)
cube, _qu, _pd           2000   (1, 0, 0)    uniform in the volume of [-1, 1]^3
ball_pd                  2000   (1, 0, 0)    Poisson disk in the volume of the unit ball
thin_plate_pd            2000   (1, 0, 1)    Poisson-disk sample of thin_plate
two_spheres_pd,          3000   as the i.i.d Poisson-disk samples of the unions (the
two_hemispheres_pd                           points near the crossing are shared)
sphere_with_segment_pd   2000   (1, 0, 1)    sphere_pd + the segment at its spacing
fibonacci_sphere         2000   (1, 0, 1)    Fibonacci lattice on the unit sphere (height
                                             1 - (2i+1)/n, longitude i x golden angle);
                                             size = the points
=======================  =====  ===========  ============================================

Command line::

    generate_clouds.py [OUTDIR] [--shapes NAME[,NAME...]] [--size NAME=N ...]
                       [--seed-offset K] [--check] [--list]

OUTDIR defaults to the repository's Data/ folder. Without
``--shapes`` every shape is written. ``--size`` overrides a default size (for
grid5_jittered and grid4_exact N is the number of points per axis, for tree the
depth).
``--seed-offset`` shifts every seed (other draws of the same distributions).
``--check`` writes nothing: it regenerates the selected shapes whose file exists
in OUTDIR and exits non-zero if any differs by more than 1e-12 of its extent
(trigonometry may differ in the last bit between CPUs; used by the tests to check that the
clouds kept in Data/ are reproducible). ``--list`` prints the table above.

The clouds kept in the repository are ``two_hemispheres.xyz`` (3000 points) and
``torus.xyz`` (2000 points), made with::

    generate_clouds.py --shapes two_hemispheres,torus

The functions below (``sphere(n, rng)``, ...) can also be imported by tests.
"""

import argparse
import math
import os
import sys

import numpy as np

from shapes import (  # noqa: F401 (unit_vectors: also read as generate_clouds.NAME)
    _inside_solid_torus, _segment_points, ball, ball_qu, genus2, genus2_qu, grid,
    grid4_exact, grid5_jittered, plate3_qu, sphere, sphere_qu, sphere_with_segment,
    sphere_with_segment_qu, torus, torus_qu, tree, trefoil, trefoil_qu, two_hemispheres,
    two_hemispheres_qu, two_spheres, two_spheres_qu, unit_vectors, vase_qu)
from sampling import (  # noqa: F401 (some also read as generate_clouds.NAME)
    QU_FACTOR, density_varying, farthest_points, graded_poisson_disk_of, poisson_disk,
    poisson_disk_of, quasi_uniform)

# --------------------------------------------------------------------------- study shapes
# Shapes added for the t_r / t_p study (Benchmarks/Study/tr_study.py): thin parts,
# a genus-4 surface, density-varying samples, Poisson-disk quasi-uniform samples (for
# large n, where farthest_points is too slow) and regular lattices.


def _cap_angles(m, rng, R, r, lo, hi):
    """m angles v in [lo, hi] with density proportional to R + r cos v (the area
    element of a torus of core radius R and tube radius r), by rejection."""
    out, count = [], 0
    while count < m:
        k = 2 * (m - count) + 16
        v = rng.uniform(lo, hi, k)
        v = v[rng.uniform(0.0, 1.0, k) * (R + r) < R + r * np.cos(v)]
        out.append(v)
        count += len(v)
    return np.concatenate(out)[:m]


def thin_tube(n, rng, mid=0.95, half=0.05, height=1.0):
    """Boundary of a thin-walled tube with rounded rims: the points at distance `half`
    from the cylinder rho = mid, |z| <= height (its offset surface): the walls rho =
    mid +- half (1 and 0.9) for |z| <= height, closed at z = +-height by half tori
    (core circle rho = mid, tube radius half). The wall is 2 half = 0.1 thick, the
    surface is smooth (C1) and is a torus, (1, 2, 1). Uniform w.r.t. area."""
    areas = np.array([2.0 * math.pi * (mid + half) * 2.0 * height,   # outer wall
                      2.0 * math.pi * (mid - half) * 2.0 * height,   # inner wall
                      2.0 * math.pi ** 2 * mid * half,               # top half torus
                      2.0 * math.pi ** 2 * mid * half])              # bottom half torus
    which = rng.choice(4, size=n, p=areas / areas.sum())
    u = rng.uniform(0.0, 2.0 * math.pi, n)
    rho = np.empty(n)
    z = np.empty(n)
    for k, rk in ((0, mid + half), (1, mid - half)):
        sel = which == k
        rho[sel] = rk
        z[sel] = rng.uniform(-height, height, int(sel.sum()))
    for k, lo, zc in ((2, 0.0, height), (3, math.pi, -height)):
        sel = which == k
        v = _cap_angles(int(sel.sum()), rng, mid, half, lo, lo + math.pi)
        rho[sel] = mid + half * np.cos(v)
        z[sel] = zc + half * np.sin(v)
    return np.column_stack((rho * np.cos(u), rho * np.sin(u), z))


def thin_plate(n, rng, radius=1.0, half=0.05):
    """Boundary of a thin round plate: the points at distance `half` from the unit
    disk of the plane z = 0: the faces z = +-half (rho <= radius) and a half torus
    rim (core circle rho = radius, tube radius half). 0.1 thick, smooth, a sphere
    (1, 0, 1). Uniform w.r.t. area."""
    areas = np.array([math.pi * radius ** 2, math.pi * radius ** 2,
                      2.0 * math.pi * half * (math.pi * radius + 2.0 * half)])
    which = rng.choice(3, size=n, p=areas / areas.sum())
    u = rng.uniform(0.0, 2.0 * math.pi, n)
    rho = np.empty(n)
    z = np.empty(n)
    for k, zk in ((0, half), (1, -half)):
        sel = which == k
        rho[sel] = radius * np.sqrt(rng.uniform(0.0, 1.0, int(sel.sum())))
        z[sel] = zk
    sel = which == 2
    v = _cap_angles(int(sel.sum()), rng, radius, half, -0.5 * math.pi, 0.5 * math.pi)
    rho[sel] = radius + half * np.cos(v)
    z[sel] = half * np.sin(v)
    return np.column_stack((rho * np.cos(u), rho * np.sin(u), z))


def torus_row(n, rng, count, R=1.0, r=0.35, offset=1.2):
    """Boundary of the union of `count` solid tori (R, r) in the plane z = 0 centred
    at x = (i - (count - 1) / 2) 2 offset: neighbours meet in one lens (a ball) as in
    genus2, tori two apart are disjoint (4 offset = 4.8 > 2 (R + r) = 2.7). Gluing
    solid tori along balls in a chain gives a handlebody of genus `count`, whose
    boundary has Betti numbers (1, 2 count, 1). Uniform w.r.t. area (every torus
    drawn with probability 1 / count, the points inside a neighbour dropped)."""
    xs = (np.arange(count) - 0.5 * (count - 1)) * 2.0 * offset
    out, total = [], 0
    while total < n:
        m = 2 * (n - total) + 16
        which = rng.integers(0, count, m)
        p = torus(m, rng, R, r)
        p[:, 0] += xs[which]
        keep = np.ones(m, dtype=bool)
        for i in range(count):
            for j in (i - 1, i + 1):
                if 0 <= j < count:
                    sel = which == i
                    keep[sel] &= ~_inside_solid_torus(p[sel], R, r, (xs[j], 0.0, 0.0))
        out.append(p[keep])
        total += int(keep.sum())
    return np.vstack(out)[:n]


def genus4(n, rng):
    """A genus-4 surface: torus_row of 4 solid tori, (1, 8, 1)."""
    return torus_row(n, rng, 4)


thin_tube_qu = quasi_uniform(thin_tube)
thin_plate_qu = quasi_uniform(thin_plate)
genus4_qu = quasi_uniform(genus4)

# density-varying i.i.d. samples

sphere_dv = density_varying(sphere, -1.0, 1.0)
torus_dv = density_varying(torus, -1.35, 1.35)

# Poisson-disk (quasi-uniform) samples: O(candidates), for large n

TORUS_AREA = 4.0 * math.pi ** 2 * 1.0 * 0.35
THIN_TUBE_AREA = 2.0 * math.pi * 1.9 * 2.0 + 2.0 * (2.0 * math.pi ** 2 * 0.95 * 0.05)
sphere_pd = poisson_disk_of(sphere, 4.0 * math.pi)
torus_pd = poisson_disk_of(torus, TORUS_AREA)
thin_tube_pd = poisson_disk_of(thin_tube, THIN_TUBE_AREA)
sphere_dvqu = graded_poisson_disk_of(sphere, 4.0 * math.pi, -1.0, 1.0)
torus_dvqu = graded_poisson_disk_of(torus, TORUS_AREA, -1.35, 1.35)

# regular lattices (degenerate on purpose: cospherical, cocircular, coplanar points)


def lattice_shell(k, rng):
    """The integer points p with | |p| - k | < 0.5 (no point is at 0.5 exactly): a
    lattice sample of the sphere of radius k, (1, 0, 1); k = 15: 2 622 points."""
    g = np.arange(-k - 1, k + 2, dtype=float)
    p = np.stack(np.meshgrid(g, g, g, indexing="ij"), axis=-1).reshape(-1, 3)
    return p[np.abs(np.linalg.norm(p, axis=1) - k) < 0.5]


def latlong_sphere(k, rng):
    """A latitude-longitude lattice on the unit sphere: k latitudes (polar angles
    (i + 1/2) pi / k, no pole) times 2k longitudes (j pi / k), (1, 0, 1); every point
    on one sphere, every ring and every isosceles trapezoid of neighbours cocircular."""
    th = (np.arange(k) + 0.5) * math.pi / k
    ph = np.arange(2 * k) * math.pi / k
    T, P = np.meshgrid(th, ph, indexing="ij")
    T, P = T.ravel(), P.ravel()
    return np.column_stack((np.sin(T) * np.cos(P), np.sin(T) * np.sin(P), np.cos(T)))


def plane_grid_jittered(n, rng, jitter=1e-12):
    """n points of a planar a x (n / a) grid of spacing 1 (a the largest divisor of n
    not above sqrt(n): 25 x 40 for 1000) in the plane z = 0, every coordinate moved
    uniformly by +-1e-12: near-coplanar, a square (1, 0, 0)."""
    a = max(d for d in range(1, int(math.isqrt(n)) + 1) if n % d == 0)
    x, y = np.meshgrid(np.arange(n // a, dtype=float), np.arange(a, dtype=float), indexing="ij")
    p = np.column_stack((x.ravel(), y.ravel(), np.zeros(n)))
    return p + rng.uniform(-jitter, jitter, p.shape) if jitter else p



# --------------------------------------------------------------------------- topology study
# Shapes added for Benchmarks/Study/topology_study.py (the classes sampling x shape family): a genus-3
# surface, a circle, a solid cube, Poisson-disk variants of the other families and a
# Fibonacci lattice on the sphere (see the fourth table of the module docstring).


def genus3(n, rng):
    """A genus-3 surface: torus_row of 3 solid tori, (1, 6, 1)."""
    return torus_row(n, rng, 3)


# Fraction of a torus's area (R 1, r 0.35) inside its neighbour of torus_row (centres
# 2.4 apart), by Monte Carlo (2e6 points: 0.048). Only poisson_disk's first guess of
# the radius uses it (it rescales the radius until it keeps 95-100 % of the points).
TORUS_LENS_FRACTION = 0.048


def torus_row_area(count):
    """About the area of torus_row(count): each of the count - 1 lenses removes a cap
    of both neighbours."""
    return TORUS_AREA * (count - 2.0 * (count - 1) * TORUS_LENS_FRACTION)


CIRCLE_Z_JITTER = 1e-3


def _circle_points(angles, rng, n):
    """Points of the unit circle of z = 0 at `angles`, each moved off the plane by a
    uniform z in +-CIRCLE_Z_JITTER times the mean spacing 2 pi / n: the points of an
    exactly planar cloud are refused by flowrecon ('all points are coplanar'), and the
    cocircular ones would be degenerate everywhere."""
    z = rng.uniform(-CIRCLE_Z_JITTER, CIRCLE_Z_JITTER, len(angles)) * (2.0 * math.pi / n)
    return np.column_stack((np.cos(angles), np.sin(angles), z))


def circle(n, rng):
    """i.i.d. w.r.t. arc length on the unit circle (near-planar, see _circle_points)."""
    return _circle_points(rng.uniform(0.0, 2.0 * math.pi, n), rng, n)


def circle_qu(n, rng):
    """Evenly spaced on the unit circle, each point moved by at most a tenth of the
    spacing along it (as trefoil_qu), near-planar (see _circle_points)."""
    return _circle_points((np.arange(n) + rng.uniform(-0.1, 0.1, n)) * (2.0 * math.pi / n),
                          rng, n)


def cube(n, rng):
    """Uniform in the volume of the cube [-1, 1]^3 (a solid, (1, 0, 0))."""
    return rng.uniform(-1.0, 1.0, (n, 3))


def fibonacci_sphere(n, rng):
    """The Fibonacci lattice on the unit sphere: point i at height 1 - (2 i + 1) / n and
    longitude i times the golden angle pi (3 - sqrt 5). Regular (every point has about
    the same neighbourhood) but not a product lattice; deterministic (rng unused)."""
    i = np.arange(n, dtype=float)
    z = 1.0 - (2.0 * i + 1.0) / n
    rho = np.sqrt(np.maximum(0.0, 1.0 - z * z))
    phi = i * (math.pi * (3.0 - math.sqrt(5.0)))
    return np.column_stack((rho * np.cos(phi), rho * np.sin(phi), z))


def sphere_with_segment_pd(n, rng):
    """sphere_pd(n) plus the segment of sphere_with_segment_qu."""
    s = sphere_pd(n, rng)
    spacing = math.sqrt(4.0 * math.pi / n)
    return np.vstack((s, _segment_points((1.0, 0.0, 0.0), (2.0, 0.0, 0.0), spacing, rng)))


THIN_PLATE_AREA = 2.0 * math.pi + 2.0 * math.pi * 0.05 * (math.pi + 0.1)
genus2_pd = poisson_disk_of(genus2, torus_row_area(2))
genus3_pd = poisson_disk_of(genus3, torus_row_area(3))
genus4_pd = poisson_disk_of(genus4, torus_row_area(4))
ball_pd = poisson_disk_of(ball, 4.0 * math.pi / 3.0, dim=3)
cube_pd = poisson_disk_of(cube, 8.0, dim=3)
thin_plate_pd = poisson_disk_of(thin_plate, THIN_PLATE_AREA)
two_spheres_pd = poisson_disk_of(two_spheres, 8.0 * math.pi)
two_hemispheres_pd = poisson_disk_of(two_hemispheres, 4.0 * math.pi)
genus3_qu = quasi_uniform(genus3)
cube_qu = quasi_uniform(cube)

# name -> (function(size, rng), default size, seed, (b0, b1, b2))
SHAPES = {
    "sphere": (sphere, 2000, 101, (1, 0, 1)),
    "torus": (torus, 2000, 102, (1, 2, 1)),
    "genus2": (genus2, 3000, 103, (1, 4, 1)),
    "trefoil": (trefoil, 1000, 104, (1, 1, 0)),
    "ball": (ball, 2000, 105, (1, 0, 0)),
    "two_spheres": (two_spheres, 3000, 106, (1, 0, 3)),
    "two_hemispheres": (two_hemispheres, 3000, 107, (1, 0, 0)),
    "sphere_with_segment": (sphere_with_segment, 2000, 108, (1, 0, 1)),
    "grid5_jittered": (grid5_jittered, 5, 109, (1, 0, 0)),
    "grid4_exact": (grid4_exact, 4, 110, (1, 0, 0)),
    # quasi-uniform samples (see the second table above)
    "sphere_qu": (sphere_qu, 1000, 201, (1, 0, 1)),
    "torus_qu": (torus_qu, 2000, 202, (1, 2, 1)),
    "genus2_qu": (genus2_qu, 3000, 203, (1, 4, 1)),
    "trefoil_qu": (trefoil_qu, 600, 204, (1, 1, 0)),
    "ball_qu": (ball_qu, 2000, 205, (1, 0, 0)),
    "two_spheres_qu": (two_spheres_qu, 3000, 206, (1, 0, 3)),
    "two_hemispheres_qu": (two_hemispheres_qu, 3000, 207, (1, 0, 0)),
    "sphere_with_segment_qu": (sphere_with_segment_qu, 2000, 208, (1, 0, 1)),
    "vase_qu": (vase_qu, 3000, 209, (1, 2, 0)),
    "plate3_qu": (plate3_qu, 8000, 210, (1, 6, 1)),
    "tree": (tree, 5, 211, (1, 0, 0)),
    # added for Benchmarks/Study/tr_study.py (see the third table above)
    "thin_tube": (thin_tube, 4000, 301, (1, 2, 1)),
    "thin_tube_qu": (thin_tube_qu, 4000, 302, (1, 2, 1)),
    "thin_plate": (thin_plate, 2000, 303, (1, 0, 1)),
    "thin_plate_qu": (thin_plate_qu, 2000, 304, (1, 0, 1)),
    "genus4": (genus4, 4000, 305, (1, 8, 1)),
    "genus4_qu": (genus4_qu, 4000, 306, (1, 8, 1)),
    "sphere_dv": (sphere_dv, 2000, 307, (1, 0, 1)),
    "torus_dv": (torus_dv, 2000, 308, (1, 2, 1)),
    "sphere_dvqu": (sphere_dvqu, 2000, 309, (1, 0, 1)),
    "torus_dvqu": (torus_dvqu, 2000, 310, (1, 2, 1)),
    "sphere_pd": (sphere_pd, 2000, 311, (1, 0, 1)),
    "torus_pd": (torus_pd, 2000, 312, (1, 2, 1)),
    "thin_tube_pd": (thin_tube_pd, 4000, 316, (1, 2, 1)),
    "lattice_shell": (lattice_shell, 15, 313, (1, 0, 1)),
    "latlong_sphere": (latlong_sphere, 30, 314, (1, 0, 1)),
    "plane_grid_jittered": (plane_grid_jittered, 1000, 315, (1, 0, 0)),
    # added for Benchmarks/Study/topology_study.py (see the fourth table above)
    "genus3": (genus3, 3000, 401, (1, 6, 1)),
    "genus3_qu": (genus3_qu, 3000, 402, (1, 6, 1)),
    "genus3_pd": (genus3_pd, 3000, 403, (1, 6, 1)),
    "genus2_pd": (genus2_pd, 3000, 404, (1, 4, 1)),
    "genus4_pd": (genus4_pd, 4000, 405, (1, 8, 1)),
    "circle": (circle, 1000, 406, (1, 1, 0)),
    "circle_qu": (circle_qu, 1000, 407, (1, 1, 0)),
    "cube": (cube, 2000, 408, (1, 0, 0)),
    "cube_qu": (cube_qu, 2000, 409, (1, 0, 0)),
    "cube_pd": (cube_pd, 2000, 410, (1, 0, 0)),
    "ball_pd": (ball_pd, 2000, 411, (1, 0, 0)),
    "thin_plate_pd": (thin_plate_pd, 2000, 412, (1, 0, 1)),
    "two_spheres_pd": (two_spheres_pd, 3000, 413, (1, 0, 3)),
    "two_hemispheres_pd": (two_hemispheres_pd, 3000, 414, (1, 0, 0)),
    "sphere_with_segment_pd": (sphere_with_segment_pd, 2000, 415, (1, 0, 1)),
    "fibonacci_sphere": (fibonacci_sphere, 2000, 416, (1, 0, 1)),
}


def make(name, size=None, seed_offset=0):
    """The cloud `name` as an (n, 3) float64 array (deterministic)."""
    func, default, seed, _ = SHAPES[name]
    rng = np.random.default_rng(seed + seed_offset)
    return np.ascontiguousarray(func(default if size is None else size, rng), dtype=float)


def betti(name):
    return SHAPES[name][3]


def to_xyz_text(points):
    return "".join("%r %r %r\n" % (float(x), float(y), float(z)) for x, y, z in points)


def read_xyz(path):
    return np.loadtxt(path, dtype=float, ndmin=2)[:, :3]


# --------------------------------------------------------------------------- command line


def main(argv=None):
    data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default=os.path.normpath(data),
                    help="output folder (default: %(default)s)")
    ap.add_argument("--shapes", default=",".join(SHAPES), help="comma-separated shape names")
    ap.add_argument("--size", action="append", default=[], metavar="NAME=N",
                    help="size of one shape (repeatable)")
    ap.add_argument("--seed-offset", type=int, default=0)
    ap.add_argument("--check", action="store_true",
                    help="compare with the existing files in OUTDIR instead of writing")
    ap.add_argument("--list", action="store_true", help="list the shapes and exit")
    args = ap.parse_args(argv)

    if args.list:
        for name, (_, size, seed, b) in SHAPES.items():
            print("%-22s size %5d  seed %d  betti %s" % (name, size, seed, b))
        return 0
    names = [s for s in args.shapes.split(",") if s]
    unknown = [s for s in names if s not in SHAPES]
    if unknown:
        ap.error("unknown shape(s): %s (known: %s)" % (", ".join(unknown), ", ".join(SHAPES)))
    sizes = {}
    for item in args.size:
        name, _, value = item.partition("=")
        if name not in SHAPES or not value.isdigit():
            ap.error("bad --size %r (want NAME=N)" % item)
        sizes[name] = int(value)

    status = 0
    if not args.check:
        os.makedirs(args.outdir, exist_ok=True)
    for name in names:
        text = to_xyz_text(make(name, sizes.get(name), args.seed_offset))
        path = os.path.join(args.outdir, name + ".xyz")
        if args.check:
            if not os.path.exists(path):
                continue
            with open(path) as f:
                kept = f.read()
            # numpy's sin/cos/exp take CPU-dependent (SIMD) paths that may differ in
            # the last bit: the same cloud up to a few ulps is the same cloud.
            same = kept == text or same_points(kept, text)
            print("%s: %s" % (path, "reproduced" if same else "DIFFERS from the generator"))
            status |= 0 if same else 1
        else:
            with open(path, "w") as f:
                f.write(text)
            print("wrote %s (%d points, betti %s)" % (path, text.count("\n"), betti(name)))
    return status


def same_points(a, b):
    """True when two .xyz texts hold the same points up to 1e-12 of the cloud's extent."""
    x = np.loadtxt(a.splitlines(), ndmin=2)
    y = np.loadtxt(b.splitlines(), ndmin=2)
    if x.shape != y.shape:
        return False
    extent = max(np.ptp(x, axis=0).max(), 1e-300)
    return bool(np.abs(x - y).max() <= 1e-12 * extent)


if __name__ == "__main__":
    sys.exit(main())
