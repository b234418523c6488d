"""The automatic thresholds on clouds that are the vertices of decimated meshes
(Benchmarks/Study/mesh_vertices.py, its quick set): the 96^3 isosurfaces of a
sphere, a torus and two spheres 0.2 apart, 90 % and 97 % of their triangles
removed by VTK's quadric decimation. The truth is each mesh's own (components
and Euler characteristic of a closed 2-manifold). At defaults each answer must
be right or warned; a warning that closed surfaces were apart for t_r in
(a, b] is checked against a run at the middle of that range, whose Betti
numbers must be the ones it names. The 97 % two spheres are apart only over
(1.42, 1.46], below the range where windows are looked for: the build before
answered 1 0 2 there without a warning.
Usage: test_mesh_vertices.py FLOWRECON WORKDIR
"""
import os
import re
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Benchmarks", "Study"))
import held_out_shapes as ho  # noqa: E402
import mesh_vertices as mv  # noqa: E402

APART = re.compile(r"^warning: (\d+) closed surfaces were apart for t_r in \(([\d.]+), ([\d.]+)\] "
                   r"\(Betti numbers (\d+) (\d+) (\d+)\)", re.M)

FLOWRECON, WORK = sys.argv[1:3]
os.makedirs(WORK, exist_ok=True)
failures, warned_apart = [], 0
for k, (name, poly) in enumerate(mv.meshes(quick=True)):
    truth = mv.truth_of(poly)
    if truth is None:
        failures.append(name + ": the mesh is not a closed 2-manifold")
        continue
    cloud = os.path.join(WORK, "mesh%02d.xyz" % k)
    np.savetxt(cloud, mv.vertices(poly), fmt="%.17g")
    out = subprocess.run([FLOWRECON, "reconstruct", cloud, "-o", cloud[:-4] + ".vtu"],
                         capture_output=True, text=True)
    m = re.search(r"^Betti numbers: (\d+) (\d+) (\d+)$", out.stdout, re.M)
    betti = tuple(int(x) for x in m.groups()) if m else None
    warned = any(line.startswith("warning:") for line in out.stderr.splitlines())
    choice = re.search(r"^t_r .*\(auto\).*$", out.stdout, re.M).group(0)
    verdict = ho.verdict(betti, warned, truth)
    print("%s: Betti %s, truth %s: %s" % (name, betti, truth, verdict))
    if verdict not in ("right", "flagged"):
        failures.append("%s: %s %s" % (name, verdict, betti))
    for m in APART.finditer(out.stderr):
        warned_apart += 1
        lo, hi = float(m.group(2)), float(m.group(3))
        named = tuple(int(m.group(i)) for i in (4, 5, 6))
        tp = re.search(r"t_p (\S+) \(auto\)", choice).group(1)
        again, _, _ = ho.run(FLOWRECON, cloud, ["--tp", tp, "--tr", "%.6f" % np.sqrt(lo * hi)])
        print("  apart for t_r in (%g, %g] at t_p %s: Betti %s there, %s named" % (lo, hi, tp, again, named))
        if again != named or named[0] != int(m.group(1)) or named[0] <= betti[0]:
            failures.append("%s: the range named apart gives %s, not %s" % (name, again, named))
if warned_apart == 0:
    failures.append("no cloud warned of closed surfaces apart below the answer")
if failures:
    raise SystemExit("; ".join(failures))
print("every answer right or warned; %d warning(s) of surfaces apart checked" % warned_apart)
