"""How the shapes of generate_clouds.py are sampled beyond i.i.d.: quasi-uniform
(farthest points of many i.i.d. candidates, or a Poisson-disk pass over them, linear
in the candidates), density growing along x, and graded Poisson-disk samples. Each
wrapper turns a sampler ``func(n, rng)`` into another with the same signature.
"""

import numpy as np

QU_FACTOR = 30


def farthest_points(candidates, n):
    """Greedy farthest-point subsampling: n of the candidates, starting from the
    first, each next one the farthest from those already chosen (ties: the lowest
    index). Deterministic; the chosen points are about evenly spaced."""
    c = np.ascontiguousarray(candidates, dtype=float)
    if n >= len(c):
        return c.copy()
    chosen = np.empty(n, dtype=np.int64)
    chosen[0] = 0
    d = np.einsum("ij,ij->i", c - c[0], c - c[0])
    for i in range(1, n):
        j = int(np.argmax(d))
        chosen[i] = j
        diff = c - c[j]
        np.minimum(d, np.einsum("ij,ij->i", diff, diff), out=d)
    return c[chosen]


def quasi_uniform(func, factor=QU_FACTOR):
    def sampler(n, rng):
        return farthest_points(func(factor * n, rng), n)
    sampler.__name__ = func.__name__ + "_qu"
    sampler.__doc__ = "Farthest-point subsample of %s (quasi-uniform)." % func.__name__
    return sampler


DV_RATIO = 10.0


def _accept_along_x(points, rng, xmin, xmax, ratio=DV_RATIO):
    """Keep each point with the probability (1 + (ratio - 1) t) / ratio, t = (x - xmin)
    / (xmax - xmin): the density grows linearly with x, ratio times from xmin to xmax."""
    t = (points[:, 0] - xmin) / (xmax - xmin)
    return points[rng.uniform(0.0, 1.0, len(points)) * ratio < 1.0 + (ratio - 1.0) * t]


def density_varying(func, xmin, xmax):
    def sampler(n, rng):
        out, count = [], 0
        while count < n:
            p = _accept_along_x(func(2 * (n - count) + 16, rng), rng, xmin, xmax)
            out.append(p)
            count += len(p)
        return np.vstack(out)[:n]
    sampler.__name__ = func.__name__ + "_dv"
    sampler.__doc__ = ("i.i.d. sample of %s whose density grows linearly along x, %g times "
                       "from x = %g to x = %g." % (func.__name__, DV_RATIO, xmin, xmax))
    return sampler


PD_FACTOR = 20            # i.i.d. candidates per point ...
PD_MAX_CANDIDATES = 10 ** 7   # ... but at most this many (10 per point at 10^6)


def _greedy_disk(c, r2, cell, kept, grid, limit):
    """One dart-throwing pass over the candidates c in their order: keep a candidate
    when no kept point is closer than sqrt(r2) (r2 a number or one per candidate),
    until `limit` points are kept. `grid` maps a cell (side `cell` >= the radius) to
    its kept points, so 27 cells are looked at per candidate."""
    lo = c.min(axis=0)
    ijk = np.floor((c - lo) / cell).astype(np.int64) + 1
    dims = ijk.max(axis=0) + 2
    keys = ijk[:, 0] + dims[0] * (ijk[:, 1] + dims[1] * ijk[:, 2])
    deltas = sorted(((dx, dy, dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)),
                    key=lambda d: abs(d[0]) + abs(d[1]) + abs(d[2]))
    offs = [int(dx + dims[0] * (dy + dims[1] * dz)) for dx, dy, dz in deltas]
    get = grid.get
    per_point = not np.isscalar(r2)
    chunk = 200000
    for s in range(0, len(c), chunk):
        pts = c[s:s + chunk].tolist()
        ks = keys[s:s + chunk].tolist()
        rs = r2[s:s + chunk].tolist() if per_point else None
        for j, (x, y, z) in enumerate(pts):
            key = ks[j]
            rr = rs[j] if per_point else r2
            for d in offs:
                cellpts = get(key + d)
                if cellpts is not None:
                    for (a, b, e) in cellpts:
                        if (a - x) * (a - x) + (b - y) * (b - y) + (e - z) * (e - z) < rr:
                            break
                    else:
                        continue
                    break
            else:
                grid.setdefault(key, []).append((x, y, z))
                kept.append(s + j)
                if len(kept) >= limit:
                    return


def poisson_disk(candidates, n, measure, dim, weight=None):
    """Exactly n of the candidates, about evenly spaced (a quasi-uniform sample, like
    farthest_points but in time linear in the candidates: about 3 us each). A greedy
    Poisson-disk (dart-throwing) pass keeps, in the candidates' (random) order, every
    candidate with no kept point closer than a radius r; r is first guessed from the
    `measure` (length, area or volume) of the `dim`-dimensional sampled set, then
    rescaled until the pass keeps 95 % to 100 % of n; a second pass with the radius
    0.85 r (0.85^2 r, ... if needed) adds the missing points, the first candidates that
    fit, so they are spread all over. The kept points are >= 0.85 r apart and every
    candidate is within r of one. `weight` (in (0, 1], one per candidate) scales the
    radius by weight^(-1/dim): a density proportional to the weight (graded samples)."""
    c = np.ascontiguousarray(candidates, dtype=float)
    scale = np.ones(len(c)) if weight is None else np.asarray(weight, dtype=float) ** (-1.0 / dim)
    effective = measure * float(np.mean(scale ** (-dim)))
    r = (0.7 * effective / n) ** (1.0 / dim)  # maximal greedy packings: ~0.7 measure / r^dim
    for _attempt in range(12):
        kept, grid = [], {}
        _greedy_disk(c, (r * scale) ** 2 if weight is not None else r * r,
                     r * scale.max(), kept, grid, n + 1)
        if 0.95 * n <= len(kept) <= n:
            break
        r *= (len(kept) / (0.98 * n)) ** (1.0 / dim)
    else:
        raise RuntimeError("poisson_disk: no radius keeps 95-100 %% of %d points" % n)
    r2 = 0.85 * r
    while len(kept) < n:
        _greedy_disk(c, (r2 * scale) ** 2 if weight is not None else r2 * r2,
                     r * scale.max(), kept, grid, n)
        r2 *= 0.85
    return c[np.asarray(kept, dtype=np.int64)]


def poisson_disk_of(func, measure, dim=2):
    def sampler(n, rng):
        m = min(PD_FACTOR * n, max(PD_MAX_CANDIDATES, n))
        return poisson_disk(func(m, rng), n, measure, dim)
    sampler.__name__ = func.__name__ + "_pd"
    sampler.__doc__ = "Poisson-disk subsample of %s (quasi-uniform)." % func.__name__
    return sampler


def graded_poisson_disk_of(func, measure, xmin, xmax, dim=2):
    def sampler(n, rng):
        c = func(min(PD_FACTOR * n, max(PD_MAX_CANDIDATES, n)), rng)
        t = (c[:, 0] - xmin) / (xmax - xmin)
        return poisson_disk(c, n, measure, dim, (1.0 + (DV_RATIO - 1.0) * t) / DV_RATIO)
    sampler.__name__ = func.__name__ + "_dvqu"
    sampler.__doc__ = ("Graded Poisson-disk sample of %s: locally even, density growing "
                       "linearly along x, %g times from x = %g to x = %g."
                       % (func.__name__, DV_RATIO, xmin, xmax))
    return sampler
