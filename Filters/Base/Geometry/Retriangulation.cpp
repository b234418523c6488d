#include "Retriangulation.h"

#include "Arithmetic.h"
#include "MemoryGuard.h"
#include "StoredCriticalSimplices.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace flowrecon
{

namespace
{

/// Triangulation, critical simplices and the walk tables, per distinct point
/// (measured peaks of the builder are 1.4-1.5 KB per point on volume samples).
constexpr double BytesPerPoint = 1500;

} // namespace

const char* Retriangulation::Mismatch()
{
  return "the flow complex does not belong to its points (edited file, or another perturbation seed)";
}

Retriangulation::Retriangulation(const std::vector<Point3>& points, const BuildOptions& options,
  const FlowComplex& fc, const Progress& progress, const std::string& advice)
  : In(PrepareForTriangulation(points))
  , Opts(options)
{
  const std::array<Id, 4> n = fc.CountByIndex();
  if (static_cast<Id>(this->In.Unique.size()) != n[0])
  {
    throw InputError(Mismatch());
  }
  for (const Node& node : fc.Nodes)
  {
    // A sample node sits exactly on its sample: any edited point shows here.
    if (node.Index == 0 && !node.IsInfinity() &&
      (node.Simplex[0] >= static_cast<Id>(points.size()) || points[node.Simplex[0]] != node.Location))
    {
      throw InputError(Mismatch());
    }
  }
  RequireMemory(BytesPerPoint * static_cast<double>(this->In.Unique.size()),
    "the triangulation of " + std::to_string(this->In.Unique.size()) + " points", advice);
  this->Coords = std::make_unique<const std::vector<Point3>>(
    AttemptCoordinates(this->In, fc.Report.Attempts, options.Seed));
  progress(0.0, "Delaunay triangulation");
  this->Tri_ = std::make_unique<const Triangulation>(*this->Coords, progress.Range(0, 0.2));
  progress(0.2, "critical points");
  // The nodes name the critical simplices; each is checked on the new
  // triangulation rather than every simplex classified again.
  this->Cs = StoredCriticalSimplices(*this->Tri_, fc.Nodes, this->In.InputId, Mismatch(), progress);
  this->SetBases();
  if (fc.InfinityNode != this->Base3_ + static_cast<Id>(this->Cs.Cells.size()))
  {
    throw InputError(Mismatch());
  }
  progress(0.35, "critical points");
}

std::unique_ptr<Retriangulation> Retriangulation::OfStoredComplex(
  const FlowComplex& fc, const Progress& progress, const std::string& advice)
{
  if (fc.NumberOfInputPoints < 0 || fc.NumberOfInputPoints > static_cast<Id>(fc.Points.size()))
  {
    throw InputError(Mismatch());
  }
  const std::vector<Point3> samples(fc.Points.begin(), fc.Points.begin() + fc.NumberOfInputPoints);
  BuildOptions options;
  options.Seed = fc.Report.Seed;
  return std::make_unique<Retriangulation>(samples, options, fc, progress, advice);
}

Retriangulation::Retriangulation(PreparedInput in, const BuildOptions& options,
  std::unique_ptr<const std::vector<Point3>> coords, std::unique_ptr<const Triangulation> tri,
  CriticalSimplices cs, std::unique_ptr<SuccessorForest> flow,
  std::unique_ptr<const std::vector<std::int32_t>> maximumOfCell, RecordedWalks walks)
  : In(std::move(in))
  , Opts(options)
  , Coords(std::move(coords))
  , Tri_(std::move(tri))
  , Cs(std::move(cs))
  , MaximumOfCell(std::move(maximumOfCell))
  , Forest(std::move(flow))
  , Walks_(std::move(walks))
{
  if (static_cast<bool>(this->Forest) != static_cast<bool>(this->MaximumOfCell))
  {
    throw std::logic_error("a kept flow-line forest without its maxima");
  }
  this->SetBases();
}

// The forest refers to the triangulation: it goes first.
Retriangulation::~Retriangulation()
{
  this->Forest.reset();
}

SuccessorForest& Retriangulation::Flow() const
{
  if (!this->Forest)
  {
    auto maxima = std::make_unique<std::vector<std::int32_t>>(
      static_cast<std::size_t>(this->Tri_->NumberOfCells()), -1);
    for (std::size_t i = 0; i < this->Cs.Cells.size(); ++i)
    {
      (*maxima)[this->Cs.Cells[i].Cell] = static_cast<std::int32_t>(this->Base3_ + static_cast<Id>(i));
    }
    this->MaximumOfCell = std::move(maxima);
    this->Forest = std::make_unique<SuccessorForest>(*this->Tri_, *this->MaximumOfCell,
      this->Base3_ + static_cast<Id>(this->Cs.Cells.size()), 0, false, this->Opts.ExactOnly);
  }
  return *this->Forest;
}

void Retriangulation::ReleaseWalks() const
{
  this->Walks_ = RecordedWalks();
}

void Retriangulation::ReleaseFlow() const
{
  this->Forest.reset(); // it refers to MaximumOfCell
  this->MaximumOfCell.reset();
}

void Retriangulation::SetBases()
{
  this->Base2_ = this->Tri_->NumberOfVertices() + this->Cs.Edges.ValueCount();
  this->Base3_ = this->Base2_ + static_cast<Id>(this->Cs.Facets.size());
}

bool Retriangulation::SameSimplex(const FlowComplex& fc, Id node, const Id* vertices, int count) const
{
  std::array<std::int32_t, 4> s{ { -1, -1, -1, -1 } };
  for (int k = 0; k < count; ++k)
  {
    s[k] = static_cast<std::int32_t>(this->In.InputId[vertices[k]]);
  }
  std::sort(s.begin(), s.begin() + count);
  return s == fc.Nodes[node].Simplex;
}

Point3 Retriangulation::BackScaled(Point3 p) const
{
  return this->In.BackScaled(p);
}

} // namespace flowrecon
