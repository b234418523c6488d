#include "ReconstructionConversion.h"

#include "FlowComplexConversion.h"
#include "FlowReconNames.h"
#include "HugePageArrays.h"
#include "MemoryGuard.h"
#include "ProfileJumps.h"
#include "TopologyConversion.h" // Unbounded

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkTypeInt32Array.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>

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
  // Steps and node ids in 32 bits (a flow complex has fewer than 2^31 nodes):
  // the profile has a row per step, millions, kept as long as the filter is.
  vtkSmartPointer<vtkTypeInt32Array> Step = NamedArray<vtkTypeInt32Array>(flowrecon::names::Step);
  vtkSmartPointer<vtkTypeInt32Array> NodeId = NamedArray<vtkTypeInt32Array>(flowrecon::names::NodeId);
  vtkSmartPointer<vtkDoubleArray> Priority = NamedArray<vtkDoubleArray>(flowrecon::names::Priority);
  vtkSmartPointer<vtkIntArray> Extension = NamedArray<vtkIntArray>(flowrecon::names::Extension);
  vtkSmartPointer<vtkTypeInt32Array> Sponsor = NamedArray<vtkTypeInt32Array>(flowrecon::names::Sponsor);

  /// `n` rows, to be filled by Set (millions of steps: no growth by copies).
  void Resize(vtkIdType n)
  {
    for (vtkDataArray* a : this->All())
    {
      a->SetNumberOfTuples(n);
    }
  }
  void Set(vtkIdType row, Id step, Id node, const flowrecon::Insertion& in)
  {
    this->Step->SetValue(row, static_cast<std::int32_t>(step));
    this->NodeId->SetValue(row, static_cast<std::int32_t>(node));
    this->Priority->SetValue(row, in.Priority);
    this->Extension->SetValue(row, static_cast<int>(in.Kind));
    this->Sponsor->SetValue(row, static_cast<std::int32_t>(in.Sponsor));
  }
  std::array<vtkDataArray*, 5> All() const
  {
    return { { this->Step, this->NodeId, this->Priority, this->Extension, this->Sponsor } };
  }
};

/// A named array of `n` values, to be filled by index.
template <class A>
vtkSmartPointer<A> Sized(const char* name, vtkIdType n)
{
  auto a = NamedArray<A>(name);
  a->SetNumberOfValues(n);
  return a;
}

/// Nodes whose cells are in the reconstruction at t, by insertion step of
/// their carrier, then by id: the order of the output cells. A counting sort
/// by step (nodes visited by id keep that order within a step): the same order
/// as sorting (step, node) pairs, in linear time (millions of nodes).
std::vector<Id> SelectedNodes(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t)
{
  auto stepOf = [&](std::size_t i) -> Id {
    const Id carrier = carriers[i];
    return carrier >= 0 && run.Contains(carrier, t) ? run.Nodes[carrier].Step : -1;
  };
  // Nodes before each step, then its next free place (steps index run.Order).
  std::vector<Id> start(run.Order.size() + 1, 0);
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Id step = stepOf(i);
    if (step >= 0)
    {
      if (static_cast<std::size_t>(step) + 1 >= start.size())
      {
        start.resize(static_cast<std::size_t>(step) + 2, 0);
      }
      ++start[step + 1];
    }
  }
  for (std::size_t k = 1; k < start.size(); ++k)
  {
    start[k] += start[k - 1];
  }
  std::vector<Id> nodes(static_cast<std::size_t>(start.back()));
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Id step = stepOf(i);
    if (step >= 0)
    {
      nodes[start[step]++] = static_cast<Id>(i);
    }
  }
  return nodes;
}

/// Calls f(vtkCellType, count, point ids, node) for each cell of `node`: its
/// vertex or Gabriel edge, its triangles, its tetrahedra (fc's point ids).
template <class F>
void ForEachCell(const FlowComplex& fc, Id node, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, F&& f)
{
  const flowrecon::Node& n = fc.Nodes[node];
  if (n.Index <= 1)
  {
    const Id v[2] = { n.Simplex[0], n.Simplex[1] };
    f(n.Index == 0 ? VTK_VERTEX : VTK_LINE, n.Index + 1, v, node);
  }
  for (const Id j : triangles.Row(node))
  {
    f(VTK_TRIANGLE, 3, fc.Triangles[j].data(), node);
  }
  for (const Id j : tetrahedra.Row(node))
  {
    f(VTK_TETRA, 4, fc.Tetrahedra[j].data(), node);
  }
}

} // namespace

namespace
{

/// A view of the first `tuples` tuples of `a`: the same reference-counted buffer
/// (vtkAOSDataArrayTemplate::ShallowCopy), whose smaller size does not
/// reallocate it. No tuples: a new empty array (a zero size would reallocate
/// the shared buffer).
vtkSmartPointer<vtkDataArray> Prefix(vtkDataArray* a, vtkIdType tuples)
{
  auto p = vtk::TakeSmartPointer(a->NewInstance());
  if (tuples > 0)
  {
    p->ShallowCopy(a);
    p->SetNumberOfTuples(tuples);
  }
  else
  {
    p->SetName(a->GetName());
    p->SetNumberOfComponents(a->GetNumberOfComponents());
  }
  return p;
}

} // namespace

void MarkProfile(vtkTable* profile, double t)
{
  // The mark of t_r in the profile's chart: a horizontal line, so t on every row.
  // Made again at each t_r change: on 2 MB pages (HugePageArrays.h).
  auto mark = NamedArray<vtkDoubleArray>("t_r");
  SetNumberOfTuplesOnHugePages(mark.Get(), profile->GetNumberOfRows());
  mark->FillValue(t < Unbounded ? t : std::numeric_limits<double>::quiet_NaN());
  profile->RemoveColumnByName("t_r");
  profile->AddColumn(mark);
}

void ProfileJumpsToVTK(const FlowComplex& fc, const ReconstructionResult& run, std::size_t count, vtkTable* profile)
{
  std::vector<double> thresholds(run.Order.size());
  for (std::size_t k = 0; k < run.Order.size(); ++k)
  {
    thresholds[k] = run.Nodes[run.Order[k]].Threshold;
  }
  const std::vector<ProfileJump> jumps = LargestJumps(thresholds, count);
  const auto node = [&](const ProfileJump& jump) -> const Node& {
    return fc.Nodes[run.Order[jump.Step]];
  };
  auto location = NamedArray<vtkDoubleArray>(flowrecon::names::JumpLocation, 3);
  for (const ProfileJump& jump : jumps)
  {
    location->InsertNextTuple(node(jump).Location.data());
  }
  const vtkSmartPointer<vtkDataArray> columns[] = {
    Column<vtkIdTypeArray>(flowrecon::names::JumpStep, jumps, &ProfileJump::Step),
    Column<vtkDoubleArray>(flowrecon::names::JumpThresholdBefore, jumps, &ProfileJump::Before),
    Column<vtkDoubleArray>(flowrecon::names::JumpThresholdAfter, jumps, &ProfileJump::After),
    Column<vtkIdTypeArray>(flowrecon::names::JumpNodeId, jumps,
      [&](const ProfileJump& jump) { return run.Order[jump.Step]; }),
    Column<vtkIntArray>(flowrecon::names::JumpIndex, jumps,
      [&](const ProfileJump& jump) { return node(jump).Index; }),
    Column<vtkDoubleArray>(flowrecon::names::JumpCriticalValue, jumps,
      [&](const ProfileJump& jump) { return node(jump).Value; }),
    location
  };
  vtkFieldData* fd = profile->GetFieldData();
  for (vtkDataArray* a : columns)
  {
    fd->RemoveArray(a->GetName());
    if (count > 0)
    {
      fd->AddArray(a);
    }
  }
}

void GridBelow(
  vtkUnstructuredGrid* full, double t, const std::vector<int>& multiplicity, vtkUnstructuredGrid* out)
{
  auto* threshold =
    vtkDoubleArray::SafeDownCast(full->GetCellData()->GetArray(flowrecon::names::Threshold));
  auto* nodeId = vtkIntArray::SafeDownCast(full->GetCellData()->GetArray(flowrecon::names::NodeId));
  auto* index = vtkIntArray::SafeDownCast(full->GetCellData()->GetArray(flowrecon::names::Index));
  vtkCellArray* cells = full->GetCells();
  if (!threshold || !nodeId || !index || !cells || !full->GetPoints())
  {
    throw std::logic_error("GridBelow: not a grid of ReconstructionToVTK");
  }
  const vtkIdType n = full->GetNumberOfCells();
  const double* th = threshold->GetPointer(0);
  const vtkIdType kept = std::lower_bound(th, th + n, t) - th; // first Threshold >= t
  vtkDataArray* offsets = cells->GetOffsetsArray();
  vtkDataArray* connectivity = cells->GetConnectivityArray();
  const vtkIdType corners = static_cast<vtkIdType>(offsets->GetTuple1(kept));
  vtkIdType points = 0;
  if (auto* narrow = vtkTypeInt32Array::SafeDownCast(connectivity))
  {
    const std::int32_t* ids = narrow->GetPointer(0);
    points = corners > 0 ? *std::max_element(ids, ids + corners) + vtkIdType(1) : 0;
  }
  else
  {
    for (vtkIdType k = 0; k < corners; ++k)
    {
      points = std::max(points, static_cast<vtkIdType>(connectivity->GetTuple1(k)) + 1);
    }
  }
  vtkNew<vtkPoints> pts;
  pts->SetData(Prefix(full->GetPoints()->GetData(), points));
  vtkNew<vtkCellArray> cellArray;
  cellArray->SetData(Prefix(offsets, kept + 1), Prefix(connectivity, corners));
  const vtkSmartPointer<vtkDataArray> types = Prefix(full->GetCellTypesArray(), kept);
  out->Initialize();
  out->SetPoints(pts);
  out->SetCells(vtkUnsignedCharArray::SafeDownCast(types), cellArray);
  vtkPointData* pd = full->GetPointData();
  for (int a = 0; a < pd->GetNumberOfArrays(); ++a)
  {
    out->GetPointData()->AddArray(Prefix(pd->GetArray(a), points));
  }
  vtkCellData* cd = full->GetCellData();
  for (int a = 0; a < cd->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = cd->GetArray(a);
    if (std::strcmp(array->GetName(), flowrecon::names::Multiplicity) != 0)
    {
      out->GetCellData()->AddArray(Prefix(array, kept));
      continue;
    }
    auto mult = Sized<vtkIntArray>(flowrecon::names::Multiplicity, kept);
    const int* nodes = nodeId->GetPointer(0);
    const int* indices = index->GetPointer(0);
    for (vtkIdType c = 0; c < kept; ++c)
    {
      mult->SetValue(c, indices[c] == 1 ? multiplicity[nodes[c]] : 0);
    }
    out->GetCellData()->AddArray(mult);
  }
  if (vtkDataArray* scalars = cd->GetScalars())
  {
    out->GetCellData()->SetActiveScalars(scalars->GetName());
  }
}

namespace
{

/// The cells of `selected` in order (`cells`, `corners`: their numbers) as
/// offsets and connectivity of id array type A, over points numbered by first
/// use (`used`: fc's point of each), into `cellArray` and `types`. Filled
/// through raw pointers: millions of cells.
template <class A>
void FillCells(const FlowComplex& fc, const std::vector<Id>& selected, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkIdType cells, vtkIdType corners, vtkUnsignedCharArray* types,
  std::vector<Id>& used, vtkCellArray* cellArray)
{
  using T = typename A::ValueType;
  auto offsets = vtkSmartPointer<A>::New();
  auto connectivity = vtkSmartPointer<A>::New();
  offsets->SetNumberOfValues(cells + 1);
  connectivity->SetNumberOfValues(corners);
  T* const offset = offsets->GetPointer(0);
  T* const corner = connectivity->GetPointer(0);
  unsigned char* const type = types->GetPointer(0);
  std::vector<T> pointOf(fc.Points.size(), T(-1));
  used.reserve(fc.Points.size()); // address space only; no growth by copies
  vtkIdType c = 0, k = 0;
  for (const Id node : selected)
  {
    ForEachCell(fc, node, triangles, tetrahedra, [&](int cellType, int n, const Id* ids, Id) {
      offset[c] = static_cast<T>(k);
      type[c++] = static_cast<unsigned char>(cellType);
      for (int j = 0; j < n; ++j)
      {
        T& p = pointOf[ids[j]];
        if (p < 0)
        {
          p = static_cast<T>(used.size());
          used.push_back(ids[j]);
        }
        corner[k++] = p;
      }
    });
  }
  offset[c] = static_cast<T>(k);
  cellArray->SetData(offsets, connectivity);
}

void ReconstructionGrid(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkUnstructuredGrid* grid, const std::string& advice)
{
  const auto& steps = run.Nodes;
  const std::vector<Id> selected = SelectedNodes(fc, carriers, run, t);
  // Sizes first: VTK aborts the process when an array cannot be allocated, so
  // check that they fit, and fill preallocated arrays (millions of cells).
  vtkIdType cells = 0, corners = 0;
  for (const Id node : selected)
  {
    const int own = fc.Nodes[node].Index <= 1 ? 1 : 0; // vertex or edge
    const Id nt = triangles.RowSize(node);
    const Id nq = tetrahedra.RowSize(node);
    cells += own + nt + nq;
    corners += own * (fc.Nodes[node].Index + 1) + 3 * nt + 4 * nq;
  }
  // 32-bit ids (cells, points and nodes fit: the builder refuses 2^31 nodes):
  // a reconstructed solid has some 70 cells per sample, and 64-bit ids would be
  // a third of its memory.
  const bool narrow = corners < std::numeric_limits<std::int32_t>::max();
  {
    // What is allocated below, array by array (an estimate short by 7 B a cell
    // let VTK abort the process under a limit): per cell its type, offset,
    // seven int and three double arrays; per corner an id; per point of fc its
    // output id and source, per output point (at most as many) its coordinates
    // and original id; per node its edge multiplicity; and the profile's rows
    // (ProfileTable: 48 B). A twentieth more for the allocators' rounding.
    const double id = narrow ? 4 : 8;
    const double bytes = (1 + id + 7 * 4 + 3 * 8) * static_cast<double>(cells) +
      id * static_cast<double>(corners) +
      (id + 8 + 24 + 8) * static_cast<double>(fc.Points.size()) +
      4.0 * static_cast<double>(fc.Nodes.size()) + 48.0 * static_cast<double>(run.Order.size());
    RequireMemory(1.05 * bytes + (16 << 20),
      "the VTK output of " + std::to_string(cells) + " cells of a " +
        std::to_string(fc.NumberOfInputPoints) + "-point cloud",
      advice);
  }
  const std::vector<int> multiplicity =
    flowrecon::EdgeMultiplicities(fc.Nodes, fc.Arcs, run, t);

  // Port 0: the cells, over the points they use (samples keep their input id).
  auto types = vtkSmartPointer<vtkUnsignedCharArray>::New();
  types->SetNumberOfValues(cells);
  std::vector<Id> used; // fc point of each output point
  vtkNew<vtkCellArray> cellArray;
  if (narrow)
  {
    FillCells<vtkTypeInt32Array>(
      fc, selected, triangles, tetrahedra, cells, corners, types, used, cellArray);
  }
  else
  {
    FillCells<vtkIdTypeArray>(
      fc, selected, triangles, tetrahedra, cells, corners, types, used, cellArray);
  }
  auto step = Sized<vtkIntArray>(flowrecon::names::Step, cells);
  auto nodeId = Sized<vtkIntArray>(flowrecon::names::NodeId, cells);
  auto priority = Sized<vtkDoubleArray>(flowrecon::names::Priority, cells);
  auto extension = Sized<vtkIntArray>(flowrecon::names::Extension, cells);
  auto sponsor = Sized<vtkIntArray>(flowrecon::names::Sponsor, cells);
  auto index = Sized<vtkIntArray>(flowrecon::names::Index, cells);
  auto value = Sized<vtkDoubleArray>(flowrecon::names::CriticalValue, cells);
  auto threshold = Sized<vtkDoubleArray>(flowrecon::names::Threshold, cells);
  auto owner = Sized<vtkIntArray>(flowrecon::names::Owner, cells);
  auto mult = Sized<vtkIntArray>(flowrecon::names::Multiplicity, cells);
  // The cell data is per node: one run of equal values for its cells (one for
  // a vertex or an edge, hundreds for a patch or a cone).
  int* const ints[7] = { step->GetPointer(0), nodeId->GetPointer(0), extension->GetPointer(0),
    sponsor->GetPointer(0), index->GetPointer(0), owner->GetPointer(0), mult->GetPointer(0) };
  double* const doubles[3] = { priority->GetPointer(0), value->GetPointer(0),
    threshold->GetPointer(0) };
  vtkIdType c = 0;
  for (const Id node : selected)
  {
    const flowrecon::Node& n = fc.Nodes[node];
    const vtkIdType count =
      (n.Index <= 1 ? 1 : 0) + triangles.RowSize(node) + tetrahedra.RowSize(node);
    const Id carrier = carriers[node];
    const flowrecon::Insertion& in = steps[carrier];
    const int intValues[7] = { static_cast<int>(in.Step), static_cast<int>(node),
      static_cast<int>(in.Kind), static_cast<int>(in.Sponsor), n.Index,
      static_cast<int>(carrier), n.Index == 1 ? multiplicity[node] : 0 };
    const double doubleValues[3] = { in.Priority, n.Value, in.Threshold };
    for (int a = 0; a < 7; ++a)
    {
      std::fill_n(ints[a] + c, count, intValues[a]);
    }
    for (int a = 0; a < 3; ++a)
    {
      std::fill_n(doubles[a] + c, count, doubleValues[a]);
    }
    c += count;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(used.size()));
  auto original = Sized<vtkIdTypeArray>(flowrecon::names::OriginalPointIds, static_cast<vtkIdType>(used.size()));
  double* const xyz = vtkDoubleArray::SafeDownCast(points->GetData())->GetPointer(0);
  vtkIdType* const ids = original->GetPointer(0);
  for (std::size_t p = 0; p < used.size(); ++p)
  {
    std::copy_n(fc.Points[used[p]].data(), 3, xyz + 3 * p);
    ids[p] = used[p] < fc.NumberOfInputPoints ? static_cast<vtkIdType>(used[p]) : -1;
  }
  grid->Initialize();
  grid->SetPoints(points);
  grid->SetCells(types, cellArray);
  grid->GetPointData()->AddArray(original);
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{ step, nodeId, priority, extension,
         sponsor, index, value, threshold, owner, mult })
  {
    grid->GetCellData()->AddArray(a);
  }
  grid->GetCellData()->SetActiveScalars(flowrecon::names::CriticalValue);
}

/// Port 1: the profile of the whole run.
void ProfileTable(const FlowComplex& fc, const ReconstructionResult& run, double t, vtkTable* profile)
{
  const auto& steps = run.Nodes;
  const vtkIdType rows = static_cast<vtkIdType>(run.Order.size());
  InsertionArrays rowInsertion;
  rowInsertion.Resize(rows);
  auto pIndex = Sized<vtkIntArray>(flowrecon::names::Index, rows);
  auto pThreshold = Sized<vtkDoubleArray>(flowrecon::names::Threshold, rows);
  for (vtkIdType k = 0; k < rows; ++k)
  {
    const Id node = run.Order[k];
    const flowrecon::Insertion& in = steps[node];
    rowInsertion.Set(k, static_cast<Id>(k), node, in);
    pIndex->SetValue(k, fc.Nodes[node].Index);
    pThreshold->SetValue(k, in.Threshold);
  }
  profile->Initialize();
  for (vtkDataArray* a : rowInsertion.All())
  {
    profile->AddColumn(a);
  }
  profile->AddColumn(pIndex);
  profile->AddColumn(pThreshold);
  MarkProfile(profile, t);
}

/// Port 2: sponsor -> node arrows of the current reconstruction.
void SponsorArrows(const FlowComplex& fc, const ReconstructionResult& run, double t, vtkPolyData* arrows)
{
  const auto& steps = run.Nodes;
  vtkNew<vtkPoints> arrowPoints;
  arrowPoints->SetDataTypeToDouble();
  vtkNew<vtkCellArray> lines;
  InsertionArrays arrowInsertion;
  // Direction (node - sponsor at the sponsor's end, 0 at the node's) draws each
  // line as an arrow glyph of its own length; glyphs take point colours, hence
  // the point copy of Priority.
  auto direction = NamedArray<vtkDoubleArray>(flowrecon::names::Direction, 3);
  auto pointPriority = NamedArray<vtkDoubleArray>(flowrecon::names::Priority);
  auto drawn = [&](Id node) { return run.Contains(node, t) && steps[node].Sponsor >= 0; };
  // Counted first: millions of arrows fill preallocated arrays.
  vtkIdType n = 0;
  for (const Id node : run.Order)
  {
    n += drawn(node) ? 1 : 0;
  }
  // Filled through raw pointers: a t_r change in ParaView redraws every arrow,
  // and per-point virtual SetTuple/InsertNextCell calls were most of that.
  arrowPoints->SetNumberOfPoints(2 * n);
  arrowInsertion.Resize(n);
  direction->SetNumberOfTuples(2 * n);
  pointPriority->SetNumberOfValues(2 * n);
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(n + 1);
  connectivity->SetNumberOfValues(2 * n);
  double* const xyz = vtkDoubleArray::SafeDownCast(arrowPoints->GetData())->GetPointer(0);
  double* const dir = direction->GetPointer(0);
  double* const priority = pointPriority->GetPointer(0);
  vtkIdType* const offset = offsets->GetPointer(0);
  vtkIdType* const corner = connectivity->GetPointer(0);
  vtkIdType a = 0;
  for (const Id node : run.Order)
  {
    if (!drawn(node))
    {
      continue;
    }
    const flowrecon::Insertion& in = steps[node];
    const auto& from = fc.Nodes[in.Sponsor].Location;
    const auto& to = fc.Nodes[node].Location;
    for (int k = 0; k < 3; ++k)
    {
      xyz[6 * a + k] = from[k];
      xyz[6 * a + 3 + k] = to[k];
      dir[6 * a + k] = to[k] - from[k];
      dir[6 * a + 3 + k] = 0;
    }
    offset[a] = 2 * a;
    corner[2 * a] = 2 * a;
    corner[2 * a + 1] = 2 * a + 1;
    arrowInsertion.Set(a, in.Step, node, in);
    priority[2 * a] = in.Priority;
    priority[2 * a + 1] = in.Priority;
    ++a;
  }
  offset[n] = 2 * n;
  lines->SetData(offsets, connectivity);
  arrows->Initialize();
  arrows->SetPoints(arrowPoints);
  arrows->SetLines(lines);
  for (vtkDataArray* a : arrowInsertion.All())
  {
    arrows->GetCellData()->AddArray(a);
  }
  arrows->GetCellData()->SetActiveScalars(flowrecon::names::Priority);
  arrows->GetPointData()->AddArray(pointPriority);
  arrows->GetPointData()->SetVectors(direction);
}

} // namespace

void ReconstructionToVTK(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkUnstructuredGrid* grid, vtkTable* profile, vtkPolyData* arrows,
  const std::string& advice)
{
  if (grid)
  {
    ReconstructionGrid(fc, carriers, run, t, triangles, tetrahedra, grid, advice);
  }
  if (profile)
  {
    ProfileTable(fc, run, t, profile);
  }
  if (arrows)
  {
    SponsorArrows(fc, run, t, arrows);
  }
}

FilteredCells ReconstructionCells(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, std::vector<Id>* cellNodes, Id maximumCells)
{
  FilteredCells cells;
  if (cellNodes)
  {
    cellNodes->clear();
  }
  const std::vector<Id> nodes = SelectedNodes(fc, carriers, run, t);
  if (maximumCells >= 0)
  {
    Id count = 0;
    for (const Id node : nodes)
    {
      ForEachCell(fc, node, triangles, tetrahedra, [&](int, int, const Id*, Id) { ++count; });
    }
    if (count > maximumCells)
    {
      throw InputError(TooManyCells(count, maximumCells));
    }
  }
  for (const Id node : nodes)
  {
    const double threshold = run.Nodes[carriers[node]].Threshold;
    ForEachCell(fc, node, triangles, tetrahedra, [&](int, int n, const Id* ids, Id) {
      cells.Add(ids, n, threshold);
      if (cellNodes)
      {
        cellNodes->push_back(node);
      }
    });
  }
  return cells;
}

} // namespace flowrecon
