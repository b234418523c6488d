#include "ProfileJumps.h"

#include <algorithm>
#include <utility>

namespace flowrecon
{

std::vector<ProfileJump> LargestJumps(const std::vector<double>& thresholds, std::size_t count)
{
  // (-rise, step): the largest rise first, then the earlier step.
  std::vector<std::pair<double, std::size_t>> rises;
  for (std::size_t r = 1; r < thresholds.size(); ++r)
  {
    const double rise = thresholds[r] - thresholds[r - 1];
    if (rise > 0)
    {
      rises.emplace_back(-rise, r);
    }
  }
  const std::size_t kept = std::min(count, rises.size());
  std::partial_sort(rises.begin(), rises.begin() + static_cast<std::ptrdiff_t>(kept), rises.end());
  std::vector<ProfileJump> jumps(kept);
  for (std::size_t j = 0; j < kept; ++j)
  {
    const std::size_t r = rises[j].second;
    jumps[j] = ProfileJump{ r, thresholds[r - 1], thresholds[r] };
  }
  return jumps;
}

} // namespace flowrecon
