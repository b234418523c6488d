#include "ExteriorRegions.h"

#include "FastPredicates.h"
#include "HugePages.h"
#include "UnionFind.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <array>
#include <atomic>
#include <stdexcept>

namespace flowrecon
{

namespace
{

/// The Voronoi vertices that enter U_r: the cells of circumradius > r not in
/// it yet (flag 0), flagged 2.
void MarkCellsOverLevel(const Triangulation& tri, double levelSq, std::vector<char>& above)
{
  const Kernel kernel;
  const auto compare = kernel.compare_squared_radius_3_object();
  const std::size_t n = above.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      if (above[c])
      {
        continue;
      }
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
                   h->vertex(3)->point(), levelSq) == CGAL::LARGER
        ? 2
        : 0;
    }
  });
}

/// Joins the components of U_r's graph (element n is infinity) across the
/// facets of the cells that entered (flag 2) whose Voronoi edge lies in U_r,
/// and across the facets that failed before (`failed`, which then records the
/// facets that fail now; null: nothing is recorded).
void JoinAcrossFacets(const Triangulation& tri, const std::vector<char>& above, double levelSq,
  UnionFind& components, std::vector<std::uint8_t>* failed)
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
  // Infinity is joined to every cell whose Voronoi ray lies in U_r. A facet
  // is tested from one side: a cell that entered, or the smaller of two.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t c = r.begin(); c != r.end(); ++c)
    {
      if (c + 8 < r.end() && above[c + 8] == 2)
      {
        const CellHandle a = tri.Cell(static_cast<Id>(c + 8));
        for (int i = 0; i < 4; ++i)
        {
          __builtin_prefetch(&a->neighbor(i)->info());
        }
      }
      const bool entered = above[c] == 2;
      const std::uint8_t again = failed && above[c] == 1 ? (*failed)[c] : 0;
      if (!entered && again == 0)
      {
        continue;
      }
      const CellHandle h = tri.Cell(static_cast<Id>(c));
      std::uint8_t fails = 0;
      for (int i = 0; i < 4; ++i)
      {
        if (!entered && !(again & (1u << i)))
        {
          continue;
        }
        const Id d = tri.CellId(h->neighbor(i));
        const std::size_t other = d < 0 ? n : static_cast<std::size_t>(d);
        const bool tested = !entered || d < 0 || above[other] == 1 || (above[other] == 2 && other > c);
        // Cells already joined need no predicate (most facets inside a region).
        if (!tested ||
          components.FindConcurrent(static_cast<std::int32_t>(c)) ==
            components.FindConcurrent(static_cast<std::int32_t>(other)))
        {
          continue;
        }
        if (edgeAbove(h, i))
        {
          components.UnionConcurrent(static_cast<std::int32_t>(c), static_cast<std::int32_t>(other));
        }
        else
        {
          fails = static_cast<std::uint8_t>(fails | (1u << i));
        }
      }
      if (failed)
      {
        (*failed)[c] = fails; // this thread's cell only
      }
    }
  });
}

} // namespace

ExteriorRegions::ExteriorRegions(const Triangulation& tri, double levelSq, bool lowerLater)
  : LevelSq(levelSq)
  , TriangulationSerial(tri.Serial())
{
  if (tri.Dimension() != 3)
  {
    throw Degenerate("exterior regions: the triangulation is not 3-dimensional");
  }
  const std::size_t n = static_cast<std::size_t>(tri.NumberOfCells());
  std::vector<char> above;
  ReserveHugePopulated(above, n);
  above.assign(n, 0);
  UnionFind components(n + 1);
  this->Tri = &tri;
  if (lowerLater)
  {
    this->Failed.assign(n, 0);
  }
  this->Enter(above, components, lowerLater ? &this->Failed : nullptr);
  if (lowerLater)
  {
    this->InU = std::move(above);
    this->Components = std::make_unique<UnionFind>(std::move(components));
  }
  else
  {
    this->Tri = nullptr;
  }
}

ExteriorRegions::~ExteriorRegions() = default;

void ExteriorRegions::Descend(double levelSq)
{
  if (!this->Components || !(levelSq <= this->LevelSq))
  {
    throw std::logic_error("exterior regions: descend below the level, on regions kept for it");
  }
  this->LevelSq = levelSq;
  this->Enter(this->InU, *this->Components, &this->Failed);
}

void ExteriorRegions::Enter(
  std::vector<char>& above, UnionFind& components, std::vector<std::uint8_t>* failed)
{
  MarkCellsOverLevel(*this->Tri, this->LevelSq, above);
  JoinAcrossFacets(*this->Tri, above, this->LevelSq, components, failed);
  this->Label(above, components);
  if (failed)
  {
    // Kept for a lower level: what entered now is in U from then on.
    tbb::parallel_for(std::size_t(0), above.size(), [&](std::size_t c) { above[c] = above[c] ? 1 : 0; });
  }
}

void ExteriorRegions::Label(const std::vector<char>& above, UnionFind& components)
{
  const std::size_t n = above.size();
  // Dense region ids in the order of the regions' smallest cells (infinity's
  // last when it is alone), labels in place: a root, the smallest element of
  // its component, comes before the other members, so one scan numbers the
  // roots (as -2 - id) and the members then copy their root's label.
  this->Count_ = 0;
  this->Above = 0;
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
