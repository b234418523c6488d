// VTK arrays on storage advised for 2 MB pages (HugePageArrays.h), and the
// compact output that a t_r change writes into them: an array so made must
// behave as one VTK sized itself (its tuples, its values, growing, copying,
// freeing), and the compact cells written through it must be the complex's,
// at sizes that take the huge-page path and sizes that do not.
#include "Check.h"

#include "CompactConversion.h"
#include "HugePageArrays.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <cstdint>
#include <vector>

namespace
{

using flowrecon::Id;

constexpr std::uintptr_t HugePage = std::uintptr_t(1) << 21;

template <class A>
void CheckArray(vtkIdType tuples, int components)
{
  using T = typename A::ValueType;
  vtkNew<A> a;
  a->SetNumberOfComponents(components);
  flowrecon::SetNumberOfTuplesOnHugePages(a.Get(), tuples);
  const vtkIdType values = tuples * components;
  CHECK(a->GetNumberOfTuples() == tuples);
  CHECK(a->GetNumberOfValues() == values);
  CHECK(a->GetNumberOfComponents() == components);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // The path taken: 2 MB-aligned storage from one huge page up, VTK's below.
  const bool spans = static_cast<std::uintptr_t>(values) * sizeof(T) >= HugePage;
  if (spans)
  {
    CHECK(reinterpret_cast<std::uintptr_t>(a->GetPointer(0)) % HugePage == 0);
  }
#endif
  T* p = a->GetPointer(0);
  for (vtkIdType k = 0; k < values; ++k)
  {
    p[k] = static_cast<T>(k % 97);
  }
  bool same = true;
  for (vtkIdType k = 0; k < values; ++k)
  {
    same = same && a->GetValue(k) == static_cast<T>(k % 97);
  }
  CHECK(same);
  // Growing by a tuple moves the values to VTK's own storage, and keeps them.
  for (int k = 0; k < components; ++k)
  {
    a->InsertNextValue(static_cast<T>(5));
  }
  CHECK(a->GetNumberOfTuples() == tuples + 1);
  CHECK(a->GetValue(values + components - 1) == static_cast<T>(5));
  same = true;
  for (vtkIdType k = 0; k < values; k += 1 + values / 1000)
  {
    same = same && a->GetValue(k) == static_cast<T>(k % 97);
  }
  CHECK(same);
  vtkNew<A> copy;
  copy->DeepCopy(a);
  CHECK(copy->GetNumberOfValues() == values + components);
  CHECK(values == 0 || copy->GetValue(values - 1) == a->GetValue(values - 1));
  // Sized again (a second t_r): the first storage is freed, the second fresh.
  flowrecon::SetNumberOfTuplesOnHugePages(a.Get(), tuples / 2);
  CHECK(a->GetNumberOfTuples() == tuples / 2);
}

/// A complex of `triangles` triangles and `tetrahedra` tetrahedra over `points`
/// samples, each cell's node and vertices told apart by its position.
flowrecon::CompactComplex Complex(std::size_t triangles, std::size_t tetrahedra, Id points)
{
  flowrecon::CompactComplex c;
  c.Vertices = { 0 };
  c.VertexNode = { 0 };
  c.Edges = { { 1, 2 } };
  c.EdgeNode = { 1 };
  for (std::size_t k = 0; k < triangles; ++k)
  {
    const Id a = static_cast<Id>(k) % points;
    c.Triangles.push_back({ a, (a + 1) % points, (a + 7) % points });
    c.TriangleNode.push_back(2);
    c.TriangleClaims.push_back(1 + static_cast<int>(k % 3));
  }
  for (std::size_t k = 0; k < tetrahedra; ++k)
  {
    const Id a = static_cast<Id>(3 * k) % points;
    c.Tetrahedra.push_back({ a, (a + 2) % points, (a + 5) % points, (a + 11) % points });
    c.TetrahedronNode.push_back(3);
  }
  return c;
}

void CheckCompactCells(std::size_t triangles, std::size_t tetrahedra)
{
  const Id points = 100003;
  const flowrecon::CompactComplex c = Complex(triangles, tetrahedra, points);
  std::vector<flowrecon::Node> nodes(4);
  for (int k = 0; k < 4; ++k)
  {
    nodes[static_cast<std::size_t>(k)].Index = k;
  }
  const std::vector<double> thresholds{ 0.0, 1.5, 2.5, 3.5 };
  vtkNew<vtkPoints> samples;
  samples->SetNumberOfPoints(points);
  vtkNew<vtkUnstructuredGrid> grid;
  flowrecon::CompactCellsToVTK(c, {}, nodes, thresholds, grid, samples);
  const vtkIdType cells = static_cast<vtkIdType>(2 + triangles + tetrahedra);
  CHECK(grid->GetNumberOfCells() == cells);
  CHECK(grid->GetNumberOfPoints() == points);
  vtkDataArray* node = grid->GetCellData()->GetArray("NodeId");
  vtkDataArray* index = grid->GetCellData()->GetArray("Index");
  vtkDataArray* threshold = grid->GetCellData()->GetArray("Threshold");
  vtkDataArray* claims = grid->GetCellData()->GetArray("Claims");
  CHECK(node && index && threshold && claims);
  if (!(node && index && threshold && claims) || grid->GetNumberOfCells() != cells)
  {
    return;
  }
  bool same = true;
  vtkNew<vtkIdList> ids;
  for (vtkIdType k = 0; k < cells; ++k)
  {
    grid->GetCellPoints(k, ids);
    std::vector<Id> want;
    int n = 0;
    if (k == 0)
    {
      want = { c.Vertices[0] };
      n = 0;
    }
    else if (k == 1)
    {
      want = { c.Edges[0][0], c.Edges[0][1] };
      n = 1;
    }
    else if (k < static_cast<vtkIdType>(2 + triangles))
    {
      const auto& t = c.Triangles[static_cast<std::size_t>(k - 2)];
      want = { t[0], t[1], t[2] };
      n = 2;
      same = same && claims->GetTuple1(k) == c.TriangleClaims[static_cast<std::size_t>(k - 2)];
    }
    else
    {
      const auto& t = c.Tetrahedra[static_cast<std::size_t>(k - 2 - static_cast<vtkIdType>(triangles))];
      want = { t[0], t[1], t[2], t[3] };
      n = 3;
    }
    same = same && ids->GetNumberOfIds() == static_cast<vtkIdType>(want.size());
    for (vtkIdType j = 0; same && j < ids->GetNumberOfIds(); ++j)
    {
      same = ids->GetId(j) == want[static_cast<std::size_t>(j)];
    }
    same = same && node->GetTuple1(k) == n && index->GetTuple1(k) == n &&
      threshold->GetTuple1(k) == thresholds[static_cast<std::size_t>(n)];
  }
  CHECK(same);
}

} // namespace

int main()
{
  for (const vtkIdType tuples : { 0, 1, 1000, 524287, 524288, 3000001 })
  {
    CheckArray<vtkIntArray>(tuples, 1);
    CheckArray<vtkDoubleArray>(tuples, 3);
    CheckArray<vtkUnsignedCharArray>(tuples, 1);
  }
  // Below one huge page for every array, and above it for all of them.
  CheckCompactCells(100, 10);
  CheckCompactCells(700000, 300000);
  return check::Finish("TestHugePageArrays");
}
