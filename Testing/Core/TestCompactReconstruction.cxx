// The compact output (Delaunay simplices on the samples) on clouds whose answer
// is known without it: the icosahedron's 20 faces; configuration D of
// docs/algorithm.md §8.3, whose walk crosses one more Delaunay triangle; and
// reconstructions of a quasi-uniform sphere and torus, which must come out as
// closed 2-manifolds (each edge in exactly two triangles) of Euler
// characteristic 2 and 0, counted here from the cells; at t_r = inf, the
// complement of an open cell (contractible); and each patch alone, whose
// Delaunay triangles must have the Betti numbers of its exact stable manifold;
// and the selection, for each t_r, from the pieces prepared once for T_max.
#include "Check.h"
#include "Clouds.h"
#include "ReconFixtures.h"

#include "CellHomology.h"
#include "CompactFamily.h"
#include "CompactReconstruction.h"
#include "FlowComplexBuilder.h"
#include "Progress.h"
#include "Reconstruction.h"
#include "Retriangulation.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace
{
using namespace flowrecon;

using fixtures::Build;
using fixtures::Built;

using fixtures::ReconstructionNodes;

/// Checks that the cells are a closed 2-manifold surface (triangles only, each
/// edge in exactly two, the link of every vertex one cycle) of Euler
/// characteristic `chi`, connected.
void CheckClosedSurface(const CompactComplex& c, Id chi, const std::string& name)
{
  std::cout << "-- " << name << ": " << c.Triangles.size() << " triangles, "
            << c.SharedTriangles << " shared, " << c.RevisitedTriangles << " revisited\n";
  CHECK(c.Tetrahedra.empty());
  CHECK(c.Edges.empty());
  CHECK(c.Vertices.empty());
  std::map<std::array<Id, 2>, int> edges;
  std::map<Id, std::vector<std::array<Id, 2>>> links;
  for (const std::array<Id, 3>& t : c.Triangles)
  {
    CHECK(t[0] < t[1] && t[1] < t[2]);
    ++edges[{ { t[0], t[1] } }];
    ++edges[{ { t[0], t[2] } }];
    ++edges[{ { t[1], t[2] } }];
    links[t[0]].push_back({ { t[1], t[2] } });
    links[t[1]].push_back({ { t[0], t[2] } });
    links[t[2]].push_back({ { t[0], t[1] } });
  }
  Id notTwo = 0;
  for (const auto& e : edges)
  {
    notTwo += e.second == 2 ? 0 : 1;
  }
  CHECK(notTwo == 0);
  // The link of a vertex of a closed surface is one cycle: its edges form a
  // connected graph in which every vertex has degree 2.
  Id badLinks = 0;
  for (const auto& l : links)
  {
    std::map<Id, std::vector<Id>> adjacent;
    for (const std::array<Id, 2>& e : l.second)
    {
      adjacent[e[0]].push_back(e[1]);
      adjacent[e[1]].push_back(e[0]);
    }
    bool ok = std::all_of(adjacent.begin(), adjacent.end(),
      [](const auto& a) { return a.second.size() == 2; });
    std::set<Id> seen{ adjacent.begin()->first };
    std::vector<Id> stack{ adjacent.begin()->first };
    while (!stack.empty())
    {
      const Id v = stack.back();
      stack.pop_back();
      for (const Id w : adjacent[v])
      {
        if (seen.insert(w).second)
        {
          stack.push_back(w);
        }
      }
    }
    badLinks += ok && seen.size() == adjacent.size() ? 0 : 1;
  }
  CHECK(badLinks == 0);
  const Id v = static_cast<Id>(links.size()), e = static_cast<Id>(edges.size()),
           f = static_cast<Id>(c.Triangles.size());
  std::cout << "   V - E + F = " << v << " - " << e << " + " << f << " = " << v - e + f
            << ", edges not in two triangles " << notTwo << ", bad vertex links " << badLinks << "\n";
  CHECK(v - e + f == chi);
  CHECK(c.SharedTriangles == 0);
}

/// Regular icosahedron (cospherical: a perturbed run): below the circumradius
/// of the sphere (1.902) and above that of a face (1.155), the nodes are its
/// vertices, edges and faces, so the compact complex is its 20 faces, the
/// triples of vertices at mutual distance 2.
void Icosahedron()
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point3> p;
  for (const double a : { -1.0, 1.0 })
    for (const double b : { -t, t })
    {
      p.push_back({ { 0, a, b } });
      p.push_back({ { a, b, 0 } });
      p.push_back({ { b, 0, a } });
    }
  Built b = Build(p);
  CHECK(b.Complex.Report.Perturbed());
  std::vector<Id> selected;
  for (std::size_t i = 0; i < b.Complex.Nodes.size(); ++i)
  {
    if (b.Complex.Nodes[i].Value < 1.5)
    {
      selected.push_back(static_cast<Id>(i));
    }
  }
  const CompactComplex c = CompactReconstruction(*b.Re, b.Complex.Nodes, selected);
  std::set<std::array<Id, 3>> faces;
  auto d2 = [&](Id i, Id j) {
    double s = 0;
    for (int k = 0; k < 3; ++k)
      s += (p[i][k] - p[j][k]) * (p[i][k] - p[j][k]);
    return s;
  };
  for (Id i = 0; i < 12; ++i)
    for (Id j = i + 1; j < 12; ++j)
      for (Id k = j + 1; k < 12; ++k)
        if (std::abs(d2(i, j) - 4) < 1e-9 && std::abs(d2(i, k) - 4) < 1e-9 &&
          std::abs(d2(j, k) - 4) < 1e-9)
          faces.insert({ { i, j, k } });
  CHECK(faces.size() == 20);
  CHECK((std::set<std::array<Id, 3>>(c.Triangles.begin(), c.Triangles.end()) == faces));
  CheckClosedSurface(c, 2, "icosahedron");
  CHECK((CompactBettiNumbers(c) == std::array<Id, 4>{ { 1, 0, 1, 0 } }));
  CHECK(c.Betti == CompactBettiNumbers(c));
}

/// Configuration D: the walk of facet (2,3,4) leaves through the Voronoi edge
/// of (0,3,4) (docs/algorithm.md §8.3 D): its compact patch is those two
/// Delaunay triangles, glued along (3,4), with its Gabriel boundary edges.
void ConfigurationD()
{
  const std::vector<Point3> p = { { { -0.9, -0.8, -0.2 } }, { { -0.8, 0.8, -0.9 } },
    { { 0.1, -0.3, 0.7 } }, { { -0.7, -0.3, -0.3 } }, { { -0.5, -1.0, -0.1 } } };
  Built b = Build(p);
  std::vector<Id> selected;
  for (std::size_t i = 0; i < b.Complex.Nodes.size(); ++i)
  {
    if (b.Complex.Nodes[i].Index == 2 && !b.Complex.Nodes[i].IsInfinity())
    {
      selected.push_back(static_cast<Id>(i));
    }
  }
  CHECK(selected.size() == 1);
  const CompactComplex c = CompactReconstruction(*b.Re, b.Complex.Nodes, selected);
  const std::vector<std::array<Id, 3>> expected = { { { 0, 3, 4 } }, { { 2, 3, 4 } } };
  CHECK(c.Triangles == expected);
  CHECK(c.SharedTriangles == 0 && c.RevisitedTriangles == 0);
  CHECK((c.TriangleClaims == std::vector<int>{ 1, 1 }));
  CHECK(c.Edges.empty() && c.Vertices.empty() && c.Tetrahedra.empty());
  // With every node but the maximum at infinity: the Gabriel edge (1,3) and
  // sample 1 hang off the patch; the other Gabriel edges are its sides.
  std::vector<Id> all;
  for (std::size_t i = 0; i < b.Complex.Nodes.size(); ++i)
  {
    all.push_back(static_cast<Id>(i));
  }
  const CompactComplex d = CompactReconstruction(*b.Re, b.Complex.Nodes, all);
  CHECK(d.Triangles == expected);
  CHECK((d.Edges == std::vector<std::array<Id, 2>>{ { { 1, 3 } } }));
  CHECK(d.Vertices.empty());
  CHECK((CompactBettiNumbers(d) == std::array<Id, 4>{ { 1, 0, 0, 0 } }));
  CHECK(d.Betti == CompactBettiNumbers(d));
}

void Reconstructed(const std::string& name, const std::vector<Point3>& p, double tr, Id chi)
{
  Built b = Build(p);
  const CompactComplex c =
    CompactReconstruction(*b.Re, b.Complex.Nodes, ReconstructionNodes(b.Complex, tr));
  CheckClosedSurface(c, chi, name);
  CHECK(c.Betti == CompactBettiNumbers(c));
  std::cout << "   " << static_cast<double>(c.NumberOfCells()) / static_cast<double>(p.size())
            << " cells per sample\n";
}

/// At t_r = inf without simplification the reconstruction holds every finite
/// node: the complement of the stable manifold of the maximum at infinity, an
/// open cell, so contractible (Alexander duality), whatever the cloud.
void Everything(const std::string& name, const std::vector<Point3>& p)
{
  Built b = Build(p);
  const CompactComplex c =
    CompactReconstruction(*b.Re, b.Complex.Nodes, ReconstructionNodes(b.Complex, HUGE_VAL));
  const std::array<Id, 4> betti = CompactBettiNumbers(c);
  std::cout << "-- " << name << " at t_r = inf: " << c.Triangles.size() << " triangles, "
            << c.Tetrahedra.size() << " tetrahedra, " << c.FilledVoids << " voids filled; Betti "
            << betti[0] << " " << betti[1] << " " << betti[2] << "\n";
  CHECK((betti == std::array<Id, 4>{ { 1, 0, 0, 0 } }));
  CHECK(c.Betti == betti);
}

/// Each index-2 node alone: T(c) (its compact triangles) has the Betti
/// numbers of S(c), its exact stable manifold drawn by the builder, both
/// computed by cell homology over their own cells.
void PatchByPatch(const std::string& name, const std::vector<Point3>& p)
{
  BuildOptions options;
  options.UnstableManifolds = false;
  const FlowComplex fc = BuildFlowComplex(p, options, Progress()); // with geometry
  const Built b = Build(p);
  CHECK(b.Complex.Nodes.size() == fc.Nodes.size());
  std::vector<FilteredCells> exact(fc.Nodes.size());
  for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
  {
    exact[fc.TriangleNode[t]].Add(fc.Triangles[t].data(), 3, 0);
  }
  Id patches = 0, differ = 0, revisited = 0, fast = 0;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (fc.Nodes[i].Index != 2 || fc.Nodes[i].IsInfinity())
    {
      continue;
    }
    const CompactComplex c = CompactReconstruction(*b.Re, fc.Nodes, { static_cast<Id>(i) });
    const std::array<Id, 4> s = BettiNumbersBelow(CellBarcode(exact[i]), 1);
    const std::array<Id, 4> t = CompactBettiNumbers(c);
    ++patches;
    differ += s == t ? 0 : 1;
    fast += c.Betti == t ? 0 : 1;
    revisited += c.RevisitedTriangles > 0 ? 1 : 0;
    if (s != t)
    {
      std::cout << "   node " << i << ": S(c) " << s[0] << " " << s[1] << " " << s[2] << ", T(c) "
                << t[0] << " " << t[1] << " " << t[2] << ", " << c.Triangles.size()
                << " triangles, " << c.RevisitedTriangles << " revisited\n";
    }
  }
  std::cout << "-- " << name << ": " << patches << " patches, " << differ
            << " of other Betti numbers than S(c), " << revisited << " with a triangle crossed twice\n";
  CHECK(patches > 0);
  CHECK(differ == 0);
  CHECK(fast == 0); // Euler characteristic and duality against cell homology
}

/// Whether two compact complexes hold the same cells, nodes and counts.
bool SameComplex(const CompactComplex& a, const CompactComplex& b)
{
  return a.Vertices == b.Vertices && a.VertexNode == b.VertexNode && a.Edges == b.Edges &&
    a.EdgeNode == b.EdgeNode && a.Triangles == b.Triangles && a.TriangleNode == b.TriangleNode &&
    a.TriangleClaims == b.TriangleClaims && a.Tetrahedra == b.Tetrahedra &&
    a.TetrahedronNode == b.TetrahedronNode && a.SharedTriangles == b.SharedTriangles &&
    a.RevisitedTriangles == b.RevisitedTriangles && a.FilledVoids == b.FilledVoids &&
    a.Voids == b.Voids && a.Betti == b.Betti && a.ExactFallbacks == b.ExactFallbacks;
}

/// The compact output's passes over a solid run in parallel, block by block:
/// on all cores they must give what one thread gives, cell for cell (a
/// solid of several blocks, and its filled voids).
void OneThreadAgrees(const std::string& name, const std::vector<Point3>& p)
{
  Built b = Build(p);
  const std::vector<Id> selected = ReconstructionNodes(b.Complex, HUGE_VAL);
  const CompactComplex all = CompactReconstruction(*b.Re, b.Complex.Nodes, selected);
  CompactComplex one;
  tbb::task_arena(1).execute([&] { one = CompactReconstruction(*b.Re, b.Complex.Nodes, selected); });
  std::cout << "-- " << name << ": " << all.Tetrahedra.size() << " tetrahedra, "
            << all.FilledVoids << " voids filled, on " << tbb::this_task_arena::max_concurrency()
            << " threads and on one\n";
  CHECK(all.Tetrahedra.size() > 2 * 4096);
  CHECK(SameComplex(all, one));
}

/// The family a filter keeps (CompactFamily, its void ranges from one sweep)
/// gives, at every threshold where the reconstruction changes and between
/// them (every one for `tries` 0, else about `tries`), the complex computed from scratch for
/// the nodes in there, and the thresholds of those nodes only. Returns the
/// voids it filled.
Id FamilyAgrees(const Built& b, double tmax, std::size_t tries)
{
  const FlowComplex& fc = b.Complex;
  const std::vector<bool> all(fc.Nodes.size(), true);
  const std::vector<Id> init =
    InitializationEdges(fc.Nodes, NearestNeighboursFromDiagram(fc.Nodes, fc.Arcs));
  const ReconstructionResult run = Reconstruct(fc.Nodes, fc.Arcs, all, init, HUGE_VAL, Progress());
  const std::vector<Id> carriers = CellCarriers(run, nullptr);
  const CompactFamily family(fc, carriers, run, tmax, nullptr, Progress(), "");
  // The thresholds themselves (a node enters just above its own), and midpoints.
  std::vector<double> steps;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (carriers[i] >= 0 && run.Contains(carriers[i], tmax))
    {
      steps.push_back(run.Nodes[carriers[i]].Threshold);
    }
  }
  std::sort(steps.begin(), steps.end());
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  std::vector<double> ts;
  const std::size_t stride = tries == 0 ? 1 : std::max<std::size_t>(1, steps.size() / tries);
  for (std::size_t k = 0; k < steps.size(); k += stride)
  {
    ts.push_back(steps[k]);
    ts.push_back(k + 1 < steps.size() ? 0.5 * (steps[k] + steps[k + 1]) : tmax);
  }
  Id filled = 0;
  int same = 0;
  for (const double t : ts)
  {
    std::vector<Id> selected;
    for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
    {
      if (carriers[i] >= 0 && run.Contains(carriers[i], t))
      {
        selected.push_back(static_cast<Id>(i));
      }
    }
    const CompactComplex fresh = CompactReconstruction(*b.Re, fc.Nodes, selected);
    std::vector<double> thresholds;
    CompactComplex kept = family.At(t, thresholds);
    CHECK(kept.Voids == 0);
    // The thresholds it hands the VTK conversion in the triangles' order.
    CHECK(kept.TriangleThreshold.size() == kept.Triangles.size());
    for (std::size_t k = 0; k < kept.Triangles.size(); ++k)
    {
      CHECK(kept.TriangleThreshold[k] == thresholds[kept.TriangleNode[k]]);
    }
    kept.Voids = fresh.Voids;
    kept.Betti = fresh.Betti;
    same += SameComplex(fresh, kept) ? 1 : 0;
    filled += kept.FilledVoids;
    std::set<Id> asked(selected.begin(), selected.end());
    // Exactly the nodes in at t (but the maximum at infinity, which has no
    // cell), each with its carrier's threshold.
    CHECK(thresholds.size() == fc.Nodes.size());
    for (std::size_t i = 0; i < thresholds.size(); ++i)
    {
      const bool in = asked.count(static_cast<Id>(i)) == 1 && !fc.Nodes[i].IsInfinity();
      CHECK(in ? thresholds[i] == run.Nodes[carriers[i]].Threshold : std::isnan(thresholds[i]));
    }
  }
  std::cout << "   the family: " << same << " of " << ts.size()
            << " thresholds give the complex computed anew; " << filled << " voids filled\n";
  CHECK(same == static_cast<int>(ts.size()));
  return filled;
}

/// The pieces of the reconstruction at T (what a filter keeps) give, for every
/// t_r <= T, the complex computed from scratch for the nodes at t_r, and
/// nothing but the nodes asked for, read from the triangulation or from the
/// table of its cells (CellsOf).
Id SelectedFromPieces(const std::string& name, const std::vector<Point3>& p, double tmax)
{
  const Built b = Build(p);
  const CompactPieces pieces =
    PrepareCompact(*b.Re, b.Complex.Nodes, ReconstructionNodes(b.Complex, tmax));
  // The table of cells a family keeps instead of the triangulation.
  const CompactCells table = CellsOf(*b.Re);
  int same = 0, tried = 0;
  Id cells = 0;
  for (const double tr : { 1.2, 1.6, 2.0, 2.5, 3.0, tmax })
  {
    const std::vector<Id> selected = ReconstructionNodes(b.Complex, tr);
    const CompactComplex fresh = CompactReconstruction(*b.Re, b.Complex.Nodes, selected);
    const CompactComplex chosen = SelectCompact(*b.Re, b.Complex.Nodes, pieces, selected);
    // Without the Betti numbers (a filter's t_r change) the void searches end
    // at their first maximum: the cells must not change.
    CompactComplex quick = SelectCompact(table, b.Complex.Nodes, pieces, selected, false);
    CHECK(SameComplex(SelectCompact(table, b.Complex.Nodes, pieces, selected), chosen));
    CHECK(quick.Betti == (std::array<Id, 4>{ { 0, 0, 0, 0 } }));
    quick.Voids = fresh.Voids;
    quick.Betti = fresh.Betti;
    ++tried;
    same += SameComplex(fresh, chosen) && SameComplex(fresh, quick) ? 1 : 0;
    CHECK(fresh.NumberOfCells() >= cells); // the family grows with t_r
    cells = fresh.NumberOfCells();
    std::set<Id> asked(selected.begin(), selected.end());
    for (const Id node : chosen.TriangleNode)
    {
      CHECK(asked.count(node) == 1);
    }
  }
  std::cout << "-- " << name << ": " << same << " of " << tried
            << " selections equal to the complex computed anew; " << cells << " cells at T\n";
  CHECK(same == tried);
  CHECK(cells > 0);
  return FamilyAgrees(b, tmax, 40);
}

/// The cells on the two sides of a claim's triangle, in either order: a walk
/// names a triangle by whichever of its cells the link cache gave.
std::set<std::pair<std::int32_t, int>> SidesOf(const CompactClaim& c)
{
  return { { c.Cells[0], c.Cells[0] < 0 ? 0 : c.Facets[0] }, { c.Cells[1], c.Cells[1] < 0 ? 0 : c.Facets[1] } };
}

/// A build that records its patches' walks (BuildOptions::RecordWalks) gives
/// the compact pieces and output of a build that does not, which walks them
/// again: at several t_r, with patches deferred (walked late, not recorded)
/// or not.
void RecordedWalksAgree(const std::string& name, const std::vector<Point3>& p, double defer)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  options.DeferPatchesAboveRatio = defer;
  Built plain, recorded;
  plain.Complex = BuildFlowComplex(p, options, Progress(), &plain.Re);
  options.RecordWalks = true;
  recorded.Complex = BuildFlowComplex(p, options, Progress(), &recorded.Re);
  CHECK(plain.Re->Walks().Known.empty());
  const RecordedWalks& walks = recorded.Re->Walks();
  const std::size_t facets = recorded.Re->Critical().Facets.size();
  std::size_t known = 0;
  for (std::size_t f = 0; f < facets; ++f)
  {
    known += walks.Has(f) ? 1 : 0;
  }
  // Every patch the build walked is recorded, and no deferred one.
  CHECK(known + recorded.Complex.DeferredPatches.size() == facets);
  CHECK(known > 0);
  // The pieces themselves, with the cells on each side of every triangle.
  const std::vector<Id> all = ReconstructionNodes(recorded.Complex, HUGE_VAL);
  const CompactPieces walked = PrepareCompact(*plain.Re, plain.Complex.Nodes, all);
  const CompactPieces replayed = PrepareCompact(*recorded.Re, recorded.Complex.Nodes, all);
  bool samePieces = walked.Claims.size() == replayed.Claims.size() &&
    walked.ExactFallbacks == replayed.ExactFallbacks;
  for (std::size_t k = 0; samePieces && k < walked.Claims.size(); ++k)
  {
    const CompactClaim& a = walked.Claims[k];
    const CompactClaim& b = replayed.Claims[k];
    samePieces = a.Triangle == b.Triangle && a.Node == b.Node && SidesOf(a) == SidesOf(b);
  }
  CHECK(samePieces);
  int same = 0, tried = 0;
  for (const double tr : { 1.5, 2.0, 3.0, HUGE_VAL })
  {
    ++tried;
    const std::vector<Id> selected = ReconstructionNodes(recorded.Complex, tr);
    same += SameComplex(CompactReconstruction(*plain.Re, plain.Complex.Nodes, selected),
              CompactReconstruction(*recorded.Re, recorded.Complex.Nodes, selected))
      ? 1
      : 0;
  }
  std::cout << "-- " << name << ": " << known << " of " << facets << " patches recorded, "
            << walks.Codes.size() << " triangles; the pieces "
            << (samePieces ? "equal" : "differ from") << " those walked again, and " << same
            << " of " << tried << " compact outputs\n";
  CHECK(same == tried);
}

} // namespace

int main()
{
  Icosahedron();
  ConfigurationD();
  Reconstructed("Fibonacci sphere, 600 points, t_r 2", fixtures::FibonacciSphere(600, 3), 2, 2);
  Reconstructed("grid torus, 80 x 28 points, t_r 2", fixtures::GridTorus(80, 4), 2, 0);
  Everything("cube, 2000 i.i.d. points", clouds::Cube(2000, 5));
  Everything("sphere, 2000 i.i.d. points", clouds::Sphere(2000, 6));
  Everything("torus, 3000 i.i.d. points", clouds::Torus(3000, 7));
  OneThreadAgrees("cube, 2000 i.i.d. points", clouds::Cube(2000, 5));
  OneThreadAgrees("torus, 3000 i.i.d. points", clouds::Torus(3000, 7));
  PatchByPatch("cube, 1500 i.i.d. points", clouds::Cube(1500, 8));
  PatchByPatch("torus, 1500 i.i.d. points", clouds::Torus(1500, 9));
  // The family's void ranges must be met: some of these fill voids.
  Id filled = SelectedFromPieces("torus, 3000 i.i.d. points", clouds::Torus(3000, 10), 4);
  filled += SelectedFromPieces("cube, 2000 i.i.d. points", clouds::Cube(2000, 11), 4);
  CHECK(filled > 0);
  // Every threshold where a small cube's reconstruction changes: a void's
  // range starts and ends at one of them.
  std::cout << "-- cube, 600 i.i.d. points, and torus, 800, every threshold:\n";
  CHECK(FamilyAgrees(Build(clouds::Cube(600, 15)), 4, 0) +
      FamilyAgrees(Build(clouds::Torus(800, 15)), 4, 0) > 0);
  // The walks the build records stand for the compact output's own.
  RecordedWalksAgree("cube, 1500 i.i.d. points", clouds::Cube(1500, 21), HUGE_VAL);
  RecordedWalksAgree("torus, 2000 i.i.d. points, far patches deferred", clouds::Torus(2000, 22), 1.0);
  RecordedWalksAgree("grid of 6^3 points (cospherical ties)", clouds::Grid(6, 0, 23), HUGE_VAL);
  return check::Finish("TestCompactReconstruction");
}
