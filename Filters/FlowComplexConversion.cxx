#include "FlowComplexConversion.h"

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
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <unordered_map>

namespace flowrecon
{

namespace
{

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

vtkSmartPointer<vtkPoints> MakePoints(const std::vector<Point3>& pts)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), pts[i].data());
  }
  return points;
}

vtkSmartPointer<vtkPolyData> CriticalPointsBlock(const FlowComplex& fc)
{
  std::vector<Point3> locations;
  locations.reserve(fc.Nodes.size());
  auto nodeId = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeId);
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  auto simplex = NamedArray<vtkIdTypeArray>(flowrecon::names::Simplex, 4);
  vtkNew<vtkCellArray> verts;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& n = fc.Nodes[i];
    locations.push_back(n.Location);
    nodeId->InsertNextValue(static_cast<vtkIdType>(i));
    index->InsertNextValue(n.Index);
    value->InsertNextValue(n.Value);
    const vtkIdType s[4] = { n.Simplex[0], n.Simplex[1], n.Simplex[2], n.Simplex[3] };
    simplex->InsertNextTypedTuple(s);
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
  auto nodeId = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeId);
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  vtkNew<vtkCellArray> lines;
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
    nodeId->InsertNextValue(static_cast<vtkIdType>(i));
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

/// The samples' bounding-box diagonal, from the index-0 nodes (the distinct
/// samples), so that it needs no geometry.
double Diagonal(const FlowComplex& fc)
{
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Node& node : fc.Nodes)
  {
    for (int k = 0; node.Index == 0 && k < 3; ++k)
    {
      lo[k] = std::min(lo[k], node.Location[k]);
      hi[k] = std::max(hi[k], node.Location[k]);
    }
  }
  if (!(hi[0] >= lo[0]))
  {
    return 0;
  }
  // Halves and hypot: no overflow even for coordinates near the largest doubles.
  return 2 * std::hypot(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1], 0.5 * hi[2] - 0.5 * lo[2]);
}

vtkSmartPointer<vtkPolyData> HasseDiagramBlock(const FlowComplex& fc)
{
  // Point k is node k's critical point, shared by its arcs (a surface sample has
  // ~100 arcs per point: two points per arc would double the block); an arc to
  // infinity ends on a short outward stub of its own instead of a point that
  // would distort the bounds.
  const double stub = 0.05 * Diagonal(fc);
  const Point3 centre = fc.InfinityNode >= 0 ? fc.Nodes[fc.InfinityNode].Location : Point3{};
  const vtkIdType nodes = static_cast<vtkIdType>(fc.Nodes.size());
  const vtkIdType arcs = static_cast<vtkIdType>(fc.Arcs.size());
  std::vector<Point3> pts;
  pts.reserve(fc.Nodes.size());
  for (const Node& node : fc.Nodes)
  {
    pts.push_back(node.Location);
  }
  auto nodeId = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeId);
  auto mult = NamedArray<vtkIntArray>(flowrecon::names::Multiplicity);
  auto ratio = NamedArray<vtkDoubleArray>(flowrecon::names::Ratio);
  auto lowerId = NamedArray<vtkIdTypeArray>(flowrecon::names::LowerNodeId);
  auto upperId = NamedArray<vtkIdTypeArray>(flowrecon::names::UpperNodeId);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(arcs + 1);
  connectivity->SetNumberOfValues(2 * arcs);
  for (auto* a : { static_cast<vtkDataArray*>(mult), static_cast<vtkDataArray*>(ratio),
         static_cast<vtkDataArray*>(lowerId), static_cast<vtkDataArray*>(upperId) })
  {
    a->SetNumberOfTuples(arcs);
  }
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
    offsets->SetValue(c, 2 * c);
    connectivity->SetValue(2 * c, a.Lower);
    connectivity->SetValue(2 * c + 1, end);
    mult->SetValue(c, a.Multiplicity);
    // Ratios are >= 1 in exact arithmetic; rounding of nearly tied values must
    // not make them look smaller.
    ratio->SetValue(c, lo.Value > 0 ? std::max(1.0, up.Value / lo.Value) : HUGE_VAL);
    lowerId->SetValue(c, a.Lower);
    upperId->SetValue(c, a.Upper);
  }
  offsets->SetValue(arcs, 2 * arcs);
  nodeId->SetNumberOfValues(static_cast<vtkIdType>(pts.size()));
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(pts.size()); ++k)
  {
    nodeId->SetValue(k, k < nodes ? k : fc.InfinityNode); // stubs stand for infinity
  }
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
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

  auto nodeId = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeId);
  auto index = NamedArray<vtkIntArray>(flowrecon::names::Index);
  auto value = NamedArray<vtkDoubleArray>(flowrecon::names::CriticalValue);
  ug->AllocateExact(static_cast<vtkIdType>(fc.Nodes.size() + fc.Triangles.size() +
                      fc.Tetrahedra.size()),
    4);
  const double cells = static_cast<double>(fc.Nodes.size() + fc.Triangles.size() +
    fc.Tetrahedra.size()) + 1;
  auto add = [&](int type, int n, const vtkIdType* ids, Id node) {
    const vtkIdType k = ug->InsertNextCell(type, n, ids);
    if ((k & 0xFFFF) == 0xFFFF)
    {
      progress(static_cast<double>(k) / cells, "VTK output: stable manifolds");
    }
    nodeId->InsertNextValue(node);
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
  vtkNew<vtkCellArray> lines;
  auto nodeId = NamedArray<vtkIdTypeArray>(flowrecon::names::NodeId);
  auto target = NamedArray<vtkIdTypeArray>(flowrecon::names::TargetNodeId);
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
    nodeId->InsertNextValue(line.Node);
    target->InsertNextValue(line.Target);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(pts));
  pd->SetLines(lines);
  pd->GetCellData()->AddArray(nodeId);
  pd->GetCellData()->AddArray(target);
  return pd;
}

} // namespace

bool ExtractSamples(vtkDataObject* input, std::vector<Point3>& points, std::string& error)
{
  points.clear();
  if (auto* ds = vtkDataSet::SafeDownCast(input))
  {
    const vtkIdType n = ds->GetNumberOfPoints();
    points.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      ds->GetPoint(i, points[i].data());
    }
    return true;
  }
  if (auto* table = vtkTable::SafeDownCast(input))
  {
    vtkDataArray* cols[3] = { nullptr, nullptr, nullptr };
    const char* names[3][3] = { { "x", "points:0", "coordsx" }, { "y", "points:1", "coordsy" },
      { "z", "points:2", "coordsz" } };
    std::vector<vtkDataArray*> numeric;
    for (vtkIdType c = 0; c < table->GetNumberOfColumns(); ++c)
    {
      auto* arr = vtkDataArray::SafeDownCast(table->GetColumn(c));
      if (!arr || arr->GetNumberOfComponents() != 1)
      {
        continue;
      }
      numeric.push_back(arr);
      const std::string name = Lower(arr->GetName() ? arr->GetName() : "");
      for (int k = 0; k < 3; ++k)
      {
        for (const char* candidate : names[k])
        {
          if (!cols[k] && name == candidate)
          {
            cols[k] = arr;
          }
        }
      }
    }
    if (!(cols[0] && cols[1] && cols[2]))
    {
      if (numeric.size() < 3)
      {
        error = "the table has fewer than three numeric columns";
        return false;
      }
      std::copy(numeric.begin(), numeric.begin() + 3, cols);
    }
    const vtkIdType n = table->GetNumberOfRows();
    points.resize(static_cast<std::size_t>(n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        points[i][k] = cols[k]->GetComponent(i, 0);
      }
    }
    return true;
  }
  error = std::string("unsupported input type ") + (input ? input->GetClassName() : "(none)");
  return false;
}

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

namespace
{

// A one-component (or `components`) array of `n` tuples named `name`, else
// nullptr with a one-line `error`.
vtkDataArray* Required(vtkFieldData* data, const char* block, const char* name, int components,
  vtkIdType n, std::string& error)
{
  vtkDataArray* a = data ? data->GetArray(name) : nullptr;
  if (!a)
  {
    error = std::string("not a flow complex: block ") + block + " has no array " + name;
    return nullptr;
  }
  if (a->GetNumberOfComponents() != components || a->GetNumberOfTuples() != n)
  {
    error = std::string("block ") + block + ": array " + name + " has the wrong size";
    return nullptr;
  }
  return a;
}

Id IdValue(vtkDataArray* a, vtkIdType i, int component = 0)
{
  return static_cast<Id>(a->GetComponent(i, component));
}

// Exact coordinates as a hash key: constructed points are stored once per node,
// so the critical point of a node is found again by its bits.
struct PointHash
{
  std::size_t operator()(const Point3& p) const
  {
    std::size_t h = 0;
    for (double x : p)
    {
      std::uint64_t bits;
      std::memcpy(&bits, &x, sizeof bits);
      h ^= std::hash<std::uint64_t>()(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    }
    return h;
  }
};

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
  vtkDataArray* nodeId = Required(pd, block, flowrecon::names::NodeId, 1, n, error);
  vtkDataArray* index = nodeId ? Required(pd, block, flowrecon::names::Index, 1, n, error) : nullptr;
  vtkDataArray* value = index ? Required(pd, block, flowrecon::names::CriticalValue, 1, n, error) : nullptr;
  vtkDataArray* simplex = value ? Required(pd, block, flowrecon::names::Simplex, 4, n, error) : nullptr;
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
  vtkDataArray* lower = Required(cd, block, flowrecon::names::LowerNodeId, 1, m, error);
  vtkDataArray* upper = lower ? Required(cd, block, flowrecon::names::UpperNodeId, 1, m, error) : nullptr;
  vtkDataArray* mult = upper ? Required(cd, block, flowrecon::names::Multiplicity, 1, m, error) : nullptr;
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
  vtkDataArray* nodeId = Required(ug->GetCellData(), block, flowrecon::names::NodeId, 1, nc, error);
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
  if (!store)
  {
    return true; // fc.NumberOfInputPoints still says how many samples there are
  }
  // Critical points of nodes of index >= 1 are constructed points.
  std::unordered_map<Point3, Id, PointHash> constructed;
  for (Id i = fc.NumberOfInputPoints; i < np; ++i)
  {
    constructed.emplace(fc.Points[i], i);
  }
  fc.NodePoint.assign(fc.Nodes.size(), -1);
  for (Id i = 0; i < n; ++i)
  {
    const Node& node = fc.Nodes[i];
    if (node.Index == 0)
    {
      fc.NodePoint[i] = node.Simplex[0];
    }
    else if (!node.IsInfinity())
    {
      const auto it = constructed.find(node.Location);
      fc.NodePoint[i] = it == constructed.end() ? -1 : it->second;
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

vtkSmartPointer<vtkPolyData> PersistencePairsBlock(const FlowComplex& fc, const SimplificationResult& s)
{
  std::vector<Point3> pts;
  vtkNew<vtkCellArray> lines;
  auto ratio = NamedArray<vtkDoubleArray>(flowrecon::names::Ratio);
  auto birth = NamedArray<vtkDoubleArray>(flowrecon::names::Birth);
  auto death = NamedArray<vtkDoubleArray>(flowrecon::names::Death);
  auto type = NamedArray<vtkIntArray>(flowrecon::names::PairType);
  auto lowerId = NamedArray<vtkIdTypeArray>(flowrecon::names::LowerNodeId);
  auto upperId = NamedArray<vtkIdTypeArray>(flowrecon::names::UpperNodeId);
  for (const CancelledPair& p : s.Pairs)
  {
    const vtkIdType ids[2] = { static_cast<vtkIdType>(pts.size()),
      static_cast<vtkIdType>(pts.size() + 1) };
    pts.push_back(fc.Nodes[p.Lower].Location);
    pts.push_back(fc.Nodes[p.Upper].Location);
    lines->InsertNextCell(2, ids);
    ratio->InsertNextValue(p.Ratio);
    birth->InsertNextValue(p.Birth);
    death->InsertNextValue(p.Death);
    type->InsertNextValue(p.PairType);
    lowerId->InsertNextValue(p.Lower);
    upperId->InsertNextValue(p.Upper);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(MakePoints(pts));
  pd->SetLines(lines);
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(ratio), static_cast<vtkDataArray*>(birth),
         static_cast<vtkDataArray*>(death), static_cast<vtkDataArray*>(type),
         static_cast<vtkDataArray*>(lowerId), static_cast<vtkDataArray*>(upperId) })
  {
    pd->GetCellData()->AddArray(a);
  }
  pd->GetCellData()->SetActiveScalars(flowrecon::names::Ratio);
  return pd;
}

} // namespace

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
    if (blockName == names::CriticalPoints)
    {
      block->GetPointData()->SetActiveScalars(names::Index);
    }
    else if (blockName == names::StableManifolds || blockName == names::GabrielEdges)
    {
      block->GetCellData()->SetActiveScalars(names::Index);
    }
    else if (blockName == names::PersistencePairs)
    {
      block->GetCellData()->SetActiveScalars(nullptr);
    }
  }
}

vtkDataObject* NamedBlock(vtkMultiBlockDataSet* input, const char* name)
{
  if (!input)
  {
    return nullptr;
  }
  for (unsigned int b = 0; b < input->GetNumberOfBlocks(); ++b)
  {
    vtkInformation* meta = input->HasMetaData(b) ? input->GetMetaData(b) : nullptr;
    const char* blockName = meta ? meta->Get(vtkCompositeDataSet::NAME()) : nullptr;
    if (blockName && std::strcmp(blockName, name) == 0)
    {
      return input->GetBlock(b);
    }
  }
  return nullptr;
}

bool FromMultiBlock(
  vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error, bool diagramOnly)
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
    !ReadStableManifolds(sm, fc, error, !diagramOnly))
  {
    fc = FlowComplex();
    return false;
  }
  auto* um = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::UnstableManifolds));
  if (um && !ReadFlowLines(um, fc, error, !diagramOnly))
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

void AddSimplification(const FlowComplex& fc, const SimplificationResult& s, double threshold,
  vtkMultiBlockDataSet* output)
{
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(output, flowrecon::names::CriticalPoints));
  auto* sm = vtkUnstructuredGrid::SafeDownCast(NamedBlock(output, flowrecon::names::StableManifolds));
  if (cp)
  {
    vtkDataArray* nodeId = cp->GetPointData()->GetArray(flowrecon::names::NodeId);
    auto cancelled = NamedArray<vtkUnsignedCharArray>(flowrecon::names::Cancelled);
    cancelled->SetNumberOfTuples(cp->GetNumberOfPoints());
    for (vtkIdType i = 0; i < cp->GetNumberOfPoints(); ++i)
    {
      cancelled->SetValue(i, s.Survives[IdValue(nodeId, i)] ? 0 : 1);
    }
    cp->GetPointData()->AddArray(cancelled);
  }
  auto* ge = vtkPolyData::SafeDownCast(NamedBlock(output, flowrecon::names::GabrielEdges));
  vtkDataArray* edgeNode = ge ? ge->GetCellData()->GetArray(flowrecon::names::NodeId) : nullptr;
  if (edgeNode && edgeNode->GetNumberOfTuples() == ge->GetNumberOfCells())
  {
    auto cancelled = NamedArray<vtkUnsignedCharArray>(flowrecon::names::Cancelled);
    cancelled->SetNumberOfTuples(ge->GetNumberOfCells());
    for (vtkIdType c = 0; c < ge->GetNumberOfCells(); ++c)
    {
      const Id node = IdValue(edgeNode, c);
      const bool known = node >= 0 && node < static_cast<Id>(s.Survives.size());
      cancelled->SetValue(c, known && !s.Survives[node] ? 1 : 0);
    }
    ge->GetCellData()->AddArray(cancelled);
  }
  if (sm)
  {
    vtkDataArray* nodeId = sm->GetCellData()->GetArray(flowrecon::names::NodeId);
    auto owner = NamedArray<vtkIdTypeArray>(flowrecon::names::Owner);
    owner->SetNumberOfTuples(sm->GetNumberOfCells());
    for (vtkIdType c = 0; c < sm->GetNumberOfCells(); ++c)
    {
      const Id node = IdValue(nodeId, c);
      const bool none = s.OwnersBegin(node) == s.OwnersEnd(node);
      owner->SetValue(c, s.Survives[node] ? node : (none ? -1 : *s.OwnersBegin(node)));
    }
    sm->GetCellData()->AddArray(owner);
  }
  auto offsets = NamedArray<vtkIdTypeArray>("OwnerOffsets");
  for (Id o : s.OwnerOffsets)
  {
    offsets->InsertNextValue(o);
  }
  auto owners = NamedArray<vtkIdTypeArray>("Owners");
  for (Id o : s.Owners)
  {
    owners->InsertNextValue(o);
  }
  auto tp = NamedArray<vtkDoubleArray>("PersistenceThreshold");
  tp->InsertNextValue(threshold);
  auto pairs = NamedArray<vtkIdTypeArray>("CancelledPairCount");
  pairs->InsertNextValue(static_cast<vtkIdType>(s.Pairs.size()));
  // What a replay of the cancellations on deferred patches needs (recorded when
  // the complex has some): per pair, its odd lowers and its direct owners.
  std::vector<vtkSmartPointer<vtkIdTypeArray>> replay;
  if (s.HasLowers)
  {
    for (const auto& rows : { std::make_pair(flowrecon::names::PairLowerOffsets, &s.LowerOffsets),
           std::make_pair(flowrecon::names::PairLowers, &s.Lowers),
           std::make_pair(flowrecon::names::PairOwnerOffsets, &s.DirectOwnerOffsets),
           std::make_pair(flowrecon::names::PairOwners, &s.DirectOwners) })
    {
      auto a = NamedArray<vtkIdTypeArray>(rows.first);
      a->SetNumberOfTuples(static_cast<vtkIdType>(rows.second->size()));
      for (std::size_t k = 0; k < rows.second->size(); ++k)
      {
        a->SetValue(static_cast<vtkIdType>(k), (*rows.second)[k]);
      }
      replay.push_back(a);
    }
  }
  for (vtkFieldData* fd : { cp ? cp->GetFieldData() : nullptr, output->GetFieldData() })
  {
    if (fd)
    {
      for (const auto& a : replay)
      {
        fd->AddArray(a);
      }
      fd->AddArray(offsets);
      fd->AddArray(owners);
      fd->AddArray(tp);
      fd->AddArray(pairs);
    }
  }
  const unsigned int b = output->GetNumberOfBlocks();
  output->SetNumberOfBlocks(b + 1);
  output->SetBlock(b, PersistencePairsBlock(fc, s));
  output->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), flowrecon::names::PersistencePairs);
}

namespace
{

/// Compressed rows of `fd` named `offsetsName` (`rows` + 1 increasing values
/// from 0) and `valuesName` (node ids), into `offsets` and `values`.
bool ReadRows(vtkFieldData* fd, const char* offsetsName, const char* valuesName, Id rows,
  Id nodeCount, std::vector<Id>& offsets, std::vector<Id>& values, std::string& error)
{
  vtkDataArray* o = fd->GetArray(offsetsName);
  vtkDataArray* v = fd->GetArray(valuesName);
  const std::string where = std::string("block CriticalPoints: ") + offsetsName + "/" + valuesName;
  if (!o || !v || o->GetNumberOfComponents() != 1 || v->GetNumberOfComponents() != 1 ||
    o->GetNumberOfTuples() != rows + 1)
  {
    error = where + " missing or not one row per cancelled pair";
    return false;
  }
  offsets.resize(static_cast<std::size_t>(rows + 1));
  for (vtkIdType k = 0; k <= rows; ++k)
  {
    offsets[k] = IdValue(o, k);
    if ((k == 0 && offsets[k] != 0) || (k > 0 && offsets[k] < offsets[k - 1]))
    {
      error = where + " offsets do not increase from 0";
      return false;
    }
  }
  if (offsets.back() != v->GetNumberOfTuples())
  {
    error = where + " offsets do not match the values";
    return false;
  }
  values.resize(static_cast<std::size_t>(v->GetNumberOfTuples()));
  for (vtkIdType k = 0; k < v->GetNumberOfTuples(); ++k)
  {
    values[k] = IdValue(v, k);
    if (values[k] < 0 || values[k] >= nodeCount)
    {
      error = where + " names a node that does not exist";
      return false;
    }
  }
  return true;
}

bool ReadReplay(vtkMultiBlockDataSet* input, vtkFieldData* fd, Id nodeCount,
  SimplificationResult& s, std::string& error)
{
  if (!fd->GetArray(flowrecon::names::PairLowerOffsets))
  {
    return true; // a simplification of a complete complex: nothing to replay
  }
  auto* pp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::PersistencePairs));
  vtkDataArray* count = fd->GetArray("CancelledPairCount");
  if (!pp || !count || count->GetNumberOfTuples() < 1)
  {
    error = "block PersistencePairs: missing, but the replay arrays need its pairs";
    return false;
  }
  const Id pairs = static_cast<Id>(count->GetComponent(0, 0));
  const char* block = flowrecon::names::PersistencePairs;
  vtkCellData* cd = pp->GetCellData();
  vtkDataArray* lower = Required(cd, block, flowrecon::names::LowerNodeId, 1, pairs, error);
  vtkDataArray* upper = lower ? Required(cd, block, flowrecon::names::UpperNodeId, 1, pairs, error) : nullptr;
  vtkDataArray* type = upper ? Required(cd, block, flowrecon::names::PairType, 1, pairs, error) : nullptr;
  vtkDataArray* ratio = type ? Required(cd, block, flowrecon::names::Ratio, 1, pairs, error) : nullptr;
  if (!ratio || pp->GetNumberOfCells() != pairs)
  {
    error = error.empty() ? std::string(block) + ": not one line per cancelled pair" : error;
    return false;
  }
  s.Pairs.resize(static_cast<std::size_t>(pairs));
  for (vtkIdType p = 0; p < pairs; ++p)
  {
    CancelledPair& c = s.Pairs[p];
    c.Lower = IdValue(lower, p);
    c.Upper = IdValue(upper, p);
    c.PairType = static_cast<int>(IdValue(type, p));
    c.Ratio = ratio->GetComponent(p, 0);
    if (c.Lower < 0 || c.Lower >= nodeCount || c.Upper < 0 || c.Upper >= nodeCount ||
      s.Survives[c.Lower] || s.Survives[c.Upper] || c.PairType < 1 || c.PairType > 2)
    {
      error = std::string("block ") + block + ": a pair whose nodes are not cancelled ones";
      return false;
    }
  }
  if (!ReadRows(fd, flowrecon::names::PairLowerOffsets, flowrecon::names::PairLowers, pairs,
        nodeCount, s.LowerOffsets, s.Lowers, error) ||
    !ReadRows(fd, flowrecon::names::PairOwnerOffsets, flowrecon::names::PairOwners, pairs,
      nodeCount, s.DirectOwnerOffsets, s.DirectOwners, error))
  {
    return false;
  }
  s.HasLowers = true;
  return true;
}

} // namespace

bool SimplificationFromMultiBlock(vtkMultiBlockDataSet* input, Id nodeCount,
  SimplificationResult& s, std::string& error)
{
  s = SimplificationResult();
  s.Survives.assign(static_cast<std::size_t>(nodeCount), true);
  s.OwnerOffsets.assign(static_cast<std::size_t>(nodeCount + 1), 0);
  error.clear();
  auto* cp = vtkPolyData::SafeDownCast(NamedBlock(input, flowrecon::names::CriticalPoints));
  vtkDataArray* cancelled = cp ? cp->GetPointData()->GetArray(flowrecon::names::Cancelled) : nullptr;
  if (!cancelled)
  {
    return false;
  }
  const char* block = flowrecon::names::CriticalPoints;
  vtkDataArray* nodeId = Required(cp->GetPointData(), block, flowrecon::names::NodeId, 1, nodeCount, error);
  vtkDataArray* offsets = nodeId
    ? Required(cp->GetFieldData(), block, "OwnerOffsets", 1, nodeCount + 1, error)
    : nullptr;
  vtkDataArray* owners = cp->GetFieldData()->GetArray("Owners");
  if (!offsets || !owners || cancelled->GetNumberOfTuples() != nodeCount)
  {
    error = error.empty() ? "block CriticalPoints: the simplification arrays are incomplete" : error;
    return false;
  }
  for (vtkIdType i = 0; i < nodeCount; ++i)
  {
    s.Survives[IdValue(nodeId, i)] = cancelled->GetComponent(i, 0) == 0;
    s.OwnerOffsets[i + 1] = IdValue(offsets, i + 1);
    if (s.OwnerOffsets[i + 1] < s.OwnerOffsets[i])
    {
      error = "block CriticalPoints: OwnerOffsets is not increasing";
      return false;
    }
  }
  if (s.OwnerOffsets[0] != 0 || s.OwnerOffsets.back() != owners->GetNumberOfTuples())
  {
    error = "block CriticalPoints: OwnerOffsets does not match Owners";
    return false;
  }
  s.Owners.resize(static_cast<std::size_t>(owners->GetNumberOfTuples()));
  for (vtkIdType k = 0; k < owners->GetNumberOfTuples(); ++k)
  {
    s.Owners[k] = IdValue(owners, k);
    if (s.Owners[k] < 0 || s.Owners[k] >= nodeCount)
    {
      error = "block CriticalPoints: Owners names a node that does not exist";
      return false;
    }
  }
  return ReadReplay(input, cp->GetFieldData(), nodeCount, s, error);
}

} // namespace flowrecon
