#include "AutomaticThresholds.h"

#include "Progress.h"

#include <algorithm>
#include <cmath>

namespace flowrecon
{

double StableWindow::Length() const
{
  return this->To > this->From && this->From > 0 ? std::log(this->To / this->From) : 0;
}

std::vector<StableWindow> StableWindows(const std::vector<TopologyStep>& profile, double lo, double hi)
{
  std::vector<StableWindow> windows;
  for (std::size_t k = 0; k < profile.size(); ++k)
  {
    const std::array<Id, 3> betti{ { profile[k].Betti[0], profile[k].Betti[1], profile[k].Betti[2] } };
    const double end = k + 1 < profile.size() ? profile[k + 1].Threshold : hi;
    if (!windows.empty() && windows.back().Betti == betti && windows.back().To >= profile[k].Threshold)
    {
      windows.back().To = end; // rows of equal Betti numbers (a change and its undoing at once)
      continue;
    }
    StableWindow w;
    w.From = profile[k].Threshold;
    w.To = end;
    w.Betti = betti;
    windows.push_back(w);
  }
  std::vector<StableWindow> clipped;
  for (StableWindow w : windows)
  {
    w.From = std::max(w.From, lo);
    w.To = std::min(w.To, hi);
    if (w.To > w.From)
    {
      clipped.push_back(w);
    }
  }
  return clipped;
}

bool ThresholdChoice::CandidatesDisagree() const
{
  for (const StableWindow& w : this->Best)
  {
    if (w.Length() > 0 && w.Betti != this->Window.Betti)
    {
      return true;
    }
  }
  return false;
}

namespace
{

/// The rule on one profile: the earliest stable window, else the longest.
StableWindow Pick(const std::vector<StableWindow>& windows, const ThresholdRule& rule)
{
  StableWindow earliest, longest;
  for (const StableWindow& w : windows)
  {
    if (w.To >= w.From * rule.Stable &&
      (earliest.Length() == 0 || w.From < earliest.From / rule.Tie ||
        (w.From <= earliest.From * rule.Tie && w.Length() > earliest.Length())))
    {
      earliest = w;
    }
    if (w.Length() > longest.Length())
    {
      longest = w;
    }
  }
  return earliest.Length() > 0 ? earliest : longest;
}

} // namespace

ThresholdChoice ChooseThresholds(
  const std::vector<std::vector<TopologyStep>>& profiles, double cap, const ThresholdRule& rule)
{
  if (profiles.empty() || !(cap > rule.Lowest))
  {
    throw InputError("automatic thresholds: no profile, or a cap not above " +
      std::to_string(rule.Lowest));
  }
  ThresholdChoice choice;
  choice.Rule = rule;
  bool found = false;
  for (std::size_t c = 0; c < profiles.size(); ++c)
  {
    const StableWindow w = Pick(StableWindows(profiles[c], rule.Lowest, cap), rule);
    choice.Best.push_back(w);
    if (w.Length() == 0)
    {
      continue;
    }
    const StableWindow& old = choice.Window;
    const bool stable = w.To >= w.From * rule.Stable;
    const bool oldStable = found && old.To >= old.From * rule.Stable;
    bool better = !found;
    if (found && stable != oldStable)
    {
      better = stable;
    }
    else if (found && stable)
    {
      better = w.From < old.From / rule.Tie ||
        (w.From <= old.From * rule.Tie && w.Length() > old.Length() * rule.Tie);
    }
    else if (found)
    {
      better = w.Length() > old.Length() * rule.Tie;
    }
    if (better)
    {
      found = true;
      choice.Candidate = c;
      choice.Window = w;
    }
  }
  if (!found)
  {
    choice.Window.From = rule.Lowest;
    choice.Window.To = rule.Lowest;
    choice.ReconstructionThreshold = rule.Lowest * rule.Margin;
    return choice;
  }
  const StableWindow& w = choice.Window;
  const std::vector<TopologyStep>& rows = profiles[choice.Candidate];
  for (std::size_t k = 1; k < rows.size(); ++k)
  {
    if (rows[k].Threshold == w.From)
    {
      for (int d = 0; d < 3; ++d)
      {
        choice.ChangesAtStart += std::abs(rows[k].Betti[d] - rows[k - 1].Betti[d]);
      }
    }
  }
  // Just above the last change, by the margin, but never past the middle.
  choice.ReconstructionThreshold = std::min(w.From * rule.Margin, std::sqrt(w.From * w.To));
  return choice;
}

} // namespace flowrecon
