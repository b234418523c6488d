// Invariants that hold for every point cloud (docs/algorithm.md §8.1):
// Euler characteristic, boundary of boundary, monotone values along arcs, arc
// counts, EMST inside the Gabriel graph, patches bounded by their Gabriel edges,
// contractible total complex, determinism; on random, structured and degenerate
// clouds.
#include "Check.h"
#include "Clouds.h"
#include "Invariants.h"

#include "CompressedRows.h"
#include "FlowComplexBuilder.h"
#include "Persistence.h"
#include "ProfileJumps.h"
#include "Triangulation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

using Cloud = std::vector<Point3>;

using clouds::Cospherical;
using clouds::Cube;
using clouds::Grid;
using clouds::Rng;
using clouds::Sphere;
using clouds::Torus;
using clouds::WithDuplicates;

double Dist2(const Point3& a, const Point3& b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]);
}

/// Edges of a Euclidean minimum spanning tree of the distinct points (Prim, O(n^2)).
std::set<std::pair<Id, Id>> Emst(const Cloud& c, const std::vector<Id>& rep)
{
  std::vector<Id> ids;
  for (Id i = 0; i < static_cast<Id>(c.size()); ++i)
  {
    if (rep[i] == i)
    {
      ids.push_back(i);
    }
  }
  std::vector<double> best(ids.size(), HUGE_VAL);
  std::vector<Id> from(ids.size(), -1);
  std::vector<bool> in(ids.size(), false);
  std::set<std::pair<Id, Id>> edges;
  best[0] = 0;
  for (std::size_t it = 0; it < ids.size(); ++it)
  {
    std::size_t u = ids.size();
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (!in[i] && (u == ids.size() || best[i] < best[u]))
        u = i;
    in[u] = true;
    if (from[u] >= 0)
      edges.insert({ std::min(ids[u], ids[from[u]]), std::max(ids[u], ids[from[u]]) });
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      const double d = Dist2(c[ids[u]], c[ids[i]]);
      if (!in[i] && d < best[i])
      {
        best[i] = d;
        from[i] = static_cast<Id>(u);
      }
    }
  }
  return edges;
}

void CheckComplex(const std::string& name, const Cloud& cloud, bool emst)
{
  std::cout << "-- " << name << " (" << cloud.size() << " points)\n";
  const FlowComplex fc = BuildFlowComplex(cloud, BuildOptions(), Progress());
  const auto n = fc.CountByIndex();
  CHECK(n[0] - n[1] + n[2] - n[3] == 1);
  CHECK(fc.Nodes.back().IsInfinity() && fc.InfinityNode == static_cast<Id>(fc.Nodes.size()) - 1);

  // Arcs go up one index with strictly increasing values.
  std::vector<int> down(fc.Nodes.size(), 0), up(fc.Nodes.size(), 0);
  for (const Arc& a : fc.Arcs)
  {
    CHECK(fc.Nodes[a.Upper].Index == fc.Nodes[a.Lower].Index + 1);
    // Strict in exact arithmetic; a perturbed degeneracy may tie in double.
    if (fc.Report.Perturbed())
      CHECK(fc.Nodes[a.Lower].Value <= fc.Nodes[a.Upper].Value);
    else
      CHECK(fc.Nodes[a.Lower].Value < fc.Nodes[a.Upper].Value);
    CHECK(a.Multiplicity >= 1);
    down[a.Upper] += a.Multiplicity;
    if (fc.Nodes[a.Lower].Index == 2)
    {
      up[a.Lower] += a.Multiplicity;
    }
  }
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const Node& node = fc.Nodes[i];
    if (node.Index == 1)
      CHECK(down[i] == 2);
    if (node.Index == 2)
      CHECK(up[i] == 2 && down[i] >= 1);
    if (node.Index == 3 && !node.IsInfinity())
      CHECK(down[i] >= 1);
  }

  // Boundary of boundary is zero over Z/2 (arcs to infinity excluded).
  CHECK(invariants::BoundaryOfBoundaryIsZero(fc.Nodes, fc.Arcs, false));

  // The finite complex is contractible: one essential class, and every maximum
  // kills a 2-cycle (boundaries of maxima are independent, GJ Theorem 2).
  int essential = 0, dimension3 = 0;
  for (const PersistencePair& p : ComputePersistence(fc.Nodes, fc.Arcs))
  {
    essential += p.Death < 0 ? 1 : 0;
    dimension3 += p.Dimension == 3 ? 1 : 0;
  }
  CHECK(essential == 1);
  CHECK(dimension3 == 0);

  // Each patch is a surface whose boundary edges are its Gabriel edges, counted
  // with the arc multiplicity; other edges are shared by exactly two triangles;
  // every index-2 node has one.
  const invariants::EdgeUse edgeUse = invariants::PatchEdgeUse(fc);
  const auto gabriel = invariants::GabrielNodes(fc);
  CHECK(invariants::PatchesBoundedByGabrielEdges(fc, edgeUse));
  // Conversely, every 1-2 arc appears on its patch as a boundary edge used as
  // often as the arc's multiplicity.
  bool arcsOnPatches = true;
  for (const Arc& a : fc.Arcs)
  {
    if (fc.Nodes[a.Lower].Index != 1 || fc.Nodes[a.Upper].Index != 2)
      continue;
    const auto& s = fc.Nodes[a.Lower].Simplex;
    const auto use = edgeUse.find(a.Upper);
    arcsOnPatches = arcsOnPatches && use != edgeUse.end() &&
      use->second.count({ s[0], s[1] }) == 1 && use->second.at({ s[0], s[1] }) == a.Multiplicity;
  }
  CHECK(arcsOnPatches);

  if (emst)
  {
    bool inside = true;
    for (const auto& e : Emst(cloud, fc.Representative))
      inside = inside && gabriel.count(e) == 1;
    CHECK(inside);
  }

  // Determinism: a second run gives the same nodes, arcs and triangles.
  const FlowComplex again = BuildFlowComplex(cloud, BuildOptions(), Progress());
  bool same = again.Nodes.size() == fc.Nodes.size() && again.Arcs.size() == fc.Arcs.size() &&
    again.Triangles == fc.Triangles && again.Points == fc.Points;
  for (std::size_t i = 0; same && i < fc.Nodes.size(); ++i)
    same = again.Nodes[i].Simplex == fc.Nodes[i].Simplex && again.Nodes[i].Value == fc.Nodes[i].Value;
  for (std::size_t i = 0; same && i < fc.Arcs.size(); ++i)
    same = again.Arcs[i].Lower == fc.Arcs[i].Lower && again.Arcs[i].Upper == fc.Arcs[i].Upper &&
      again.Arcs[i].Multiplicity == fc.Arcs[i].Multiplicity;
  CHECK(same);
  std::cout << "   nodes " << n[0] << "/" << n[1] << "/" << n[2] << "/" << n[3]
            << ", triangles " << fc.Triangles.size() << ", attempts " << fc.Report.Attempts
            << ", duplicates " << fc.Report.DuplicatePoints << "\n";
}

/// Scaling a cloud by 2^k (exact in floating point) scales every critical value
/// and location by 2^k and changes nothing else, even near the ends of the
/// double range, where squares of coordinates overflow or underflow.
void CheckScaleInvariance(const Cloud& cloud, int k)
{
  std::cout << "-- scaled by 2^" << k << "\n";
  Cloud scaled = cloud;
  for (Point3& p : scaled)
    for (double& x : p)
      x = std::ldexp(x, k);
  const FlowComplex a = BuildFlowComplex(cloud, BuildOptions(), Progress());
  const FlowComplex b = BuildFlowComplex(scaled, BuildOptions(), Progress());
  bool same = a.Nodes.size() == b.Nodes.size() && a.Arcs.size() == b.Arcs.size() &&
    a.Triangles == b.Triangles && a.Points.size() == b.Points.size();
  for (std::size_t i = 0; same && i < a.Nodes.size(); ++i)
  {
    same = a.Nodes[i].Simplex == b.Nodes[i].Simplex &&
      (a.Nodes[i].IsInfinity() || std::ldexp(a.Nodes[i].Value, k) == b.Nodes[i].Value);
    for (int c = 0; same && c < 3 && !a.Nodes[i].IsInfinity(); ++c)
      same = std::ldexp(a.Nodes[i].Location[c], k) == b.Nodes[i].Location[c];
  }
  for (std::size_t i = 0; same && i < a.Arcs.size(); ++i)
    same = a.Arcs[i].Lower == b.Arcs[i].Lower && a.Arcs[i].Upper == b.Arcs[i].Upper &&
      a.Arcs[i].Multiplicity == b.Arcs[i].Multiplicity;
  bool finite = true;
  for (const Point3& p : b.Points)
    finite = finite && std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  CHECK(same);
  CHECK(finite);
}

/// The interval-filtered walks and the exact-only walks give the same complex.
void CheckExactAgreement(const std::string& name, const Cloud& cloud)
{
  std::cout << "-- exact agreement: " << name << "\n";
  BuildOptions exact;
  exact.ExactOnly = true;
  const FlowComplex a = BuildFlowComplex(cloud, BuildOptions(), Progress());
  const FlowComplex b = BuildFlowComplex(cloud, exact, Progress());
  CHECK(b.Report.ExactFallbacks > 0);
  CHECK(a.Nodes.size() == b.Nodes.size() && a.Arcs.size() == b.Arcs.size());
  CHECK(a.Triangles == b.Triangles && a.TriangleNode == b.TriangleNode);
  bool arcs = a.Arcs.size() == b.Arcs.size();
  for (std::size_t i = 0; arcs && i < a.Arcs.size(); ++i)
    arcs = a.Arcs[i].Lower == b.Arcs[i].Lower && a.Arcs[i].Upper == b.Arcs[i].Upper &&
      a.Arcs[i].Multiplicity == b.Arcs[i].Multiplicity;
  CHECK(arcs);
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.Points.size(), b.Points.size()); ++i)
    worst = std::max(worst, std::sqrt(Dist2(a.Points[i], b.Points[i])));
  CHECK(a.Points.size() == b.Points.size() && worst < 1e-8);
  bool lines = a.FlowLines.size() == b.FlowLines.size();
  for (std::size_t i = 0; lines && i < a.FlowLines.size(); ++i)
    lines = a.FlowLines[i].Target == b.FlowLines[i].Target;
  CHECK(lines);
}

} // namespace

/// The one compressed-rows type: stable grouping, empty rows, sorting; and the
/// one persistence ratio with its clamping.
// The profile's largest jumps (paper §5.2), on a profile worked by hand: rises
// 0.2 (step 1), 0.8 (step 2), 0 (step 3), 1.4 (step 4), 0.8 (step 5).
void CheckProfileJumps()
{
  const std::vector<double> t = { 1.0, 1.2, 2.0, 2.0, 3.4, 4.2 };
  const std::vector<ProfileJump> two = LargestJumps(t, 2);
  CHECK(two.size() == 2 && two[0].Step == 4 && two[0].Before == 2.0 && two[0].After == 3.4);
  // 0.8 twice (steps 2 and 5, up to rounding): the largest first.
  CHECK(two[1].Step == ((t[2] - t[1]) >= (t[5] - t[4]) ? 2u : 5u));
  const std::vector<ProfileJump> all = LargestJumps(t, 10);
  CHECK(all.size() == 4); // the flat step 3 is no jump
  CHECK(all.back().Step == 1 && all.back().Before == 1.0 && all.back().After == 1.2);
  CHECK(LargestJumps({ 1.5 }, 3).empty() && LargestJumps({}, 3).empty());
  CHECK(LargestJumps({ 1, 2, 3 }, 2)[0].Step == 1); // equal rises: the earlier step
}

void CheckDataModel()
{
  using Rows = CompressedRows<int>;
  const std::vector<std::pair<Id, int>> entries = { { 2, 7 }, { 0, 9 }, { 2, 3 }, { 3, 5 }, { 0, 1 } };
  Rows rows = Rows::Group(5, [&](const auto& emit) {
    for (const auto& e : entries)
      emit(e.first, e.second);
  });
  CHECK(rows.Offsets == (std::vector<Id>{ 0, 2, 2, 4, 5, 5 }));
  CHECK(rows.Values == (std::vector<int>{ 9, 1, 7, 3, 5 }));
  CHECK(rows.RowCount() == 5 && rows.ValueCount() == 5 && rows.RowSize(2) == 2);
  CHECK(rows.Row(1).empty() && rows.Row(4).empty() && rows.Row(3).size() == 1 && rows.Row(3)[0] == 5);
  rows.SortRows();
  CHECK(rows.Values == (std::vector<int>{ 1, 9, 3, 7, 5 }));
  Rows appended; // rows made one at a time: an empty row keeps its place
  const std::vector<int> row = { 4, 2 };
  appended.AppendRow(row.begin(), row.end());
  appended.AppendRow(row.begin(), row.begin());
  appended.AppendRow(row.begin() + 1, row.end());
  CHECK(appended.Offsets == (std::vector<Id>{ 0, 2, 2, 3 }) && appended.Values == (std::vector<int>{ 4, 2, 2 }));
  CHECK(appended.RowCount() == 3 && appended.Row(1).empty() && appended.Row(2)[0] == 2);
  const Rows none = Rows::Group(0, [](const auto&) {});
  CHECK(none.Offsets == std::vector<Id>{ 0 } && none.Values.empty() && none.RowCount() == 0);
  const CompressedRows<Id> byRow = PositionsByRow({ 1, 0, 1, 1 }, 3);
  CHECK(byRow.Offsets == (std::vector<Id>{ 0, 1, 4, 4 }));
  CHECK(byRow.Values == (std::vector<Id>{ 1, 0, 2, 3 }));
  const std::vector<Id> values(byRow.Row(1).begin(), byRow.Row(1).end());
  CHECK(values == (std::vector<Id>{ 0, 2, 3 }));

  CHECK(PersistenceRatio(3, 2) == 1.5 && PersistenceRatio(0.5, 1) == 0.5);
  CHECK(PersistenceRatio(1, 0) == HUGE_VAL && PersistenceRatio(1, std::nan("")) == HUGE_VAL);
  CHECK(PersistenceRatioAtLeastOne(0.5, 1) == 1 && PersistenceRatioAtLeastOne(3, 2) == 1.5);
  CHECK(PersistenceRatioAtLeastOne(1, 0) == HUGE_VAL && PersistenceRatioAtLeastOne(HUGE_VAL, 2) == HUGE_VAL);
}

// Drawing the flow lines (their polylines) must not send a walk to exact
// arithmetic that finding their maxima did not: the drawn points only need to be
// close, and exact walks on flat samples cost ~20 ms each (10^5 bunny-mesh
// points: 127 s instead of 3 s, when a loose drawn point forced them).
void CheckDrawingAddsNoExactWalks()
{
  const std::vector<Point3> flat = clouds::Icosahedron(3000, 41);
  BuildOptions draw, count;
  draw.StableManifolds = count.StableManifolds = false;
  draw.UnstableManifolds = true;
  count.UnstableManifolds = false;
  const FlowComplex drawn = BuildFlowComplex(flat, draw, Progress());
  const FlowComplex counted = BuildFlowComplex(flat, count, Progress());
  CHECK(counted.Report.ExactFallbacks > 0); // the cloud does need exact walks
  CHECK(drawn.Report.ExactFallbacks == counted.Report.ExactFallbacks);
  CHECK(!drawn.FlowLines.empty());
  std::set<std::pair<Id, Id>> drawnEnds, arcs;
  for (const FlowLine& line : drawn.FlowLines)
  {
    drawnEnds.insert({ line.Node, line.Target });
  }
  for (const Arc& a : counted.Arcs)
  {
    if (counted.Nodes[a.Lower].Index == 2)
    {
      arcs.insert({ a.Lower, a.Upper });
    }
  }
  CHECK(drawnEnds == arcs); // each drawn line ends where its 2-3 arc says
}

/// Triangulation::Link skips repeats by where they can be in the cycle of link
/// vertices, not by a search: against CGAL's own incident cells, every finite
/// edge's link is each finite vertex of its cells once, and each recorded cell
/// holds its facet.
void CheckLinks(const std::string& name, const Cloud& cloud)
{
  const Triangulation tri(cloud);
  const Delaunay& dt = tri.Dt();
  std::size_t edges = 0;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
  {
    const VertexHandle a = e->first->vertex(e->second), b = e->first->vertex(e->third);
    std::set<Id> expected;
    auto start = dt.incident_cells(*e), c = start;
    do
    {
      for (int k = 0; k < 4; ++k)
      {
        const VertexHandle w = c->vertex(k);
        if (w != a && w != b && !dt.is_infinite(w))
        {
          expected.insert(w->info());
        }
      }
    } while (++c != start);
    std::vector<Id> link;
    std::vector<CellHandle> cells;
    // With and without a hint: the circulation then starts elsewhere.
    for (const CellHandle hint : { CellHandle(), CellHandle(e->first) })
    {
      link.clear();
      cells.clear();
      CHECK(tri.Link(a->info(), b->info(), link, &cells, hint));
      CHECK(link.size() == expected.size() && cells.size() == link.size());
      CHECK(std::set<Id>(link.begin(), link.end()) == expected);
      for (std::size_t k = 0; k < link.size() && k < cells.size(); ++k)
      {
        CHECK(cells[k]->has_vertex(a) && cells[k]->has_vertex(b) &&
          cells[k]->has_vertex(tri.Vertex(link[k])));
      }
    }
    ++edges;
  }
  CHECK(edges > cloud.size());
  std::cout << name << ": links of " << edges << " edges checked\n";
}

int main()
{
  CheckLinks("cube", Cube(2000, 51));
  CheckLinks("exact grid", Grid(6, 0, 0));
  CheckLinks("cospherical", Cospherical());
  CheckLinks("sphere", Sphere(1500, 52));
  CheckDrawingAddsNoExactWalks();
  CheckDataModel();
  CheckProfileJumps();
  for (std::uint64_t seed = 1; seed <= 6; ++seed)
  {
    CheckComplex("cube " + std::to_string(seed), Cube(20 + 40 * static_cast<int>(seed), seed), true);
    CheckComplex("sphere " + std::to_string(seed), Sphere(30 + 50 * static_cast<int>(seed), seed), true);
    CheckComplex("torus " + std::to_string(seed), Torus(60 * static_cast<int>(seed), seed), true);
  }
  CheckComplex("cube 5000", Cube(5000, 7), false);
  CheckComplex("torus 8000", Torus(8000, 8), false);
  for (const int k : { 700, -700, 250, -1000 })
    CheckScaleInvariance(Cube(300, 31), k);
  CheckExactAgreement("cube", Cube(400, 21));
  CheckExactAgreement("torus", Torus(600, 22));
  CheckExactAgreement("jittered grid", Grid(5, 1e-3, 23));
  CheckComplex("jittered grid", Grid(6, 1e-3, 9), true);
  CheckComplex("exact grid", Grid(5, 0, 0), true);
  const FlowComplex grid = BuildFlowComplex(Grid(4, 0, 0), BuildOptions(), Progress());
  CHECK(grid.Report.Perturbed() && grid.Report.RightAngles > 0);
  CheckComplex("cospherical", Cospherical(), true);
  const Cloud dup = WithDuplicates(Sphere(100, 11));
  CheckComplex("duplicates", dup, true);
  const FlowComplex fd = BuildFlowComplex(dup, BuildOptions(), Progress());
  CHECK(fd.Report.DuplicatePoints == 34 && fd.CountByIndex()[0] == 100);
  return check::Finish("TestCoreInvariants");
}
