// The jumps of the reconstruction profile (paper §5.2): where the threshold, a
// running maximum of the popped priorities, rises. A large jump is the step
// whose node is where the sampling is poorest: what to look at first when
// tracking back an unwanted reconstruction.
#ifndef flowrecon_ProfileJumps_h
#define flowrecon_ProfileJumps_h

#include <cstddef>
#include <vector>

namespace flowrecon
{

/// Step `Step` of the profile, whose threshold rises from `Before` (step
/// Step - 1) to `After`.
struct ProfileJump
{
  std::size_t Step = 0;
  double Before = 0;
  double After = 0;
};

/// The `count` largest rises of `thresholds` (the profile's Threshold column,
/// one value per step), largest first, the earlier step first on ties.
std::vector<ProfileJump> LargestJumps(const std::vector<double>& thresholds, std::size_t count);

} // namespace flowrecon

#endif
