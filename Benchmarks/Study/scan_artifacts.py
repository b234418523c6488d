#!/usr/bin/python3
"""The automatic thresholds on clouds with what scanning and storage do to them,
and on curves, none of them in the topology study:
- several scans of one object, misregistered: the unit sphere and the torus (R 1,
  r 0.35) sampled i.i.d., each of 6 views (random directions) keeping the points
  that face it (more than 0.1 along it from the centre) and moved by its own
  small rigid motion (a rotation of `angle` radians about a random axis, a shift
  of normal deviation `shift` on each coordinate): overlaps hold two or three
  slightly offset layers;
- quantized coordinates: i.i.d. sphere and torus points rounded to a grid of
  step 10^-3 to 10^-2 (duplicates, coplanar and cospherical sets: the
  perturbation's work);
- rows far finer along than across: the unit sphere scanned along parallels 0.06
  and 0.03 apart with points 0.01 apart on each (and the first thinned to every
  sixth point, even), and grids of vertices on a tube around a trefoil knot
  (1 2 1), 200 x 12 to 1000 x 12 around it;
- curves: the edges of the unit cube sampled at a spacing (a wire frame, 1 5 0),
  a trefoil knot and a closed toroidal helix (1 1 0), evenly in their parameter.
`flowrecon reconstruct` runs at its defaults and at `--tp 1.1 --tr 2`; verdicts
as in held_out_shapes.py (right, flagged: wrong with a warning, silent: wrong
without one). Prints a Markdown table and the counts.

  /usr/bin/python3 Benchmarks/Study/scan_artifacts.py build/bin/flowrecon WORKDIR
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import held_out_shapes as ho  # noqa: E402
import separate_surfaces as ss  # noqa: E402


def sphere(rng, n):
    return ss.iid_sphere(rng, n)


def torus(rng, n):
    return ss.iid_torus(rng, n, 1.0, 0.35)


def rotation(rng, angle):
    """A rotation by `angle` about a random axis (Rodrigues)."""
    a = rng.normal(size=3)
    a /= np.linalg.norm(a)
    k = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + np.sin(angle) * k + (1 - np.cos(angle)) * k @ k


def scans(rng, make, n, views, shift, angle):
    """`views` scans of `make`'s n points, misregistered (see above)."""
    p = make(rng, n)
    out = []
    for d in sphere(rng, views):
        seen = p[p @ d > 0.1]
        out.append(seen @ rotation(rng, angle).T + rng.normal(size=3) * shift)
    return np.vstack(out)


def polyline(corners, spacing):
    out = []
    for a, b in zip(corners[:-1], corners[1:]):
        t = np.linspace(0, 1, max(2, int(np.linalg.norm(b - a) / spacing)), endpoint=False)[:, None]
        out.append(a + t * (b - a))
    return np.vstack(out)


def wire_cube(spacing):
    c = np.array([[x, y, z] for x in (0, 1) for y in (0, 1) for z in (0, 1)], float)
    edges = [(i, j) for i in range(8) for j in range(i + 1, 8) if np.abs(c[i] - c[j]).sum() == 1]
    return np.unique(np.vstack([polyline([c[i], c[j]], spacing) for i, j in edges] + [c]), axis=0)


def parallels(across, along, keep_every=1):
    """The unit sphere scanned along parallels: points `along` apart on each,
    the parallels `across` apart in latitude (from across / 2 off the poles)."""
    rows = []
    for polar in np.arange(across / 2, np.pi, across):
        r = np.sin(polar)
        m = max(3, int(2 * np.pi * r / along))
        t = np.linspace(0, 2 * np.pi, m, endpoint=False)[::keep_every]
        rows.append(np.c_[r * np.cos(t), r * np.sin(t), np.full(len(t), np.cos(polar))])
    return np.vstack(rows)


def trefoil(t):
    """The trefoil knot at parameters t."""
    return np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t), -np.sin(3 * t)]


def knot_tube(nu, nv, radius):
    """The vertices of an nu x nv grid on a tube of `radius` around the trefoil
    (a closed tube: Betti numbers 1 2 1)."""
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, nu, endpoint=False),
                       np.linspace(0, 2 * np.pi, nv, endpoint=False), indexing="ij")
    u, v = u.ravel(), v.ravel()
    h = 1e-4
    tangent = trefoil(u + h) - trefoil(u - h)
    tangent /= np.linalg.norm(tangent, axis=1)[:, None]
    normal = np.cross(tangent, [0.3, 0.5, 0.81])
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    binormal = np.cross(tangent, normal)
    return trefoil(u) + radius * (np.cos(v)[:, None] * normal + np.sin(v)[:, None] * binormal)


def toroidal_helix(n):
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    r = 2 + 0.5 * np.cos(12 * t)
    return np.c_[r * np.cos(t), r * np.sin(t), 0.5 * np.sin(12 * t)]


def clouds():
    """Yields (name, true Betti numbers, function of a numpy Generator giving the cloud)."""
    for n in (12000, 80000):
        for shift, angle in ((0.003, 0.003), (0.01, 0.01), (0.03, 0.02)):
            for name, make, truth in (("sphere", sphere, (1, 0, 1)), ("torus", torus, (1, 2, 1))):
                yield ("%s, 6 scans of %d points, shift %g" % (name, n, shift), truth,
                       lambda rng, m=make, n=n, s=shift, a=angle: scans(rng, m, n, 6, s, a))
    for n, step in ((5000, 1e-2), (20000, 1e-3), (20000, 5e-3), (100000, 1e-3)):
        for name, make, truth in (("sphere", sphere, (1, 0, 1)), ("torus", torus, (1, 2, 1))):
            yield ("%s, %d points quantized to %g" % (name, n, step), truth,
                   lambda rng, m=make, n=n, s=step: np.round(m(rng, n) / s) * s)
    for spacing in (0.05, 0.02):
        yield "cube's edges, spacing %g" % spacing, (1, 5, 0), lambda rng, s=spacing: wire_cube(s)
    for across in (0.06, 0.03):
        yield ("sphere scanned along parallels %g apart, 0.01 along" % across, (1, 0, 1),
               lambda rng, a=across: parallels(a, 0.01))
    yield ("sphere scanned along parallels 0.06 apart, every sixth point", (1, 0, 1),
           lambda rng: parallels(0.06, 0.01, 6))
    for nu, nv, radius in ((200, 12, 0.3), (1000, 12, 0.4), (600, 24, 0.3)):
        yield ("trefoil tube, %d x %d grid, radius %g" % (nu, nv, radius), (1, 2, 1),
               lambda rng, nu=nu, nv=nv, r=radius: knot_tube(nu, nv, r))
    for n in (300, 1000, 5000):
        yield ("trefoil knot, %d points" % n, (1, 1, 0),
               lambda rng, n=n: trefoil(np.linspace(0, 2 * np.pi, n, endpoint=False)))
        yield "toroidal helix, %d points" % n, (1, 1, 0), lambda rng, n=n: toroidal_helix(n)


def main():
    args = ho.arguments(__doc__)
    return ho.compare(args.flowrecon, args.work, ["cloud"],
                      (([name], make(np.random.default_rng(100 + k)), truth)
                       for k, (name, truth, make) in enumerate(clouds())))


if __name__ == "__main__":
    main()
