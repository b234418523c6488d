#!/usr/bin/env python3
"""`flowrecon diagram` against GUDHI's alpha-complex persistence, same points, same run.

For each N: N points uniform in the unit cube (numpy, fixed seed) are written as
.xyz; `flowrecon diagram X.xyz -o D.csv --quiet` is timed as a whole process
(start-up, reading the text file, flow complex, persistence, writing the CSV);
GUDHI's alpha persistence (gudhi.AlphaComplex(points=P).create_simplex_tree() and
compute_persistence(homology_coeff_field=2), in a child process given the points
as a numpy array, timed without its start-up and loading) runs on the same points.
Printed: wall and CPU seconds and peak resident memory of each process, the ratio
of GUDHI's time to flowrecon's, and whether the two diagrams agree: per dimension,
the multisets of (birth, death) with GUDHI's squared radii square-rooted, pairs of
persistence below 1e-9 relative dropped on both sides, values equal within 1e-9
relative; values of GUDHI's default precision ('safe') are only guaranteed within
1e-5 relative, so pairs beyond 1e-9 but within 1e-5 are listed, not failed. Exit
code 1 if a diagram differs.

Run (Debian's python3 has gudhi and numpy):
  /usr/bin/python3 Benchmarks/diagram_vs_gudhi.py [--sizes 100000 1000000] [--seed 1]
      [--flowrecon build/bin/flowrecon] [--work DIR] [--threads N] [--no-gudhi]
GUDHI needs about 10 GB at 10^6 points.
"""

import argparse
import json
import os
import sys
import tempfile

import numpy as np

from process_measure import run_measured

HERE = os.path.dirname(os.path.abspath(__file__))
REL = 1e-9
SAFE = 1e-5  # CGAL's relative precision of to_double, which GUDHI's 'safe' values have

GUDHI_CHILD = r"""
import json, sys, time
import numpy as np
import gudhi
P = np.load(sys.argv[1])
t0 = time.perf_counter()
st = gudhi.AlphaComplex(points=P).create_simplex_tree()
t1 = time.perf_counter()
st.compute_persistence(homology_coeff_field=2)
t2 = time.perf_counter()
out = {}
for d in range(3):
    out["h%d" % d] = np.asarray(st.persistence_intervals_in_dimension(d),
                                dtype=float).reshape(-1, 2)
np.savez(sys.argv[2], **out)
print(json.dumps({"complex": t1 - t0, "persistence": t2 - t1, "simplices": st.num_simplices()}))
"""


def read_flowrecon_csv(path):
    with open(path) as f:
        header = f.readline().strip()
        if header != "dimension,birth,death":
            raise RuntimeError("%s: unexpected header %r" % (path, header))
        a = np.loadtxt(f, delimiter=",", dtype=float, ndmin=2)  # "inf" parses
    return {d: a[a[:, 0] == d, 1:3] for d in range(3)}


def significant(pairs):
    b, e = pairs[:, 0], pairs[:, 1]
    keep = np.isinf(e) | (e - b > REL * np.abs(e))
    return pairs[keep]


def close_values(x, y):
    with np.errstate(invalid="ignore"):  # inf - inf
        return (x == y) | (np.abs(x - y) <= REL * np.maximum(np.abs(x), np.abs(y)))


def close(x, y):
    return bool(np.all(close_values(x, y)))


def compare(mine, gudhi_pairs):
    """(ok, message): per dimension, the same number of pairs, equal within REL once
    sorted; pairs beyond REL but within SAFE are counted (GUDHI's default 'safe'
    precision only guarantees its values within a relative 1e-5 of the exact ones)."""
    msgs = []
    ok = True
    for d in range(3):
        a = significant(mine[d])
        g = gudhi_pairs["h%d" % d]
        g = significant(np.sqrt(np.maximum(g, 0.0)))
        if len(a) != len(g):
            ok = False
            msgs.append("H%d: %d pairs (flowrecon) vs %d (GUDHI)" % (d, len(a), len(g)))
            continue
        best = None
        for keys in ((0, 1), (1, 0)):  # near ties may sort differently on one key
            ia = np.lexsort((a[:, keys[1]], a[:, keys[0]]))
            ig = np.lexsort((g[:, keys[1]], g[:, keys[0]]))
            bad = np.nonzero(~np.all(close_values(a[ia], g[ig]), axis=1))[0]
            if best is None or len(bad) < len(best[0]):
                best = (bad, a[ia], g[ig])
        bad, sa, sg = best
        if len(bad) == 0:
            continue
        with np.errstate(invalid="ignore"):
            rel = np.nanmax(np.abs(sa[bad] - sg[bad]) /
                            np.maximum(np.abs(sa[bad]), np.abs(sg[bad])))
        within = rel <= SAFE
        ok = ok and within
        msgs.append("H%d: %d of %d pairs differ by more than %g relative, at most %.2g%s; first "
                    "%s vs GUDHI %s" % (d, len(bad), len(a), REL, rel,
                                        " (within GUDHI's 'safe' precision %g)" % SAFE if within
                                        else "", sa[bad[0]].tolist(), sg[bad[0]].tolist()))
    return ok, "; ".join(msgs)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100000])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--flowrecon",
                        default=os.path.join(HERE, "..", "build", "bin", "flowrecon"))
    parser.add_argument("--work", default=None, help="directory for the files (default: temporary)")
    parser.add_argument("--threads", type=int, default=None, help="flowrecon --threads N")
    parser.add_argument("--no-gudhi", action="store_true", help="time flowrecon only")
    args = parser.parse_args()

    work = args.work or tempfile.mkdtemp(prefix="diagram_vs_gudhi_")
    os.makedirs(work, exist_ok=True)
    print("flowrecon: %s; work directory %s; %d cores" % (
        os.path.abspath(args.flowrecon), work, os.cpu_count()), flush=True)
    failed = False
    for n in args.sizes:
        points = np.random.default_rng(args.seed).uniform(0.0, 1.0, (n, 3))
        xyz = os.path.join(work, "cube_%d.xyz" % n)
        npy = os.path.join(work, "cube_%d.npy" % n)
        np.savetxt(xyz, points, fmt="%.17g")
        np.save(npy, points)

        csv = os.path.join(work, "cube_%d_flowrecon.csv" % n)
        cmd = [args.flowrecon, "diagram", xyz, "-o", csv, "--quiet"]
        if args.threads:
            cmd += ["--threads", str(args.threads)]
        code, fr_wall, fr_cpu, fr_mem = run_measured(cmd, os.path.join(work, "flowrecon.log"))
        if code != 0:
            print("N=%d: flowrecon exits %d (see %s/flowrecon.log)" % (n, code, work))
            failed = True
            continue
        print("N=%-8d flowrecon diagram (whole process): %7.2f s wall, %7.2f s CPU, %6.0f MB peak"
              % (n, fr_wall, fr_cpu, fr_mem), flush=True)
        if args.no_gudhi:
            continue

        npz = os.path.join(work, "cube_%d_gudhi.npz" % n)
        log = os.path.join(work, "gudhi.log")
        code, g_wall, g_cpu, g_mem = run_measured(
            [sys.executable, "-c", GUDHI_CHILD, npy, npz], log)
        if code != 0:
            print("N=%d: GUDHI exits %d (see %s)" % (n, code, log))
            failed = True
            continue
        with open(log) as f:
            g = json.loads(f.read().strip().splitlines()[-1])
        g_time = g["complex"] + g["persistence"]
        print("           GUDHI alpha persistence:           %7.2f s (complex %.2f + persistence "
              "%.2f; whole process %.2f s wall, %.2f s CPU), %6.0f MB peak"
              % (g_time, g["complex"], g["persistence"], g_wall, g_cpu, g_mem))
        print("           ratio GUDHI / flowrecon: %.1fx (whole process of GUDHI: %.1fx)"
              % (g_time / fr_wall, g_wall / fr_wall))
        ok, msg = compare(read_flowrecon_csv(csv), np.load(npz))
        print("           diagrams %s%s" % ("agree" if ok else "DIFFER",
                                         (": " + msg) if msg else ""), flush=True)
        failed = failed or not ok
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
