// The cones of index-3 stable manifolds (StableManifoldCone.h): over a sphere a
// ball; over a sphere pinched at a point or along an edge (a cell that wraps
// around and meets itself) a ball with boundary points identified, which has
// one loop. A plain cone over the pinched sphere is contractible: glued to the
// neighbouring cells, which fill that loop too, it enclosed a void.
#include "CellHomology.h"
#include "Check.h"
#include "StableManifoldCone.h"

#include <cmath>
#include <vector>

using flowrecon::Id;
using flowrecon::Point3;

namespace
{

std::vector<Point3> Icosahedron()
{
  const double f = (1 + std::sqrt(5.0)) / 2;
  return { { -1, f, 0 }, { 1, f, 0 }, { -1, -f, 0 }, { 1, -f, 0 }, { 0, -1, f }, { 0, 1, f },
    { 0, -1, -f }, { 0, 1, -f }, { f, 0, -1 }, { f, 0, 1 }, { -f, 0, -1 }, { -f, 0, 1 } };
}

std::vector<std::array<Id, 3>> IcosahedronFaces()
{
  return { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 }, { 1, 5, 9 },
    { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
}

std::array<Id, 4> BettiOf(const std::vector<std::array<Id, 4>>& tetrahedra)
{
  flowrecon::FilteredCells cells;
  for (const auto& t : tetrahedra)
  {
    cells.Add(t.data(), 4, 1.0);
  }
  return flowrecon::BettiNumbersBelow(flowrecon::CellBarcode(cells), 2.0);
}

// The face (a, b, c) of a tetrahedron, ordered so that its normal points to
// `inside`.
std::array<Id, 3> Facing(const std::vector<Point3>& p, Id a, Id b, Id c, const Point3& inside)
{
  double n[3], d[3];
  const Point3 &A = p[a], &B = p[b], &C = p[c];
  n[0] = (B[1] - A[1]) * (C[2] - A[2]) - (B[2] - A[2]) * (C[1] - A[1]);
  n[1] = (B[2] - A[2]) * (C[0] - A[0]) - (B[0] - A[0]) * (C[2] - A[2]);
  n[2] = (B[0] - A[0]) * (C[1] - A[1]) - (B[1] - A[1]) * (C[0] - A[0]);
  for (int j = 0; j < 3; ++j)
    d[j] = inside[j] - A[j];
  return n[0] * d[0] + n[1] * d[1] + n[2] * d[2] > 0 ? std::array<Id, 3>{ { a, b, c } }
                                                     : std::array<Id, 3>{ { a, c, b } };
}

// The boundaries of two tetrahedra (0, 1, a, b) that share the edge (0, 1) and
// lie in the wedges 0-90 and 180-270 degrees around it: a cell that meets
// itself along that edge (its interior joins them elsewhere). `inward` orients
// every triangle toward its tetrahedron, else away from it.
std::vector<std::array<Id, 3>> EdgePinched(const std::vector<Point3>& p, bool inward)
{
  std::vector<std::array<Id, 3>> faces;
  for (const std::array<Id, 2>& ab : { std::array<Id, 2>{ { 2, 3 } }, std::array<Id, 2>{ { 4, 5 } } })
  {
    const Id t[4] = { 0, 1, ab[0], ab[1] };
    Point3 centre{ { 0, 0, 0 } };
    for (const Id v : t)
      for (int j = 0; j < 3; ++j)
        centre[j] += p[v][j] / 4;
    for (int skip = 0; skip < 4; ++skip)
    {
      Id f[3], k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != skip)
          f[k++] = t[j];
      std::array<Id, 3> face = Facing(p, f[0], f[1], f[2], centre);
      if (!inward)
        std::swap(face[1], face[2]);
      faces.push_back(face);
    }
  }
  return faces;
}

std::vector<Point3> EdgePinchedPoints()
{
  return { { 0, 0, 0 }, { 0, 0, 1 }, { 1, 0, 0.5 }, { 0, 1, 0.5 }, { -1, 0, 0.5 },
    { 0, -1, 0.5 }, { 0.3, 0.3, 0.5 } };
}

bool Distinct(const std::array<Id, 4>& t)
{
  return t[0] != t[1] && t[0] != t[2] && t[0] != t[3] && t[1] != t[2] && t[1] != t[3] &&
    t[2] != t[3];
}

} // namespace

int main()
{
  // A sphere: one tetrahedron per triangle, a ball.
  {
    std::vector<Point3> points = Icosahedron();
    points.push_back({ 0, 0, 0 });
    std::vector<std::array<Id, 4>> tets;
    CHECK(flowrecon::AppendCone(12, IcosahedronFaces(), points, tets) == 20);
    CHECK(tets.size() == 20 && points.size() == 13);
    const auto b = BettiOf(tets);
    CHECK(b[0] == 1 && b[1] == 0 && b[2] == 0);
  }

  // The sphere pinched: vertex 3 (the antipode of 0, whose link is disjoint
  // from 0's) renamed 0. The five triangles that were around 3 form the second
  // sheet at 0: their tetrahedra are split at a new point on the segment from
  // the apex, so the sheets meet at 0 only.
  {
    std::vector<Point3> points = Icosahedron();
    points.push_back({ 0, 0, 0 });
    auto faces = IcosahedronFaces();
    for (auto& f : faces)
      for (Id& v : f)
        v = v == 3 ? 0 : v;
    std::vector<std::array<Id, 4>> tets(1, { { 100, 101, 102, 103 } }); // kept as it is
    CHECK(flowrecon::AppendCone(12, faces, points, tets) == 25);
    CHECK(tets.size() == 26 && tets[0][0] == 100 && points.size() == 14);
    tets.erase(tets.begin());
    for (const auto& t : tets)
      CHECK(Distinct(t));
    // The new point is strictly between the apex and the pinched point's side.
    const Point3 m = points.size() > 13 ? points[13] : Point3{ { 0, 0, 0 } };
    CHECK(std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) > 0.1);
    const auto b = BettiOf(tets);
    CHECK(b[0] == 1 && b[1] == 1 && b[2] == 0);
    // The edge from the apex to 0 is in the first sheet's tetrahedra only.
    int withEdge = 0;
    for (const auto& t : tets)
    {
      bool apex = false, zero = false;
      for (const Id v : t)
      {
        apex = apex || v == 12;
        zero = zero || v == 0;
      }
      withEdge += apex && zero ? 1 : 0;
    }
    CHECK(withEdge == 5);

    // Deterministic: the same input gives the same cells and points.
    std::vector<Point3> again = Icosahedron();
    again.push_back({ 0, 0, 0 });
    std::vector<std::array<Id, 4>> tets2;
    flowrecon::AppendCone(12, faces, again, tets2);
    CHECK(tets2 == tets && again == points);
  }

  // Two sheets along an edge: the triangles around (0, 1) pair up through the
  // wedges inside the cell, so each sheet is coned on its own and the sheets
  // meet along the edge and at the apex: a loop. Oriented outward, the outer
  // wedges pair triangles of different tetrahedra, which joins the sheets:
  // a plain cone, contractible. So the orientation decides.
  {
    std::vector<Point3> points = EdgePinchedPoints();
    std::vector<std::array<Id, 4>> tets;
    const Id count = flowrecon::AppendCone(6, EdgePinched(points, true), points, tets);
    CHECK(count > 8 && points.size() > 7);
    for (const auto& t : tets)
      CHECK(Distinct(t));
    const auto b = BettiOf(tets);
    CHECK(b[0] == 1 && b[1] == 1 && b[2] == 0);

    std::vector<Point3> outward = EdgePinchedPoints();
    std::vector<std::array<Id, 4>> plain;
    CHECK(flowrecon::AppendCone(6, EdgePinched(outward, false), outward, plain) == 8);
    const auto c = BettiOf(plain);
    CHECK(c[0] == 1 && c[1] == 0 && c[2] == 0);
  }

  // SheetsAroundEdge on its own: the four triangles around (0, 1) above, at
  // 0, 90, 180 and 270 degrees.
  {
    const std::vector<Point3> points = EdgePinchedPoints();
    const auto faces = EdgePinched(points, true);
    std::vector<std::size_t> around;
    for (std::size_t t = 0; t < faces.size(); ++t)
    {
      int has = 0;
      for (const Id v : faces[t])
        has += v == 0 || v == 1 ? 1 : 0;
      if (has == 2)
        around.push_back(t);
    }
    CHECK(around.size() == 4);
    const auto first = flowrecon::SheetsAroundEdge(points, faces, nullptr, 0, 1, around);
    CHECK(first.size() == 4);
    if (first.size() == 4)
    {
      // Triangles of one tetrahedron together, of the other apart.
      CHECK(first[0] == first[1] && first[2] == first[3] && first[0] != first[2]);
    }
    // One triangle turned the other way: a wedge claimed from one side only.
    auto turned = faces;
    std::swap(turned[around[0]][1], turned[around[0]][2]);
    CHECK(flowrecon::SheetsAroundEdge(points, turned, nullptr, 0, 1, around).empty());
    // A fin (a two-sided patch, either orientation) at 45 degrees, inside the
    // first tetrahedron's wedge: in that sheet.
    auto withFin = faces;
    auto finPoints = points;
    finPoints.push_back({ 0.7, 0.7, 0.5 });
    withFin.push_back({ { 1, 0, 7 } });
    std::vector<char> twoSided(withFin.size(), 0);
    twoSided.back() = 1;
    auto aroundFin = around;
    aroundFin.push_back(withFin.size() - 1);
    const auto joined =
      flowrecon::SheetsAroundEdge(finPoints, withFin, &twoSided, 0, 1, aroundFin);
    CHECK(joined.size() == 5);
    if (joined.size() == 5)
    {
      CHECK(joined[4] == joined[0] && joined[0] == joined[1] && joined[2] == joined[3] &&
        joined[0] != joined[2]);
    }
    // Not two-sided, that triangle claims a single wedge, which its neighbour
    // does not: refused.
    CHECK(flowrecon::SheetsAroundEdge(finPoints, withFin, nullptr, 0, 1, aroundFin).empty());
  }

  // No boundary, no cells.
  {
    std::vector<Point3> points(1, Point3{ { 0, 0, 0 } });
    std::vector<std::array<Id, 4>> tets;
    CHECK(flowrecon::AppendCone(0, {}, points, tets) == 0 && tets.empty() && points.size() == 1);
  }
  return check::Finish("TestStableManifoldCone");
}
