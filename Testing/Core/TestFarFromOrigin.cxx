// Clouds far from the origin next to their extent (georeferenced scans: LAS
// files hold coordinates some 10^6 m away for a site 100 m wide). The
// triangulated points are the input moved next to the origin where that is
// exact (PrepareForTriangulation), so that the floating-point filters keep
// their precision:
// - the move is exact: every prepared point, scaled and moved back, is its
//   input point bit for bit, on each side of the origin; a cloud across the
//   origin, or not far from it, is not moved;
// - a quantized terrain 2^22 away builds the very flow complex of the same
//   terrain 1024 away (both are moved to the same place): the same nodes,
//   values and arcs, the same walks redone exactly, and its points (critical
//   points, patches, flow lines) the other's moved by the offset. Without the
//   move the far terrain's walks fall back to exact arithmetic thousands of
//   times more (and its build took 30 times longer);
// - from the triangulation kept for the later stages (Retriangulation, which
//   prepares the samples again), the far terrain's compact reconstruction is
//   the near one's, cell for cell.
#include "Check.h"
#include "CompactReconstruction.h"
#include "FlowComplexBuilder.h"
#include "InputPreparation.h"
#include "ReconFixtures.h"
#include "Retriangulation.h"

#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <random>
#include <vector>

using namespace flowrecon;

namespace
{

/// A height field sampled at random, coordinates on a grid of 1/64 (as a
/// scanner's quantized ones), x and y in [1024, 1124).
std::vector<Point3> Terrain(int n, std::uint32_t seed)
{
  std::mt19937 random(seed);
  std::vector<Point3> points;
  const auto quantized = [](double x) { return std::round(x * 64) / 64; };
  for (int i = 0; i < n; ++i)
  {
    const double x = 1024 + static_cast<double>(random() % 6400) / 64;
    const double y = 1024 + static_cast<double>(random() % 6400) / 64;
    const double z = 1024 + 5 * std::sin(x / 10) * std::cos(y / 13) + 2 * std::sin(x / 3 + y / 5);
    points.push_back({ { x, y, quantized(z) } });
  }
  return points;
}

std::vector<Point3> Moved(std::vector<Point3> points, const Point3& by)
{
  for (Point3& p : points)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] += by[k]; // exact: the grid of 1/64 holds at these magnitudes
    }
  }
  return points;
}

void TestExactMove()
{
  std::cout << "-- the prepared points are the input's, moved exactly\n";
  const std::vector<Point3> near = Terrain(500, 1);
  struct Case
  {
    const char* Name;
    std::vector<Point3> Points;
  };
  const std::vector<Case> cases = {
    { "far, positive", Moved(near, { { 4194304, 8388608, 1048576 } }) },
    { "far, negative", Moved(near, { { -4194304 - 2048, -2048, -1048576 - 2048 } }) },
    { "across the origin on x", Moved(near, { { -1074, 0, 0 } }) },
    { "near the origin", Moved(near, { { -1024, -1024, -1024 } }) },
  };
  for (const Case& c : cases)
  {
    const PreparedInput in = PrepareForTriangulation(c.Points);
    bool exact = true;
    for (std::size_t i = 0; i < in.Unique.size(); ++i)
    {
      exact = exact && in.BackScaled(in.Unique[i]) == c.Points[in.InputId[i]];
    }
    CHECK(exact);
    // Each axis moved by its least coordinate (its largest below 0) when all
    // lie within twice that; otherwise not moved.
    for (int k = 0; k < 3; ++k)
    {
      double lo = HUGE_VAL, hi = -HUGE_VAL;
      for (const Point3& p : c.Points)
      {
        lo = std::min(lo, p[k]);
        hi = std::max(hi, p[k]);
      }
      const double expected = lo > 0 && hi <= 2 * lo ? lo : hi < 0 && lo >= 2 * hi ? hi : 0.0;
      CHECK(in.Translation[k] == expected);
    }
    std::cout << "   " << c.Name << ": moved by " << in.Translation[0] << " " << in.Translation[1]
              << " " << in.Translation[2] << "\n";
  }
  // Which axes moved: all of the far clouds'; across the origin, y and z
  // only; near it (in [0, 100]), none.
  const auto moves = [](const std::vector<Point3>& points) {
    const Point3 t = PrepareForTriangulation(points).Translation;
    return (t[0] != 0 ? 1 : 0) + (t[1] != 0 ? 2 : 0) + (t[2] != 0 ? 4 : 0);
  };
  CHECK(moves(cases[0].Points) == 7 && moves(cases[1].Points) == 7);
  CHECK(moves(cases[2].Points) == 6 && moves(cases[3].Points) == 0);
}

bool Near(const Point3& a, const Point3& b, double tolerance)
{
  return std::fabs(a[0] - b[0]) <= tolerance && std::fabs(a[1] - b[1]) <= tolerance &&
    std::fabs(a[2] - b[2]) <= tolerance;
}

void TestSameComplex()
{
  std::cout << "-- a quantized terrain 2^22 away and 1024 away: one flow complex\n";
  const std::vector<Point3> near = Terrain(3000, 7);
  const Point3 offset{ { 4194304, 8388608, 4194304 } };
  const std::vector<Point3> far = Moved(near, offset);
  BuildOptions options; // with every geometry: its points must move back too
  const FlowComplex a = BuildFlowComplex(near, options, Progress());
  const FlowComplex b = BuildFlowComplex(far, options, Progress());
  std::cout << "   nodes " << a.Nodes.size() << ", exact fallbacks " << a.Report.ExactFallbacks
            << " and " << b.Report.ExactFallbacks << ", attempts " << a.Report.Attempts << "\n";
  CHECK(b.Report.Attempts == a.Report.Attempts);
  CHECK(b.Report.ExactFallbacks == a.Report.ExactFallbacks);
  CHECK(a.Nodes.size() == b.Nodes.size() && a.Arcs.size() == b.Arcs.size());
  if (a.Nodes.size() != b.Nodes.size() || a.Arcs.size() != b.Arcs.size())
  {
    return;
  }
  // The offset's magnitude (2^23) leaves doubles about 1e-9 apart.
  const double tolerance = 1e-8;
  bool same = true, moved = true;
  for (std::size_t i = 0; i < a.Nodes.size(); ++i)
  {
    const Node &x = a.Nodes[i], &y = b.Nodes[i];
    same = same && x.Index == y.Index && x.Simplex == y.Simplex && x.Value == y.Value;
    if (!x.IsInfinity())
    {
      moved = moved &&
        Near({ { x.Location[0] + offset[0], x.Location[1] + offset[1], x.Location[2] + offset[2] } },
          y.Location, tolerance);
    }
  }
  CHECK(same);
  CHECK(moved);
  bool arcs = true;
  for (std::size_t i = 0; i < a.Arcs.size(); ++i)
  {
    arcs = arcs && a.Arcs[i].Lower == b.Arcs[i].Lower && a.Arcs[i].Upper == b.Arcs[i].Upper &&
      a.Arcs[i].Multiplicity == b.Arcs[i].Multiplicity;
  }
  CHECK(arcs);
  CHECK(a.Points.size() == b.Points.size() && a.FlowLines.size() == b.FlowLines.size());
  bool geometry = a.Points.size() == b.Points.size();
  for (std::size_t i = 0; geometry && i < a.Points.size(); ++i)
  {
    const Point3& p = a.Points[i];
    geometry = Near({ { p[0] + offset[0], p[1] + offset[1], p[2] + offset[2] } }, b.Points[i], tolerance);
  }
  for (std::size_t i = 0; geometry && i < a.FlowLines.size(); ++i)
  {
    geometry = a.FlowLines[i].Points.size() == b.FlowLines[i].Points.size();
    for (std::size_t j = 0; geometry && j < a.FlowLines[i].Points.size(); ++j)
    {
      const Point3& p = a.FlowLines[i].Points[j];
      geometry = Near({ { p[0] + offset[0], p[1] + offset[1], p[2] + offset[2] } },
        b.FlowLines[i].Points[j], tolerance);
    }
  }
  CHECK(geometry);
}

/// The compact reconstruction at t_r 2.5 without simplification (as
/// `reconstruct --tp 0 --tr 2.5` writes it), on the kept triangulation.
CompactComplex Compact(const std::vector<Point3>& points)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  std::unique_ptr<Retriangulation> re;
  const FlowComplex fc = BuildFlowComplex(points, options, Progress(), &re);
  const std::vector<Id> selected = fixtures::ReconstructionNodes(fc, 2.5);
  return CompactReconstruction(*re, fc.Nodes, selected);
}

void TestSameCompactOutput()
{
  std::cout << "-- the compact reconstruction, far and near\n";
  const std::vector<Point3> near = Terrain(3000, 9);
  const CompactComplex a = Compact(near);
  const CompactComplex b = Compact(Moved(near, { { 4194304, 8388608, 4194304 } }));
  std::cout << "   " << a.Triangles.size() << " triangles, " << a.Tetrahedra.size()
            << " tetrahedra; Betti " << a.Betti[0] << " " << a.Betti[1] << " " << a.Betti[2] << "\n";
  CHECK(a.Triangles.size() > 1000);
  CHECK(a.Triangles == b.Triangles && a.Tetrahedra == b.Tetrahedra && a.Edges == b.Edges &&
    a.Vertices == b.Vertices && a.Betti == b.Betti);
}

} // namespace

int main()
{
  TestExactMove();
  TestSameComplex();
  TestSameCompactOutput();
  return check::Finish("TestFarFromOrigin");
}
