"""The basic and composite shapes of generate_clouds.py, each a sampler
``func(n, rng)`` (or ``func(k, rng)`` for lattices) returning an (n, 3) array:
spheres, tori, a genus-2 surface, a trefoil, balls, hemispheres, grids, and the
composite parts (a vase, a plate with holes, a tree of segments). Their sizes, seeds
and Betti numbers are in generate_clouds.SHAPES.
"""

import math

import numpy as np

from sampling import QU_FACTOR, farthest_points, quasi_uniform

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


# --------------------------------------------------------------------------- quasi-uniform

sphere_qu = quasi_uniform(sphere)
torus_qu = quasi_uniform(torus)
genus2_qu = quasi_uniform(genus2)
ball_qu = quasi_uniform(ball)
two_spheres_qu = quasi_uniform(two_spheres)
two_hemispheres_qu = quasi_uniform(two_hemispheres)


def trefoil_qu(n, rng):
    """Evenly spaced in arc length, each point moved by at most a tenth of the
    spacing along the curve."""
    t = np.linspace(0.0, 2.0 * math.pi, 200001)
    p = _trefoil_curve(t)
    s = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(p, axis=0), axis=1))))
    target = (np.arange(n) + rng.uniform(-0.1, 0.1, n)) * (s[-1] / n)
    return _trefoil_curve(np.interp(np.mod(target, s[-1]), s, t))


def _segment_points(a, b, spacing, rng):
    """Points of the segment a-b (a excluded, b included) at about `spacing`,
    each moved by a random offset of at most a tenth of the spacing."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    k = max(2, int(math.ceil(np.linalg.norm(b - a) / spacing)))
    seg = a + (np.arange(1, k + 1) / k)[:, None] * (b - a)
    return seg + rng.uniform(-0.1 * spacing, 0.1 * spacing, seg.shape) / math.sqrt(3.0)


def sphere_with_segment_qu(n, rng):
    s = sphere_qu(n, rng)
    spacing = math.sqrt(4.0 * math.pi / n)
    return np.vstack((s, _segment_points((1.0, 0.0, 0.0), (2.0, 0.0, 0.0), spacing, rng)))


def _vase_radius(z):
    return 0.55 + 0.25 * np.sin(1.5 * math.pi * z / 2.0 + 0.3)


def _vase_surface(n, rng, height=2.0):
    """i.i.d. w.r.t. area: the wall (rejection on r(z) sqrt(1 + r'(z)^2)) and the
    flat bottom disk z = 0."""
    zz = np.linspace(0.0, height, 4001)
    r = _vase_radius(zz)
    dr = np.gradient(r, zz)
    density = r * np.sqrt(1.0 + dr * dr)
    wall_area = 2.0 * math.pi * np.trapz(density, zz)
    r0 = float(_vase_radius(0.0))
    bottom_area = math.pi * r0 * r0
    n_bottom = int(round(n * bottom_area / (wall_area + bottom_area)))
    out, count, dmax = [], 0, density.max()
    while count < n - n_bottom:
        m = 2 * (n - n_bottom - count) + 16
        z = rng.uniform(0.0, height, m)
        keep = rng.uniform(0.0, dmax, m) < np.interp(z, zz, density)
        z = z[keep]
        a = rng.uniform(0.0, 2.0 * math.pi, len(z))
        rz = _vase_radius(z)
        out.append(np.column_stack((rz * np.cos(a), rz * np.sin(a), z)))
        count += len(z)
    wall = np.vstack(out)[: n - n_bottom]
    rho = r0 * np.sqrt(rng.uniform(0.0, 1.0, n_bottom))
    a = rng.uniform(0.0, 2.0 * math.pi, n_bottom)
    bottom = np.column_stack((rho * np.cos(a), rho * np.sin(a), np.zeros(n_bottom)))
    return np.vstack((wall, bottom)), wall_area + bottom_area


def vase_qu(n, rng):
    """The vase: a quasi-uniform sample of the surface (n points) plus two handles
    sampled as curves at the surface's spacing: the arcs
    wall(z(s)) + 0.5 sin(pi s) (cos th, sin th, 0), z(s) = 0.6 + 0.9 s, 0 < s < 1,
    for th = 0 and pi (their ends are on the wall)."""
    dense, area = _vase_surface(QU_FACTOR * n, rng)
    surf = farthest_points(dense, n)
    spacing = math.sqrt(area / n)
    handles = []
    for th in (0.0, math.pi):
        s = np.linspace(0.0, 1.0, 20001)
        z = 0.6 + 0.9 * s
        rad = _vase_radius(z) + 0.5 * np.sin(math.pi * s)
        curve = np.column_stack((rad * math.cos(th), rad * math.sin(th), z))
        length = np.concatenate(([0.0], np.cumsum(np.linalg.norm(np.diff(curve, axis=0), axis=1))))
        k = max(2, int(math.ceil(length[-1] / spacing)))
        target = (np.arange(1, k) + rng.uniform(-0.1, 0.1, k - 1)) * (length[-1] / k)
        si = np.interp(target, length, s)
        zi = 0.6 + 0.9 * si
        radi = _vase_radius(zi) + 0.5 * np.sin(math.pi * si)
        handles.append(np.column_stack((radi * math.cos(th), radi * math.sin(th), zi)))
    return np.vstack([surf] + handles)


PLATE_HALF = (2.0, 0.8, 0.25)
PLATE_HOLES = (-1.3, 0.0, 1.3)
PLATE_HOLE_RADIUS = 0.4


def _plate_surface(n, rng):
    """i.i.d. w.r.t. area on the surface of the plate with three through holes:
    top and bottom faces minus the disks, the four sides, the three hole walls."""
    ax, ay, az = PLATE_HALF
    rh = PLATE_HOLE_RADIUS
    holes = np.asarray(PLATE_HOLES)
    faces_area = 2.0 * (4.0 * ax * ay - len(holes) * math.pi * rh * rh)
    sides_x = 2.0 * (2.0 * ay * 2.0 * az)   # faces x = +-ax
    sides_y = 2.0 * (2.0 * ax * 2.0 * az)   # faces y = +-ay
    walls = len(holes) * 2.0 * math.pi * rh * 2.0 * az
    areas = np.array([faces_area, sides_x, sides_y, walls])
    which = rng.choice(4, size=n, p=areas / areas.sum())
    out = []
    # top / bottom faces: rejection of the hole disks
    m = int(np.sum(which == 0))
    pts, count = [], 0
    while count < m:
        k = 2 * (m - count) + 16
        x = rng.uniform(-ax, ax, k)
        y = rng.uniform(-ay, ay, k)
        ok = np.all((x[:, None] - holes[None, :]) ** 2 + y[:, None] ** 2 >= rh * rh, axis=1)
        z = np.where(rng.integers(0, 2, k) == 0, -az, az)
        pts.append(np.column_stack((x, y, z))[ok])
        count += int(ok.sum())
    out.append(np.vstack(pts)[:m])
    m = int(np.sum(which == 1))
    out.append(np.column_stack((np.where(rng.integers(0, 2, m) == 0, -ax, ax),
                                rng.uniform(-ay, ay, m), rng.uniform(-az, az, m))))
    m = int(np.sum(which == 2))
    out.append(np.column_stack((rng.uniform(-ax, ax, m),
                                np.where(rng.integers(0, 2, m) == 0, -ay, ay),
                                rng.uniform(-az, az, m))))
    m = int(np.sum(which == 3))
    a = rng.uniform(0.0, 2.0 * math.pi, m)
    c = holes[rng.integers(0, len(holes), m)]
    out.append(np.column_stack((c + rh * np.cos(a), rh * np.sin(a), rng.uniform(-az, az, m))))
    return np.vstack(out)


def plate3_qu(n, rng):
    return farthest_points(_plate_surface(4 * n, rng), n)


def _segment_distance(p0, p1, q0, q1, samples=64):
    """Distance between two segments (on 64 points each: enough for a clearance test)."""
    s = np.linspace(0.0, 1.0, samples)
    a = p0 + s[:, None] * (p1 - p0)
    b = q0 + s[:, None] * (q1 - q0)
    return float(np.sqrt(np.min(np.sum((a[:, None, :] - b[None, :, :]) ** 2, axis=2))))


TREE_CLEARANCE = 0.1


def _tree_branches(depth, rng):
    """Segments (start, end, radius) of a random branching tree: a trunk of length
    1 along z, then per level 2 or 3 children from the end of their parent, length
    x0.7, radius x0.7, directions at 25..55 degrees from the parent's, spread
    evenly around it with a random phase. A child that would come closer than
    TREE_CLEARANCE to a branch it does not touch is drawn again (up to 20 times,
    then left out), so the tree of curves has no extra loop at the sampling scale."""
    branches = [(np.zeros(3), np.array([0.0, 0.0, 1.0]), 0.012)]
    frontier = [0]
    for _level in range(depth):
        nxt = []
        for b in frontier:
            start, end, radius = branches[b]
            axis = (end - start) / np.linalg.norm(end - start)
            helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
            u = np.cross(axis, helper)
            u /= np.linalg.norm(u)
            v = np.cross(axis, u)
            k = int(rng.integers(2, 4))
            phase = rng.uniform(0.0, 2.0 * math.pi)
            length = np.linalg.norm(end - start) * 0.7
            for i in range(k):
                for _attempt in range(20):
                    tilt = math.radians(rng.uniform(25.0, 55.0))
                    turn = phase + 2.0 * math.pi * i / k + rng.uniform(-0.3, 0.3)
                    d = math.cos(tilt) * axis + math.sin(tilt) * (
                        math.cos(turn) * u + math.sin(turn) * v)
                    tip = end + length * d
                    clear = True
                    for (s0, s1, _r) in branches:
                        touching = min(np.linalg.norm(a - c) for a in (end, tip)
                                       for c in (s0, s1)) < 1e-12
                        if not touching and _segment_distance(end, tip, s0, s1) < TREE_CLEARANCE:
                            clear = False
                            break
                    if clear:
                        break
                if clear:
                    branches.append((end, tip, radius * 0.7))
                    nxt.append(len(branches) - 1)
        frontier = nxt
    return branches


def tree(depth, rng, step=0.02):
    """Points on the thin cylinders around the branches of _tree_branches, one
    every `step` along each axis at a random angle, plus the root (0, 0, 0)."""
    branches = _tree_branches(depth, rng)
    out = []
    for start, end, radius in branches:
        axis = end - start
        length = np.linalg.norm(axis)
        axis /= length
        helper = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
        u = np.cross(axis, helper)
        u /= np.linalg.norm(u)
        v = np.cross(axis, u)
        k = max(2, int(math.ceil(length / step)))
        t = (np.arange(1, k + 1) / k) * length  # the start is the parent's end
        a = rng.uniform(0.0, 2.0 * math.pi, k)
        out.append(start + t[:, None] * axis
                   + radius * (np.cos(a)[:, None] * u + np.sin(a)[:, None] * v))
    root = np.zeros((1, 3))
    return np.vstack([root] + out)
