#include "FlowComplexBuilder.h"

#include "Arithmetic.h"
#include "CriticalSimplices.h"
#include "DrawingBox.h"
#include "HugePages.h"
#include "InputPreparation.h"
#include "MemoryGuard.h"
#include "ParallelSlices.h"
#include "Retriangulation.h"
#include "StableManifold.h"
#include "StableManifoldCone.h"
#include "StableManifoldGeometry.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <string>

namespace flowrecon
{

namespace
{

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

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

const char* const TooClose = "points too close together for the size of the cloud (a critical "
                            "value underflows in double precision); rescale or separate the clusters";

class Builder
{
public:
  Builder(const PreparedInput& in, const std::vector<Point3>& input, const BuildOptions& options,
    const Progress& progress, FlowComplex& fc)
    : In(in)
    , Input(input)
    , Options(options)
    , Report(progress)
    , FC(fc)
  {
  }

  /// One attempt on `coords` (the unique points, perhaps perturbed, scaled by
  /// 2^-ScaleExponent). Throws Degenerate if general position fails; `first`
  /// records the counts. Constructed values and points are scaled back.
  void Run(const std::vector<Point3>& coords, bool first);

  int ScaleExponent = 0;
  /// When set, Run leaves its triangulation and critical simplices here.
  bool Keep = false;
  std::unique_ptr<const Triangulation> KeptTriangulation;
  CriticalSimplices KeptCritical;

private:
  void ScaleBack();
  Node MakeNode(int index, const Id* simplex, const std::vector<Point3>& coords) const;

  const PreparedInput& In;
  const std::vector<Point3>& Input;
  const BuildOptions& Options;
  const Progress& Report;
  FlowComplex& FC;
};

Node Builder::MakeNode(int index, const Id* simplex, const std::vector<Point3>& coords) const
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
    const std::array<double, 4> cr = CentreAndSquaredRadius(pts, static_cast<std::size_t>(index + 1));
    node.Location = { { cr[0], cr[1], cr[2] } };
    node.Value = std::sqrt(cr[3]);
  }
  return node;
}

void Builder::Run(const std::vector<Point3>& coords, bool first)
{
  FlowComplex& fc = this->FC;
  const auto t0 = Clock::now();
  this->Report(0.0, "Delaunay triangulation");
  // Held by pointer so that it can be freed before the nodes and arcs are built:
  // the triangulation is the largest structure, and peak memory matters.
  // Measured peaks are 1.4-1.5 KB per point on volume samples (more on
  // surfaces, checked again below as the arcs come in).
  const std::string cloud = std::to_string(coords.size()) + " points";
  RequireMemory(1500.0 * static_cast<double>(coords.size()), "the flow complex of " + cloud,
    "use fewer points (a subsample) or a machine with more memory");
  auto tri = std::make_unique<const Triangulation>(coords, this->Report.Range(0, 0.2));
  if (tri->Dimension() < 3)
  {
    throw InputError(tri->Dimension() == 2 ? "all points are coplanar"
                                           : "all points are collinear");
  }
  if (tri->NumberOfVertices() != static_cast<Id>(coords.size()) ||
    static_cast<Id>(tri->Dt().number_of_vertices()) != tri->NumberOfVertices())
  {
    throw Degenerate("perturbation created duplicate points");
  }
  fc.Time.Delaunay = Seconds(t0);

  auto t = Clock::now();
  this->Report(0.2, "critical points");
  CriticalSimplices cs = FindCriticalSimplices(*tri, this->Report);
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
    const bool close = tbb::parallel_reduce(tbb::blocked_range<std::size_t>(0, cs.Edges.size()), false,
      [&](const tbb::blocked_range<std::size_t>& r, bool found) {
        for (std::size_t i = r.begin(); i != r.end() && !found; ++i)
        {
          const Point3& a = coords[cs.Edges[i][0]];
          const Point3& b = coords[cs.Edges[i][1]];
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
  if (first)
  {
    fc.Report.RightAngles = cs.RightAngles;
    fc.Report.ApexOnSphere = cs.ApexOnSphere;
  }
  if (cs.Degenerate())
  {
    throw Degenerate("input not in general position");
  }
  // Node ids: by index; within an index in the (Hilbert) order of their vertices.
  const Id m = tri->NumberOfVertices();
  const Id nEdges = static_cast<Id>(cs.Edges.size()), nFacets = static_cast<Id>(cs.Facets.size());
  const Id base1 = m, base2 = base1 + nEdges, base3 = base2 + nFacets;
  fc.InfinityNode = base3 + static_cast<Id>(cs.Cells.size());
  if (fc.InfinityNode >= std::numeric_limits<std::int32_t>::max())
  {
    throw InputError("the flow complex of this many points exceeds 2^31 nodes");
  }
  fc.NodePoint.clear();
  if (this->Options.StableManifolds)
  {
    fc.NodePoint.assign(static_cast<std::size_t>(fc.InfinityNode + 1), -1);
    for (Id k = 0; k < m; ++k)
    {
      fc.NodePoint[k] = this->In.InputId[k];
    }
  }
  // Arcs grouped by the index of their lower node: 0->1 now, 1->2 from the
  // patches, 2->3 from the flow lines.
  fc.Arcs.clear();
  // Measured on volume samples: about 3.8 arcs 1->2 per index-2 node, so 6 per
  // node avoids the doubling reallocation of the largest vector (surfaces have more).
  ReserveHuge(fc.Arcs, static_cast<std::size_t>(2 * nEdges + 6 * nFacets));
  for (Id i = 0; i < nEdges; ++i)
  {
    fc.Arcs.emplace_back(cs.Edges[i][0], base1 + i, 1);
    fc.Arcs.emplace_back(cs.Edges[i][1], base1 + i, 1);
  }
  fc.Time.CriticalPoints = Seconds(t);

  // Deferred patches: decided on the very values MakeNode gives the nodes below,
  // before any walk (the 1-2 arcs cannot raise them: see the check after ScaleBack).
  std::vector<char> deferred;
  fc.DeferredPatches.clear();
  fc.DeferralRatio = HUGE_VAL;
  if (!this->Options.StableManifolds && this->Options.DeferPatchesAboveRatio < HUGE_VAL &&
    nEdges > 0)
  {
    const double largest = tbb::parallel_reduce(tbb::blocked_range<Id>(0, nEdges), 0.0,
      [&](const tbb::blocked_range<Id>& r, double v) {
        for (Id i = r.begin(); i != r.end(); ++i)
        {
          v = std::max(v, this->MakeNode(1, cs.Edges[i].data(), coords).Value);
        }
        return v;
      },
      [](double a, double b) { return std::max(a, b); });
    deferred.assign(cs.Facets.size(), 0);
    const double ratio = this->Options.DeferPatchesAboveRatio;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cs.Facets.size()),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          // V/L >= ratio in doubles implies V/V(a) >= ratio for every edge a
          // (V(a) <= L, and rounding is monotone).
          const double v = this->MakeNode(2, Widen(cs.Facets[i].Vertices).data(), coords).Value;
          deferred[i] = v / largest >= ratio ? 1 : 0;
        }
      });
    for (std::size_t i = 0; i < deferred.size(); ++i)
    {
      if (deferred[i])
      {
        fc.DeferredPatches.push_back(base2 + static_cast<Id>(i));
      }
    }
    fc.DeferralRatio = ratio;
  }

  // Stable manifolds of index-2 points and the 1-2 incidences.
  t = Clock::now();
  fc.Points.assign(this->Input.begin(), this->Input.end());
  fc.NumberOfInputPoints = static_cast<Id>(this->Input.size());
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  // Where each patch's triangles start (for the index-3 cones); geometry only.
  std::vector<Id> triangleBegin(this->Options.StableManifolds ? cs.Facets.size() + 1 : 0, 0);
  const double nf = static_cast<double>(nFacets) + 1;
  // Patches are independent: compute them in parallel, chunk by chunk, and merge
  // them in node order on this thread (which also reports progress).
  const std::size_t chunk = 8192;
  // A pipeline: the walks of the next chunk run on the workers while this thread
  // merges the current one (the merge is sequential: it appends to the arc list).
  struct Batch
  {
    std::size_t Begin = 0, Last = 0;
    std::vector<Patch> Patches;
    std::vector<Id> Fallbacks;
  };
  auto walk = [&](std::size_t begin, Batch& batch) {
    batch.Begin = begin;
    batch.Last = std::min(cs.Facets.size(), begin + chunk);
    batch.Patches.assign(batch.Last - begin, Patch());
    batch.Fallbacks.assign(batch.Last - begin, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, batch.Last),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          Patch& patch = batch.Patches[i - begin];
          if (!deferred.empty() && deferred[i])
          {
            continue;
          }
          patch = ComputeStableManifold(
            *tri, cs, i, this->Options.StableManifolds, batch.Fallbacks[i - begin],
            this->Options.ExactOnly);
          // Sorted here, in parallel: equal runs are the 1-2 multiplicities.
          std::sort(patch.Arrivals.begin(), patch.Arrivals.end());
        }
      });
  };
  auto merge = [&](Batch& batch) {
    const std::size_t begin = batch.Begin, last = batch.Last;
    std::vector<Patch>& patches = batch.Patches;
    std::vector<Id>& fallbacks = batch.Fallbacks;
    // Surfaces have far more 1-2 arcs than the first guess: grow the arc list to
    // an estimate of its final size (from the rate so far) rather than by
    // doubling, which would copy it several times and overshoot memory.
    std::size_t chunkArcs = 0;
    for (const Patch& patch : patches)
    {
      for (std::size_t k = 0; k < patch.Arrivals.size(); ++k)
      {
        chunkArcs += (k == 0 || patch.Arrivals[k] != patch.Arrivals[k - 1]) ? 1 : 0;
      }
    }
    if (fc.Arcs.size() + chunkArcs > fc.Arcs.capacity())
    {
      const std::size_t arcs12 = fc.Arcs.size() + chunkArcs - 2 * static_cast<std::size_t>(nEdges);
      const double perFacet = static_cast<double>(arcs12) / static_cast<double>(last);
      const std::size_t estimate = 2 * static_cast<std::size_t>(nEdges) +
        static_cast<std::size_t>(1.05 * perFacet * static_cast<double>(nFacets)) + 2 * cs.Facets.size();
      const std::size_t grown = std::max(estimate, fc.Arcs.capacity() + fc.Arcs.capacity() / 2);
      // Surface samples with tubes have ~n^1.5 arcs: say so before the kernel
      // kills the process (the copy holds the old and the new list at once).
      RequireMemory(static_cast<double>(sizeof(Arc)) * static_cast<double>(grown + fc.Arcs.size()),
        "the Hasse diagram of " + cloud + " (about " + std::to_string(estimate) + " arcs)",
        "use fewer points (a subsample) or a machine with more memory");
      ReserveHuge(fc.Arcs, grown);
    }
    for (std::size_t i = begin; i < last; ++i)
    {
      const Id node = base2 + static_cast<Id>(i);
      Patch& patch = patches[i - begin];
      fc.Report.ExactFallbacks += fallbacks[i - begin];
      // Arrival counts per Gabriel edge are the 1-2 multiplicities.
      for (std::size_t k = 0; k < patch.Arrivals.size();)
      {
        std::size_t l = k;
        while (l < patch.Arrivals.size() && patch.Arrivals[l] == patch.Arrivals[k])
        {
          ++l;
        }
        fc.Arcs.emplace_back(base1 + patch.Arrivals[k], node, static_cast<Id>(l - k));
        k = l;
      }
      if (this->Options.StableManifolds)
      {
        if (fc.Triangles.size() == fc.Triangles.capacity() && !fc.Triangles.empty())
        {
          // All the geometry was asked for: refuse before it no longer fits.
          const double perFacet = static_cast<double>(fc.Triangles.size()) / static_cast<double>(i);
          RequireMemory(3 * 48 * perFacet * static_cast<double>(nFacets),
            "drawing every stable manifold of " + cloud,
            "draw fewer cells (MaximumStableManifoldCells, flowrecon --max-cells)");
        }
        triangleBegin[i] = static_cast<Id>(fc.Triangles.size());
        const Id offset = static_cast<Id>(fc.Points.size());
        fc.Points.insert(fc.Points.end(), patch.Constructed.begin(), patch.Constructed.end());
        fc.NodePoint[node] = offset; // Constructed[0] is the critical point
        for (const auto& tr : patch.Triangles)
        {
          std::array<Id, 3> v;
          for (int k = 0; k < 3; ++k)
          {
            v[k] = tr[k] >= 0 ? this->In.InputId[tr[k]] : offset + (-1 - tr[k]);
          }
          fc.Triangles.push_back(v);
          fc.TriangleNode.push_back(node);
        }
      }
      patch = Patch(); // release memory early
    }
  };
  Batch current, next;
  tbb::task_group group;
  try
  {
    if (!cs.Facets.empty())
    {
      walk(0, current);
    }
    for (std::size_t begin = 0; begin < cs.Facets.size(); begin += chunk)
    {
      this->Report(0.35 + 0.35 * begin / nf, "stable manifolds");
      const bool more = begin + chunk < cs.Facets.size();
      if (more)
      {
        group.run([&, begin]() { walk(begin + chunk, next); });
      }
      try
      {
        merge(current);
      }
      catch (...)
      {
        group.cancel();
        group.wait();
        throw;
      }
      group.wait(); // rethrows what the walks threw
      std::swap(current, next);
    }
  }
  catch (const Degenerate&)
  {
    if (first)
    {
      ++fc.Report.WalkTies;
    }
    throw;
  }
  current = Batch();
  next = Batch();
  if (this->Options.StableManifolds)
  {
    triangleBegin[cs.Facets.size()] = static_cast<Id>(fc.Triangles.size());
  }
  // The edge index served the walks only (unless the walks go on later).
  if (!this->Keep)
  {
    std::vector<Id>().swap(cs.EdgeOffsets);
  }
  fc.Time.StableManifolds = Seconds(t);

  // Unstable manifolds: the two flow lines of each index-2 point.
  t = Clock::now();
  std::vector<std::array<std::int32_t, 2>> ends(cs.Facets.size()); // maxima reached
  // Which of ends[i] the normals of patch i face (PatchFacesSide, after the
  // reordering of the sides below): the cones need the side of each patch.
  std::vector<char> patchFaces(this->Options.StableManifolds ? cs.Facets.size() : 0, 0);
  fc.FlowLines.clear();
  {
    std::vector<std::int32_t> maximumOfCell(static_cast<std::size_t>(tri->NumberOfCells()), -1);
    for (std::size_t i = 0; i < cs.Cells.size(); ++i)
    {
      maximumOfCell[cs.Cells[i].Cell] = static_cast<std::int32_t>(base3 + static_cast<Id>(i));
    }
    const double stub = 0.25 * this->In.Diagonal;
    SuccessorForest forest(
      *tri, maximumOfCell, fc.InfinityNode, stub, this->Options.UnstableManifolds,
      this->Options.ExactOnly);
    const bool record = this->Options.UnstableManifolds;
    // The two flow lines of index-2 point i: ends[i], and their polylines when
    // recording (which memoises NEXT and shares tails, so runs on this thread).
    auto flowLines = [&](std::size_t i) {
      const Id node = base2 + static_cast<Id>(i);
      const auto& f = cs.Facets[i].Vertices;
      const CellHandle cell = tri->Cell(cs.Facets[i].Cell);
      const int opposite = cs.Facets[i].Opposite;
      CellHandle sides[2] = { cell, cell->neighbor(opposite) };
      // Which cell holds the facet depends on the triangulation's cell order, so
      // order the two sides by their apex (vertex index, infinite last) to keep
      // the output deterministic.
      {
        const VertexHandle a0 = cell->vertex(opposite);
        const VertexHandle a1 = sides[1]->vertex(sides[1]->index(cell));
        const Id k0 = tri->Dt().is_infinite(a0) ? m : a0->info();
        const Id k1 = tri->Dt().is_infinite(a1) ? m : a1->info();
        if (k1 < k0)
        {
          std::swap(sides[0], sides[1]);
        }
        if (!patchFaces.empty())
        {
          patchFaces[i] = static_cast<char>(PatchFacesSide(*tri, cs, i) ^ (k1 < k0 ? 1 : 0));
        }
      }
      Point3 centre{ { 0, 0, 0 } };
      if (record)
      {
        const KPoint pts[3] = { tri->KCoord(f[0]), tri->KCoord(f[1]), tri->KCoord(f[2]) };
        const std::array<double, 4> cr = CentreAndSquaredRadius(pts, 3);
        centre = { { cr[0], cr[1], cr[2] } };
      }
      for (int s = 0; s < 2; ++s)
      {
        FlowLine line;
        line.Node = node;
        if (record)
        {
          line.Points.push_back(centre);
        }
        if (tri->Dt().is_infinite(sides[s]))
        {
          line.Target = fc.InfinityNode;
          if (record)
          {
            // The Voronoi edge of a hull facet is a ray normal to it, away from the other cell.
            const CellHandle other = sides[1 - s];
            const KPoint& apex = other->vertex(other->index(sides[s]))->point();
            const KPoint& p = tri->KCoord(f[0]);
            Kernel::Vector_3 n = CGAL::cross_product(tri->KCoord(f[1]) - p, tri->KCoord(f[2]) - p);
            if (n * (apex - p) > 0)
            {
              n = -n;
            }
            const double len = std::sqrt(n.squared_length());
            line.Points.push_back({ { centre[0] + n.x() / len * stub,
              centre[1] + n.y() / len * stub, centre[2] + n.z() / len * stub } });
          }
        }
        else
        {
          const Id id = tri->CellId(sides[s]);
          line.Target = forest.Root(id);
          if (record)
          {
            line.Points.push_back(forest.Circumcentre(id));
            forest.AppendPath(id, line.Points, true);
          }
        }
        ends[i][s] = static_cast<std::int32_t>(line.Target);
        if (record)
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
    };
    try
    {
      if (record)
      {
        for (std::size_t i = 0; i < cs.Facets.size(); ++i)
        {
          if ((i & 0x3FF) == 0)
          {
            this->Report(0.7 + 0.2 * i / nf, "unstable manifolds");
          }
          flowLines(i);
        }
      }
      else
      {
        ParallelSlices(nFacets, 16 * chunk, this->Report, 0.7, 0.9, "unstable manifolds",
          [&](Id first, Id last) {
            for (Id i = first; i < last; ++i)
            {
              flowLines(static_cast<std::size_t>(i));
            }
          });
      }
    }
    catch (const Degenerate&)
    {
      if (first)
      {
        ++fc.Report.WalkTies;
      }
      throw;
    }
    fc.Report.ExactFallbacks += forest.ExactFallbacks();
  }
  fc.Time.UnstableManifolds = Seconds(t);

  // Everything below needs only the critical simplices: free the triangulation.
  t = Clock::now();
  this->Report(0.9, "Hasse diagram");
  if (!this->Keep)
  {
    tri.reset();
    // The triangulation's blocks came from tbbmalloc and the heap; the nodes below
    // are one large mapping that cannot reuse them.
    ReleaseFreedMemory();
  }

  // Nodes are independent constructions: fill them in parallel.
  fc.Nodes.clear();
  ReserveHugePopulated(fc.Nodes, static_cast<std::size_t>(fc.InfinityNode + 1));
  fc.Nodes.resize(static_cast<std::size_t>(fc.InfinityNode + 1));
  tbb::parallel_for(tbb::blocked_range<Id>(0, fc.InfinityNode), [&](const tbb::blocked_range<Id>& r) {
    for (Id n = r.begin(); n != r.end(); ++n)
    {
      if (n < base1)
      {
        fc.Nodes[n] = this->MakeNode(0, &n, coords);
      }
      else if (n < base2)
      {
        fc.Nodes[n] = this->MakeNode(1, cs.Edges[n - base1].data(), coords);
      }
      else if (n < base3)
      {
        fc.Nodes[n] = this->MakeNode(2, Widen(cs.Facets[n - base2].Vertices).data(), coords);
      }
      else
      {
        fc.Nodes[n] = this->MakeNode(3, Widen(cs.Cells[n - base3].Vertices).data(), coords);
      }
    }
  });
  {
    Node& inf = fc.Nodes.back();
    inf.Index = 3;
    inf.Value = HUGE_VAL;
    inf.Location = this->In.Centre;
  }

  for (std::size_t i = 0; i < ends.size(); ++i)
  {
    const Id node = base2 + static_cast<Id>(i);
    if (ends[i][0] == ends[i][1])
    {
      fc.Arcs.emplace_back(node, ends[i][0], 2);
    }
    else
    {
      fc.Arcs.emplace_back(node, ends[i][0], 1);
      fc.Arcs.emplace_back(node, ends[i][1], 1);
    }
  }
  // Values increase strictly along arcs in exact arithmetic, but a perturbed
  // degeneracy can leave a gap below double precision. The arcs come grouped by
  // index: one pass makes the doubles non-decreasing along every arc (a change
  // of at most an ulp or two), which the filtration relies on.
  for (const Arc& a : fc.Arcs)
  {
    fc.Nodes[a.Upper].Value = std::max(fc.Nodes[a.Upper].Value, fc.Nodes[a.Lower].Value);
  }
  // The critical points are double constructions (exact combinatorics, rounded
  // geometry): a cloud whose spacing is some 1e-20 of its extent makes them
  // underflow or cancel (values 0 or NaN). Refuse rather than answer wrongly.
  for (Id n = base1; n < fc.InfinityNode; ++n)
  {
    const Node& node = fc.Nodes[n];
    if (!(node.Value > 0 && std::isfinite(node.Value) && std::isfinite(node.Location[0]) &&
          std::isfinite(node.Location[1]) && std::isfinite(node.Location[2])))
    {
      throw InputError(TooClose);
    }
  }

  this->ScaleBack();
  if (!fc.DeferredPatches.empty())
  {
    // The promise of DeferredPatches on the final values (scaling back by a
    // power of two keeps every ratio; a value raised by the pass above would not).
    double largest = 0;
    for (Id n = base1; n < base2; ++n)
    {
      largest = std::max(largest, fc.Nodes[n].Value);
    }
    for (const Id n : fc.DeferredPatches)
    {
      if (!(fc.Nodes[n].Value / largest >= fc.DeferralRatio))
      {
        throw Degenerate("deferred patch below its ratio");
      }
    }
  }
  const DrawingBox box = BoxAround(fc.Points, fc.NumberOfInputPoints, 0.25);
  for (FlowLine& line : fc.FlowLines)
  {
    if (line.Target == fc.InfinityNode)
    {
      ClipPolyline(line.Points, box);
    }
  }
  // After scaling back: the cones' added points are then computed from the
  // same coordinates as DrawStableManifolds's.
  fc.Tetrahedra.clear();
  fc.TetrahedronNode.clear();
  if (this->Options.StableManifolds)
  {
    for (std::size_t i = 0; i < cs.Cells.size(); ++i)
    {
      const Id node = base3 + static_cast<Id>(i);
      fc.NodePoint[node] = static_cast<Id>(fc.Points.size());
      fc.Points.push_back(fc.Nodes[node].Location);
    }
    // The boundary patches of each maximum, in facet order (arcs are grouped by
    // lower node); fins (both flow lines here) too: see DrawStableManifolds.
    std::vector<Id> boundaryBegin(cs.Cells.size() + 1, 0), boundary;
    for (const Arc& arc : fc.Arcs)
    {
      if (arc.Lower >= base2 && arc.Lower < base3 && arc.Upper != fc.InfinityNode)
      {
        ++boundaryBegin[arc.Upper - base3 + 1];
      }
    }
    std::partial_sum(boundaryBegin.begin(), boundaryBegin.end(), boundaryBegin.begin());
    boundary.resize(static_cast<std::size_t>(boundaryBegin.back()));
    std::vector<Id> fill(boundaryBegin.begin(), boundaryBegin.end() - 1);
    for (const Arc& arc : fc.Arcs)
    {
      if (arc.Lower >= base2 && arc.Lower < base3 && arc.Upper != fc.InfinityNode)
      {
        boundary[fill[arc.Upper - base3]++] = arc.Lower - base2;
      }
    }
    ConeBoundary coneBoundary;
    for (std::size_t i = 0; i < cs.Cells.size(); ++i)
    {
      const Id node = base3 + static_cast<Id>(i);
      coneBoundary.Clear();
      for (Id b = boundaryBegin[i]; b < boundaryBegin[i + 1]; ++b)
      {
        const std::size_t f = static_cast<std::size_t>(boundary[b]);
        const bool fin = ends[f][0] == ends[f][1];
        coneBoundary.Add(fc.Triangles.data() + triangleBegin[f],
          fc.Triangles.data() + triangleBegin[f + 1], !fin && ends[f][patchFaces[f]] != node, fin);
      }
      fc.TetrahedronNode.insert(fc.TetrahedronNode.end(),
        static_cast<std::size_t>(AppendCone(fc.NodePoint[node], coneBoundary.Triangles, fc.Points,
          fc.Tetrahedra, &coneBoundary.TwoSided)),
        node);
    }
  }
  fc.Time.Assembly = Seconds(t);
  if (this->Keep)
  {
    this->KeptTriangulation = std::move(tri);
    this->KeptCritical = std::move(cs);
  }
}

void Builder::ScaleBack()
{
  const int e = this->ScaleExponent;
  if (e == 0)
  {
    return;
  }
  auto back = [e](Point3& p) {
    for (double& x : p)
    {
      x = std::ldexp(x, e);
    }
  };
  FlowComplex& fc = this->FC;
  for (Node& n : fc.Nodes)
  {
    if (n.Index > 0 && !n.IsInfinity())
    {
      n.Value = std::ldexp(n.Value, e);
      back(n.Location);
    }
  }
  for (std::size_t k = static_cast<std::size_t>(fc.NumberOfInputPoints); k < fc.Points.size(); ++k)
  {
    back(fc.Points[k]);
  }
  for (FlowLine& line : fc.FlowLines)
  {
    for (Point3& p : line.Points)
    {
      back(p);
    }
  }
}

} // namespace

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
    FlowComplex fc = BuildFlowComplex(points, hasse, first);
    std::vector<Id> counts = StableManifoldCellCounts(fc.Nodes, fc.Arcs);
    for (const Id node : fc.DeferredPatches)
    {
      // Not walked, so of unknown size (a patch across a tube): the drawing
      // stops below the first of them, keeping the budget a bound.
      counts[node] = std::numeric_limits<Id>::max() / 4;
    }
    const std::vector<Id> draw = NodesWithinBudget(fc.Nodes, counts, options.MaximumGeometryCells);
    const auto t = Clock::now();
    DrawStableManifolds(points, options, draw, fc, second, "lower the cell budget");
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
      builder.KeptTriangulation.reset(); // refers to the coordinates below
      coords = std::make_unique<const std::vector<Point3>>(AttemptCoordinates(in, attempt, options.Seed));
      builder.Run(*coords, attempt == 1);
      fc.Report.Attempts = attempt;
      fc.Report.Seed = options.Seed;
      fc.Report.PerturbationMagnitude = std::ldexp(magnitude, builder.ScaleExponent);
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
      std::move(builder.KeptTriangulation), std::move(builder.KeptCritical));
  }
  fc.Time.Total = Seconds(start);
  progress(1.0, "done");
  return fc;
}

} // namespace flowrecon
