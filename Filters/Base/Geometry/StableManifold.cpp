#include "StableManifold.h"

#include "VoronoiWalk.h"

#include <deque>
#include <string>

namespace flowrecon
{

namespace
{

// Walks are bounded by the number of Voronoi edges; this only guards against a
// bug turning into a hang.
constexpr std::size_t MaxWalkItems = 1u << 22;

template <class FT>
struct Item
{
  EdgePoint<FT> Z; // on the Voronoi edge V(u v w), or c itself (lambda = 0 on V(f))
  Id ZRef;         // its vertex reference in the patch
  Id U, V, W;
  CellHandle Hint; // a cell containing u, v and w
  bool Flip;       // the patch's orientation is (v, z, u) here, not (u, z, v)
};

template <class FT>
Patch Walk(const Triangulation& tri, const CriticalSimplices& cs, const std::array<Id, 3>& f,
  CellHandle cell, bool withGeometry, bool withWalked)
{
  Patch patch;
  std::vector<EdgePoint<FT>> points{ EdgePoint<FT>{ f, FT(0) } }; // c = c_f
  std::deque<Item<FT>> queue;
  queue.push_back({ points[0], -1, f[0], f[1], f[2], cell, false });
  queue.push_back({ points[0], -1, f[1], f[2], f[0], cell, false });
  queue.push_back({ points[0], -1, f[2], f[0], f[1], cell, false });
  std::vector<Id> excluded(1);
  std::size_t items = 0;
  while (!queue.empty())
  {
    if (++items > MaxWalkItems)
    {
      throw std::runtime_error("stable manifold walk did not terminate");
    }
    const Item<FT> it = queue.front();
    queue.pop_front();
    const Id edge = cs.FindEdge(it.U, it.V);
    if (edge >= 0)
    {
      // The segment from z to the midpoint stays in V(uv): the flow ends on the
      // Gabriel edge, and (u, z, m) + (m, z, v) is the triangle (u, z, v).
      patch.Arrivals.push_back(edge);
      if (withGeometry)
      {
        patch.Triangles.push_back(
          it.Flip ? std::array<Id, 3>{ { it.V, it.ZRef, it.U } } : std::array<Id, 3>{ { it.U, it.ZRef, it.V } });
      }
      continue;
    }
    // uv is not Gabriel: walking back toward its midpoint, z leaves V(uv) first.
    excluded[0] = it.W;
    Id s = -1;
    EdgePoint<FT> y;
    CellHandle exitCell;
    if (!FirstExit(tri, it.Z, it.U, it.V, excluded, true, it.Hint, s, y, exitCell))
    {
      throw Degenerate("descending walk found no exit");
    }
    if (withWalked)
    {
      patch.Walked.push_back({ { it.U, it.V, s } });
      patch.WalkedCells.push_back(exitCell);
    }
    const Id yRef = -1 - static_cast<Id>(points.size());
    points.push_back(y);
    if (withGeometry)
    {
      // (u, z, v) = (u, z, y) + (y, z, v), with the orientation of (u, z, v).
      if (it.Flip)
      {
        patch.Triangles.push_back({ { yRef, it.ZRef, it.U } });
        patch.Triangles.push_back({ { it.V, it.ZRef, yRef } });
      }
      else
      {
        patch.Triangles.push_back({ { it.U, it.ZRef, yRef } });
        patch.Triangles.push_back({ { yRef, it.ZRef, it.V } });
      }
    }
    // Both V(u s) and V(v s) flow into y (uvs is obtuse at s): two branches,
    // (u, y, s) with the orientation of (u, z, y) and (v, y, s) against it.
    queue.push_back({ y, yRef, it.U, s, it.V, exitCell, it.Flip });
    queue.push_back({ y, yRef, it.V, s, it.U, exitCell, !it.Flip });
  }
  if (withGeometry)
  {
    patch.Constructed.reserve(points.size());
    for (const EdgePoint<FT>& p : points)
    {
      patch.Constructed.push_back(RequireTight(Frame<FT>(tri, p.G).At(p.Lambda)));
    }
  }
  return patch;
}

} // namespace

Patch ComputeStableManifold(const Triangulation& tri, const CriticalSimplices& cs,
  std::size_t facet, bool withGeometry, Id& fallbacks, bool exactOnly, bool withWalked)
{
  return Filtered(
    [&](auto ft) {
      return Walk<decltype(ft)>(
        tri, cs, Widen(cs.Facets[facet].Vertices), tri.Cell(cs.Facets[facet].Cell), withGeometry,
        withWalked);
    },
    fallbacks, exactOnly);
}

int PatchFacesSide(const Triangulation& tri, const CriticalSimplices& cs, std::size_t facet)
{
  // The first triangles are (f0, c, f1)... with c inside the acute facet: the
  // reverse of (f0, f1, f2), so their normals face the negative side of it.
  const CriticalFacet& f = cs.Facets[facet];
  const CellHandle cell = tri.Cell(f.Cell);
  const CGAL::Orientation o = CGAL::orientation(tri.KCoord(f.Vertices[0]), tri.KCoord(f.Vertices[1]),
    tri.KCoord(f.Vertices[2]), cell->vertex(f.Opposite)->point());
  return o == CGAL::NEGATIVE ? 0 : 1;
}

} // namespace flowrecon
