#include "StableManifoldCone.h"

#include "UnionFind.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace flowrecon
{

namespace
{

Point3 Minus(const Point3& a, const Point3& b)
{
  return { { a[0] - b[0], a[1] - b[1], a[2] - b[2] } };
}

Point3 Cross(const Point3& a, const Point3& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}

double Dot(const Point3& a, const Point3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

} // namespace

std::vector<std::size_t> SheetsAroundEdge(const std::vector<Point3>& points,
  const std::vector<std::array<Id, 3>>& boundary, const std::vector<char>* twoSided, Id p, Id x,
  const std::vector<std::size_t>& triangles)
{
  const std::size_t r = triangles.size();
  // Coordinates relative to p, scaled by a power of two to about 1: products
  // of up to seven of them neither overflow nor underflow, and a cloud scaled
  // by 2^k gives exactly the same answer.
  double largest = 0;
  for (const std::size_t t : triangles)
  {
    for (const Id w : boundary[t])
    {
      for (int j = 0; j < 3; ++j)
      {
        largest = std::max(largest, std::abs(points[w][j] - points[p][j]));
      }
    }
  }
  if (!(largest > 0) || !std::isfinite(largest))
  {
    return {};
  }
  const int exponent = std::ilogb(largest);
  const auto at = [&](Id w) {
    Point3 d = Minus(points[w], points[p]);
    for (double& c : d)
    {
      c = std::ldexp(c, -exponent);
    }
    return d;
  };
  // A frame (u, v) of the plane normal to the edge, with u x v along it.
  const Point3 axis = at(x);
  const int small = std::abs(axis[0]) <= std::abs(axis[1])
    ? (std::abs(axis[0]) <= std::abs(axis[2]) ? 0 : 2)
    : (std::abs(axis[1]) <= std::abs(axis[2]) ? 1 : 2);
  Point3 e{ { 0, 0, 0 } };
  e[small] = 1;
  const Point3 u = Cross(axis, e), v = Cross(axis, u);
  struct Side
  {
    double Angle;
    int Claims; // 1: the wedge after it (counterclockwise), 2: the one before, 3: both
    std::size_t Position;
  };
  std::vector<Side> sides;
  sides.reserve(r);
  for (std::size_t k = 0; k < r; ++k)
  {
    const std::array<Id, 3>& t = boundary[triangles[k]];
    Id y = -1;
    for (const Id w : t)
    {
      y = w != p && w != x ? w : y;
    }
    if (y < 0)
    {
      return {}; // a degenerate triangle
    }
    const Point3 d = at(y);
    const double du = Dot(d, u), dv = Dot(d, v);
    // Counterclockwise at d (about the axis): u x v turns u into v.
    Point3 ahead;
    for (int j = 0; j < 3; ++j)
    {
      ahead[j] = du * v[j] - dv * u[j];
    }
    const double facing =
      Dot(Cross(Minus(at(t[1]), at(t[0])), Minus(at(t[2]), at(t[0]))), ahead);
    const bool both = twoSided && (*twoSided)[triangles[k]];
    if (!(facing != 0) && !both)
    {
      return {};
    }
    sides.push_back({ std::atan2(dv, du), both ? 3 : (facing > 0 ? 1 : 2), k });
  }
  std::sort(sides.begin(), sides.end(), [](const Side& a, const Side& b) {
    return a.Angle < b.Angle || (a.Angle == b.Angle && a.Position < b.Position);
  });
  UnionFind sheet(r);
  for (std::size_t i = 0; i < r; ++i)
  {
    const Side& a = sides[i];
    const Side& b = sides[(i + 1) % r];
    if (a.Angle == b.Angle && r > 1)
    {
      return {}; // two patches in one half-plane: no wedge between them
    }
    const bool fromA = (a.Claims & 1) != 0, fromB = (b.Claims & 2) != 0;
    if (fromA != fromB)
    {
      return {};
    }
    if (fromA)
    {
      sheet.Merge(static_cast<std::int32_t>(a.Position), static_cast<std::int32_t>(b.Position));
    }
  }
  std::vector<std::size_t> first(r);
  for (std::size_t k = 0; k < r; ++k)
  {
    first[k] = static_cast<std::size_t>(sheet.Find(static_cast<std::int32_t>(k)));
  }
  return first;
}

namespace
{

/// A boundary point whose link in the boundary has several components: the
/// triangles (positions in the boundary) of each of its sheets.
struct Pinch
{
  Id P;
  std::vector<std::vector<std::size_t>> Sheets;
};

/// Joins in `sheet` the triangles at p (corners[begin, end), all at p) through
/// their edges (p, x); where more than two triangles share an edge (p, x), only
/// those of one sheet around it (SheetsAroundEdge). Returns the number of
/// sheets. `around` and `shared` are scratch space.
std::size_t JoinSheetsAt(const std::vector<Point3>& points,
  const std::vector<std::array<Id, 3>>& boundary, const std::vector<char>* twoSided,
  const std::vector<std::pair<Id, Id>>& corners, std::size_t begin, std::size_t end,
  UnionFind& sheet, std::vector<std::pair<Id, Id>>& around, std::vector<std::size_t>& shared)
{
  const Id p = corners[begin].first;
  around.clear(); // (x, local triangle) for each edge (p, x)
  for (std::size_t k = begin; k < end; ++k)
  {
    for (const Id x : boundary[corners[k].second])
    {
      if (x != p)
      {
        around.emplace_back(x, static_cast<Id>(k - begin));
      }
    }
  }
  std::sort(around.begin(), around.end());
  std::size_t components = end - begin;
  for (std::size_t i = 0; i < around.size();)
  {
    std::size_t j = i + 1;
    while (j < around.size() && around[j].first == around[i].first)
    {
      ++j;
    }
    std::vector<std::size_t> firstOfSheet;
    if (j - i > 2)
    {
      shared.clear();
      for (std::size_t k = i; k < j; ++k)
      {
        shared.push_back(static_cast<std::size_t>(corners[begin + around[k].second].second));
      }
      firstOfSheet = SheetsAroundEdge(points, boundary, twoSided, p, around[i].first, shared);
    }
    for (std::size_t k = i + 1; k < j; ++k)
    {
      const std::size_t other = firstOfSheet.empty() ? i : i + firstOfSheet[k - i];
      const auto a = static_cast<std::int32_t>(around[k].second);
      const auto b = static_cast<std::int32_t>(around[other].second);
      if (sheet.Merge(a, b) >= 0)
      {
        --components;
      }
    }
    i = j;
  }
  return components;
}

/// The points of the boundary with several sheets, each with its sheets: its
/// triangles joined through their edges (p, x), that is the components of p's
/// link. The sheets of one point do not depend on the splits at others, so
/// these points are all found first and split afterwards in an order of the
/// geometry.
std::vector<Pinch> FindPinches(const std::vector<Point3>& points,
  const std::vector<std::array<Id, 3>>& boundary, const std::vector<char>* twoSided)
{
  // Corners (vertex, triangle) sorted by vertex id: the star of each boundary point.
  std::vector<std::pair<Id, Id>> corners;
  corners.reserve(3 * boundary.size());
  for (std::size_t t = 0; t < boundary.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      corners.emplace_back(boundary[t][c], static_cast<Id>(t));
    }
  }
  std::sort(corners.begin(), corners.end());

  std::vector<Pinch> pinches;
  std::vector<std::pair<Id, Id>> around;
  std::vector<std::size_t> shared;
  std::vector<Id> sheetOfRoot;
  for (std::size_t begin = 0; begin < corners.size();)
  {
    const Id p = corners[begin].first;
    std::size_t end = begin;
    while (end < corners.size() && corners[end].first == p)
    {
      ++end;
    }
    UnionFind sheet(end - begin);
    if (JoinSheetsAt(points, boundary, twoSided, corners, begin, end, sheet, around, shared) > 1)
    {
      Pinch pinch{ p, {} };
      sheetOfRoot.assign(end - begin, -1);
      for (std::size_t k = begin; k < end; ++k)
      {
        const Id root = sheet.Find(static_cast<std::int32_t>(k - begin));
        if (sheetOfRoot[root] < 0)
        {
          sheetOfRoot[root] = static_cast<Id>(pinch.Sheets.size());
          pinch.Sheets.emplace_back();
        }
        pinch.Sheets[sheetOfRoot[root]].push_back(static_cast<std::size_t>(corners[k].second));
      }
      pinches.push_back(std::move(pinch));
    }
    begin = end;
  }
  return pinches;
}

/// The least triangle of a sheet by sorted corner coordinates: an order of the
/// geometry, not of the triangles, which follows the numbering of the input.
std::array<Point3, 3> LeastTriangle(const std::vector<Point3>& points,
  const std::vector<std::array<Id, 3>>& boundary, const std::vector<std::size_t>& sheetTriangles)
{
  std::array<Point3, 3> least;
  bool firstTriangle = true;
  for (const std::size_t t : sheetTriangles)
  {
    std::array<Point3, 3> c{ { points[boundary[t][0]], points[boundary[t][1]],
      points[boundary[t][2]] } };
    std::sort(c.begin(), c.end());
    if (firstTriangle || c < least)
    {
      least = c;
      firstTriangle = false;
    }
  }
  return least;
}

/// Splits the cone at a pinched point p: the sheet that keeps the apex is the
/// least by geometry; each other sheet gets a point m of its own on the segment
/// from the apex towards it, and its tetrahedra holding the edge (apex, p) are
/// subdivided there. `tetsOfTriangle`: the tetrahedra of each boundary triangle.
void SplitAtPinch(const std::vector<std::array<Id, 3>>& boundary, Id apex, Pinch& pinch,
  std::vector<Point3>& points, std::vector<std::array<Id, 4>>& tetrahedra,
  std::vector<std::vector<std::size_t>>& tetsOfTriangle)
{
  const Id p = pinch.P;
  std::vector<std::vector<std::size_t>>& sheets = pinch.Sheets;
  for (std::vector<std::size_t>& sheetTriangles : sheets)
  {
    // Sums over a sheet (its middle) in an order of the geometry too.
    std::sort(sheetTriangles.begin(), sheetTriangles.end(), [&](std::size_t a, std::size_t b) {
      return LeastTriangle(points, boundary, { a }) < LeastTriangle(points, boundary, { b });
    });
  }
  std::vector<std::pair<std::array<Point3, 3>, std::size_t>> order;
  for (std::size_t s = 0; s < sheets.size(); ++s)
  {
    order.emplace_back(LeastTriangle(points, boundary, sheets[s]), s);
  }
  std::sort(order.begin(), order.end());
  for (std::size_t o = 1; o < order.size(); ++o)
  {
    const std::vector<std::size_t>& sheetTriangles = sheets[order[o].second];
    // The new point: halfway from the apex to the sheet's middle near p, so
    // that it is inside this sheet's part of the cone.
    Point3 middle = points[p];
    Id near = 1;
    for (const std::size_t t : sheetTriangles)
    {
      for (int c = 0; c < 3; ++c)
      {
        if (boundary[t][c] != p)
        {
          for (int j = 0; j < 3; ++j)
            middle[j] += points[boundary[t][c]][j];
          ++near;
        }
      }
    }
    const Id m = static_cast<Id>(points.size());
    Point3 q;
    for (int j = 0; j < 3; ++j)
    {
      q[j] = 0.5 * points[apex][j] + 0.5 * (0.5 * points[p][j] + 0.5 * middle[j] / static_cast<double>(near));
    }
    points.push_back(q);
    // Every tetrahedron of these triangles that holds the edge (apex, p)
    // becomes two: (m, p, x, y) and (apex, m, x, y). Tetrahedra keep the apex
    // first, so later splits at another corner find it.
    for (const std::size_t t : sheetTriangles)
    {
      const std::size_t count = tetsOfTriangle[t].size();
      for (std::size_t i = 0; i < count; ++i)
      {
        const std::size_t k = tetsOfTriangle[t][i];
        std::array<Id, 4> tet = tetrahedra[k];
        if (tet[0] != apex || std::find(tet.begin() + 1, tet.end(), p) == tet.end())
        {
          continue;
        }
        tetrahedra[k][0] = m;
        std::replace(tet.begin() + 1, tet.end(), p, m);
        tetsOfTriangle[t].push_back(tetrahedra.size());
        tetrahedra.push_back(tet);
      }
    }
  }
}

} // namespace

Id AppendCone(Id apex, const std::vector<std::array<Id, 3>>& boundary,
  std::vector<Point3>& points, std::vector<std::array<Id, 4>>& tetrahedra,
  const std::vector<char>* twoSided)
{
  const std::size_t first = tetrahedra.size();
  for (const auto& t : boundary)
  {
    tetrahedra.push_back({ { apex, t[0], t[1], t[2] } });
  }
  std::vector<Pinch> pinches = FindPinches(points, boundary, twoSided);
  if (pinches.empty())
  {
    return static_cast<Id>(boundary.size());
  }

  // Points in the order of their coordinates (then ids): where a sheet is split
  // at both ends of an edge, the tetrahedra depend on which end comes first, and
  // they must not depend on the numbering of the input.
  std::sort(pinches.begin(), pinches.end(), [&points](const Pinch& a, const Pinch& b) {
    return points[a.P] != points[b.P] ? points[a.P] < points[b.P] : a.P < b.P;
  });
  std::vector<std::vector<std::size_t>> tetsOfTriangle(boundary.size());
  for (std::size_t t = 0; t < boundary.size(); ++t)
  {
    tetsOfTriangle[t].push_back(first + t);
  }
  for (Pinch& pinch : pinches)
  {
    SplitAtPinch(boundary, apex, pinch, points, tetrahedra, tetsOfTriangle);
  }
  return static_cast<Id>(tetrahedra.size() - first);
}

} // namespace flowrecon
