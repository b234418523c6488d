// vtkFlowComplexSimplification and vtkFlowReconstruction as a VTK user meets
// them: a .vtm round trip gives the same reconstruction, reconstructions are
// nested in t_r, the output is closed under faces, a new t_r does not rerun the
// queue, and quasi-uniform samples of a sphere and a torus are reconstructed
// with their Betti numbers (computed here by a Z/2 reduction of the output).
#include "Check.h"

#include "vtkFlowComplex.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkCellType.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkCell.h"
#include "vtkCellArray.h"
#include "vtkInformation.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLMultiBlockDataReader.h"
#include "vtkXMLMultiBlockDataWriter.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{

using Cloud = std::vector<std::array<double, 3>>;

/// Fibonacci sphere (unit radius), jittered by 1e-4 to avoid cospherical ties.
Cloud FibonacciSphere(int n)
{
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-5e-5, 5e-5);
  Cloud c;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / n, r = std::sqrt(1 - z * z), a = golden * i;
    c.push_back({ { r * std::cos(a) + u(g), r * std::sin(a) + u(g), z + u(g) } });
  }
  return c;
}

/// Whether an output holds nothing: no points, cells, columns or field data.
bool Empty(vtkDataObject* o)
{
  if (!o || o->GetFieldData()->GetNumberOfArrays() > 0)
  {
    return false;
  }
  if (auto* table = vtkTable::SafeDownCast(o))
  {
    return table->GetNumberOfColumns() == 0;
  }
  auto* data = vtkDataSet::SafeDownCast(o);
  return data && data->GetNumberOfPoints() == 0 && data->GetNumberOfCells() == 0;
}

/// A progress observer that aborts the algorithm once its progress passes
/// *clientData.
void AbortPast(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* algorithm = vtkAlgorithm::SafeDownCast(caller);
  if (algorithm->GetProgress() > *static_cast<const double*>(clientData))
  {
    algorithm->SetAbortExecute(1);
  }
}

/// Updates `a` with an observer that aborts it once its progress passes
/// `past`; AbortExecute stays set.
void UpdateAborting(vtkAlgorithm* a, double past)
{
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback(AbortPast);
  abort->SetClientData(&past);
  const unsigned long tag = a->AddObserver(vtkCommand::ProgressEvent, abort);
  a->Update();
  a->RemoveObserver(tag);
}

/// Clears the abort and updates again.
void UpdateAgain(vtkAlgorithm* a)
{
  a->SetAbortExecute(0);
  a->Modified();
  a->Update();
}

bool AllOutputsEmpty(vtkAlgorithm* a)
{
  for (int port = 0; port < a->GetNumberOfOutputPorts(); ++port)
  {
    if (!Empty(a->GetOutputDataObject(port)))
    {
      return false;
    }
  }
  return true;
}

/// Torus R = 1, r = 0.35 sampled on a staggered nu x nv angle grid, jittered by 1e-3.
Cloud GridTorus(int nu, int nv)
{
  std::mt19937_64 g(11);
  std::uniform_real_distribution<double> u(-5e-4, 5e-4);
  Cloud c;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double a = 2 * M_PI * (i + 0.5 * (j % 2)) / nu, b = 2 * M_PI * j / nv;
      c.push_back({ { (1 + 0.35 * std::cos(b)) * std::cos(a) + u(g),
        (1 + 0.35 * std::cos(b)) * std::sin(a) + u(g), 0.35 * std::sin(b) + u(g) } });
    }
  }
  return c;
}

/// `cells`: MaximumStableManifoldCells (-1 all), or -2 for no stable manifolds.
vtkSmartPointer<vtkMultiBlockDataSet> FlowComplexOf(
  const Cloud& cloud, vtkIdType cells = -1, int seed = 1)
{
  vtkNew<vtkPoints> pts;
  for (const auto& p : cloud)
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  vtkNew<vtkFlowComplex> fc;
  fc->SetInputData(pd);
  fc->SetComputeUnstableManifolds(false);
  fc->SetComputeStableManifolds(cells != -2);
  fc->SetMaximumStableManifoldCells(std::max<vtkIdType>(cells, -1));
  // Every patch walked: these runs go to t_r = infinity, above any deferral
  // ratio (deferred patches are pv.deferred_pipeline's subject).
  fc->SetDeferPatchesAbove(0);
  fc->SetPerturbationSeed(seed);
  fc->Update();
  return fc->GetOutput();
}

vtkSmartPointer<vtkMultiBlockDataSet> Simplified(vtkMultiBlockDataSet* complex, double tp)
{
  vtkNew<vtkFlowComplexSimplification> s;
  s->SetInputData(complex);
  s->SetPersistenceThreshold(tp);
  s->AutomaticPersistenceThresholdOff();
  s->Update();
  return s->GetOutput();
}

/// The reconstruction at `tr` (and T_max = tr when tr is infinite).
vtkSmartPointer<vtkUnstructuredGrid> Reconstructed(vtkMultiBlockDataSet* input, double tr)
{
  vtkNew<vtkFlowReconstruction> r;
  r->SetInputData(input);
  r->SetReconstructionThreshold(tr);
  r->AutomaticReconstructionThresholdOff();
  r->SetMaximumThreshold(std::max(4.0, tr));
  r->Update();
  return vtkUnstructuredGrid::SafeDownCast(r->GetOutputDataObject(0));
}

vtkDataObject* Block(vtkMultiBlockDataSet* mb, const std::string& name)
{
  for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
  {
    if (mb->HasMetaData(b) && name == mb->GetMetaData(b)->Get(vtkCompositeDataSet::NAME()))
    {
      return mb->GetBlock(b);
    }
  }
  return nullptr;
}

vtkSmartPointer<vtkMultiBlockDataSet> RoundTrip(vtkMultiBlockDataSet* mb, const std::string& file)
{
  vtkNew<vtkXMLMultiBlockDataWriter> w;
  w->SetFileName(file.c_str());
  w->SetInputData(mb);
  CHECK(w->Write() == 1);
  vtkNew<vtkXMLMultiBlockDataReader> r;
  r->SetFileName(file.c_str());
  r->Update();
  return vtkMultiBlockDataSet::SafeDownCast(r->GetOutputDataObject(0));
}

/// One row per cell: type, point coordinates, then the cell data used here.
/// Multiplicity (patches of the current reconstruction an edge bounds) grows
/// with t_r, so nestedness compares without it.
using Row = std::vector<double>;
std::vector<Row> Rows(vtkUnstructuredGrid* g, bool multiplicity = true)
{
  const char* names[] = { "NodeId", "Index", "CriticalValue", "Step", "Priority", "Threshold",
    "Extension", "Sponsor", "Multiplicity" };
  std::vector<Row> rows;
  const vtkIdType n = g->GetNumberOfCells();
  for (vtkIdType c = 0; c < n; ++c)
  {
    Row row{ double(g->GetCellType(c)) };
    vtkIdType npts;
    const vtkIdType* pts;
    g->GetCellPoints(c, npts, pts);
    for (vtkIdType k = 0; k < npts; ++k)
    {
      double x[3];
      g->GetPoint(pts[k], x);
      row.insert(row.end(), x, x + 3);
    }
    for (const char* name : names)
    {
      if (!multiplicity && std::string(name) == "Multiplicity")
      {
        continue;
      }
      vtkDataArray* a = g->GetCellData()->GetArray(name);
      row.push_back(a ? a->GetComponent(c, 0) : NAN);
    }
    rows.push_back(row);
  }
  return rows;
}

/// Rows of the cells with Threshold < t.
std::vector<Row> RowsBelow(vtkUnstructuredGrid* g, double t)
{
  std::vector<Row> all = Rows(g, false), kept;
  vtkDataArray* threshold = g->GetCellData()->GetArray("Threshold");
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    if (threshold->GetComponent(c, 0) < t)
    {
      kept.push_back(all[c]);
    }
  }
  return kept;
}

using Simplex = std::vector<vtkIdType>; // sorted point ids

Simplex CellSimplex(vtkUnstructuredGrid* g, vtkIdType c)
{
  vtkIdType npts;
  const vtkIdType* pts;
  g->GetCellPoints(c, npts, pts);
  Simplex s(pts, pts + npts);
  std::sort(s.begin(), s.end());
  return s;
}

/// Every cell's boundary is in the output: an edge's two vertices; a
/// triangle's sample vertices and its edges that are Gabriel edges of the flow
/// complex; one face of each tetrahedron (the base patch triangle).
void CheckClosure(const std::string& label, vtkUnstructuredGrid* g, vtkMultiBlockDataSet* complex)
{
  auto* sm = vtkUnstructuredGrid::SafeDownCast(Block(complex, "StableManifolds"));
  std::set<Simplex> gabriel;
  for (vtkIdType c = 0; c < sm->GetNumberOfCells(); ++c)
  {
    if (sm->GetCellType(c) == VTK_LINE)
    {
      gabriel.insert(CellSimplex(sm, c));
    }
  }
  std::set<Simplex> present;
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    present.insert(CellSimplex(g, c));
  }
  vtkDataArray* original = g->GetPointData()->GetArray("vtkOriginalPointIds");
  CHECK(original != nullptr);
  long missing = 0;
  for (vtkIdType c = 0; c < g->GetNumberOfCells() && original; ++c)
  {
    const Simplex s = CellSimplex(g, c);
    const int type = g->GetCellType(c);
    if (type == VTK_LINE || type == VTK_TRIANGLE)
    {
      for (vtkIdType v : s)
      {
        if (original->GetComponent(v, 0) >= 0 && !present.count(Simplex{ v }))
        {
          ++missing;
        }
      }
    }
    if (type == VTK_TRIANGLE)
    {
      for (int k = 0; k < 3; ++k)
      {
        Simplex e{ s[k], s[(k + 1) % 3] };
        std::sort(e.begin(), e.end());
        if (gabriel.count(e) && !present.count(e))
        {
          ++missing;
        }
      }
    }
    if (type == VTK_TETRA)
    {
      bool face = false;
      for (int k = 0; k < 4; ++k)
      {
        Simplex f = s;
        f.erase(f.begin() + k);
        face = face || present.count(f) > 0;
      }
      missing += face ? 0 : 1;
    }
  }
  CHECK(missing == 0);
  if (missing)
  {
    std::cout << "   " << label << ": " << missing << " boundary cells missing\n";
  }
}

/// Betti numbers over Z/2 of the simplicial complex made of the output cells
/// and all their faces (simplices are sets of point ids).
std::array<long, 4> Betti(vtkUnstructuredGrid* g)
{
  std::array<std::map<Simplex, long>, 4> ids; // simplex -> column number per dimension
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    const Simplex s = CellSimplex(g, c);
    const int n = static_cast<int>(s.size());
    for (int mask = 1; mask < (1 << n); ++mask) // every face
    {
      Simplex f;
      for (int k = 0; k < n; ++k)
      {
        if (mask & (1 << k))
        {
          f.push_back(s[k]);
        }
      }
      ids[f.size() - 1].emplace(f, 0);
    }
  }
  std::array<long, 4> count{}, rank{};
  for (int d = 0; d < 4; ++d)
  {
    long i = 0;
    for (auto& entry : ids[d])
    {
      entry.second = i++;
    }
    count[d] = i;
  }
  for (int d = 1; d < 4; ++d) // rank of the boundary map from dimension d to d - 1
  {
    std::map<long, std::vector<long>> pivots; // lowest row -> reduced column
    for (const auto& entry : ids[d])
    {
      std::vector<long> col;
      for (std::size_t k = 0; k < entry.first.size(); ++k)
      {
        Simplex f = entry.first;
        f.erase(f.begin() + k);
        col.push_back(ids[d - 1].at(f));
      }
      std::sort(col.begin(), col.end());
      while (!col.empty())
      {
        const auto p = pivots.find(col.back());
        if (p == pivots.end())
        {
          pivots.emplace(col.back(), col);
          break;
        }
        std::vector<long> sum;
        std::set_symmetric_difference(
          col.begin(), col.end(), p->second.begin(), p->second.end(), std::back_inserter(sum));
        col.swap(sum);
      }
    }
    rank[d] = static_cast<long>(pivots.size());
  }
  std::array<long, 4> b{};
  for (int d = 0; d < 4; ++d)
  {
    b[d] = count[d] - rank[d] - (d < 3 ? rank[d + 1] : 0);
  }
  return b;
}

void CheckBetti(const std::string& label, vtkUnstructuredGrid* g, std::array<long, 4> expected)
{
  const auto b = Betti(g);
  CHECK(b == expected);
  if (b != expected)
  {
    std::cout << "   " << label << ": Betti " << b[0] << " " << b[1] << " " << b[2] << " "
              << b[3] << ", expected " << expected[0] << " " << expected[1] << " "
              << expected[2] << " " << expected[3] << "\n";
  }
}

/// Lines (points of both ends) and cell arrays of a polydata, cell by cell.
std::vector<Row> LineRows(vtkPolyData* pd)
{
  std::vector<Row> rows;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    Row row;
    vtkNew<vtkIdList> ids;
    pd->GetCellPoints(c, ids);
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      double x[3];
      pd->GetPoint(ids->GetId(k), x);
      row.insert(row.end(), x, x + 3);
    }
    for (int a = 0; a < pd->GetCellData()->GetNumberOfArrays(); ++a)
    {
      row.push_back(pd->GetCellData()->GetArray(a)->GetComponent(c, 0));
    }
    rows.push_back(row);
  }
  return rows;
}

/// The simplification changes the arcs only: every other block of its output
/// shares its input's points and arrays (no copy of the drawn geometry), the
/// input is left as it was, and at t_p 0 the HasseDiagram block is rebuilt with
/// the input's arcs, stubs toward infinity included.
/// Per cell of `pd`, its point ids and the value of cell array `name`; the
/// cells whose `keep` (a cell array, -1 for every cell) is 0.
std::vector<std::vector<double>> CellRows(vtkPolyData* pd, const char* name, const char* keep)
{
  std::vector<std::vector<double>> rows;
  vtkDataArray* value = pd->GetCellData()->GetArray(name);
  vtkDataArray* filter = keep ? pd->GetCellData()->GetArray(keep) : nullptr;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c)
  {
    if (!filter || filter->GetComponent(c, 0) == 0)
    {
      pd->GetCellPoints(c, ids);
      rows.push_back({ value->GetComponent(c, 0) });
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      {
        rows.back().push_back(static_cast<double>(ids->GetId(k)));
      }
    }
  }
  return rows;
}

/// The blocks the display shows are the complete ones' parts with Cancelled 0:
/// the same points (coordinates, NodeId, Index, CriticalValue) in order, the
/// vertices of those points, the Gabriel edges in order over the same samples.
void CheckSurvivingBlocks(vtkMultiBlockDataSet* simplified)
{
  std::vector<vtkPolyData*> b;
  for (const char* name :
    { "CriticalPoints", "SurvivingCriticalPoints", "GabrielEdges", "SurvivingGabrielEdges" })
  {
    b.push_back(vtkPolyData::SafeDownCast(Block(simplified, name)));
  }
  CHECK(std::count(b.begin(), b.end(), nullptr) == 0);
  if (std::count(b.begin(), b.end(), nullptr) > 0)
  {
    return;
  }
  vtkPolyData *cp = b[0], *scp = b[1], *ge = b[2], *sge = b[3];
  vtkDataArray* cancelled = cp->GetPointData()->GetArray("Cancelled");
  std::vector<std::vector<double>> points, survivingPoints;
  for (auto [pd, all] : { std::pair{ cp, false }, std::pair{ scp, true } })
  {
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      if (all || cancelled->GetComponent(i, 0) == 0)
      {
        std::vector<double> row(pd->GetPoint(i), pd->GetPoint(i) + 3);
        for (const char* name : { "NodeId", "Index", "CriticalValue" })
        {
          row.push_back(pd->GetPointData()->GetArray(name)->GetComponent(i, 0));
        }
        (all ? survivingPoints : points).push_back(row);
      }
    }
  }
  CHECK(points == survivingPoints);
  // Vertices as the NodeIds of their points, with the cell array Index.
  std::vector<std::vector<double>> vertices, survivingVertices;
  for (auto [pd, rows] : { std::pair{ cp, &vertices }, std::pair{ scp, &survivingVertices } })
  {
    for (const auto& row : CellRows(pd, "Index", nullptr))
    {
      const vtkIdType p = static_cast<vtkIdType>(row[1]);
      if (pd == scp || cancelled->GetComponent(p, 0) == 0)
      {
        rows->push_back({ row[0], pd->GetPointData()->GetArray("NodeId")->GetComponent(p, 0) });
      }
    }
  }
  CHECK(!vertices.empty() && vertices == survivingVertices);
  CHECK(sge->GetPoints()->GetNumberOfPoints() == ge->GetPoints()->GetNumberOfPoints());
  CHECK(CellRows(ge, "NodeId", "Cancelled") == CellRows(sge, "NodeId", nullptr));
}

void CheckPassThrough(vtkMultiBlockDataSet* complex, vtkMultiBlockDataSet* simplified, double tp)
{
  // the complex's blocks, PersistencePairs and the two surviving blocks
  CHECK(simplified->GetNumberOfBlocks() == complex->GetNumberOfBlocks() + 3);
  for (unsigned int b = 0; b < complex->GetNumberOfBlocks(); ++b)
  {
    const std::string name = complex->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
    auto* in = vtkPointSet::SafeDownCast(complex->GetBlock(b));
    auto* out = vtkPointSet::SafeDownCast(Block(simplified, name));
    CHECK(in && out && in != out);
    if (!in || !out || name == "HasseDiagram")
    {
      continue;
    }
    CHECK(in->GetPoints() == out->GetPoints());
    for (vtkFieldData* fd : { static_cast<vtkFieldData*>(in->GetPointData()),
           static_cast<vtkFieldData*>(in->GetCellData()) })
    {
      vtkFieldData* other = fd == in->GetPointData() ? static_cast<vtkFieldData*>(out->GetPointData())
                                                      : out->GetCellData();
      for (int a = 0; a < fd->GetNumberOfArrays(); ++a)
      {
        CHECK(other->GetAbstractArray(fd->GetArrayName(a)) == fd->GetAbstractArray(a));
      }
    }
  }
  auto* cp = vtkPolyData::SafeDownCast(Block(complex, "CriticalPoints"));
  CHECK(cp && !cp->GetPointData()->GetArray("Cancelled"));
  auto* hdIn = vtkPolyData::SafeDownCast(Block(complex, "HasseDiagram"));
  auto* hdOut = vtkPolyData::SafeDownCast(Block(simplified, "HasseDiagram"));
  CHECK(hdIn && hdOut && hdIn != hdOut);
  if (hdIn && hdOut && tp == 0.0)
  {
    // The same arcs; the simplification lists them in its own order.
    std::vector<Row> before = LineRows(hdIn), after = LineRows(hdOut);
    std::sort(before.begin(), before.end());
    std::sort(after.begin(), after.end());
    CHECK(before == after);
  }
}

void TestShape(const std::string& name, const Cloud& cloud, std::array<long, 4> betti,
  const std::string& dir)
{
  std::cout << "-- " << name << "\n";
  vtkSmartPointer<vtkMultiBlockDataSet> complex = FlowComplexOf(cloud);
  CHECK(Block(complex, "StableManifolds") != nullptr);
  for (const double tp : { 0.0, 1.1 })
  {
    const std::string label = name + ", t_p " + std::to_string(tp);
    vtkSmartPointer<vtkMultiBlockDataSet> simplified = Simplified(complex, tp);
    CheckPassThrough(complex, simplified, tp);
    CheckSurvivingBlocks(simplified);
    CHECK(Block(simplified, "PersistencePairs") != nullptr);
    auto* cp = vtkPolyData::SafeDownCast(Block(simplified, "CriticalPoints"));
    CHECK(cp && cp->GetPointData()->GetArray("Cancelled"));
    CHECK(simplified->GetFieldData()->GetArray("PersistenceThreshold") != nullptr);
    auto* pairs = vtkPolyData::SafeDownCast(Block(simplified, "PersistencePairs"));
    CHECK(pairs && pairs->GetCellData()->GetArray("Ratio") && pairs->GetCellData()->GetArray("Birth") &&
      pairs->GetCellData()->GetArray("Death") && pairs->GetCellData()->GetArray("PairType"));
    if (pairs && tp == 0.0)
    {
      CHECK(pairs->GetNumberOfCells() == 0); // t_p = 0 cancels nothing
    }
    if (pairs && tp > 1 && pairs->GetNumberOfCells() > 0)
    {
      vtkDataArray* ratio = pairs->GetCellData()->GetArray("Ratio");
      CHECK(ratio->GetRange()[0] >= 1 && ratio->GetRange()[1] <= tp);
    }

    vtkSmartPointer<vtkUnstructuredGrid> at2 = Reconstructed(simplified, 2.0);
    vtkSmartPointer<vtkUnstructuredGrid> atInf = Reconstructed(simplified, VTK_DOUBLE_MAX);
    CHECK(at2->GetNumberOfCells() > 0);
    CHECK(at2->GetNumberOfCells() < atInf->GetNumberOfCells());
    // Nestedness: the run at 2 is the Threshold < 2 part of the run at infinity.
    CHECK(Rows(at2, false) == RowsBelow(atInf, 2.0));
    CHECK(RowsBelow(atInf, 1.5) == Rows(Reconstructed(simplified, 1.5), false));
    CheckClosure(label + ", t_r 2", at2, complex);
    CheckClosure(label + ", t_r inf", atInf, complex);
    CheckBetti(label + ", t_r 2", at2, betti);
    CheckBetti(label + ", t_r 1.9", Reconstructed(simplified, 1.9), betti);
    CheckBetti(label + ", t_r inf", atInf, { { 1, 0, 0, 0 } }); // the whole hull is contractible

    // Round trips: the flow complex and the simplified complex through .vtm.
    const std::string base = dir + "/" + name + (tp > 0 ? "_tp" : "_notp");
    auto complexBack = RoundTrip(complex, base + "_complex.vtm");
    CHECK(Rows(Reconstructed(Simplified(complexBack, tp), 2.0)) == Rows(at2));
    auto simplifiedBack = RoundTrip(simplified, base + "_simplified.vtm");
    CHECK(Rows(Reconstructed(simplifiedBack, 2.0)) == Rows(at2));

    // Geometry on demand: from a complex without stable manifolds, or with a
    // small cell budget, the reconstruction draws its own cells and equals the
    // one made of the eager cells, cell by cell, at t_r 2 and infinity.
    for (const vtkIdType cells : { vtkIdType(-2), vtkIdType(50) })
    {
      auto lazy = Simplified(FlowComplexOf(cloud, cells), tp);
      CHECK(Rows(Reconstructed(lazy, VTK_DOUBLE_MAX)) == Rows(atInf));
      CHECK(Rows(Reconstructed(lazy, 2.0)) == Rows(at2));
      auto lazyBack = RoundTrip(lazy, base + "_lazy.vtm");
      CHECK(Rows(Reconstructed(lazyBack, 2.0)) == Rows(at2));
    }
  }
}

/// Changing only t_r re-selects cells; a new input reruns the queue once.
void TestQueueCache(const Cloud& cloud)
{
  std::cout << "-- queue cache\n";
  vtkSmartPointer<vtkMultiBlockDataSet> complex = FlowComplexOf(cloud);
  vtkNew<vtkFlowComplexSimplification> s;
  s->SetInputData(complex);
  s->AutomaticPersistenceThresholdOff();
  vtkNew<vtkFlowReconstruction> r;
  r->SetInputConnection(s->GetOutputPort());
  r->SetReconstructionThreshold(2.0);
  r->AutomaticReconstructionThresholdOff();
  r->Update();
  CHECK(r->GetNumberOfQueueRuns() == 1);
  const vtkIdType cells2 = r->GetOutput()->GetNumberOfCells();
  auto* profile = vtkTable::SafeDownCast(r->GetOutputDataObject(1));
  CHECK(profile && profile->GetColumnByName("Threshold") && profile->GetNumberOfRows() > 0);
  auto* arrows = vtkPolyData::SafeDownCast(r->GetOutputDataObject(2));
  CHECK(arrows && arrows->GetNumberOfCells() > 0 && arrows->GetCellData()->GetArray("Extension"));
  // A new t_r cuts its grid out of the same arrays (GridBelow): nothing is
  // drawn or copied, so the outputs at 2 and 1.2 share their buffers.
  vtkNew<vtkUnstructuredGrid> at2;
  at2->ShallowCopy(r->GetOutput());
  r->SetReconstructionThreshold(1.2);
  r->Update();
  CHECK(r->GetNumberOfQueueRuns() == 1);
  CHECK(r->GetOutput()->GetNumberOfCells() < cells2);
  CHECK(r->GetOutput()->GetNumberOfCells() > 0);
  for (const char* name : { "Threshold", "NodeId", "Step" })
  {
    vtkDataArray* a = at2->GetCellData()->GetArray(name);
    vtkDataArray* b = r->GetOutput()->GetCellData()->GetArray(name);
    CHECK(a && b && a != b && a->GetVoidPointer(0) == b->GetVoidPointer(0));
  }
  CHECK(at2->GetPoints()->GetData()->GetVoidPointer(0) ==
    r->GetOutput()->GetPoints()->GetData()->GetVoidPointer(0));
  CHECK(at2->GetNumberOfCells() == cells2); // the earlier output is left as it was
  r->SetReconstructionThreshold(2.0);
  r->Update();
  CHECK(r->GetNumberOfQueueRuns() == 1);
  CHECK(r->GetOutput()->GetNumberOfCells() == cells2);
  s->SetPersistenceThreshold(1.05); // a new input
  r->Update();
  CHECK(r->GetNumberOfQueueRuns() == 2);
  // The profile's rows: steps 0..n-1 in order, Threshold the running maximum of Priority.
  profile = vtkTable::SafeDownCast(r->GetOutputDataObject(1));
  vtkDataArray* step = vtkDataArray::SafeDownCast(profile->GetColumnByName("Step"));
  vtkDataArray* priority = vtkDataArray::SafeDownCast(profile->GetColumnByName("Priority"));
  vtkDataArray* threshold = vtkDataArray::SafeDownCast(profile->GetColumnByName("Threshold"));
  double running = 0;
  bool ok = step && priority && threshold;
  for (vtkIdType k = 0; ok && k < profile->GetNumberOfRows(); ++k)
  {
    running = std::max(running, priority->GetComponent(k, 0));
    ok = step->GetComponent(k, 0) == k && threshold->GetComponent(k, 0) == running;
  }
  CHECK(ok);
  // Its ids in 32 bits (a row per step, millions of them), and t_r on every row.
  for (const char* name : { "Step", "NodeId", "Sponsor" })
  {
    auto* a = vtkDataArray::SafeDownCast(profile->GetColumnByName(name));
    CHECK(a && a->GetDataTypeSize() == 4);
  }
  auto* mark = vtkDataArray::SafeDownCast(profile->GetColumnByName("t_r"));
  ok = mark && mark->GetNumberOfTuples() == profile->GetNumberOfRows();
  for (vtkIdType k = 0; ok && k < profile->GetNumberOfRows(); ++k)
  {
    ok = mark->GetComponent(k, 0) == 2.0;
  }
  CHECK(ok);

  // An abort leaves every output empty and caches nothing: the next update reruns.
  CHECK(!Empty(r->GetOutputDataObject(vtkFlowReconstruction::TOPOLOGY_PROFILE)));
  s->SetPersistenceThreshold(1.1);
  UpdateAborting(r, -1); // at the first progress event
  CHECK(r->GetNumberOfQueueRuns() == 3);
  CHECK(AllOutputsEmpty(r));
  UpdateAgain(r);
  CHECK(r->GetNumberOfQueueRuns() == 4);
  CHECK(r->GetOutput()->GetNumberOfCells() == cells2);
}

/// An abort while the stable manifolds are drawn leaves every output empty;
/// the queue's run stays cached, and the next update only draws.
void TestDrawingAbort(const Cloud& cloud)
{
  std::cout << "-- abort while drawing\n";
  vtkNew<vtkFlowComplexSimplification> s;
  s->SetInputData(FlowComplexOf(cloud, -2)); // no stable manifolds: drawn on demand
  s->AutomaticPersistenceThresholdOff();
  vtkNew<vtkFlowReconstruction> r;
  r->SetInputConnection(s->GetOutputPort());
  r->SetReconstructionThreshold(2.0);
  r->AutomaticReconstructionThresholdOff();
  vtkObject::GlobalWarningDisplayOff(); // the abort's warning
  UpdateAborting(r, 0.3); // past the queue's 30 %: while drawing
  vtkObject::GlobalWarningDisplayOn();
  CHECK(r->GetAbortExecute() == 1);
  CHECK(r->GetNumberOfQueueRuns() == 1);
  CHECK(AllOutputsEmpty(r));
  UpdateAgain(r);
  CHECK(r->GetNumberOfQueueRuns() == 1);
  CHECK(r->GetOutput()->GetNumberOfCells() > 0);
}

void TestErrors()
{
  std::cout << "-- errors\n";
  vtkObject::GlobalWarningDisplayOff(); // the expected error messages
  vtkNew<vtkMultiBlockDataSet> empty;
  vtkNew<vtkFlowReconstruction> r;
  r->SetInputData(empty);
  r->SetReconstructionThreshold(-5);
  CHECK(r->GetReconstructionThreshold() == 1.0); // clamped
  r->Update(); // an error message, no crash, empty outputs
  CHECK(r->GetOutput()->GetNumberOfCells() == 0);
  vtkNew<vtkFlowComplexSimplification> s;
  s->SetInputData(empty);
  s->SetPersistenceThreshold(-1);
  CHECK(s->GetPersistenceThreshold() == 0.0);
  s->Update();
  CHECK(s->GetOutput()->GetNumberOfBlocks() == 0);
  vtkObject::GlobalWarningDisplayOn();
}

/// A saved complex whose UnstableManifolds polyline names a point that does not
/// exist (one edited id) must give an error naming the block, not a crash.
void TestCorruptFlowLines()
{
  std::cout << "-- corrupt UnstableManifolds\n";
  vtkNew<vtkPoints> pts;
  for (const auto& p : FibonacciSphere(60))
  {
    pts->InsertNextPoint(p.data());
  }
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(pts);
  vtkNew<vtkFlowComplex> fc;
  fc->SetInputData(cloud);
  fc->Update();
  vtkNew<vtkMultiBlockDataSet> complex;
  complex->DeepCopy(fc->GetOutput());
  vtkPolyData* lines = nullptr;
  for (unsigned int b = 0; b < complex->GetNumberOfBlocks(); ++b)
  {
    const char* name = complex->GetMetaData(b)->Get(vtkCompositeDataSet::NAME());
    if (name && std::string(name) == "UnstableManifolds")
    {
      lines = vtkPolyData::SafeDownCast(complex->GetBlock(b));
    }
  }
  CHECK(lines && lines->GetNumberOfCells() > 0);
  if (!lines || lines->GetNumberOfCells() == 0)
  {
    return;
  }
  vtkNew<vtkIdList> ids;
  lines->GetCellPoints(0, ids);
  ids->SetId(ids->GetNumberOfIds() - 1, 1000000000);
  lines->GetLines()->ReplaceCellAtId(0, ids);
  std::string message;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&message);
  onError->SetCallback([](vtkObject*, unsigned long, void* data, void* call) {
    *static_cast<std::string*>(data) += static_cast<const char*>(call);
  });
  // Error events are invoked only while warnings are displayed (the two messages
  // below are expected).
  vtkNew<vtkFlowComplexSimplification> s;
  s->AddObserver(vtkCommand::ErrorEvent, onError);
  s->SetInputData(complex);
  s->Update();
  CHECK(message.find("UnstableManifolds") != std::string::npos);
  message.clear();
  vtkNew<vtkFlowReconstruction> r;
  r->AddObserver(vtkCommand::ErrorEvent, onError);
  r->SetInputData(complex);
  r->Update();
  CHECK(message.find("UnstableManifolds") != std::string::npos);
  CHECK(r->GetOutput()->GetNumberOfCells() == 0);
}

/// A degenerate cloud (an exact grid) is perturbed with the filter's seed; a
/// reconstruction redrawn from a saved complex must redo that perturbation
/// (the seed travels in the file) to find the same cells.
void TestSeedTravels(const std::string& dir)
{
  std::cout << "-- perturbation seed in the file\n";
  Cloud grid;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 4; ++k)
        grid.push_back({ { double(i), double(j), double(k) } });
  auto eager = Reconstructed(FlowComplexOf(grid, -1, 7), 3.0);
  auto lazy = Reconstructed(RoundTrip(FlowComplexOf(grid, -2, 7), dir + "/grid_seed7.vtm"), 3.0);
  CHECK(eager->GetNumberOfCells() > 0);
  CHECK(Rows(lazy) == Rows(eager));
  // Another seed gives another perturbation: the rows differ (so the check above
  // would notice a lost seed).
  CHECK(Rows(Reconstructed(FlowComplexOf(grid, -1, 1), 3.0)) != Rows(eager));
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string dir = argc > 1 ? argv[1] : ".";
  TestErrors();
  TestCorruptFlowLines();
  TestSeedTravels(dir);
  TestQueueCache(FibonacciSphere(300));
  TestDrawingAbort(FibonacciSphere(300));
  TestShape("sphere", FibonacciSphere(800), { { 1, 0, 1, 0 } }, dir);
  TestShape("torus", GridTorus(40, 14), { { 1, 2, 1, 0 } }, dir);
  return check::Finish("TestReconstructionFilters");
}
