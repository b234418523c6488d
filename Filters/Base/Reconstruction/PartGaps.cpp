#include "PartGaps.h"

#include "UnionFind.h"

#include <algorithm>
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
  constexpr double None = std::numeric_limits<double>::infinity();
  std::vector<double> nearest(static_cast<std::size_t>(gaps.Parts), None);
  std::vector<Point3> where(static_cast<std::size_t>(gaps.Parts));
  for (const Node& n : nodes)
  {
    const Id a = n.Simplex[0], b = n.Simplex[1];
    if (n.Index != 1 || !valid(a) || !valid(b) || !in[static_cast<std::size_t>(a)] || !in[static_cast<std::size_t>(b)])
    {
      continue;
    }
    const Id pa = part[static_cast<std::size_t>(parts.Find(static_cast<std::int32_t>(a)))];
    const Id pb = part[static_cast<std::size_t>(parts.Find(static_cast<std::int32_t>(b)))];
    if (pa == pb)
    {
      continue;
    }
    for (const Id p : { pa, pb })
    {
      if (n.Value < nearest[static_cast<std::size_t>(p)])
      {
        nearest[static_cast<std::size_t>(p)] = n.Value;
        where[static_cast<std::size_t>(p)] = n.Location;
      }
    }
  }
  for (Id p = 0; p < gaps.Parts; ++p)
  {
    if (nearest[static_cast<std::size_t>(p)] > gaps.Widest || p == 0)
    {
      gaps.Widest = nearest[static_cast<std::size_t>(p)];
      gaps.Where = where[static_cast<std::size_t>(p)];
    }
  }
  return gaps;
}

} // namespace flowrecon
