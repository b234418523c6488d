"""Flow Reconstruction's Betti numbers read off the Hasse diagram, against GUDHI.

The filter takes the Betti numbers of every t_r from the Hasse diagram: handed
on by Flow Complex Simplification (field data ReconstructionBars, for an
automatic or a given t_p) or computed with its queue on an unsimplified input;
with them its compact output never draws the exact cells. The oracle is GUDHI:
a SimplexTree of the exact output's cells (Geometry exact, every step up to
T_max) filtered by their Threshold, whose persistence over Z/2 gives the Betti
numbers at any t. Checked, for each pipeline and cloud: every row of the
topology profile (port 3) at the middle and the end of its interval, the
BettiNumbers field data at t_r, the same profile and Betti numbers with the
compact geometry, the compact cells' own Betti numbers (GUDHI), the same exact
cells when they are drawn after the compact ones (the filter then reads the
input's cells late), and the same
profile when the Betti numbers come from the drawn cells instead (Simplification
without Compute Topology). Clouds: surfaces, a solid, a curve, a non-manifold
union, a sphere with a segment, an exact grid, a noisy sphere; deferred patches
(Defer Patches Above near T_max) on two of them.
"""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon import vtkFlowComplexSimplification, vtkFlowReconstruction
from flowrecon_testing import clouds as cl
from flowrecon_testing.checks import check, finish
from flowrecon_testing.flowcomplex_io import import_filter, make_polydata
from flowrecon_testing.oracles import betti_at, filtered_intervals, gudhi_betti

TMAX = 4.0
TR = 2.0


def clouds():
    return cl.topology_fixtures(np.random.default_rng(11), 500, 800, 600, 150, 350)


def profile(reconstruction):
    table = reconstruction.GetOutputDataObject(vtkFlowReconstruction.TOPOLOGY_PROFILE)
    cols = [vtk_to_numpy(table.GetColumnByName(n)) for n in ("Threshold", "b0", "b1", "b2")]
    return [(float(r[0]), tuple(int(v) for v in r[1:])) for r in zip(*cols)]


def betti_field(reconstruction):
    a = reconstruction.GetOutput().GetFieldData().GetArray("BettiNumbers")
    return tuple(int(a.GetValue(k)) for k in range(3)) if a else None


def grid_key(grid):
    """The cells, points and Threshold of a grid, for equality."""
    return (grid.GetNumberOfCells(), grid.GetNumberOfPoints(),
            vtk_to_numpy(grid.GetCells().GetConnectivityArray()).tobytes(),
            vtk_to_numpy(grid.GetPoints().GetData()).tobytes(),
            vtk_to_numpy(grid.GetCellData().GetArray("Threshold")).tobytes())


def pipeline(points, tp, defer, hasse=True):
    """(reconstruction, simplification or None) at t_p `tp` ("auto", a number,
    or None for no simplification filter), T_max 4, t_r 2, every step drawn."""
    fc = import_filter()()
    fc.SetInputData(make_polydata(points))
    fc.SetDeferPatchesAbove(defer)
    upstream = fc
    simplification = None
    if tp is not None:
        simplification = vtkFlowComplexSimplification()
        simplification.SetInputConnection(fc.GetOutputPort())
        simplification.SetMaximumThreshold(TMAX)
        if tp == "auto":
            simplification.AutomaticPersistenceThresholdOn()
        else:
            simplification.AutomaticPersistenceThresholdOff()
            simplification.SetPersistenceThreshold(tp)
            simplification.SetComputeTopology(hasse)
        upstream = simplification
    r = vtkFlowReconstruction()
    r.SetInputConnection(upstream.GetOutputPort())
    r.SetMaximumThreshold(TMAX)
    r.AutomaticReconstructionThresholdOff()
    r.SetReconstructionThreshold(TR)
    r.SetMaximumTopologyCells(-1)
    return r, simplification


checked = 0
for name, points in clouds().items():
    cases = [("auto", 5.0), (1.1, 5.0), (None, 5.0)]
    if name in ("torus", "noisy sphere"):
        cases += [("auto", TMAX), (None, TMAX)]
    for tp, defer in cases:
        label = "%s, t_p %s, deferral %g" % (name, tp, defer)
        r, simplification = pipeline(points, tp, defer)
        if simplification is not None:
            simplification.Update()
            check(simplification.GetOutput().GetFieldData().GetArray("ReconstructionBars")
                  is not None, label + ": the simplification hands on no bars")
        r.SetGeometryToExact()
        r.EveryStepOn()  # the whole family below T_max, for GUDHI
        r.Update()
        intervals = filtered_intervals(r.GetOutput())
        r.EveryStepOff()
        r.Update()
        rows = profile(r)
        check(len(rows) > 0, label + ": no topology profile")
        ends = [t for t, _ in rows[1:]] + [TMAX]
        for (start, betti), end in zip(rows, ends):
            for t in [x for x in ((start + end) / 2, end) if start < x <= end]:
                checked += 1
                check(betti_at(intervals, t) == betti,
                      "%s: profile row from %.6g says %s, GUDHI %s at %.9g"
                      % (label, start, betti, betti_at(intervals, t), t))
        exact = betti_field(r)
        check(exact == betti_at(intervals, TR),
              "%s: BettiNumbers %s, GUDHI %s at t_r 2" % (label, exact, betti_at(intervals, TR)))
        r.SetGeometryToCompact()
        r.Update()
        check(profile(r) == rows, label + ": the compact geometry changes the profile")
        check(betti_field(r) == exact, label + ": the compact geometry changes BettiNumbers")
        check(gudhi_betti(r.GetOutput()) == exact,
              "%s: the compact cells' Betti numbers %s, the reconstruction's %s"
              % (label, gudhi_betti(r.GetOutput()), exact))
        # Compact first, exact next: the input's cells are read only then,
        # and the exact output is the one drawn above.
        later, _ = pipeline(points, tp, defer)
        later.SetGeometryToCompact()
        later.Update()
        later.SetGeometryToExact()
        later.EveryStepOn()
        later.Update()
        r.SetGeometryToExact()
        r.EveryStepOn()
        r.Update()
        check(grid_key(later.GetOutput()) == grid_key(r.GetOutput()),
              label + ": the exact cells drawn after the compact ones differ")
        if tp == 1.1:
            # The drawn cells' persistent homology, the filter's other way.
            cells, _ = pipeline(points, tp, defer, hasse=False)
            cells.SetGeometryToExact()
            cells.Update()
            check(profile(cells) == rows and betti_field(cells) == exact,
                  label + ": the drawn cells give another topology")
        print("%s: %d rows, Betti numbers %s at t_r 2" % (label, len(rows), exact))
check(checked > 100, "only %d profile points checked" % checked)


def corrupted_bars(points, mutate):
    """The reconstruction of the simplification's output whose ReconstructionBars
    were changed by `mutate` (a vtkDoubleArray, in place), with t_p 1.1."""
    from vtkmodules.vtkCommonCore import vtkDoubleArray
    from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
    _, simplification = pipeline(points, 1.1, 5.0)
    simplification.Update()
    data = vtkMultiBlockDataSet()
    data.ShallowCopy(simplification.GetOutput())
    bars = vtkDoubleArray()
    bars.DeepCopy(data.GetFieldData().GetArray("ReconstructionBars"))
    mutate(bars)
    data.GetFieldData().RemoveArray("ReconstructionBars")
    data.GetFieldData().AddArray(bars)
    r = vtkFlowReconstruction()
    r.SetInputData(data)
    r.SetMaximumThreshold(TMAX)
    r.AutomaticReconstructionThresholdOff()
    r.SetReconstructionThreshold(TR)
    r.SetMaximumTopologyCells(-1)
    r.GlobalWarningDisplayOff()  # the warning is expected
    r.Update()
    return r


# Bars that do not fit the complex are not trusted: the filter falls back to the
# drawn cells and gives the same topology as with sound bars.
points = clouds()["torus"]
sound, _ = pipeline(points, 1.1, 5.0)
sound.Update()
for what, mutate in (
        ("a node id beyond the complex", lambda a: a.SetComponent(0, 3, 1e12)),
        ("a death before its birth", lambda a: a.SetComponent(0, 2, a.GetComponent(0, 1) - 1)),
        ("a dimension 3", lambda a: a.SetComponent(0, 0, 3)),
        ("four components", lambda a: a.SetNumberOfComponents(4))):
    r = corrupted_bars(points, mutate)
    check(profile(r) == profile(sound) and betti_field(r) == betti_field(sound),
          "bars with %s: the topology %s, not the drawn cells' %s"
          % (what, betti_field(r), betti_field(sound)))
print("%d profile points equal GUDHI's" % checked)
finish()
