#include "FlowComplexConversion.h"

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
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace flowrecon
{

namespace
{

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

template <class A>
vtkNew<A> NamedArray(const char* name, int components = 1)
{
  vtkNew<A> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  return a;
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
  auto nodeId = NamedArray<vtkIdTypeArray>("NodeId");
  auto index = NamedArray<vtkIntArray>("Index");
  auto value = NamedArray<vtkDoubleArray>("CriticalValue");
  auto simplex = NamedArray<vtkIdTypeArray>("Simplex", 4);
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
  pd->GetPointData()->SetActiveScalars("CriticalValue");
  return pd;
}

double Diagonal(const FlowComplex& fc)
{
  double lo[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi[3] = { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (Id i = 0; i < fc.NumberOfInputPoints; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], fc.Points[i][k]);
      hi[k] = std::max(hi[k], fc.Points[i][k]);
    }
  }
  double d2 = 0;
  for (int k = 0; k < 3; ++k)
  {
    d2 += hi[k] > lo[k] ? (hi[k] - lo[k]) * (hi[k] - lo[k]) : 0;
  }
  return std::sqrt(d2);
}

vtkSmartPointer<vtkPolyData> HasseDiagramBlock(const FlowComplex& fc)
{
  // Two points per arc, so that an arc to infinity can end on a short outward
  // stub instead of a point that would distort the bounds.
  const double stub = 0.05 * Diagonal(fc);
  const Point3 centre = fc.InfinityNode >= 0 ? fc.Nodes[fc.InfinityNode].Location : Point3{};
  std::vector<Point3> pts;
  auto nodeId = NamedArray<vtkIdTypeArray>("NodeId");
  auto mult = NamedArray<vtkIntArray>("Multiplicity");
  auto ratio = NamedArray<vtkDoubleArray>("Ratio");
  auto lowerId = NamedArray<vtkIdTypeArray>("LowerNodeId");
  auto upperId = NamedArray<vtkIdTypeArray>("UpperNodeId");
  vtkNew<vtkCellArray> lines;
  for (const Arc& a : fc.Arcs)
  {
    const Node& lo = fc.Nodes[a.Lower];
    const Node& up = fc.Nodes[a.Upper];
    Point3 end = up.Location;
    if (up.IsInfinity())
    {
      Point3 d{ { lo.Location[0] - centre[0], lo.Location[1] - centre[1],
        lo.Location[2] - centre[2] } };
      const double n = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      for (int k = 0; k < 3; ++k)
      {
        end[k] = lo.Location[k] + (n > 0 ? d[k] / n * stub : (k == 2 ? stub : 0));
      }
    }
    const vtkIdType ids[2] = { static_cast<vtkIdType>(pts.size()),
      static_cast<vtkIdType>(pts.size() + 1) };
    pts.push_back(lo.Location);
    pts.push_back(end);
    lines->InsertNextCell(2, ids);
    nodeId->InsertNextValue(a.Lower);
    nodeId->InsertNextValue(a.Upper);
    mult->InsertNextValue(a.Multiplicity);
    // Ratios are >= 1 in exact arithmetic; rounding of nearly tied values must
    // not make them look smaller.
    ratio->InsertNextValue(lo.Value > 0 ? std::max(1.0, up.Value / lo.Value) : HUGE_VAL);
    lowerId->InsertNextValue(a.Lower);
    upperId->InsertNextValue(a.Upper);
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

vtkSmartPointer<vtkUnstructuredGrid> StableManifoldsBlock(const FlowComplex& fc)
{
  vtkNew<vtkUnstructuredGrid> ug;
  ug->SetPoints(MakePoints(fc.Points));
  auto original = NamedArray<vtkIdTypeArray>("vtkOriginalPointIds");
  original->SetNumberOfTuples(static_cast<vtkIdType>(fc.Points.size()));
  for (std::size_t i = 0; i < fc.Points.size(); ++i)
  {
    original->SetValue(static_cast<vtkIdType>(i),
      static_cast<Id>(i) < fc.NumberOfInputPoints ? static_cast<vtkIdType>(i) : -1);
  }
  ug->GetPointData()->AddArray(original);

  auto nodeId = NamedArray<vtkIdTypeArray>("NodeId");
  auto index = NamedArray<vtkIntArray>("Index");
  auto value = NamedArray<vtkDoubleArray>("CriticalValue");
  ug->AllocateExact(static_cast<vtkIdType>(fc.Nodes.size() + fc.Triangles.size() +
                      fc.Tetrahedra.size()),
    4);
  auto add = [&](int type, int n, const vtkIdType* ids, Id node) {
    ug->InsertNextCell(type, n, ids);
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
  ug->GetCellData()->SetActiveScalars("CriticalValue");
  return ug;
}

vtkSmartPointer<vtkPolyData> UnstableManifoldsBlock(const FlowComplex& fc)
{
  std::vector<Point3> pts;
  vtkNew<vtkCellArray> lines;
  auto nodeId = NamedArray<vtkIdTypeArray>("NodeId");
  auto target = NamedArray<vtkIdTypeArray>("TargetNodeId");
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
  auto counts = NamedArray<vtkIdTypeArray>("NodeCountByIndex", 4);
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
  auto magnitude = NamedArray<vtkDoubleArray>("PerturbationMagnitude");
  magnitude->InsertNextValue(fc.Report.PerturbationMagnitude);
  fd->AddArray(magnitude);
  auto timings = NamedArray<vtkDoubleArray>("Timings", 6);
  const char* phases[6] = { "Delaunay", "CriticalPoints", "StableManifolds", "UnstableManifolds",
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

void ToMultiBlock(const FlowComplex& fc, vtkMultiBlockDataSet* output)
{
  vtkSmartPointer<vtkDataObject> blocks[4] = { CriticalPointsBlock(fc), HasseDiagramBlock(fc),
    StableManifoldsBlock(fc), UnstableManifoldsBlock(fc) };
  const char* names[4] = { "CriticalPoints", "HasseDiagram", "StableManifolds",
    "UnstableManifolds" };
  output->SetNumberOfBlocks(4);
  for (unsigned int b = 0; b < 4; ++b)
  {
    output->SetBlock(b, blocks[b]);
    output->GetMetaData(b)->Set(vtkCompositeDataSet::NAME(), names[b]);
  }
  AddReport(fc, blocks[0]->GetFieldData());
  AddReport(fc, output->GetFieldData());
}

} // namespace flowrecon
