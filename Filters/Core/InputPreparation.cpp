#include "InputPreparation.h"

#include "Progress.h"

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace flowrecon
{

PreparedInput PrepareInput(const std::vector<Point3>& points)
{
  PreparedInput in;
  const Id n = static_cast<Id>(points.size());
  Point3 lo{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, hi{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (Id i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (!std::isfinite(points[i][k]))
      {
        throw InputError("point " + std::to_string(i) + " has a non-finite coordinate");
      }
      lo[k] = std::min(lo[k], points[i][k]);
      hi[k] = std::max(hi[k], points[i][k]);
    }
  }
  // Sort ids by coordinates so that equal points are adjacent; the first
  // occurrence (smallest id) represents the others.
  std::vector<Id> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Id(0));
  // The id breaks ties: a total order, so the parallel sort is deterministic.
  tbb::parallel_sort(order.begin(), order.end(),
    [&](Id a, Id b) { return points[a] < points[b] || (points[a] == points[b] && a < b); });
  in.Representative.assign(static_cast<std::size_t>(n), -1);
  for (std::size_t i = 0; i < order.size();)
  {
    std::size_t j = i;
    while (j < order.size() && points[order[j]] == points[order[i]])
    {
      in.Representative[order[j]] = order[i];
      ++j;
    }
    i = j;
  }
  for (Id i = 0; i < n; ++i)
  {
    if (in.Representative[i] == i)
    {
      in.InputId.push_back(i);
      in.Unique.push_back(points[i]);
    }
  }
  if (in.Unique.size() < 4)
  {
    throw InputError("need at least 4 distinct points, got " + std::to_string(in.Unique.size()));
  }
  for (int k = 0; k < 3; ++k)
  {
    in.Centre[k] = 0.5 * lo[k] + 0.5 * hi[k]; // halves: no overflow near the largest doubles
  }
  in.Diagonal =
    2 * std::hypot(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1], 0.5 * hi[2] - 0.5 * lo[2]);
  return in;
}

namespace
{
// SplitMix64: a tiny generator whose output is fixed by the standard, unlike
// std:: distributions.
std::uint64_t SplitMix(std::uint64_t& state)
{
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
} // namespace

std::vector<Point3> Perturb(const std::vector<Point3>& points, double magnitude, std::uint64_t seed)
{
  std::uint64_t state = seed;
  std::vector<Point3> out(points);
  for (Point3& p : out)
  {
    for (double& x : p)
    {
      const double u = static_cast<double>(SplitMix(state) >> 11) * 0x1.0p-53; // [0,1)
      x += magnitude * (2 * u - 1);
    }
  }
  return out;
}

} // namespace flowrecon
