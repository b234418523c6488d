#!/usr/bin/python3
"""The volume references of the local flatness test (Filters/Base/Reconstruction/LocalFlatness.h,
FlatnessScales): the median of lambda_min / lambda_mid over the k nearest samples
(the probe included) of a uniform i.i.d. volume sample, for the neighbourhood sizes
the test uses. Probes are kept away from the cube's faces, so that the figure is a
volume's, not a boundary's.

    /usr/bin/python3 Benchmarks/Study/flatness_reference.py [--points 200000] [--probes 4000]
"""
import argparse

import numpy as np
from scipy.spatial import cKDTree


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=200000)
    ap.add_argument("--probes", type=int, default=4000)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--k", default="10,30,100")
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    points = rng.random((args.points, 3))
    tree = cKDTree(points)
    inner = points[(np.abs(points - 0.5) < 0.3).all(axis=1)][: args.probes]
    print("k  median  (10th, 90th percentile)")
    for k in (int(x) for x in args.k.split(",")):
        _, near = tree.query(inner, k)
        q = points[near] - points[near].mean(axis=1, keepdims=True)
        ev = np.linalg.eigvalsh(np.einsum("nki,nkj->nij", q, q))
        ratio = ev[:, 0] / ev[:, 1]
        lo, hi = np.percentile(ratio, [10, 90])
        print("%-3d %.3f   (%.3f, %.3f)" % (k, np.median(ratio), lo, hi))


if __name__ == "__main__":
    main()
