// What Flow Reconstruction's outputs say, read back as plain values for a text
// report: the Betti numbers at a threshold (the topology profile), the
// under-sampled places in words (the under-sampling points) and the largest
// jumps of the profile. `flowrecon reconstruct` prints them, from the filter's
// outputs or from the same outputs built by ReconstructCloud.
#ifndef ReconstructionReport_h
#define ReconstructionReport_h

#include "AutomaticThresholds.h" // core: ThresholdChoice
#include "FlowComplex.h"  // core: Id
#include "ProfileJumps.h" // core data structure

#include <array>
#include <string>
#include <vector>

class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// b0, b1, b2 at t_r = `t` from the topology profile (TopologyToVTK's table:
/// row k holds for t_r in (Threshold_k, Threshold_k+1]). Returns false for an
/// empty table (the Betti numbers were skipped); throws InputError when a
/// column is missing.
bool BettiNumbersAt(vtkTable* topology, double t, std::array<long long, 3>& betti);

/// The rows of the topology profile (TopologyToVTK's table) as the core's
/// TopologyStep; empty for an empty table.
std::vector<TopologyStep> TopologyRows(vtkTable* topology);

/// What an automatic choice says (the thresholds, the Betti numbers and their
/// window): "t_r 3.3 (auto), t_p 1.1 (auto): Betti numbers 1 2 1, unchanged
/// for t_r in (3.00, 6.00]". `tps` are the t_p candidates, in the choice's order.
std::string DescribeChoice(const ThresholdChoice& choice, const std::vector<double>& tps,
  bool trChosen, bool tpChosen);

/// The choice's warnings, one line each. With t_r chosen: no stable topology,
/// a short window, a window opened by several changes at once, a longer
/// window with other Betti numbers; with t_p chosen: another t_p whose most
/// stable (or, t_r given, whose) Betti numbers differ.
std::vector<std::string> ChoiceWarnings(const ThresholdChoice& choice,
  const std::vector<double>& tps, bool trChosen, bool tpChosen);
/// ChoiceWarnings' two parts: those of a chosen t_r, and those of a chosen t_p.
std::vector<std::string> ReconstructionChoiceWarnings(const ThresholdChoice& choice);
std::vector<std::string> PersistenceChoiceWarnings(
  const ThresholdChoice& choice, const std::vector<double>& tps, bool trChosen);

/// One line for people saying what the reconstruction at t_r = `t` is, read
/// back from the outputs as written: "Betti numbers 1 2 1 at t_r 3.100 (auto),
/// t_p 1.1 (auto); unchanged for 3.00 < t_r <= 4.00; 2 warnings". The Betti
/// numbers at `t` from the rows of `topology` (the last holds up to `limit`),
/// else the field data BettiNumbers of `grid`; from the field data of `grid`
/// PersistenceThreshold, ThresholdsChosen, StableWindow (else the range is the
/// profile's) and ThresholdWarnings; the warnings are counted as the command
/// line prints them, the lines of ThresholdWarnings and one per place of
/// `undersampling`. Without Betti numbers: "t_r 2.000: no Betti numbers"
/// followed by `why`.
/// `profile`, when given, is the table's rows (TopologyRows), not read again.
std::string TopologyLine(vtkUnstructuredGrid* grid, vtkTable* topology,
  vtkPolyData* undersampling, double t, double limit, const std::string& why,
  const std::vector<TopologyStep>* profile = nullptr);

/// The number of steps of `profile` (ReconstructionToVTK's table) with
/// Threshold < t: the steps of the reconstruction at t_r = t.
long long StepsBelow(vtkTable* profile, double t);

/// A jump of the profile (LargestJumps) with the node of its step.
struct ProfileJumpNode
{
  ProfileJump Jump;
  Id Node = -1;
  int Index = -1;
};

/// The `count` largest jumps of `profile`'s Threshold column, largest first.
std::vector<ProfileJumpNode> LargestProfileJumps(vtkTable* profile, std::size_t count);

/// The under-sampling points (UnderSamplingToVTK) of one node, one t_r, one
/// dimension and one direction of change: one place in a report.
struct UnderSampledPlace
{
  std::array<double, 3> Location{ { 0, 0, 0 } }; ///< of the first such point
  double Spacing = 0;
  double Threshold = 0; ///< the t_r above which the topology changes there
  int Dimension = 0;    ///< 0 to 3
  bool Appears = false; ///< a class appears (Change +1), else one goes
  Id Node = -1;
  int Count = 0; ///< how many changes
};

/// The places of `warnings` in the order of their first point (the nearest
/// t_r first); none when it lacks the arrays.
std::vector<UnderSampledPlace> UnderSampledPlaces(vtkPolyData* warnings);

/// "under-sampled near (x, y, z): spacing s; at t_r t a hole closes" ("2 holes
/// close" for two changes).
std::string Describe(const UnderSampledPlace& place);

/// "(x, y, z)" with enough significant digits (6 at least) that a step of
/// `resolution` shows, however far x is from the origin: a georeferenced scan
/// sits at 10^6 units and more, where 6 digits do not tell places apart.
std::string PlaceText(const std::array<double, 3>& x, double resolution);

} // namespace flowrecon

#endif
