"""Prints the cloud a fuzz_core input stands for, as .xyz lines (and its
options on stderr), following CloudOf in FuzzCore.cxx.

Usage: python3 Testing/Fuzz/decode_core.py INPUT > cloud.xyz
"""
import math
import struct
import sys

data = open(sys.argv[1], "rb").read()
if len(data) < 2:
    sys.exit("shorter than 2 bytes: no points")
flags, s = data[0], struct.unpack("b", data[1:2])[0]
mode = flags & 3
exponent = 0 if abs(s) < 100 else (1 if s > 0 else -1) * (abs(s) - 99) * 40
width = {0: 1, 1: 1, 2: 2, 3: 8}[mode]
body = data[2:]
n = min(len(body) // (3 * width), 64)
print("# encoding %d, eager %d, t_p %g, scale 2^%d, %d points" % (
    mode, (flags >> 2) & 1, [0, 1.05, 1.1, 1.5][(flags >> 3) & 3], exponent, n), file=sys.stderr)
for i in range(n):
    xyz = []
    for k in range(3):
        o = (3 * i + k) * width
        if mode == 0:
            x = body[o] & 7
        elif mode == 1:
            x = struct.unpack_from("b", body, o)[0]
        elif mode == 2:
            x = struct.unpack_from("<H", body, o)[0] / 65536.0
        else:
            x = struct.unpack_from("<d", body, o)[0]
        try:
            xyz.append(math.ldexp(x, exponent))
        except OverflowError:
            xyz.append(math.copysign(math.inf, x))
    print(" ".join("%.17g" % x for x in xyz))
