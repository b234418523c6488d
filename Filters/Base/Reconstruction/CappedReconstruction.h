// The reconstruction of a cloud, exact below a cap T_max, whose work follows
// what lies below the cap (docs/design.md, "Cost follows the output"): the patches
// that cannot matter below T_max are walked only if a maximum below it
// regularizes them (DeferredPatches.h). The eager computation is its oracle.
#ifndef flowrecon_CappedReconstruction_h
#define flowrecon_CappedReconstruction_h

#include "DeferredFlowLines.h"
#include "FlowComplexBuilder.h"
#include "PackedRun.h"
#include "Reconstruction.h"
#include "Retriangulation.h"
#include "Simplification.h"

#include <memory>
#include <string>
#include <vector>

namespace flowrecon
{

struct CappedReconstruction
{
  /// Nodes and arcs of the simplified diagram (arcs into deferred nodes only
  /// for those walked), no geometry.
  FlowComplex Complex;
  /// The 2-3 arcs as computed, before simplification: the cones' boundaries.
  std::vector<Arc> Cones;
  /// With keepRawPatchArcs: the 1-2 arcs as built, before simplification (the
  /// deferred patches' are not among them), for the topology (HasseTopology.h).
  std::vector<Arc> RawPatchArcs;
  bool Simplified = false;
  SimplificationResult Simplification; ///< when Simplified (its Arcs moved to Complex)
  /// The run at t_r = the cap: every node with Threshold < cap, as the run at
  /// t_r = inf has them.
  ReconstructionResult Run;
  std::vector<Id> Carriers; ///< CellCarriers, exact for every carrier below the cap
  /// The build's triangulation, kept for the walks that follow (share it with
  /// DrawStableManifolds, then free it); shared by the runs of one build.
  std::shared_ptr<Retriangulation> Triangulation;
  Id DeferredPatches = 0; ///< patches not walked by the build
  Id WalkedLate = 0;      ///< deferred patches walked for the reconstruction
  Id ReplayedOwners = 0;  ///< owners of cancelled pairs found by the replays
  /// The flow lines the build stopped (null: none), followed when needed; the
  /// drawing of cones needs them (CompleteCones). Refers to Triangulation.
  std::unique_ptr<DeferredFlowLines> Lines;
  /// Why the deferring run was abandoned for an eager one ("" when it was not).
  std::string EagerBecause;
  double SimplificationSeconds = 0, QueueSeconds = 0; ///< wall-clock, after the build
};

/// A flow complex built once for the runs of several t_p (ReconstructBuilt):
/// its lines are deferred from the largest t_p, which suits the smaller ones.
struct CappedBuild
{
  FlowComplex Complex;            ///< nodes and arcs as built, no geometry
  bool KeepRawPatchArcs = false;  ///< runs keep their RawPatchArcs
  std::shared_ptr<Retriangulation> Triangulation;
  double Cap = HUGE_VAL;
  double PersistenceThreshold = 0; ///< the largest t_p it serves
  bool Deferred = false;           ///< patches and lines were deferred
};

/// Makes Cones hold every 2-3 arc into the maxima among `nodes` (the nodes to
/// draw): the deferred flow lines that may end there are followed. Throws
/// Degenerate when a walk meets a tie (build again without deferral).
void CompleteCones(CappedReconstruction& r, const std::vector<Id>& nodes);

/// The ratio from which the capped build stops flow lines: above the cap and
/// t_p by a margin, so that few lines are needed below them (DeferredFlowLines.h).
double FlowLineDeferralRatio(double cap, double persistenceThreshold);

/// Builds the Hasse diagram of `points` (`options`: seed, attempts; no geometry),
/// simplifies it at `persistenceThreshold` (t_p < 1: none) and reconstructs it
/// up to `cap` (> 1; HUGE_VAL: every step, which is the eager computation).
/// With a finite cap above t_p, the patches of index-2 nodes at least `cap`
/// times above the largest Gabriel edge are deferred, and so are the flow lines
/// beyond FlowLineDeferralRatio; a walk that meets a tie
/// in a deferred patch makes it start again without deferral (drawing a
/// deferred patch later may meet one too: then call again with
/// `allowDeferral` false). Throws what the stages throw (InputError, Aborted).
CappedReconstruction ReconstructBelow(const std::vector<Point3>& points, BuildOptions options,
  double persistenceThreshold, double cap, bool allowDeferral, const Progress& progress,
  bool keepRawPatchArcs = false);

/// ReconstructBelow in two parts: the build for every t_p up to
/// `persistenceThreshold`, then each t_p's run (which copies what it changes
/// and borrows the rest, or takes it all when `take`: the build is spent). A
/// run that does not take it must give what it borrowed back (ReturnNodes)
/// before the next one. A Degenerate from a deferring build's run means: build
/// again without deferral.
CappedBuild BuildBelow(const std::vector<Point3>& points, BuildOptions options,
  double persistenceThreshold, double cap, bool allowDeferral, const Progress& progress,
  bool keepRawPatchArcs);
CappedReconstruction ReconstructBuilt(
  CappedBuild& build, double persistenceThreshold, bool take, const Progress& progress);

/// A run of a build kept for an output that reads only its insertions and
/// carriers (the compact output: no drawn stable manifolds, hence no cones,
/// lines or arcs), while the build serves another t_p. About a third of the
/// memory of the run held whole, and no time to make it again.
struct HeldRun
{
  PackedRun Run;
  /// The run without its tables (complex, arcs, cones, lines, simplification,
  /// insertions, carriers): its counts, times and flags.
  CappedReconstruction Rest;
};

/// Keeps what an output without drawn stable manifolds reads of `r` (a run of
/// a build that did not take it, its nodes given back) and frees the rest.
HeldRun Hold(CappedReconstruction&& r);

/// The held run made whole again on the build's complex, which it takes (the
/// build is spent): nodes and triangulation, without the build's arcs or
/// pending lines. Its Lines, Cones and arcs are empty: the stable manifolds
/// cannot be drawn from it, and CompleteCones does nothing.
CappedReconstruction Restore(HeldRun&& held, CappedBuild& build);

/// Moves the parts of a flow complex that no run changes (nodes, points,
/// representatives): lent by the build to a run that does not take it, so
/// that the runs of several t_p hold them once.
void MoveNodes(FlowComplex& from, FlowComplex& to);
/// Gives what the run `r` (which did not take the build) borrowed back to it.
void ReturnNodes(CappedReconstruction& r, CappedBuild& build);

} // namespace flowrecon

#endif
