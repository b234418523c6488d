#!/usr/bin/env python3
"""Invariants of the flow complex that must hold on every input
(docs/algorithm.md §8.1, docs/design.md §3), on random clouds (uniform cube,
sphere, torus; 20..2000 points; several seeds) and on structured, degenerate
ones (jittered and exact grids, cospherical points, duplicates, right angles):

- Euler: n0 - n1 + n2 - n3 = 1 over the finite nodes;
- arcs go from index i to i+1, multiplicities >= 1, values strictly increase;
- d o d = 0 mod 2 (Z/2 boundary matrices from the arcs, multiplicity mod 2, arcs
  to the maximum at infinity excluded) and rank d3 = n3 (maxima independent);
- every index-1 node has exactly two 0->1 arcs (its Gabriel edge, located at the
  edge midpoint), every index-2 node exactly two unstable arrivals (2->3
  multiplicities, infinity included, sum to 2), every finite maximum has an
  index-2 predecessor;
- every node's value is d_P at its location; index-0 nodes are the distinct samples;
- the Euclidean MST (computed here with scipy on the complete graph) is made of
  Gabriel edges (index-1 nodes); under degeneracy: the Gabriel graph is connected
  and contains a spanning tree as light as the EMST;
- determinism: two runs give identical outputs (timings excepted);
- random input is not perturbed; degenerate input is, and the report says so;
  duplicates are merged and reported.

Run: PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Python:Apps/Scripts /usr/bin/python3 test_invariants.py
"""

import sys

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.csgraph import connected_components, minimum_spanning_tree
from scipy.spatial import cKDTree
from scipy.spatial.distance import cdist
import generate_clouds as gen

from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing.clouds import random_cloud
from flowrecon_testing.checks import Checker

CHK = Checker("test_invariants")
CUBE = (-1.0, 1.0)  # the random cubes' side


# --------------------------------------------------------------------------- inputs


def random_inputs():
    out = []
    for kind in ("cube", "sphere", "torus"):
        for n, seeds in ((20, (1, 2, 3)), (50, (4, 5)), (200, (6, 7)), (600, (8,)), (2000, (9,))):
            for s in seeds:
                out.append(("%s n=%d seed=%d" % (kind, n, s), random_cloud(kind, n, 100 * s + n, CUBE)))
    # nearly cospherical (every sample on the unit sphere up to rounding): critical
    # values near the centre tie in double precision, so arcs there may only be
    # non-decreasing, and the filter may or may not call the input degenerate
    out.append(("unit sphere n=500 (near-cospherical)", random_cloud("unit sphere", 500, 10)))
    return out


def lattice(k, spacing=(1.0, 1.0, 1.0)):
    g = [(x * spacing[0], y * spacing[1], z * spacing[2])
         for x in range(k) for y in range(k) for z in range(k)]
    return np.array(g, dtype=float)


def structured_inputs():
    """(label, points, expectation) with expectation in {'generic', 'perturbed',
    'duplicates'}."""
    out = []
    out.append(("jittered 5x5x5 grid", gen.make("grid5_jittered"), "generic"))
    rng = np.random.default_rng(31)
    out.append(("jittered 4x4x4 grid (1e-6)", lattice(4) + rng.uniform(-1e-6, 1e-6, (64, 3)),
                "generic"))
    out.append(("exact 4x4x4 grid", gen.make("grid4_exact"), "perturbed"))
    out.append(("exact 5x5x5 grid", lattice(5), "perturbed"))
    out.append(("exact 3x3x3 grid, spacing (1,2,3)", lattice(3, (1.0, 2.0, 3.0)), "perturbed"))
    cube = np.array([(x, y, z) for x in (-1, 1) for y in (-1, 1) for z in (-1, 1)], dtype=float)
    octa = np.array([(1.5, 0, 0), (-1.5, 0, 0), (0, 1.5, 0), (0, -1.5, 0), (0, 0, 1.5),
                     (0, 0, -1.5)])
    out.append(("cube corners + octahedron", np.vstack((cube, octa)), "perturbed"))
    # 30 points exactly on the sphere of radius 3: permutations of (+-3,0,0), (+-1,+-2,+-2)
    sph = set()
    for a, b, c in ((3, 0, 0), (1, 2, 2)):
        for perm in ((a, b, c), (b, c, a), (c, a, b), (a, c, b), (b, a, c), (c, b, a)):
            for sx in (-1, 1):
                for sy in (-1, 1):
                    for sz in (-1, 1):
                        sph.add((sx * perm[0], sy * perm[1], sz * perm[2]))
    out.append(("30 cospherical integer points", np.array(sorted(sph), dtype=float), "perturbed"))
    out.append(("right-angled corner tetrahedron",
                np.array([(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], dtype=float), "perturbed"))
    out.append(("box 2x3x4 corners",
                np.array([(x, y, z) for x in (0, 2) for y in (0, 3) for z in (0, 4)], dtype=float),
                "perturbed"))
    pts = lattice(6)
    sel = np.random.default_rng(5).choice(len(pts), 60, replace=False)
    out.append(("60 random points of a 6x6x6 lattice", pts[np.sort(sel)], "perturbed"))
    base = random_cloud("cube", 100, 77, CUBE)
    rep = np.random.default_rng(78).choice(100, 20, replace=False)
    out.append(("100 random points + 20 exact duplicates", np.vstack((base, base[rep])),
                "duplicates"))
    out.append(("sphere n=200 given twice", np.vstack((random_cloud("sphere", 200, 79),) * 2),
                "duplicates"))
    return out


# --------------------------------------------------------------------------- checks


def distinct_points(P):
    _, first = np.unique(P, axis=0, return_index=True)
    return np.sort(first)


def sample_of_node(res, P, tree, tol):
    """{index-0 node id: sample id} (nearest sample within tol)."""
    out = {}
    far = []
    for r in res.nodes_of_index(0):
        d, i = tree.query(res.loc[r])
        if d > tol:
            far.append((int(res.node_id[r]), res.loc[r].tolist(), d))
        out[int(res.node_id[r])] = int(i)
    return out, far


def gf2_rank(columns):
    """Rank over Z/2 of columns given as Python-int bitsets."""
    pivots = {}
    rank = 0
    for c in columns:
        while c:
            h = c.bit_length() - 1
            if h in pivots:
                c ^= pivots[h]
            else:
                pivots[h] = c
                rank += 1
                break
    return rank


def check_invariants(label, P, res, expectation):
    diam = fio.diameter(P)
    mag = float(res.report_value("PerturbationMagnitude") or 0.0)
    tol = 1e-6 * diam + 4.0 * mag  # positions move by the perturbation (~1e-9 * diameter)
    distinct = distinct_points(P)
    Pd = P[distinct]
    tree = cKDTree(Pd)
    n = res.counts()

    # --- nodes
    CHK.check(res.euler() == 1, "%s: n0-n1+n2-n3 = %d != 1 (counts %s)" % (label, res.euler(), n))
    CHK.check(len(res.infinity_ids()) == 1, "%s: %d nodes with value +inf (expected exactly one, "
              "the maximum at infinity)" % (label, len(res.infinity_ids())))
    for r in np.nonzero(~res.finite)[0]:
        CHK.check(res.index[r] == 3, "%s: the maximum at infinity has index %d" % (label, res.index[r]))
    CHK.check(len(set(res.node_id.tolist())) == len(res.node_id), "%s: NodeId not unique" % label)
    CHK.check(n[0] == len(Pd), "%s: %d index-0 nodes for %d distinct samples" % (label, n[0], len(Pd)))
    fin = np.nonzero(res.finite)[0]
    d, _ = tree.query(res.loc[fin])
    err = np.abs(d - res.value[fin])
    worst = int(np.argmax(err)) if len(err) else 0
    CHK.check(len(err) == 0 or err[worst] <= tol,
              "%s: a node value is not d_P at its location: node %d index %d value %r, d_P %r" % (
                  label, res.node_id[fin[worst]], res.index[fin[worst]], res.value[fin[worst]],
                  d[worst]) if len(err) else "")
    node_sample, far = sample_of_node(res, Pd, tree, tol)
    CHK.check(not far, "%s: index-0 nodes away from every sample: %s" % (label, far[:5]))
    CHK.check(len(set(node_sample.values())) == len(node_sample),
              "%s: two index-0 nodes on the same sample" % label)

    # --- arcs
    row = res.row
    known = np.array([int(lo) in row and int(up) in row for lo, up in zip(res.lower, res.upper)],
                     dtype=bool)
    CHK.check(known.all(), "%s: %d arcs name unknown nodes, e.g. %s" % (
        label, int((~known).sum()), list(zip(res.lower[~known], res.upper[~known]))[:5]))
    lo_r = np.array([row.get(int(x), 0) for x in res.lower])
    up_r = np.array([row.get(int(x), 0) for x in res.upper])
    step = res.index[up_r] - res.index[lo_r]
    CHK.check(np.all(step == 1), "%s: %d arcs do not go from index i to i+1, e.g. %s" % (
        label, int(np.sum(step != 1)),
        [(int(a), int(res.index[row[int(a)]]), int(b), int(res.index[row[int(b)]]))
         for a, b in zip(res.lower[step != 1], res.upper[step != 1])][:5]))
    CHK.check(np.all(res.mult >= 1), "%s: multiplicities < 1: %s" % (label, res.mult[res.mult < 1][:5]))
    if expectation == "generic" and "grid" not in label:
        inc = res.value[up_r] > res.value[lo_r]
    else:
        # Exact values increase along arcs, but near degeneracies (jittered grids,
        # near-cospherical samples, or degenerate input made generic by a tiny
        # perturbation eps) the gap can be O(eps^2), below double resolution: e.g. a
        # right triangle jittered by 1e-6 gives an index-1/index-2 gap of 4e-17 in
        # squared value. Allow ties and inversions of a few ulps there, and say so.
        lo_v, up_v = res.value[lo_r], res.value[up_r]
        inc = up_v >= lo_v * (1.0 - 4.0 * np.finfo(float).eps)
        ties = int(np.sum(up_v <= lo_v))
        if ties:
            print("  note: %s: %d arcs between nodes whose double values tie or invert by at "
                  "most 4 ulps" % (label, ties))
    CHK.check(inc.all(), "%s: %d arcs do not increase in value, e.g. %s" % (
        label, int((~inc).sum()),
        [(int(a), float(res.value[row[int(a)]]), int(b), float(res.value[row[int(b)]]))
         for a, b in zip(res.lower[~inc], res.upper[~inc])][:5]))
    # Ratio = V(upper) / V(lower), never below 1 (docs/design.md §1)
    with np.errstate(divide="ignore", invalid="ignore"):
        expect_ratio = res.value[up_r] / res.value[lo_r]
    same = (res.ratio == expect_ratio) | (np.abs(res.ratio - expect_ratio) <=
                                          1e-12 * np.abs(expect_ratio))
    CHK.check(same.all(), "%s: %d arcs whose Ratio is not V(upper)/V(lower), e.g. %s" % (
        label, int((~same).sum()), list(zip(res.lower[~same], res.upper[~same],
                                            res.ratio[~same], expect_ratio[~same]))[:5]))
    below = res.ratio < 1.0
    CHK.check(not below.any(), "%s: %d arcs have Ratio < 1 (docs/design.md §1: ratios are never "
              "below 1), e.g. (lower, upper, ratio, lower value, upper value) %s" % (
                  label, int(below.sum()),
                  [(int(a), int(b), repr(float(q)), repr(float(res.value[row[int(a)]])),
                    repr(float(res.value[row[int(b)]])))
                   for a, b, q in zip(res.lower[below], res.upper[below], res.ratio[below])][:4]))
    pairs = list(zip(res.lower.tolist(), res.upper.tolist()))
    CHK.check(len(set(pairs)) == len(pairs), "%s: %d arcs listed more than once" % (
        label, len(pairs) - len(set(pairs))))

    lowers = res.lower_neighbours()
    uppers = res.upper_neighbours()
    # index-1: two 0->1 arcs, at the midpoint of their samples
    bad1 = []
    gabriel = []
    for r in res.nodes_of_index(1):
        nid = int(res.node_id[r])
        lw = lowers.get(nid, [])
        if len(lw) != 2 or any(m != 1 for _, m in lw) or lw[0][0] == lw[1][0]:
            bad1.append((nid, lw))
            continue
        a, b = (node_sample.get(x) for x, _ in lw)
        if a is None or b is None:
            bad1.append((nid, lw))
            continue
        gabriel.append((a, b))
        mid = 0.5 * (Pd[a] + Pd[b])
        if np.linalg.norm(mid - res.loc[r]) > tol or \
                abs(0.5 * np.linalg.norm(Pd[a] - Pd[b]) - res.value[r]) > tol:
            bad1.append((nid, "not at the midpoint of samples %d, %d" % (a, b)))
    CHK.check(not bad1, "%s: %d index-1 nodes without exactly two 0->1 arcs to their edge ends" % (
        label, len(bad1)), bad1[:5])
    # index-2: two unstable arrivals
    bad2 = []
    for r in res.nodes_of_index(2):
        nid = int(res.node_id[r])
        ups = uppers.get(nid, [])
        if sum(m for _, m in ups) != 2:
            bad2.append((nid, ups))
    CHK.check(not bad2, "%s: %d index-2 nodes whose 2->3 multiplicities do not sum to 2" % (
        label, len(bad2)), bad2[:5])
    orphan = [int(res.node_id[r]) for r in res.nodes_of_index(3) if not lowers.get(int(res.node_id[r]))]
    CHK.check(not orphan, "%s: finite maxima without an index-2 predecessor: %s" % (label, orphan[:5]))

    # --- d o d = 0 mod 2
    pos = {}
    for k in range(4):
        for j, r in enumerate(res.nodes_of_index(k)):
            pos[int(res.node_id[r])] = (k, j)
    entries = {1: ([], []), 2: ([], []), 3: ([], [])}
    for lo, up, m in zip(res.lower, res.upper, res.mult):
        if m % 2 == 0 or int(up) not in pos or int(lo) not in pos:
            continue  # even multiplicity, or an arc to infinity
        (k, j), (_, i) = pos[int(up)], pos[int(lo)]
        entries[k][0].append(i)
        entries[k][1].append(j)
    B = {}
    for k in (1, 2, 3):
        rows, cols = entries[k]
        B[k] = coo_matrix((np.ones(len(rows), dtype=np.int64), (rows, cols)),
                          shape=(n[k - 1], n[k])).tocsr()
    for k in (1, 2):
        prod = (B[k] @ B[k + 1]).tocoo()
        odd = prod.data % 2 == 1
        CHK.check(not odd.any(), "%s: d%d o d%d != 0 mod 2 in %d entries, e.g. (row, column) %s" % (
            label, k, k + 1, int(odd.sum()), list(zip(prod.row[odd], prod.col[odd]))[:5]))
    cols3 = []
    B3 = B[3].tocsc()
    for j in range(n[3]):
        c = 0
        span = slice(B3.indptr[j], B3.indptr[j + 1])
        for i, v in zip(B3.indices[span], B3.data[span]):
            if v % 2:
                c ^= 1 << int(i)
        cols3.append(c)
    rk = gf2_rank(cols3)
    CHK.check(rk == n[3], "%s: rank of d3 over Z/2 is %d, expected n3 = %d" % (label, rk, n[3]))

    # --- EMST inside the Gabriel graph
    m = len(Pd)
    D = cdist(Pd, Pd)
    mst = minimum_spanning_tree(D).tocoo()
    emst_weight = float(mst.data.sum())
    gset = {tuple(sorted(e)) for e in gabriel}
    if gabriel:
        ga = np.array(gabriel)
        G = coo_matrix((np.linalg.norm(Pd[ga[:, 0]] - Pd[ga[:, 1]], axis=1), (ga[:, 0], ga[:, 1])),
                       shape=(m, m)).tocsr()
        ncomp, _ = connected_components(G, directed=False)
    else:
        G, ncomp = None, m
    CHK.check(ncomp == 1, "%s: the Gabriel graph has %d components" % (label, ncomp))
    if expectation in ("generic", "duplicates"):
        missing = [(int(a), int(b), float(D[a, b])) for a, b in zip(mst.row, mst.col)
                   if tuple(sorted((int(a), int(b)))) not in gset]
        CHK.check(not missing, "%s: %d EMST edges are not Gabriel edges (index-1 nodes): %s" % (
            label, len(missing), missing[:5]))
    elif G is not None and ncomp == 1:
        w = float(minimum_spanning_tree(G).data.sum())
        wtol = 4.0 * m * max(mag, 1e-9 * diam) + 1e-12
        CHK.check(abs(w - emst_weight) <= wtol,
                  "%s: lightest spanning tree of the Gabriel graph weighs %r, the EMST %r "
                  "(tolerance %.3g)" % (label, w, emst_weight, wtol))

    # --- stable manifolds: cells refer to known nodes of the right index
    if len(res.tri_nodes):
        ok = all(int(x) in row and res.index[row[int(x)]] == 2 for x in np.unique(res.tri_nodes))
        CHK.check(ok, "%s: Index-2 triangles with a NodeId that is not an index-2 node" % label)
        with_tris = set(int(x) for x in np.unique(res.tri_nodes))
        no_tris = [int(res.node_id[r]) for r in res.nodes_of_index(2)
                   if int(res.node_id[r]) not in with_tris]
        CHK.check(not no_tris, "%s: index-2 nodes without stable-manifold triangles: %s" % (
            label, no_tris[:5]))
    elif n[2]:
        CHK.check(False, "%s: no Index-2 triangles in StableManifolds although n2 = %d" % (label, n[2]))

    # --- degeneracy report
    attempts = res.report_value("PerturbationAttempts")
    duplicates = res.report_value("DuplicatePointCount", "DuplicatePoints")
    if expectation == "generic":
        CHK.check(attempts == 1, "%s: general-position input but PerturbationAttempts = %r "
                  "(report %s)" % (label, attempts, res.report))
    elif expectation == "perturbed":
        CHK.check(attempts is not None and attempts > 1,
                  "%s: degenerate input but the report does not say it was perturbed: "
                  "PerturbationAttempts = %r (report %s)" % (label, attempts, res.report))
    elif expectation == "duplicates":
        CHK.check(duplicates == len(P) - len(Pd),
                  "%s: DuplicatePoints = %r, expected %d merged duplicates (report %s)" % (
                      label, duplicates, len(P) - len(Pd), res.report))


def check_determinism(label, P):
    mb1, _ = fio.run_filter(P)
    mb2, _ = fio.run_filter(P)
    f1, f2 = fio.fingerprint(mb1), fio.fingerprint(mb2)
    diff = sorted(k for k in set(f1) | set(f2) if f1.get(k) != f2.get(k))
    CHK.check(not diff, "%s: two runs on the same input differ in %s" % (label, diff))


def run_case(label, P, expectation, determinism):
    res = fio.run(P)
    print("  %s: %s" % (label, res.summary()), flush=True)
    check_invariants(label, P, res, expectation)
    if determinism:
        check_determinism(label, P)


def main():
    for label, P in random_inputs():
        near = "near-cospherical" in label
        # determinism on a few sizes (each check runs the filter twice)
        det = near or len(P) in (50, 600) or label == "cube n=2000 seed=9"
        CHK.run("random %s" % label, run_case, label, P, "any" if near else "generic",
                determinism=det)
    for label, P, expectation in structured_inputs():
        CHK.run("structured %s" % label, run_case, label, P, expectation, determinism=True)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
