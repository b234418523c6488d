#include "FarSamples.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flowrecon
{

FarSamples FindFarSamples(const std::vector<Node>& nodes, Id samples, double factor)
{
  FarSamples far;
  samples = std::max<Id>(samples, 0);
  auto valid = [samples](Id s) { return s >= 0 && s < samples; };
  // Each sample's shortest edge (node values: half the lengths).
  constexpr double None = std::numeric_limits<double>::infinity();
  std::vector<double> nearest(static_cast<std::size_t>(samples), None);
  for (const Node& n : nodes)
  {
    if (n.Index == 1 && valid(n.Simplex[0]) && valid(n.Simplex[1]))
    {
      for (int k = 0; k < 2; ++k)
      {
        double& d = nearest[static_cast<std::size_t>(n.Simplex[k])];
        d = std::min(d, n.Value);
      }
    }
  }
  std::vector<double> known;
  known.reserve(nearest.size());
  std::copy_if(nearest.begin(), nearest.end(), std::back_inserter(known), [](double d) { return d < None; });
  if (known.empty())
  {
    return far;
  }
  const auto middle = known.begin() + static_cast<std::ptrdiff_t>(known.size() / 2);
  std::nth_element(known.begin(), middle, known.end());
  far.Median = *middle;
  if (!(far.Median > 0))
  {
    return far;
  }
  Id farthest = -1;
  for (std::size_t s = 0; s < nearest.size(); ++s)
  {
    if (nearest[s] < None && nearest[s] > factor * far.Median)
    {
      ++far.Count;
      farthest = farthest < 0 || nearest[s] > nearest[static_cast<std::size_t>(farthest)] ? static_cast<Id>(s) : farthest;
    }
  }
  if (farthest >= 0)
  {
    far.Largest = nearest[static_cast<std::size_t>(farthest)] / far.Median;
    for (const Node& n : nodes)
    {
      if (n.Index == 0 && n.Simplex[0] == farthest)
      {
        far.Farthest = n.Location;
        break;
      }
    }
  }
  return far;
}

} // namespace flowrecon
