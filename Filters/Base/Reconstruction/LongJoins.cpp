#include "LongJoins.h"

#include "UnionFind.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace flowrecon
{

std::vector<double> NeighbourSpacing(const std::vector<Point3>& samples, const std::vector<char>& wanted, int k)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Search_traits_3<K>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  std::vector<double> spacing(samples.size(), 0.0);
  if (samples.size() < 2 || k < 1)
  {
    return spacing;
  }
  std::vector<K::Point_3> pts;
  pts.reserve(samples.size());
  for (const Point3& p : samples)
  {
    pts.emplace_back(p[0], p[1], p[2]);
  }
  Search::Tree tree(pts.begin(), pts.end());
  tree.build(); // before the concurrent searches, which would each build it
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i != r.end(); ++i)
    {
      if (!wanted.empty() && !wanted[i])
      {
        continue;
      }
      // Sorted by distance, the sample's own place first; duplicates (at 0)
      // are no neighbours, so ask for more while they fill the answer.
      std::size_t asked = static_cast<std::size_t>(k) + 1;
      for (;;)
      {
        asked = std::min(asked, pts.size());
        const Search search(tree, pts[i], static_cast<unsigned>(asked));
        double last = 0;
        int found = 0;
        for (const auto& hit : search)
        {
          if (hit.second > 0)
          {
            last = hit.second;
            if (++found == k)
            {
              break;
            }
          }
        }
        if (found == k || asked == pts.size())
        {
          spacing[i] = std::sqrt(last);
          break;
        }
        asked *= 2;
      }
    }
  });
  return spacing;
}

namespace
{

/// Calls f(a, b) for every edge of every cell of `cells` whose ends are below n.
template <class F>
void ForEachEdge(const CompactComplex& cells, Id n, F&& f)
{
  const auto pairs = [&](const auto& ids) {
    for (std::size_t i = 0; i < ids.size(); ++i)
    {
      for (std::size_t j = i + 1; j < ids.size(); ++j)
      {
        if (ids[i] >= 0 && ids[i] < n && ids[j] >= 0 && ids[j] < n)
        {
          f(ids[i], ids[j]);
        }
      }
    }
  };
  for (const auto& e : cells.Edges)
  {
    pairs(e);
  }
  for (const auto& t : cells.Triangles)
  {
    pairs(t);
  }
  for (const auto& t : cells.Tetrahedra)
  {
    pairs(t);
  }
}

double Distance(const Point3& a, const Point3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// The sizes of the components of `parts` over the samples in `used`, of at
/// least `least` samples each, largest first; `size` gets every root's size.
std::vector<Id> LargeParts(UnionFind& parts, const std::vector<char>& used, Id least, std::vector<Id>& size)
{
  size.assign(used.size(), 0);
  for (std::size_t v = 0; v < used.size(); ++v)
  {
    if (used[v])
    {
      ++size[static_cast<std::size_t>(parts.Find(static_cast<std::int32_t>(v)))];
    }
  }
  std::vector<Id> large;
  for (const Id s : size)
  {
    if (s >= least)
    {
      large.push_back(s);
    }
  }
  std::sort(large.rbegin(), large.rend());
  return large;
}

/// Which samples `cells` hold.
std::vector<char> InCells(const CompactComplex& cells, Id n)
{
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  for (const Id v : cells.Vertices)
  {
    if (v >= 0 && v < n)
    {
      used[static_cast<std::size_t>(v)] = 1;
    }
  }
  ForEachEdge(cells, n, [&](Id a, Id b) { used[static_cast<std::size_t>(a)] = used[static_cast<std::size_t>(b)] = 1; });
  return used;
}

} // namespace

LongJoins FindLongJoins(const std::vector<Point3>& samples, const CompactComplex& cells, double factor, int k,
  double share, Id smallest)
{
  return FindLongJoins(samples, NeighbourSpacing(samples, InCells(cells, static_cast<Id>(samples.size())), k), cells,
    factor, share, smallest);
}

LongJoins FindLongJoins(const std::vector<Point3>& samples, const std::vector<double>& spacing,
  const CompactComplex& cells, double factor, double share, Id smallest)
{
  LongJoins joins;
  const Id n = static_cast<Id>(std::min(samples.size(), spacing.size()));
  const std::vector<char> used = InCells(cells, n);
  const Id inCells = static_cast<Id>(std::count(used.begin(), used.end(), 1));
  const Id least = std::max(smallest, static_cast<Id>(std::ceil(share * static_cast<double>(inCells))));
  const auto ratio = [&](Id a, Id b) {
    const double s = std::min(spacing[static_cast<std::size_t>(a)], spacing[static_cast<std::size_t>(b)]);
    const double d = Distance(samples[static_cast<std::size_t>(a)], samples[static_cast<std::size_t>(b)]);
    return s > 0 ? d / s : (d > 0 ? HUGE_VAL : 0.0);
  };
  UnionFind all(used.size());
  UnionFind held(used.size());
  ForEachEdge(cells, n, [&](Id a, Id b) {
    all.Merge(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b));
    if (ratio(a, b) <= factor)
    {
      held.Merge(static_cast<std::int32_t>(a), static_cast<std::int32_t>(b));
    }
  });
  std::vector<Id> size;
  const std::size_t before = LargeParts(all, used, least, size).size();
  std::vector<Id> parts = LargeParts(held, used, least, size);
  if (parts.size() <= before)
  {
    return joins;
  }
  joins.Parts = std::move(parts);
  // Where two large parts meet: the least long of the edges between them
  // (first met on ties: the cells' order is deterministic).
  joins.Ratio = HUGE_VAL;
  ForEachEdge(cells, n, [&](Id a, Id b) {
    const std::int32_t ra = held.Find(static_cast<std::int32_t>(a));
    const std::int32_t rb = held.Find(static_cast<std::int32_t>(b));
    if (ra != rb && size[static_cast<std::size_t>(ra)] >= least && size[static_cast<std::size_t>(rb)] >= least)
    {
      const double r = ratio(a, b);
      if (r < joins.Ratio)
      {
        joins.Ratio = r;
        const Point3& p = samples[static_cast<std::size_t>(a)];
        const Point3& q = samples[static_cast<std::size_t>(b)];
        joins.Where = { { (p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2 } };
      }
    }
  });
  if (joins.Ratio == HUGE_VAL)
  {
    joins.Ratio = 0; // joined through small parts only: no edge between two large ones
  }
  return joins;
}

} // namespace flowrecon
