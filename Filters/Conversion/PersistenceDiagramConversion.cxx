#include "PersistenceDiagramConversion.h"

#include "FlowComplexConversion.h" // NamedArray
#include "FlowReconNames.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <stdexcept>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace flowrecon
{

namespace
{

// The cell data of a diagram; Append adds one line with its values.
struct DiagramCells
{
  explicit DiagramCells(vtkUnstructuredGrid* grid)
    : Grid(grid)
  {
    vtkCellData* cd = grid->GetCellData();
    this->Id = vtkIntArray::SafeDownCast(cd->GetArray(flowrecon::names::PairIdentifier));
    this->Type = vtkIntArray::SafeDownCast(cd->GetArray(flowrecon::names::PairType));
    this->Persistence = vtkDoubleArray::SafeDownCast(cd->GetArray(flowrecon::names::Persistence));
    this->Birth = vtkDoubleArray::SafeDownCast(cd->GetArray(flowrecon::names::Birth));
    this->IsFinite = vtkIntArray::SafeDownCast(cd->GetArray(flowrecon::names::IsFinite));
  }
  bool Valid() const
  {
    return this->Grid->GetPoints() && this->Id && this->Type && this->Persistence && this->Birth &&
      this->IsFinite;
  }
  void Append(const double from[2], const double to[2], int id, int type, double persistence,
    double birth, int isFinite)
  {
    vtkPoints* points = this->Grid->GetPoints();
    const vtkIdType ids[2] = { points->InsertNextPoint(from[0], from[1], 0),
      points->InsertNextPoint(to[0], to[1], 0) };
    this->Grid->InsertNextCell(VTK_LINE, 2, ids);
    this->Id->InsertNextValue(id);
    this->Type->InsertNextValue(type);
    this->Persistence->InsertNextValue(persistence);
    this->Birth->InsertNextValue(birth);
    this->IsFinite->InsertNextValue(isFinite);
  }

  vtkUnstructuredGrid* Grid;
  vtkIntArray* Id;
  vtkIntArray* Type;
  vtkDoubleArray* Persistence;
  vtkDoubleArray* Birth;
  vtkIntArray* IsFinite;
};

} // namespace

std::vector<PersistencePair> DiagramPairs(const FlowComplex& fc)
{
  if (!fc.DeferredPatches.empty())
  {
    // Their arcs are missing: the pairs would be wrong without a word.
    throw std::logic_error("persistence of a complex with deferred patches (walk them first)");
  }
  std::vector<PersistencePair> pairs = ComputePersistence(fc.Nodes, fc.Arcs);
  pairs.erase(std::remove_if(pairs.begin(), pairs.end(),
                [](const PersistencePair& p) { return !(p.DeathValue > p.BirthValue); }),
    pairs.end());
  return pairs;
}

void DiagramToVTK(const std::vector<PersistencePair>& pairs, vtkUnstructuredGrid* grid)
{
  double top = 0;
  for (const auto& p : pairs)
  {
    top = std::max(top, std::isinf(p.DeathValue) ? p.BirthValue : p.DeathValue);
  }
  grid->Initialize();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  grid->SetPoints(points);
  grid->AllocateExact(static_cast<vtkIdType>(pairs.size() + 1), 2);
  vtkCellData* cd = grid->GetCellData();
  cd->AddArray(NamedArray<vtkIntArray>(flowrecon::names::PairIdentifier));
  cd->AddArray(NamedArray<vtkIntArray>(flowrecon::names::PairType));
  cd->AddArray(NamedArray<vtkDoubleArray>(flowrecon::names::Persistence));
  cd->AddArray(NamedArray<vtkDoubleArray>(flowrecon::names::Birth));
  cd->AddArray(NamedArray<vtkIntArray>(flowrecon::names::IsFinite));
  DiagramCells cells(grid);
  for (std::size_t i = 0; i < pairs.size(); ++i)
  {
    const auto& p = pairs[i];
    const bool isFinite = !std::isinf(p.DeathValue);
    const double death = isFinite ? p.DeathValue : top;
    const double from[2] = { p.BirthValue, p.BirthValue };
    const double to[2] = { p.BirthValue, death };
    cells.Append(from, to, static_cast<int>(i), p.Dimension, death - p.BirthValue, p.BirthValue,
      isFinite ? 1 : 0);
  }
  const double origin[2] = { 0, 0 };
  const double end[2] = { top, top };
  cells.Append(origin, end, -1, -1, 0, 0, 0);
}

void AddThresholdLine(double threshold, vtkUnstructuredGrid* grid)
{
  auto tp = NamedArray<vtkDoubleArray>("PersistenceThreshold");
  tp->InsertNextValue(threshold);
  grid->GetFieldData()->AddArray(tp);
  DiagramCells cells(grid);
  const vtkIdType n = grid->GetNumberOfCells();
  if (!(threshold >= 1) || !cells.Valid() || n == 0 || cells.Id->GetValue(n - 1) != -1)
  {
    return;
  }
  // The diagonal, last cell of DiagramToVTK, ends at the top of the range.
  const vtkIdType* ids;
  vtkIdType count;
  grid->GetCellPoints(n - 1, count, ids);
  const double top = grid->GetPoints()->GetPoint(ids[count - 1])[1];
  const double origin[2] = { 0, 0 };
  const double to[2] = { top / threshold, top };
  cells.Append(origin, to, -2, -2, 0, 0, 0);
}

void DiagramChartToVTK(
  const std::vector<PersistencePair>& pairs, double threshold, vtkUnstructuredGrid* grid)
{
  struct Row
  {
    double X;
    int Dimension; // -1: a row of the lines only
    double Death;
  };
  double top = 0;
  for (const auto& p : pairs)
  {
    top = std::max(top, std::isinf(p.DeathValue) ? p.BirthValue : p.DeathValue);
  }
  const bool line = threshold >= 1 && !std::isinf(threshold);
  std::vector<Row> rows;
  rows.reserve(pairs.size() + 3);
  rows.push_back({ 0, -1, 0 });
  for (const auto& p : pairs)
  {
    rows.push_back({ p.BirthValue, p.Dimension, std::isinf(p.DeathValue) ? top : p.DeathValue });
  }
  rows.push_back({ top, -1, 0 });
  if (line)
  {
    rows.push_back({ top / threshold, -1, 0 });
  }
  std::stable_sort(rows.begin(), rows.end(), [](const Row& a, const Row& b) { return a.X < b.X; });
  const char* names[6] = { flowrecon::names::Birth, "H0", "H1", "H2", "Diagonal", "t_p" };
  vtkSmartPointer<vtkDoubleArray> series[6];
  const auto n = static_cast<vtkIdType>(rows.size());
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 6; ++k)
  {
    series[k] = NamedArray<vtkDoubleArray>(names[k]);
    series[k]->SetNumberOfTuples(n);
  }
  for (vtkIdType r = 0; r < n; ++r)
  {
    const Row& row = rows[r];
    series[0]->SetValue(r, row.X);
    for (int d = 0; d < 3; ++d)
    {
      series[1 + d]->SetValue(r, row.Dimension == d ? row.Death : nan);
    }
    series[4]->SetValue(r, row.X);
    series[5]->SetValue(r, line && row.X * threshold <= top * (1 + 1e-12) ? row.X * threshold : nan);
  }
  for (auto& a : series)
  {
    grid->GetFieldData()->AddArray(a);
  }
}

void PersistenceCurveToVTK(
  const std::vector<PersistencePair>& pairs, double threshold, vtkTable* table)
{
  // Finite ratios per dimension, sorted; H0 (born at 0) and any other pair born
  // at 0 count at every x.
  std::array<std::vector<double>, 3> ratios;
  std::array<vtkIdType, 3> always = { 0, 0, 0 };
  std::vector<double> xs = { 1.0 };
  for (const auto& p : pairs)
  {
    if (std::isinf(p.DeathValue) || p.Dimension < 0 || p.Dimension > 2)
    {
      continue;
    }
    if (p.BirthValue > 0)
    {
      const double r = PersistenceRatio(p.DeathValue, p.BirthValue);
      ratios[p.Dimension].push_back(r);
      if (r > 1)
      {
        xs.push_back(r);
      }
    }
    else
    {
      ++always[p.Dimension];
    }
  }
  for (auto& r : ratios)
  {
    std::sort(r.begin(), r.end());
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  // The threshold mark: x = threshold twice (once more if it is already an x).
  const bool mark = threshold >= 1 && !std::isinf(threshold);
  if (mark)
  {
    auto at = std::lower_bound(xs.begin(), xs.end(), threshold);
    xs.insert(at, (at != xs.end() && *at == threshold) ? 1 : 2, threshold);
  }

  auto ratio = NamedArray<vtkDoubleArray>(flowrecon::names::Ratio);
  auto all = NamedArray<vtkIdTypeArray>("Pairs");
  vtkSmartPointer<vtkIdTypeArray> byDimension[3] = { NamedArray<vtkIdTypeArray>("PairsH0"),
    NamedArray<vtkIdTypeArray>("PairsH1"), NamedArray<vtkIdTypeArray>("PairsH2") };
  auto marker = NamedArray<vtkDoubleArray>("t_p");
  const vtkIdType rows = static_cast<vtkIdType>(xs.size());
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{
         ratio, all, byDimension[0], byDimension[1], byDimension[2], marker })
  {
    a->SetNumberOfTuples(rows);
  }
  // The mark is as high as the highest curve of finite ratios: the constant
  // H0 count would dwarf them.
  vtkIdType height = 0;
  for (const auto& r : ratios)
  {
    height = std::max(height, static_cast<vtkIdType>(r.size()));
  }
  bool firstMark = true;
  for (vtkIdType row = 0; row < rows; ++row)
  {
    const double x = xs[row];
    vtkIdType sum = 0;
    for (int d = 0; d < 3; ++d)
    {
      const auto& r = ratios[d];
      const vtkIdType count =
        always[d] + static_cast<vtkIdType>(r.end() - std::lower_bound(r.begin(), r.end(), x));
      byDimension[d]->SetValue(row, count);
      sum += count;
    }
    ratio->SetValue(row, x);
    all->SetValue(row, sum);
    double m = std::numeric_limits<double>::quiet_NaN();
    if (mark && x == threshold)
    {
      m = firstMark ? 0.0 : static_cast<double>(height);
      firstMark = false;
    }
    marker->SetValue(row, m);
  }

  table->Initialize();
  table->AddColumn(ratio);
  table->AddColumn(all);
  for (auto& a : byDimension)
  {
    table->AddColumn(a);
  }
  table->AddColumn(marker);
  // The same curves for a chart with logarithmic axes, which draws no zero:
  // zero counts are NaN there (a gap), and the mark starts at 1.
  for (vtkDataArray* column : std::initializer_list<vtkDataArray*>{
         ratio, all, byDimension[0], byDimension[1], byDimension[2], marker })
  {
    auto series = NamedArray<vtkDoubleArray>(column->GetName());
    series->SetNumberOfTuples(rows);
    for (vtkIdType row = 0; row < rows; ++row)
    {
      double v = column->GetComponent(row, 0);
      if (column == marker && v == 0)
      {
        v = 1;
      }
      else if (column != ratio && column != marker && v == 0)
      {
        v = std::numeric_limits<double>::quiet_NaN();
      }
      series->SetValue(row, v);
    }
    table->GetFieldData()->AddArray(series);
  }
  auto tp = NamedArray<vtkDoubleArray>("PersistenceThreshold");
  tp->InsertNextValue(threshold);
  table->GetFieldData()->AddArray(tp);
}

} // namespace flowrecon
