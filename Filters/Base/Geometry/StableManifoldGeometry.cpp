#include "StableManifoldGeometry.h"

#include "Arithmetic.h"
#include "CriticalSimplices.h"
#include "InputPreparation.h"
#include "Retriangulation.h"
#include "MemoryGuard.h"
#include "ParallelSlices.h"
#include "StableManifold.h"
#include "StableManifoldCone.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

namespace flowrecon
{

namespace
{

/// Memory of one drawn cell in the core: the cell and its node (16 B), the
/// cones' copy of walked triangles, a share of the constructed points and of
/// the vectors' growth (measured: 66 B a triangle on 10^6 points of a scanned
/// surface). The VTK output has guards of its own (ReconstructionConversion,
/// FlowComplexToVTK), by when `reconstruct` has freed the triangulation (~0.7 KB
/// a point): counting VTK's arrays here refused a 10^7-point drawing that fits.
constexpr double BytesPerCell = 100;

} // namespace

std::vector<Id> StableManifoldCellCounts(const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
{
  std::vector<Id> counts(nodes.size(), 0);
  for (const Arc& a : arcs)
  {
    if (nodes[a.Lower].Index == 1)
    {
      counts[a.Upper] += a.Multiplicity; // arrivals first
    }
  }
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (nodes[i].Index == 2)
    {
      counts[i] = std::max<Id>(0, 3 * counts[i] - 6);
    }
  }
  for (const Arc& a : arcs)
  {
    if (nodes[a.Lower].Index == 2 && !nodes[a.Upper].IsInfinity())
    {
      counts[a.Upper] += counts[a.Lower];
    }
  }
  return counts;
}

std::vector<Id> NodesWithinBudget(
  const std::vector<Node>& nodes, const std::vector<Id>& counts, Id budget)
{
  std::vector<Id> order;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (nodes[i].Index >= 2 && !nodes[i].IsInfinity())
    {
      order.push_back(static_cast<Id>(i));
    }
  }
  std::sort(order.begin(), order.end(), [&](Id a, Id b) { return FiltrationLess(nodes, a, b); });
  Id used = 0;
  std::size_t k = 0;
  for (; k < order.size() && counts[order[k]] <= budget - used; ++k)
  {
    used += counts[order[k]];
  }
  order.resize(k);
  std::sort(order.begin(), order.end());
  return order;
}

namespace
{

/// What every step of a drawing reads: the triangulation of the samples, its
/// critical simplices, and where their nodes start in the flow complex.
struct DrawingContext
{
  const Retriangulation& Re;
  const Triangulation& Tri;
  const CriticalSimplices& Cs;
  Id NumberOfFacets, NumberOfCells;
  Id Base2, Base3; ///< node of facet 0, of cell 0
  std::string Mismatch;

  explicit DrawingContext(const Retriangulation& re)
    : Re(re)
    , Tri(re.Tri())
    , Cs(re.Critical())
    , NumberOfFacets(static_cast<Id>(re.Critical().Facets.size()))
    , NumberOfCells(static_cast<Id>(re.Critical().Cells.size()))
    , Base2(re.Base2())
    , Base3(re.Base3())
    , Mismatch(Retriangulation::Mismatch())
  {
  }
};

/// The index-2 facets (patches) and index-3 cells (cones) whose stable
/// manifolds are asked for, as positions among the facets and cells, sorted.
struct AskedCells
{
  std::vector<Id> Patches, Cones;
};

/// Resets fc's geometry to the samples alone, each sample node on its sample.
void StartFromSamples(const std::vector<Point3>& points, FlowComplex& fc, const std::string& mismatch)
{
  fc.Points = points;
  fc.NumberOfInputPoints = static_cast<Id>(points.size());
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  fc.Tetrahedra.clear();
  fc.TetrahedronNode.clear();
  fc.NodePoint.assign(fc.Nodes.size(), -1);
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& node = fc.Nodes[i];
    if (node.Index == 0 && !node.IsInfinity())
    {
      // A sample node sits exactly on its sample: any edited point shows here.
      if (node.Simplex[0] >= static_cast<Id>(points.size()) || points[node.Simplex[0]] != node.Location)
      {
        throw InputError(mismatch);
      }
      fc.NodePoint[i] = node.Simplex[0];
    }
  }
}

AskedCells CellsAskedFor(const std::vector<Id>& draw, const FlowComplex& fc, const std::array<Id, 4>& n)
{
  AskedCells asked;
  const Id base2 = n[0] + n[1], base3 = base2 + n[2];
  for (const Id node : draw)
  {
    if (node < 0 || node >= static_cast<Id>(fc.Nodes.size()) || fc.Nodes[node].IsInfinity())
    {
      continue;
    }
    if (fc.Nodes[node].Index == 2)
    {
      asked.Patches.push_back(node - base2);
    }
    else if (fc.Nodes[node].Index == 3)
    {
      asked.Cones.push_back(node - base3);
    }
  }
  for (std::vector<Id>* v : { &asked.Patches, &asked.Cones })
  {
    std::sort(v->begin(), v->end());
    v->erase(std::unique(v->begin(), v->end()), v->end());
  }
  return asked;
}

/// The boundary of each cone: the index-2 points with a flow line ending at its
/// maximum (the 2-3 arcs of the unsimplified complex, which a simplified input
/// no longer holds). A patch with both lines there is a fin inside the cell:
/// left out, it would be a disc glued to the contractible cone along its rim,
/// a void that the flow complex does not have.
struct ConeBoundaries
{
  /// Per cone, its boundary facets in facet order.
  std::vector<std::vector<Id>> Facets;
  /// Per facet, the maxima its two flow lines reach (side 0: its cell, side 1:
  /// the neighbour; -1: not followed): the side of each patch the cell is on.
  std::vector<std::array<std::int32_t, 2>> Ends;
};

/// Where the flow lines of the facets [0, count) of `facets` (null: of all
/// facets) end, followed in parallel.
void FollowFlowLines(const DrawingContext& at, Id infinity, SuccessorForest& forest,
  const Id* facets, Id count, const Progress& progress, ConeBoundaries& cones)
{
  ParallelSlices(count, Id(1) << 17, progress, 0.35, 0.45, "boundaries of maxima",
    [&](Id first, Id last) {
      for (Id k = first; k < last; ++k)
      {
        const Id i = facets ? facets[k] : k;
        const CellHandle cell = at.Tri.Cell(at.Cs.Facets[i].Cell);
        const CellHandle sides[2] = { cell, cell->neighbor(at.Cs.Facets[i].Opposite) };
        for (int s = 0; s < 2; ++s)
        {
          cones.Ends[i][s] = static_cast<std::int32_t>(at.Tri.Dt().is_infinite(sides[s])
              ? infinity
              : forest.Root(at.Tri.CellId(sides[s])));
        }
      }
    });
}

/// The boundaries of the cones, and the facets whose patches are walked for
/// them marked in `walk`. With the unsimplified arcs, the boundary facets are
/// read from them and only their flow lines followed; otherwise the flow lines
/// of every facet are.
ConeBoundaries FindConeBoundaries(const DrawingContext& at, const FlowComplex& fc,
  const std::vector<Id>& cones, const std::vector<Arc>* unsimplifiedArcs, bool exactOnly,
  const Progress& progress, std::vector<char>& walk)
{
  ConeBoundaries boundaries;
  boundaries.Facets.resize(cones.size());
  if (cones.empty())
  {
    return boundaries;
  }
  std::vector<std::int32_t> maximumOfCell(static_cast<std::size_t>(at.Tri.NumberOfCells()), -1);
  for (Id i = 0; i < at.NumberOfCells; ++i)
  {
    maximumOfCell[at.Cs.Cells[i].Cell] = static_cast<std::int32_t>(at.Base3 + i);
  }
  boundaries.Ends.assign(static_cast<std::size_t>(at.NumberOfFacets), { { -1, -1 } });
  SuccessorForest forest(at.Tri, maximumOfCell, fc.InfinityNode, 0, false, exactOnly);
  std::vector<std::int32_t> coneOf(static_cast<std::size_t>(at.NumberOfCells), -1);
  for (std::size_t k = 0; k < cones.size(); ++k)
  {
    coneOf[cones[k]] = static_cast<std::int32_t>(k);
  }
  if (unsimplifiedArcs)
  {
    for (const Arc& a : *unsimplifiedArcs) // grouped by lower node: facets in order
    {
      if (a.Lower >= at.Base2 && a.Lower < at.Base3 && a.Upper >= at.Base3 &&
        a.Upper < fc.InfinityNode && coneOf[a.Upper - at.Base3] >= 0)
      {
        boundaries.Facets[coneOf[a.Upper - at.Base3]].push_back(a.Lower - at.Base2);
        walk[a.Lower - at.Base2] = 1;
      }
    }
    std::vector<Id> boundaryFacets;
    for (const std::vector<Id>& b : boundaries.Facets)
    {
      boundaryFacets.insert(boundaryFacets.end(), b.begin(), b.end());
    }
    std::sort(boundaryFacets.begin(), boundaryFacets.end());
    boundaryFacets.erase(
      std::unique(boundaryFacets.begin(), boundaryFacets.end()), boundaryFacets.end());
    FollowFlowLines(at, fc.InfinityNode, forest, boundaryFacets.data(),
      static_cast<Id>(boundaryFacets.size()), progress, boundaries);
  }
  else
  {
    FollowFlowLines(at, fc.InfinityNode, forest, nullptr, at.NumberOfFacets, progress, boundaries);
    for (Id i = 0; i < at.NumberOfFacets; ++i)
    {
      for (int s = 0; s < 2; ++s)
      {
        const std::int32_t e = boundaries.Ends[i][s];
        if (s == 1 && e == boundaries.Ends[i][0])
        {
          break; // a fin: once in the cone
        }
        if (e != fc.InfinityNode && coneOf[e - at.Base3] >= 0)
        {
          boundaries.Facets[coneOf[e - at.Base3]].push_back(i);
          walk[i] = 1;
        }
      }
    }
  }
  for (std::vector<Id>& b : boundaries.Facets)
  {
    std::sort(b.begin(), b.end()); // facet order, however the arcs came
  }
  return boundaries;
}

/// Triangles of every walked patch, kept for the cones only (without cones
/// they would copy fc.Triangles: 24 B per drawn triangle).
struct WalkedPatches
{
  std::vector<std::array<Id, 3>> Triangles;
  /// Per facet: its patch is Triangles[Begin[f], End[f]).
  std::vector<Id> Begin, End;
};

/// Moves the walked patch of facet f into fc (its constructed points, and its
/// triangles when drawn) and into `walked` (its triangles, when kept).
void AddPatch(const DrawingContext& at, Id f, Patch& patch, bool drawn, bool keep,
  FlowComplex& fc, WalkedPatches& walked)
{
  const Id node = at.Base2 + f;
  const Id v[3] = { at.Cs.Facets[f].Vertices[0], at.Cs.Facets[f].Vertices[1],
    at.Cs.Facets[f].Vertices[2] };
  if (!at.Re.SameSimplex(fc, node, v, 3))
  {
    throw InputError(at.Mismatch);
  }
  const auto& inputId = at.Re.Prepared().InputId;
  const Id offset = static_cast<Id>(fc.Points.size());
  for (const Point3& p : patch.Constructed)
  {
    fc.Points.push_back(at.Re.BackScaled(p));
  }
  fc.NodePoint[node] = offset; // Constructed[0] is the critical point
  walked.Begin[f] = static_cast<Id>(walked.Triangles.size());
  for (const auto& t : patch.Triangles)
  {
    std::array<Id, 3> w;
    for (int j = 0; j < 3; ++j)
    {
      w[j] = t[j] >= 0 ? inputId[t[j]] : offset + (-1 - t[j]);
    }
    if (keep)
    {
      walked.Triangles.push_back(w);
    }
    if (drawn)
    {
      fc.Triangles.push_back(w);
      fc.TriangleNode.push_back(node);
    }
  }
  walked.End[f] = static_cast<Id>(walked.Triangles.size());
  patch = Patch();
}

/// Walks the patches of the facets marked in `walk` (in parallel chunks, merged
/// in facet order: deterministic), draws those marked in `drawPatch`, and keeps
/// them all for the cones when there are cones. Refuses, from the first chunk
/// on, a drawing that would not fit in memory.
WalkedPatches WalkPatches(const DrawingContext& at, const std::vector<char>& walk,
  const std::vector<char>& drawPatch, const AskedCells& asked, std::size_t numberOfPoints,
  bool exactOnly, FlowComplex& fc, const Progress& progress, const std::string& advice)
{
  std::vector<Id> facets;
  for (Id i = 0; i < at.NumberOfFacets; ++i)
  {
    if (walk[i])
    {
      facets.push_back(i);
    }
  }
  const bool keep = !asked.Cones.empty();
  WalkedPatches walked;
  walked.Begin.assign(static_cast<std::size_t>(at.NumberOfFacets) + 1, -1);
  walked.End = walked.Begin;
  Id walkedCount = 0;
  // A small first chunk: the guard below predicts from it before much is drawn.
  std::size_t chunk = 512;
  Id fallbacks = 0;
  for (std::size_t begin = 0; begin < facets.size(); begin += chunk, chunk = 4096)
  {
    progress(0.45 + 0.5 * static_cast<double>(begin) / static_cast<double>(facets.size()),
      "stable manifolds");
    const std::size_t last = std::min(facets.size(), begin + chunk);
    std::vector<Patch> batch(last - begin);
    std::vector<Id> batchFallbacks(last - begin, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, last),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k)
        {
          batch[k - begin] = ComputeStableManifold(at.Tri, at.Cs,
            static_cast<std::size_t>(facets[k]), true, batchFallbacks[k - begin], exactOnly);
        }
      });
    for (std::size_t k = begin; k < last; ++k)
    {
      fallbacks += batchFallbacks[k - begin];
      walkedCount += static_cast<Id>(batch[k - begin].Triangles.size());
      AddPatch(at, facets[k], batch[k - begin], drawPatch[facets[k]] != 0, keep, fc, walked);
    }
    // The drawing so far predicts the rest: refuse before it no longer fits.
    const double perFacet = static_cast<double>(walkedCount) / static_cast<double>(last);
    RequireMemory(BytesPerCell * perFacet * static_cast<double>(facets.size() - last) *
        (keep ? 2.0 : 1.0),
      "drawing the stable manifolds of " +
        std::to_string(asked.Patches.size() + asked.Cones.size()) + " nodes of a " +
        std::to_string(numberOfPoints) + "-point cloud",
      advice);
    if (begin == 0 && last < facets.size())
    {
      // Room for the predicted rest and a quarter more (which fits: checked
      // above), so that the largest vectors do not grow by copies into fresh,
      // page-faulting memory. Only address space until written.
      const double scale = 1.25 * static_cast<double>(facets.size()) / static_cast<double>(last);
      auto room = [&](auto& v, std::size_t fixed) {
        v.reserve(fixed + static_cast<std::size_t>(scale * static_cast<double>(v.size() - fixed)));
      };
      room(fc.Points, numberOfPoints);
      room(fc.Triangles, 0);
      room(fc.TriangleNode, 0);
      room(walked.Triangles, 0);
    }
  }
  fc.Report.ExactFallbacks += fallbacks;
  return walked;
}

/// The tetrahedra of each cone: from its maximum over its boundary patches,
/// each turned to face into the cell (fins two-sided).
void AppendCones(const DrawingContext& at, const std::vector<Id>& cones,
  const ConeBoundaries& boundaries, const WalkedPatches& walked, FlowComplex& fc)
{
  ConeBoundary coneBoundary;
  for (std::size_t k = 0; k < cones.size(); ++k)
  {
    const Id node = at.Base3 + cones[k];
    const Id v[4] = { at.Cs.Cells[cones[k]].Vertices[0], at.Cs.Cells[cones[k]].Vertices[1],
      at.Cs.Cells[cones[k]].Vertices[2], at.Cs.Cells[cones[k]].Vertices[3] };
    if (!at.Re.SameSimplex(fc, node, v, 4))
    {
      throw InputError(at.Mismatch);
    }
    const Id apex = static_cast<Id>(fc.Points.size());
    fc.NodePoint[node] = apex;
    fc.Points.push_back(fc.Nodes[node].Location);
    coneBoundary.Clear();
    for (const Id f : boundaries.Facets[k])
    {
      const std::array<std::int32_t, 2>& ends = boundaries.Ends[f];
      const bool fin = ends[0] == ends[1];
      const int faces = PatchFacesSide(at.Tri, at.Cs, static_cast<std::size_t>(f));
      coneBoundary.Add(walked.Triangles.data() + walked.Begin[f],
        walked.Triangles.data() + walked.End[f], !fin && ends[faces] != node, fin);
    }
    fc.TetrahedronNode.insert(fc.TetrahedronNode.end(),
      static_cast<std::size_t>(AppendCone(
        apex, coneBoundary.Triangles, fc.Points, fc.Tetrahedra, &coneBoundary.TwoSided)),
      node);
  }
}

} // namespace

void DrawStableManifolds(const std::vector<Point3>& points, const BuildOptions& options,
  const std::vector<Id>& draw, FlowComplex& fc, const Progress& progress, const std::string& advice,
  const std::vector<Arc>* unsimplifiedArcs, const Retriangulation* retriangulation)
{
  StartFromSamples(points, fc, Retriangulation::Mismatch());
  const std::array<Id, 4> n = fc.CountByIndex();
  const AskedCells asked = CellsAskedFor(draw, fc, n);
  if (asked.Patches.empty() && asked.Cones.empty())
  {
    return;
  }

  std::optional<Retriangulation> own;
  if (!retriangulation)
  {
    own.emplace(points, options, fc, progress, advice);
    retriangulation = &*own;
  }
  const DrawingContext at(*retriangulation);
  if (at.Re.Options().Seed != options.Seed || at.Re.Options().ExactOnly != options.ExactOnly)
  {
    throw InputError("drawing: the triangulation was made with other options");
  }
  if (at.Base3 + at.NumberOfCells != fc.InfinityNode || n[2] != at.NumberOfFacets ||
    n[3] != at.NumberOfCells)
  {
    throw InputError(at.Mismatch);
  }

  // The patches asked for, and those the cones' boundaries need.
  std::vector<char> drawPatch(static_cast<std::size_t>(at.NumberOfFacets), 0);
  for (const Id f : asked.Patches)
  {
    drawPatch[f] = 1;
  }
  std::vector<char> walk(drawPatch);
  const ConeBoundaries boundaries = FindConeBoundaries(
    at, fc, asked.Cones, unsimplifiedArcs, options.ExactOnly, progress, walk);
  const WalkedPatches walked = WalkPatches(
    at, walk, drawPatch, asked, points.size(), options.ExactOnly, fc, progress, advice);

  progress(0.95, "index-3 cones");
  AppendCones(at, asked.Cones, boundaries, walked, fc);
  progress(1.0, "stable manifolds");
}

} // namespace flowrecon
