#include "TopologyConversion.h"

#include "FlowComplexConversion.h"
#include "FlowReconNames.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <initializer_list>
#include <limits>

namespace flowrecon
{

namespace
{

/// The topology profile drawn as steps, for its line chart: a chart joins
/// rows with slopes, and the rows (one per change) are what the command line
/// writes, so the steps go to the table's field data. Two points per row, at
/// the start and the end of its interval, and two at x = t for a vertical mark
/// (`t_r`, NaN elsewhere) from 0 to the largest Betti number drawn. With a
/// mark, the steps start at t / ChartSpan: the chart's height is then that of
/// the Betti numbers around t_r, not of the hundreds of components near
/// t_r = 1 (the rows keep the whole profile).
constexpr double ChartSpan = 1.25;

void AddStaircase(const std::vector<TopologyStep>& profile, double t, double limit,
  vtkFieldData* field)
{
  if (profile.empty())
  {
    return;
  }
  const char* names[4] = { flowrecon::names::Threshold, "b0", "b1", "b2" };
  vtkSmartPointer<vtkDoubleArray> steps[5];
  for (int k = 0; k < 4; ++k)
  {
    steps[k] = NamedArray<vtkDoubleArray>(names[k]);
  }
  steps[4] = NamedArray<vtkDoubleArray>("t_r");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const bool mark = t < Unbounded;
  const double from = mark ? std::max(1.0, t / ChartSpan) : 0;
  // The interval of row k: (start, end], clipped to the chart's span.
  auto interval = [&](std::size_t k) {
    double end = k + 1 < profile.size() ? profile[k + 1].Threshold : limit;
    if (end >= Unbounded)
    {
      end = mark ? std::max(profile[k].Threshold, t) : profile[k].Threshold;
    }
    return std::make_pair(std::max(profile[k].Threshold, from), end);
  };
  auto drawn = [&](std::size_t k) {
    const auto span = interval(k);
    return span.second > from || (k + 1 == profile.size() && span.second >= span.first);
  };
  double height = 1;
  for (std::size_t k = 0; k < profile.size(); ++k)
  {
    for (int d = 0; d < 3 && drawn(k); ++d)
    {
      height = std::max(height, static_cast<double>(profile[k].Betti[d]));
    }
  }
  // A point of the curves (of `step`, NaN without) and of the mark.
  auto point = [&](double x, const TopologyStep* step, double m) {
    steps[0]->InsertNextValue(x);
    for (int d = 0; d < 3; ++d)
    {
      steps[d + 1]->InsertNextValue(step ? static_cast<double>(step->Betti[d]) : nan);
    }
    steps[4]->InsertNextValue(m);
  };
  if (mark && t <= profile.front().Threshold)
  {
    point(t, nullptr, 0); // before the first interval: the mark alone
    point(t, nullptr, height);
  }
  for (std::size_t k = 0; k < profile.size(); ++k)
  {
    if (!drawn(k))
    {
      continue;
    }
    const auto [start, end] = interval(k);
    point(start, &profile[k], nan);
    if (mark && profile[k].Threshold < t && t <= end)
    {
      point(t, &profile[k], 0);
      point(t, &profile[k], height);
    }
    point(end, &profile[k], nan);
  }
  for (auto& a : steps)
  {
    field->AddArray(a);
  }
}

} // namespace

void UnderSamplingToVTK(const std::vector<TopologyChange>& changes,
  const std::vector<Id>& cellNodes, const FlowComplex& fc, vtkPolyData* output)
{
  struct Place
  {
    const TopologyChange* Change;
    Id Node;
  };
  std::vector<Place> places;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> vertices;
  for (const TopologyChange& c : changes)
  {
    const Id node = cellNodes.empty()
      ? (c.Cell >= 0 && c.Cell < static_cast<Id>(fc.Nodes.size()) ? c.Cell : -1)
      : (c.Cell >= 0 && c.Cell < static_cast<Id>(cellNodes.size()) ? cellNodes[c.Cell] : -1);
    if (node >= 0)
    {
      const vtkIdType id = points->InsertNextPoint(fc.Nodes[node].Location.data());
      vertices->InsertNextCell(1, &id);
      places.push_back({ &c, node });
    }
  }
  output->Initialize();
  output->SetPoints(points);
  output->SetVerts(vertices);
  vtkPointData* pd = output->GetPointData();
  pd->AddArray(Column<vtkDoubleArray>(
    flowrecon::names::Threshold, places, [](const Place& p) { return p.Change->Threshold; }));
  pd->AddArray(Column<vtkIntArray>(
    flowrecon::names::Dimension, places, [](const Place& p) { return p.Change->Dimension; }));
  pd->AddArray(Column<vtkIntArray>(
    flowrecon::names::Change, places, [](const Place& p) { return p.Change->Change; }));
  // The diameter of the empty ball at the node's critical point: the gap in
  // the sampling there (a sample's node has value 0: its nearest Gabriel edge
  // would do, but a sample brings no change above t_r > 1).
  pd->AddArray(Column<vtkDoubleArray>(flowrecon::names::Spacing, places,
    [&](const Place& p) { return 2 * fc.Nodes[p.Node].Value; }));
  pd->AddArray(Column<vtkIdTypeArray>(flowrecon::names::NodeId, places, &Place::Node));
  pd->SetActiveScalars(flowrecon::names::Threshold);
}

void TopologyToVTK(const std::vector<Bar>& bars, double t, double limit,
  vtkUnstructuredGrid* grid, vtkTable* table)
{
  TopologyToVTK(bars, TopologyProfile(bars, 1, limit), t, limit, grid, table);
}

void TopologyToVTK(const std::vector<Bar>& bars, const std::vector<TopologyStep>& profile,
  double t, double limit, vtkUnstructuredGrid* grid, vtkTable* table)
{
  const std::array<Id, 4> betti = BettiNumbersBelow(bars, t);
  auto field = NamedArray<vtkIdTypeArray>(flowrecon::names::BettiNumbers);
  for (int d = 0; d < 3; ++d)
  {
    field->InsertNextValue(static_cast<vtkIdType>(betti[d]));
  }
  grid->GetFieldData()->AddArray(field);

  table->Initialize();
  auto threshold = NamedArray<vtkDoubleArray>(flowrecon::names::Threshold);
  vtkSmartPointer<vtkIdTypeArray> b[3] = { NamedArray<vtkIdTypeArray>("b0"),
    NamedArray<vtkIdTypeArray>("b1"), NamedArray<vtkIdTypeArray>("b2") };
  for (const TopologyStep& step : profile)
  {
    threshold->InsertNextValue(step.Threshold);
    for (int d = 0; d < 3; ++d)
    {
      b[d]->InsertNextValue(static_cast<vtkIdType>(step.Betti[d]));
    }
  }
  table->AddColumn(threshold);
  for (auto& column : b)
  {
    table->AddColumn(column);
  }
  AddStaircase(profile, t, limit, table->GetFieldData());
}

void ThresholdWarningsToVTK(const std::vector<std::string>& lines, vtkUnstructuredGrid* grid)
{
  auto warnings = NamedArray<vtkStringArray>(flowrecon::names::ThresholdWarnings);
  for (const std::string& line : lines)
  {
    warnings->InsertNextValue(line);
  }
  grid->GetFieldData()->AddArray(warnings);
}

void TopologyTextToVTK(const std::string& line, vtkUnstructuredGrid* grid, vtkTable* text)
{
  auto field = NamedArray<vtkStringArray>(flowrecon::names::Topology);
  field->InsertNextValue(line);
  grid->GetFieldData()->AddArray(field);
  if (!text)
  {
    return;
  }
  // Short lines for a corner of a view: the Betti numbers, the thresholds, the
  // range, the warnings.
  std::string lines = line;
  for (std::size_t at = lines.find("; "); at != std::string::npos; at = lines.find("; ", at))
  {
    lines.replace(at, 2, "\n");
  }
  const std::size_t at = lines.find(" at t_r ");
  if (lines.compare(0, 13, "Betti numbers") == 0 && at != std::string::npos)
  {
    lines[at] = '\n';
  }
  auto column = NamedArray<vtkStringArray>(flowrecon::names::Topology);
  column->InsertNextValue(lines);
  text->Initialize();
  text->AddColumn(column);
}

void ThresholdsToVTK(double tp, double tr, bool tpChosen, bool trChosen,
  const StableWindow* window, vtkUnstructuredGrid* grid)
{
  vtkFieldData* field = grid->GetFieldData();
  auto one = [field](const char* name, double value) {
    auto a = NamedArray<vtkDoubleArray>(name);
    a->InsertNextValue(value);
    field->AddArray(a);
  };
  one(flowrecon::names::UsedPersistenceThreshold, tp);
  one(flowrecon::names::UsedReconstructionThreshold, tr);
  auto chosen = NamedArray<vtkIntArray>(flowrecon::names::ThresholdsChosen);
  chosen->InsertNextValue(trChosen ? 1 : 0);
  chosen->InsertNextValue(tpChosen ? 1 : 0);
  field->AddArray(chosen);
  if (window)
  {
    auto w = NamedArray<vtkDoubleArray>(flowrecon::names::StableWindow);
    w->InsertNextValue(window->From);
    w->InsertNextValue(window->To);
    field->AddArray(w);
  }
}

void ReconstructionBarsToVTK(const std::vector<Bar>& bars, double below, vtkFieldData* field)
{
  auto a = NamedArray<vtkDoubleArray>(flowrecon::names::ReconstructionBars);
  const char* parts[] = { "Dimension", "Birth", "Death", "BirthNode", "DeathNode" };
  a->SetNumberOfComponents(5);
  for (int k = 0; k < 5; ++k)
  {
    a->SetComponentName(k, parts[k]);
  }
  a->SetNumberOfTuples(static_cast<vtkIdType>(bars.size()));
  for (std::size_t i = 0; i < bars.size(); ++i)
  {
    const Bar& b = bars[i];
    // Node ids below 2^53 are exact in a double.
    const double row[5] = { static_cast<double>(b.Dimension), b.Birth,
      std::min(b.Death, Unbounded), static_cast<double>(b.BirthCell),
      static_cast<double>(b.DeathCell) };
    a->SetTypedTuple(static_cast<vtkIdType>(i), row);
  }
  field->AddArray(a);
  auto cap = NamedArray<vtkDoubleArray>(flowrecon::names::ReconstructionBarsBelow);
  cap->InsertNextValue(std::min(below, Unbounded));
  field->AddArray(cap);
}

bool ReconstructionBarsFromVTK(vtkFieldData* field, Id nodeCount, std::vector<Bar>& bars,
  double& below, std::string& error)
{
  bars.clear();
  error.clear();
  vtkDataArray* a = field ? field->GetArray(flowrecon::names::ReconstructionBars) : nullptr;
  vtkDataArray* cap = field ? field->GetArray(flowrecon::names::ReconstructionBarsBelow) : nullptr;
  if (!a || !cap)
  {
    return false;
  }
  if (a->GetNumberOfComponents() != 5 || cap->GetNumberOfTuples() != 1)
  {
    error = "field data ReconstructionBars: expected 5 components and one ReconstructionBarsBelow";
    return false;
  }
  below = cap->GetComponent(0, 0);
  below = below >= Unbounded ? HUGE_VAL : below;
  bars.resize(static_cast<std::size_t>(a->GetNumberOfTuples()));
  const auto isNode = [nodeCount](double v, bool orNone) {
    return (orNone && v == -1) || (v >= 0 && v < static_cast<double>(nodeCount) && v == std::floor(v));
  };
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    double row[5];
    a->GetTuple(i, row);
    Bar& b = bars[static_cast<std::size_t>(i)];
    b.Dimension = static_cast<int>(row[0]);
    b.Birth = row[1];
    b.Death = row[2] >= Unbounded ? HUGE_VAL : row[2];
    if (!(row[0] == 0 || row[0] == 1 || row[0] == 2) || !(b.Birth < b.Death) ||
      !isNode(row[3], false) || !isNode(row[4], true))
    {
      error = "field data ReconstructionBars: tuple " + std::to_string(i) +
        " is not a bar of this complex (dimension 0-2, birth < death, node ids)";
      bars.clear();
      return false;
    }
    b.BirthCell = static_cast<Id>(row[3]);
    b.DeathCell = static_cast<Id>(row[4]);
  }
  return true;
}

} // namespace flowrecon
