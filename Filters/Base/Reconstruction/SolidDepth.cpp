#include "SolidDepth.h"

#include "CompressedRows.h"
#include "Progress.h" // InputError

#include <algorithm>
#include <cstdint>

namespace flowrecon
{

Id SolidDepth(const std::vector<std::array<Id, 4>>& tetrahedra, Id limit)
{
  if (tetrahedra.empty())
  {
    return -1;
  }
  // Samples renumbered 0..m-1 in id order, so that the stars and the search
  // use 32 bits.
  Id largest = -1;
  for (const std::array<Id, 4>& t : tetrahedra)
  {
    std::array<Id, 4> s = t;
    std::sort(s.begin(), s.end());
    if (s[0] < 0 || s[0] == s[1] || s[1] == s[2] || s[2] == s[3])
    {
      throw InputError("solid depth: a tetrahedron with a negative or repeated sample id");
    }
    largest = std::max(largest, s[3]);
  }
  std::vector<std::int32_t> number(static_cast<std::size_t>(largest) + 1, -1);
  for (const std::array<Id, 4>& t : tetrahedra)
  {
    for (const Id v : t)
    {
      number[v] = 0;
    }
  }
  std::size_t m = 0;
  for (std::int32_t& k : number)
  {
    if (k == 0)
    {
      k = static_cast<std::int32_t>(m++);
    }
  }
  std::vector<std::array<std::int32_t, 4>> cells(tetrahedra.size());
  for (std::size_t i = 0; i < tetrahedra.size(); ++i)
  {
    for (int k = 0; k < 4; ++k)
    {
      cells[i][k] = number[tetrahedra[i][k]];
    }
  }
  number = std::vector<std::int32_t>();
  // Each sample's tetrahedra: its star. A sample is inside when every
  // triangle of its star through it is shared by two of the star's
  // tetrahedra, on the boundary otherwise. Local to each sample, so parallel
  // and without sorting every face (a 10^6-point solid has 2.6·10^7).
  const auto star = CompressedRows<std::int32_t>::Group(m, [&cells](auto&& emit) {
    for (std::size_t t = 0; t < cells.size(); ++t)
    {
      for (const std::int32_t v : cells[t])
      {
        emit(v, static_cast<std::int32_t>(t));
      }
    }
  });
  // Whether v is on the boundary, computed when first asked.
  std::vector<std::int8_t> boundary(m, -1);
  std::vector<std::uint64_t> edges; // the star's triangles through v, by their other two samples
  const auto onBoundary = [&](std::int32_t v) {
    if (boundary[v] >= 0)
    {
      return boundary[v] == 1;
    }
    edges.clear();
    for (const std::int32_t t : star.Row(v))
    {
      std::array<std::uint32_t, 3> o{};
      int n = 0;
      for (const std::int32_t w : cells[t])
      {
        if (w != v)
        {
          o[n++] = static_cast<std::uint32_t>(w);
        }
      }
      std::sort(o.begin(), o.end());
      edges.push_back(std::uint64_t(o[0]) << 32 | o[1]);
      edges.push_back(std::uint64_t(o[0]) << 32 | o[2]);
      edges.push_back(std::uint64_t(o[1]) << 32 | o[2]);
    }
    std::sort(edges.begin(), edges.end());
    bool open = false;
    for (std::size_t i = 0; i < edges.size() && !open;)
    {
      std::size_t j = i + 1;
      while (j < edges.size() && edges[j] == edges[i])
      {
        ++j;
      }
      open = j - i == 1;
      i = j;
    }
    boundary[v] = open ? 1 : 0;
    return open;
  };
  // A sample with no boundary sample within `limit` edges answers at once: a
  // volume sample has many (most of a 10^6-point cube's), found by the first
  // probes, so a deep solid is not searched whole.
  std::vector<std::int32_t> seen(m, -1), ring, next;
  for (std::int32_t probe = 0; probe < static_cast<std::int32_t>(m); ++probe)
  {
    ring.assign(1, probe);
    seen[probe] = probe;
    bool deep = !onBoundary(probe);
    for (Id hop = 0; deep && hop < limit; ++hop)
    {
      next.clear();
      for (std::size_t k = 0; deep && k < ring.size(); ++k)
      {
        for (const std::int32_t t : star.Row(ring[k]))
        {
          for (const std::int32_t w : cells[t])
          {
            if (seen[w] != probe)
            {
              seen[w] = probe;
              next.push_back(w);
              deep = deep && !onBoundary(w);
            }
          }
        }
      }
      ring.swap(next);
    }
    if (deep)
    {
      return limit + 1;
    }
  }
  // Shallow: the depth itself, searched from the boundary's samples.
  std::vector<std::int32_t> depth(m, -1);
  std::vector<std::int32_t> front;
  for (std::int32_t v = 0; v < static_cast<std::int32_t>(m); ++v)
  {
    if (onBoundary(v))
    {
      depth[v] = 0;
      front.push_back(v);
    }
  }
  Id reached = 0;
  while (!front.empty() && reached <= limit)
  {
    std::vector<std::int32_t> following;
    for (const std::int32_t v : front)
    {
      for (const std::int32_t t : star.Row(v))
      {
        for (const std::int32_t w : cells[t])
        {
          if (depth[w] < 0)
          {
            depth[w] = depth[v] + 1;
            following.push_back(w);
          }
        }
      }
    }
    if (following.empty())
    {
      break;
    }
    ++reached;
    front.swap(following);
  }
  return std::min(reached, limit + 1);
}

} // namespace flowrecon
