#include "FlowComplexBuilder.h"

#include "Arithmetic.h"
#include "CriticalSimplices.h"
#include "InputPreparation.h"
#include "StableManifold.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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

  /// One attempt on `coords` (the unique points, perhaps perturbed). Throws
  /// Degenerate if general position fails; `first` records the counts.
  void Run(const std::vector<Point3>& coords, bool first);

private:
  void AddNode(int index, const Id* simplex, const Triangulation& tri);

  const PreparedInput& In;
  const std::vector<Point3>& Input;
  const BuildOptions& Options;
  const Progress& Report;
  FlowComplex& FC;
};

void Builder::AddNode(int index, const Id* simplex, const Triangulation& tri)
{
  Node node;
  node.Index = index;
  KPoint pts[4];
  for (int i = 0; i <= index; ++i)
  {
    node.Simplex[i] = this->In.InputId[simplex[i]];
    pts[i] = tri.KCoord(simplex[i]);
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
  this->FC.Nodes.push_back(node);
  this->FC.NodePoint.push_back(index == 0 ? node.Simplex[0] : -1);
}

void Builder::Run(const std::vector<Point3>& coords, bool first)
{
  FlowComplex& fc = this->FC;
  const auto t0 = Clock::now();
  this->Report(0.0, "Delaunay triangulation");
  const Triangulation tri(coords);
  if (tri.Dimension() < 3)
  {
    throw InputError(tri.Dimension() == 2 ? "all points are coplanar"
                                          : "all points are collinear");
  }
  if (tri.NumberOfVertices() != static_cast<Id>(coords.size()) ||
    static_cast<Id>(tri.Dt().number_of_vertices()) != tri.NumberOfVertices())
  {
    throw Degenerate("perturbation created duplicate points");
  }
  fc.Time.Delaunay = Seconds(t0);

  auto t = Clock::now();
  this->Report(0.2, "critical points");
  const CriticalSimplices cs = FindCriticalSimplices(tri, this->Report);
  if (first)
  {
    fc.Report.RightAngles = cs.RightAngles;
    fc.Report.ApexOnSphere = cs.ApexOnSphere;
  }
  if (cs.Degenerate())
  {
    throw Degenerate("input not in general position");
  }

  // Nodes by index; within an index in the (Hilbert) order of their vertices.
  fc.Nodes.clear();
  fc.NodePoint.clear();
  const Id m = tri.NumberOfVertices();
  const Id base1 = m, base2 = base1 + static_cast<Id>(cs.Edges.size());
  const Id base3 = base2 + static_cast<Id>(cs.Facets.size());
  fc.InfinityNode = base3 + static_cast<Id>(cs.Cells.size());
  fc.Nodes.reserve(static_cast<std::size_t>(fc.InfinityNode + 1));
  for (Id k = 0; k < m; ++k)
  {
    this->AddNode(0, &k, tri);
  }
  for (const auto& e : cs.Edges)
  {
    this->AddNode(1, e.data(), tri);
  }
  for (const auto& f : cs.Facets)
  {
    this->AddNode(2, f.data(), tri);
  }
  for (const auto& c : cs.Cells)
  {
    this->AddNode(3, c.data(), tri);
  }
  {
    Node inf;
    inf.Index = 3;
    inf.Value = HUGE_VAL;
    inf.Location = this->In.Centre;
    fc.Nodes.push_back(inf);
    fc.NodePoint.push_back(-1);
  }
  fc.Time.CriticalPoints = Seconds(t);

  // Stable manifolds of index-2 points and the 1-2 incidences.
  t = Clock::now();
  fc.Points.assign(this->Input.begin(), this->Input.end());
  fc.NumberOfInputPoints = static_cast<Id>(this->Input.size());
  fc.Triangles.clear();
  fc.TriangleNode.clear();
  fc.Arcs.clear();
  std::vector<Id> triangleBegin(cs.Facets.size() + 1, 0);
  std::vector<std::pair<Id, Id>> arrivals; // (edge node, facet node), one per arrival
  const double nf = static_cast<double>(cs.Facets.size()) + 1;
  // Patches are independent: compute them in parallel, chunk by chunk, and merge
  // them in node order on this thread (which also reports progress).
  const std::size_t chunk = 8192;
  std::vector<Patch> patches;
  std::vector<Id> fallbacks;
  for (std::size_t begin = 0; begin < cs.Facets.size(); begin += chunk)
  {
    this->Report(0.35 + 0.35 * begin / nf, "stable manifolds");
    const std::size_t last = std::min(cs.Facets.size(), begin + chunk);
    patches.assign(last - begin, Patch());
    fallbacks.assign(last - begin, 0);
    try
    {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, last),
        [&](const tbb::blocked_range<std::size_t>& r) {
          for (std::size_t i = r.begin(); i != r.end(); ++i)
          {
            patches[i - begin] = ComputeStableManifold(
              tri, cs, i, this->Options.StableManifolds, fallbacks[i - begin]);
          }
        });
    }
    catch (const Degenerate&)
    {
      if (first)
      {
        ++fc.Report.WalkTies;
      }
      throw;
    }
    for (std::size_t i = begin; i < last; ++i)
    {
      const Id node = base2 + static_cast<Id>(i);
      Patch& patch = patches[i - begin];
      fc.Report.ExactFallbacks += fallbacks[i - begin];
      for (const Id edge : patch.Arrivals)
      {
        arrivals.emplace_back(base1 + edge, node);
      }
      triangleBegin[i] = static_cast<Id>(fc.Triangles.size());
      if (this->Options.StableManifolds)
      {
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
  }
  triangleBegin[cs.Facets.size()] = static_cast<Id>(fc.Triangles.size());
  fc.Time.StableManifolds = Seconds(t);

  // Unstable manifolds: the two flow lines of each index-2 point.
  t = Clock::now();
  std::vector<Id> maximumOfCell(static_cast<std::size_t>(tri.NumberOfCells()), -1);
  for (std::size_t i = 0; i < cs.Cells.size(); ++i)
  {
    maximumOfCell[cs.CellOfMaximum[i]] = base3 + static_cast<Id>(i);
  }
  const double stub = 0.25 * this->In.Diagonal;
  SuccessorForest forest(tri, maximumOfCell, fc.InfinityNode, stub);
  std::vector<std::array<Id, 2>> ends(cs.Facets.size());
  fc.FlowLines.clear();
  for (std::size_t i = 0; i < cs.Facets.size(); ++i)
  {
    if ((i & 0x3FF) == 0)
    {
      this->Report(0.7 + 0.2 * i / nf, "unstable manifolds");
    }
    const Id node = base2 + static_cast<Id>(i);
    const auto& f = cs.Facets[i];
    const CellHandle cell = cs.FacetCells[i].first;
    const int opposite = cs.FacetCells[i].second;
    CellHandle sides[2] = { cell, cell->neighbor(opposite) };
    // CGAL's spatial sort shuffles with a global generator, so which cell holds
    // the facet varies between runs: order the two sides by their apex (input id,
    // infinite last) to keep the output deterministic.
    {
      const VertexHandle a0 = cell->vertex(opposite);
      const VertexHandle a1 = sides[1]->vertex(sides[1]->index(cell));
      const Id k0 = tri.Dt().is_infinite(a0) ? m : a0->info();
      const Id k1 = tri.Dt().is_infinite(a1) ? m : a1->info();
      if (k1 < k0)
      {
        std::swap(sides[0], sides[1]);
      }
    }
    for (int s = 0; s < 2; ++s)
    {
      FlowLine line;
      line.Node = node;
      const bool record = this->Options.UnstableManifolds;
      if (record)
      {
        line.Points.push_back(fc.Nodes[node].Location);
      }
      try
      {
        if (tri.Dt().is_infinite(sides[s]))
        {
          line.Target = fc.InfinityNode;
          if (record)
          {
            // The Voronoi edge of a hull facet is a ray normal to it, away from the other cell.
            const CellHandle other = sides[1 - s];
            const KPoint& apex = other->vertex(other->index(sides[s]))->point();
            const KPoint& p = tri.KCoord(f[0]);
            Kernel::Vector_3 n =
              CGAL::cross_product(tri.KCoord(f[1]) - p, tri.KCoord(f[2]) - p);
            if (n * (apex - p) > 0)
            {
              n = -n;
            }
            const double len = std::sqrt(n.squared_length());
            const Point3& c = line.Points[0];
            line.Points.push_back({ { c[0] + n.x() / len * stub, c[1] + n.y() / len * stub,
              c[2] + n.z() / len * stub } });
          }
        }
        else
        {
          const Id id = tri.CellId(sides[s]);
          line.Target = forest.Root(id);
          if (record)
          {
            line.Points.push_back(forest.Circumcentre(id));
            forest.AppendPath(id, line.Points, true);
          }
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
      ends[i][s] = line.Target;
      if (record)
      {
        fc.FlowLines.push_back(std::move(line));
      }
    }
  }
  fc.Report.ExactFallbacks += forest.ExactFallbacks;
  fc.Time.UnstableManifolds = Seconds(t);

  // Hasse diagram and index-3 cones.
  t = Clock::now();
  this->Report(0.9, "Hasse diagram");
  for (std::size_t i = 0; i < cs.Edges.size(); ++i)
  {
    const Id node = base1 + static_cast<Id>(i);
    fc.Arcs.push_back({ cs.Edges[i][0], node, 1 });
    fc.Arcs.push_back({ cs.Edges[i][1], node, 1 });
  }
  // Arrivals are grouped by patch: count the repeats within each group.
  for (std::size_t i = 0; i < arrivals.size();)
  {
    std::size_t j = i;
    while (j < arrivals.size() && arrivals[j].second == arrivals[i].second)
    {
      ++j;
    }
    std::sort(arrivals.begin() + i, arrivals.begin() + j);
    for (std::size_t k = i; k < j;)
    {
      std::size_t l = k;
      while (l < j && arrivals[l] == arrivals[k])
      {
        ++l;
      }
      fc.Arcs.push_back({ arrivals[k].first, arrivals[k].second, static_cast<int>(l - k) });
      k = l;
    }
    i = j;
  }
  std::vector<std::pair<Id, Id>>().swap(arrivals);
  for (std::size_t i = 0; i < ends.size(); ++i)
  {
    const Id node = base2 + static_cast<Id>(i);
    if (ends[i][0] == ends[i][1])
    {
      fc.Arcs.push_back({ node, ends[i][0], 2 });
    }
    else
    {
      fc.Arcs.push_back({ node, ends[i][0], 1 });
      fc.Arcs.push_back({ node, ends[i][1], 1 });
    }
  }
  // Values increase strictly along arcs in exact arithmetic, but a perturbed
  // degeneracy can leave a gap below double precision. Arcs come grouped by the
  // index of their lower node: one pass makes the doubles non-decreasing along
  // every arc (a change of at most an ulp or two), which the filtration relies on.
  for (const Arc& a : fc.Arcs)
  {
    fc.Nodes[a.Upper].Value = std::max(fc.Nodes[a.Upper].Value, fc.Nodes[a.Lower].Value);
  }

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
    for (const Arc& arc : fc.Arcs)
    {
      if (arc.Lower < base2 || arc.Lower >= base3 || arc.Upper == fc.InfinityNode ||
        arc.Multiplicity % 2 == 0)
      {
        continue;
      }
      const std::size_t f = static_cast<std::size_t>(arc.Lower - base2);
      for (Id k = triangleBegin[f]; k < triangleBegin[f + 1]; ++k)
      {
        const auto& tr = fc.Triangles[k];
        fc.Tetrahedra.push_back({ { fc.NodePoint[arc.Upper], tr[0], tr[1], tr[2] } });
        fc.TetrahedronNode.push_back(arc.Upper);
      }
    }
  }
  fc.Time.Assembly = Seconds(t);
}

/// Renumbers the distinct points along a Hilbert curve. Every per-vertex table
/// (adjacency, walks, node lists) is then visited with spatial locality, which
/// matters more than anything else for large clouds; hilbert_sort is
/// deterministic (unlike spatial_sort, which shuffles).
void SpatialOrder(PreparedInput& in)
{
  std::vector<KPoint> pts;
  pts.reserve(in.Unique.size());
  for (const Point3& p : in.Unique)
  {
    pts.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::size_t> order(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  using Map = CGAL::Pointer_property_map<KPoint>::const_type;
  const Map map = CGAL::make_property_map(static_cast<const std::vector<KPoint>&>(pts));
  CGAL::hilbert_sort(order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<Kernel, Map>(map));
  std::vector<Point3> unique(order.size());
  std::vector<Id> ids(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    unique[i] = in.Unique[order[i]];
    ids[i] = in.InputId[order[i]];
  }
  in.Unique.swap(unique);
  in.InputId.swap(ids);
}

} // namespace

FlowComplex BuildFlowComplex(
  const std::vector<Point3>& points, const BuildOptions& options, const Progress& progress)
{
  const auto start = Clock::now();
  struct ExactScope
  {
    bool Saved = ExactOnly();
    ~ExactScope() { ExactOnly() = this->Saved; }
  } exactScope;
  ExactOnly() = options.ExactOnly;
  PreparedInput in = PrepareInput(points);
  SpatialOrder(in);
  FlowComplex fc;
  fc.Representative = in.Representative;
  fc.Report.InputPoints = static_cast<Id>(points.size());
  fc.Report.DuplicatePoints = static_cast<Id>(points.size() - in.Unique.size());
  Builder builder(in, points, options, progress, fc);

  // Perturbations are relative to the cloud size (never below a few ulps of the
  // coordinates). Degenerate configurations split their critical values only at
  // second order in the perturbation, so 1e-6 of the diagonal keeps those gaps
  // (~1e-12) well above double precision: values stay strictly ordered.
  double maxAbs = 0;
  for (const Point3& p : in.Unique)
  {
    for (const double x : p)
    {
      maxAbs = std::max(maxAbs, std::fabs(x));
    }
  }
  const double floor = 64 * std::numeric_limits<double>::epsilon() * maxAbs;
  for (int attempt = 1;; ++attempt)
  {
    const double magnitude =
      attempt == 1 ? 0 : std::max(1e-6 * in.Diagonal * std::ldexp(1.0, attempt - 2), floor);
    try
    {
      if (attempt == 1)
      {
        builder.Run(in.Unique, true);
      }
      else
      {
        builder.Run(Perturb(in.Unique, magnitude, options.Seed * 0x100000001B3ull + attempt), false);
      }
      fc.Report.Attempts = attempt;
      fc.Report.PerturbationMagnitude = magnitude;
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
  fc.Time.Total = Seconds(start);
  progress(1.0, "done");
  return fc;
}

} // namespace flowrecon
