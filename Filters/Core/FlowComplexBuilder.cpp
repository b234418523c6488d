#include "FlowComplexBuilder.h"

#include "Arithmetic.h"
#include "CriticalSimplices.h"
#include "InputPreparation.h"
#include "StableManifold.h"
#include "SuccessorForest.h"
#include "Triangulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
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

/// Squared circumradius and circumcentre of a simplex given by 2..4 points.
std::array<double, 4> CentreAndSquaredRadius(const std::vector<Point3>& pts)
{
  return Certified<4>([&](auto ft) {
    using FT = decltype(ft);
    std::vector<Vec<FT>> p;
    for (const Point3& q : pts)
    {
      p.push_back(Vec<FT>::From(q));
    }
    Vec<FT> c = p[0];
    if (p.size() == 2)
    {
      c = (p[0] + p[1]) / FT(2);
    }
    else if (p.size() == 3)
    {
      c = Circumcenter(p[0], p[1], p[2]);
    }
    else
    {
      c = Circumcenter(p[0], p[1], p[2], p[3]);
    }
    return std::array<FT, 4>{ { c.X, c.Y, c.Z, (c - p[0]).SquaredLength() } };
  });
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
  void AddNode(int index, const std::vector<Id>& simplex, const std::vector<Point3>& coords);

  const PreparedInput& In;
  const std::vector<Point3>& Input;
  const BuildOptions& Options;
  const Progress& Report;
  FlowComplex& FC;
};

void Builder::AddNode(int index, const std::vector<Id>& simplex, const std::vector<Point3>& coords)
{
  Node node;
  node.Index = index;
  std::vector<Point3> pts;
  for (std::size_t i = 0; i < simplex.size(); ++i)
  {
    node.Simplex[i] = this->In.InputId[simplex[i]];
    pts.push_back(coords[simplex[i]]);
  }
  if (index == 0)
  {
    node.Location = this->Input[node.Simplex[0]];
    node.Value = 0;
  }
  else
  {
    const std::array<double, 4> cr = CentreAndSquaredRadius(pts);
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

  // Nodes, sorted by (index, input ids): unique indices increase with input ids.
  fc.Nodes.clear();
  fc.NodePoint.clear();
  const Id m = tri.NumberOfVertices();
  const Id base1 = m, base2 = base1 + static_cast<Id>(cs.Edges.size());
  const Id base3 = base2 + static_cast<Id>(cs.Facets.size());
  fc.InfinityNode = base3 + static_cast<Id>(cs.Cells.size());
  fc.Nodes.reserve(static_cast<std::size_t>(fc.InfinityNode + 1));
  for (Id k = 0; k < m; ++k)
  {
    this->AddNode(0, { k }, coords);
  }
  for (const auto& e : cs.Edges)
  {
    this->AddNode(1, { e[0], e[1] }, coords);
  }
  for (const auto& f : cs.Facets)
  {
    this->AddNode(2, { f[0], f[1], f[2] }, coords);
  }
  for (const auto& c : cs.Cells)
  {
    this->AddNode(3, { c[0], c[1], c[2], c[3] }, coords);
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
  std::map<std::pair<Id, Id>, int> arrivals; // (edge node, facet node) -> count
  const double nf = static_cast<double>(cs.Facets.size()) + 1;
  for (std::size_t i = 0; i < cs.Facets.size(); ++i)
  {
    if ((i & 0x3FF) == 0)
    {
      this->Report(0.35 + 0.35 * i / nf, "stable manifolds");
    }
    const Id node = base2 + static_cast<Id>(i);
    Patch patch;
    try
    {
      patch = ComputeStableManifold(
        tri, cs, cs.Facets[i], this->Options.StableManifolds, fc.Report.ExactFallbacks);
    }
    catch (const Degenerate&)
    {
      if (first)
      {
        ++fc.Report.WalkTies;
      }
      throw;
    }
    for (const Id edge : patch.Arrivals)
    {
      ++arrivals[{ base1 + edge, node }];
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
    CellHandle cell;
    int opposite = 0;
    tri.Facet(f[0], f[1], f[2], cell, opposite);
    const CellHandle sides[2] = { cell, cell->neighbor(opposite) };
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
  for (const auto& a : arrivals)
  {
    fc.Arcs.push_back({ a.first.first, a.first.second, a.second });
  }
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
  std::sort(fc.Arcs.begin(), fc.Arcs.end(), [](const Arc& a, const Arc& b) {
    return a.Lower != b.Lower ? a.Lower < b.Lower : a.Upper < b.Upper;
  });

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
  const PreparedInput in = PrepareInput(points);
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
