#include "FlowComplexBuilder.h"

#include "BuildPhases.h"
#include "ExactCriticalPoint.h"
#include "Retriangulation.h"
#include "StableManifoldGeometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace flowrecon
{
namespace internal
{

/// Circumcentre (within the simplex's affine hull) and squared radius of a
/// simplex of 2..4 points; double constructions, relative to its first vertex.
std::array<double, 4> CentreAndSquaredRadius(const KPoint* p, std::size_t n)
{
  KPoint c;
  if (n == 2)
  {
    c = CGAL::midpoint(p[0], p[1]);
  }
  else if (n == 3)
  {
    c = CGAL::circumcenter(p[0], p[1], p[2]);
  }
  else
  {
    c = CGAL::circumcenter(p[0], p[1], p[2], p[3]);
  }
  return { { c.x(), c.y(), c.z(), CGAL::squared_distance(c, p[0]) } };
}

const char* const TooLarge = "coordinates too large: a critical point lies beyond the largest double "
                             "(about 1.8e308); rescale the cloud";
const char* const TooClose = "points too close together for the size of the cloud (a critical "
                             "value underflows in double precision); rescale or separate the clusters";

Node Builder::MakeNode(int index, const Id* simplex, const std::vector<Point3>& coords, bool count) const
{
  Node node;
  node.Index = index;
  KPoint pts[4];
  for (int i = 0; i <= index; ++i)
  {
    node.Simplex[i] = this->In.InputId[simplex[i]];
    const Point3& c = coords[simplex[i]];
    pts[i] = KPoint(c[0], c[1], c[2]);
  }
  std::sort(node.Simplex.begin(), node.Simplex.begin() + index + 1);
  if (index == 0)
  {
    node.Location = this->Input[node.Simplex[0]];
    node.Value = 0;
  }
  else
  {
    if (this->Perturbed)
    {
      // The perturbation chose the simplex; its value is the input's.
      Point3 input[4];
      for (int i = 0; i <= index; ++i)
      {
        input[i] = this->In.Unique[simplex[i]];
      }
      ExactCriticalPoint e;
      if (ExactCriticalPointOf(input, index + 1, e))
      {
        node.Location = e.Location;
        node.Value = std::sqrt(e.SquaredRadius);
        return node;
      }
      if (count)
      {
        this->PerturbedValues.fetch_add(1, std::memory_order_relaxed);
      }
    }
    const std::array<double, 4> cr = CentreAndSquaredRadius(pts, static_cast<std::size_t>(index + 1));
    node.Location = { { cr[0], cr[1], cr[2] } };
    node.Value = std::sqrt(cr[3]);
  }
  return node;
}

void Builder::Run(const std::vector<Point3>& coords, bool first)
{
  FlowComplex& fc = this->FC;
  this->CoordsOfAttempt = &coords;
  this->First = first;
  this->PerturbedValues = 0;
  // The triangulation refers to this attempt's coordinates: whatever happens,
  // it and the critical simplices go with the attempt (the retry makes new ones).
  struct Release
  {
    Builder* B;
    ~Release()
    {
      B->LineForest.reset();
      B->LineMaxima.reset();
      B->Tri.reset();
      B->Cs = CriticalSimplices();
    }
  } release{ this };
  auto t = Clock::now();
  this->Triangulate();
  fc.Time.Delaunay = Seconds(t);
  t = Clock::now();
  this->FindCriticalPoints();
  fc.Time.CriticalPoints = Seconds(t);
  this->DeferFarPatches();
  t = Clock::now();
  this->WalkStablePatches();
  fc.Time.StableManifolds = Seconds(t);
  t = Clock::now();
  this->TraceUnstableManifolds();
  this->LowerPendingBounds();
  fc.Time.UnstableManifolds = Seconds(t);
  t = Clock::now();
  this->AssembleHasseDiagram();
  this->BuildStableCones();
  fc.Time.Assembly = Seconds(t);
  if (this->Keep)
  {
    this->KeptTriangulation = std::move(this->Tri);
    this->KeptCritical = std::move(this->Cs);
    this->KeptForest = std::move(this->LineForest);
    this->KeptMaximumOfCell = std::move(this->LineMaxima);
  }
}

void Builder::LowerPendingBounds()
{
  if (!this->Perturbed)
  {
    return;
  }
  // A pending line's Bound is below the perturbed value r' of the maximum it
  // reaches, which is the radius of the smallest ball enclosing that cell's
  // perturbed vertices (the cell contains its circumcentre). Each vertex moved
  // by at most sqrt(3) Displacement (plus a rounding of under 1/64 of it), so
  // the input's vertices fit in that ball widened by eps = 1.8 Displacement:
  // the input value, the radius of a sphere through them, is at least r' - eps
  // (also for the circle of a flat cell). The value's own truncation: 4 ulps.
  const double eps = 1.8 * this->Displacement;
  for (PendingFlowLine& line : this->FC.PendingFlowLines)
  {
    const double b = (static_cast<double>(line.Bound) - eps) * (1 - 4 * std::numeric_limits<double>::epsilon());
    line.Bound = RoundedDown(std::max(0.0, b));
  }
}

void Builder::ScaleBack()
{
  const int e = this->ScaleExponent;
  if (e == 0 && this->In.Translation == Point3{ { 0, 0, 0 } })
  {
    return;
  }
  auto back = [this](Point3& p) { p = this->In.BackScaled(p); };
  FlowComplex& fc = this->FC;
  for (Node& n : fc.Nodes)
  {
    if (n.Index > 0 && !n.IsInfinity())
    {
      n.Value = std::ldexp(n.Value, e);
      back(n.Location);
      // Scaled, the construction was finite; back at the cloud's scale a
      // critical point of a cloud near the largest doubles can lie beyond them.
      if (!(std::isfinite(n.Value) && std::isfinite(n.Location[0]) && std::isfinite(n.Location[1]) &&
            std::isfinite(n.Location[2])))
      {
        throw InputError(TooLarge);
      }
    }
  }
  for (std::size_t k = static_cast<std::size_t>(fc.NumberOfInputPoints); k < fc.Points.size(); ++k)
  {
    back(fc.Points[k]);
  }
  for (PendingFlowLine& line : fc.PendingFlowLines)
  {
    line.Bound = RoundedDown(std::ldexp(static_cast<double>(line.Bound), e));
  }
  for (FlowLine& line : fc.FlowLines)
  {
    for (Point3& p : line.Points)
    {
      back(p);
    }
  }
}

} // namespace internal

using internal::Builder;
using internal::Clock;
using internal::Seconds;

FlowComplex BuildFlowComplex(
  const std::vector<Point3>& points, const BuildOptions& options, const Progress& progress)
{
  return BuildFlowComplex(points, options, progress, nullptr);
}

FlowComplex BuildFlowComplex(const std::vector<Point3>& points, const BuildOptions& options,
  const Progress& progress, std::unique_ptr<Retriangulation>* keep)
{
  if (keep && options.StableManifolds)
  {
    throw InputError("keeping the triangulation is for builds without geometry");
  }
  if (options.StableManifolds && options.MaximumGeometryCells >= 0)
  {
    // A budget: the Hasse diagram first, then the nodes that fit are drawn.
    const auto start = Clock::now();
    BuildOptions hasse = options;
    hasse.StableManifolds = false;
    Progress first = progress, second = progress;
    if (progress.Report)
    {
      first.Report = [&](double f, const char* phase) { progress.Report(0.7 * f, phase); };
      second.Report = [&](double f, const char* phase) { progress.Report(0.7 + 0.3 * f, phase); };
    }
    // The build's triangulation is kept for the drawing when there is one: the
    // drawing would otherwise compute it again (a quarter of a surface's build),
    // and the kept one costs no more than that second one at the drawing's peak.
    std::unique_ptr<Retriangulation> kept;
    FlowComplex fc = BuildFlowComplex(
      points, hasse, first, options.MaximumGeometryCells > 0 ? &kept : nullptr);
    std::vector<Id> counts = StableManifoldCellCounts(fc.Nodes, fc.Arcs);
    for (const Id node : fc.DeferredPatches)
    {
      // Not walked, so of unknown size (a patch across a tube): the drawing
      // stops below the first of them, keeping the budget a bound.
      counts[node] = std::numeric_limits<Id>::max() / 4;
    }
    const std::vector<Id> draw = NodesWithinBudget(fc.Nodes, counts, options.MaximumGeometryCells);
    const auto t = Clock::now();
    DrawStableManifolds(points, options, draw, fc, second, "lower the cell budget", nullptr, kept.get());
    fc.Time.StableManifolds += Seconds(t);
    fc.Time.Total = Seconds(start);
    progress(1.0, "done");
    return fc;
  }
  const auto start = Clock::now();
  PreparedInput in = PrepareForTriangulation(points);
  FlowComplex fc;
  fc.Representative = in.Representative;
  fc.Report.InputPoints = static_cast<Id>(points.size());
  fc.Report.DuplicatePoints = static_cast<Id>(points.size() - in.Unique.size());
  Builder builder(in, points, options, progress, fc);
  builder.ScaleExponent = in.ScaleExponent;
  builder.Keep = keep != nullptr;
  std::unique_ptr<const std::vector<Point3>> coords;
  for (int attempt = 1;; ++attempt)
  {
    const double magnitude = PerturbationMagnitude(in, attempt);
    try
    {
      builder.KeptForest.reset(); // refers to the triangulation below
      builder.KeptMaximumOfCell.reset();
      builder.KeptTriangulation.reset(); // refers to the coordinates below
      builder.Perturbed = attempt > 1;
      builder.Displacement = magnitude;
      coords = std::make_unique<const std::vector<Point3>>(AttemptCoordinates(in, attempt, options.Seed));
      builder.Run(*coords, attempt == 1);
      fc.Report.Attempts = attempt;
      fc.Report.Seed = options.Seed;
      fc.Report.PerturbationMagnitude = std::ldexp(magnitude, builder.ScaleExponent);
      fc.Report.PerturbedValues = builder.PerturbedValues.load();
      break;
    }
    catch (const Degenerate& e)
    {
      if (attempt >= options.MaxAttempts)
      {
        throw InputError(std::string("input too degenerate even after perturbation (") +
          e.what() + ")");
      }
    }
  }
  if (keep)
  {
    *keep = std::make_unique<Retriangulation>(std::move(in), options, std::move(coords),
      std::move(builder.KeptTriangulation), std::move(builder.KeptCritical),
      std::move(builder.KeptForest), std::move(builder.KeptMaximumOfCell),
      std::move(builder.KeptWalks));
  }
  fc.Time.Total = Seconds(start);
  progress(1.0, "done");
  return fc;
}

} // namespace flowrecon
