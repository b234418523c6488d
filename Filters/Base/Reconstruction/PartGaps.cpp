#include "PartGaps.h"

#include "UnionFind.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace flowrecon
{

PartGaps FindPartGaps(const std::vector<Node>& nodes, Id samples, const CompactComplex& cells)
{
  PartGaps gaps;
  samples = std::max<Id>(samples, 0);
  auto valid = [samples](Id s) { return s >= 0 && s < samples; };
  std::vector<char> in(static_cast<std::size_t>(samples), 0);
  UnionFind parts(static_cast<std::size_t>(samples));
  JoinCells(cells, samples, in, parts);
  // Dense part ids, by their roots.
  std::vector<Id> part(static_cast<std::size_t>(samples), -1);
  for (Id s = 0; s < samples; ++s)
  {
    const std::size_t root = static_cast<std::size_t>(parts.Find(static_cast<std::int32_t>(s)));
    if (in[static_cast<std::size_t>(s)] && part[root] < 0)
    {
      part[root] = gaps.Parts++;
    }
  }
  if (gaps.Parts < 2)
  {
    return gaps;
  }
  gaps.Curves = cells.Triangles.empty() && cells.Tetrahedra.empty();
  constexpr double None = std::numeric_limits<double>::infinity();
  const std::size_t count = static_cast<std::size_t>(gaps.Parts);
  std::vector<double> nearest(count, None);
  std::vector<Id> neighbour(count, -1);
  std::vector<Point3> where(count);
  // Each part's bounding box, from its samples' index-0 nodes.
  std::vector<std::array<double, 6>> box(count, { { None, None, None, -None, -None, -None } });
  auto partOf = [&](Id s) {
    return part[static_cast<std::size_t>(parts.Find(static_cast<std::int32_t>(s)))];
  };
  for (const Node& n : nodes)
  {
    const Id s = n.Simplex[0];
    if (n.Index != 0 || !valid(s) || !in[static_cast<std::size_t>(s)])
    {
      continue;
    }
    std::array<double, 6>& b = box[static_cast<std::size_t>(partOf(s))];
    for (int k = 0; k < 3; ++k)
    {
      b[k] = std::min(b[k], n.Location[k]);
      b[k + 3] = std::max(b[k + 3], n.Location[k]);
    }
  }
  auto extent = [&](Id p) {
    const std::array<double, 6>& b = box[static_cast<std::size_t>(p)];
    double sq = 0;
    for (int k = 0; k < 3; ++k)
    {
      sq += b[k + 3] > b[k] ? (b[k + 3] - b[k]) * (b[k + 3] - b[k]) : 0;
    }
    return std::sqrt(sq);
  };
  for (const Node& n : nodes)
  {
    const Id a = n.Simplex[0], b = n.Simplex[1];
    if (n.Index != 1 || !valid(a) || !valid(b) || !in[static_cast<std::size_t>(a)] || !in[static_cast<std::size_t>(b)])
    {
      continue;
    }
    const Id pa = partOf(a), pb = partOf(b);
    if (pa == pb)
    {
      continue;
    }
    for (const auto& [p, q] : { std::make_pair(pa, pb), std::make_pair(pb, pa) })
    {
      const std::size_t k = static_cast<std::size_t>(p);
      // Ties (regular samplings have many) go to the least place, so that
      // no numbering of the samples or the parts decides.
      if (n.Value < nearest[k] || (n.Value == nearest[k] && n.Location < where[k]))
      {
        nearest[k] = n.Value;
        neighbour[k] = q;
        where[k] = n.Location;
      }
    }
  }
  for (Id p = 0; p < gaps.Parts; ++p)
  {
    const std::size_t k = static_cast<std::size_t>(p);
    if (p == 0 || nearest[k] > gaps.Widest || (nearest[k] == gaps.Widest && where[k] < gaps.Where))
    {
      gaps.Widest = nearest[k];
      gaps.Where = where[k];
    }
    // The gap is twice the edge's value (its midpoint's distance to both ends).
    const Id q = neighbour[k];
    const double size = q < 0 ? 0 : std::max(extent(p), extent(q));
    const double span = q < 0 ? None : size > 0 ? 2 * nearest[k] / size : None;
    if (p == 0 || span > gaps.WidestSpan || (span == gaps.WidestSpan && where[k] < gaps.SpanWhere))
    {
      gaps.WidestSpan = span;
      gaps.SpanGap = nearest[k];
      gaps.SpanWhere = where[k];
    }
  }
  return gaps;
}

} // namespace flowrecon
