// Choosing t_r and t_p from the data. The reconstructions are nested in t_r:
// as t_r grows, the holes of the sampling close, voids appear where a surface
// closes, then coarser shapes come: voids filled into solids, parts joined. A
// topology that holds over a range of t_r is what a well-sampled shape gives
// (the paper's guarantee holds for an interval of t_r). Among the stable
// windows of the topology profiles of a few persistence thresholds, the rule
// takes the one enclosing the most voids (a surface with a hole not closed
// yet, and the solid that fills it later, both have fewer), among those one
// that can be closed surfaces (even b1), then the one with the most closed
// surfaces apart (components join as t_r grows: surfaces apart over a stable
// window, joined later with their voids kept, were bridged across a gap), the
// longest among those. The range where the shape holds moves with the sampling (i.i.d.
// samples need more t_r as they grow, regular lattices lose patches to the
// simplification), so no fixed pair is right on every cloud.
// Data/EXPERIMENTS.md gives the rule's measured grounds.
#ifndef flowrecon_AutomaticThresholds_h
#define flowrecon_AutomaticThresholds_h

#include "CellHomology.h"
#include "CompactReconstruction.h"
#include "FarSamples.h"
#include "LongJoins.h"
#include "Reconstruction.h"

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

/// The window of StableWindows(profile, lo, hi) with From < t <= To, found
/// around t's row (a profile of 10^6 steps is read at every t_r change); of
/// length 0 when none holds t.
StableWindow StableWindowAt(const std::vector<TopologyStep>& profile, double lo, double hi, double t);

/// The rule's constants (Data/EXPERIMENTS.md).
struct ThresholdRule
{
  double Lowest = 1.5;   ///< windows are looked for in (Lowest, cap]
  double Stable = 1.1;   ///< a window with To/From at least this is stable
  double Margin = 1.1;   ///< t_r = From * Margin, at most the window's middle (log)
  double Short = 1.3;    ///< a chosen window with To/From below this is short: warned
  /// Windows within this factor of length are ties, settled for the earlier
  /// candidate (the order of the t_p candidates is a preference).
  double Tie = 1.02;
  /// A cloud is a surface's (or a curve's) sample when its RelativeFlatness
  /// is below this (volume samples: 0.84-1; surfaces up to noise of the
  /// spacing, and thin tubes and plates: below 0.5, Data/EXPERIMENTS.md).
  double SurfaceFlatness = 0.6;
  /// A reconstruction is solid when it holds this many maxima per sample or
  /// more (an open surface's has a few slivers: under 0.1 per sample).
  double SolidShare = 0.125;
  /// A solid whose samples are all within this many Delaunay edges of its
  /// boundary (SolidDepth) is shallow: a ball of 10^3 volume samples is 3-4
  /// deep, a closed surface with noise of 1-2 times its spacing 1-2 at any
  /// size (Data/EXPERIMENTS.md).
  Id ShallowDepth = 2;
  /// Samples whose nearest sample is over this many times the median
  /// nearest-sample distance away are apart from the rest (FarSamples.h):
  /// 4.5 at most in i.i.d. surface samples of 10^6 points, 7.4 with a density
  /// varying 10 times, 14 in an i.i.d. circle of 10^4 points (wrong and
  /// warned anyway: its gaps); 22-32 for outliers strewn in a scan's box
  /// (Data/EXPERIMENTS.md).
  double FarFactor = 10;
  /// An answer of three parts or more without a void, each of whose parts
  /// has another within this many times the median nearest-sample distance,
  /// is warned as rows of one surface (PartGaps.h): 6.0 on a sphere scanned
  /// along parallels 6 times farther apart than the points on each, 6.3 on a
  /// knot tube's grid of vertices about as uneven; 12-17 on the study's i.i.d.
  /// curves, wrong and warned already; no right answer of 273 clouds has three
  /// parts and no void (Data/EXPERIMENTS.md).
  double RowFactor = 10;
  /// Closed curves (three or more, no void, b1 = b0, drawn as edges only)
  /// each within this fraction of its extent (the larger of it and its
  /// nearest's bounding-box diagonal) of another are warned the same way:
  /// 0.18 on the rings of a mesh's open cylinder, 0.25 apart and 1.41 across,
  /// 20 and 64 spacings apart; 0.71 on three unit circles 4 apart.
  double RowExtent = 0.25;
  /// An answer with voids, where a part holds several (b2 > b0) or a solid
  /// (Filled, or SolidShare tetrahedra a sample), is warned as surfaces
  /// joined across a gap when, without its edges longer than JoinFactor times
  /// the spacing (the JoinNeighbours-th nearest sample's distance) at one of
  /// their ends, it has more parts of JoinShare of its samples (and
  /// JoinSmallest) than with them (LongJoins.h): two spheres of 6 000 and 600
  /// i.i.d. points 0.5 apart, joined by a lump of tetrahedra, and two nested
  /// cube surfaces whose shell filled, fall into their two surfaces at any
  /// factor from 2.5 to 4 (6 misses the cubes); no right answer of 282 clouds
  /// falls apart at 2.5-4 (at 2, two spheres joined by a rod do;
  /// Data/EXPERIMENTS.md).
  double JoinFactor = 3;
  int JoinNeighbours = 6;
  double JoinShare = 0.01;
  Id JoinSmallest = 10;
  /// Voids sharing a part with no long edge to part them are still warned
  /// when the samples are noisy: their MedianFlatness at the smallest
  /// FlatnessScale is at least this share of a volume sample's there. Noise
  /// blurs a gap narrower than itself into cells of the sample spacing, so
  /// two surfaces that close apart cannot be told from two that touch.
  /// Measured (Data/EXPERIMENTS.md): surfaces without noise 0.00-0.06, even
  /// 316 vertices of a decimated mesh; noise of half the spacing 0.41, of one
  /// spacing 0.74-0.89.
  double NoisyFlatness = 0.25;
};

struct ThresholdChoice
{
  std::size_t Candidate = 0;     ///< index of the chosen profile
  double ReconstructionThreshold = 2;
  StableWindow Window;           ///< where the chosen Betti numbers hold
  /// Each candidate's window as the rule picks it alone (Length 0: none).
  std::vector<StableWindow> Best;
  /// The longest window of every candidate: when its Betti numbers are not
  /// the chosen ones, a coarser or finer shape lasts longer (warned).
  StableWindow Longest;
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
  /// A closed surface filled in (CheckFilled): a solid reconstruction
  /// (with or without voids) of samples that lie on a surface (warned when
  /// without a void, or when PreferSurface takes more voids: a noisy closed
  /// surface is solid around its void too).
  bool Filled = false;
  /// Filled, and PreferSurface then took a window with more voids instead:
  /// Solid is the window first chosen.
  bool Resurfaced = false;
  StableWindow Solid;
  /// Too few samples for RelativeFlatness (FlatnessMinimumPoints) and an
  /// answer without a void (CheckFilled): whether a surface was filled in,
  /// or left open, cannot be told; PreferSurface then treats it as Filled
  /// (warned either way).
  bool TooFew = false;
  double Flatness = 1;   ///< RelativeFlatness of the samples (1: not measured)
  Id Maxima = 0;         ///< maxima in the reconstruction at t_r
  Id Samples = 0;
  /// A solid answer not Filled whose samples are all near its boundary
  /// (CheckShallow): a noisy closed surface may have been filled (warned).
  bool Shallow = false;
  Id Depth = -1; ///< SolidDepth of the answer's tetrahedra, up to ShallowDepth + 1 (-1: not measured)
  /// Samples apart from the rest (CheckFar; warned): outliers can fill a
  /// closed surface or join parts whatever the window says.
  FarSamples Far;
  /// Closed surfaces apart below the window, joined in it (warned): the last
  /// window of the chosen profile below From with the chosen b1 and b2 (two
  /// voids or more, b1 even) and more components, each able to bound a void
  /// of its own (b0 <= b2); Length 0 when there is none. Components only
  /// join as t_r grows, and a closed surface cannot split in two, so such
  /// surfaces were bridged across a gap after they closed: separate surfaces
  /// whose gap is about the spacing, which the rule looks for only above
  /// Rule.Lowest and over a stable window.
  StableWindow Apart;
  /// Parts side by side (CheckRows; warned): the answer's parts, when there
  /// are three or more, none with a void, and each has another within
  /// Rule.RowFactor times the median nearest-sample distance; else 0.
  Id Rows = 0;
  double RowGap = 0; ///< the widest gap from a part to its nearest, over that distance
  Point3 RowPlace{ { 0, 0, 0 } }; ///< the middle of that gap
  /// When the rows are closed curves within Rule.RowExtent of their extent
  /// (and not within RowFactor spacings): the widest gap over that extent;
  /// RowGap and RowPlace are then that gap's.
  double RowGapOfExtent = 0;
  /// Parts joined across a gap (CheckJoins; warned): the sizes of the parts
  /// that the answer's short edges hold together, largest first, when its
  /// long edges join more of them than it has parts (Rule.JoinFactor); else
  /// empty.
  std::vector<Id> Joined;
  double JoinRatio = 0; ///< the least long edge between two of them, over the spacing at its finer end
  Point3 JoinPlace{ { 0, 0, 0 } }; ///< that edge's midpoint
  /// Voids sharing a part (b2 > b0) that no long edge holds together, in a
  /// noisy sample (CheckJoins; warned): NoiseFlatness is at least
  /// Rule.NoisyFlatness.
  bool NoisyJoin = false;
  /// The samples' MedianFlatness at the smallest FlatnessScale over a volume
  /// sample's there, when CheckJoins measured it (-1: not measured).
  double NoiseFlatness = -1;
  /// Whether CheckJoins may have something to measure: a window with voids,
  /// where a part holds several of them or the answer is Filled (CheckJoins
  /// also measures answers whose cells are solid enough).
  bool NeedsJoins() const;
  /// Whether CheckRows has something to measure: a window with no void and
  /// three components or more, after CheckFar.
  bool NeedsRows() const;
  /// Whether CheckShallow has something to measure: a solid answer (no void,
  /// SolidShare maxima a sample, after CheckFilled) that is not Filled or TooFew.
  bool NeedsDepth() const;
  ThresholdRule Rule;
};

/// The stable window with the largest b2 over every profile (one per t_p
/// candidate, profiles up to `cap`), on ties one whose b1 is even when it has
/// voids (a union of closed surfaces), then the one with the most components
/// when each can bound a void of its own (b0 <= b2: closed surfaces apart),
/// then the longest, and t_r in it;
/// without a stable window, the longest one (Unstable() is then true). When
/// no profile has a window above Lowest, t_r is Lowest * Margin (at most the
/// cap) on the first
/// candidate. Throws InputError without profiles or with a cap not above Lowest.
ThresholdChoice ChooseThresholds(const std::vector<std::vector<TopologyStep>>& profiles,
  double cap, const ThresholdRule& rule = ThresholdRule());

/// With t_r given: the candidate whose Betti numbers at `tr` hold over the
/// longest window around it (the first on ties, and the first when tr is past
/// every profile's end); Window is that window, unclipped.
ThresholdChoice ChoosePersistence(
  const std::vector<std::vector<TopologyStep>>& profiles, double tr, double cap);

/// Sets choice.Filled when the reconstruction at t_r holds at least
/// Rule.SolidShare maxima per sample
/// (`maxima`: MaximaBelow) and the samples are locally flat at some scale
/// (RelativeFlatness below Rule.SurfaceFlatness, measured only then): a surface sampled too
/// sparsely or too noisily for its thickness closes only as a solid, which
/// no topology profile tells from a volume sample (so does the space between
/// two nested surfaces, around a void). Under
/// FlatnessMinimumPoints samples, where the flatness cannot be measured, sets
/// TooFew instead for any answer without a void.
void CheckFilled(ThresholdChoice& choice, const std::vector<Point3>& samples, Id maxima);

/// After CheckFilled: when the answer is Filled, the window of `profiles`
/// (those ChooseThresholds chose from, up to `cap`) with more voids than the
/// answer (the most, the stable ones first, the longest on ties, the earlier
/// candidate within Rule.Tie) replaces it, and t_r is set in it as ChooseThresholds does.
/// Samples that lie on a surface and a solid answer disagree; a surface
/// closes with its void, so a window that has one is that surface, even when
/// it is shorter than Rule.Stable (Data/EXPERIMENTS.md). Returns whether it
/// changed the choice (Resurfaced); without such a window it keeps it.
/// TooFew is treated as Filled: volume samples of 30-190 points had no
/// window with a void (60 clouds), surface samples that small often do.
bool PreferSurface(ThresholdChoice& choice, const std::vector<std::vector<TopologyStep>>& profiles, double cap);

/// Sets choice.Far from the Gabriel edges of `nodes` (a flow complex's over
/// `samples` input points; any t_p: cancellations leave the nodes in place),
/// Rule.FarFactor.
void CheckFar(ThresholdChoice& choice, const std::vector<Node>& nodes, Id samples);

/// After CheckFilled, with the tetrahedra of the compact output at t_r:
/// measures their depth when NeedsDepth() and sets Shallow when it is at most
/// Rule.ShallowDepth. At that depth a solid sampled through its volume and a
/// closed surface whose noise is about its spacing give the same samples, so
/// the answer is doubtful either way; deeper solids are volume samples.
void CheckShallow(ThresholdChoice& choice, const std::vector<std::array<Id, 4>>& tetrahedra);

/// After CheckFar, with the reconstruction at t_r as cells on the samples
/// (the compact output): when NeedsRows(), sets Rows, RowGap and RowPlace if
/// every part has another within Rule.RowFactor spacings (FindPartGaps over
/// `nodes`, a flow complex's over `samples` input points), or, for closed
/// curves, within Rule.RowExtent of their extent (RowGapOfExtent too). A
/// surface sampled far more finely along lines than across gives such parts,
/// each line a curve of its own over the whole range of t_r looked at.
void CheckRows(ThresholdChoice& choice, const std::vector<Node>& nodes, Id samples, const CompactComplex& cells);

/// With the reconstruction at t_r as cells on `samples` (the compact output):
/// sets Joined, JoinRatio and JoinPlace (FindLongJoins with the Rule's Join
/// constants) when the window has voids and a part of it holds several
/// (b2 > b0), or it is Filled, or `cells` has Rule.SolidShare tetrahedra per
/// sample in it; clears them otherwise. Where a part holds several voids and
/// no long edge parts it, sets NoiseFlatness and NoisyJoin (at least
/// FlatnessMinimumPoints samples). Returns whether it measured.
/// `spacing`, when given, keeps every sample's NeighbourSpacing across calls
/// on one cloud (filled on the first measure); else only the samples in
/// `cells` are measured. `noise`, when given, keeps NoiseFlatness the same
/// way (negative: not measured yet).
bool CheckJoins(ThresholdChoice& choice, const std::vector<Point3>& samples, const CompactComplex& cells,
  std::vector<double>* spacing = nullptr, double* noise = nullptr);

/// The Threshold of the carrier of every maximum with cells in `run`, sorted:
/// MaximaBelow at any t (the count below t) once the run is gone.
std::vector<double> MaximumThresholds(
  const std::vector<Node>& nodes, const std::vector<Id>& carriers, const ReconstructionResult& run);

/// The maxima whose cells are in the reconstruction at t_r = t (their carrier,
/// CellCarriers, has Threshold < t in `run`).
Id MaximaBelow(const std::vector<Node>& nodes, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t);

} // namespace flowrecon

#endif
