#include "FlowComplexFromVTK.h"

#include "ContractArrays.h"
#include "FlowReconNames.h"

#include "vtkAbstractArray.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace flowrecon
{

namespace
{

void ReadReport(vtkFieldData* fd, FlowComplex& fc)
{
  auto get = [fd](const char* name, int component, double fallback) {
    vtkDataArray* a = fd ? fd->GetArray(name) : nullptr;
    return a && a->GetNumberOfTuples() > 0 && component < a->GetNumberOfComponents()
      ? a->GetComponent(0, component)
      : fallback;
  };
  DegeneracyReport& r = fc.Report;
  r.InputPoints = static_cast<Id>(get("InputPointCount", 0, double(fc.NumberOfInputPoints)));
  r.DuplicatePoints = static_cast<Id>(get("DuplicatePointCount", 0, 0));
  r.RightAngles = static_cast<Id>(get("RightAngleCount", 0, 0));
  r.ApexOnSphere = static_cast<Id>(get("ApexOnSphereCount", 0, 0));
  r.WalkTies = static_cast<Id>(get("WalkTieCount", 0, 0));
  r.ExactFallbacks = static_cast<Id>(get("ExactFallbackCount", 0, 0));
  r.Attempts = static_cast<int>(get("PerturbationAttempts", 0, 1));
  r.PerturbationMagnitude = get("PerturbationMagnitude", 0, 0);
  r.PerturbedValues = static_cast<Id>(get("PerturbedValueCount", 0, 0));
  r.Seed = static_cast<std::uint64_t>(static_cast<vtkIdType>(get("PerturbationSeed", 0, 1)));
  double* t[6] = { &fc.Time.Delaunay, &fc.Time.CriticalPoints, &fc.Time.StableManifolds,
    &fc.Time.UnstableManifolds, &fc.Time.Assembly, &fc.Time.Total };
  for (int k = 0; k < 6; ++k)
  {
    *t[k] = get("Timings", k, 0);
  }
}

bool ReadNodes(vtkPolyData* cp, FlowComplex& fc, std::string& error)
{
  const char* block = flowrecon::names::CriticalPoints;
  const vtkIdType n = cp->GetNumberOfPoints();
  vtkPointData* pd = cp->GetPointData();
  vtkDataArray* nodeId = RequiredArray(pd, block, flowrecon::names::NodeId, 1, n, error);
  vtkDataArray* index = nodeId ? RequiredArray(pd, block, flowrecon::names::Index, 1, n, error) : nullptr;
  vtkDataArray* value = index ? RequiredArray(pd, block, flowrecon::names::CriticalValue, 1, n, error) : nullptr;
  vtkDataArray* simplex = value ? RequiredArray(pd, block, flowrecon::names::Simplex, 4, n, error) : nullptr;
  if (!simplex)
  {
    return false;
  }
  fc.Nodes.assign(static_cast<std::size_t>(n), Node());
  std::vector<bool> seen(static_cast<std::size_t>(n), false);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Id id = IdValue(nodeId, i);
    if (id < 0 || id >= n || seen[id])
    {
      error = "block CriticalPoints: NodeId is not a numbering 0..n-1 of its points";
      return false;
    }
    seen[id] = true;
    Node& node = fc.Nodes[id];
    node.Index = static_cast<int>(index->GetComponent(i, 0));
    node.Value = value->GetComponent(i, 0);
    cp->GetPoint(i, node.Location.data());
    for (int k = 0; k < 4; ++k)
    {
      node.Simplex[k] = IdValue(simplex, i, k);
    }
    if (node.Index < 0 || node.Index > 3)
    {
      error = "block CriticalPoints: node " + std::to_string(id) + " has an index outside 0..3";
      return false;
    }
    // A distance: finite and not negative, but at infinity (+inf). A NaN
    // would leave every later order (queue, filtration) undefined.
    if (node.IsInfinity() ? !(node.Value == HUGE_VAL) : !(std::isfinite(node.Value) && node.Value >= 0))
    {
      error = "block CriticalPoints: node " + std::to_string(id) + " has the critical value " +
        std::to_string(node.Value) + (node.IsInfinity() ? " (the maximum at infinity needs inf)" : "");
      return false;
    }
    if (node.IsInfinity())
    {
      if (fc.InfinityNode >= 0)
      {
        error = "block CriticalPoints: two nodes have no simplex (maximum at infinity)";
        return false;
      }
      fc.InfinityNode = id;
    }
  }
  return true;
}

/// The deferred patches of a complex built with them (point array Deferred and
/// field data DeferralRatio of CriticalPoints): index-2 nodes only, none with an
/// arc in the HasseDiagram block.
bool ReadDeferred(vtkPolyData* cp, FlowComplex& fc, std::string& error)
{
  const char* block = flowrecon::names::CriticalPoints;
  vtkDataArray* flags = cp->GetPointData()->GetArray(flowrecon::names::Deferred);
  if (!flags)
  {
    return true;
  }
  const vtkIdType n = static_cast<vtkIdType>(fc.Nodes.size());
  vtkDataArray* nodeId = cp->GetPointData()->GetArray(flowrecon::names::NodeId);
  vtkDataArray* ratio = cp->GetFieldData()->GetArray(flowrecon::names::DeferralRatio);
  if (flags->GetNumberOfTuples() != n || flags->GetNumberOfComponents() != 1 || !nodeId)
  {
    error = std::string("block ") + block + ": array Deferred does not have one value per node";
    return false;
  }
  if (!ratio || ratio->GetNumberOfTuples() < 1 || !(ratio->GetComponent(0, 0) > 1) ||
    !std::isfinite(ratio->GetComponent(0, 0)))
  {
    error = std::string("block ") + block +
      ": a complex with deferred patches needs a finite DeferralRatio above 1";
    return false;
  }
  std::vector<char> deferred(fc.Nodes.size(), 0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (flags->GetComponent(i, 0) != 0)
    {
      const Id node = IdValue(nodeId, i);
      if (fc.Nodes[node].Index != 2)
      {
        error = std::string("block ") + block + ": a deferred node that is not of index 2";
        return false;
      }
      deferred[node] = 1;
    }
  }
  for (const Arc& a : fc.Arcs)
  {
    if (deferred[a.Upper])
    {
      error = "block HasseDiagram: an arc into a deferred node (DeferralRatio promises none)";
      return false;
    }
  }
  for (std::size_t i = 0; i < deferred.size(); ++i)
  {
    if (deferred[i])
    {
      fc.DeferredPatches.push_back(static_cast<Id>(i));
    }
  }
  fc.DeferralRatio = fc.DeferredPatches.empty() ? HUGE_VAL : ratio->GetComponent(0, 0);
  return true;
}

bool ReadArcs(vtkPolyData* hd, FlowComplex& fc, std::string& error)
{
  const char* block = flowrecon::names::HasseDiagram;
  const vtkIdType m = hd->GetNumberOfCells();
  vtkCellData* cd = hd->GetCellData();
  vtkDataArray* lower = RequiredArray(cd, block, flowrecon::names::LowerNodeId, 1, m, error);
  vtkDataArray* upper = lower ? RequiredArray(cd, block, flowrecon::names::UpperNodeId, 1, m, error) : nullptr;
  vtkDataArray* mult = upper ? RequiredArray(cd, block, flowrecon::names::Multiplicity, 1, m, error) : nullptr;
  if (!mult)
  {
    return false;
  }
  const Id n = static_cast<Id>(fc.Nodes.size());
  fc.Arcs.resize(static_cast<std::size_t>(m));
  for (vtkIdType c = 0; c < m; ++c)
  {
    Arc& a = fc.Arcs[c];
    a.Lower = IdValue(lower, c);
    a.Upper = IdValue(upper, c);
    a.Multiplicity = static_cast<int>(mult->GetComponent(c, 0));
    if (a.Lower < 0 || a.Lower >= n || a.Upper < 0 || a.Upper >= n)
    {
      error = "block HasseDiagram: arc " + std::to_string(c) + " names a node that does not exist";
      return false;
    }
  }
  return true;
}

/// Checks the block and, with `store`, reads its geometry into fc (a stage that
/// passes the block through checks it without the copy's memory).
bool ReadStableManifolds(vtkUnstructuredGrid* ug, FlowComplex& fc, std::string& error, bool store)
{
  const char* block = flowrecon::names::StableManifolds;
  const vtkIdType np = ug->GetNumberOfPoints();
  fc.Points.resize(store ? static_cast<std::size_t>(np) : 0);
  for (vtkIdType i = 0; store && i < np; ++i)
  {
    ug->GetPoint(i, fc.Points[i].data());
  }
  // Input points come first; constructed points have original id -1.
  vtkDataArray* original = ug->GetPointData()->GetArray(flowrecon::names::OriginalPointIds);
  fc.NumberOfInputPoints = np;
  if (original && original->GetNumberOfTuples() == np)
  {
    fc.NumberOfInputPoints = 0;
    while (fc.NumberOfInputPoints < np && IdValue(original, fc.NumberOfInputPoints) >= 0)
    {
      ++fc.NumberOfInputPoints;
    }
  }
  fc.Representative.resize(static_cast<std::size_t>(fc.NumberOfInputPoints));
  for (Id i = 0; i < fc.NumberOfInputPoints; ++i)
  {
    fc.Representative[i] = i;
  }
  const vtkIdType nc = ug->GetNumberOfCells();
  vtkDataArray* nodeId = RequiredArray(ug->GetCellData(), block, flowrecon::names::NodeId, 1, nc, error);
  if (!nodeId)
  {
    return false;
  }
  const Id n = static_cast<Id>(fc.Nodes.size());
  for (vtkIdType c = 0; c < nc; ++c)
  {
    const int type = ug->GetCellType(c);
    if (type != VTK_TRIANGLE && type != VTK_TETRA)
    {
      continue; // vertices and edges are the nodes' simplices
    }
    vtkIdType npts;
    const vtkIdType* pts;
    ug->GetCellPoints(c, npts, pts);
    const Id node = IdValue(nodeId, c);
    bool ok = node >= 0 && node < n;
    for (vtkIdType k = 0; ok && k < npts; ++k)
    {
      ok = pts[k] >= 0 && pts[k] < np;
    }
    if (!ok)
    {
      error = "block StableManifolds: cell " + std::to_string(c) + " has an invalid node or point";
      return false;
    }
    if (!store)
    {
      continue;
    }
    if (type == VTK_TRIANGLE)
    {
      fc.Triangles.push_back({ { pts[0], pts[1], pts[2] } });
      fc.TriangleNode.push_back(node);
    }
    else
    {
      fc.Tetrahedra.push_back({ { pts[0], pts[1], pts[2], pts[3] } });
      fc.TetrahedronNode.push_back(node);
    }
  }
  return true; // without `store`, fc.NumberOfInputPoints still says how many samples there are
}

/// fc.NodePoint (with `store`) from the CriticalPoints array StableManifoldPointId,
/// checked against the `points` of StableManifolds. Files written before that
/// array give the samples' points alone (a sample node's point is its Simplex[0]).
bool ReadNodePoints(vtkPolyData* cp, vtkIdType points, FlowComplex& fc, std::string& error, bool store)
{
  const char* block = flowrecon::names::CriticalPoints;
  const vtkIdType n = static_cast<vtkIdType>(fc.Nodes.size());
  vtkPointData* pd = cp->GetPointData();
  vtkDataArray* point = pd->GetArray(flowrecon::names::StableManifoldPointId);
  if (point && !RequiredArray(pd, block, flowrecon::names::StableManifoldPointId, 1, n, error))
  {
    return false;
  }
  vtkDataArray* nodeId = pd->GetArray(flowrecon::names::NodeId); // checked by ReadNodes
  fc.NodePoint.assign(store ? fc.Nodes.size() : 0, -1);
  for (vtkIdType i = 0; i < n; ++i)
  {
    const Id node = IdValue(nodeId, i);
    const Id p = point ? IdValue(point, i) : (fc.Nodes[node].Index == 0 ? fc.Nodes[node].Simplex[0] : -1);
    if (p < -1 || p >= points)
    {
      error = std::string("block ") + block + ": node " + std::to_string(node) +
        (point ? " has a StableManifoldPointId" : " has a sample") + " that is not a point of StableManifolds";
      return false;
    }
    if (store)
    {
      fc.NodePoint[node] = p;
    }
  }
  return true;
}

/// Checks the block and, with `store`, reads the flow lines into fc.
bool ReadFlowLines(vtkPolyData* um, FlowComplex& fc, std::string& error, bool store)
{
  vtkDataArray* nodeId = um->GetCellData()->GetArray(flowrecon::names::NodeId);
  vtkDataArray* target = um->GetCellData()->GetArray(flowrecon::names::TargetNodeId);
  const vtkIdType nc = um->GetNumberOfCells();
  if (!nodeId || !target || nodeId->GetNumberOfTuples() != nc || target->GetNumberOfTuples() != nc)
  {
    return true; // optional geometry
  }
  const vtkIdType np = um->GetNumberOfPoints();
  const Id n = static_cast<Id>(fc.Nodes.size());
  for (vtkIdType c = 0; c < nc; ++c)
  {
    FlowLine line;
    line.Node = IdValue(nodeId, c);
    line.Target = IdValue(target, c);
    vtkIdType npts;
    const vtkIdType* pts;
    um->GetCellPoints(c, npts, pts);
    // Ids come from a file: check them, as for the other blocks.
    bool ok = line.Node >= 0 && line.Node < n && line.Target >= 0 && line.Target < n;
    for (vtkIdType k = 0; ok && k < npts; ++k)
    {
      ok = pts[k] >= 0 && pts[k] < np;
    }
    if (!ok)
    {
      error = "block UnstableManifolds: cell " + std::to_string(c) + " has an invalid node or point";
      return false;
    }
    for (vtkIdType k = 0; store && k < npts; ++k)
    {
      Point3 p;
      um->GetPoint(pts[k], p.data());
      line.Points.push_back(p);
    }
    if (store)
    {
      fc.FlowLines.push_back(std::move(line));
    }
  }
  return true;
}

} // namespace

bool FromMultiBlock(
  vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error, bool diagramOnly, bool flowLines)
{
  fc = FlowComplex();
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::CriticalPoints));
  auto* hd = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::HasseDiagram));
  auto* sm = vtkUnstructuredGrid::SafeDownCast(NamedBlock(input, flowrecon::names::StableManifolds));
  if (!cp || !hd || !sm)
  {
    error = "not a flow complex: the blocks CriticalPoints (vtkPolyData), HasseDiagram "
            "(vtkPolyData) and StableManifolds (vtkUnstructuredGrid) are required";
    return false;
  }
  if (!ReadNodes(cp, fc, error) || !ReadArcs(hd, fc, error) ||
    !ReadStableManifolds(sm, fc, error, !diagramOnly) ||
    !ReadNodePoints(cp, sm->GetNumberOfPoints(), fc, error, !diagramOnly))
  {
    fc = FlowComplex();
    return false;
  }
  auto* um = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::UnstableManifolds));
  if (um && !ReadFlowLines(um, fc, error, !diagramOnly && flowLines))
  {
    fc = FlowComplex();
    return false;
  }
  ReadReport(cp->GetFieldData(), fc);
  if (!ReadDeferred(cp, fc, error))
  {
    fc = FlowComplex();
    return false;
  }
  return true;
}

bool ReadManifoldGeometry(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error)
{
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::CriticalPoints));
  auto* sm = vtkUnstructuredGrid::SafeDownCast(NamedBlock(input, flowrecon::names::StableManifolds));
  if (!cp || !sm)
  {
    error = "not a flow complex: the blocks CriticalPoints and StableManifolds are required";
    return false;
  }
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  fc.Tetrahedra.clear();
  fc.TetrahedronNode.clear();
  return ReadStableManifolds(sm, fc, error, true) &&
    ReadNodePoints(cp, sm->GetNumberOfPoints(), fc, error, true);
}

bool ReadSamples(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error)
{
  auto* sm = vtkUnstructuredGrid::SafeDownCast(NamedBlock(input, flowrecon::names::StableManifolds));
  if (!sm || fc.NumberOfInputPoints > sm->GetNumberOfPoints())
  {
    error = "not a flow complex: the block StableManifolds lacks the samples";
    return false;
  }
  fc.Points.resize(static_cast<std::size_t>(fc.NumberOfInputPoints));
  for (Id i = 0; i < fc.NumberOfInputPoints; ++i)
  {
    sm->GetPoint(i, fc.Points[i].data());
  }
  return true;
}

std::vector<Node> GabrielEdgeNodes(vtkMultiBlockDataSet* input)
{
  std::vector<Node> nodes;
  auto* ge = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::GabrielEdges));
  vtkDataArray* value = ge ? ge->GetCellData()->GetArray(flowrecon::names::CriticalValue) : nullptr;
  if (!ge || !value || value->GetNumberOfTuples() != ge->GetNumberOfCells() || !ge->GetLines())
  {
    return nodes;
  }
  nodes.resize(static_cast<std::size_t>(ge->GetNumberOfPoints()));
  for (vtkIdType k = 0; k < ge->GetNumberOfPoints(); ++k)
  {
    Node& n = nodes[static_cast<std::size_t>(k)];
    n.Simplex[0] = static_cast<std::int32_t>(k);
    ge->GetPoint(k, n.Location.data());
  }
  vtkCellArray* lines = ge->GetLines();
  vtkIdType cell = 0;
  vtkIdType count = 0;
  const vtkIdType* ends = nullptr;
  for (lines->InitTraversal(); lines->GetNextCell(count, ends); ++cell)
  {
    if (count == 2 && ends[0] >= 0 && ends[1] >= 0 && ends[0] < ge->GetNumberOfPoints() &&
      ends[1] < ge->GetNumberOfPoints() && ends[0] != ends[1])
    {
      Node n;
      n.Index = 1;
      n.Value = value->GetComponent(cell, 0);
      n.Simplex[0] = static_cast<std::int32_t>(std::min(ends[0], ends[1]));
      n.Simplex[1] = static_cast<std::int32_t>(std::max(ends[0], ends[1]));
      nodes.push_back(n);
    }
  }
  return nodes;
}

} // namespace flowrecon
