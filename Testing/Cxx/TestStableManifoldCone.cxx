// The cones of index-3 stable manifolds (StableManifoldCone.h): over a sphere a
// ball; over a sphere pinched at a point (a cell that wraps around and meets
// itself at a sample) a ball with two boundary points identified, which has one
// loop. A plain cone over the pinched sphere is contractible: glued to the
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

  // No boundary, no cells.
  {
    std::vector<Point3> points(1, Point3{ { 0, 0, 0 } });
    std::vector<std::array<Id, 4>> tets;
    CHECK(flowrecon::AppendCone(0, {}, points, tets) == 0 && tets.empty() && points.size() == 1);
  }
  return check::Finish("TestStableManifoldCone");
}
