#include "CompactConversion.h"

#include "ContractArrays.h"
#include "FlowReconNames.h"
#include "HugePageArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cstdint>

namespace flowrecon
{

namespace
{

/// The cells' offsets and point ids in `Ids` (32-bit ids when they fit:
/// half the memory that a t_r change writes and faults in).
template <class Ids>
vtkSmartPointer<vtkCellArray> CellArray(const CompactComplex& compact)
{
  const vtkIdType cells = static_cast<vtkIdType>(compact.NumberOfCells());
  vtkNew<Ids> offsets, connectivity;
  SetNumberOfTuplesOnHugePages(offsets.Get(), cells + 1);
  SetNumberOfTuplesOnHugePages(connectivity.Get(), static_cast<vtkIdType>(compact.Vertices.size() +
    2 * compact.Edges.size() + 3 * compact.Triangles.size() + 4 * compact.Tetrahedra.size()));
  auto* offset = offsets->GetPointer(0);
  auto* point = connectivity->GetPointer(0);
  using Value = typename Ids::ValueType;
  vtkIdType c = 0, at = 0;
  const auto add = [&](const Id* v, int n) {
    offset[c++] = static_cast<Value>(at);
    for (int k = 0; k < n; ++k)
    {
      point[at++] = static_cast<Value>(v[k]);
    }
  };
  for (const Id& v : compact.Vertices)
  {
    add(&v, 1);
  }
  for (const auto& e : compact.Edges)
  {
    add(e.data(), 2);
  }
  for (const auto& t : compact.Triangles)
  {
    add(t.data(), 3);
  }
  for (const auto& t : compact.Tetrahedra)
  {
    add(t.data(), 4);
  }
  offset[c] = static_cast<Value>(at);
  auto cellArray = vtkSmartPointer<vtkCellArray>::New();
  cellArray->SetData(offsets, connectivity);
  return cellArray;
}

} // namespace

void CompactCellsToVTK(const CompactComplex& compact, const std::vector<Point3>& samples,
  const std::vector<Node>& nodes, const std::vector<double>& nodeThreshold,
  vtkUnstructuredGrid* grid, vtkPoints* points)
{
  const vtkIdType cells = static_cast<vtkIdType>(compact.NumberOfCells());
  const vtkIdType corners = static_cast<vtkIdType>(compact.Vertices.size() +
    2 * compact.Edges.size() + 3 * compact.Triangles.size() + 4 * compact.Tetrahedra.size());
  const vtkIdType pointCount = points ? points->GetNumberOfPoints() : static_cast<vtkIdType>(samples.size());
  // Filled through raw pointers: a t_r change in ParaView writes millions of
  // cells, and InsertNextCell and SetValue per cell took most of that.
  const vtkSmartPointer<vtkCellArray> cellArray =
    std::max(corners, pointCount) < static_cast<vtkIdType>(INT32_MAX)
    ? CellArray<vtkTypeInt32Array>(compact)
    : CellArray<vtkTypeInt64Array>(compact);
  vtkNew<vtkUnsignedCharArray> types;
  SetNumberOfTuplesOnHugePages(types.Get(), cells);
  auto nodeId = NamedArray<vtkIntArray>(names::NodeId);
  auto index = NamedArray<vtkIntArray>(names::Index);
  auto threshold = NamedArray<vtkDoubleArray>(names::Threshold);
  auto claims = NamedArray<vtkIntArray>(names::Claims);
  for (vtkIntArray* a : { nodeId.Get(), index.Get(), claims.Get() })
  {
    SetNumberOfTuplesOnHugePages(a, cells);
  }
  SetNumberOfTuplesOnHugePages(threshold.Get(), cells);
  unsigned char* type = types->GetPointer(0);
  int* node = nodeId->GetPointer(0);
  int* nodeIndex = index->GetPointer(0);
  double* nodeThresholds = threshold->GetPointer(0);
  int* claimed = claims->GetPointer(0);
  vtkIdType c = 0;
  const bool ordered = compact.TriangleThreshold.size() == compact.Triangles.size();
  // A sample, an edge and a triangle stand for nodes of index 0, 1 and 2; a
  // tetrahedron for a maximum or a filled void's wall (read from the node).
  const auto add = [&](int n, Id id, unsigned char cellType, int count) {
    type[c] = cellType;
    node[c] = static_cast<int>(id);
    nodeIndex[c] = n < 4 ? n - 1 : nodes[id].Index;
    nodeThresholds[c] = n == 3 && ordered ? 0.0 : nodeThreshold[id];
    claimed[c] = count;
    ++c;
  };
  for (const Id id : compact.VertexNode)
  {
    add(1, id, VTK_VERTEX, 1);
  }
  for (const Id id : compact.EdgeNode)
  {
    add(2, id, VTK_LINE, 1);
  }
  for (std::size_t k = 0; k < compact.Triangles.size(); ++k)
  {
    add(3, compact.TriangleNode[k], VTK_TRIANGLE, compact.TriangleClaims[k]);
    nodeThresholds[c - 1] = ordered ? compact.TriangleThreshold[k] : nodeThresholds[c - 1];
  }
  for (const Id id : compact.TetrahedronNode)
  {
    add(4, id, VTK_TETRA, 1);
  }
  vtkNew<vtkFieldData> kept;
  kept->ShallowCopy(grid->GetFieldData());
  grid->Initialize();
  grid->SetFieldData(kept);
  if (points)
  {
    grid->SetPoints(points);
  }
  else
  {
    grid->SetPoints(MakePoints(samples));
  }
  grid->SetCells(types, cellArray);
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ nodeId, index, threshold, claims })
  {
    grid->GetCellData()->AddArray(a);
  }
  grid->GetCellData()->SetActiveScalars(names::Index);
}

void CompactToVTK(const CompactComplex& compact, const std::vector<Point3>& samples,
  const std::vector<Node>& nodes, const std::vector<double>& nodeThreshold,
  const std::array<Id, 4>& betti, vtkUnstructuredGrid* grid)
{
  auto field = NamedArray<vtkIdTypeArray>(names::BettiNumbers);
  for (int d = 0; d < 3; ++d)
  {
    field->InsertNextValue(static_cast<vtkIdType>(betti[d]));
  }
  grid->GetFieldData()->Initialize();
  grid->GetFieldData()->AddArray(field);
  CompactCellsToVTK(compact, samples, nodes, nodeThreshold, grid);
  const std::pair<const char*, Id> counts[3] = { { names::SharedTriangles, compact.SharedTriangles },
    { names::RevisitedTriangles, compact.RevisitedTriangles },
    { names::FilledVoids, compact.FilledVoids } };
  for (const auto& count : counts)
  {
    auto a = NamedArray<vtkIdTypeArray>(count.first);
    a->InsertNextValue(static_cast<vtkIdType>(count.second));
    grid->GetFieldData()->AddArray(a);
  }
}

} // namespace flowrecon
