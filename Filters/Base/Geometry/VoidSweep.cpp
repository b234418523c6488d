#include "VoidSweep.h"

#include "UnionFind.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace flowrecon
{

namespace
{

/// The regions of the complement, merged as t goes down. Each component keeps
/// its cells in a circular list (spliced in O(1)) and whether it is unbounded
/// or holds a maximum ("open"): an open component never closes again, so a
/// cell's void range ends where its component first opens.
class Regions
{
public:
  Regions(std::size_t cells, const std::vector<std::int32_t>& maxima)
    : Sets(cells + 1)
    , Next(cells + 1)
    , Open(cells + 1, 0)
  {
    std::iota(this->Next.begin(), this->Next.end(), 0);
    for (const std::int32_t c : maxima)
    {
      this->Open[c] = 1;
    }
    this->Open[cells] = 1; // the infinite cells: unbounded
  }

  /// Joins the regions of a and b at threshold `key`; the cells of a region
  /// that opens here receive their range (key, entry] through `closed`.
  template <class Closed>
  void Join(std::int32_t a, std::int32_t b, double key, const Closed& closed)
  {
    a = this->Sets.Find(a);
    b = this->Sets.Find(b);
    if (a == b)
    {
      return;
    }
    if (this->Open[a] != this->Open[b])
    {
      const std::int32_t shut = this->Open[a] ? b : a;
      std::int32_t x = shut;
      do
      {
        closed(x, key);
        x = this->Next[x];
      } while (x != shut);
    }
    const bool open = this->Open[a] || this->Open[b];
    std::swap(this->Next[a], this->Next[b]); // one list
    const std::int32_t root = this->Sets.Merge(a, b) == a ? b : a;
    this->Open[root] = open ? 1 : 0;
  }

  /// Every cell whose region never opened (none once every facet is open).
  template <class Closed>
  void Finish(const Closed& closed)
  {
    const std::int32_t n = static_cast<std::int32_t>(this->Open.size());
    for (std::int32_t c = 0; c < n; ++c)
    {
      if (this->Sets.Find(c) == c && !this->Open[c])
      {
        std::int32_t x = c;
        do
        {
          closed(x, -HUGE_VAL);
          x = this->Next[x];
        } while (x != c);
      }
    }
  }

private:
  UnionFind Sets;
  std::vector<std::int32_t> Next;
  std::vector<std::uint8_t> Open;
};

} // namespace

std::vector<VoidCell> SweepVoids(const VoidSweepInput& in, const Progress& progress)
{
  const auto& neighbours = *in.Neighbours;
  const auto& claims = *in.Claims;
  const auto& start = *in.GroupStart;
  const auto& entry = *in.GroupEntry;
  const std::size_t cells = neighbours.size();
  if (cells >= static_cast<std::size_t>(INT32_MAX))
  {
    throw InputError("compact output: more than 2^31 Delaunay cells");
  }
  const std::int32_t outside = static_cast<std::int32_t>(cells);
  const auto cellEntry = [&](std::int32_t c) {
    if (c == outside || in.CellMaximum->empty() || (*in.CellMaximum)[c] < 0)
    {
      return HUGE_VAL;
    }
    return (*in.NodeEntry)[(*in.CellMaximum)[c]];
  };
  // The claimed facets: a bit per facet, and (4 * cell + facet, group) sorted.
  std::vector<std::uint8_t> claimed(cells, 0);
  std::vector<std::pair<std::int64_t, std::int32_t>> facetGroup;
  const std::size_t groups = entry.size();
  for (std::size_t g = 0; g < groups; ++g)
  {
    const CompactClaim& c = claims[start[g]];
    for (int side = 0; side < 2; ++side)
    {
      if (c.Cells[side] >= 0)
      {
        claimed[c.Cells[side]] |= static_cast<std::uint8_t>(1u << c.Facets[side]);
        facetGroup.emplace_back(4 * std::int64_t(c.Cells[side]) + c.Facets[side],
          static_cast<std::int32_t>(g));
      }
    }
  }
  std::sort(facetGroup.begin(), facetGroup.end());
  const auto groupOf = [&](std::int32_t c, int k) -> std::int32_t {
    if (!(claimed[c] & (1u << k)))
    {
      return -1;
    }
    const auto it = std::lower_bound(
      facetGroup.begin(), facetGroup.end(), std::make_pair(4 * std::int64_t(c) + k, -1));
    return it->second;
  };
  const auto facetEntry = [&](std::int32_t c, int k) {
    const std::int32_t g = groupOf(c, k);
    return g < 0 ? HUGE_VAL : entry[g];
  };
  progress(0.2, "compact voids");

  std::vector<VoidCell> voids;
  const auto closed = [&](std::int32_t c, double key) {
    const double high = cellEntry(c);
    if (c != outside && key < high)
    {
      VoidCell v;
      v.Cell = c;
      v.Low = key;
      v.High = high;
      voids.push_back(v);
    }
  };
  Regions regions(cells, *in.Maxima);
  // A cell joins a neighbour at the least of their entries and their facet's:
  // each pair is joined by whichever of the three comes last going down.
  const auto joinAround = [&](std::int32_t c, double key) {
    for (int k = 0; k < 4; ++k)
    {
      const std::int32_t n = neighbours[c][k] < 0 ? outside : neighbours[c][k];
      if (facetEntry(c, k) >= key && cellEntry(n) >= key)
      {
        regions.Join(c, n, key, closed);
      }
    }
  };
  // Above every entry: the cells that are never solid, across open facets.
  std::vector<std::pair<double, std::int64_t>> events; // (key, cell or -1 - group)
  for (std::int32_t c = 0; c < outside; ++c)
  {
    const double key = cellEntry(c);
    if (key == HUGE_VAL)
    {
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t n = neighbours[c][k] < 0 ? outside : neighbours[c][k];
        if (groupOf(c, k) < 0 && cellEntry(n) == HUGE_VAL)
        {
          regions.Join(c, n, HUGE_VAL, closed);
        }
      }
    }
    else
    {
      events.emplace_back(key, c);
    }
  }
  for (std::size_t g = 0; g < groups; ++g)
  {
    events.emplace_back(entry[g], -1 - static_cast<std::int64_t>(g));
  }
  std::sort(events.begin(), events.end(),
    [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
  progress(0.5, "compact voids");
  for (std::size_t e = 0; e < events.size(); ++e)
  {
    const double key = events[e].first;
    if (events[e].second >= 0)
    {
      joinAround(static_cast<std::int32_t>(events[e].second), key);
      continue;
    }
    const CompactClaim& c = claims[start[static_cast<std::size_t>(-1 - events[e].second)]];
    const std::int32_t a = c.Cells[0] < 0 ? outside : c.Cells[0];
    const std::int32_t b = c.Cells[1] < 0 ? outside : c.Cells[1];
    if (cellEntry(a) >= key && cellEntry(b) >= key)
    {
      regions.Join(a, b, key, closed);
    }
  }
  regions.Finish(closed);
  progress(0.9, "compact voids");

  std::sort(voids.begin(), voids.end(),
    [](const VoidCell& a, const VoidCell& b) { return a.Cell < b.Cell; });
  for (VoidCell& v : voids)
  {
    for (int k = 0; k < 4; ++k)
    {
      v.Neighbours[k] = neighbours[v.Cell][k];
      v.Walls[k] = groupOf(v.Cell, k);
    }
  }
  progress(1.0, "compact voids");
  return voids;
}

} // namespace flowrecon
