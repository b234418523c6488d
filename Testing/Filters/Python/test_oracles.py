#!/usr/bin/env python3
"""vtkFlowComplex against oracles that do not share its code.

(a) Brute-force critical points of d_P on small random clouds (n <= 40): every
    subset S of 2, 3 or 4 samples whose circumcentre in aff S has positive
    barycentric coordinates and no sample strictly closer is critical of index
    |S|-1 (docs/algorithm.md §8.2). The filter must give the same nodes
    (index, location, value, nearest set). The brute force is itself checked
    against GUDHI (the critical simplices of the Delaunay radius function) and
    the Euler relation. Also: a patch whose three edges are Gabriel is its
    Delaunay facet (same area, §8.1.6).
(b) The configurations with known answers A, B, C, D of §8.3 (counts, values,
    Hasse arcs, stable-manifold areas and geometry, persistence) and the
    degenerate inputs F (cube corners, octahedron, regular hexagon and pentagon),
    checked at persistence level only.
(c) Flow-back: random points strictly inside the index-2 stable-manifold
    triangles, pushed through our own brute-force ascending flow (the
    piecewise-linear state machine of §3 over all samples, floating point), must
    reach their own index-2 critical point before any other critical point.

Run: PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Python:Apps/Scripts /usr/bin/python3 test_oracles.py
"""

import itertools
import math
import sys

import numpy as np
import generate_clouds as gen

from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing.checks import Checker

CHK = Checker("test_oracles")

# --------------------------------------------------------------------------- brute force


def circumcentres(P, combos):
    """Circumcentres in aff S of the subsets combos (m, k+1): (centres, bary, r2, ok)."""
    p0 = P[combos[:, 0]]
    V = P[combos[:, 1:]] - p0[:, None, :]                 # (m, k, 3)
    G = 2.0 * np.einsum("mid,mjd->mij", V, V)              # (m, k, k)
    b = np.einsum("mid,mid->mi", V, V)                     # (m, k)
    det = np.linalg.det(G)
    scale = np.prod(np.einsum("mii->mi", G), axis=1)
    ok = np.abs(det) > 1e-12 * np.maximum(scale, 1e-300)   # affinely independent
    lam = np.zeros_like(b)
    if np.any(ok):
        lam[ok] = np.linalg.solve(G[ok], b[ok][..., None])[..., 0]
    c = p0 + np.einsum("mi,mid->md", lam, V)
    bary = np.concatenate((1.0 - lam.sum(axis=1)[:, None], lam), axis=1)
    r2 = np.einsum("md,md->m", c - p0, c - p0)
    return c, bary, r2, ok


def brute_force_critical(P, ambiguity=1e-9):
    """{k: [(S, centre, value)]} for k = 0..3 and a list of near-ties (subsets whose
    status depends on less than `ambiguity` relative: the test avoids such clouds)."""
    n = len(P)
    crit = {0: [((i,), P[i].copy(), 0.0) for i in range(n)], 1: [], 2: [], 3: []}
    ambiguous = []
    for k in (1, 2, 3):
        combos = np.array(list(itertools.combinations(range(n), k + 1)), dtype=np.int64)
        if len(combos) == 0:
            continue
        c, bary, r2, ok = circumcentres(P, combos)
        bmin = bary.min(axis=1)
        near_b = ok & (np.abs(bmin) <= ambiguity)
        cand = np.nonzero(ok & (bmin > ambiguity))[0]
        # distances from all samples to the candidate centres
        for start in range(0, len(cand), 20000):
            sel = cand[start:start + 20000]
            d2 = ((P[None, :, :] - c[sel, None, :]) ** 2).sum(axis=2)   # (m, n)
            rel = d2 / r2[sel, None] - 1.0
            member = np.zeros_like(d2, dtype=bool)
            np.put_along_axis(member, combos[sel], True, axis=1)
            rel[member] = np.inf
            rmin = rel.min(axis=1)
            for j, i in enumerate(sel):
                if abs(rmin[j]) <= ambiguity:
                    ambiguous.append((tuple(combos[i]), "sample on the diametral sphere", rmin[j]))
                elif rmin[j] > 0:
                    crit[k].append((tuple(int(x) for x in combos[i]), c[i].copy(),
                                    math.sqrt(r2[i])))
        for i in np.nonzero(near_b)[0]:
            ambiguous.append((tuple(combos[i]), "centre on the boundary of S", bmin[i]))
    return crit, ambiguous


def gudhi_critical_simplices(P):
    """Critical simplices of the Delaunay radius function from GUDHI's exact alpha
    filtration: simplices alone in their level (singleton intervals)."""
    import gudhi
    st = gudhi.AlphaComplex(points=P, precision="exact").create_simplex_tree()
    groups = {}
    for s, f in st.get_filtration():
        groups.setdefault(f, []).append(tuple(sorted(s)))
    out = {0: set(), 1: set(), 2: set(), 3: set()}
    values = {}
    for f, simplices in groups.items():
        if len(simplices) == 1:
            s = simplices[0]
            out[len(s) - 1].add(s)
            values[s] = math.sqrt(max(f, 0.0))
    for i in range(len(P)):
        out[0].add((i,))  # all vertices have value 0: one level, all critical
        values[(i,)] = 0.0
    return out, values


# --------------------------------------------------------------------------- clouds


def random_cloud(kind, n, seed):
    rng = np.random.default_rng(seed)
    if kind == "cube":
        return rng.uniform(0.0, 1.0, (n, 3))
    if kind == "sphere":
        return gen.sphere(n, rng) * (1.0 + 0.05 * rng.uniform(0.0, 1.0, (n, 1)))
    if kind == "torus":
        p = gen.torus(n, rng, 1.0, 0.4)
        p[:, 2] += 0.01 * rng.uniform(0.0, 1.0, n)
        return p
    raise ValueError(kind)


def generic_clouds():
    """Small random clouds for which the brute force has no near-tie."""
    wanted = [("cube", 12), ("cube", 25), ("cube", 40), ("sphere", 30), ("sphere", 40),
              ("torus", 35), ("torus", 40), ("cube", 30), ("sphere", 20), ("torus", 25)]
    out = []
    for i, (kind, n) in enumerate(wanted):
        for seed in range(1000 + 17 * i, 1000 + 17 * i + 10):
            P = random_cloud(kind, n, seed)
            crit, amb = brute_force_critical(P)
            if not amb:
                out.append(("%s n=%d seed=%d" % (kind, n, seed), P, crit))
                break
            print("  (skipping %s n=%d seed=%d: %d near-ties in the brute force)" % (
                kind, n, seed, len(amb)))
    return out


# --------------------------------------------------------------------------- geometry


def tri_area(t):
    t = np.asarray(t, dtype=float)
    return 0.5 * float(np.linalg.norm(np.cross(t[1] - t[0], t[2] - t[0])))


def nearest_set(P, x, value, rel=1e-9):
    d = np.linalg.norm(P - x, axis=1)
    return tuple(int(i) for i in np.nonzero(np.abs(d - value) <= rel * max(value, 1e-300)
                                            + 1e-15)[0]) if value > 0 else (int(np.argmin(d)),)


def node_simplices(res, P, rel=1e-9):
    """{node id: sorted sample ids N(x)} for the finite nodes, from their location
    and value (independent of any simplex array the filter may expose)."""
    out = {}
    for r in np.nonzero(res.finite)[0]:
        out[int(res.node_id[r])] = nearest_set(P, res.loc[r], float(res.value[r]), rel)
    return out


def closest_point_of_hull(Q, x):
    """Closest point of conv(Q) to x (|Q| <= 4), and the minimal support (indices
    into Q) of that point. Brute force over the faces of the simplex."""
    best = None
    m = len(Q)
    for size in range(1, m + 1):
        for T in itertools.combinations(range(m), size):
            p0 = Q[T[0]]
            if size == 1:
                y, bary = p0, np.array([1.0])
            else:
                V = Q[list(T[1:])] - p0
                G = V @ V.T
                try:
                    lam = np.linalg.solve(G, V @ (x - p0))
                except np.linalg.LinAlgError:
                    continue
                bary = np.concatenate(([1.0 - lam.sum()], lam))
                y = p0 + lam @ V
            if bary.min() < -1e-12:
                continue
            d = float(np.linalg.norm(x - y))
            if best is None or d < best[0] - 1e-13 * (1.0 + d):
                best = (d, y, T)
    return best[1], best[2]


def segment_point_distance(a, b, p):
    ab = b - a
    L2 = float(ab @ ab)
    t = 0.0 if L2 == 0 else min(1.0, max(0.0, float((p - a) @ ab) / L2))
    return float(np.linalg.norm(a + t * ab - p))


def ascend(P, x, targets, tol, max_steps=10000):
    """Our own ascending flow of d_P from x (§3, brute force over all samples).

    targets: (k, 3) critical points to watch. Returns (event, info): event is
    ('hit', j) for the first target j the orbit passes within tol of, ('max', x)
    or ('crit', x) if it stops at a critical point away from every target,
    ('inf', x) if it escapes; info carries the polyline."""
    d = np.linalg.norm(P - x, axis=1)
    N = [int(np.argmin(d))]
    path = [x.copy()]
    for _ in range(max_steps):
        driver, T = closest_point_of_hull(P[N], x)
        N = [N[i] for i in T]
        w = x - driver
        if float(np.linalg.norm(w)) <= 1e-13 * (1.0 + float(np.linalg.norm(x))):
            # stopped at a critical point (should have been caught as a target)
            dist = np.linalg.norm(targets - x, axis=1)
            j = int(np.argmin(dist)) if len(targets) else -1
            if j >= 0 and dist[j] <= tol:
                return ("hit", j), path
            return ("max" if len(N) == 4 else "crit", x), path
        u = P[N[0]]
        slope = 2.0 * ((P - u) @ w)
        f0 = ((x - P) ** 2).sum(axis=1) - float((x - u) @ (x - u))
        cand = slope > 1e-14 * float(np.linalg.norm(w)) * (1.0 + float(np.abs(P).max()))
        cand[N] = False
        if not np.any(cand):
            end = x + w * (10.0 * (1.0 + float(np.abs(P).max())) / float(np.linalg.norm(w)))
            hit = first_target(x, end, targets, tol)
            path.append(end)
            return (("hit", hit) if hit is not None else ("inf", end)), path
        t = np.full(len(P), np.inf)
        t[cand] = np.maximum(f0[cand], 0.0) / slope[cand]
        s = int(np.argmin(t))
        y = x + t[s] * w
        hit = first_target(x, y, targets, tol)
        path.append(y)
        if hit is not None:
            return ("hit", hit), path
        x = y
        N = sorted(set(N) | {s})
    raise RuntimeError("ascending flow did not terminate in %d steps" % max_steps)


def first_target(a, b, targets, tol):
    """The target nearest to a among those within tol of segment [a, b], or None."""
    best = None
    for j in range(len(targets)):
        if segment_point_distance(a, b, targets[j]) <= tol:
            along = float(np.linalg.norm(targets[j] - a))
            if best is None or along < best[0]:
                best = (along, j)
    return None if best is None else best[1]


# --------------------------------------------------------------------------- (a)


def check_oracle_self_consistency(clouds):
    """The brute force agrees with GUDHI and with the Euler relation."""
    for label, P, crit in clouds:
        counts = [len(crit[k]) for k in range(4)]
        CHK.check(counts[0] - counts[1] + counts[2] - counts[3] == 1,
                  "brute force on %s: Euler characteristic %d != 1 (counts %s)" % (
                      label, counts[0] - counts[1] + counts[2] - counts[3], counts))
        g, gval = gudhi_critical_simplices(P)
        for k in range(4):
            mine = {S for S, _, _ in crit[k]}
            CHK.check(mine == g[k], "brute force vs GUDHI critical simplices of index %d on %s" % (
                k, label), "only brute force: %s\nonly GUDHI: %s" % (
                    sorted(mine - g[k])[:10], sorted(g[k] - mine)[:10]))
            for S, _, v in crit[k]:
                if S in gval and abs(gval[S] - v) > 1e-12 * (1 + v):
                    CHK.check(False, "brute force value %r vs GUDHI %r for %s on %s" % (
                        v, gval[S], S, label))


def check_critical_points(label, P, crit, res):
    diam = fio.diameter(P)
    tol = 1e-9 * diam
    CHK.check(res.counts() == tuple(len(crit[k]) for k in range(4)),
              "%s: node counts by index %s, brute force %s" % (
                  label, res.counts(), tuple(len(crit[k]) for k in range(4))))
    simp = node_simplices(res, P)
    for k in range(4):
        rows = res.nodes_of_index(k)
        by_simplex = {}
        for r in rows:
            by_simplex.setdefault(simp[int(res.node_id[r])], []).append(r)
        expected = {S: (c, v) for S, c, v in crit[k]}
        dup = {S: rs for S, rs in by_simplex.items() if len(rs) > 1}
        CHK.check(not dup, "%s: index-%d nodes with the same nearest set: %s" % (label, k, dup))
        missing = sorted(set(expected) - set(by_simplex))
        extra = sorted(set(by_simplex) - set(expected))
        CHK.check(not missing and not extra,
                  "%s: index-%d critical simplices differ from the brute force" % (label, k),
                  "missing (brute force only): %s\nextra (filter only, as nearest sets of "
                  "node locations): %s" % (
                      [(S, expected[S][1]) for S in missing[:8]],
                      [(S, [float(res.value[r]) for r in by_simplex[S]],
                        [res.loc[r].tolist() for r in by_simplex[S]]) for S in extra[:8]]))
        worst_loc = worst_val = 0.0
        worst = None
        for S, (c, v) in expected.items():
            for r in by_simplex.get(S, []):
                dl = float(np.linalg.norm(res.loc[r] - c))
                dv = abs(float(res.value[r]) - v)
                if dl > worst_loc or dv > worst_val:
                    worst = (S, res.loc[r].tolist(), c.tolist(), float(res.value[r]), v)
                worst_loc, worst_val = max(worst_loc, dl), max(worst_val, dv)
        CHK.check(worst_loc <= tol and worst_val <= 1e-9 * max(diam, 1.0),
                  "%s: index-%d locations/values off by %.3g / %.3g (tolerance %.3g)" % (
                      label, k, worst_loc, worst_val, tol),
                  "worst: simplex %s filter loc %s brute %s, value %r vs %r" % worst
                  if worst else None)
        if res.simplex is not None:
            exposed = {tuple(sorted(int(x) for x in res.simplex[r] if x >= 0)) for r in rows}
            CHK.check(exposed == set(expected),
                      "%s: exposed Simplex array of index-%d nodes differs from the brute force"
                      % (label, k))


ALL_GABRIEL_FACETS = []  # how many each cloud had: the check must not be vacuous


def check_gabriel_facet_patches(label, P, crit, res):
    """§8.1.6: S(c) of a facet whose three edges are Gabriel is the facet itself."""
    gabriel = {S for S, _, _ in crit[1]}
    simp = node_simplices(res, P)
    tris = res.triangles_by_node()
    bad = []
    n = 0
    for r in res.nodes_of_index(2):
        nid = int(res.node_id[r])
        S = simp[nid]
        if len(S) != 3 or not all(tuple(sorted(e)) in gabriel for e in itertools.combinations(S, 2)):
            continue
        n += 1
        area = sum(tri_area(t) for t in tris.get(nid, []))
        facet = tri_area(P[list(S)])
        if abs(area - facet) > 1e-9 * max(facet, 1e-12):
            bad.append((S, area, facet))
    ALL_GABRIEL_FACETS.append(n)
    CHK.check(not bad, "%s: %d of %d all-Gabriel facets have a patch whose area differs from "
              "the facet's" % (label, len(bad), n), "(simplex, patch area, facet area): %s" % bad[:8])


# --------------------------------------------------------------------------- (c)


def check_flow_back(label, P, crit, res, rng, samples_per_node=4):
    diam = fio.diameter(P)
    tol = 1e-6 * diam
    targets = np.array([c for k in (1, 2, 3) for _, c, _ in crit[k]]).reshape(-1, 3)
    tris = res.triangles_by_node()
    failures = []
    n_ok = 0
    for r in res.nodes_of_index(2):
        nid = int(res.node_id[r])
        own = int(np.argmin(np.linalg.norm(targets - res.loc[r], axis=1)))
        T = tris.get(nid)
        if T is None or len(T) == 0:
            failures.append((nid, "no stable-manifold triangles"))
            continue
        areas = np.array([tri_area(t) for t in T])
        if areas.sum() <= 0:
            failures.append((nid, "zero-area stable manifold"))
            continue
        picks = rng.choice(len(T), size=samples_per_node, p=areas / areas.sum())
        for ti in picks:
            while True:  # barycentric coordinates strictly inside (>= 0.02 each)
                bc = rng.dirichlet((1.0, 1.0, 1.0))
                if bc.min() >= 0.02:
                    break
            x = bc @ T[ti]
            try:
                (event, what), path = ascend(P, x, targets, tol)
            except RuntimeError as exc:
                failures.append((nid, "start %s: %s" % (x.tolist(), exc)))
                continue
            if event == "hit" and what == own:
                n_ok += 1
            else:
                got = ("critical point %s" % targets[what].tolist() if event == "hit"
                       else "%s at %s" % (event, np.asarray(what).tolist()))
                failures.append((nid, "start %s (triangle %s) reached %s before its own "
                                 "critical point %s; orbit %s" % (
                                     x.tolist(), T[ti].tolist(), got, res.loc[r].tolist(),
                                     [p.tolist() for p in path[:12]])))
    CHK.check(not failures, "%s: flow-back failed for %d samples (%d ok)" % (
        label, len(failures), n_ok), "\n".join("node %d: %s" % f for f in failures[:5]))
    return n_ok


# --------------------------------------------------------------------------- (b) configs


def node_near(res, k, xyz, tol=1e-6):
    rows = res.nodes_of_index(k)
    if len(rows) == 0:
        return None
    d = np.linalg.norm(res.loc[rows] - np.asarray(xyz, dtype=float), axis=1)
    j = int(np.argmin(d))
    return int(res.node_id[rows[j]]) if d[j] <= tol else None


def arc_multiplicity(res, lower, upper):
    m = (res.lower == lower) & (res.upper == upper)
    return int(res.mult[m].sum())


def sorted_values(res, k):
    return sorted(float(v) for v in res.value[res.nodes_of_index(k)])


def close_lists(a, b, tol):
    return len(a) == len(b) and all(abs(x - y) <= tol for x, y in zip(sorted(a), sorted(b)))


def check_persistence_against(label, res, expected, tol=1e-6, min_pers=1e-4):
    got = fio.significant(fio.flow_complex_diagram(res), min_pers)
    ok, msg = fio.compare_diagrams(got, expected, tol, ("filter", "reference §8.3"))
    CHK.check(ok, "%s: persistence (pairs longer than %g) differs from the reference" % (
        label, min_pers), msg + "\nfilter diagram: %s" % sorted(got))


def check_gabriel_edges_of_config(label, res, P, expected_edges):
    """Index-1 nodes <-> expected Gabriel edges (pairs of sample ids)."""
    got = {}
    for r in res.nodes_of_index(1):
        a, b = sorted(nearest_set(P, res.loc[r], float(res.value[r])))[:2]
        got[(a, b)] = int(res.node_id[r])
    CHK.check(set(got) == set(expected_edges), "%s: Gabriel edges %s, expected %s" % (
        label, sorted(got), sorted(expected_edges)))
    return got


def config_A():
    label = "A regular tetrahedron"
    V = np.array([(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)], dtype=float)
    res = fio.run(V)
    print("  %s: %s" % (label, res.summary()))
    CHK.check(res.counts() == (4, 6, 4, 1), "%s: counts %s, expected 4/6/4/1" % (label, res.counts()))
    s2, s83, s3 = math.sqrt(2), math.sqrt(8.0 / 3.0), math.sqrt(3)
    edges = {}
    for a, b in itertools.combinations(range(4), 2):
        nid = node_near(res, 1, (V[a] + V[b]) / 2, 1e-9)
        CHK.check(nid is not None, "%s: no index-1 node at the midpoint of %d%d" % (label, a, b))
        if nid is not None:
            edges[(a, b)] = nid
            CHK.check(abs(res.value[res.row[nid]] - s2) <= 1e-12,
                      "%s: edge value %r != sqrt(2)" % (label, res.value[res.row[nid]]))
    mx = node_near(res, 3, (0, 0, 0), 1e-9)
    CHK.check(mx is not None and abs(res.value[res.row[mx]] - s3) <= 1e-12,
              "%s: no maximum at the origin with value sqrt(3)" % label)
    inf = res.infinity_ids()
    CHK.check(len(inf) == 1, "%s: %d maxima at infinity" % (label, len(inf)))
    tris = res.triangles_by_node()
    for v in range(4):
        face = [i for i in range(4) if i != v]
        nid = node_near(res, 2, -V[v] / 3.0, 1e-9)
        CHK.check(nid is not None, "%s: no index-2 node at the centroid of face %s" % (label, face))
        if nid is None:
            continue
        CHK.check(abs(res.value[res.row[nid]] - s83) <= 1e-12,
                  "%s: face value %r != sqrt(8/3)" % (label, res.value[res.row[nid]]))
        for a, b in itertools.combinations(face, 2):
            if (a, b) in edges:
                m = arc_multiplicity(res, edges[(a, b)], nid)
                CHK.check(m == 1, "%s: arc edge %d%d -> face %s has multiplicity %d, expected 1" % (
                    label, a, b, face, m))
        lows = {lo for lo, _ in res.lower_neighbours().get(nid, [])}
        CHK.check(lows == {edges.get(e) for e in itertools.combinations(face, 2)},
                  "%s: face %s has lower neighbours %s" % (label, face, lows))
        if mx is not None:
            CHK.check(arc_multiplicity(res, nid, mx) == 1, "%s: face %s -> max multiplicity %d" % (
                label, face, arc_multiplicity(res, nid, mx)))
        if inf:
            CHK.check(arc_multiplicity(res, nid, inf[0]) == 1,
                      "%s: face %s -> infinity multiplicity %d" % (
                          label, face, arc_multiplicity(res, nid, inf[0])))
        area = sum(tri_area(t) for t in tris.get(nid, []))
        CHK.check(abs(area - 2 * math.sqrt(3)) <= 1e-9,
                  "%s: S(face %s) area %r, expected 2*sqrt(3) = 3.464102" % (label, face, area))
    check_persistence_against(label, res, [(0, 0, 1.414214)] * 3 + [(0, 0, math.inf)] +
                              [(1, 1.414214, 1.632993)] * 3 + [(2, 1.632993, 1.732051)])


def config_B():
    label = "B corner tetrahedron"
    P = np.array([(-0.1, -0.1, -0.1), (1, 0, 0), (0, 1, 0), (0, 0, 1)], dtype=float)
    res = fio.run(P)
    print("  %s: %s" % (label, res.summary()))
    CHK.check(res.counts() == (4, 6, 3, 0), "%s: counts %s, expected 4/6/3/0" % (label, res.counts()))
    CHK.check(close_lists(sorted_values(res, 1), [0.554527] * 3 + [0.707107] * 3, 1e-6),
              "%s: index-1 values %s" % (label, sorted_values(res, 1)))
    CHK.check(close_lists(sorted_values(res, 2), [0.719803] * 3, 1e-6),
              "%s: index-2 values %s" % (label, sorted_values(res, 2)))
    simp = node_simplices(res, P)
    faces = sorted(simp[int(res.node_id[r])] for r in res.nodes_of_index(2))
    CHK.check(faces == [(0, 1, 2), (0, 1, 3), (0, 2, 3)],
              "%s: index-2 nodes on faces %s; the big face (1,2,3) must not be one" % (label, faces))
    inf = res.infinity_ids()
    for r in res.nodes_of_index(2):
        nid = int(res.node_id[r])
        ups = res.upper_neighbours().get(nid, [])
        CHK.check(len(inf) == 1 and sum(m for u, m in ups if u == inf[0]) == 2 and
                  all(u == inf[0] for u, m in ups),
                  "%s: both unstable lines of %s must go to infinity; arcs up: %s" % (
                      label, simp[nid], ups))
    check_persistence_against(label, res, [(0, 0, 0.554527)] * 3 + [(0, 0, math.inf)] +
                              [(1, 0.707107, 0.719803)] * 3)


def config_C():
    label = "C acute triangle + apex"
    P = np.array([(0, 0, 0), (1, 0, 0), (0.4, 0.8, 0), (0.5, 0.25, 3)], dtype=float)
    res = fio.run(P)
    print("  %s: %s" % (label, res.summary()))
    CHK.check(res.counts() == (4, 6, 4, 1), "%s: counts %s, expected 4/6/4/1" % (label, res.counts()))
    CHK.check(close_lists(sorted_values(res, 1), [0.447214, 0.5, 0.5] + [1.525819] * 3, 1e-6),
              "%s: index-1 values %s" % (label, sorted_values(res, 1)))
    CHK.check(close_lists(sorted_values(res, 2), [0.559017, 1.542473, 1.546722, 1.546722], 1e-6),
              "%s: index-2 values %s" % (label, sorted_values(res, 2)))
    CHK.check(close_lists(sorted_values(res, 3), [1.552083], 1e-6),
              "%s: index-3 values %s" % (label, sorted_values(res, 3)))
    mx = node_near(res, 3, (0.5, 0.25, 1.447917), 1e-5)
    CHK.check(mx is not None, "%s: no maximum at (0.5, 0.25, 1.447917)" % label)
    check_persistence_against(label, res, [(0, 0, 0.447214), (0, 0, 0.5), (0, 0, 1.525819),
                                           (0, 0, math.inf), (1, 0.5, 0.559017),
                                           (1, 1.525819, 1.542473), (1, 1.525819, 1.546722),
                                           (2, 1.546722, 1.552083)])


def point_in_triangle(p, t, tol):
    """p within tol of triangle t (3,3)?"""
    a, b, c = t
    n = np.cross(b - a, c - a)
    nn = float(np.linalg.norm(n))
    if nn == 0:
        return False
    if abs(float((p - a) @ n)) / nn > tol:
        return False
    # barycentric in the plane
    v0, v1, v2 = b - a, c - a, p - a
    d00, d01, d11 = v0 @ v0, v0 @ v1, v1 @ v1
    d20, d21 = v2 @ v0, v2 @ v1
    den = d00 * d11 - d01 * d01
    v = (d11 * d20 - d01 * d21) / den
    w = (d00 * d21 - d01 * d20) / den
    u = 1 - v - w
    scale = math.sqrt(max(d00, d11))
    return min(u, v, w) >= -tol / scale


def config_D():
    label = "D recursive stable manifold"
    P = np.array([(-0.9, -0.8, -0.2), (-0.8, 0.8, -0.9), (0.1, -0.3, 0.7), (-0.7, -0.3, -0.3),
                  (-0.5, -1.0, -0.1)], dtype=float)
    res = fio.run(P)
    print("  %s: %s" % (label, res.summary()))
    CHK.check(res.counts() == (5, 5, 1, 0), "%s: counts %s, expected 5/5/1/0" % (label, res.counts()))
    expected_edges = {(0, 3): 0.273861, (0, 4): 0.229129, (1, 3): 0.628490, (2, 3): 0.640312,
                      (2, 4): 0.610328}
    edges = check_gabriel_edges_of_config(label, res, P, expected_edges)
    for e, v in expected_edges.items():
        if e in edges:
            got = float(res.value[res.row[edges[e]]])
            CHK.check(abs(got - v) <= 1e-6, "%s: value of edge %s is %r, expected %r" % (
                label, e, got, v))
    c = np.array([-0.294784, -0.449702, 0.195827])
    nid = node_near(res, 2, c, 1e-5)
    CHK.check(nid is not None, "%s: no index-2 node near %s" % (label, c.tolist()))
    if nid is None:
        return
    r = res.row[nid]
    CHK.check(abs(res.value[r] - 0.657613) <= 1e-6, "%s: index-2 value %r, expected 0.657613" % (
        label, res.value[r]))
    CHK.check(nearest_set(P, res.loc[r], float(res.value[r])) == (2, 3, 4),
              "%s: index-2 node is not the facet (2,3,4)" % label)
    # 1-2 incidences
    lows = dict(res.lower_neighbours().get(nid, []))
    inc = {e: lows.get(edges[e], 0) for e in edges}
    CHK.check(all(inc.get(e) == 1 for e in [(0, 3), (0, 4), (2, 3), (2, 4)]) and inc.get((1, 3)) == 0
              and set(lows) <= {edges[e] for e in [(0, 3), (0, 4), (2, 3), (2, 4)]},
              "%s: 1-2 incidences %s; expected (0,3),(0,4),(2,3),(2,4) with multiplicity 1, "
              "not (1,3), not (3,4)" % (label, inc))
    # geometry of S(c)
    T = res.triangles_by_node().get(nid, np.zeros((0, 3, 3)))
    area = sum(tri_area(t) for t in T)
    CHK.check(abs(area - 0.567435) <= 1e-6, "%s: S(c) area %r, expected 0.567435" % (label, area))
    y = np.array([-239.0 / 425.0, -1063.0 / 1700.0, -257.0 / 1700.0])
    verts = T.reshape(-1, 3)
    dy = float(np.min(np.linalg.norm(verts - y, axis=1))) if len(verts) else math.inf
    CHK.check(dy <= 1e-12, "%s: the exit point y = (-239/425, -1063/1700, -257/1700) is not a "
              "vertex of S(c) (closest vertex at %.3g)" % (label, dy))
    cc = res.loc[r]
    p = P
    expected = [np.array(t) for t in ((p[2], cc, p[3]), (p[2], cc, p[4]), (cc, y, p[3]),
                                      (cc, y, p[4]), (p[0], y, p[3]), (p[0], y, p[4]))]
    exp_area = [tri_area(t) for t in expected]
    covered = [0.0] * 6
    outside = []
    for t in T:
        homes = [i for i, e in enumerate(expected) if all(point_in_triangle(q, e, 1e-9) for q in t)]
        if homes:
            covered[homes[0]] += tri_area(t)
        else:
            outside.append(t.tolist())
    CHK.check(not outside, "%s: %d triangles of S(c) lie in none of the six expected triangles "
              "(P2,c,P3),(P2,c,P4),(c,y,P3),(c,y,P4),(P0,y,P3),(P0,y,P4)" % (label, len(outside)),
              outside[:4])
    CHK.check(all(abs(a - b) <= 1e-9 for a, b in zip(covered, exp_area)),
              "%s: area covered in each expected triangle %s, expected %s" % (
                  label, covered, exp_area))
    print("  %s: S(c) has %d triangles (GJ form: 6), area %.6f" % (label, len(T), area))
    check_persistence_against(label, res, [(0, 0, 0.229129), (0, 0, 0.273861), (0, 0, 0.610328),
                                           (0, 0, 0.628490), (0, 0, math.inf),
                                           (1, 0.640312, 0.657613)])
    check_flow_back(label, P, brute_force_critical(P)[0], res, np.random.default_rng(4), 20)


def check_degenerate(label, P, expected, allow_reject=False):
    """Degenerate input: the filter perturbs it; check Euler, the report and persistence."""
    mb, messages = fio.run_filter(P)
    if "CriticalPoints" not in fio.block_names(mb) or \
            fio.get_block(mb, "CriticalPoints").GetNumberOfPoints() == 0:
        # only acceptable for exactly coplanar input, with an error that says so
        CHK.check(allow_reject, "%s: the filter produced no nodes (errors %s)" % (
            label, messages.errors))
        CHK.check(any("coplanar" in e for e in messages.errors),
                  "%s: input rejected without an error naming the problem (errors %s)" % (
                      label, messages.errors))
        print("  NOTE %s: exactly coplanar input rejected by the filter with the error %r" % (
            label, messages.errors[0].strip().splitlines()[-1] if messages.errors else None))
        return
    res = fio.FlowComplexResult(mb, messages)
    print("  %s: %s" % (label, res.summary()))
    CHK.check(res.euler() == 1, "%s: Euler characteristic %d != 1 (counts %s)" % (
        label, res.euler(), res.counts()))
    attempts = res.report_value("PerturbationAttempts", "Attempts")
    CHK.check(attempts is not None and attempts > 1,
              "%s: degenerate input but the report does not say it was perturbed "
              "(PerturbationAttempts = %r; report %s)" % (label, attempts, res.report))
    mag = float(res.report_value("PerturbationMagnitude") or 0.0)
    check_persistence_against(label, res, expected, tol=1e-6 + 20.0 * mag)


def config_F():
    cube = np.array([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)
    check_degenerate("F cube corners", cube, [(0, 0, 0.5)] * 7 + [(0, 0, math.inf)] +
                     [(1, 0.5, 0.707107)] * 5 + [(2, 0.707107, 0.866025)])
    octa = np.array([(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)], dtype=float)
    check_degenerate("F octahedron", octa, [(0, 0, 0.707107)] * 5 + [(0, 0, math.inf)] +
                     [(1, 0.707107, 0.816497)] * 7 + [(2, 0.816497, 1.0)])
    rng = np.random.default_rng(77)
    for n in (6, 5):
        poly = np.array([(math.cos(2 * math.pi * k / n), math.sin(2 * math.pi * k / n), 0.0)
                         for k in range(n)])
        edge = math.sin(math.pi / n)
        expected = [(0, 0, edge)] * (n - 1) + [(0, 0, math.inf), (1, edge, 1.0)]
        name = "F regular %s" % ("hexagon" if n == 6 else "pentagon")
        # exactly coplanar: the filter may reject it (DESIGN §1) or perturb it
        check_degenerate(name + " (exactly planar)", poly, expected, allow_reject=True)
        # cospherical/cocircular but 3D: jittered by us by 1e-6
        jit = poly + rng.uniform(-1e-6, 1e-6, poly.shape)
        res = fio.run(jit)
        print("  %s jittered 1e-6: %s" % (name, res.summary()))
        CHK.check(res.euler() == 1, "%s jittered: Euler %d" % (name, res.euler()))
        check_persistence_against(name + " jittered 1e-6", res, expected, tol=1e-5)


# --------------------------------------------------------------------------- main


def main():
    CHK.section("oracle: brute-force critical points on small random clouds")
    clouds = generic_clouds()
    CHK.check(len(clouds) >= 8, "only %d usable random clouds" % len(clouds))
    CHK.run("oracle self-check: brute force vs GUDHI and Euler", check_oracle_self_consistency,
            clouds)
    rng = np.random.default_rng(2009)
    total_flow = 0
    for label, P, crit in clouds:
        try:
            res = fio.run(P)
        except Exception:
            import traceback
            CHK.section("(a) %s" % label)
            CHK.check(False, "the filter failed on %s" % label, traceback.format_exc())
            continue
        CHK.run("(a) critical points %s" % label, check_critical_points, label, P, crit, res)
        CHK.run("(a) all-Gabriel facets %s" % label, check_gabriel_facet_patches, label, P, crit, res)
        CHK.section("(c) flow-back %s" % label)
        try:
            total_flow += check_flow_back(label, P, crit, res, rng)
        except Exception:
            import traceback
            CHK.check(False, "exception in the flow-back of %s" % label, traceback.format_exc())
    print("  flow-back: %d samples reached their own critical point" % total_flow)
    CHK.section("(a) all-Gabriel facets were met")
    CHK.check(sum(ALL_GABRIEL_FACETS) > 0, "no cloud had a facet whose three edges are Gabriel: "
              "the all-Gabriel-facet check tested nothing")
    CHK.check(total_flow > 0, "no flow-back sample reached a critical point: the check tested nothing")
    CHK.run("(b) configuration A", config_A)
    CHK.run("(b) configuration B", config_B)
    CHK.run("(b) configuration C", config_C)
    CHK.run("(b) configuration D", config_D)
    CHK.run("(b) degenerate configurations F", config_F)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
