#include "ReconstructionConversion.h"

#include "FlowComplexConversion.h"
#include "MemoryGuard.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <utility>

namespace flowrecon
{

namespace
{

using flowrecon::NamedArray;

/// The arrays that describe an insertion, in all three outputs (cells of the
/// reconstruction, rows of the profile, sponsor arrows): Step, NodeId, Priority,
/// Extension, Sponsor.
struct InsertionArrays
{
  vtkSmartPointer<vtkIdTypeArray> Step = NamedArray<vtkIdTypeArray>("Step");
  vtkSmartPointer<vtkIdTypeArray> NodeId = NamedArray<vtkIdTypeArray>("NodeId");
  vtkSmartPointer<vtkDoubleArray> Priority = NamedArray<vtkDoubleArray>("Priority");
  vtkSmartPointer<vtkIntArray> Extension = NamedArray<vtkIntArray>("Extension");
  vtkSmartPointer<vtkIdTypeArray> Sponsor = NamedArray<vtkIdTypeArray>("Sponsor");

  void Append(Id step, Id node, const flowrecon::Insertion& in)
  {
    this->Step->InsertNextValue(step);
    this->NodeId->InsertNextValue(node);
    this->Priority->InsertNextValue(in.Priority);
    this->Extension->InsertNextValue(static_cast<int>(in.Kind));
    this->Sponsor->InsertNextValue(in.Sponsor);
  }
  std::array<vtkDataArray*, 5> All() const
  {
    return { { this->Step, this->NodeId, this->Priority, this->Extension, this->Sponsor } };
  }
};

} // namespace

CellsByNode::CellsByNode(const std::vector<Id>& cellNode, std::size_t nodes)
{
  this->Offsets.assign(nodes + 1, 0);
  for (Id node : cellNode)
  {
    ++this->Offsets[node + 1];
  }
  for (std::size_t i = 0; i < nodes; ++i)
  {
    this->Offsets[i + 1] += this->Offsets[i];
  }
  this->List.resize(cellNode.size());
  std::vector<Id> next(this->Offsets.begin(), this->Offsets.end() - 1);
  for (std::size_t c = 0; c < cellNode.size(); ++c)
  {
    this->List[next[cellNode[c]]++] = static_cast<Id>(c);
  }
}

void ReconstructionToVTK(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkUnstructuredGrid* grid, vtkTable* profile, vtkPolyData* arrows)
{
  const auto& steps = run.Nodes;
  // Nodes whose cells are in the reconstruction at t, in insertion order.
  std::vector<std::pair<Id, Id>> selected; // (step of the carrier, node)
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Id carrier = carriers[i];
    if (carrier >= 0 && run.Contains(carrier, t))
    {
      selected.emplace_back(steps[carrier].Step, static_cast<Id>(i));
    }
  }
  std::sort(selected.begin(), selected.end());
  {
    // VTK aborts the process when an array cannot grow: check first. About 110
    // bytes a cell and 40 a point, twice for the arrays' growth by doubling.
    double cells = static_cast<double>(selected.size());
    for (const auto& entry : selected)
    {
      const Id node = entry.second;
      cells += static_cast<double>(triangles.Offsets[node + 1] - triangles.Offsets[node] +
        tetrahedra.Offsets[node + 1] - tetrahedra.Offsets[node]);
    }
    RequireMemory(2 * (110 * cells + 40 * static_cast<double>(fc.Points.size())),
      "the VTK output of " + std::to_string(static_cast<long long>(cells)) + " cells",
      "lower the reconstruction threshold (or MaximumThreshold)");
  }
  const std::vector<int> multiplicity =
    flowrecon::EdgeMultiplicities(fc.Nodes, fc.Arcs, run, t);

  // Port 0: the cells, over the points they use (samples keep their input id).
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  auto original = NamedArray<vtkIdTypeArray>("vtkOriginalPointIds");
  std::vector<vtkIdType> pointOf(fc.Points.size(), -1);
  auto point = [&](Id p) {
    if (pointOf[p] < 0)
    {
      pointOf[p] = points->InsertNextPoint(fc.Points[p].data());
      original->InsertNextValue(p < fc.NumberOfInputPoints ? static_cast<vtkIdType>(p) : -1);
    }
    return pointOf[p];
  };
  grid->Initialize();
  InsertionArrays cellInsertion;
  auto index = NamedArray<vtkIntArray>("Index");
  auto value = NamedArray<vtkDoubleArray>("CriticalValue");
  auto threshold = NamedArray<vtkDoubleArray>("Threshold");
  auto owner = NamedArray<vtkIdTypeArray>("Owner");
  auto mult = NamedArray<vtkIntArray>("Multiplicity");
  grid->AllocateEstimate(static_cast<vtkIdType>(selected.size()), 3);
  auto add = [&](int type, int n, const vtkIdType* ids, Id node) {
    const Id carrier = carriers[node];
    const flowrecon::Insertion& in = steps[carrier];
    vtkIdType local[4];
    for (int k = 0; k < n; ++k)
    {
      local[k] = point(ids[k]);
    }
    grid->InsertNextCell(type, n, local);
    cellInsertion.Append(in.Step, node, in);
    index->InsertNextValue(fc.Nodes[node].Index);
    value->InsertNextValue(fc.Nodes[node].Value);
    threshold->InsertNextValue(in.Threshold);
    owner->InsertNextValue(carrier);
    mult->InsertNextValue(fc.Nodes[node].Index == 1 ? multiplicity[node] : 0);
  };
  for (const auto& entry : selected)
  {
    const Id node = entry.second;
    const flowrecon::Node& n = fc.Nodes[node];
    if (n.Index == 0)
    {
      const vtkIdType v = n.Simplex[0];
      add(VTK_VERTEX, 1, &v, node);
    }
    else if (n.Index == 1)
    {
      const vtkIdType e[2] = { n.Simplex[0], n.Simplex[1] };
      add(VTK_LINE, 2, e, node);
    }
    for (Id k = triangles.Offsets[node]; k < triangles.Offsets[node + 1]; ++k)
    {
      const auto& tri = fc.Triangles[triangles.List[k]];
      const vtkIdType ids[3] = { tri[0], tri[1], tri[2] };
      add(VTK_TRIANGLE, 3, ids, node);
    }
    for (Id k = tetrahedra.Offsets[node]; k < tetrahedra.Offsets[node + 1]; ++k)
    {
      const auto& tet = fc.Tetrahedra[tetrahedra.List[k]];
      const vtkIdType ids[4] = { tet[0], tet[1], tet[2], tet[3] };
      add(VTK_TETRA, 4, ids, node);
    }
  }
  grid->SetPoints(points);
  grid->GetPointData()->AddArray(original);
  for (vtkDataArray* a : cellInsertion.All())
  {
    grid->GetCellData()->AddArray(a);
  }
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ index, value, threshold, owner, mult })
  {
    grid->GetCellData()->AddArray(a);
  }
  grid->GetCellData()->SetActiveScalars("CriticalValue");

  // Port 1: the profile of the whole run.
  InsertionArrays rowInsertion;
  auto pIndex = NamedArray<vtkIntArray>("Index");
  auto pThreshold = NamedArray<vtkDoubleArray>("Threshold");
  for (std::size_t k = 0; k < run.Order.size(); ++k)
  {
    const Id node = run.Order[k];
    const flowrecon::Insertion& in = steps[node];
    rowInsertion.Append(static_cast<Id>(k), node, in);
    pIndex->InsertNextValue(fc.Nodes[node].Index);
    pThreshold->InsertNextValue(in.Threshold);
  }
  profile->Initialize();
  for (vtkDataArray* a : rowInsertion.All())
  {
    profile->AddColumn(a);
  }
  profile->AddColumn(pIndex);
  profile->AddColumn(pThreshold);

  // Port 2: sponsor -> node arrows of the current reconstruction.
  vtkNew<vtkPoints> arrowPoints;
  arrowPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  InsertionArrays arrowInsertion;
  for (const Id node : run.Order)
  {
    const flowrecon::Insertion& in = steps[node];
    if (!run.Contains(node, t) || in.Sponsor < 0)
    {
      continue;
    }
    const vtkIdType ids[2] = { arrowPoints->InsertNextPoint(fc.Nodes[in.Sponsor].Location.data()),
      arrowPoints->InsertNextPoint(fc.Nodes[node].Location.data()) };
    lines->InsertNextCell(2, ids);
    arrowInsertion.Append(in.Step, node, in);
  }
  arrows->Initialize();
  arrows->SetPoints(arrowPoints);
  arrows->SetLines(lines);
  for (vtkDataArray* a : arrowInsertion.All())
  {
    arrows->GetCellData()->AddArray(a);
  }
  arrows->GetCellData()->SetActiveScalars("Priority");
}

} // namespace flowrecon
