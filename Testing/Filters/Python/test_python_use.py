#!/usr/bin/env python3
"""Plain VTK scripting with the `flowrecon` package: vtkFlowComplex in a pipeline
after a vtkPointSource, and its output checked against the data contract of
docs/data-contract.md and Filters/vtkFlowComplex.h (block names and order, data types,
array names and types, the maximum at infinity, cell kinds per index, input ids
of the samples, options, vtkTable input, unstable manifolds vs 2->3 arcs).

Run: PYTHONPATH=<build>/lib/python3/dist-packages:Testing/Python:Apps/Scripts /usr/bin/python3 test_python_use.py
"""

import sys

import numpy as np

import flowrecon  # the package under test
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkMath
from vtkmodules.vtkCommonDataModel import (
    VTK_LINE, VTK_POLY_LINE, VTK_TETRA, VTK_TRIANGLE, VTK_VERTEX,
    vtkMultiBlockDataSet, vtkTable)
from vtkmodules.vtkFiltersSources import vtkPointSource

from flowrecon_testing import flowcomplex_io as fio
from flowrecon_testing.checks import Checker

CHK = Checker("test_python_use")

EXPECTED_BLOCKS = [
    ("CriticalPoints", "vtkPolyData", {"point": ["NodeId", "Index", "CriticalValue"]}),
    ("HasseDiagram", "vtkPolyData", {"cell": ["Multiplicity", "Ratio", "LowerNodeId",
                                              "UpperNodeId"], "point": ["NodeId"]}),
    ("StableManifolds", "vtkUnstructuredGrid", {"cell": ["NodeId", "Index", "CriticalValue"],
                                                "point": ["vtkOriginalPointIds"]}),
    ("UnstableManifolds", "vtkPolyData", {"cell": ["NodeId", "TargetNodeId"]}),
    ("GabrielEdges", "vtkPolyData", {"cell": ["NodeId", "Index", "CriticalValue"]}),
]
INTEGER_ARRAYS = {"NodeId", "Index", "Multiplicity", "LowerNodeId", "UpperNodeId", "TargetNodeId",
                  "vtkOriginalPointIds"}
# VTK_CHAR .. VTK_UNSIGNED_LONG, VTK_ID_TYPE, VTK_SIGNED_CHAR, VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG
INTEGER_TYPES = {2, 3, 4, 5, 6, 7, 8, 9, 12, 15, 16, 17}
CELL_OF_INDEX = {0: VTK_VERTEX, 1: VTK_LINE, 2: VTK_TRIANGLE, 3: VTK_TETRA}


def point_source(n=300, seed=5):
    vtkMath.RandomSeed(seed)
    src = vtkPointSource()
    src.SetNumberOfPoints(n)
    src.SetRadius(1.0)
    src.SetCenter(0.5, -0.25, 2.0)
    src.SetDistributionToShell()
    src.SetOutputPointsPrecision(1)  # double
    src.Update()
    return src


def check_contract():
    CHK.check(hasattr(flowrecon, "vtkFlowComplex"), "flowrecon has no vtkFlowComplex")
    src = point_source()
    flt = flowrecon.vtkFlowComplex()
    flt.SetInputConnection(src.GetOutputPort())
    flt.Update()
    out = flt.GetOutput()
    CHK.check(out is not None and out.IsA("vtkMultiBlockDataSet"),
              "output is %s, expected vtkMultiBlockDataSet" % (out and out.GetClassName()))
    names = fio.block_names(out)
    CHK.check(names == [b[0] for b in EXPECTED_BLOCKS],
              "block names %r, expected %r in this order" % (names, [b[0] for b in EXPECTED_BLOCKS]))
    for i, (name, _, _) in enumerate(EXPECTED_BLOCKS):
        CHK.check(flowrecon.vtkFlowComplex.BlockName(i) == name,
                  "vtkFlowComplex.BlockName(%d) = %r, expected %r" % (
                      i, flowrecon.vtkFlowComplex.BlockName(i), name))
    for name, cls, arrays in EXPECTED_BLOCKS:
        b = fio.get_block(out, name, required=False)
        CHK.check(b is not None and b.GetClassName() == cls, "block %s is %s, expected %s" % (
            name, b.GetClassName() if b is not None else None, cls))
        if b is None:
            continue
        for where, wanted in arrays.items():
            data = b.GetPointData() if where == "point" else b.GetCellData()
            have = [data.GetArrayName(k) for k in range(data.GetNumberOfArrays())]
            for a in wanted:
                arr = data.GetArray(a)
                CHK.check(arr is not None, "%s %s data has no array %r (has %r)" % (
                    name, where, a, have))
                if arr is None:
                    continue
                CHK.check(arr.GetNumberOfTuples() == (b.GetNumberOfPoints() if where == "point"
                                                      else b.GetNumberOfCells()),
                          "%s %s array %s has %d tuples" % (name, where, a, arr.GetNumberOfTuples()))
                if a in INTEGER_ARRAYS:
                    CHK.check(arr.GetDataType() in INTEGER_TYPES,
                              "%s array %s is %s, expected an integer type"
                              % (name, a, arr.GetClassName()))
                if a in ("CriticalValue", "Ratio"):
                    CHK.check(arr.GetDataType() in (10, 11),  # VTK_FLOAT, VTK_DOUBLE
                              "%s array %s is %s, expected floating point" % (
                                  name, a, arr.GetClassName()))

    res = fio.FlowComplexResult(out)
    print("  %s" % res.summary())
    P = np.array([src.GetOutput().GetPoint(i) for i in range(src.GetOutput().GetNumberOfPoints())])

    # the maximum at infinity: one node, +inf, index 3, the last point, no vertex cell
    inf_rows = np.nonzero(~res.finite)[0]
    CHK.check(len(inf_rows) == 1 and inf_rows[0] == len(res.value) - 1 and
              np.isposinf(res.value[inf_rows[0]]) and res.index[inf_rows[0]] == 3,
              "the maximum at infinity must be the last CriticalPoints point with value +inf and "
              "Index 3 (rows with non-finite values: %s)" % inf_rows.tolist())
    cp = fio.get_block(out, "CriticalPoints")
    CHK.check(cp.GetNumberOfVerts() == int(res.finite.sum()),
              "CriticalPoints has %d vertex cells for %d finite nodes (infinity must not be drawn)"
              % (cp.GetNumberOfVerts(), int(res.finite.sum())))
    CHK.check(np.all(np.isfinite(res.loc)), "a CriticalPoints coordinate is not finite")
    CHK.check(res.counts()[0] == len(P), "%d index-0 nodes for %d input points" % (
        res.counts()[0], len(P)))

    # StableManifolds: cell kind per index, input ids of samples, conforming points
    sm = res.sm
    types, cindex = res.sm_cell_types, res.sm_cell_index
    for k, t in CELL_OF_INDEX.items():
        wrong = np.sum((cindex == k) & (types != t))
        CHK.check(wrong == 0, "StableManifolds: %d Index-%d cells are not of type %d" % (wrong, k, t))
    CHK.check(np.sum(cindex == 0) == len(P) and np.sum(cindex == 1) == res.counts()[1] and
              len(np.unique(res.tri_nodes)) == res.counts()[2],
              "StableManifolds: %d vertices, %d Gabriel edges, patches of %d nodes; counts %s" % (
                  np.sum(cindex == 0), np.sum(cindex == 1), len(np.unique(res.tri_nodes)),
                  res.counts()))
    orig = res.sm_original_ids
    xyz = res.sm_points
    sample = orig >= 0
    CHK.check(np.array_equal(np.sort(orig[sample]), np.arange(len(P))),
              "vtkOriginalPointIds of the sample points are not the input ids 0..n-1")
    if np.any(sample):
        err = float(np.abs(xyz[sample] - P[orig[sample]]).max())
        CHK.check(err == 0.0, "sample points moved (max %.3g) in StableManifolds" % err)
    CHK.check(np.all(orig[~sample] == -1), "constructed points must have vtkOriginalPointIds -1")
    uniq = len(np.unique(xyz, axis=0))
    CHK.check(uniq == len(xyz), "StableManifolds is not conforming: %d points but %d distinct "
              "positions (patches must share point ids along shared boundaries)" % (len(xyz), uniq))
    # StableManifolds CriticalValue / Index agree with the node of each cell
    cnode = fio.array(sm.GetCellData(), "NodeId").astype(np.int64)
    cval = fio.array(sm.GetCellData(), "CriticalValue")
    rows = np.array([res.row.get(int(x), -1) for x in cnode])
    CHK.check(np.all(rows >= 0), "StableManifolds cells with unknown NodeId")
    if np.all(rows >= 0):
        CHK.check(np.array_equal(res.index[rows], cindex) and np.array_equal(res.value[rows], cval),
                  "StableManifolds Index/CriticalValue disagree with the node of the cell")

    # GabrielEdges: one line per index-1 node, between the two input points of
    # its Gabriel edge (the input coordinates), Index 1, CriticalValue half the
    # edge's length (the distance function at its midpoint).
    ge = fio.get_block(out, "GabrielEdges")
    gnode = fio.array(ge.GetCellData(), "NodeId").astype(np.int64)
    gval = fio.array(ge.GetCellData(), "CriticalValue")
    gindex = fio.array(ge.GetCellData(), "Index")
    ends = np.array([[ge.GetPoint(ge.GetCell(c).GetPointId(k)) for k in (0, 1)]
                     for c in range(ge.GetNumberOfCells())]).reshape(-1, 2, 3)
    CHK.check(ge.GetNumberOfLines() == ge.GetNumberOfCells() == res.counts()[1] and
              np.all(gindex == 1),
              "GabrielEdges: %d cells (%d lines) for %d index-1 nodes" % (
                  ge.GetNumberOfCells(), ge.GetNumberOfLines(), res.counts()[1]))
    grows = np.array([res.row.get(int(x), -1) for x in gnode])
    CHK.check(len(grows) == 0 or (np.all(grows >= 0) and np.all(res.index[grows] == 1) and
                                  len(np.unique(gnode)) == len(gnode)),
              "GabrielEdges: NodeIds that are not the index-1 nodes, once each")
    on_input = [bool(np.any(np.all(P == e, axis=1))) for e in ends.reshape(-1, 3)]
    CHK.check(all(on_input), "GabrielEdges: %d line ends are not input points" % (
        len(on_input) - sum(on_input)))
    half = 0.5 * np.linalg.norm(ends[:, 0] - ends[:, 1], axis=1)
    CHK.check(np.allclose(gval, half, rtol=1e-12, atol=0),
              "GabrielEdges: CriticalValue is not half the edge's length (max error %.3g)" % (
                  float(np.abs(gval - half).max()) if len(half) else 0.0))
    if np.all(grows >= 0):
        CHK.check(np.array_equal(res.value[grows], gval),
                  "GabrielEdges: CriticalValue disagrees with the node's")

    # Ratio = V(upper)/V(lower)
    lo = np.array([res.row[int(x)] for x in res.lower])
    up = np.array([res.row[int(x)] for x in res.upper])
    with np.errstate(divide="ignore", invalid="ignore"):
        expect = res.value[up] / res.value[lo]
        good = (res.ratio == expect) | (np.abs(res.ratio - expect) <= 1e-12 * np.abs(expect))
    CHK.check(good.all(), "Ratio != V(upper)/V(lower) on %d arcs, e.g. %s" % (
        int((~good).sum()), list(zip(res.ratio[~good], expect[~good]))[:4]))

    # UnstableManifolds: two polylines per index-2 node, targets = its 2->3 arcs
    um = fio.get_block(out, "UnstableManifolds")
    utypes, uconn = fio.cells_of(um)
    unode = fio.array(um.GetCellData(), "NodeId").astype(np.int64)
    utarget = fio.array(um.GetCellData(), "TargetNodeId").astype(np.int64)
    upts = fio.points_of(um)
    CHK.check(np.all((utypes == VTK_POLY_LINE) | (utypes == VTK_LINE)),
              "UnstableManifolds cells are not polylines: types %s" % sorted(set(utypes.tolist())))
    ups = res.upper_neighbours()
    bad = []
    for r in res.nodes_of_index(2):
        nid = int(res.node_id[r])
        got = sorted(int(t) for t in utarget[unode == nid])
        want = sorted(u for u, m in ups.get(nid, []) for _ in range(m))
        if got != want:
            bad.append((nid, got, want))
        for ci in np.nonzero(unode == nid)[0]:
            start = upts[uconn[ci][0]]
            if np.linalg.norm(start - res.loc[r]) > 1e-9:
                bad.append((nid, "polyline starts at %s, node at %s" % (start, res.loc[r])))
    CHK.check(not bad, "UnstableManifolds disagree with the 2->3 arcs for %d nodes: %s" % (
        len(bad), bad[:4]))

    # field data report
    CHK.check(res.report_value("PerturbationAttempts") == 1,
              "field data: PerturbationAttempts = %r (report %s)" % (
                  res.report_value("PerturbationAttempts"), res.report))
    return src, res


def arcs_of(res):
    return sorted(zip(res.lower.tolist(), res.upper.tolist(), res.mult.tolist()))


def check_options(src, full):
    flt = flowrecon.vtkFlowComplex()
    flt.SetInputConnection(src.GetOutputPort())
    CHK.check(flt.GetComputeStableManifolds() and flt.GetComputeUnstableManifolds() and
              flt.GetPerturbationSeed() == 1, "defaults: ComputeStableManifolds %r "
              "ComputeUnstableManifolds %r PerturbationSeed %r" % (
                  flt.GetComputeStableManifolds(), flt.GetComputeUnstableManifolds(),
                  flt.GetPerturbationSeed()))
    flt.ComputeStableManifoldsOff()
    flt.ComputeUnstableManifoldsOff()
    flt.Update()
    mb = vtkMultiBlockDataSet()
    mb.ShallowCopy(flt.GetOutput())
    res = fio.FlowComplexResult(mb)
    CHK.check(arcs_of(res) == arcs_of(full) and res.counts() == full.counts(),
              "with both manifold options off the Hasse diagram changed")
    CHK.check(len(res.tri_nodes) == 0, "ComputeStableManifolds off but %d index-2 triangles" %
              len(res.tri_nodes))
    um = fio.get_block(mb, "UnstableManifolds")
    CHK.check(um.GetNumberOfCells() == 0, "ComputeUnstableManifolds off but %d polylines" %
              um.GetNumberOfCells())
    # back on: the pipeline re-executes
    flt.ComputeStableManifoldsOn()
    flt.ComputeUnstableManifoldsOn()
    flt.SetPerturbationSeed(7)
    flt.Update()
    res2 = fio.FlowComplexResult(flt.GetOutput())
    CHK.check(len(res2.tri_nodes) == len(full.tri_nodes) and arcs_of(res2) == arcs_of(full),
              "re-executing with manifolds on does not reproduce the first output")


def check_table_input(src, full):
    pd = src.GetOutput()
    P = np.array([pd.GetPoint(i) for i in range(pd.GetNumberOfPoints())])
    table = vtkTable()
    for k, name in enumerate("xyz"):
        col = numpy_to_vtk(np.ascontiguousarray(P[:, k]), deep=True)
        col.SetName(name)
        table.AddColumn(col)
    flt = flowrecon.vtkFlowComplex()
    flt.SetInputData(table)
    flt.Update()
    res = fio.FlowComplexResult(flt.GetOutput())
    CHK.check(res.counts() == full.counts() and arcs_of(res) == arcs_of(full),
              "vtkTable input (columns x, y, z) gives counts %s, vtkPolyData input %s" % (
                  res.counts(), full.counts()))


def main():
    CHK.section("contract of the output")
    try:
        src, full = check_contract()
    except Exception:
        import traceback
        CHK.check(False, "exception", traceback.format_exc())
        return CHK.finish()
    CHK.run("options", check_options, src, full)
    CHK.run("vtkTable input", check_table_input, src, full)
    return CHK.finish()


if __name__ == "__main__":
    sys.exit(main())
