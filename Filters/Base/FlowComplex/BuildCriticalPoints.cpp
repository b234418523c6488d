// Build phases 1-2: the Delaunay triangulation, its critical simplices as node
// ids and the 0-1 arcs, and which index-2 patches are deferred (not walked).
#include "BuildPhases.h"

#include "Arithmetic.h"
#include "HugePages.h"
#include "MemoryGuard.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace flowrecon
{
namespace internal
{

void Builder::Triangulate()
{
  FlowComplex& fc = this->FC;
  this->Report(0.0, "Delaunay triangulation");
  // Held by pointer so that it can be freed before the nodes and arcs are built:
  // the triangulation is the largest structure, and peak memory matters.
  // Measured peaks are 1.4-1.5 KB per point on volume samples (more on
  // surfaces, checked again below as the arcs come in).
  RequireMemory(1500.0 * static_cast<double>(this->Coords().size()), "the flow complex of " + this->Cloud(),
    "use fewer points (a subsample) or a machine with more memory");
  this->Tri = std::make_unique<const Triangulation>(this->Coords(), this->Report.Range(0, 0.2));
  if (this->Tri->Dimension() < 3)
  {
    throw InputError(this->Tri->Dimension() == 2 ? "all points are coplanar"
                                           : "all points are collinear");
  }
  if (this->Tri->NumberOfVertices() != static_cast<Id>(this->Coords().size()) ||
    static_cast<Id>(this->Tri->Dt().number_of_vertices()) != this->Tri->NumberOfVertices())
  {
    throw Degenerate("perturbation created duplicate points");
  }
}

void Builder::FindCriticalPoints()
{
  FlowComplex& fc = this->FC;
  this->Report(0.2, "critical points");
  this->Cs = FindCriticalSimplices(*this->Tri, this->Report);
  // Critical points are double constructions (exact combinatorics, rounded
  // geometry): products of a few edge lengths underflow or cancel when the
  // spacing is some 1e-20 of the extent, and CGAL's constructions divide by
  // zero. Refuse such clouds before any construction (the critical simplices
  // are exact predicates only). Distinct doubles of the size of the extent are
  // at least 1e-16 of it apart: only clusters near the origin get closer (no
  // sampled shape has 20 orders of magnitude between its spacing and its
  // size). The shortest Delaunay edge joins nearest neighbours, so it is a
  // Gabriel edge: checking those, in parallel, is checking them all.
  {
    const double tiny = 1e-20 * this->In.Diagonal;
    const bool close = tbb::parallel_reduce(tbb::blocked_range<std::size_t>(0, this->Cs.Edges.Values.size()), false,
      [&](const tbb::blocked_range<std::size_t>& r, bool found) {
        for (std::size_t i = r.begin(); i != r.end() && !found; ++i)
        {
          const Point3& a = this->Coords()[this->Cs.Edges.Values[i][0]];
          const Point3& b = this->Coords()[this->Cs.Edges.Values[i][1]];
          const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
          found = !(std::sqrt(dx * dx + dy * dy + dz * dz) > tiny);
        }
        return found;
      },
      [](bool x, bool y) { return x || y; });
    if (close)
    {
      throw InputError(TooClose);
    }
  }
  if (this->First)
  {
    fc.Report.RightAngles = this->Cs.RightAngles;
    fc.Report.ApexOnSphere = this->Cs.ApexOnSphere;
  }
  if (this->Cs.Degenerate())
  {
    throw Degenerate("input not in general position");
  }
  // Node ids: by index; within an index in the (Hilbert) order of their vertices.
  this->M = this->Tri->NumberOfVertices();
  this->NEdges = static_cast<Id>(this->Cs.Edges.Values.size());
  this->NFacets = static_cast<Id>(this->Cs.Facets.size());
  this->Base1 = this->M;
  this->Base2 = this->Base1 + this->NEdges;
  this->Base3 = this->Base2 + this->NFacets;
  fc.InfinityNode = this->Base3 + static_cast<Id>(this->Cs.Cells.size());
  if (fc.InfinityNode >= std::numeric_limits<std::int32_t>::max())
  {
    throw InputError("the flow complex of this many points exceeds 2^31 nodes");
  }
  fc.NodePoint.clear();
  if (this->Options.StableManifolds)
  {
    fc.NodePoint.assign(static_cast<std::size_t>(fc.InfinityNode + 1), -1);
    for (Id k = 0; k < this->M; ++k)
    {
      fc.NodePoint[k] = this->In.InputId[k];
    }
  }
  // Arcs grouped by the index of their lower node: 0->1 now, 1->2 from the
  // patches, 2->3 from the flow lines.
  fc.Arcs.clear();
  // Measured on volume samples: about 3.8 arcs 1->2 per index-2 node, so 6 per
  // node avoids the doubling reallocation of the largest vector (surfaces have more).
  ReserveHuge(fc.Arcs, static_cast<std::size_t>(2 * this->NEdges + 6 * this->NFacets));
  for (Id i = 0; i < this->NEdges; ++i)
  {
    fc.Arcs.emplace_back(this->Cs.Edges.Values[i][0], this->Base1 + i, 1);
    fc.Arcs.emplace_back(this->Cs.Edges.Values[i][1], this->Base1 + i, 1);
  }
}

void Builder::DeferFarPatches()
{
  FlowComplex& fc = this->FC;
  // Deferred patches: decided on the very values MakeNode gives the nodes below,
  // before any walk (the 1-2 arcs cannot raise them: see the check after ScaleBack).
  this->Deferred.clear();
  fc.DeferredPatches.clear();
  fc.DeferralRatio = HUGE_VAL;
  if (!this->Options.StableManifolds && this->Options.DeferPatchesAboveRatio < HUGE_VAL &&
    this->NEdges > 0)
  {
    const double largest = tbb::parallel_reduce(tbb::blocked_range<Id>(0, this->NEdges), 0.0,
      [&](const tbb::blocked_range<Id>& r, double v) {
        for (Id i = r.begin(); i != r.end(); ++i)
        {
          v = std::max(v, this->MakeNode(1, this->Cs.Edges.Values[i].data(), this->Coords(), false).Value);
        }
        return v;
      },
      [](double a, double b) { return std::max(a, b); });
    this->Deferred.assign(this->Cs.Facets.size(), 0);
    const double ratio = this->Options.DeferPatchesAboveRatio;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, this->Cs.Facets.size()),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          // V/L >= ratio in doubles implies V/V(a) >= ratio for every edge a
          // (V(a) <= L, and rounding is monotone).
          const double v = this->MakeNode(2, Widen(this->Cs.Facets[i].Vertices).data(), this->Coords(), false).Value;
          this->Deferred[i] = v / largest >= ratio ? 1 : 0;
        }
      });
    for (std::size_t i = 0; i < this->Deferred.size(); ++i)
    {
      if (this->Deferred[i])
      {
        fc.DeferredPatches.push_back(this->Base2 + static_cast<Id>(i));
      }
    }
    fc.DeferralRatio = ratio;
  }
}

} // namespace internal
} // namespace flowrecon
