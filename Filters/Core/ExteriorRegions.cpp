#include "ExteriorRegions.h"

#include "FastPredicates.h"
#include "HugePages.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>

namespace flowrecon
{

namespace
{

/// Union-find for concurrent unions: a root is the smallest element of its
/// component whatever the order of the unions, so the result is deterministic.
class ConcurrentUnionFind
{
public:
  explicit ConcurrentUnionFind(std::size_t n)
  {
    ReserveHugePopulated(this->Parent, n);
    this->Parent.resize(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { this->Parent[i] = static_cast<std::int32_t>(i); });
  }

  std::int32_t Find(std::int32_t x)
  {
    while (true)
    {
      std::int32_t p = __atomic_load_n(&this->Parent[x], __ATOMIC_RELAXED);
      if (p == x)
      {
        return x;
      }
      const std::int32_t g = __atomic_load_n(&this->Parent[p], __ATOMIC_RELAXED);
      if (g != p)
      {
        // Halving; losing the race only leaves a longer path.
        __atomic_compare_exchange_n(&this->Parent[x], &p, g, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
      }
      x = p;
    }
  }

  void Union(std::int32_t a, std::int32_t b)
  {
    while (true)
    {
      a = this->Find(a);
      b = this->Find(b);
      if (a == b)
      {
        return;
      }
      if (a < b)
      {
        std::swap(a, b);
      }
      // Link the larger root under the smaller, if it is still a root.
      std::int32_t expected = a;
      if (__atomic_compare_exchange_n(&this->Parent[a], &expected, b, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
      {
        return;
      }
    }
  }

private:
  // Plain integers under GCC's atomic built-ins: a vector of std::atomic
  // cannot be sized after a reserve (for huge pages).
  std::vector<std::int32_t> Parent;
};

} // namespace

ExteriorRegions::ExteriorRegions(const Triangulation& tri, double levelSq)
  : LevelSq(levelSq)
  , TriangulationSerial(tri.Serial())
{
  if (tri.Dimension() != 3)
  {
    throw Degenerate("exterior regions: the triangulation is not 3-dimensional");
  }
  const Kernel kernel;
  const auto compare = kernel.compare_squared_radius_3_object();
  const Delaunay& dt = tri.Dt();
  const std::size_t n = static_cast<std::size_t>(tri.NumberOfCells());
  // The Voronoi vertices in U_r: cells of circumradius > r.
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
  // Element n: infinity, joined to every cell whose Voronoi ray lies in U_r.
  ConcurrentUnionFind components(n + 1);
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
          components.Find(static_cast<std::int32_t>(c)) != components.Find(static_cast<std::int32_t>(other)) &&
          edgeAbove(h, i))
        {
          components.Union(static_cast<std::int32_t>(c), static_cast<std::int32_t>(other));
        }
      }
    }
  });
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
        region[c] = components.Find(static_cast<std::int32_t>(c));
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
  const std::int32_t infinity = components.Find(static_cast<std::int32_t>(n));
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
