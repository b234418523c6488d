// Geometry on demand against the eager construction (its oracle): the stable
// manifolds drawn later from a recomputed triangulation, for any set of nodes,
// are the eager ones cell by cell; the cell counts read off the Hasse diagram
// are the walks' counts; a budget draws a prefix of the filtration; a complex
// that is not of these points, or a drawing that does not fit, is refused.
#include "Check.h"
#include "Clouds.h"

#include "FlowComplexBuilder.h"
#include "Progress.h"
#include "StableManifoldGeometry.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace flowrecon;

/// Each node's cells as sorted vertex coordinates, sorted: independent of point
/// numbering and cell order.
std::map<Id, std::vector<std::vector<Point3>>> CellsByNode(const FlowComplex& fc)
{
  std::map<Id, std::vector<std::vector<Point3>>> cells;
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    std::vector<Point3> c;
    for (const Id v : fc.Triangles[t])
    {
      c.push_back(fc.Points[v]);
    }
    std::sort(c.begin(), c.end());
    cells[fc.TriangleNode[t]].push_back(c);
  }
  for (std::size_t t = 0; t < fc.Tetrahedra.size(); ++t)
  {
    std::vector<Point3> c;
    for (const Id v : fc.Tetrahedra[t])
    {
      c.push_back(fc.Points[v]);
    }
    std::sort(c.begin(), c.end());
    cells[fc.TetrahedronNode[t]].push_back(c);
  }
  for (auto& entry : cells)
  {
    std::sort(entry.second.begin(), entry.second.end());
  }
  return cells;
}

void TestCloud(const std::string& name, const std::vector<Point3>& points)
{
  std::cout << "-- " << name << "\n";
  BuildOptions eagerOptions;
  eagerOptions.UnstableManifolds = false;
  const FlowComplex eager = BuildFlowComplex(points, eagerOptions, Progress());
  const auto eagerCells = CellsByNode(eager);

  // Counts from the diagram alone = the eager walks' counts, except that a cone
  // split where its cell meets itself has a few tetrahedra more (extra).
  const std::vector<Id> counts = StableManifoldCellCounts(eager.Nodes, eager.Arcs);
  std::vector<Id> extra(eager.Nodes.size(), 0);
  Id total = 0, wrong = 0, extraTotal = 0;
  for (std::size_t i = 0; i < eager.Nodes.size(); ++i)
  {
    const auto it = eagerCells.find(static_cast<Id>(i));
    const Id actual = it == eagerCells.end() ? 0 : static_cast<Id>(it->second.size());
    if (eager.Nodes[i].IsInfinity())
    {
      continue;
    }
    extra[i] = actual - counts[i];
    wrong += (eager.Nodes[i].Index == 3 ? extra[i] < 0 : extra[i] != 0) ? 1 : 0;
    total += counts[i];
    extraTotal += extra[i];
  }
  CHECK(wrong == 0);
  CHECK(total + extraTotal == static_cast<Id>(eager.Triangles.size() + eager.Tetrahedra.size()));
  CHECK(total > 0 && extraTotal <= total / 20);

  BuildOptions hasseOptions = eagerOptions;
  hasseOptions.StableManifolds = false;
  const FlowComplex hasse = BuildFlowComplex(points, hasseOptions, Progress());
  CHECK(hasse.Triangles.empty() && hasse.Tetrahedra.empty());

  // Every node, then every third node: the same cells as the eager run.
  for (const int stride : { 1, 3 })
  {
    std::vector<Id> draw;
    for (std::size_t i = 0; i < hasse.Nodes.size(); i += stride)
    {
      draw.push_back(static_cast<Id>(i));
    }
    FlowComplex lazy = hasse;
    DrawStableManifolds(points, hasseOptions, draw, lazy, Progress(), "test");
    auto expected = eagerCells;
    for (auto it = expected.begin(); it != expected.end();)
    {
      it = (it->first % stride == 0) ? std::next(it) : expected.erase(it);
    }
    CHECK(CellsByNode(lazy) == expected);
    // The cones' boundaries read from the arcs instead of flow-line roots.
    FlowComplex fromArcs = hasse;
    DrawStableManifolds(points, hasseOptions, draw, fromArcs, Progress(), "test", &hasse.Arcs);
    CHECK(CellsByNode(fromArcs) == expected);
    // Input points keep their ids and coordinates.
    CHECK(std::equal(points.begin(), points.end(), lazy.Points.begin()));
  }

  // A budget draws the longest prefix of the filtration that fits.
  BuildOptions budgetOptions = eagerOptions;
  budgetOptions.MaximumGeometryCells = total / 2;
  const FlowComplex budget = BuildFlowComplex(points, budgetOptions, Progress());
  const auto budgetCells = CellsByNode(budget);
  Id drawnCells = 0, drawnExtra = 0;
  for (const auto& entry : budgetCells)
  {
    CHECK(entry.second == eagerCells.at(entry.first));
    drawnCells += static_cast<Id>(entry.second.size());
    drawnExtra += extra[entry.first];
  }
  CHECK(drawnCells - drawnExtra <= total / 2);
  std::vector<Id> order;
  for (std::size_t i = 0; i < eager.Nodes.size(); ++i)
  {
    if (eager.Nodes[i].Index >= 2 && !eager.Nodes[i].IsInfinity())
    {
      order.push_back(static_cast<Id>(i));
    }
  }
  std::sort(order.begin(), order.end(), [&](Id a, Id b) {
    const Node &x = eager.Nodes[a], &y = eager.Nodes[b];
    return x.Value != y.Value ? x.Value < y.Value : (x.Index != y.Index ? x.Index < y.Index : a < b);
  });
  Id used = 0;
  bool prefix = true, stopped = false;
  for (const Id node : order)
  {
    const bool fits = !stopped && used + counts[node] <= total / 2;
    stopped = !fits;
    used += fits ? counts[node] : 0;
    const bool drawn = budgetCells.count(node) > 0 || counts[node] == 0;
    prefix = prefix && (drawn == fits || (counts[node] == 0 && fits));
  }
  CHECK(prefix);
  CHECK(used == drawnCells - drawnExtra);

  // Not the points of this complex: refused, not silently wrong.
  std::vector<Point3> moved = points;
  moved[moved.size() / 2][0] += 1e-3;
  FlowComplex other = hasse;
  bool refused = false;
  try
  {
    DrawStableManifolds(moved, hasseOptions, { hasse.InfinityNode - 1 }, other, Progress(), "test");
  }
  catch (const InputError&)
  {
    refused = true;
  }
  CHECK(refused);
}

void TestMemoryGuard()
{
  std::cout << "-- memory guard\n";
  const std::vector<Point3> points = clouds::Torus(2000, 5);
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  FlowComplex fc = BuildFlowComplex(points, options, Progress());
  std::vector<Id> all(fc.Nodes.size());
  for (std::size_t i = 0; i < all.size(); ++i)
  {
    all[i] = static_cast<Id>(i);
  }
  setenv("FLOWRECON_MEMORY_LIMIT", "1000", 1); // 1 kB: nothing fits
  std::string message;
  try
  {
    DrawStableManifolds(points, options, all, fc, Progress(), "lower the threshold");
  }
  catch (const InputError& e)
  {
    message = e.what();
  }
  unsetenv("FLOWRECON_MEMORY_LIMIT");
  std::cout << "   " << message << "\n";
  CHECK(message.find("needs about") != std::string::npos);
  CHECK(message.find("lower the threshold") != std::string::npos);
}

} // namespace

int main()
{
  TestCloud("cube", clouds::Cube(400, 1));
  TestCloud("sphere", clouds::Sphere(500, 2));
  TestCloud("torus", clouds::Torus(700, 3));
  {
    // A grid: degenerate, so the complex comes from a perturbed attempt.
    std::vector<Point3> grid;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        for (int k = 0; k < 5; ++k)
          grid.push_back({ { double(i), double(j), double(k) } });
    TestCloud("grid", grid);
  }
  {
    // Non-manifold: a sphere pierced by a segment, with duplicate points, far
    // from the origin and tiny (the builder's power-of-two scaling).
    std::vector<Point3> mix = clouds::Sphere(300, 4);
    for (int i = 0; i < 60; ++i)
    {
      mix.push_back({ { 0.0013 * i, -1.7 + 0.057 * i, 0.0009 * i } });
    }
    mix.push_back(mix[10]);
    mix.push_back(mix[200]);
    for (Point3& p : mix)
    {
      for (double& x : p)
      {
        x = 1e-40 * x + 3e-39;
      }
    }
    TestCloud("sphere and segment, duplicates, scale 1e-40", mix);
  }
  TestMemoryGuard();
  return check::Finish("TestStableManifoldGeometry");
}
