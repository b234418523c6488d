"""Run vtkFlowComplex on a numpy point array and turn its output multiblock into
plain numpy / Python structures, following the data contract of
Filters/vtkFlowComplex.h and docs/data-contract.md; plus the Z/2 persistence of a
Hasse diagram and a tolerant comparison of persistence diagrams.

Nothing here decides what the right answer is: the tests take their expected
values from independent oracles (brute force, GUDHI, the reference document).

Needs the build's `flowrecon` package on PYTHONPATH (CTest puts it there).
"""

import hashlib
import math
import sys

import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import (
    VTK_LINE, VTK_TETRA, VTK_TRIANGLE, VTK_VERTEX, vtkCellArray, vtkCompositeDataSet,
    vtkMultiBlockDataSet, vtkPolyData)

BLOCK_NAMES = ("CriticalPoints", "HasseDiagram", "StableManifolds", "UnstableManifolds",
               "GabrielEdges")


def import_filter():
    """vtkFlowComplex from the `flowrecon` package, with a clear message if missing."""
    try:
        from flowrecon import vtkFlowComplex
    except ImportError as exc:  # pragma: no cover - environment problem
        sys.stderr.write(
            "cannot import flowrecon.vtkFlowComplex (%s); run with /usr/bin/python3 and "
            "PYTHONPATH=<build>/lib/python3/dist-packages\nsys.path=%s\n" % (exc, sys.path))
        raise
    return vtkFlowComplex


# --------------------------------------------------------------------------- input / run


def make_polydata(points):
    """vtkPolyData with double points and one vertex cell per point."""
    p = np.ascontiguousarray(np.asarray(points, dtype=np.float64).reshape(-1, 3))
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    pts.SetData(numpy_to_vtk(p, deep=True))
    verts = vtkCellArray()
    for i in range(len(p)):
        verts.InsertNextCell(1)
        verts.InsertCellPoint(i)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetVerts(verts)
    return pd


class _Messages:
    """Collects the error and warning events of an algorithm."""

    def __init__(self, algorithm):
        self.errors = []
        self.warnings = []
        algorithm.AddObserver(vtkCommand.ErrorEvent, self._error)
        algorithm.AddObserver(vtkCommand.WarningEvent, self._warning)
        executive = algorithm.GetExecutive()
        if executive is not None:
            executive.AddObserver(vtkCommand.ErrorEvent, self._error)

    def _error(self, obj, event, calldata=None):
        self.errors.append(str(calldata) if calldata is not None else event)

    def _warning(self, obj, event, calldata=None):
        self.warnings.append(str(calldata) if calldata is not None else event)

    _error.CallDataType = "string0"
    _warning.CallDataType = "string0"


def run_filter(points, **properties):
    """Runs vtkFlowComplex on an (n, 3) array. properties: e.g.
    ComputeStableManifolds=False, PerturbationSeed=3 (calls Set<Name>).
    Returns (output multiblock (a shallow copy), messages)."""
    vtkFlowComplex = import_filter()
    flt = vtkFlowComplex()
    for name, value in properties.items():
        getattr(flt, "Set" + name)(value)
    messages = _Messages(flt)
    flt.SetInputData(make_polydata(points))
    flt.Update()
    out = vtkMultiBlockDataSet()
    out.ShallowCopy(flt.GetOutput())
    return out, messages


def reconstruction_pipeline(points, tp, tr):
    """(flow complex, reconstruction) filters of the VTK pipeline vtkFlowComplex ->
    vtkFlowComplexSimplification -> vtkFlowReconstruction on an (n, 3) array at the
    given t_p and t_r (no automatic choice), updated."""
    from flowrecon import vtkFlowComplexSimplification, vtkFlowReconstruction
    fc = import_filter()()
    fc.SetInputData(make_polydata(points))
    simplification = vtkFlowComplexSimplification()
    simplification.SetInputConnection(fc.GetOutputPort())
    simplification.SetPersistenceThreshold(tp)
    simplification.AutomaticPersistenceThresholdOff()
    reconstruction = vtkFlowReconstruction()
    reconstruction.SetInputConnection(simplification.GetOutputPort())
    reconstruction.SetReconstructionThreshold(tr)
    reconstruction.AutomaticReconstructionThresholdOff()
    reconstruction.Update()
    return fc, reconstruction


# --------------------------------------------------------------------------- blocks


def block_names(mb):
    names = []
    for i in range(mb.GetNumberOfBlocks()):
        md = mb.GetMetaData(i) if mb.HasMetaData(i) else None
        names.append(md.Get(vtkCompositeDataSet.NAME()) if md is not None and
                     md.Has(vtkCompositeDataSet.NAME()) else None)
    return names


def get_block(mb, name, required=True):
    """The block named `name` (by the composite NAME() metadata, not by position)."""
    names = block_names(mb)
    if name in names:
        return mb.GetBlock(names.index(name))
    if required:
        raise KeyError("no block named %r in the output; blocks are %r" % (name, names))
    return None


def array(data, name, required=True):
    """A point/cell/field data array as numpy (copy), or None."""
    arr = data.GetAbstractArray(name)
    if arr is None:
        if required:
            names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays())]
            raise KeyError("no array %r; arrays are %r" % (name, names))
        return None
    if arr.IsA("vtkStringArray"):
        return [arr.GetValue(i) for i in range(arr.GetNumberOfValues())]
    return np.array(vtk_to_numpy(arr), copy=True)


def field_report(data_object):
    """Field data of a data object as {name: scalar | list | str}."""
    report = {}
    if data_object is None:
        return report
    fd = data_object.GetFieldData()
    if fd is None:
        return report
    for i in range(fd.GetNumberOfArrays()):
        arr = fd.GetAbstractArray(i)
        name = arr.GetName()
        if arr.IsA("vtkStringArray"):
            vals = [arr.GetValue(k) for k in range(arr.GetNumberOfValues())]
        else:
            vals = vtk_to_numpy(arr).ravel().tolist()
        report[name] = vals[0] if len(vals) == 1 else vals
    return report


def cells_of(ds):
    """(types, list of point-id tuples) of a vtkPolyData or vtkUnstructuredGrid."""
    n = ds.GetNumberOfCells()
    arrays = None
    if ds.IsA("vtkUnstructuredGrid") and ds.GetCells() is not None:
        arrays = (ds.GetCells(), np.array(vtk_to_numpy(ds.GetCellTypesArray()), dtype=int))
    elif ds.IsA("vtkPolyData"):
        parts = [(ds.GetVerts(), VTK_VERTEX), (ds.GetLines(), VTK_LINE), (ds.GetPolys(), None),
                 (ds.GetStrips(), None)]
        used = [(ca, t) for ca, t in parts if ca is not None and ca.GetNumberOfCells() > 0]
        if len(used) == 1 and used[0][1] is not None:
            ca, t = used[0]
            arrays = (ca, None)
        elif not used:
            return np.zeros(0, dtype=int), []
    if arrays is not None:
        ca, types = arrays
        off = np.array(vtk_to_numpy(ca.GetOffsetsArray()), dtype=np.int64)
        con = np.array(vtk_to_numpy(ca.GetConnectivityArray()), dtype=np.int64)
        conn = [tuple(con[off[i]:off[i + 1]].tolist()) for i in range(len(off) - 1)]
        if types is None:
            types = np.array([ds.GetCellType(i) for i in range(n)], dtype=int) if n < 64 else \
                np.full(n, ds.GetCellType(0), dtype=int)
        return types, conn
    types = np.array([ds.GetCellType(i) for i in range(n)], dtype=int)
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    conn = []
    for i in range(n):
        ds.GetCellPoints(i, ids)
        conn.append(tuple(ids.GetId(k) for k in range(ids.GetNumberOfIds())))
    return types, conn


def points_of(ds):
    if ds.GetPoints() is None:
        return np.zeros((0, 3))
    return np.array(vtk_to_numpy(ds.GetPoints().GetData()), dtype=float).reshape(-1, 3)


# --------------------------------------------------------------------------- result


class FlowComplexResult:
    """Plain structures extracted from the filter output.

    nodes:  node_id, index, value, loc (numpy arrays, one row per CriticalPoints
            point); simplex ((n,4) or None, if the filter exposes one); row (node
            id -> row); finite (bool mask: not the maximum at infinity).
    arcs:   lower, upper, mult, ratio (numpy arrays, one per HasseDiagram line).
    stable: tri_nodes (node id per index-2 triangle), tri_xyz (k,3,3), tri_ids
            (k,3) point ids into sm_points, sm_points, sm_original_ids (or None);
            edge_nodes/edge_ids for Index-1 lines, tet_nodes/tet_ids.
    report: field data of the output and of CriticalPoints, merged.
    """

    def __init__(self, mb, messages=None):
        self.output = mb
        self.messages = messages
        self.names = block_names(mb)
        cp = get_block(mb, "CriticalPoints")
        pd = cp.GetPointData()
        self.node_id = array(pd, "NodeId").astype(np.int64)
        self.index = array(pd, "Index").astype(np.int64)
        self.value = array(pd, "CriticalValue").astype(float)
        self.loc = points_of(cp)
        self.simplex = None
        for name in ("Simplex", "Simplices", "NodeSimplex"):
            s = array(pd, name, required=False)
            if s is not None:
                self.simplex = np.asarray(s, dtype=np.int64).reshape(len(self.node_id), -1)
                break
        self.finite = np.isfinite(self.value)
        self.row = {int(nid): i for i, nid in enumerate(self.node_id)}
        self.cp_vertex_cells = cp.GetNumberOfVerts() if cp.IsA("vtkPolyData") else None

        hd = get_block(mb, "HasseDiagram")
        cd = hd.GetCellData()
        lower = array(cd, "LowerNodeId", required=False)
        upper = array(cd, "UpperNodeId", required=False)
        if lower is None or upper is None:
            # fall back on the point data NodeId at the two ends of each line
            pnid = array(hd.GetPointData(), "NodeId")
            _, conn = cells_of(hd)
            lower = np.array([pnid[c[0]] for c in conn])
            upper = np.array([pnid[c[-1]] for c in conn])
            print("note: HasseDiagram has no LowerNodeId/UpperNodeId cell data; "
                  "used the NodeId of the line ends")
        self.lower = np.asarray(lower, dtype=np.int64)
        self.upper = np.asarray(upper, dtype=np.int64)
        self.mult = array(cd, "Multiplicity").astype(np.int64)
        self.ratio = array(cd, "Ratio").astype(float)

        self.report = field_report(mb)
        for k, v in field_report(cp).items():
            self.report.setdefault(k, v)

        sm = get_block(mb, "StableManifolds", required=False)
        self.sm = sm
        self.tri_nodes = np.zeros(0, dtype=np.int64)
        self.tri_ids = np.zeros((0, 3), dtype=np.int64)
        self.tri_xyz = np.zeros((0, 3, 3))
        self.edge_nodes = np.zeros(0, dtype=np.int64)
        self.edge_ids = np.zeros((0, 2), dtype=np.int64)
        self.tet_nodes = np.zeros(0, dtype=np.int64)
        self.tet_ids = np.zeros((0, 4), dtype=np.int64)
        self.sm_points = np.zeros((0, 3))
        self.sm_original_ids = None
        if sm is not None and sm.GetNumberOfCells() > 0:
            self.sm_points = points_of(sm)
            self.sm_original_ids = array(sm.GetPointData(), "vtkOriginalPointIds",
                                         required=False)
            cnode = array(sm.GetCellData(), "NodeId").astype(np.int64)
            cindex = array(sm.GetCellData(), "Index").astype(np.int64)
            types, conn = cells_of(sm)
            self.sm_cell_types, self.sm_cell_index, self.sm_cell_node = types, cindex, cnode
            t = np.nonzero((types == VTK_TRIANGLE) & (cindex == 2))[0]
            self.tri_nodes = cnode[t]
            self.tri_ids = np.array([conn[i] for i in t], dtype=np.int64).reshape(-1, 3)
            self.tri_xyz = self.sm_points[self.tri_ids] if len(t) else np.zeros((0, 3, 3))
            e = np.nonzero((types == VTK_LINE) & (cindex == 1))[0]
            self.edge_nodes = cnode[e]
            self.edge_ids = np.array([conn[i] for i in e], dtype=np.int64).reshape(-1, 2)
            q = np.nonzero((types == VTK_TETRA) & (cindex == 3))[0]
            self.tet_nodes = cnode[q]
            self.tet_ids = np.array([conn[i] for i in q], dtype=np.int64).reshape(-1, 4)

    # -- conveniences
    def counts(self):
        """Finite node counts by index (n0, n1, n2, n3)."""
        return tuple(int(np.sum((self.index == k) & self.finite)) for k in range(4))

    def euler(self):
        n = self.counts()
        return n[0] - n[1] + n[2] - n[3]

    def infinity_ids(self):
        return [int(i) for i in self.node_id[~self.finite]]

    def nodes_of_index(self, k, finite_only=True):
        m = self.index == k
        if finite_only:
            m &= self.finite
        return np.nonzero(m)[0]

    def triangles_by_node(self):
        """{node id: (k,3,3) triangle coordinates} for index-2 nodes."""
        out = {}
        for nid in np.unique(self.tri_nodes):
            out[int(nid)] = self.tri_xyz[self.tri_nodes == nid]
        return out

    def lower_neighbours(self):
        """{upper node id: [(lower node id, multiplicity), ...]}"""
        d = {}
        for lo, up, m in zip(self.lower, self.upper, self.mult):
            d.setdefault(int(up), []).append((int(lo), int(m)))
        return d

    def upper_neighbours(self):
        d = {}
        for lo, up, m in zip(self.lower, self.upper, self.mult):
            d.setdefault(int(lo), []).append((int(up), int(m)))
        return d

    def report_value(self, *names):
        """First field-data value among `names` (exact, then case-insensitive)."""
        for n in names:
            if n in self.report:
                return self.report[n]
        low = {k.lower(): v for k, v in self.report.items()}
        for n in names:
            if n.lower() in low:
                return low[n.lower()]
        return None

    def summary(self):
        skip = ("time", "timing", "nodecount", "euler", "arccount", "infinitynode")
        return "counts %s chi %d arcs %d triangles %d report %s" % (
            self.counts(), self.euler(), len(self.lower), len(self.tri_nodes),
            {k: v for k, v in self.report.items() if not any(s in k.lower() for s in skip)})


def run(points, **properties):
    mb, messages = run_filter(points, **properties)
    if messages.errors:
        print("vtkFlowComplex reported errors: %s" % messages.errors)
    return FlowComplexResult(mb, messages)


# --------------------------------------------------------------------------- determinism


def _hash(a):
    return hashlib.sha256(np.ascontiguousarray(a).tobytes()).hexdigest()[:16]


def fingerprint(mb, skip_field=("time", "timing", "second", "duration")):
    """{item: hash} over every block's points, cells and arrays and the field data,
    except field arrays whose names contain one of skip_field (timings)."""
    fp = {}

    def arrays(prefix, data, skip=()):
        for i in range(data.GetNumberOfArrays()):
            arr = data.GetAbstractArray(i)
            name = arr.GetName() or ("#%d" % i)
            if any(s in name.lower() for s in skip):
                continue
            if arr.IsA("vtkStringArray"):
                fp[prefix + name] = "|".join(arr.GetValue(k) for k in range(arr.GetNumberOfValues()))
            else:
                fp[prefix + name] = _hash(vtk_to_numpy(arr))

    arrays("field:", mb.GetFieldData(), skip_field)
    for name, i in zip(block_names(mb), range(mb.GetNumberOfBlocks())):
        b = mb.GetBlock(i)
        tag = "%s/" % name
        if b is None:
            fp[tag] = None
            continue
        fp[tag + "class"] = b.GetClassName()
        fp[tag + "points"] = _hash(points_of(b))
        types, conn = cells_of(b)
        fp[tag + "cells"] = _hash(np.array(types)) + _hash(
            np.array([x for c in conn for x in (len(c),) + c], dtype=np.int64))
        arrays(tag + "pd:", b.GetPointData())
        arrays(tag + "cd:", b.GetCellData())
        arrays(tag + "fd:", b.GetFieldData(), skip_field)
    return fp


# --------------------------------------------------------------------------- persistence


def reduce_z2(dims, boundaries):
    """Standard Z/2 column reduction (with clearing) of a filtration given in order.

    dims[j]: dimension of cell j; boundaries[j]: iterable of positions (< j) of its
    faces with odd coefficient. Returns (pairs, essential): pairs = [(i, j)] with i
    the creator position and j the destroyer position; essential = creator positions
    never destroyed."""
    n = len(dims)
    cols = [0] * n
    for j, b in enumerate(boundaries):
        c = 0
        for i in b:
            if i >= j:
                raise ValueError("face %d does not precede cell %d in the filtration" % (i, j))
            c ^= 1 << i
        cols[j] = c
    owner = {}       # low -> column
    cleared = set()  # columns known to reduce to zero (they are lows of higher columns)
    by_dim = {}
    for j, d in enumerate(dims):
        by_dim.setdefault(d, []).append(j)
    for d in sorted(by_dim, reverse=True):
        for j in by_dim[d]:
            if j in cleared:
                cols[j] = 0
                continue
            c = cols[j]
            while c:
                low = c.bit_length() - 1
                k = owner.get(low)
                if k is None:
                    break
                c ^= cols[k]
            cols[j] = c
            if c:
                low = c.bit_length() - 1
                owner[low] = j
                cleared.add(low)
    pairs = sorted((low, j) for low, j in owner.items())
    paired = set()
    for i, j in pairs:
        paired.add(i)
        paired.add(j)
    essential = [j for j in range(n) if j not in paired and cols[j] == 0]
    return pairs, essential


def diagram_from_filtration(dims, values, boundaries):
    """[(dim, birth, death)] with death = inf for essential classes."""
    pairs, essential = reduce_z2(dims, boundaries)
    out = [(dims[i], values[i], values[j]) for i, j in pairs]
    out += [(dims[i], values[i], math.inf) for i in essential]
    return out


def flow_complex_diagram(res):
    """Persistence diagram of the flow-complex filtration of a FlowComplexResult:
    finite nodes ordered by (value, index), Z/2 boundary = arcs with odd
    multiplicity, arcs to the maximum at infinity excluded."""
    fin = np.nonzero(res.finite)[0]
    # A filtration needs every face before its cofaces. Values along arcs increase
    # exactly, but after a perturbation by eps two of them may differ by O(eps^2)
    # and come out tied or inverted by an ulp in double precision: take the
    # monotone closure value(node) = max(own value, values of its faces), which
    # changes nothing when the values are consistent.
    eff = {int(res.node_id[r]): float(res.value[r]) for r in fin}
    faces_of = {}
    for lo, up in zip(res.lower, res.upper):
        faces_of.setdefault(int(up), []).append(int(lo))
    inversions = 0
    worst = 0.0
    for k in (1, 2, 3):
        for r in res.nodes_of_index(k):
            nid = int(res.node_id[r])
            top = max((eff[f] for f in faces_of.get(nid, []) if f in eff), default=-math.inf)
            if top > eff[nid]:
                inversions += 1
                worst = max(worst, top - eff[nid])
                eff[nid] = top
    if inversions:
        print("  note: %d arcs decrease in value (by at most %.3g); monotone closure used "
              "for the filtration" % (inversions, worst))
    order = sorted(fin, key=lambda r: (eff[int(res.node_id[r])], res.index[r], res.node_id[r]))
    pos = {int(res.node_id[r]): p for p, r in enumerate(order)}
    faces = [[] for _ in order]
    for lo, up, m in zip(res.lower, res.upper, res.mult):
        lo, up = int(lo), int(up)
        if up not in pos or lo not in pos:
            continue  # arc to infinity
        if m % 2:
            faces[pos[up]].append(pos[lo])
    # an arc listed twice (split multiplicity) must cancel mod 2
    boundaries = []
    for f in faces:
        odd = set()
        for i in f:
            odd ^= {i}
        boundaries.append(sorted(odd))
    dims = [int(res.index[r]) for r in order]
    values = [eff[int(res.node_id[r])] for r in order]
    return diagram_from_filtration(dims, values, boundaries)


def significant(diagram, min_persistence):
    return [(d, b, e) for d, b, e in diagram if e - b >= min_persistence]


def compare_diagrams(a, b, tol, labels=("flow complex", "oracle"), max_report=8):
    """Compares two diagrams [(dim, birth, death)] as multisets per dimension, within
    `tol` (L-infinity; essential classes must be essential on both sides).
    Returns (ok, message)."""
    from scipy.optimize import linear_sum_assignment
    msgs = []
    ok = True
    dims = sorted({d for d, _, _ in a} | {d for d, _, _ in b})
    for d in dims:
        A = sorted((x, y) for k, x, y in a if k == d)
        B = sorted((x, y) for k, x, y in b if k == d)
        Ae = sorted(x for x, y in A if math.isinf(y))
        Be = sorted(x for x, y in B if math.isinf(y))
        Af = sorted(((x, y) for x, y in A if not math.isinf(y)), key=lambda p: (p[1], p[0]))
        Bf = sorted(((x, y) for x, y in B if not math.isinf(y)), key=lambda p: (p[1], p[0]))
        if len(Ae) != len(Be) or any(abs(x - y) > tol for x, y in zip(Ae, Be)):
            ok = False
            msgs.append("H%d essential classes differ: %s %s vs %s %s" % (
                d, labels[0], Ae[:max_report], labels[1], Be[:max_report]))
        if len(Af) != len(Bf):
            ok = False
            msgs.append("H%d: %d finite pairs (%s) vs %d (%s)" % (d, len(Af), labels[0],
                                                                    len(Bf), labels[1]))
        if not Af or not Bf:
            if Af or Bf:
                msgs.append("   H%d %s only: %s" % (d, labels[0] if Af else labels[1],
                                                     (Af or Bf)[:max_report]))
            continue
        if len(Af) == len(Bf) and all(max(abs(p[0] - q[0]), abs(p[1] - q[1])) <= tol
                                       for p, q in zip(Af, Bf)):
            continue
        # optimal matching; unmatched points may go to the diagonal
        PA = np.array(Af)
        PB = np.array(Bf)
        cost = np.maximum(np.abs(PA[:, None, 0] - PB[None, :, 0]),
                          np.abs(PA[:, None, 1] - PB[None, :, 1]))
        ri, ci = linear_sum_assignment(cost)
        bad = [(tuple(PA[i]), tuple(PB[j]), cost[i, j]) for i, j in zip(ri, ci) if cost[i, j] > tol]
        onlyA = sorted(set(range(len(PA))) - set(ri))
        onlyB = sorted(set(range(len(PB))) - set(ci))
        if bad or onlyA or onlyB:
            ok = False
            msgs.append("H%d: %d matched pairs differ by more than %g" % (d, len(bad), tol))
            for p, q, c in sorted(bad, key=lambda t: -t[2])[:max_report]:
                msgs.append("   %s %r vs %s %r (diff %.3g)" % (labels[0], p, labels[1], q, c))
            for i in onlyA[:max_report]:
                msgs.append("   only in %s: %r" % (labels[0], tuple(PA[i])))
            for j in onlyB[:max_report]:
                msgs.append("   only in %s: %r" % (labels[1], tuple(PB[j])))
    return ok, "\n".join(msgs)


def gudhi_alpha_diagram(points):
    """Alpha-complex persistence (GUDHI) with filtration values converted from
    squared radii to radii."""
    import gudhi
    st = gudhi.AlphaComplex(points=np.asarray(points, dtype=float)).create_simplex_tree()
    dgm = st.persistence(homology_coeff_field=2, min_persistence=-1.0)
    out = []
    for d, (b, e) in dgm:
        out.append((d, math.sqrt(max(b, 0.0)), math.inf if math.isinf(e) else math.sqrt(max(e, 0.0))))
    return out


def diameter(points):
    p = np.asarray(points, dtype=float)
    return float(np.linalg.norm(p.max(axis=0) - p.min(axis=0)))
