#include "ExteriorRegions.h"

#include "FastPredicates.h"
#include "HugePages.h"
#include "UnionFind.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>

namespace flowrecon
{

namespace
{

/// The Voronoi vertices in U_r: the cells of circumradius > r.
std::vector<char> CellsOverLevel(const Triangulation& tri, double levelSq)
{
  const Kernel kernel;
  const auto compare = kernel.compare_squared_radius_3_object();
  const std::size_t n = static_cast<std::size_t>(tri.NumberOfCells());
  std::vector<char> above;
  ReserveHugePopulated(above, n);
  above.resize(n);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      // Memory-bound: fetch the cells ahead, then their vertices.
      if (c + 16 < r.end())
      {
        __builtin_prefetch(&*tri.Cell(static_cast<Id>(c + 16)));
      }
      if (c + 8 < r.end())
      {
        const CellHandle a = tri.Cell(static_cast<Id>(c + 8));
        for (int k = 0; k < 4; ++k)
        {
          __builtin_prefetch(&a->vertex(k)->point());
        }
      }
      const CellHandle h = tri.Cell(static_cast<Id>(c));
      above[c] = compare(h->vertex(0)->point(), h->vertex(1)->point(), h->vertex(2)->point(),
                   h->vertex(3)->point(), levelSq) == CGAL::LARGER;
    }
  });
  return above;
}

/// The components of U_r's graph: cells above joined across the facets whose
/// Voronoi edge lies in U_r; element n is infinity.
UnionFind JoinAcrossFacets(const Triangulation& tri, const std::vector<char>& above, double levelSq)
{
  const Kernel kernel;
  const auto compare = kernel.compare_squared_radius_3_object();
  const Delaunay& dt = tri.Dt();
  const std::size_t n = above.size();
  // The Voronoi edge dual to facet (c, i) lies in U_r, given that its finite
  // ends do: f is not Gabriel (its lowest point is an end) or R_f > r.
  auto edgeAbove = [&](CellHandle c, int i) {
    std::array<const KPoint*, 3> f;
    for (int k = 0, j = 0; k < 4; ++k)
    {
      if (k != i)
      {
        f[j++] = &c->vertex(k)->point();
      }
    }
    if (compare(*f[0], *f[1], *f[2], levelSq) == CGAL::LARGER)
    {
      return true;
    }
    const CellHandle d = c->neighbor(i);
    for (const auto& [cell, apex] : { std::make_pair(c, i), std::make_pair(d, d->index(c)) })
    {
      if (!dt.is_infinite(cell->vertex(apex)) &&
        FastSideOfDiametralSphere(*f[0], *f[1], *f[2], cell->vertex(apex)->point()) ==
          CGAL::ON_BOUNDED_SIDE)
      {
        return true;
      }
    }
    return false;
  };
  // Infinity is joined to every cell whose Voronoi ray lies in U_r.
  UnionFind components(n + 1);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      if (c + 8 < r.end() && above[c + 8])
      {
        const CellHandle a = tri.Cell(static_cast<Id>(c + 8));
        for (int i = 0; i < 4; ++i)
        {
          __builtin_prefetch(&a->neighbor(i)->info());
        }
      }
      if (!above[c])
      {
        continue;
      }
      const CellHandle h = tri.Cell(static_cast<Id>(c));
      for (int i = 0; i < 4; ++i)
      {
        const Id d = tri.CellId(h->neighbor(i));
        const std::size_t other = d < 0 ? n : static_cast<std::size_t>(d);
        // Cells already joined need no predicate (most facets inside a region).
        if ((d < 0 || (other > c && above[other])) &&
          components.FindConcurrent(static_cast<std::int32_t>(c)) != components.FindConcurrent(static_cast<std::int32_t>(other)) &&
          edgeAbove(h, i))
        {
          components.UnionConcurrent(static_cast<std::int32_t>(c), static_cast<std::int32_t>(other));
        }
      }
    }
  });
  return components;
}

} // namespace

ExteriorRegions::ExteriorRegions(const Triangulation& tri, double levelSq)
  : LevelSq(levelSq)
  , TriangulationSerial(tri.Serial())
{
  if (tri.Dimension() != 3)
  {
    throw Degenerate("exterior regions: the triangulation is not 3-dimensional");
  }
  const std::vector<char> above = CellsOverLevel(tri, levelSq);
  UnionFind components = JoinAcrossFacets(tri, above, levelSq);
  this->Label(above, components);
}

void ExteriorRegions::Label(const std::vector<char>& above, UnionFind& components)
{
  const std::size_t n = above.size();
  // Dense region ids in the order of the regions' smallest cells (infinity's
  // last when it is alone), labels in place: a root, the smallest element of
  // its component, comes before the other members, so one scan numbers the
  // roots (as -2 - id) and the members then copy their root's label.
  ReserveHugePopulated(this->Region, n);
  this->Region.assign(n, -1);
  std::vector<std::int32_t>& region = this->Region;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      if (above[c])
      {
        region[c] = components.FindConcurrent(static_cast<std::int32_t>(c));
      }
    }
  });
  for (std::size_t c = 0; c < n; ++c)
  {
    if (region[c] == static_cast<std::int32_t>(c))
    {
      region[c] = -2 - this->Count_++;
      ++this->Above;
    }
    else if (region[c] >= 0)
    {
      ++this->Above;
    }
  }
  const std::int32_t infinity = components.FindConcurrent(static_cast<std::int32_t>(n));
  this->Infinite = infinity == static_cast<std::int32_t>(n) ? this->Count_++ : -2 - region[infinity];
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      if (region[c] >= 0)
      {
        region[c] = region[region[c]]; // a root's label, not changed by this pass
      }
    }
  });
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      region[c] = region[c] == -1 ? -1 : -2 - region[c];
    }
  });
}

} // namespace flowrecon
