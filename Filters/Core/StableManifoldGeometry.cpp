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

void DrawStableManifolds(const std::vector<Point3>& points, const BuildOptions& options,
  const std::vector<Id>& draw, FlowComplex& fc, const Progress& progress, const std::string& advice,
  const std::vector<Arc>* unsimplifiedArcs, const Retriangulation* retriangulation)
{
  const std::string mismatch = Retriangulation::Mismatch();
  fc.Points = points;
  fc.NumberOfInputPoints = static_cast<Id>(points.size());
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  fc.Tetrahedra.clear();
  fc.TetrahedronNode.clear();
  fc.NodePoint.assign(fc.Nodes.size(), -1);
  const std::array<Id, 4> n = fc.CountByIndex();
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
  std::vector<Id> patches, cones; // facet and cell positions asked for
  for (const Id node : draw)
  {
    if (node < 0 || node >= static_cast<Id>(fc.Nodes.size()) || fc.Nodes[node].IsInfinity())
    {
      continue;
    }
    const Id base2 = n[0] + n[1], base3 = base2 + n[2];
    if (fc.Nodes[node].Index == 2)
    {
      patches.push_back(node - base2);
    }
    else if (fc.Nodes[node].Index == 3)
    {
      cones.push_back(node - base3);
    }
  }
  std::sort(patches.begin(), patches.end());
  patches.erase(std::unique(patches.begin(), patches.end()), patches.end());
  std::sort(cones.begin(), cones.end());
  cones.erase(std::unique(cones.begin(), cones.end()), cones.end());
  if (patches.empty() && cones.empty())
  {
    return;
  }

  std::optional<Retriangulation> own;
  if (!retriangulation)
  {
    own.emplace(points, options, fc, progress, advice);
    retriangulation = &*own;
  }
  const Retriangulation& re = *retriangulation;
  if (re.Options().Seed != options.Seed || re.Options().ExactOnly != options.ExactOnly)
  {
    throw InputError("drawing: the triangulation was made with other options");
  }
  const Triangulation& tri = re.Tri();
  const CriticalSimplices& cs = re.Critical();
  const PreparedInput& in = re.Prepared();
  const Id nFacets = static_cast<Id>(cs.Facets.size());
  const Id nCells = static_cast<Id>(cs.Cells.size());
  const Id base2 = re.Base2(), base3 = re.Base3();
  if (base3 + nCells != fc.InfinityNode || n[2] != nFacets || n[3] != nCells)
  {
    throw InputError(mismatch);
  }
  auto sameSimplex = [&](Id node, const Id* v, int count) {
    return re.SameSimplex(fc, node, v, count);
  };
  auto backScaled = [&](const Point3& p) { return re.BackScaled(p); };

  // The boundary of a cone: the index-2 points with a flow line ending at its
  // maximum (the 2-3 arcs of the unsimplified complex, which a simplified input
  // no longer holds). A patch with both lines there is a fin inside the cell:
  // left out, it would be a disc glued to the contractible cone along its rim,
  // a void that the flow complex does not have.
  std::vector<std::vector<Id>> boundary(cones.size());
  std::vector<char> drawPatch(static_cast<std::size_t>(nFacets), 0);
  for (const Id f : patches)
  {
    drawPatch[f] = 1;
  }
  std::vector<char> walk(drawPatch);
  // The maxima the two flow lines of each boundary facet reach (side 0: its
  // cell, side 1: the neighbour): the side of each patch the cell is on.
  std::vector<std::array<std::int32_t, 2>> ends;
  std::vector<std::int32_t> maximumOfCell;
  if (!cones.empty())
  {
    maximumOfCell.assign(static_cast<std::size_t>(tri.NumberOfCells()), -1);
    for (Id i = 0; i < nCells; ++i)
    {
      maximumOfCell[cs.Cells[i].Cell] = static_cast<std::int32_t>(base3 + i);
    }
    ends.assign(static_cast<std::size_t>(nFacets), { { -1, -1 } });
  }
  std::optional<SuccessorForest> forest;
  if (!cones.empty())
  {
    forest.emplace(tri, maximumOfCell, fc.InfinityNode, 0, false, options.ExactOnly);
  }
  auto endsOf = [&](Id i) {
    const CellHandle cell = tri.Cell(cs.Facets[i].Cell);
    const CellHandle sides[2] = { cell, cell->neighbor(cs.Facets[i].Opposite) };
    for (int s = 0; s < 2; ++s)
    {
      ends[i][s] = static_cast<std::int32_t>(
        tri.Dt().is_infinite(sides[s]) ? fc.InfinityNode : forest->Root(tri.CellId(sides[s])));
    }
  };
  if (!cones.empty() && unsimplifiedArcs)
  {
    std::vector<std::int32_t> coneOf(static_cast<std::size_t>(nCells), -1);
    for (std::size_t k = 0; k < cones.size(); ++k)
    {
      coneOf[cones[k]] = static_cast<std::int32_t>(k);
    }
    for (const Arc& a : *unsimplifiedArcs) // grouped by lower node: facets in order
    {
      if (a.Lower >= base2 && a.Lower < base3 && a.Upper >= base3 && a.Upper < fc.InfinityNode &&
        coneOf[a.Upper - base3] >= 0)
      {
        boundary[coneOf[a.Upper - base3]].push_back(a.Lower - base2);
        walk[a.Lower - base2] = 1;
      }
    }
    std::vector<Id> boundaryFacets;
    for (const std::vector<Id>& b : boundary)
    {
      boundaryFacets.insert(boundaryFacets.end(), b.begin(), b.end());
    }
    std::sort(boundaryFacets.begin(), boundaryFacets.end());
    boundaryFacets.erase(
      std::unique(boundaryFacets.begin(), boundaryFacets.end()), boundaryFacets.end());
    ParallelSlices(static_cast<Id>(boundaryFacets.size()), Id(1) << 17, progress, 0.35, 0.45,
      "boundaries of maxima", [&](Id first, Id last) {
        for (Id k = first; k < last; ++k)
        {
          endsOf(boundaryFacets[k]);
        }
      });
  }
  else if (!cones.empty())
  {
    std::vector<std::int32_t> coneOf(static_cast<std::size_t>(nCells), -1);
    for (std::size_t k = 0; k < cones.size(); ++k)
    {
      coneOf[cones[k]] = static_cast<std::int32_t>(k);
    }
    ParallelSlices(nFacets, Id(1) << 17, progress, 0.35, 0.45, "boundaries of maxima",
      [&](Id first, Id last) {
        for (Id i = first; i < last; ++i)
        {
          endsOf(i);
        }
      });
    for (Id i = 0; i < nFacets; ++i)
    {
      for (int s = 0; s < 2; ++s)
      {
        const std::int32_t e = ends[i][s];
        if (s == 1 && e == ends[i][0])
        {
          break; // a fin: once in the cone
        }
        if (e != fc.InfinityNode && coneOf[e - base3] >= 0)
        {
          boundary[coneOf[e - base3]].push_back(i);
          walk[i] = 1;
        }
      }
    }
  }

  for (std::vector<Id>& b : boundary)
  {
    std::sort(b.begin(), b.end()); // facet order, however the arcs came
  }

  // Walks in parallel chunks, merged in facet order (deterministic).
  std::vector<Id> facets;
  for (Id i = 0; i < nFacets; ++i)
  {
    if (walk[i])
    {
      facets.push_back(i);
    }
  }
  std::vector<Id> patchBegin(static_cast<std::size_t>(nFacets) + 1, -1), patchEnd(patchBegin);
  // Triangles of every walked patch, kept for the cones only (without cones
  // they would copy fc.Triangles: 24 B per drawn triangle).
  std::vector<std::array<Id, 3>> walked;
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
          batch[k - begin] = ComputeStableManifold(
            tri, cs, static_cast<std::size_t>(facets[k]), true, batchFallbacks[k - begin],
            options.ExactOnly);
        }
      });
    for (std::size_t k = begin; k < last; ++k)
    {
      const Id f = facets[k];
      const Id node = base2 + f;
      const Id v[3] = { cs.Facets[f].Vertices[0], cs.Facets[f].Vertices[1], cs.Facets[f].Vertices[2] };
      if (!sameSimplex(node, v, 3))
      {
        throw InputError(mismatch);
      }
      Patch& patch = batch[k - begin];
      fallbacks += batchFallbacks[k - begin];
      const Id offset = static_cast<Id>(fc.Points.size());
      for (const Point3& p : patch.Constructed)
      {
        fc.Points.push_back(backScaled(p));
      }
      fc.NodePoint[node] = offset; // Constructed[0] is the critical point
      patchBegin[f] = static_cast<Id>(walked.size());
      walkedCount += static_cast<Id>(patch.Triangles.size());
      for (const auto& t : patch.Triangles)
      {
        std::array<Id, 3> w;
        for (int j = 0; j < 3; ++j)
        {
          w[j] = t[j] >= 0 ? in.InputId[t[j]] : offset + (-1 - t[j]);
        }
        if (!cones.empty())
        {
          walked.push_back(w);
        }
        if (drawPatch[f])
        {
          fc.Triangles.push_back(w);
          fc.TriangleNode.push_back(node);
        }
      }
      patchEnd[f] = static_cast<Id>(walked.size());
      patch = Patch();
    }
    // The drawing so far predicts the rest: refuse before it no longer fits.
    const double perFacet = static_cast<double>(walkedCount) / static_cast<double>(last);
    RequireMemory(BytesPerCell * perFacet * static_cast<double>(facets.size() - last) *
        (cones.empty() ? 1.0 : 2.0),
      "drawing the stable manifolds of " + std::to_string(patches.size() + cones.size()) +
        " nodes of a " + std::to_string(points.size()) + "-point cloud",
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
      room(fc.Points, points.size());
      room(fc.Triangles, 0);
      room(fc.TriangleNode, 0);
      room(walked, 0);
    }
  }
  fc.Report.ExactFallbacks += fallbacks;

  progress(0.95, "index-3 cones");
  ConeBoundary coneBoundary;
  for (std::size_t k = 0; k < cones.size(); ++k)
  {
    const Id node = base3 + cones[k];
    const Id v[4] = { cs.Cells[cones[k]].Vertices[0], cs.Cells[cones[k]].Vertices[1],
      cs.Cells[cones[k]].Vertices[2], cs.Cells[cones[k]].Vertices[3] };
    if (!sameSimplex(node, v, 4))
    {
      throw InputError(mismatch);
    }
    const Id apex = static_cast<Id>(fc.Points.size());
    fc.NodePoint[node] = apex;
    fc.Points.push_back(fc.Nodes[node].Location);
    coneBoundary.Clear();
    for (const Id f : boundary[k])
    {
      const bool fin = ends[f][0] == ends[f][1];
      const int faces = PatchFacesSide(tri, cs, static_cast<std::size_t>(f));
      coneBoundary.Add(walked.data() + patchBegin[f], walked.data() + patchEnd[f],
        !fin && ends[f][faces] != node, fin);
    }
    fc.TetrahedronNode.insert(fc.TetrahedronNode.end(),
      static_cast<std::size_t>(AppendCone(
        apex, coneBoundary.Triangles, fc.Points, fc.Tetrahedra, &coneBoundary.TwoSided)),
      node);
  }
  progress(1.0, "stable manifolds");
}

} // namespace flowrecon
