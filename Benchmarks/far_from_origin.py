#!/usr/bin/env python3
"""`flowrecon reconstruct` of a scan far from the origin against the same scan at it, same run.

Georeferenced scans (LAS files of terrain, buildings, sites) hold coordinates some
10^6 m from the origin for a site 100 m wide, quantized to the scanner's step. For
each N, a height field z = 5 sin(x/10) cos(y/13) + 2 sin(x/3 + y/5) is sampled at N
uniform (x, y) over a square as dense as 10^5 points on 100 m x 100 m, quantized to
0.01 m, and written twice as LAS 1.2 (point format 0): with the
offset (500 000, 4 000 000, 100) m, as UTM coordinates are, and with none. The
integers are the same in both files, so the clouds are the same up to the offset.
Each file is reconstructed as a whole process (reading, flow complex, topology,
compact output, writing) and timed with os.wait4: wall and CPU seconds, peak
resident memory. Printed: those figures, the ratio far / near of the wall times
(the baseline is the near run of the same cloud, in the same run), and whether both
print the same Betti numbers. Exit code 1 if they differ.

Run:
  /usr/bin/python3 Benchmarks/far_from_origin.py [--sizes 100000 1000000]
      [--flowrecon build/bin/flowrecon] [--work DIR] [--seed 11]
"""

import argparse
import os
import re
import struct
import sys
import tempfile

import numpy as np

from process_measure import run_measured

HERE = os.path.dirname(os.path.abspath(__file__))
OFFSET = (500000.0, 4000000.0, 100.0)
STEP = 0.01


def write_las(path, ints, offset):
    """LAS 1.2, point format 0 (20-byte records), scale STEP, the given offset."""
    n = len(ints)
    head = bytearray(b"LASF" + bytes(20) + bytes([1, 2]) + bytes(227 - 26))
    struct.pack_into("<HIIBHI", head, 94, 227, 227, 0, 0, 20, n)
    struct.pack_into("<6d", head, 131, STEP, STEP, STEP, *offset)
    records = np.zeros(n, dtype=[("xyz", "<i4", 3), ("rest", "V8")])
    records["xyz"] = ints
    with open(path, "wb") as f:
        f.write(bytes(head) + records.tobytes())


def terrain(n, seed):
    rng = np.random.default_rng(seed)
    side = 100.0 * np.sqrt(n / 1e5)
    x = rng.uniform(0, side, n)
    y = rng.uniform(0, side, n)
    z = 5 * np.sin(x / 10) * np.cos(y / 13) + 2 * np.sin(x / 3 + y / 5)
    return np.round(np.stack([x, y, z], axis=1) / STEP).astype(np.int64)


def betti(log_path):
    with open(log_path) as f:
        m = re.search(r"^Betti numbers: (\d+ \d+ \d+)$", f.read(), re.M)
    return m.group(1) if m else None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", type=int, nargs="+", default=[100000])
    parser.add_argument("--flowrecon", default=os.path.join(HERE, "..", "build", "bin", "flowrecon"))
    parser.add_argument("--work", default=None)
    parser.add_argument("--seed", type=int, default=11)
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="far_from_origin_")
    os.makedirs(work, exist_ok=True)
    failed = False
    print("points  cloud  wall s  cpu s  peak MB  Betti  far/near wall")
    for n in args.sizes:
        ints = terrain(n, args.seed)
        rows = {}
        for name, offset in (("near", (0.0, 0.0, 0.0)), ("far", OFFSET)):
            las = os.path.join(work, "terrain_%d_%s.las" % (n, name))
            write_las(las, ints, offset)
            log = las + ".log"
            code, wall, cpu, peak = run_measured(
                [args.flowrecon, "reconstruct", las, "-o", las[:-4] + ".vtu"], log)
            rows[name] = (code, wall, cpu, peak, betti(log))
        for name in ("near", "far"):
            code, wall, cpu, peak, b = rows[name]
            ratio = "%.2f" % (rows["far"][1] / rows["near"][1]) if name == "far" else ""
            print("%7d  %-5s  %6.2f  %5.1f  %7.0f  %s  %s" % (n, name, wall, cpu, peak, b, ratio))
            failed = failed or code != 0
        if rows["near"][4] is None or rows["near"][4] != rows["far"][4]:
            print("  the Betti numbers differ (or are missing): see %s" % work)
            failed = True
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
