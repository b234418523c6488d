"""Reconstruct Point Cloud (one filter, from the cloud, automatic thresholds) in
pvpython gives what the step-by-step pipeline at its defaults gives:

- on 10^4 i.i.d. points of a torus (the generator's truth: Betti numbers 1 2 1),
  both give 1 2 1, the same t_p, the same t_r (to 5e-4) and stable window (to
  5e-3), the same topology profile rows (to 1e-9) and the same under-sampling
  places; its Topology field data and Topology Text say the same Betti numbers
  and thresholds, with "(auto)";
- its Profile has a row per step with the column t_r = the chosen t_r;
- its Persistence Diagram has, per dimension, as many pairs as Persistence
  Diagram of the step-by-step Flow Complex, its t_p line where t_p says (none
  for t_p 0); with Compute Persistence Diagram off, it is empty and the
  reconstruction the same;
- it reports progress (increasing, from the start) and stops when AbortExecute is
  set from a progress observer: within a few seconds, every output empty, the
  warning "... aborted".

Usage: pvpython test_point_cloud_reconstruction.py PLUGIN WORKDIR
"""
import os
import sys
import time

import generate_clouds as gc
from paraview import servermanager
from paraview.simple import Delete, LoadPlugin, OpenDataFile

from flowrecon_testing.checks import check, finish

PLUGIN, WORK = sys.argv[1:3]
LoadPlugin(PLUGIN, remote=False, ns=globals())


def values(fd, name):
    a = fd.GetAbstractArray(name)
    if a is None:
        return None
    if a.IsA("vtkStringArray"):
        return [a.GetValue(k) for k in range(a.GetNumberOfValues())]
    return [a.GetComponent(k // a.GetNumberOfComponents(), k % a.GetNumberOfComponents())
            for k in range(a.GetNumberOfValues())]


def rows(table, names):
    return [tuple(table.GetValueByName(r, n).ToDouble() for n in names)
            for r in range(table.GetNumberOfRows())]


def places(warnings):
    pd = warnings.GetPointData()
    return sorted((round(pd.GetArray("Threshold").GetValue(k), 9), int(pd.GetArray("Dimension").GetValue(k)),
                   int(pd.GetArray("Change").GetValue(k)))
                  for k in range(warnings.GetNumberOfPoints()))


def pairs_by_dimension(diagram):
    types = diagram.GetCellData().GetArray("PairType")
    counts = {}
    for k in range(diagram.GetNumberOfCells()):
        t = int(types.GetValue(k))
        counts[t] = counts.get(t, 0) + 1
    return counts


def outputs(proxy, ports):
    proxy.UpdatePipeline()
    return {k: servermanager.Fetch(proxy, idx=k) for k in ports}


def main():
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, "torus_1e4.xyz")
    with open(path, "w") as f:
        f.write(gc.to_xyz_text(gc.make("torus", 10000)))
    truth = tuple(gc.betti("torus"))
    reader = OpenDataFile(path)

    t0 = time.time()
    one = ReconstructPointCloud(Input=reader)  # noqa: F821 (defined by LoadPlugin)
    o = outputs(one, range(6))
    seconds = time.time() - t0
    t0 = time.time()
    fc = FlowComplex(Input=reader)  # noqa: F821
    simplified = FlowComplexSimplification(Input=fc)  # noqa: F821
    recon = FlowReconstruction(Input=simplified)  # noqa: F821
    s = outputs(recon, (0, 3, 4))
    steps = time.time() - t0
    fd1, fd2 = o[0].GetFieldData(), s[0].GetFieldData()
    betti1 = tuple(int(v) for v in values(fd1, "BettiNumbers"))
    betti2 = tuple(int(v) for v in values(fd2, "BettiNumbers"))
    tr1, tr2 = values(fd1, "ReconstructionThreshold")[0], values(fd2, "ReconstructionThreshold")[0]
    tp1, tp2 = values(fd1, "PersistenceThreshold")[0], values(fd2, "PersistenceThreshold")[0]
    w1, w2 = values(fd1, "StableWindow"), values(fd2, "StableWindow")
    print("Reconstruct Point Cloud (%.1f s): Betti %s, t_r %.4f, t_p %g, window %s" % (
        seconds, betti1, tr1, tp1, w1))
    print("step by step (%.1f s): Betti %s, t_r %.4f, t_p %g, window %s" % (steps, betti2, tr2, tp2, w2))
    check(betti1 == truth and betti2 == truth,
          "Betti numbers %s (one filter) and %s (step by step), the truth is %s" % (betti1, betti2, truth))
    check(abs(tr1 - tr2) <= 5e-4 * tr2 and tp1 == tp2,
          "one filter chose t_r %g t_p %g, the pipeline t_r %g t_p %g" % (tr1, tp1, tr2, tp2))
    check(w1 is not None and w2 is not None and all(abs(a - b) <= 5e-3 * b for a, b in zip(w1, w2)),
          "stable windows %s and %s" % (w1, w2))
    check(values(fd1, "ThresholdsChosen") == [1.0, 1.0], "ThresholdsChosen %s" % values(fd1, "ThresholdsChosen"))
    names = ("Threshold", "b0", "b1", "b2")
    r1, r2 = rows(o[3], names), rows(s[3], names)
    check(len(r1) == len(r2) and all(abs(a[0] - b[0]) <= 1e-9 * max(1, b[0]) and a[1:] == b[1:]
                                     for a, b in zip(r1, r2)),
          "topology profiles differ: %d and %d rows" % (len(r1), len(r2)))
    check(places(o[4]) == places(s[4]), "under-sampling places %s and %s" % (places(o[4]), places(s[4])))
    line = values(fd1, "Topology")[0]
    text = o[5].GetValueByName(0, "Topology").ToString()
    print("Topology:", line)
    expected = "Betti numbers %d %d %d at t_r %.3f (auto), t_p %g (auto)" % (betti1 + (tr1, tp1))
    check(line.startswith(expected), "Topology %r does not start with %r" % (line, expected))
    check(text.replace("\n", " ").replace("  ", " ").startswith(expected.split(" at ")[0]),
          "Topology Text %r" % text)
    profile = o[1]
    tcol = profile.GetColumnByName("t_r")
    check(profile.GetNumberOfRows() > 1000 and tcol is not None and
          tcol.GetRange() == (tr1, tr1),
          "the profile has %d rows, t_r %s" % (profile.GetNumberOfRows(),
                                                tcol.GetRange() if tcol else None))

    # The diagram: the one of the cloud, as Persistence Diagram computes it.
    pd = PersistenceDiagram(Input=fc, PersistenceThreshold=tp1)  # noqa: F821
    reference = outputs(pd, (0,))[0]
    got, want = pairs_by_dimension(o[2]), pairs_by_dimension(reference)
    print("diagram pairs by PairType:", got, "Persistence Diagram's:", want)
    check(got == want and got.get(1, 0) > 0, "diagram pairs %s, Persistence Diagram's %s" % (got, want))
    check((-2 in got) == (tp1 >= 1), "the t_p line is %s for t_p %g" % (-2 in got, tp1))
    one.ComputePersistenceDiagram = 0
    off = outputs(one, (0, 2))
    check(off[2].GetNumberOfCells() == 0, "Compute Persistence Diagram off: %d diagram cells"
          % off[2].GetNumberOfCells())
    check(off[0].GetNumberOfCells() == o[0].GetNumberOfCells() and
          values(off[0].GetFieldData(), "BettiNumbers") == values(fd1, "BettiNumbers"),
          "without the diagram the reconstruction changed")

    # Progress, and abort from a progress observer.
    one.ComputePersistenceDiagram = 1
    one.MaximumThreshold = 4.9  # a new run
    algorithm = one.GetClientSideObject()
    seen = []
    state = {}

    def on_progress(obj, event):
        seen.append((time.time(), obj.GetProgress()))
        if obj.GetProgress() >= 0.05 and "asked" not in state:
            state["asked"] = time.time()
            obj.SetAbortExecute(1)

    tag = algorithm.AddObserver("ProgressEvent", on_progress)
    t0 = time.time()
    aborted = outputs(one, range(6))
    end = time.time()
    algorithm.RemoveObserver(tag)
    algorithm.SetAbortExecute(0)
    progress = [p for _, p in seen]
    print("progress reports: %d, first %.3f s in; abort asked %.2f s in, run ended %.2f s later"
          % (len(seen), seen[0][0] - t0 if seen else -1, state.get("asked", t0) - t0,
             end - state.get("asked", end)))
    check(len(seen) >= 3 and progress == sorted(progress[:-1]) + progress[-1:],
          "progress reports %s" % progress[:20])
    check("asked" in state and end - state["asked"] < 10,
          "the run went on %.1f s after AbortExecute" % (end - state.get("asked", t0)))
    sizes = [aborted[0].GetNumberOfCells(), aborted[1].GetNumberOfRows(),
             aborted[2].GetNumberOfCells(), aborted[3].GetNumberOfRows(),
             aborted[4].GetNumberOfPoints(), aborted[5].GetNumberOfRows()]
    check(sizes == [0] * 6, "an aborted run left outputs of sizes %s" % sizes)
    for proxy in (one, pd, recon, simplified, fc, reader):
        Delete(proxy)


main()
finish()
