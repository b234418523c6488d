// The fast persistence (union-find for H0, union-find on the dual graph for H2,
// column reduction with clearing for H1) against the plain column reduction of the
// whole boundary matrix, pair by pair (dimension, birth and death nodes, values):
// on the flow complexes of random, surface, grid, tiny, duplicated, degenerate and
// non-manifold clouds; on the same complexes with values coarsened to a few levels
// and node ids shuffled (ties everywhere: the tie rules by value, then index, then
// node id must be the reference's); with values shuffled at random (not a
// filtration any more, still the same matrix reduction); on simplified complexes;
// and on broken inputs the fast path must hand to the reference.
#include "Check.h"
#include "Clouds.h"

#include "FlowComplexBuilder.h"
#include "Persistence.h"
#include "Simplification.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

using Cloud = std::vector<Point3>;
using clouds::Cospherical;
using clouds::Grid;
using clouds::Rng;
using clouds::WithDuplicates;

int Compared = 0;
int Grouped = 0; // comparisons where the arcs into each index-2 node were consecutive

/// Runs both and checks that the pairs are the same, in the same order.
void Compare(const std::string& label, const std::vector<Node>& nodes,
  const std::vector<Arc>& arcs, bool expectFast)
{
  PersistenceReport report;
  const std::vector<PersistencePair> fast = ComputePersistence(nodes, arcs, &report);
  const std::vector<PersistencePair> ref = ComputePersistenceByReduction(nodes, arcs);
  ++Compared;
  Grouped += report.GroupedArcs ? 1 : 0;
  if (report.FastPath != expectFast)
  {
    std::cout << label << ": the fast path was " << (report.FastPath ? "" : "not ")
              << "taken\n";
    ++check::Failures();
  }
  if (fast.size() != ref.size())
  {
    std::cout << label << ": " << fast.size() << " pairs, the reduction has " << ref.size()
              << "\n";
    ++check::Failures();
    return;
  }
  for (std::size_t i = 0; i < ref.size(); ++i)
  {
    const PersistencePair& a = fast[i];
    const PersistencePair& b = ref[i];
    if (a.Dimension != b.Dimension || a.Birth != b.Birth || a.Death != b.Death ||
      a.BirthValue != b.BirthValue || a.DeathValue != b.DeathValue)
    {
      std::cout << label << ": pair " << i << " is (dim " << a.Dimension << ", " << a.Birth
                << " -> " << a.Death << ", " << a.BirthValue << " -> " << a.DeathValue
                << "), the reduction has (dim " << b.Dimension << ", " << b.Birth << " -> "
                << b.Death << ", " << b.BirthValue << " -> " << b.DeathValue << ")\n";
      ++check::Failures();
      return;
    }
  }
}

FlowComplex Build(const Cloud& c)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  return BuildFlowComplex(c, options, Progress());
}

/// Values floored to `levels` levels of the largest finite value: still a
/// filtration (flooring is monotone), with many ties across and within indices.
std::vector<Node> Coarsened(std::vector<Node> nodes, int levels)
{
  double top = 0;
  for (const Node& x : nodes)
  {
    if (!x.IsInfinity())
    {
      top = std::max(top, x.Value);
    }
  }
  for (Node& x : nodes)
  {
    if (!x.IsInfinity() && top > 0)
    {
      x.Value = std::floor(x.Value / top * levels) / levels * top;
    }
  }
  return nodes;
}

/// The same complex with the node ids permuted (the maximum at infinity too) and
/// the arcs in random order.
void Shuffled(const std::vector<Node>& nodes, const std::vector<Arc>& arcs, std::uint64_t seed,
  std::vector<Node>& outNodes, std::vector<Arc>& outArcs)
{
  Rng r(seed);
  std::vector<Id> to(nodes.size());
  std::iota(to.begin(), to.end(), 0);
  for (std::size_t i = to.size(); i > 1; --i)
  {
    std::swap(to[i - 1], to[static_cast<std::size_t>(r.U() * static_cast<double>(i))]);
  }
  outNodes.assign(nodes.size(), Node());
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    outNodes[to[i]] = nodes[i];
  }
  outArcs.clear();
  for (const Arc& a : arcs)
  {
    outArcs.emplace_back(to[a.Lower], to[a.Upper], a.Multiplicity);
  }
  // Arcs in random order too: nothing may depend on it.
  for (std::size_t i = outArcs.size(); i > 1; --i)
  {
    std::swap(outArcs[i - 1], outArcs[static_cast<std::size_t>(r.U() * static_cast<double>(i))]);
  }
}

/// Values drawn at random from a few levels around 0, ignoring the arcs; zeros
/// are +0 or -0 (equal values).
std::vector<Node> RandomValues(std::vector<Node> nodes, int levels, std::uint64_t seed)
{
  Rng r(seed);
  for (Node& x : nodes)
  {
    if (!x.IsInfinity())
    {
      x.Value = std::floor(r.U() * levels) - levels / 2;
      if (x.Value == 0 && r.U() < 0.5)
      {
        x.Value = -0.0;
      }
    }
  }
  return nodes;
}

/// The surviving part of a simplified complex, renumbered.
void Simplified(const FlowComplex& fc, double threshold, std::vector<Node>& kept,
  std::vector<Arc>& mapped)
{
  const SimplificationResult s = Simplify(fc.Nodes, fc.Arcs, threshold, Progress());
  std::vector<Id> newId(fc.Nodes.size(), -1);
  kept.clear();
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (s.Survives[i])
    {
      newId[i] = static_cast<Id>(kept.size());
      kept.push_back(fc.Nodes[i]);
    }
  }
  mapped.clear();
  for (const Arc& a : s.Arcs)
  {
    mapped.emplace_back(newId[a.Lower], newId[a.Upper], a.Multiplicity);
  }
}

void CheckComplex(const std::string& label, const FlowComplex& fc, std::uint64_t seed)
{
  Compare(label, fc.Nodes, fc.Arcs, true);
  for (const int levels : { 3, 40 })
  {
    std::vector<Node> nodes;
    std::vector<Arc> arcs;
    const std::string tag = label + ", values on " + std::to_string(levels) + " levels";
    Compare(tag, Coarsened(fc.Nodes, levels), fc.Arcs, true);
    Shuffled(Coarsened(fc.Nodes, levels), fc.Arcs, seed, nodes, arcs);
    Compare(tag + ", ids shuffled", nodes, arcs, true);
  }
  Compare(label + ", random values", RandomValues(fc.Nodes, 5, seed), fc.Arcs, true);
  std::vector<Node> kept;
  std::vector<Arc> mapped;
  for (const double tp : { 1.1, 2.0 })
  {
    Simplified(fc, tp, kept, mapped);
    Compare(label + ", simplified at t_p " + std::to_string(tp), kept, mapped, true);
  }
}

/// Broken inputs: the fast path must see them and give the reference's answer.
void CheckFallbacks(const FlowComplex& fc)
{
  std::vector<Id> index2, index3;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (!fc.Nodes[i].IsInfinity() && fc.Nodes[i].Index == 2)
      index2.push_back(static_cast<Id>(i));
    if (!fc.Nodes[i].IsInfinity() && fc.Nodes[i].Index == 3)
      index3.push_back(static_cast<Id>(i));
  }
  // An index-2 node with three finite upper ends.
  {
    std::vector<Arc> arcs = fc.Arcs;
    for (const Id s : index3)
      arcs.emplace_back(index2.front(), s, 1);
    Compare("three maxima above an index-2 node", fc.Nodes, arcs, false);
  }
  // A repeated arc.
  {
    std::vector<Arc> arcs = fc.Arcs;
    for (const Arc& a : fc.Arcs)
    {
      if (fc.Nodes[a.Lower].Index == 1 && a.Multiplicity % 2 == 1)
      {
        arcs.push_back(a);
        break;
      }
    }
    Compare("a repeated 1->2 arc", fc.Nodes, arcs, false);
  }
  // An arc that skips an index.
  {
    std::vector<Arc> arcs = fc.Arcs;
    arcs.emplace_back(arcs.front().Lower, index2.front(), 1);
    Compare("a 0->2 arc", fc.Nodes, arcs, false);
  }
  // An arc to a node that does not exist: an error, not undefined behaviour.
  {
    std::vector<Arc> arcs = fc.Arcs;
    arcs.emplace_back(0, static_cast<Id>(fc.Nodes.size()), 1);
    bool thrown = false;
    try
    {
      ComputePersistence(fc.Nodes, arcs);
    }
    catch (const std::out_of_range&)
    {
      thrown = true;
    }
    CHECK(thrown);
  }
  // Boundary of boundary not zero: a 1->2 arc, then a finite 2->3 arc, left out.
  for (const int lower : { 1, 2 })
  {
    std::vector<Arc> arcs;
    bool removed = false;
    for (const Arc& a : fc.Arcs)
    {
      if (!removed && fc.Nodes[a.Lower].Index == lower && !fc.Nodes[a.Upper].IsInfinity() &&
        a.Multiplicity == 1)
      {
        removed = true;
        continue;
      }
      arcs.push_back(a);
    }
    Compare("boundary of boundary not zero (" + std::to_string(lower) + "->" +
        std::to_string(lower + 1) + " arc left out)",
      fc.Nodes, arcs, false);
  }
}

/// A sphere, a segment through it and beyond, and a square sheet touching it: a
/// solid-less non-manifold mix of a surface, a curve and a second surface.
Cloud NonManifold(int n, std::uint64_t seed)
{
  Rng r(seed);
  Cloud c = clouds::Sphere(n, seed);
  for (int i = 0; i < n / 4; ++i)
    c.push_back({ { -2 + 4 * r.U(), 1e-3 * r.U(), 1e-3 * r.U() } });
  for (int i = 0; i < n / 2; ++i)
    c.push_back({ { 1 + 1.5 * r.U(), -0.75 + 1.5 * r.U(), 0.5 + 1e-3 * r.U() } });
  return c;
}

/// Two spheres touching at a point, and a helix around them.
Cloud Bouquet(int n, std::uint64_t seed)
{
  Rng r(seed);
  Cloud c = clouds::Sphere(n, seed);
  for (const Point3& p : clouds::Sphere(n, seed + 1))
    c.push_back({ { p[0] + 2, p[1], p[2] } });
  for (int i = 0; i < n / 2; ++i)
  {
    const double t = 6 * M_PI * r.U();
    c.push_back({ { 1 + 0.5 * t / M_PI - 1.5, 1.5 * std::cos(t), 1.5 * std::sin(t) } });
  }
  return c;
}

} // namespace

int main()
{
  struct Case
  {
    std::string Label;
    Cloud Points;
  };
  std::vector<Case> cases;
  for (int n = 4; n <= 10; ++n)
    for (std::uint64_t seed = 1; seed <= 4; ++seed)
      cases.push_back({ "cube n=" + std::to_string(n) + " seed " + std::to_string(seed),
        clouds::Cube(n, 100 * n + seed) });
  cases.push_back({ "regular tetrahedron",
    { { { 1, 1, 1 } }, { { 1, -1, -1 } }, { { -1, 1, -1 } }, { { -1, -1, 1 } } } });
  cases.push_back({ "cube corners", Grid(2, 0, 1) });
  for (const int n : { 50, 200, 1000, 3000, 20000 })
    cases.push_back({ "cube n=" + std::to_string(n), clouds::Cube(n, 7 + n) });
  for (const int n : { 100, 500, 2000 })
    cases.push_back({ "sphere n=" + std::to_string(n), clouds::Sphere(n, 11 + n) });
  for (const int n : { 300, 1000, 4000 })
    cases.push_back({ "torus n=" + std::to_string(n), clouds::Torus(n, 13 + n) });
  cases.push_back({ "grid 4^3 exact (perturbed by the builder)", Grid(4, 0, 1) });
  cases.push_back({ "grid 5^3 jitter 1e-3", Grid(5, 1e-3, 2) });
  cases.push_back({ "grid 8^3 jitter 0.2", Grid(8, 0.2, 3) });
  cases.push_back({ "cospherical integer points", Cospherical() });
  cases.push_back({ "cube n=300 with duplicates", WithDuplicates(clouds::Cube(300, 5)) });
  cases.push_back({ "torus n=600 with duplicates", WithDuplicates(clouds::Torus(600, 6)) });
  cases.push_back({ "non-manifold: sphere, segment, sheet", NonManifold(800, 21) });
  cases.push_back({ "non-manifold: two touching spheres and a helix", Bouquet(600, 22) });

  std::uint64_t seed = 1000;
  for (const Case& c : cases)
  {
    CheckComplex(c.Label, Build(c.Points), ++seed);
  }
  CheckFallbacks(Build(clouds::Cube(200, 3)));

  // The fast path must actually do H1 work on a large cloud (not vacuous).
  {
    PersistenceReport report;
    const FlowComplex fc = Build(clouds::Cube(20000, 5));
    ComputePersistence(fc.Nodes, fc.Arcs, &report);
    CHECK(report.FastPath);
    CHECK(report.ColumnAdditions > 0);
    std::cout << "cube n=20000: " << report.ReducedColumns << " H1 columns reduced, "
              << report.ColumnAdditions << " column additions\n";
  }
  // Both ways of gathering the faces of index-2 nodes were compared.
  std::cout << Compared << " comparisons, " << Grouped << " with grouped arcs\n";
  CHECK(Grouped > 0);
  CHECK(Grouped < Compared - 5);
  return check::Finish("TestPersistence");
}
