"""The small clouds the tests draw, each written once. Every generator takes the
test's numpy Generator and draws in a fixed order, so a test that keeps its seed
keeps its cloud bit for bit. The shapes with known topology, sampled for the
studies, are Apps/Scripts/generate_clouds.py's."""
import os

import generate_clouds as gc
import numpy as np

DATA = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                     "..", "..", "..", "Data"))


def write_xyz(path, points):
    """Writes the cloud with every digit of its doubles; returns path."""
    np.savetxt(path, points, fmt="%.17g")
    return path


def sphere(n, rng):
    """n points i.i.d. on the unit sphere."""
    return gc.unit_vectors(n, rng)


def chart_torus(n, rng, r=0.35):
    """n points on the torus of radii 1 and r, uniform in its angles (denser inside
    than outside, unlike generate_clouds' torus, uniform in area)."""
    u, v = rng.uniform(0, 2 * np.pi, (2, n))
    return np.c_[(1 + r * np.cos(v)) * np.cos(u), (1 + r * np.cos(v)) * np.sin(u), r * np.sin(v)]


def grid(*axes, indexing="xy"):
    """The points of the lattice of the three axes, in numpy.meshgrid's order."""
    return np.array(np.meshgrid(*axes, indexing=indexing)).reshape(3, -1).T


def shell(n, rng):
    """n points i.i.d. between the spheres of radii 1 and 1.05: exactly spherical
    samples would be nearly cospherical."""
    return gc.sphere(n, rng) * rng.uniform(1.0, 1.05, (n, 1))


def noisy(points, rng, sigma):
    """points moved radially by a relative normal noise of deviation sigma."""
    return points * (1 + sigma * rng.normal(size=(len(points), 1)))


def with_segment(points, t):
    """points and the segment through the origin along y, nearly straight, at the
    parameters t."""
    return np.r_[points, np.c_[0.01 * t, t, 0.02 * t]]


def basic_clouds(rng, cube, sphere_points, torus, indexing="xy"):
    """{name: points} of the clouds the comparisons start from: i.i.d. in the unit
    cube, on the unit sphere and on the torus (chart_torus), of the given sizes, and
    the exact, degenerate, 6 x 6 x 5 grid."""
    g = np.arange(6.0)
    return {"cube": rng.uniform(0, 1, (cube, 3)), "sphere": sphere(sphere_points, rng),
            "torus": chart_torus(torus, rng), "grid 6x6x5": grid(g, g, g[:5], indexing=indexing)}


def topology_fixtures(rng, sphere_points, torus_points, ball_points, curve_points,
                      segment_sphere_points):
    """{name: points} of the clouds the topology tests check against GUDHI: a
    sphere, a torus (r 0.4), a ball, a trefoil, the paper's two hemispheres, a sphere
    with a segment, an exact (degenerate) 5 x 5 x 5 grid and a noisy sphere."""
    ball = sphere(sphere_points, rng)
    torus = chart_torus(torus_points, rng, 0.4)
    t = np.linspace(0, 2 * np.pi, curve_points, endpoint=False)
    g = np.arange(5.0)
    return {
        "sphere": ball,
        "torus": torus,
        "ball": rng.uniform(-1, 1, (ball_points, 3)),
        "trefoil": np.c_[np.sin(t) + 2 * np.sin(2 * t), np.cos(t) - 2 * np.cos(2 * t),
                         -np.sin(3 * t)],
        "two hemispheres": two_hemispheres(),
        "sphere and segment": with_segment(ball[:segment_sphere_points],
                                           np.linspace(-1.7, 1.7, 40)),
        "grid": grid(g, g, g),
        "noisy sphere": noisy(ball, rng, 0.04),
    }


def two_hemispheres():
    """The paper's two hemispheres, Data/two_hemispheres.xyz."""
    return np.loadtxt(os.path.join(DATA, "two_hemispheres.xyz"))[:, :3]


def random_cloud(kind, n, seed, cube=(0.0, 1.0)):
    """A cloud of n points from the seed: cube (uniform in cube^3), sphere (a shell),
    unit sphere (on it up to rounding: a stress test of exactness), torus, grid (a
    jittered lattice of about n points)."""
    rng = np.random.default_rng(seed)
    if kind == "cube":
        return rng.uniform(cube[0], cube[1], (n, 3))
    if kind == "sphere":
        return shell(n, rng)
    if kind == "unit sphere":
        return gc.sphere(n, rng)
    if kind == "torus":
        return gc.torus(n, rng)
    if kind == "grid":
        return gc.grid(int(round(n ** (1.0 / 3.0))), 1e-3, rng)
    raise ValueError(kind)


def noisy_surface(shape, n, times, seed):
    """generate_clouds' `shape` with n points plus Gaussian noise of standard
    deviation `times` its mean nearest-neighbour spacing per coordinate: the
    topology study's noisy class (its seed is the study's cloud name's CRC32)."""
    from scipy.spatial import cKDTree
    points = gc.make(shape, n)
    d, _ = cKDTree(points).query(points, k=2)
    rng = np.random.default_rng(seed)
    return points + rng.normal(0.0, times * float(np.mean(d[:, 1])), points.shape)

