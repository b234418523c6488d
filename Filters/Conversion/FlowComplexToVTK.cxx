#include "FlowComplexToVTK.h"

#include "ContractArrays.h"
#include "DrawingBox.h"
#include "FlowReconNames.h"
#include "MemoryGuard.h"


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
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

namespace flowrecon
{

namespace
{

vtkSmartPointer<vtkPolyData> CriticalPointsBlock(const FlowComplex& fc)
{
  std::vector<Point3> locations;
  locations.reserve(fc.Nodes.size());
  // Node and input ids in 32 bits (flow complexes are limited to 2^31 nodes,
  // and a node's samples are fewer): half the memory of vtkIdType's, which
  // ParaView holds for as long as the filter is.
  auto nodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId);
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  auto simplex = NamedArray<vtkTypeInt32Array>(flowrecon::names::Simplex, 4);
  // Written, not left to be found again by coordinates: a node's critical point
  // is one point of StableManifolds (a sample's vertex cell uses Simplex[0]).
  const bool drawn = fc.NodePoint.size() == fc.Nodes.size();
  const bool narrowPoints = !drawn ||
    std::all_of(fc.NodePoint.begin(), fc.NodePoint.end(), [](Id p) { return p < INT32_MAX; });
  auto point = narrowPoints
    ? vtkSmartPointer<vtkDataArray>(NamedArray<vtkTypeInt32Array>(flowrecon::names::StableManifoldPointId))
    : vtkSmartPointer<vtkDataArray>(NamedArray<vtkIdTypeArray>(flowrecon::names::StableManifoldPointId));
  const vtkIdType count = static_cast<vtkIdType>(fc.Nodes.size());
  nodeId->SetNumberOfTuples(count);
  index->SetNumberOfTuples(count);
  value->SetNumberOfTuples(count);
  simplex->SetNumberOfTuples(count);
  point->SetNumberOfTuples(count);
  vtkNew<vtkCellArray> verts;
  verts->Use32BitStorage(); // node ids fit
  verts->AllocateExact(count, count);
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& n = fc.Nodes[i];
    const vtkIdType k = static_cast<vtkIdType>(i);
    locations.push_back(n.Location);
    nodeId->SetValue(k, static_cast<std::int32_t>(i));
    index->SetValue(k, n.Index);
    value->SetValue(k, n.Value);
    for (int j = 0; j < 4; ++j)
    {
      simplex->SetTypedComponent(k, j, static_cast<std::int32_t>(n.Simplex[j]));
    }
    point->SetTuple1(k, static_cast<double>(drawn ? fc.NodePoint[i] : (n.Index == 0 ? n.Simplex[0] : -1)));
    if (!n.IsInfinity()) // the maximum at infinity is kept as data, never drawn
    {
      const vtkIdType id = static_cast<vtkIdType>(i);
      verts->InsertNextCell(1, &id);
    }
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(locations));
  pd->SetVerts(verts);
  pd->GetPointData()->AddArray(nodeId);
  pd->GetPointData()->AddArray(index);
  pd->GetPointData()->AddArray(value);
  pd->GetPointData()->AddArray(simplex);
  pd->GetPointData()->AddArray(point);
  pd->GetPointData()->SetActiveScalars(flowrecon::names::Index);
  // Index on the vertex cells too: a display coloured by the cell array Index
  // draws these points and the GabrielEdges lines in one legend.
  auto cellIndex = NamedArray<vtkIntArray>(flowrecon::names::Index);
  for (const Node& n : fc.Nodes)
  {
    if (!n.IsInfinity())
    {
      cellIndex->InsertNextValue(n.Index);
    }
  }
  pd->GetCellData()->AddArray(cellIndex);
  return pd;
}

/// The Gabriel edges (the index-1 stable manifolds) as lines between the
/// samples, a light block a display can show by default: point k is index-0
/// node k, as in CriticalPoints.
vtkSmartPointer<vtkPolyData> GabrielEdgesBlock(const FlowComplex& fc)
{
  std::vector<Point3> samples;
  // Input id -> point: a map, since the ids of a stored complex are not trusted.
  std::unordered_map<Id, vtkIdType> pointOfInput;
  for (std::size_t i = 0; i < fc.Nodes.size() && fc.Nodes[i].Index == 0; ++i)
  {
    pointOfInput.emplace(fc.Nodes[i].Simplex[0], static_cast<vtkIdType>(samples.size()));
    samples.push_back(fc.Nodes[i].Location);
  }
  auto nodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId);
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  vtkNew<vtkCellArray> lines;
  lines->Use32BitStorage(); // the samples are fewer than the nodes
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& n = fc.Nodes[i];
    if (n.Index != 1)
    {
      continue;
    }
    const auto a = pointOfInput.find(n.Simplex[0]), b = pointOfInput.find(n.Simplex[1]);
    if (a == pointOfInput.end() || b == pointOfInput.end())
    {
      throw InputError("an index-1 node whose vertices are not samples");
    }
    const vtkIdType ends[2] = { a->second, b->second };
    lines->InsertNextCell(2, ends);
    nodeId->InsertNextValue(static_cast<std::int32_t>(i));
    index->InsertNextValue(1);
    value->InsertNextValue(n.Value);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(samples));
  pd->SetLines(lines);
  pd->GetCellData()->AddArray(nodeId);
  pd->GetCellData()->AddArray(index);
  pd->GetCellData()->AddArray(value);
  pd->GetCellData()->SetActiveScalars(flowrecon::names::Index);
  return pd;
}

vtkSmartPointer<vtkPolyData> HasseDiagramBlock(const FlowComplex& fc)
{
  // Point k is node k's critical point, shared by its arcs (a surface sample has
  // ~100 arcs per point: two points per arc would double the block); an arc to
  // infinity ends on a short outward stub of its own instead of a point that
  // would distort the bounds.
  const double stub = ArcStub * SamplesDiagonal(fc);
  const Point3 centre = fc.InfinityNode >= 0 ? fc.Nodes[fc.InfinityNode].Location : Point3{};
  const vtkIdType nodes = static_cast<vtkIdType>(fc.Nodes.size());
  const vtkIdType arcs = static_cast<vtkIdType>(fc.Arcs.size());
  vtkIdType stubs = 0;
  for (const Arc& a : fc.Arcs)
  {
    stubs += fc.Nodes[a.Upper].IsInfinity() ? 1 : 0;
  }
  std::vector<Point3> pts;
  pts.reserve(fc.Nodes.size() + static_cast<std::size_t>(stubs));
  for (const Node& node : fc.Nodes)
  {
    pts.push_back(node.Location);
  }
  // Ids in 32 bits (node ids always fit; the lines' where the points and
  // corners do): 20 bytes an arc less than vtkIdType's, on a block of ~100
  // arcs a sample that ParaView holds for as long as the filter is.
  auto nodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId);
  auto mult = NamedArray<vtkIntArray>(flowrecon::names::Multiplicity);
  auto ratio = NamedArray<vtkDoubleArray>(flowrecon::names::Ratio);
  auto lowerId = NamedArray<vtkTypeInt32Array>(flowrecon::names::LowerNodeId);
  auto upperId = NamedArray<vtkTypeInt32Array>(flowrecon::names::UpperNodeId);
  for (auto* a : { static_cast<vtkDataArray*>(mult), static_cast<vtkDataArray*>(ratio),
         static_cast<vtkDataArray*>(lowerId), static_cast<vtkDataArray*>(upperId) })
  {
    a->SetNumberOfTuples(arcs);
  }
  // One line per arc, filled through raw pointers of either width.
  const auto fill = [&](auto* offset, auto* point) {
    using Value = std::remove_pointer_t<decltype(offset)>;
    for (vtkIdType c = 0; c < arcs; ++c)
    {
      const Arc& a = fc.Arcs[c];
      const Node& lo = fc.Nodes[a.Lower];
      const Node& up = fc.Nodes[a.Upper];
      vtkIdType end = a.Upper;
      if (up.IsInfinity())
      {
        Point3 d{ { lo.Location[0] - centre[0], lo.Location[1] - centre[1],
          lo.Location[2] - centre[2] } };
        const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        Point3 tip;
        for (int k = 0; k < 3; ++k)
        {
          tip[k] = lo.Location[k] + (n > 0 ? d[k] / n * stub : (k == 2 ? stub : 0));
        }
        end = static_cast<vtkIdType>(pts.size());
        pts.push_back(tip);
      }
      offset[c] = static_cast<Value>(2 * c);
      point[2 * c] = static_cast<Value>(a.Lower);
      point[2 * c + 1] = static_cast<Value>(end);
      mult->SetValue(c, a.Multiplicity);
      ratio->SetValue(c, PersistenceRatioAtLeastOne(up.Value, lo.Value));
      lowerId->SetValue(c, static_cast<std::int32_t>(a.Lower));
      upperId->SetValue(c, static_cast<std::int32_t>(a.Upper));
    }
    offset[arcs] = static_cast<Value>(2 * arcs);
  };
  vtkNew<vtkCellArray> lines;
  if (std::max(nodes + stubs, 2 * arcs) < static_cast<vtkIdType>(INT32_MAX))
  {
    vtkNew<vtkTypeInt32Array> offsets, connectivity;
    offsets->SetNumberOfValues(arcs + 1);
    connectivity->SetNumberOfValues(2 * arcs);
    fill(offsets->GetPointer(0), connectivity->GetPointer(0));
    lines->SetData(offsets, connectivity);
  }
  else
  {
    vtkNew<vtkTypeInt64Array> offsets, connectivity;
    offsets->SetNumberOfValues(arcs + 1);
    connectivity->SetNumberOfValues(2 * arcs);
    fill(offsets->GetPointer(0), connectivity->GetPointer(0));
    lines->SetData(offsets, connectivity);
  }
  nodeId->SetNumberOfValues(static_cast<vtkIdType>(pts.size()));
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(pts.size()); ++k)
  {
    // stubs stand for infinity
    nodeId->SetValue(k, static_cast<std::int32_t>(k < nodes ? k : fc.InfinityNode));
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(pts));
  pd->SetLines(lines);
  pd->GetPointData()->AddArray(nodeId);
  pd->GetCellData()->AddArray(mult);
  pd->GetCellData()->AddArray(ratio);
  pd->GetCellData()->AddArray(lowerId);
  pd->GetCellData()->AddArray(upperId);
  return pd;
}

vtkSmartPointer<vtkUnstructuredGrid> StableManifoldsBlock(
  const FlowComplex& fc, const Progress& progress)
{
  vtkNew<vtkUnstructuredGrid> ug;
  ug->SetPoints(MakePoints(fc.Points));
  auto original = NamedArray<vtkIdTypeArray>(flowrecon::names::OriginalPointIds);
  original->SetNumberOfTuples(static_cast<vtkIdType>(fc.Points.size()));
  for (std::size_t i = 0; i < fc.Points.size(); ++i)
  {
    original->SetValue(static_cast<vtkIdType>(i),
      static_cast<Id>(i) < fc.NumberOfInputPoints ? static_cast<vtkIdType>(i) : -1);
  }
  ug->GetPointData()->AddArray(original);

  auto nodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId); // node ids fit
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  const vtkIdType cellCount = static_cast<vtkIdType>(fc.Nodes.size() + fc.Triangles.size() +
    fc.Tetrahedra.size());
  ug->AllocateExact(cellCount, 4);
  if (fc.Points.size() < static_cast<std::size_t>(INT32_MAX))
  {
    // 32-bit point ids: half the connectivity's memory.
    ug->GetCells()->Use32BitStorage();
    ug->GetCells()->AllocateEstimate(cellCount, 4);
  }
  const double cells = static_cast<double>(fc.Nodes.size() + fc.Triangles.size() +
    fc.Tetrahedra.size()) + 1;
  auto add = [&](int type, int n, const vtkIdType* ids, Id node) {
    const vtkIdType k = ug->InsertNextCell(type, n, ids);
    if ((k & 0xFFFF) == 0xFFFF)
    {
      progress(static_cast<double>(k) / cells, "VTK output: stable manifolds");
    }
    nodeId->InsertNextValue(static_cast<std::int32_t>(node));
    index->InsertNextValue(fc.Nodes[node].Index);
    value->InsertNextValue(fc.Nodes[node].Value);
  };
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& n = fc.Nodes[i];
    if (n.Index == 0)
    {
      const vtkIdType v = n.Simplex[0];
      add(VTK_VERTEX, 1, &v, static_cast<Id>(i));
    }
    else if (n.Index == 1)
    {
      const vtkIdType e[2] = { n.Simplex[0], n.Simplex[1] };
      add(VTK_LINE, 2, e, static_cast<Id>(i));
    }
  }
  for (std::size_t i = 0; i < fc.Triangles.size(); ++i)
  {
    const vtkIdType t[3] = { fc.Triangles[i][0], fc.Triangles[i][1], fc.Triangles[i][2] };
    add(VTK_TRIANGLE, 3, t, fc.TriangleNode[i]);
  }
  for (std::size_t i = 0; i < fc.Tetrahedra.size(); ++i)
  {
    const auto& t = fc.Tetrahedra[i];
    const vtkIdType ids[4] = { t[0], t[1], t[2], t[3] };
    add(VTK_TETRA, 4, ids, fc.TetrahedronNode[i]);
  }
  ug->GetCellData()->AddArray(nodeId);
  ug->GetCellData()->AddArray(index);
  ug->GetCellData()->AddArray(value);
  ug->GetCellData()->SetActiveScalars(flowrecon::names::CriticalValue);
  return ug;
}

vtkSmartPointer<vtkPolyData> UnstableManifoldsBlock(const FlowComplex& fc)
{
  std::vector<Point3> pts;
  std::size_t corners = 0;
  for (const FlowLine& line : fc.FlowLines)
  {
    corners += line.Points.size();
  }
  pts.reserve(corners);
  vtkNew<vtkCellArray> lines;
  if (corners < static_cast<std::size_t>(INT32_MAX))
  {
    lines->Use32BitStorage(); // half the connectivity's memory
  }
  lines->AllocateExact(static_cast<vtkIdType>(fc.FlowLines.size()), static_cast<vtkIdType>(corners));
  auto nodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId); // node ids fit
  auto target = NamedArray<vtkTypeInt32Array>(flowrecon::names::TargetNodeId);
  std::vector<vtkIdType> ids;
  for (const FlowLine& line : fc.FlowLines)
  {
    ids.clear();
    for (const Point3& p : line.Points)
    {
      ids.push_back(static_cast<vtkIdType>(pts.size()));
      pts.push_back(p);
    }
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    nodeId->InsertNextValue(static_cast<std::int32_t>(line.Node));
    target->InsertNextValue(static_cast<std::int32_t>(line.Target));
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(pts));
  pd->SetLines(lines);
  pd->GetCellData()->AddArray(nodeId);
  pd->GetCellData()->AddArray(target);
  return pd;
}

} // namespace

void AddReport(const FlowComplex& fc, vtkFieldData* fd)
{
  const auto n = fc.CountByIndex();
  auto counts = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeCountByIndex, 4);
  const vtkIdType c[4] = { n[0], n[1], n[2], n[3] };
  counts->InsertNextTypedTuple(c);
  fd->AddArray(counts);
  auto scalar = [&](const char* name, vtkIdType v) {
    auto a = NamedArray<vtkIdTypeArray>(name);
    a->InsertNextValue(v);
    fd->AddArray(a);
  };
  scalar("EulerCharacteristic", n[0] - n[1] + n[2] - n[3]);
  scalar("ArcCount", static_cast<vtkIdType>(fc.Arcs.size()));
  scalar("InfinityNodeId", fc.InfinityNode);
  scalar("InputPointCount", fc.Report.InputPoints);
  scalar("DuplicatePointCount", fc.Report.DuplicatePoints);
  scalar("RightAngleCount", fc.Report.RightAngles);
  scalar("ApexOnSphereCount", fc.Report.ApexOnSphere);
  scalar("WalkTieCount", fc.Report.WalkTies);
  scalar("ExactFallbackCount", fc.Report.ExactFallbacks);
  auto attempts = NamedArray<vtkIntArray>("PerturbationAttempts");
  attempts->InsertNextValue(fc.Report.Attempts);
  fd->AddArray(attempts);
  // With the attempts, what a later stage needs to redo the triangulation.
  scalar("PerturbationSeed", static_cast<vtkIdType>(fc.Report.Seed));
  scalar("PerturbedValueCount", fc.Report.PerturbedValues);
  auto magnitude = NamedArray<vtkDoubleArray>("PerturbationMagnitude");
  magnitude->InsertNextValue(fc.Report.PerturbationMagnitude);
  fd->AddArray(magnitude);
  auto timings = NamedArray<vtkDoubleArray>("Timings", 6);
  const char* phases[6] = { "Delaunay", flowrecon::names::CriticalPoints, flowrecon::names::StableManifolds, flowrecon::names::UnstableManifolds,
    "Assembly", "Total" };
  for (int k = 0; k < 6; ++k)
  {
    timings->SetComponentName(k, phases[k]);
  }
  const double t[6] = { fc.Time.Delaunay, fc.Time.CriticalPoints, fc.Time.StableManifolds,
    fc.Time.UnstableManifolds, fc.Time.Assembly, fc.Time.Total };
  timings->InsertNextTypedTuple(t);
  fd->AddArray(timings);
}

void RequireMemoryForVTK(const FlowComplex& fc)
{
  const double bytes = 60.0 * static_cast<double>(fc.Arcs.size()) +
    150.0 * static_cast<double>(fc.Nodes.size()) +
    200.0 * static_cast<double>(fc.Triangles.size() + fc.Tetrahedra.size());
  RequireMemory(bytes,
    "the VTK output of the flow complex of " + std::to_string(fc.Report.InputPoints) +
      " points (" + std::to_string(fc.Arcs.size()) + " arcs)",
    "use 'flowrecon reconstruct', which keeps the complex in its compact form, or fewer points");
}

void ToMultiBlock(const FlowComplex& fc, vtkMultiBlockDataSet* output, const Progress& progress)
{
  // Each block's share of the progress: its number of items (nodes, arcs,
  // cells, flow-line points), which is what its copy costs.
  double points = 0;
  for (const FlowLine& line : fc.FlowLines)
  {
    points += static_cast<double>(line.Points.size());
  }
  const double share[4] = { static_cast<double>(fc.Nodes.size()),
    static_cast<double>(fc.Arcs.size()),
    static_cast<double>(fc.Nodes.size() + fc.Triangles.size() + fc.Tetrahedra.size()), points };
  const double total = share[0] + share[1] + share[2] + share[3] + 1;
  const double at[4] = { 0, share[0] / total, (share[0] + share[1]) / total,
    (share[0] + share[1] + share[2]) / total };
  progress(at[0], "VTK output: critical points");
  vtkSmartPointer<vtkDataObject> blocks[5];
  blocks[0] = CriticalPointsBlock(fc);
  progress(at[1], "VTK output: Hasse diagram");
  blocks[1] = HasseDiagramBlock(fc);
  progress(at[2], "VTK output: stable manifolds");
  blocks[2] = StableManifoldsBlock(fc, progress.Range(at[2], at[3]));
  progress(at[3], "VTK output: unstable manifolds");
  blocks[3] = UnstableManifoldsBlock(fc);
  blocks[4] = GabrielEdgesBlock(fc);
  const char* names[5] = { flowrecon::names::CriticalPoints, flowrecon::names::HasseDiagram,
    flowrecon::names::StableManifolds, flowrecon::names::UnstableManifolds,
    flowrecon::names::GabrielEdges };
  output->SetNumberOfBlocks(5);
  for (unsigned int b = 0; b < 5; ++b)
  {
    output->SetBlock(b, blocks[b]);
    output->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), names[b]);
  }
  AddReport(fc, blocks[0]->GetFieldData());
  AddReport(fc, output->GetFieldData());
  if (!fc.DeferredPatches.empty())
  {
    // The HasseDiagram block then lacks the 1-2 arcs into these nodes, every
    // one of ratio >= DeferralRatio (FlowComplex::DeferredPatches).
    auto* cp = vtkPolyData::SafeDownCast(blocks[0]);
    auto deferred = NamedArray<vtkUnsignedCharArray>(flowrecon::names::Deferred);
    deferred->SetNumberOfTuples(static_cast<vtkIdType>(fc.Nodes.size()));
    deferred->FillValue(0);
    for (const Id node : fc.DeferredPatches)
    {
      deferred->SetValue(node, 1);
    }
    cp->GetPointData()->AddArray(deferred);
    auto ratio = NamedArray<vtkDoubleArray>(flowrecon::names::DeferralRatio);
    ratio->InsertNextValue(fc.DeferralRatio);
    cp->GetFieldData()->AddArray(ratio);
    output->GetFieldData()->AddArray(ratio);
  }
  progress(1, "VTK output");
}

void ReplaceHasseDiagram(
  vtkMultiBlockDataSet* input, const FlowComplex& fc, vtkMultiBlockDataSet* output)
{
  output->Initialize();
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  output->SetNumberOfBlocks(input->GetNumberOfBlocks());
  for (unsigned int b = 0; b < input->GetNumberOfBlocks(); ++b)
  {
    vtkInformation* meta = input->HasMetaData(b) ? input->GetMetaData(b) : nullptr;
    const char* name = meta ? meta->Get(vtkCompositeDataSet::NAME()) : nullptr;
    vtkDataObject* block = input->GetBlock(b);
    vtkSmartPointer<vtkDataObject> copy;
    if (name && std::strcmp(name, flowrecon::names::HasseDiagram) == 0)
    {
      copy = HasseDiagramBlock(fc);
    }
    else if (block)
    {
      copy = vtk::TakeSmartPointer(block->NewInstance());
      copy->ShallowCopy(block);
    }
    output->SetBlock(b, copy);
    if (meta)
    {
      output->GetMetaData(b)->Copy(meta);
    }
  }
}

void SetDefaultScalars(vtkMultiBlockDataSet* output)
{
  for (unsigned int b = 0; b < output->GetNumberOfBlocks(); ++b)
  {
    auto* block = vtkDataSet::SafeDownCast(output->GetBlock(b));
    const char* name =
      output->HasMetaData(b) ? output->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()) : nullptr;
    if (!block || !name)
    {
      continue;
    }
    const std::string blockName(name);
    if (blockName == names::CriticalPoints || blockName == names::SurvivingCriticalPoints)
    {
      block->GetPointData()->SetActiveScalars(names::Index);
    }
    else if (blockName == names::StableManifolds || blockName == names::GabrielEdges ||
      blockName == names::SurvivingGabrielEdges)
    {
      block->GetCellData()->SetActiveScalars(names::Index);
    }
    else if (blockName == names::PersistencePairs)
    {
      block->GetCellData()->SetActiveScalars(nullptr);
    }
  }
}

} // namespace flowrecon
