// Fixtures shared by the core's tests of simplification, reconstruction and
// compact output: hand-made Hasse diagrams, quasi-uniform clouds, and small
// helpers over nodes and arcs.
#ifndef flowrecon_ReconFixtures_h
#define flowrecon_ReconFixtures_h

#include "Clouds.h"
#include "FlowComplex.h"
#include "FlowComplexBuilder.h"
#include "Progress.h"
#include "Reconstruction.h"
#include "Retriangulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace fixtures
{
using namespace flowrecon;
using clouds::Rng;
using clouds::Cube;
using clouds::Sphere;
using clouds::Torus;

/// The command line's T_max.
constexpr double CommandLineCap = 5;

/// A build of the Hasse diagram alone, as `reconstruct` makes it.
inline BuildOptions DiagramOnly()
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  return options;
}

/// The flow complex of `points` (the Hasse diagram alone) with the builder's
/// triangulation kept: its classification of the critical simplices, and what
/// the compact output walks.
struct Built
{
  FlowComplex Complex;
  std::unique_ptr<Retriangulation> Re;
};

inline Built Build(const std::vector<Point3>& points)
{
  Built b;
  b.Complex = BuildFlowComplex(points, DiagramOnly(), Progress(), &b.Re);
  return b;
}

inline Node MakeNode(int index, double value, std::array<Id, 4> simplex)
{
  Node n;
  n.Index = index;
  n.Value = value;
  for (int k = 0; k < 4; ++k)
  {
    n.Simplex[k] = static_cast<std::int32_t>(simplex[k]);
  }
  return n;
}

inline Node Sample(Id p) { return MakeNode(0, 0, { { p, -1, -1, -1 } }); }
inline Node Edge(Id p, Id q, double v) { return MakeNode(1, v, { { p, q, -1, -1 } }); }
inline Node Infinity(int index)
{
  return MakeNode(index, HUGE_VAL, { { -1, -1, -1, -1 } });
}

struct Diagram
{
  std::vector<Node> Nodes;
  std::vector<Arc> Arcs;
  void Link(Id lower, Id upper, int multiplicity = 1)
  {
    this->Arcs.push_back(Arc{ lower, upper, multiplicity });
  }
};

/// The 2D example of the paper's Fig. 1-2: samples p0..p3 forming two acute
/// triangles T1 = p0p1p2 (maximum M1) and T2 = p0p2p3 (maximum M2) sharing the
/// diagonal p0p2 (saddle s2). In 2D the maxima, the maximum at infinity
/// included, have index 2. Values (half edge lengths, circumradii):
///   s1 = p0p1 1.0, s3 = p1p2 1.1, s2 = p0p2 1.2, s4 = p2p3 1.5, s5 = p3p0 1.6,
///   M1 1.3, M2 2.0.
/// Ids follow the (index, simplex) order: p0..p3 = 0..3, s1 = 4 (0,1),
/// s2 = 5 (0,2), s5 = 6 (0,3), s3 = 7 (1,2), s4 = 8 (2,3), M1 = 9, M2 = 10,
/// infinity = 11. Hull edges s1, s3, s4, s5 flow to their triangle's maximum and
/// to infinity; the diagonal s2 flows to M1 and M2.
enum Fig1Ids : Id
{
  P0 = 0, P1, P2, P3, S1, S2, S5, S3, S4, M1, M2, Inf
};
inline Diagram Fig1()
{
  Diagram d;
  for (Id p = 0; p < 4; ++p)
  {
    d.Nodes.push_back(Sample(p));
  }
  d.Nodes.push_back(Edge(0, 1, 1.0));
  d.Nodes.push_back(Edge(0, 2, 1.2));
  d.Nodes.push_back(Edge(0, 3, 1.6));
  d.Nodes.push_back(Edge(1, 2, 1.1));
  d.Nodes.push_back(Edge(2, 3, 1.5));
  d.Nodes.push_back(MakeNode(2, 1.3, { { 0, 1, 2, -1 } }));
  d.Nodes.push_back(MakeNode(2, 2.0, { { 0, 2, 3, -1 } }));
  d.Nodes.push_back(Infinity(2));
  const Id ends[5][3] = { { S1, P0, P1 }, { S2, P0, P2 }, { S5, P0, P3 }, { S3, P1, P2 },
    { S4, P2, P3 } };
  for (const auto& e : ends)
  {
    d.Link(e[1], e[0]);
    d.Link(e[2], e[0]);
  }
  d.Link(S1, M1);
  d.Link(S1, Inf);
  d.Link(S2, M1);
  d.Link(S2, M2);
  d.Link(S5, M2);
  d.Link(S5, Inf);
  d.Link(S3, M1);
  d.Link(S3, Inf);
  d.Link(S4, M2);
  d.Link(S4, Inf);
  std::sort(d.Arcs.begin(), d.Arcs.end(), [](const Arc& a, const Arc& b) {
    return std::make_pair(a.Lower, a.Upper) < std::make_pair(b.Lower, b.Upper);
  });
  return d;
}

/// Arcs as a map (lower, upper) -> multiplicity, for comparisons.
inline std::map<std::pair<Id, Id>, int> ArcMap(const std::vector<Arc>& arcs)
{
  std::map<std::pair<Id, Id>, int> m;
  for (const Arc& a : arcs)
  {
    m[{ a.Lower, a.Upper }] += a.Multiplicity;
  }
  return m;
}

/// Quasi-uniform sphere sample (Fibonacci lattice), jittered by 1e-4 so that
/// it is in general position.
inline std::vector<Point3> FibonacciSphere(int n, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c;
  const double golden = M_PI * (3 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double z = 1 - 2 * (i + 0.5) / n, radius = std::sqrt(1 - z * z), a = golden * i;
    Point3 p{ { radius * std::cos(a), radius * std::sin(a), z } };
    for (double& x : p)
    {
      x += 1e-4 * (r.U() - 0.5);
    }
    c.push_back(p);
  }
  return c;
}

/// Quasi-uniform torus sample (R = 1, r = 0.35): nu x (nu * 21 / 60) staggered
/// grid in the angles, jittered by 1e-3.
inline std::vector<Point3> GridTorus(int nu, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c;
  const int nv = nu * 21 / 60;
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      const double u = 2 * M_PI * (i + 0.5 * (j % 2)) / nu, v = 2 * M_PI * j / nv;
      Point3 p{ { (1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u),
        0.35 * std::sin(v) } };
      for (double& x : p)
      {
        x += 1e-3 * (r.U() - 0.5);
      }
      c.push_back(p);
    }
  }
  return c;
}

/// The nodes of the reconstruction at t_r (no simplification): what
/// `reconstruct --tp 0 --tr T` writes.
inline std::vector<Id> ReconstructionNodes(const FlowComplex& fc, double tr)
{
  const std::vector<bool> all(fc.Nodes.size(), true);
  const std::vector<Id> init =
    InitializationEdges(fc.Nodes, NearestNeighboursFromDiagram(fc.Nodes, fc.Arcs));
  const ReconstructionResult run = Reconstruct(fc.Nodes, fc.Arcs, all, init, HUGE_VAL, Progress());
  const std::vector<Id> carriers = CellCarriers(run, nullptr);
  std::vector<Id> selected;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (carriers[i] >= 0 && run.Contains(carriers[i], tr))
    {
      selected.push_back(static_cast<Id>(i));
    }
  }
  return selected;
}

} // namespace fixtures

#endif
