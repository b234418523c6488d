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

Command line::

    generate_clouds.py [OUTDIR] [--shapes NAME[,NAME...]] [--size NAME=N ...]
                       [--seed-offset K] [--check] [--list]

OUTDIR defaults to the folder of this script (the Data/ folder). Without
``--shapes`` every shape is written. ``--size`` overrides a default size (for
grid5_jittered and grid4_exact N is the number of points per axis).
``--seed-offset`` shifts every seed (other draws of the same distributions).
``--check`` writes nothing: it regenerates the selected shapes whose file exists
in OUTDIR and exits non-zero if any differs (used by the tests to check that the
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

# --------------------------------------------------------------------------- samplers


def unit_vectors(n, rng):
    """n directions uniform on the unit sphere (normalised Gaussians)."""
    v = rng.standard_normal((n, 3))
    return v / np.linalg.norm(v, axis=1)[:, None]


def sphere(n, rng, center=(0.0, 0.0, 0.0), radius=1.0):
    return np.asarray(center, dtype=float) + radius * unit_vectors(n, rng)


def torus(n, rng, R=1.0, r=0.35, center=(0.0, 0.0, 0.0)):
    """Uniform w.r.t. area: the area element is r (R + r cos v) du dv, so accept a
    uniform (u, v) with probability (R + r cos v) / (R + r)."""
    out = []
    count = 0
    while count < n:
        m = 2 * (n - count) + 16
        u = rng.uniform(0.0, 2.0 * math.pi, m)
        v = rng.uniform(0.0, 2.0 * math.pi, m)
        keep = rng.uniform(0.0, 1.0, m) * (R + r) < R + r * np.cos(v)
        u, v = u[keep], v[keep]
        p = np.column_stack(
            ((R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)))
        out.append(p)
        count += len(p)
    return np.vstack(out)[:n] + np.asarray(center, dtype=float)


def _inside_solid_torus(p, R, r, center):
    q = p - np.asarray(center, dtype=float)
    rho = np.hypot(q[:, 0], q[:, 1])
    return (rho - R) ** 2 + q[:, 2] ** 2 < r * r


def genus2(n, rng, R=1.0, r=0.35, offset=1.2):
    """Boundary of the union of two solid tori centred at (+-offset, 0, 0). Their
    intersection is a single lens (the core circles are 2*offset - 2R = 0.4 < 2r
    apart), so the union is a genus-2 handlebody. Both tori have the same area:
    draw from either with probability 1/2 and drop the points inside the other."""
    centers = ((-offset, 0.0, 0.0), (offset, 0.0, 0.0))
    out = []
    count = 0
    while count < n:
        m = 2 * (n - count) + 16
        which = rng.integers(0, 2, m)
        p = torus(m, rng, R, r)
        p[:, 0] += np.where(which == 0, -offset, offset)
        other0 = _inside_solid_torus(p, R, r, centers[1])  # points of torus 0 inside torus 1
        other1 = _inside_solid_torus(p, R, r, centers[0])
        keep = np.where(which == 0, ~other0, ~other1)
        p = p[keep]
        out.append(p)
        count += len(p)
    return np.vstack(out)[:n]


def _trefoil_curve(t):
    return np.column_stack(
        (np.sin(t) + 2.0 * np.sin(2.0 * t), np.cos(t) - 2.0 * np.cos(2.0 * t), -np.sin(3.0 * t))) / 3.0


def trefoil(n, rng):
    """Uniform w.r.t. arc length (inverse of a fine arc-length table)."""
    t = np.linspace(0.0, 2.0 * math.pi, 200001)
    p = _trefoil_curve(t)
    s = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))))
    target = rng.uniform(0.0, s[-1], n)
    return _trefoil_curve(np.interp(target, s, t))


def ball(n, rng, radius=1.0):
    return unit_vectors(n, rng) * (radius * rng.uniform(0.0, 1.0, n) ** (1.0 / 3.0))[:, None]


def two_spheres(n, rng):
    a = n // 2
    return np.vstack((sphere(a, rng, (-0.5, 0.0, 0.0)), sphere(n - a, rng, (0.5, 0.0, 0.0))))


def upper_hemisphere(n, rng, center):
    v = unit_vectors(n, rng)
    v[:, 2] = np.abs(v[:, 2])
    return v + np.asarray(center, dtype=float)


def two_hemispheres(n, rng):
    a = n // 2
    return np.vstack((upper_hemisphere(a, rng, (-0.5, 0.0, 0.0)),
                      upper_hemisphere(n - a, rng, (0.5, 0.0, 0.0))))


def sphere_with_segment(n, rng):
    """n points on the unit sphere, plus the segment (1,0,0)-(2,0,0) at the mean
    spacing of the sphere sample, every point moved by a random offset of at most
    a tenth of the spacing (so no three are collinear)."""
    s = sphere(n, rng)
    spacing = math.sqrt(4.0 * math.pi / n)
    k = max(2, int(math.ceil(1.0 / spacing)))
    x = 1.0 + np.arange(1, k + 1) / k  # the attachment point (1,0,0) itself is left to the sphere
    seg = np.column_stack((x, np.zeros(k), np.zeros(k)))
    seg += rng.uniform(-0.1 * spacing, 0.1 * spacing, seg.shape) / math.sqrt(3.0)
    return np.vstack((s, seg))


def grid(k, jitter=0.0, rng=None):
    g = np.arange(k, dtype=float)
    p = np.array([(x, y, z) for x in g for y in g for z in g], dtype=float)
    if jitter:
        p += rng.uniform(-jitter, jitter, p.shape)
    return p


def grid5_jittered(k, rng):
    return grid(k, 1e-3, rng)


def grid4_exact(k, rng):
    return grid(k)


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
    here = os.path.dirname(os.path.abspath(__file__))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir", nargs="?", default=here, help="output folder (default: %(default)s)")
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
            print("%-20s size %5d  seed %d  betti %s" % (name, size, seed, b))
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
                same = f.read() == text
            print("%s: %s" % (path, "reproduced" if same else "DIFFERS from the generator"))
            status |= 0 if same else 1
        else:
            with open(path, "w") as f:
                f.write(text)
            print("wrote %s (%d points, betti %s)" % (path, text.count("\n"), betti(name)))
    return status


if __name__ == "__main__":
    sys.exit(main())
