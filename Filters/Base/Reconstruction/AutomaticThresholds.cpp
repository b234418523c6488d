#include "AutomaticThresholds.h"

#include "LocalFlatness.h"
#include "PartGaps.h"
#include "SolidDepth.h"

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

StableWindow StableWindowAt(const std::vector<TopologyStep>& profile, double lo, double hi, double t)
{
  // Row k holds for (Threshold_k, Threshold_k+1]: the last row below t.
  const auto above = std::lower_bound(profile.begin(), profile.end(), t,
    [](const TopologyStep& s, double x) { return s.Threshold < x; });
  StableWindow w;
  if (above == profile.begin())
  {
    return w;
  }
  std::size_t first = static_cast<std::size_t>(above - profile.begin()) - 1, last = first;
  const auto betti = [&](std::size_t k) {
    return std::array<Id, 3>{ { profile[k].Betti[0], profile[k].Betti[1], profile[k].Betti[2] } };
  };
  while (first > 0 && betti(first - 1) == betti(first))
  {
    --first;
  }
  while (last + 1 < profile.size() && betti(last + 1) == betti(last))
  {
    ++last;
  }
  w.From = std::max(profile[first].Threshold, lo);
  w.To = std::min(last + 1 < profile.size() ? profile[last + 1].Threshold : hi, hi);
  w.Betti = betti(first);
  if (!(w.To > w.From && w.From < t && t <= w.To))
  {
    return StableWindow();
  }
  return w;
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

/// Whether Betti numbers with voids can be a union of closed surfaces: each
/// closed orientable surface of genus g adds 2g to b1, so b1 is even. An odd
/// b1 beside a void is a closed surface with a loop more (a membrane across a
/// torus's hole, a tunnel of noise).
bool ClosedSurfaces(const StableWindow& w)
{
  return w.Betti[2] == 0 || w.Betti[1] % 2 == 0;
}

/// How many separate closed surfaces a window can be: its components when
/// each can bound a void of its own (b0 <= b2) and b1 is even, else 1. The
/// reconstructions are nested, so components only join as t_r grows; closed
/// surfaces that are apart over a stable window and joined later, their voids
/// kept, were joined by a bridge across the gap between them (a hole of the
/// sampling cannot split a closed surface in two). A component that cannot
/// bound a void (b0 > b2: a curve or an open sheet beside a surface) may be
/// attached to the surface where its samples thin out, so then no window is
/// preferred for its components.
Id SeparateSurfaces(const StableWindow& w)
{
  return w.Betti[2] > 0 && w.Betti[1] % 2 == 0 && w.Betti[0] <= w.Betti[2] ? w.Betti[0] : 1;
}

/// Whether `w` beats `best` (ties within `tie` go to `best`, the earlier):
/// stable first, then the most voids, then (with voids) an even b1, then the
/// most separate closed surfaces, then the longest.
bool Better(const StableWindow& w, const StableWindow& best, double stable, double tie)
{
  const bool a = w.To >= w.From * stable, b = best.To >= best.From * stable;
  if (best.Length() == 0 || a != b)
  {
    return best.Length() == 0 ? w.Length() > 0 : a;
  }
  if (a && w.Betti[2] != best.Betti[2])
  {
    return w.Betti[2] > best.Betti[2];
  }
  if (a && ClosedSurfaces(w) != ClosedSurfaces(best))
  {
    return ClosedSurfaces(w);
  }
  if (a && SeparateSurfaces(w) != SeparateSurfaces(best))
  {
    return SeparateSurfaces(w) > SeparateSurfaces(best);
  }
  return w.Length() > best.Length() * tie + 1e-12;
}

Id ChangesAt(const std::vector<TopologyStep>& rows, double t)
{
  Id changes = 0;
  for (std::size_t k = 1; k < rows.size(); ++k)
  {
    if (rows[k].Threshold == t)
    {
      for (int d = 0; d < 3; ++d)
      {
        changes += std::abs(rows[k].Betti[d] - rows[k - 1].Betti[d]);
      }
    }
  }
  return changes;
}

/// ThresholdChoice::Apart of `chosen` in its candidate's `profile`.
StableWindow ApartBelow(const std::vector<TopologyStep>& profile, const StableWindow& chosen)
{
  const std::array<Id, 3>& b = chosen.Betti;
  StableWindow apart;
  if (chosen.Length() == 0 || b[2] < 2 || b[0] >= b[2] || b[1] % 2 != 0 || !(chosen.From > 1))
  {
    return apart;
  }
  for (const StableWindow& w : StableWindows(profile, 1, chosen.From))
  {
    if (w.Betti[1] == b[1] && w.Betti[2] == b[2] && w.Betti[0] > b[0] && w.Betti[0] <= b[2])
    {
      apart = w;
    }
  }
  return apart;
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
  for (std::size_t c = 0; c < profiles.size(); ++c)
  {
    StableWindow best;
    for (const StableWindow& w : StableWindows(profiles[c], rule.Lowest, cap))
    {
      best = Better(w, best, rule.Stable, 1) ? w : best;
      choice.Longest = w.Length() > choice.Longest.Length() * rule.Tie + 1e-12 ? w : choice.Longest;
    }
    choice.Best.push_back(best);
    if (Better(best, choice.Window, rule.Stable, rule.Tie))
    {
      choice.Candidate = c;
      choice.Window = best;
    }
  }
  if (choice.Window.Length() == 0)
  {
    choice.Window.From = rule.Lowest;
    choice.Window.To = rule.Lowest;
    // Never past the cap: the run has nothing above it.
    choice.ReconstructionThreshold = std::min(rule.Lowest * rule.Margin, cap);
    return choice;
  }
  const StableWindow& w = choice.Window;
  choice.ChangesAtStart = w.From > rule.Lowest ? ChangesAt(profiles[choice.Candidate], w.From) : 0;
  // Just above the last change, by the margin, but never past the middle.
  choice.ReconstructionThreshold = std::min(w.From * rule.Margin, std::sqrt(w.From * w.To));
  choice.Apart = ApartBelow(profiles[choice.Candidate], w);
  return choice;
}

ThresholdChoice ChoosePersistence(
  const std::vector<std::vector<TopologyStep>>& profiles, double tr, double cap)
{
  if (profiles.empty())
  {
    throw InputError("automatic t_p: no profile");
  }
  ThresholdChoice choice;
  choice.ReconstructionThreshold = tr;
  for (std::size_t c = 0; c < profiles.size(); ++c)
  {
    StableWindow around;
    for (const StableWindow& w : StableWindows(profiles[c], 1, cap))
    {
      if (w.From < tr && tr <= w.To)
      {
        around = w;
      }
    }
    choice.Best.push_back(around);
    if (around.Length() > choice.Window.Length() * choice.Rule.Tie + 1e-12)
    {
      choice.Candidate = c;
      choice.Window = around;
    }
  }
  if (choice.Window.Length() == 0)
  {
    choice.Window.From = choice.Window.To = tr;
  }
  return choice;
}

void CheckFar(ThresholdChoice& choice, const std::vector<Node>& nodes, Id samples)
{
  choice.Far = FindFarSamples(nodes, samples, choice.Rule.FarFactor);
}

void CheckFilled(ThresholdChoice& choice, const std::vector<Point3>& samples, Id maxima)
{
  choice.Maxima = maxima;
  choice.Samples = static_cast<Id>(samples.size());
  choice.Filled = false;
  choice.TooFew = false;
  choice.Flatness = 1;
  if (choice.Window.Length() == 0 || samples.empty())
  {
    return;
  }
  // Below the flatness test's size the solid share says nothing either: a
  // sphere of 30 samples fills with 2 maxima, under a share of 0.125, and one
  // of 150 can stay open (1 0 0, no maximum) over every t_r looked at.
  if (samples.size() < FlatnessMinimumPoints())
  {
    choice.TooFew = choice.Window.Betti[2] == 0;
    return;
  }
  // With voids too: the space between two nested surfaces fills as a solid
  // shell (1 0 1 for two nested cubes of 1 500 samples each).
  if (static_cast<double>(maxima) < choice.Rule.SolidShare * static_cast<double>(samples.size()))
  {
    return;
  }
  choice.Flatness = RelativeFlatness(samples);
  choice.Filled = choice.Flatness < choice.Rule.SurfaceFlatness;
}

namespace
{

/// The window with more voids than `voids` PreferSurface takes, and its candidate.
StableWindow BestHollow(const ThresholdRule& rule, const std::vector<std::vector<TopologyStep>>& profiles,
  double cap, Id voids, std::size_t& candidate)
{
  StableWindow best;
  candidate = 0;
  bool bestStable = false;
  for (std::size_t c = 0; c < profiles.size(); ++c)
  {
    for (const StableWindow& w : StableWindows(profiles[c], rule.Lowest, cap))
    {
      if (w.Betti[2] <= voids)
      {
        continue;
      }
      // Unstable ones too, ordered as Better orders stable ones.
      const bool stable = w.To >= w.From * rule.Stable;
      const bool better = best.Length() == 0 || stable != bestStable ? best.Length() == 0 || stable
        : w.Betti[2] != best.Betti[2]                               ? w.Betti[2] > best.Betti[2]
        : ClosedSurfaces(w) != ClosedSurfaces(best)                 ? ClosedSurfaces(w)
        : SeparateSurfaces(w) != SeparateSurfaces(best) ? SeparateSurfaces(w) > SeparateSurfaces(best)
                                                        : w.Length() > best.Length() * rule.Tie + 1e-12;
      if (better)
      {
        best = w;
        bestStable = stable;
        candidate = c;
      }
    }
  }
  return best;
}

} // namespace

bool PreferSurface(ThresholdChoice& choice, const std::vector<std::vector<TopologyStep>>& profiles, double cap)
{
  const ThresholdRule& rule = choice.Rule;
  std::size_t candidate = 0;
  if (!(choice.Filled || choice.TooFew) || choice.Resurfaced)
  {
    return false;
  }
  const StableWindow best = BestHollow(rule, profiles, cap, choice.Window.Betti[2], candidate);
  if (best.Length() == 0)
  {
    return false;
  }
  choice.Solid = choice.Window;
  choice.Resurfaced = true;
  choice.Candidate = candidate;
  choice.Window = best;
  choice.ChangesAtStart = best.From > rule.Lowest ? ChangesAt(profiles[candidate], best.From) : 0;
  choice.ReconstructionThreshold = std::min(best.From * rule.Margin, std::sqrt(best.From * best.To));
  choice.Apart = ApartBelow(profiles[candidate], best);
  return true;
}

bool ThresholdChoice::NeedsRows() const
{
  return this->Window.Length() > 0 && this->Window.Betti[2] == 0 && this->Window.Betti[0] >= 3 &&
    this->Far.Median > 0;
}

void CheckRows(ThresholdChoice& choice, const std::vector<Node>& nodes, Id samples, const CompactComplex& cells)
{
  choice.Rows = 0;
  choice.RowGap = 0;
  choice.RowGapOfExtent = 0;
  if (!choice.NeedsRows())
  {
    return;
  }
  const PartGaps gaps = FindPartGaps(nodes, samples, cells);
  if (gaps.Parts < 3)
  {
    return;
  }
  const double gap = gaps.Widest / choice.Far.Median;
  if (gap <= choice.Rule.RowFactor)
  {
    choice.Rows = gaps.Parts;
    choice.RowGap = gap;
    choice.RowPlace = gaps.Where;
  }
  // Loops only: arcs so close are a curve broken by its gaps (warned apart),
  // and pieces with cells of their own can be separate objects side by side.
  else if (gaps.Curves && choice.Window.Betti[1] == choice.Window.Betti[0] &&
    gaps.WidestSpan <= choice.Rule.RowExtent)
  {
    choice.Rows = gaps.Parts;
    choice.RowGapOfExtent = gaps.WidestSpan;
    choice.RowGap = gaps.SpanGap / choice.Far.Median;
    choice.RowPlace = gaps.SpanWhere;
  }
}

bool ThresholdChoice::NeedsJoins() const
{
  const auto& b = this->Window.Betti;
  return this->Window.Length() > 0 && b[2] >= 1 && (b[2] > b[0] || this->Filled);
}

bool CheckJoins(ThresholdChoice& choice, const std::vector<Point3>& samples, const CompactComplex& cells,
  std::vector<double>* spacing, double* noise)
{
  const ThresholdRule& rule = choice.Rule;
  choice.Joined.clear();
  choice.JoinRatio = 0;
  choice.JoinPlace = { { 0, 0, 0 } };
  choice.NoisyJoin = false;
  choice.NoiseFlatness = -1;
  const auto& b = choice.Window.Betti;
  // Only where the profile cannot tell (voids sharing a part, a solid around
  // voids): elsewhere the search for the spacing would cost a k-NN pass.
  const bool solid = static_cast<double>(cells.Tetrahedra.size()) >=
    rule.SolidShare * static_cast<double>(samples.size());
  if (choice.Window.Length() == 0 || b[2] < 1 || !(b[2] > b[0] || choice.Filled || solid))
  {
    return false;
  }
  if (spacing && spacing->size() != samples.size())
  {
    *spacing = NeighbourSpacing(samples, {}, rule.JoinNeighbours);
  }
  LongJoins joins = spacing
    ? FindLongJoins(samples, *spacing, cells, rule.JoinFactor, rule.JoinShare, rule.JoinSmallest)
    : FindLongJoins(samples, cells, rule.JoinFactor, rule.JoinNeighbours, rule.JoinShare, rule.JoinSmallest);
  choice.Joined = std::move(joins.Parts);
  choice.JoinRatio = joins.Ratio;
  choice.JoinPlace = joins.Where;
  if (choice.Joined.empty() && b[2] > b[0] && samples.size() >= FlatnessMinimumPoints())
  {
    const FlatnessScale& smallest = FlatnessScales().front();
    if (!(noise && *noise >= 0))
    {
      // Each place once: copies of a sample would make its neighbourhood one
      // point, which says nothing of the noise.
      std::vector<Point3> places(samples);
      std::sort(places.begin(), places.end());
      places.erase(std::unique(places.begin(), places.end()), places.end());
      choice.NoiseFlatness = places.size() >= FlatnessMinimumPoints()
        ? MedianFlatness(places, smallest.K) / smallest.Volume
        : -1;
    }
    else
    {
      choice.NoiseFlatness = *noise;
    }
    if (noise)
    {
      *noise = choice.NoiseFlatness;
    }
    choice.NoisyJoin = choice.NoiseFlatness >= rule.NoisyFlatness;
  }
  return true;
}

bool ThresholdChoice::NeedsDepth() const
{
  return this->Window.Length() > 0 && this->Window.Betti[2] == 0 && !this->Filled && !this->TooFew &&
    this->Samples > 0 &&
    static_cast<double>(this->Maxima) >= this->Rule.SolidShare * static_cast<double>(this->Samples);
}

void CheckShallow(ThresholdChoice& choice, const std::vector<std::array<Id, 4>>& tetrahedra)
{
  choice.Shallow = false;
  choice.Depth = -1;
  if (!choice.NeedsDepth())
  {
    return;
  }
  choice.Depth = SolidDepth(tetrahedra, choice.Rule.ShallowDepth);
  choice.Shallow = choice.Depth >= 0 && choice.Depth <= choice.Rule.ShallowDepth;
}

std::vector<double> MaximumThresholds(
  const std::vector<Node>& nodes, const std::vector<Id>& carriers, const ReconstructionResult& run)
{
  std::vector<double> thresholds;
  for (std::size_t v = 0; v < nodes.size() && v < carriers.size(); ++v)
  {
    if (nodes[v].Index == 3 && !nodes[v].IsInfinity() && carriers[v] >= 0)
    {
      thresholds.push_back(run.Nodes[carriers[v]].Threshold);
    }
  }
  std::sort(thresholds.begin(), thresholds.end());
  return thresholds;
}

Id MaximaBelow(const std::vector<Node>& nodes, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t)
{
  Id count = 0;
  for (std::size_t v = 0; v < nodes.size() && v < carriers.size(); ++v)
  {
    if (nodes[v].Index == 3 && !nodes[v].IsInfinity() && carriers[v] >= 0 &&
      run.Nodes[carriers[v]].Threshold < t)
    {
      ++count;
    }
  }
  return count;
}

} // namespace flowrecon
