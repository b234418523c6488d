#include "StableManifoldCone.h"

#include "PersistenceUnionFind.h"

#include <algorithm>
#include <numeric>
#include <utility>

namespace flowrecon
{

Id AppendCone(Id apex, const std::vector<std::array<Id, 3>>& boundary,
  std::vector<Point3>& points, std::vector<std::array<Id, 4>>& tetrahedra)
{
  const std::size_t first = tetrahedra.size();
  for (const auto& t : boundary)
  {
    tetrahedra.push_back({ { apex, t[0], t[1], t[2] } });
  }

  // Corners (triangle, vertex) sorted by vertex: the star of each boundary point.
  std::vector<std::pair<Id, Id>> corners; // (vertex, triangle)
  corners.reserve(3 * boundary.size());
  for (std::size_t t = 0; t < boundary.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      corners.emplace_back(boundary[t][c], static_cast<Id>(t));
    }
  }
  std::sort(corners.begin(), corners.end());

  // The sheets at p: its triangles joined through their edges (p, x), that is
  // the components of p's link. Two sheets pinched along a whole edge (p, x)
  // stay joined: telling them from a boundary folded onto the edge needs the
  // side of each triangle the cell is on (README, known limits).
  std::vector<std::pair<Id, Id>> around; // (x, local triangle) for each edge (p, x)
  std::vector<std::vector<std::size_t>> sheets;
  std::vector<std::vector<std::size_t>> tetsOfTriangle; // filled at the first split
  for (std::size_t begin = 0; begin < corners.size();)
  {
    const Id p = corners[begin].first;
    std::size_t end = begin;
    while (end < corners.size() && corners[end].first == p)
    {
      ++end;
    }
    around.clear();
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
    ElderUnionFind sheet(end - begin);
    for (std::size_t i = 1; i < around.size(); ++i)
    {
      if (around[i].first == around[i - 1].first)
      {
        sheet.Merge(static_cast<std::int32_t>(around[i].second),
          static_cast<std::int32_t>(around[i - 1].second));
      }
    }
    // Sheets in the order of their least triangle (corners are sorted by it).
    sheets.clear();
    std::vector<Id> sheetOfRoot(end - begin, -1);
    for (std::size_t k = begin; k < end; ++k)
    {
      const Id root = sheet.Find(static_cast<std::int32_t>(k - begin));
      if (sheetOfRoot[root] < 0)
      {
        sheetOfRoot[root] = static_cast<Id>(sheets.size());
        sheets.emplace_back();
      }
      sheets[sheetOfRoot[root]].push_back(static_cast<std::size_t>(corners[k].second));
    }
    for (std::size_t s = 1; s < sheets.size(); ++s)
    {
      // The new point: halfway from the apex to the sheet's middle near p, so
      // that it is inside this sheet's part of the cone.
      Point3 middle = points[p];
      Id near = 1;
      for (const std::size_t t : sheets[s])
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
      if (tetsOfTriangle.empty())
      {
        tetsOfTriangle.resize(boundary.size());
        for (std::size_t t = 0; t < boundary.size(); ++t)
        {
          tetsOfTriangle[t].push_back(first + t);
        }
      }
      for (const std::size_t t : sheets[s])
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
    begin = end;
  }
  return static_cast<Id>(tetrahedra.size() - first);
}

} // namespace flowrecon
