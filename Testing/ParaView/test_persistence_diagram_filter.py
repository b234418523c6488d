#!/usr/bin/env python3
"""The Persistence Diagram filter in pvpython.

For a few clouds, Flow Complex -> Persistence Diagram in ParaView must give
- on port 0, the grid `flowrecon diagram -o PD.vtu` writes, cell by cell (points
  and the TTK arrays), with pairs equal to `flowrecon diagram -o PD.csv` row by
  row, then the line death = t_p x birth (PairType -2), and pairs equal to
  GUDHI's alpha-complex persistence (square roots of its filtration values);
- on port 1, the persistence curve: at each Ratio x the number of finite pairs
  of each dimension with death/birth >= x counted from the CSV, non-increasing,
  all finite pairs at x = 1, and the column t_p NaN except a vertical mark
  (0, then the most pairs not born at 0 in one dimension) at Ratio = t_p.
Changing t_p moves only the marks (none below 1). The proxy prefers a render
view for port 0 and a line chart for port 1. Bad input (a point cloud, a block
that is not a flow complex, a simplified complex) gives a VTK error and empty
output, never a crash; an empty multiblock gives empty outputs and no error.

Run: pvpython test_persistence_diagram_filter.py PLUGIN FLOWRECON WORKDIR
with PYTHONPATH holding the build's `flowrecon` package, Testing/Python and Apps/Scripts.
"""

import math
import os
import subprocess
import sys

import generate_clouds as gen
import numpy as np
from paraview import servermanager
from paraview import simple
from vtkmodules.util.numpy_support import vtk_to_numpy

from flowrecon_testing import clouds as cl
from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing.checks import Checker

PLUGIN, FLOWRECON, WORK = sys.argv[1:4]
CHK = Checker("test_persistence_diagram_filter")
TTK = ("PairIdentifier", "PairType", "Persistence", "Birth", "IsFinite")
DROP = 1e-9
TOL = 1e-7
TP = 1.1


def cli_pairs(xyz):
    csv = xyz[:-4] + "_pd.csv"
    vtu = xyz[:-4] + "_pd.vtu"
    for out in (csv, vtu):
        p = subprocess.run([FLOWRECON, "diagram", xyz, "-o", out, "--quiet"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError("flowrecon diagram -o %s: %s" % (out, p.stderr))
    with open(csv) as f:
        f.readline()
        rows = [line.strip().split(",") for line in f if line.strip()]
    pairs = [(int(d), float(b), math.inf if e == "inf" else float(e)) for d, b, e in rows]
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
    r = vtkXMLUnstructuredGridReader()
    r.SetFileName(vtu)
    r.Update()
    return pairs, r.GetOutput()


def cells(grid):
    """[(cell data tuple, first point, second point)] per cell."""
    pts = vtk_to_numpy(grid.GetPoints().GetData()) if grid.GetNumberOfPoints() else None
    a = {n: vtk_to_numpy(grid.GetCellData().GetArray(n)) for n in TTK}
    out = []
    for c in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(c)
        p = [tuple(pts[cell.GetPointId(k)]) for k in range(cell.GetNumberOfPoints())]
        out.append((tuple(a[n][c].item() for n in TTK), p))
    return out


def columns(table):
    return {table.GetColumnName(k): vtk_to_numpy(table.GetColumn(k)).astype(float)
            for k in range(table.GetNumberOfColumns())}


def expected_curve(pairs, xs):
    """Counts per dimension of the finite pairs with death/birth >= x (birth 0: always)."""
    finite = [(d, b, e) for d, b, e in pairs if not math.isinf(e)]
    ratio = [(d, math.inf if b == 0 else e / b) for d, b, e in finite]
    return {d: np.array([sum(1 for k, r in ratio if k == d and r >= x) for x in xs])
            for d in range(3)}


def check_curve(name, pairs, table, tp):
    col = columns(table)
    for c in ("Ratio", "Pairs", "PairsH0", "PairsH1", "PairsH2", "t_p"):
        if not CHK.check(c in col, "%s: curve has no column %s (%s)" % (name, c, sorted(col))):
            return
    x = col["Ratio"]
    finite = sum(1 for _, _, e in pairs if not math.isinf(e))
    CHK.check(len(x) > 1 and x[0] == 1.0 and np.all(np.diff(x) >= 0),
              "%s: Ratio does not start at 1 and increase: %s" % (name, x[:10]))
    CHK.check(np.all(np.diff(col["Pairs"]) <= 0),
              "%s: the curve increases somewhere" % name)
    CHK.check(col["Pairs"][0] == finite, "%s: curve at x = 1 is %d, %d finite pairs"
              % (name, col["Pairs"][0], finite))
    want = expected_curve(pairs, x)
    for d in range(3):
        CHK.check(np.array_equal(col["PairsH%d" % d], want[d]),
                  "%s: PairsH%d differs from the counts of the CSV" % (name, d))
    CHK.check(np.array_equal(col["Pairs"], sum(want[d] for d in range(3))),
              "%s: Pairs is not the sum over dimensions" % name)
    ratios = {e / b for d, b, e in pairs if not math.isinf(e) and b > 0 and e / b > 1}
    marks = [tp] if tp >= 1 else []
    CHK.check(set(x.tolist()) == ratios | {1.0} | set(marks),
              "%s: the rows are not 1, the distinct ratios and t_p" % name)
    CHK.check(len(x) == len(ratios | {1.0} | set(marks)) + len(marks),
              "%s: %d rows, expected one per x and two at t_p" % (name, len(x)))
    mark = col["t_p"]
    shown = ~np.isnan(mark)
    height = max(sum(1 for k, b, e in pairs if k == d and not math.isinf(e) and b > 0)
                 for d in range(3))
    if tp >= 1:
        CHK.check(np.all(x[shown] == tp) and mark[shown].tolist() == [0.0, float(height)],
                  "%s: column t_p is not the mark (0, %d) at Ratio %g: %s at %s"
                  % (name, height, tp, mark[shown], x[shown]))
    else:
        CHK.check(not np.any(shown), "%s: t_p %g < 1 still marked" % (name, tp))
    fd = table.GetFieldData().GetArray("PersistenceThreshold")
    CHK.check(fd is not None and fd.GetValue(0) == tp,
              "%s: curve field data PersistenceThreshold is not %g" % (name, tp))
    # The chart's copy for log axes: the same curves, zeros as gaps, the mark from 1.
    field = table.GetFieldData()
    for c in ("Ratio", "Pairs", "PairsH0", "PairsH1", "PairsH2", "t_p"):
        a = field.GetArray(c)
        if not CHK.check(a is not None and a.GetNumberOfTuples() == len(x),
                         "%s: the curve's field data has no series %s of %d values" % (name, c, len(x))):
            continue
        got = np.array([a.GetValue(k) for k in range(len(x))])
        want = col[c].astype(float)
        if c == "t_p":
            want = np.where(want == 0, 1.0, want)
        elif c != "Ratio":
            want = np.where(want == 0, np.nan, want)
        CHK.check(np.array_equal(got, want, equal_nan=True) and not np.any(got[~np.isnan(got)] <= 0),
                  "%s: the field data series %s is not the column with its zeros as gaps" % (name, c))


def check_chart_series(name, pairs, grid, tp):
    """The diagram's chart series (field data) against the CLI's pairs: every pair
    a point (birth, death) of the series of its dimension, essential ones at the
    top; the diagonal y = x; the t_p line y = t_p x up to the top."""
    field = grid.GetFieldData()
    series = {}
    for c in ("Birth", "H0", "H1", "H2", "Diagonal", "t_p"):
        a = field.GetArray(c)
        if not CHK.check(a is not None, "%s: the diagram's field data has no series %s" % (name, c)):
            return
        series[c] = np.array([a.GetValue(k) for k in range(a.GetNumberOfTuples())])
    x = series["Birth"]
    top = max(b if math.isinf(e) else e for _, b, e in pairs)
    CHK.check(np.all(np.diff(x) >= 0) and x[0] == 0 and x[-1] == top,
              "%s: Birth does not increase from 0 to the top %g" % (name, top))
    points = sorted((d, b, top if math.isinf(e) else e) for d, b, e in pairs)
    drawn = sorted((d, x[k], series["H%d" % d][k]) for d in range(3)
                   for k in np.nonzero(~np.isnan(series["H%d" % d]))[0])
    CHK.check(drawn == points, "%s: the series H0-H2 hold %d points, the CLI %d pairs (or differ)"
              % (name, len(drawn), len(points)))
    CHK.check(np.array_equal(series["Diagonal"], x), "%s: Diagonal is not y = x" % name)
    line = series["t_p"]
    if tp >= 1:
        on = ~np.isnan(line)
        CHK.check(np.allclose(line[on], tp * x[on], rtol=1e-12) and
                  abs(line[on].max() - top) <= 1e-12 * top and np.all(x[~on] * tp > top),
                  "%s: t_p is not death = %g x birth up to the top" % (name, tp))
    else:
        CHK.check(np.all(np.isnan(line)), "%s: t_p %g < 1 still drew a line" % (name, tp))


def check_diagram(name, points, pairs, cli_grid, grid, tp):
    got, ref = cells(grid), cells(cli_grid)
    n = len(pairs)
    CHK.check(len(ref) == n + 1, "%s: the CLI's .vtu has %d cells for %d pairs"
              % (name, len(ref), n))
    first = next((i for i, (g, r) in enumerate(zip(got, ref)) if g != r), None)
    CHK.check(len(got) > n and first is None,
              "%s: the first %d cells differ from the CLI's .vtu" % (name, n + 1),
              None if first is None else "cell %d: %s, CLI %s" % (first, got[first], ref[first]))
    for i, (d, b, e) in enumerate(pairs):
        (ident, ptype, _, birth, finite), (_, end) = got[i]
        ok = (ident == i and ptype == d and birth == b and finite == (0 if math.isinf(e) else 1)
              and (math.isinf(e) or end[1] == e))
        if not CHK.check(ok, "%s: cell %d is %s, CSV row (%d, %r, %r)"
                         % (name, i, got[i], d, b, e)):
            break
    top = ref[-1][1][1][1] if ref else 0.0  # the diagonal's end
    if tp >= 1:
        CHK.check(len(got) == n + 2, "%s: %d cells, expected the pairs, the diagonal and the t_p "
                  "line" % (name, len(got)))
        if len(got) == n + 2:
            (ident, ptype, *_), (start, end) = got[-1]
            CHK.check(ident == -2 and ptype == -2 and start == (0.0, 0.0, 0.0) and end[1] == top
                      and abs(end[0] * tp - top) <= 1e-12 * top,
                      "%s: last cell is not death = %g x birth up to %g: %s"
                      % (name, tp, top, got[-1]))
    else:
        CHK.check(len(got) == n + 1, "%s: t_p %g < 1 still drew a line" % (name, tp))
    fd = grid.GetFieldData().GetArray("PersistenceThreshold")
    CHK.check(fd is not None and fd.GetValue(0) == tp,
              "%s: diagram field data PersistenceThreshold is not %g" % (name, tp))
    check_chart_series(name, pairs, grid, tp)
    # The independent oracle.
    mine = [(v[1], v[3], end[1] if v[4] else math.inf) for v, (_, end) in got if v[0] >= 0]
    diam = fio.diameter(points)
    ok, msg = fio.compare_diagrams(fio.significant(mine, DROP * diam),
                                   fio.significant(fio.gudhi_alpha_diagram(points), DROP * diam),
                                   TOL * diam, ("Persistence Diagram", "GUDHI alpha"))
    CHK.check(ok, "%s: diagram differs from GUDHI's alpha persistence" % name, msg)


def check_cloud(name, points, manifolds):
    xyz = os.path.join(WORK, name + ".xyz")
    cl.write_xyz(xyz, points)
    pairs, cli_grid = cli_pairs(xyz)
    reader = simple.OpenDataFile(xyz)
    fc = FlowComplex(Input=reader, ComputeStableManifolds=manifolds)  # noqa: F821
    pd = PersistenceDiagram(Input=fc)  # noqa: F821
    CHK.check(pd.GetXMLLabel() == "Persistence Diagram" and float(pd.PersistenceThreshold) == TP,
              "%s: proxy label %r or default t_p %r"
              % (name, pd.GetXMLLabel(), pd.PersistenceThreshold))
    pd.UpdatePipeline()
    check_diagram(name, points, pairs, cli_grid, servermanager.Fetch(pd, idx=0), TP)
    check_curve(name, pairs, servermanager.Fetch(pd, idx=1), TP)
    print("%s: %d pairs (%d finite), %d curve rows" % (
        name, len(pairs), sum(1 for p in pairs if not math.isinf(p[2])),
        servermanager.Fetch(pd, idx=1).GetNumberOfRows()), flush=True)
    for tp in (1.5, 0.5):
        pd.PersistenceThreshold = tp
        pd.UpdatePipeline()
        check_diagram("%s t_p %g" % (name, tp), points, pairs, cli_grid,
                      servermanager.Fetch(pd, idx=0), tp)
        check_curve("%s t_p %g" % (name, tp), pairs, servermanager.Fetch(pd, idx=1), tp)
    simple.Delete(pd)
    simple.Delete(fc)
    simple.Delete(reader)


def check_views():
    from paraview.modules.vtkRemotingViews import vtkSMParaViewPipelineControllerWithRendering
    src = simple.PointSource(NumberOfPoints=30)
    pd = PersistenceDiagram(Input=FlowComplex(Input=src))  # noqa: F821
    controller = vtkSMParaViewPipelineControllerWithRendering()
    views = [controller.GetPreferredViewType(pd.SMProxy, port) for port in (0, 1)]
    CHK.check(views == ["FlowReconDiagramChartView", "FlowReconPersistenceChartView"],
              "preferred views of ports 0 and 1 are %s" % views)
    names = [pd.SMProxy.GetOutputPortName(k) for k in range(pd.SMProxy.GetNumberOfOutputPorts())]
    CHK.check(names == ["Diagram", "Persistence Curve"], "output ports are %s" % names)


class Errors:
    def __init__(self, algorithm):
        from vtkmodules.vtkCommonCore import vtkCommand
        self.messages = []
        for obj in (algorithm, algorithm.GetExecutive()):
            obj.AddObserver(vtkCommand.ErrorEvent, self.error)

    def error(self, obj, event, calldata=None):
        self.messages.append(str(calldata))

    error.CallDataType = "string0"


def check_bad_input():
    from flowrecon import vtkFlowComplex, vtkFlowComplexSimplification, vtkPersistenceDiagram
    from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet

    rng = np.random.default_rng(2)
    cloud = fio.make_polydata(rng.uniform(size=(40, 3)))
    fc = vtkFlowComplex()
    fc.SetInputData(cloud)
    simplified = vtkFlowComplexSimplification()
    simplified.SetInputConnection(fc.GetOutputPort())
    simplified.Update()
    stranger = vtkMultiBlockDataSet()
    stranger.SetNumberOfBlocks(1)
    stranger.SetBlock(0, cloud)
    stranger.GetMetaData(0).Set(vtkCompositeDataSet.NAME(), "CriticalPoints")
    cases = (("a point cloud", cloud, "vtkMultiBlockDataSet"),
             ("a multiblock that is not a flow complex", stranger, "not a flow complex"),
             ("a simplified complex", simplified.GetOutput(), "simplified"),
             ("an empty multiblock", vtkMultiBlockDataSet(), None))
    for what, data, error in cases:
        pd = vtkPersistenceDiagram()
        errors = Errors(pd)
        pd.SetInputData(data)
        pd.Update()
        diagram, curve = pd.GetOutputDataObject(0), pd.GetOutputDataObject(1)
        empty = diagram.GetNumberOfCells() == 0 and curve.GetNumberOfRows() == 0
        if error is None:
            CHK.check(not errors.messages and empty, "%s: errors %s or output not empty"
                      % (what, errors.messages))
        else:
            CHK.check(any(error in m for m in errors.messages) and empty,
                      "%s: no VTK error with '%s' (got %s) or output not empty"
                      % (what, error, errors.messages))
    # The same in ParaView: an error, not a crash.
    bad = PersistenceDiagram(Input=simple.PointSource(NumberOfPoints=20))  # noqa: F821
    bad.UpdatePipeline()
    CHK.check(bad.GetDataInformation(0).GetNumberOfCells() == 0,
              "a Point Source into Persistence Diagram gave cells")


def main():
    os.makedirs(WORK, exist_ok=True)
    simple.LoadPlugin(PLUGIN, remote=False, ns=globals())
    if not CHK.check("PersistenceDiagram" in globals(),
                     "LoadPlugin did not define PersistenceDiagram"):
        return CHK.finish()
    rng = np.random.default_rng(5)
    clouds = (("cube", rng.uniform(0.0, 1.0, (120, 3)), 1),
              ("shell", gen.sphere(150, rng) * rng.uniform(1.0, 1.05, (150, 1)), 0),
              ("torus", gen.torus(200, rng), 1))
    for name, points, manifolds in clouds:
        CHK.run(name, check_cloud, name, points, manifolds)
    CHK.run("views", check_views)
    CHK.run("bad input", check_bad_input)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
