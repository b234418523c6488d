#include "SolidDepth.h"

#include "CompressedRows.h"
#include "Progress.h" // InputError

#include <tbb/parallel_sort.h>

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
  // Samples renumbered 0..m-1 in id order, so that the faces and the search
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
  const auto local = [&number](Id v) { return number[v]; };
  std::vector<std::array<std::int32_t, 4>> cells(tetrahedra.size());
  std::vector<std::array<std::int32_t, 3>> faces;
  faces.reserve(4 * tetrahedra.size());
  for (std::size_t i = 0; i < tetrahedra.size(); ++i)
  {
    std::array<std::int32_t, 4>& c = cells[i];
    for (int k = 0; k < 4; ++k)
    {
      c[k] = local(tetrahedra[i][k]);
    }
    std::sort(c.begin(), c.end());
    faces.push_back({ { c[1], c[2], c[3] } });
    faces.push_back({ { c[0], c[2], c[3] } });
    faces.push_back({ { c[0], c[1], c[3] } });
    faces.push_back({ { c[0], c[1], c[2] } });
  }
  tbb::parallel_sort(faces.begin(), faces.end());
  number = std::vector<std::int32_t>();
  // The boundary's samples start the search at depth 0.
  std::vector<std::int32_t> depth(m, -1);
  std::vector<std::int32_t> front;
  for (std::size_t i = 0; i < faces.size();)
  {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j] == faces[i])
    {
      ++j;
    }
    if (j - i == 1)
    {
      for (const std::int32_t v : faces[i])
      {
        if (depth[v] < 0)
        {
          depth[v] = 0;
          front.push_back(v);
        }
      }
    }
    i = j;
  }
  faces = std::vector<std::array<std::int32_t, 3>>();
  // Each sample's neighbours along the tetrahedra's edges (repeats are harmless).
  const auto next = CompressedRows<std::int32_t>::Group(m, [&cells](auto&& emit) {
    for (const std::array<std::int32_t, 4>& c : cells)
    {
      for (int a = 0; a < 4; ++a)
      {
        for (int b = 0; b < 4; ++b)
        {
          if (a != b)
          {
            emit(c[a], c[b]);
          }
        }
      }
    }
  });
  cells = std::vector<std::array<std::int32_t, 4>>();
  Id reached = 0;
  while (!front.empty() && reached <= limit)
  {
    std::vector<std::int32_t> following;
    for (const std::int32_t v : front)
    {
      for (const std::int32_t w : next.Row(v))
      {
        if (depth[w] < 0)
        {
          depth[w] = depth[v] + 1;
          following.push_back(w);
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
