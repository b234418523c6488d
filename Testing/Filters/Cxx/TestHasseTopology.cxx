// The Betti numbers a cloud's reconstruction reports come from its Hasse
// diagram (HasseBarcode); the oracle is the persistent homology over Z/2 of the
// cells actually written (CellBarcode on the output grid, filtered by each
// cell's Threshold). Both topology profiles must agree at every t_r up to the
// cap, on clouds of every kind, with and without simplification, and with the
// deferred patches and flow lines of the output-sensitive run. The same for a
// stored flow complex (what Flow Complex Simplification's automatic t_p reads,
// TopologyOfStoredComplex), with and without deferred patches, against the
// cells the Simplification and Reconstruction filters write.
#include "Check.h"
#include "Clouds.h"

#include "CellHomology.h"
#include "CloudReconstruction.h"
#include "FlowComplexFromVTK.h"
#include "Retriangulation.h"
#include "StoredComplexTopology.h"
#include "vtkFlowComplex.h"
#include "vtkFlowComplexSimplification.h"
#include "vtkFlowReconstruction.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPointCloudReader.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkCellData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace flowrecon;

void Expect(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cout << "TestHasseTopology: " << what << "\n";
    ++check::Failures();
  }
}

/// Betti numbers (b0, b1, b2) at t of a profile given as (threshold, betti) rows.
std::array<Id, 3> At(const std::vector<TopologyStep>& rows, double t)
{
  std::array<Id, 3> b{ { -1, -1, -1 } };
  for (const TopologyStep& row : rows)
  {
    if (row.Threshold < t)
    {
      b = { { row.Betti[0], row.Betti[1], row.Betti[2] } };
    }
  }
  return b;
}

std::vector<TopologyStep> Rows(vtkTable* table)
{
  std::vector<TopologyStep> rows;
  for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
  {
    TopologyStep s;
    s.Threshold = table->GetValueByName(r, "Threshold").ToDouble();
    for (int d = 0; d < 3; ++d)
    {
      s.Betti[d] = table->GetValueByName(r, ("b" + std::to_string(d)).c_str()).ToLongLong();
    }
    rows.push_back(s);
  }
  return rows;
}

/// The oracle: the written cells, each from its Threshold.
std::vector<TopologyStep> CellProfile(vtkUnstructuredGrid* grid, double cap)
{
  FilteredCells cells;
  vtkDataArray* threshold = grid->GetCellData()->GetArray("Threshold");
  std::vector<Id> ids;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    vtkIdType n;
    const vtkIdType* pts;
    grid->GetCellPoints(c, n, pts);
    ids.assign(pts, pts + n);
    cells.Add(ids.data(), static_cast<int>(n), threshold->GetTuple1(c));
  }
  return TopologyProfile(CellBarcode(cells), 1, cap);
}

/// The two profiles give the same Betti numbers at every t_r in (1, cap].
void SameProfiles(const std::string& what, const std::vector<TopologyStep>& hasse,
  const std::vector<TopologyStep>& cells, double cap)
{
  std::vector<double> at;
  for (const auto* rows : { &hasse, &cells })
  {
    for (const TopologyStep& s : *rows)
    {
      at.push_back(s.Threshold);
    }
  }
  std::sort(at.begin(), at.end());
  at.push_back(cap);
  int differ = 0;
  for (std::size_t k = 0; k + 1 < at.size(); ++k)
  {
    const double t = std::min(cap, 0.5 * (at[k] + at[k + 1]));
    if (!(t > 1) || at[k] == at[k + 1])
    {
      continue;
    }
    const auto a = At(hasse, t), b = At(cells, t);
    if (a != b && ++differ <= 3)
    {
      std::cout << what << ": at t_r " << t << " Hasse " << a[0] << " " << a[1] << " " << a[2]
                << ", cells " << b[0] << " " << b[1] << " " << b[2] << "\n";
    }
  }
  Expect(differ == 0, what + ": the profiles differ at " + std::to_string(differ) + " places");
}

long& LinesEndedLower()
{
  static long count = 0;
  return count;
}

long& LinesEndedEarly()
{
  static long n = 0;
  return n;
}

void Compare(const std::string& name, const std::vector<Point3>& cloud, double tp, double cap)
{
  CloudReconstructionSettings settings;
  settings.PersistenceThreshold = tp;
  settings.ReconstructionThreshold = 2;
  settings.OutputThreshold = settings.DrawThreshold = settings.Cap = cap;
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkTable> profile, topology;
  vtkNew<vtkPolyData> warnings;
  const CloudReconstructionReport report = ReconstructCloud(
    cloud, settings, { grid, profile, topology, warnings }, Progress(), [](const char*) {});
  const std::string what = name + " t_p " + std::to_string(tp) + " cap " + std::to_string(cap);
  Expect(report.TopologyError.empty(), what + ": " + report.TopologyError);
  // Lines ended in a region of the complement rather than followed (TopologyInput.h).
  const std::string tag = "ended in regions of the complement for the topology: ";
  const std::size_t at = report.Work.find(tag);
  Expect(at != std::string::npos, what + ": the work report does not count the lines ended early");
  LinesEndedEarly() += at == std::string::npos ? 0 : std::stol(report.Work.substr(at + tag.size()));
  // Of those, the lines of nodes present before r*: ended at a lower level.
  const std::string lower = "Delaunay cells; ";
  const std::size_t low = report.Work.find(lower);
  Expect(low != std::string::npos, what + ": the work report does not count the lines ended at a lower level");
  const long below = low == std::string::npos ? 0 : std::stol(report.Work.substr(low + lower.size()));
  LinesEndedLower() += below;
  // The levels' premises hold by construction: never a fallback to every line.
  Expect(report.Work.find("every line followed") == std::string::npos,
    what + ": the topology followed every line (a level's premise failed)");
  if (below > 0)
  {
    std::cout << what << ": " << below << " flow lines ended at a lower level\n";
  }
  const std::vector<TopologyStep> hasse = Rows(topology);
  const std::vector<TopologyStep> cells = CellProfile(grid, cap);
  if (name == "grid")
  {
    // Exact values on a unit grid: edge midpoints 1/2, square centres sqrt(2)/2,
    // cube centres sqrt(3)/2, so every step is at one of their ratios (the
    // perturbation decides only the combinatorics). A t_p above a ratio
    // cancels its pairs, so the profile may be one row.
    // The filled cube is the last reconstruction: contractible.
    Expect(!hasse.empty() && hasse.back().Betti[0] == 1 && hasse.back().Betti[1] == 0 &&
        hasse.back().Betti[2] == 0,
      what + ": the last reconstruction is not contractible");
    for (const TopologyStep& row : hasse)
    {
      bool exact = false;
      for (const double r : { 1.0, std::sqrt(1.5), std::sqrt(2.0), std::sqrt(3.0) })
      {
        exact = exact || std::abs(row.Threshold - r) <= 1e-12 * r;
      }
      Expect(exact, what + ": a step at t_r " + std::to_string(row.Threshold) +
          ", not a ratio of the grid's critical values");
    }
  }
  else
  {
    Expect(hasse.size() > 3, what + ": a profile of a few rows only");
  }
  SameProfiles(what, hasse, cells, cap);
}

/// A stored flow complex (vtkFlowComplex's output, its patches above `defer`
/// deferred, and the cap there; 0: none, cap 5): the topology TopologyOfStoredComplex reads off its
/// Hasse diagram, against the cells Flow Complex Simplification and Flow
/// Reconstruction write at the same t_p (given), up to the cap.
void CompareStored(const std::string& name, const std::vector<Point3>& cloud, double tp, double defer)
{
  const double cap = defer > 1 ? defer : 5; // the cap may not pass the deferral
  vtkNew<vtkPoints> points;
  for (const Point3& p : cloud)
  {
    points->InsertNextPoint(p[0], p[1], p[2]);
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  vtkNew<vtkFlowComplex> complex;
  complex->SetInputData(input);
  complex->SetComputeStableManifolds(false);
  complex->SetDeferPatchesAbove(defer);
  complex->Update();
  auto* blocks = vtkMultiBlockDataSet::SafeDownCast(complex->GetOutputDataObject(0));
  FlowComplex fc;
  std::string error;
  const bool read = FromMultiBlock(blocks, fc, error, true) && ReadSamples(blocks, fc, error);
  const std::string what = name + " stored, t_p " + std::to_string(tp) + " deferred above " +
    std::to_string(defer) + " (" + std::to_string(fc.DeferredPatches.size()) + " patches)";
  Expect(read, what + ": " + error);
  // The torus's far patches are deferred (the walks of the late patches are checked).
  Expect(name != "torus" || defer == 0 || fc.DeferredPatches.size() > 100, what + ": too few deferred");
  std::unique_ptr<Retriangulation> re;
  if (!fc.DeferredPatches.empty())
  {
    re = Retriangulation::OfStoredComplex(fc, Progress(), "");
  }
  const StoredTopology t = TopologyOfStoredComplex(fc, tp, cap, re.get(), Progress());
  Expect(t.Error.empty(), what + ": " + t.Error);

  vtkNew<vtkFlowComplexSimplification> simplification;
  simplification->SetInputConnection(complex->GetOutputPort());
  simplification->AutomaticPersistenceThresholdOff();
  simplification->SetPersistenceThreshold(tp);
  vtkNew<vtkFlowReconstruction> reconstruction;
  reconstruction->SetInputConnection(simplification->GetOutputPort());
  reconstruction->AutomaticReconstructionThresholdOff();
  reconstruction->SetMaximumThreshold(cap);
  reconstruction->SetReconstructionThreshold(cap);
  reconstruction->Update();
  const std::vector<TopologyStep> cells = CellProfile(reconstruction->GetOutput(), cap);
  Expect(t.Profile.size() > 3, what + ": a profile of a few rows only");
  SameProfiles(what, t.Profile, cells, cap);
  std::cout << what << ": " << t.Profile.size() << " profile rows\n";
}

/// Two unit spheres through each other's centres: b2 = 3, non-manifold.
std::vector<Point3> TwoSpheres(int n, std::uint64_t seed)
{
  std::vector<Point3> a = clouds::Sphere(n / 2, seed), b = clouds::Sphere(n - n / 2, seed + 1);
  for (Point3& p : a)
  {
    p[0] -= 0.5;
  }
  for (Point3& p : b)
  {
    p[0] += 0.5;
  }
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// A trefoil knot, i.i.d. along its parameter: a curve.
std::vector<Point3> Trefoil(int n, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 2 * M_PI);
  std::vector<Point3> p;
  for (int k = 0; k < n; ++k)
  {
    const double t = u(rng);
    p.push_back({ { (std::sin(t) + 2 * std::sin(2 * t)) / 3,
      (std::cos(t) - 2 * std::cos(2 * t)) / 3, -std::sin(3 * t) / 3 } });
  }
  return p;
}

/// The bundled bunny's samples, read as the tools read a cloud.
std::vector<Point3> Bunny()
{
  vtkNew<vtkPointCloudReader> reader;
  reader->SetFileName(FLOWRECON_BUNNY);
  reader->Update();
  std::vector<Point3> p;
  auto* cloud = vtkPointSet::SafeDownCast(reader->GetOutputDataObject(0));
  for (vtkIdType i = 0; cloud && i < cloud->GetNumberOfPoints(); ++i)
  {
    double x[3];
    cloud->GetPoint(i, x);
    p.push_back({ { x[0], x[1], x[2] } });
  }
  Expect(p.size() > 1000, std::string("cannot read ") + FLOWRECON_BUNNY);
  return p;
}

/// An exact integer grid: cospherical and right-angled everywhere (perturbed).
std::vector<Point3> Grid(int k)
{
  std::vector<Point3> p;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z)
        p.push_back({ { double(x), double(y), double(z) } });
  return p;
}

} // namespace

int main()
{
  for (const double tp : { 0.0, 1.1, 1.5 })
  {
    for (const double cap : { 4.0, 8.0 })
    {
      Compare("sphere", clouds::Sphere(1500, 3), tp, cap);
      Compare("torus", clouds::Torus(2000, 5), tp, cap);
      Compare("two spheres", TwoSpheres(2400, 7), tp, cap);
      Compare("cube", clouds::Cube(800, 11), tp, cap);
      Compare("trefoil", Trefoil(600, 13), tp, cap);
      Compare("icosahedron", clouds::Icosahedron(1500, 17), tp, cap);
      Compare("grid", Grid(6), tp, cap);
      // Its inner maxima enter at t_p 0 after most of its patches: the lines
      // of those end at levels below r* (TopologyInput.h).
      Compare("bunny", Bunny(), tp, cap);
    }
    for (const double defer : { 0.0, 2.5 })
    {
      CompareStored("torus", clouds::Torus(3000, 19), tp, defer);
      CompareStored("two spheres", TwoSpheres(2400, 7), tp, defer);
      CompareStored("cube", clouds::Cube(800, 11), tp, defer);
    }
  }
  // The fixtures exercise the regions, not only the lines followed to their maxima.
  std::cout << LinesEndedEarly() << " flow lines ended in a region of the complement\n";
  Expect(LinesEndedEarly() > 1000, "few flow lines ended in a region of the complement");
  // And the lower levels, where a node present before r* needs less.
  std::cout << LinesEndedLower() << " of them at a level below r*\n";
  Expect(LinesEndedLower() > 1000, "few flow lines ended at a level below r*");
  return check::Finish("TestHasseTopology");
}
