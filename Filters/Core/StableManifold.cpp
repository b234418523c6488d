#include "StableManifold.h"

#include "Arithmetic.h"

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
  Vec<FT> Z; // on the Voronoi edge V(u v w), or c itself
  Id ZRef;   // its vertex reference in the patch
  Id U, V, W;
};

template <class FT>
Patch Walk(const Triangulation& tri, const CriticalSimplices& cs, const std::array<Id, 3>& f,
  bool withGeometry)
{
  auto P = [&](Id k) { return Vec<FT>::From(tri.Coord(k)); };
  Patch patch;
  std::vector<Vec<FT>> points; // exact (or interval) constructed vertices
  points.push_back(Circumcenter(P(f[0]), P(f[1]), P(f[2])));
  std::deque<Item<FT>> queue;
  queue.push_back({ points[0], -1, f[0], f[1], f[2] });
  queue.push_back({ points[0], -1, f[1], f[2], f[0] });
  queue.push_back({ points[0], -1, f[2], f[0], f[1] });
  std::vector<Id> link;
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
        patch.Triangles.push_back({ { it.U, it.ZRef, it.V } });
      }
      continue;
    }
    // Walk backwards toward the driver m_uv of V(uv) until the first sample s
    // becomes equidistant: t_s = (|z-s|^2 - |z-u|^2) / (2 d.(s-u)), d = m - z.
    const Vec<FT> u = P(it.U);
    const Vec<FT> m = (u + P(it.V)) / FT(2);
    const Vec<FT> d = m - it.Z;
    const FT zu = (it.Z - u).SquaredLength();
    link.clear();
    tri.Link(it.U, it.V, link);
    Id best = -1;
    FT bestNum(0), bestDen(1);
    for (const Id s : link)
    {
      if (s == it.W)
      {
        continue;
      }
      const Vec<FT> ps = P(s);
      const FT den = d.Dot(ps - u);
      if (CertainSign(den) <= 0)
      {
        continue;
      }
      const FT num = (it.Z - ps).SquaredLength() - zu;
      if (CertainSign(num) <= 0)
      {
        throw Degenerate("descending walk starts on a Voronoi vertex");
      }
      if (best >= 0)
      {
        const int cmp = CertainSign(num * bestDen - bestNum * den);
        if (cmp == 0)
        {
          throw Degenerate("descending walk meets a Voronoi vertex");
        }
        if (cmp > 0)
        {
          continue;
        }
      }
      best = s;
      bestNum = num;
      bestDen = den;
    }
    // uv is not Gabriel, so some link vertex is strictly closer to m than u: t* < 1.
    if (best < 0 || CertainSign(bestNum - FT(2) * bestDen) >= 0)
    {
      throw Degenerate("descending walk found no exit before the driver");
    }
    const Vec<FT> y = it.Z + d * (bestNum / (FT(2) * bestDen));
    const Id yRef = -1 - static_cast<Id>(points.size());
    points.push_back(y);
    if (withGeometry)
    {
      patch.Triangles.push_back({ { it.U, it.ZRef, yRef } });
      patch.Triangles.push_back({ { it.V, it.ZRef, yRef } });
    }
    // Both V(u s) and V(v s) flow into y (uvs is obtuse at s): two branches.
    queue.push_back({ y, yRef, it.U, best, it.V });
    queue.push_back({ y, yRef, it.V, best, it.U });
  }
  if (withGeometry)
  {
    patch.Constructed.reserve(points.size());
    for (const Vec<FT>& p : points)
    {
      patch.Constructed.push_back(p.ToDouble());
    }
  }
  return patch;
}

} // namespace

Patch ComputeStableManifold(const Triangulation& tri, const CriticalSimplices& cs,
  const std::array<Id, 3>& facet, bool withGeometry, Id& fallbacks)
{
  return Filtered([&](auto ft) { return Walk<decltype(ft)>(tri, cs, facet, withGeometry); },
    fallbacks);
}

} // namespace flowrecon
