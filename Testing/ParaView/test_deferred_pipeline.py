"""Deferred patches through the ParaView filters: Flow Complex with
Defer Patches Above = T leaves out the 1-2 arcs of the index-2 saddles at least T
times above the largest Gabriel edge (T = 4 in ParaView; 2 here, where
these small clouds have many such patches); Flow Complex Simplification records what a
replay needs; Flow Reconstruction walks the patches it needs. The eager pipeline
(Defer Patches Above = 0) is the oracle: at every t_r up to Maximum Threshold T
both give the same reconstruction cell by cell (points, cells, NodeId, Index,
Step, Priority, Threshold, Extension, Sponsor), the same profile below T, the
same topology profile and sponsor arrows; the Persistence Diagram of the deferred
complex (which walks every deferred patch) equals the eager one. Wrong settings
give errors naming the GUI's properties, and a stored simplification whose pairs
claim a ratio at T is refused.

The CLI's `flowrecon diagram` of the deferred complex, saved as a .vtm, must give
the pairs of the cloud itself, and `flowrecon reconstruct` the filter's grid: the
exact one (`--exact`), and the compact one (the default) at t_r 1.2, 1.5 and 1.8, which the
filter selects from walks made once for T_max.

Run: pvpython test_deferred_pipeline.py PLUGIN WORKDIR [FLOWRECON]   (no X server needed)
"""

import os
import subprocess
import sys

import numpy as np
from paraview import servermanager, simple
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand

from flowrecon_testing import clouds as cl
from flowrecon_testing.checks import check, finish

PLUGIN, WORK = sys.argv[1:3]
CLI = sys.argv[3] if len(sys.argv) > 3 else None  # the flowrecon program
simple.LoadPlugin(PLUGIN, ns=globals())


def arrays(data, names):
    out = {}
    for where, attrs in (("pd", data.GetPointData()), ("cd", data.GetCellData())):
        for name in names:
            a = attrs.GetArray(name)
            if a is not None:
                out[where + ":" + name] = vtk_to_numpy(a).copy()
    return out


def dataset_state(data):
    """Points, cells and the contract's arrays of a vtkDataSet or vtkTable."""
    names = ("NodeId", "Index", "Step", "Priority", "Threshold", "Extension", "Sponsor",
             "CriticalValue", "Multiplicity", "Direction", "b0", "b1", "b2", "t_r")
    if data.IsA("vtkTable"):
        return {data.GetColumnName(i): vtk_to_numpy(data.GetColumn(i)).copy()
                for i in range(data.GetNumberOfColumns())
                if data.GetColumn(i).IsA("vtkDataArray")}
    state = arrays(data, names)
    if data.GetNumberOfPoints():
        state["points"] = vtk_to_numpy(data.GetPoints().GetData()).copy()
    if data.IsA("vtkUnstructuredGrid"):
        state["cells"] = vtk_to_numpy(data.GetCells().GetConnectivityArray()).copy()
        state["types"] = vtk_to_numpy(data.GetCellTypesArray()).copy()
    elif data.IsA("vtkPolyData"):
        state["lines"] = vtk_to_numpy(data.GetLines().GetConnectivityArray()).copy()
    return state


def same(label, a, b):
    keys = sorted(set(a) | set(b))
    bad = [k for k in keys if k not in a or k not in b or a[k].shape != b[k].shape or
           not np.array_equal(a[k], b[k], equal_nan=a[k].dtype.kind == "f")]
    check(not bad, "%s: the deferred pipeline differs from the eager one in %s" % (label, bad))
    return not bad


class Errors:
    """Collects the error messages of an algorithm."""

    def __init__(self, proxy):
        self.messages = []
        algo = proxy.GetClientSideObject()
        algo.AddObserver(vtkCommand.ErrorEvent, self.on_error)

    def on_error(self, obj, event, message=None):
        self.messages.append(str(message))

    on_error.CallDataType = "string0"


def pipeline(reader, defer, cap):
    fc = FlowComplex(Input=reader, ComputeStableManifolds=0,  # noqa: F821
                     DeferPatchesAbove=defer)
    # Given thresholds (t_p 1.1): the eager and the lazy run at each t_r.
    simp = FlowComplexSimplification(Input=fc, AutomaticPersistenceThreshold=0)  # noqa: F821
    recon = FlowReconstruction(Input=simp, MaximumThreshold=cap,  # noqa: F821
                               AutomaticReconstructionThreshold=0,
                               Geometry="Exact stable manifolds", SponsorArrows=1)
    return fc, simp, recon


def compare_cloud(name, points, ratio, least):
    xyz = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(xyz, points)
    reader = simple.OpenDataFile(xyz)
    eager = pipeline(reader, 0.0, ratio)
    lazy = pipeline(reader, ratio, ratio)
    cp = servermanager.Fetch(lazy[0]).GetBlock(0)
    deferred = cp.GetPointData().GetArray("Deferred")
    count = int(vtk_to_numpy(deferred).sum()) if deferred is not None else 0
    arcs = [servermanager.Fetch(p[0]).GetBlock(1).GetNumberOfCells() for p in (eager, lazy)]
    print("%s: %d points, %d deferred patches, Hasse arcs %d eager, %d deferred" % (
        name, len(points), count, arcs[0], arcs[1]), flush=True)
    check(count >= least and arcs[1] < arcs[0],
          "%s: Defer Patches Above %g deferred %d patches (%d of %d arcs kept)" % (
              name, ratio, count, arcs[1], arcs[0]))
    for tr, every in [(t, 0) for t in (1.2, 1.5, 2.0, 3.0) if t < ratio] + [(ratio, 1)]:
        for p in (eager, lazy):
            p[2].ReconstructionThreshold = tr
            p[2].EveryStep = every
            p[2].UpdatePipeline()
        label = "%s at t_r %g%s" % (name, tr, " (Every Step)" if every else "")
        for port in (0, 2, 3):
            states = [dataset_state(servermanager.Fetch(p[2], idx=port)) for p in (eager, lazy)]
            same("%s, output %d" % (label, port), *states)
        cells = servermanager.Fetch(lazy[2]).GetNumberOfCells()
        check(cells > 0, "%s: no cells" % label)
        # The profile: the same rows wherever Threshold < T_max (the deferred run
        # stops there; the eager one goes on).
        tables = [dataset_state(servermanager.Fetch(p[2], idx=1)) for p in (eager, lazy)]
        below = [t["Threshold"] < ratio for t in tables]
        check(count == 0 or below[1].all(),
              "%s: the deferred profile has rows at or above T_max" % label)
        same("%s, profile below T_max" % label,
             {k: v[below[0]] for k, v in tables[0].items()},
             {k: v[below[1]] for k, v in tables[1].items()})
    # The persistence diagram of the deferred complex walks every patch.
    diagrams = [PersistenceDiagram(Input=p[0]) for p in (eager, lazy)]  # noqa: F821
    for port in (0, 1):
        states = [dataset_state(servermanager.Fetch(d, idx=port)) for d in diagrams]
        same("%s, persistence diagram output %d" % (name, port), *states)
    if CLI:
        # `flowrecon diagram` of the deferred complex saved from ParaView walks
        # every patch too: its pairs are those of the cloud itself.
        vtm = os.path.join(WORK, name.replace(" ", "_") + "_deferred.vtm")
        simple.SaveData(vtm, proxy=lazy[0])
        rows = []
        for source in (vtm, xyz):
            csv = source + ".diagram.csv"
            run = subprocess.run([CLI, "diagram", source, "-o", csv, "--quiet"],
                                 capture_output=True, text=True)
            check(run.returncode == 0, "flowrecon diagram %s: %s" % (source, run.stderr))
            rows.append(sorted(open(csv).read().splitlines()[1:]) if run.returncode == 0 else [])
        check(rows[0] == rows[1] and len(rows[0]) > 0,
              "%s: flowrecon diagram of the deferred .vtm differs from the cloud's "
              "(%d against %d pairs)" % (name, len(rows[0]), len(rows[1])))
        # The filter cuts each t_r's grid out of its grid at T_max (GridBelow);
        # `flowrecon reconstruct` draws the grid at t_r itself: the same cells,
        # points and arrays (Multiplicity at t_r included).
        vtu = os.path.join(WORK, name.replace(" ", "_") + "_tr1.5.vtu")
        run = subprocess.run([CLI, "reconstruct", xyz, "-o", vtu, "--tr", "1.5", "--tp", "1.1", "--exact",
                              "--quiet"],
                             capture_output=True, text=True)
        check(run.returncode == 0, "flowrecon reconstruct %s: %s" % (xyz, run.stderr))
        lazy[2].ReconstructionThreshold = 1.5
        lazy[2].EveryStep = 0
        lazy[2].UpdatePipeline()
        reader = simple.XMLUnstructuredGridReader(FileName=[vtu])
        same("%s at t_r 1.5: the filter against flowrecon reconstruct" % name,
             dataset_state(servermanager.Fetch(reader)),
             dataset_state(servermanager.Fetch(lazy[2])))
        simple.Delete(reader)
        compare_compact(name, xyz, lazy, ratio)
    return reader, lazy


def compact_cells(grid):
    """{(NodeId, sorted point ids)} of a compact grid (its points are the samples,
    in input order, in both files)."""
    node = grid.GetCellData().GetArray("NodeId")
    cells = set()
    for c in range(grid.GetNumberOfCells()):
        ids = grid.GetCell(c).GetPointIds()
        cells.add((node.GetValue(c), tuple(sorted(ids.GetId(k) for k in range(ids.GetNumberOfIds())))))
    return cells


def compare_compact(name, xyz, lazy, ratio):
    """The compact geometry of the filter, prepared once for T_max and selected at
    each t_r, against `flowrecon reconstruct`'s default file, made anew from the
    cloud for that t_r alone (its own triangulation and walks)."""
    recon = lazy[2]
    recon.Geometry = "Compact (Delaunay simplices on the samples)"
    for tr in [t for t in (1.2, 1.5, 1.8) if t < ratio]:
        vtu = os.path.join(WORK, "%s_compact_tr%g.vtu" % (name.replace(" ", "_"), tr))
        run = subprocess.run([CLI, "reconstruct", xyz, "-o", vtu, "--tr", str(tr), "--tp", "1.1",
                              "--quiet"], capture_output=True, text=True)
        check(run.returncode == 0, "flowrecon reconstruct %s: %s" % (xyz, run.stderr))
        recon.ReconstructionThreshold = tr
        recon.UpdatePipeline()
        reader = simple.XMLUnstructuredGridReader(FileName=[vtu])
        cli, ours = compact_cells(servermanager.Fetch(reader)), compact_cells(servermanager.Fetch(recon))
        print("%s at t_r %g, compact: %d cells (flowrecon reconstruct %d)" % (
            name, tr, len(ours), len(cli)), flush=True)
        check(len(ours) > 0 and ours == cli,
              "%s at t_r %g: the compact geometry differs from flowrecon reconstruct's "
              "(%d and %d cells, %d in common)" % (name, tr, len(ours), len(cli), len(ours & cli)))
        simple.Delete(reader)
    recon.Geometry = "Exact stable manifolds"


def wrong_settings(lazy):
    fc, simp, recon = lazy
    ratio = fc.DeferPatchesAbove
    errors = Errors(simp)
    simp.PersistenceThreshold = ratio
    simp.UpdatePipeline()
    check(any("Persistence Threshold (t_p)" in m and "Defer Patches Above" in m
              for m in errors.messages),
          "t_p = Defer Patches Above: errors %s" % errors.messages)
    simp.PersistenceThreshold = 1.1
    errors = Errors(recon)
    recon.MaximumThreshold = ratio * 2
    recon.UpdatePipeline()
    check(any("Maximum Threshold (T_max)" in m and "Defer Patches Above" in m
              for m in errors.messages),
          "T_max above Defer Patches Above: errors %s" % errors.messages)
    check(servermanager.Fetch(recon).GetNumberOfCells() == 0,
          "T_max above Defer Patches Above: the output is not empty")
    recon.MaximumThreshold = ratio
    # A stored simplification whose pairs claim a ratio at or above T (an edited
    # file): the replays could not be exact, so the reconstruction refuses it.
    edited = servermanager.Fetch(simp)
    for b in range(edited.GetNumberOfBlocks()):
        if edited.GetMetaData(b).Get(edited.NAME()) == "PersistencePairs":
            pairs = edited.GetBlock(b).GetCellData().GetArray("Ratio")
            check(pairs.GetNumberOfTuples() > 0, "no cancelled pair to edit")
            pairs.SetValue(0, ratio)
    producer = servermanager.sources.PVTrivialProducer()
    producer.GetClientSideObject().SetOutput(edited)
    again = FlowReconstruction(Input=producer, MaximumThreshold=ratio)  # noqa: F821
    errors = Errors(again)
    again.UpdatePipeline()
    check(any("deferral ratio" in m for m in errors.messages),
          "a stored pair at the deferral ratio: errors %s" % errors.messages)


def edited_perturbation(lazy):
    """A stored deferred complex whose perturbation record was edited (attempt 1:
    no perturbation, on a cloud that needed one): completing it for the diagram
    recomputes the triangulation with that record, meets the ties the build
    perturbed away, and must say the file does not fit its points in one line,
    from the CLI and from the Persistence Diagram filter."""
    fc = servermanager.Fetch(lazy[0])
    attempts = fc.GetBlock(0).GetFieldData().GetArray("PerturbationAttempts")
    check(attempts is not None and attempts.GetValue(0) > 1,
          "lattice torus: the build did not perturb (attempts %s)" %
          (attempts.GetValue(0) if attempts is not None else None))
    for fd in (fc.GetFieldData(), fc.GetBlock(0).GetFieldData()):
        fd.GetArray("PerturbationAttempts").SetValue(0, 1)
    expected = "does not belong to its points"
    if CLI:
        from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter
        vtm = os.path.join(WORK, "lattice_edited.vtm")
        writer = vtkXMLMultiBlockDataWriter()
        writer.SetInputData(fc)
        writer.SetFileName(vtm)
        check(writer.Write() == 1, "could not write %s" % vtm)
        run = subprocess.run([CLI, "diagram", vtm, "-o", vtm + ".csv", "--quiet"],
                             capture_output=True, text=True)
        lines = run.stderr.strip().splitlines()
        check(run.returncode == 1 and len(lines) == 1 and expected in lines[0],
              "flowrecon diagram of an edited perturbation record: exit %d, stderr %r" % (
                  run.returncode, run.stderr))
    producer = servermanager.sources.PVTrivialProducer()
    producer.GetClientSideObject().SetOutput(fc)
    diagram = PersistenceDiagram(Input=producer)  # noqa: F821
    errors = Errors(diagram)
    diagram.UpdatePipeline()
    check(any(expected in m for m in errors.messages),
          "Persistence Diagram of an edited perturbation record: errors %s" % errors.messages)


def main():
    os.makedirs(WORK, exist_ok=True)
    # Uniform in the angles (denser inside the hole): many patches across the tube.
    rng = np.random.default_rng(11)
    u, v = rng.uniform(0, 2 * np.pi, (2, 3000))
    torus = np.c_[(1 + .35 * np.cos(v)) * np.cos(u), (1 + .35 * np.cos(v)) * np.sin(u),
                  .35 * np.sin(v)]
    _, lazy = compare_cloud("torus", torus, 2.0, 300)
    # A noisy, non-manifold mix: a noisy torus with a flat flange along its outer
    # equator (a fin where three sheets meet).
    u, v = rng.uniform(0, 2 * np.pi, (2, 2500))
    ring = np.c_[(1 + .35 * np.cos(v)) * np.cos(u), (1 + .35 * np.cos(v)) * np.sin(u),
                 .35 * np.sin(v)]
    r, w = np.sqrt(rng.uniform(1.35 ** 2, 1.7 ** 2, 1200)), rng.uniform(0, 2 * np.pi, 1200)
    flange = np.c_[r * np.cos(w), r * np.sin(w), np.zeros(1200)]
    mix = np.r_[ring, flange] + rng.normal(0, 0.003, (3700, 3))
    compare_cloud("noisy torus with a flange", mix, 2.0, 100)
    # A torus beside a lattice block (cospherical points), so the build perturbs;
    # deferral must still equal the eager pipeline.
    block = np.stack(np.meshgrid(*[np.arange(3) * 0.04] * 3), -1).reshape(-1, 3) + (1.37, -.04, -.04)
    _, lattice_lazy = compare_cloud("torus beside a lattice", np.r_[torus[:1500], block], 2.0, 100)
    edited_perturbation(lattice_lazy)
    wrong_settings(lazy)
    finish()


main()
