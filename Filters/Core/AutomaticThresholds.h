// Choosing t_r and t_p from the data. The reconstructions are nested in t_r:
// as t_r grows, holes of the sampling close, then the shape is found, then
// coarser shapes come (solids filled in, parts joined). A stable topology, one
// that holds over a range of t_r, is what a well-sampled shape gives (the
// paper's guarantee holds for a whole interval of t_r), and the finest stable
// one is the shape itself: so the rule takes the first window of constant
// Betti numbers that is long enough, among the topology profiles of a few
// persistence thresholds. The range where the shape holds moves with the
// sampling (i.i.d. samples need more t_r as they grow, regular lattices lose
// patches to the simplification), so no fixed pair is right on every cloud.
// Data/EXPERIMENTS.md gives the rule's measured grounds.
#ifndef flowrecon_AutomaticThresholds_h
#define flowrecon_AutomaticThresholds_h

#include "CellHomology.h"

#include <array>
#include <vector>

namespace flowrecon
{

/// Betti numbers (b0, b1, b2) constant for t_r in (From, To].
struct StableWindow
{
  double From = 0;
  double To = 0;
  std::array<Id, 3> Betti{ { 0, 0, 0 } };
  /// Its length in log t_r.
  double Length() const;
};

/// The maximal windows of constant Betti numbers of `profile` (TopologyProfile
/// rows: row k holds for t_r in (Threshold_k, Threshold_k+1], the last up to
/// `hi`), clipped to (lo, hi]; the windows that do not reach above lo are left
/// out.
std::vector<StableWindow> StableWindows(const std::vector<TopologyStep>& profile, double lo, double hi);

/// The rule's constants (Data/EXPERIMENTS.md).
struct ThresholdRule
{
  double Lowest = 1.5;   ///< windows are looked for in (Lowest, cap]
  double Stable = 1.2;   ///< a window with To/From at least this is stable
  double Margin = 1.1;   ///< t_r = From * Margin, at most the window's middle (log)
  double Short = 1.3;    ///< a chosen window with To/From below this is short: warned
  /// Stable windows starting within this factor of the earliest are ties,
  /// settled for the longer, then for the earlier candidate.
  double Tie = 1.01;
};

struct ThresholdChoice
{
  std::size_t Candidate = 0;     ///< index of the chosen profile
  double ReconstructionThreshold = 2;
  StableWindow Window;           ///< where the chosen Betti numbers hold
  /// Each candidate's window as the rule picks it alone (Length 0: none).
  std::vector<StableWindow> Best;
  bool Short() const { return this->Ratio() < this->Rule.Short; }
  /// No window was stable: the longest was taken.
  bool Unstable() const { return this->Ratio() < this->Rule.Stable; }
  /// Whether another candidate's longest window has other Betti numbers.
  bool CandidatesDisagree() const;
  double Ratio() const { return this->Window.To / this->Window.From; }
  /// How many classes change at once where the window starts (the sum of
  /// |b_i before - b_i in it|; 0 when it starts at Lowest): more than one is a
  /// cascade, a cavity filled together with its walls, which a surface sample
  /// with holes gives (warned).
  Id ChangesAtStart = 0;
  ThresholdRule Rule;
};

/// The earliest stable window over every profile (one per t_p candidate,
/// profiles up to `cap`), and t_r in it; without a stable window, the longest
/// one (Unstable() is then true). A profile with no window above Lowest cannot
/// be chosen; when none has one, t_r is Lowest * Margin on the first candidate.
/// Throws InputError without profiles or with a cap not above Lowest.
ThresholdChoice ChooseThresholds(const std::vector<std::vector<TopologyStep>>& profiles,
  double cap, const ThresholdRule& rule = ThresholdRule());

} // namespace flowrecon

#endif
