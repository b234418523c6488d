// Build phase 4: the unstable manifolds of the index-2 critical points, two flow
// lines each, followed to the maxima they reach (the ends of the 2-3 arcs).
#include "BuildPhases.h"

#include "DrawingBox.h"
#include "ParallelSlices.h"
#include "StableManifold.h"
#include "StableManifoldGeometry.h"
#include "SuccessorForest.h"

#include <algorithm>
#include <tbb/enumerable_thread_specific.h>

#include <cmath>
#include <limits>
#include <tuple>

namespace flowrecon
{
namespace internal
{

float RoundedDown(double x)
{
  if (!(x < static_cast<double>(std::numeric_limits<float>::max())))
  {
    return std::numeric_limits<float>::max();
  }
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x)
  {
    f = std::nextafter(f, 0.0f);
  }
  return f;
}

namespace
{

/// The end of the stub drawn from `centre` along the Voronoi ray of hull facet
/// `f`: normal to the facet, away from `other`, the finite cell beyond
/// `infinite`.
Point3 RayEnd(const Triangulation& tri, const std::array<std::int32_t, 3>& f, CellHandle infinite,
  CellHandle other, const Point3& centre, double stub)
{
  const KPoint& apex = other->vertex(other->index(infinite))->point();
  const KPoint& p = tri.KCoord(f[0]);
  Kernel::Vector_3 n = CGAL::cross_product(tri.KCoord(f[1]) - p, tri.KCoord(f[2]) - p);
  if (n * (apex - p) > 0)
  {
    n = -n;
  }
  const double len = std::sqrt(n.squared_length());
  return { { centre[0] + n.x() / len * stub, centre[1] + n.y() / len * stub,
    centre[2] + n.z() / len * stub } };
}

} // namespace

/// What the flow lines of one build share.
struct Builder::FlowLineWalk
{
  SuccessorForest& Forest;
  double Stub;  ///< length of the drawn rays toward infinity
  double Defer; ///< the deferral ratio (when Stop)
  bool Record;  ///< polylines kept (memoises NEXT and shares tails: one thread)
  bool Stop;    ///< lines stopped above Defer
  tbb::enumerable_thread_specific<std::vector<PendingFlowLine>> Pending;
};

void Builder::TraceUnstableManifolds()
{
  FlowComplex& fc = this->FC;
  this->Ends.assign(this->Cs.Facets.size(), { { 0, 0 } }); // maxima reached
  // Which of Ends[i] the normals of patch i face (PatchFacesSide, after the
  // reordering of the sides below): the cones need the side of each patch.
  this->PatchFaces.assign(this->Options.StableManifolds ? this->Cs.Facets.size() : 0, 0);
  fc.FlowLines.clear();
  this->LineMaxima = std::make_unique<const std::vector<std::int32_t>>(this->MaximumOfCells());
  const double stub = RayStub * this->In.Diagonal;
  this->LineForest = std::make_unique<SuccessorForest>(*this->Tri, *this->LineMaxima,
    fc.InfinityNode, stub, this->Options.UnstableManifolds, this->Options.ExactOnly);
  SuccessorForest& forest = *this->LineForest;
  const bool record = this->Options.UnstableManifolds;
  // Deferred flow lines: stopped where their ratio is certainly above the
  // deferral ratio (a geometry-free build only: drawing needs every line).
  const double defer = this->Options.DeferFlowLinesAboveRatio;
  const bool stop = defer < HUGE_VAL && !record && !this->Options.StableManifolds;
  FlowLineWalk walk{ forest, stub, defer, record, stop, {} };
  try
  {
    if (record)
    {
      this->RecordFlowLines(walk);
    }
    else
    {
      ParallelSlices(this->NFacets, 16 * PatchChunk, this->Report, 0.7, 0.9, "unstable manifolds",
        [&](Id begin, Id last) {
          for (Id i = begin; i < last; ++i)
          {
            this->TraceFlowLines(static_cast<std::size_t>(i), walk);
          }
        });
    }
  }
  catch (const Degenerate&)
  {
    if (this->First)
    {
      ++fc.Report.WalkTies;
    }
    throw;
  }
  fc.Report.ExactFallbacks += forest.ExactFallbacks();
  // A kept triangulation keeps the forest: the deferred lines' walks go on
  // from where these stopped, and what each stage follows serves the next.
  if (!this->Keep || record)
  {
    this->LineForest.reset();
    this->LineMaxima.reset();
  }
  fc.PendingFlowLines.clear();
  for (const std::vector<PendingFlowLine>& lines : walk.Pending)
  {
    fc.PendingFlowLines.insert(fc.PendingFlowLines.end(), lines.begin(), lines.end());
  }
  std::sort(fc.PendingFlowLines.begin(), fc.PendingFlowLines.end(),
    [](const PendingFlowLine& a, const PendingFlowLine& b) {
      return std::tie(a.Node, a.Side) < std::tie(b.Node, b.Side);
    });
}

std::vector<std::int32_t> Builder::MaximumOfCells() const
{
  std::vector<std::int32_t> maximumOfCell(static_cast<std::size_t>(this->Tri->NumberOfCells()), -1);
  for (std::size_t i = 0; i < this->Cs.Cells.size(); ++i)
  {
    maximumOfCell[this->Cs.Cells[i].Cell] = static_cast<std::int32_t>(this->Base3 + static_cast<Id>(i));
  }
  return maximumOfCell;
}

void Builder::RecordFlowLines(FlowLineWalk& walk)
{
  // The walks in parallel first; the polylines are then gathered in facet
  // order (shared tails belong to the first line that reaches them).
  std::vector<Id> starts;
  starts.reserve(2 * this->Cs.Facets.size());
  for (const auto& facet : this->Cs.Facets)
  {
    const CellHandle cell = this->Tri->Cell(facet.Cell);
    for (const CellHandle side : { cell, cell->neighbor(facet.Opposite) })
    {
      if (!this->Tri->Dt().is_infinite(side))
      {
        starts.push_back(this->Tri->CellId(side));
      }
    }
  }
  walk.Forest.PrecomputeSteps(starts, this->Report, 0.7, 0.85);
  std::vector<Id>().swap(starts);
  const double nf = static_cast<double>(this->NFacets) + 1;
  for (std::size_t i = 0; i < this->Cs.Facets.size(); ++i)
  {
    if ((i & 0xFFFF) == 0)
    {
      this->Report(0.85 + 0.05 * i / nf, "unstable manifolds");
    }
    this->TraceFlowLines(i, walk);
  }
}

void Builder::TraceFlowLines(std::size_t i, FlowLineWalk& walk)
{
  FlowComplex& fc = this->FC;
  const Id node = this->Base2 + static_cast<Id>(i);
  const auto& f = this->Cs.Facets[i].Vertices;
  const std::array<CellHandle, 2> sides =
    FlowLineSides(*this->Tri, this->Cs.Facets[i].Cell, this->Cs.Facets[i].Opposite);
  if (!this->PatchFaces.empty())
  {
    const bool swapped = sides[0] != this->Tri->Cell(this->Cs.Facets[i].Cell);
    this->PatchFaces[i] = static_cast<char>(PatchFacesSide(*this->Tri, this->Cs, i) ^ (swapped ? 1 : 0));
  }
  Point3 centre{ { 0, 0, 0 } };
  double limitSq = HUGE_VAL;
  if (walk.Stop)
  {
    const KPoint pts[3] = { this->Tri->KCoord(f[0]), this->Tri->KCoord(f[1]), this->Tri->KCoord(f[2]) };
    limitSq = walk.Defer * walk.Defer * CentreAndSquaredRadius(pts, 3)[3];
  }
  if (walk.Record)
  {
    const KPoint pts[3] = { this->Tri->KCoord(f[0]), this->Tri->KCoord(f[1]), this->Tri->KCoord(f[2]) };
    const std::array<double, 4> cr = CentreAndSquaredRadius(pts, 3);
    centre = { { cr[0], cr[1], cr[2] } };
  }
  for (int s = 0; s < 2; ++s)
  {
    FlowLine line;
    line.Node = node;
    if (walk.Record)
    {
      line.Points.push_back(centre);
    }
    if (this->Tri->Dt().is_infinite(sides[s]))
    {
      line.Target = fc.InfinityNode;
      if (walk.Record)
      {
        // The Voronoi edge of a hull facet is a ray normal to it, away from the other cell.
        line.Points.push_back(RayEnd(*this->Tri, f, sides[s], sides[1 - s], centre, walk.Stub));
      }
    }
    else
    {
      const Id id = this->Tri->CellId(sides[s]);
      double boundSq = 0;
      line.Target = walk.Forest.RootBelow(id, limitSq, &boundSq);
      if (line.Target == SuccessorForest::Pending)
      {
        // In the triangulation's units, like the values (ScaleBack).
        walk.Pending.local().push_back(
          PendingFlowLine{ static_cast<std::int32_t>(node), s, RoundedDown(std::sqrt(boundSq)) });
      }
      if (walk.Record)
      {
        line.Points.push_back(walk.Forest.Circumcentre(id));
        walk.Forest.AppendPath(id, line.Points, true);
      }
    }
    this->Ends[i][s] = static_cast<std::int32_t>(line.Target);
    if (walk.Record)
    {
      // Voronoi vertices of nearly cospherical samples can lie beyond the
      // range of doubles (clouds mixing scales); such points of a drawn
      // polyline are left out. The flow line's target is exact regardless.
      line.Points.erase(std::remove_if(line.Points.begin(), line.Points.end(),
                          [](const Point3& p) {
                            return !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
                          }),
        line.Points.end());
      fc.FlowLines.push_back(std::move(line));
    }
  }
}

} // namespace internal
} // namespace flowrecon
