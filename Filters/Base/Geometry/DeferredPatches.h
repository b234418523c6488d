// Deferred patches (BuildOptions::DeferPatchesAboveRatio), walked when a stage
// needs them: the paper's §6 outlook, "interleave the flow complex construction
// and the reconstruction". The index-2 nodes far above every Gabriel edge hold
// almost all 1-2 arcs on samples of surfaces with tubes (their patches span the
// tube), yet below the deferral ratio they can only enter a reconstruction by
// regularization, and no cancellation below it involves their 1-2 arcs.
#ifndef flowrecon_DeferredPatches_h
#define flowrecon_DeferredPatches_h

#include "CancellationReplay.h"
#include "FlowComplex.h"
#include "Progress.h"
#include "Simplification.h"

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace flowrecon
{

class Retriangulation;

class DeferredPatches
{
public:
  /// `fc`: the complex with deferred patches (its arcs are not used);
  /// `simplification`: null, or the simplification of its diagram, made with
  /// recordLowers and a threshold below fc.DeferralRatio. Throws InputError when
  /// they do not fit together. Keeps references to all three.
  DeferredPatches(const FlowComplex& fc, const SimplificationResult* simplification,
    const Retriangulation& retriangulation);

  bool IsDeferred(Id node) const { return this->Deferred[node] != 0; }
  const std::vector<char>& Flags() const { return this->Deferred; }

  /// The 1-2 arcs into the deferred nodes of `nodes` (others are skipped) in
  /// the simplified diagram: their patches are walked (in parallel) and the
  /// cancellations replayed on their In lists, which the simplification could
  /// not update (a cancellation (a, b) flips x -> y for the odd lowers x of b
  /// when a -> y is odd, then removes a). Cancelled nodes get no arcs. The arcs
  /// come sorted by (Upper, Lower). Each replay also finds the pairs whose
  /// lower had the node as a successor: see ExtraOwners. Throws Degenerate when
  /// a walk meets a tie (the build should then be redone without deferral).
  std::vector<Arc> Walk(const std::vector<Id>& nodes, const Progress& progress);

  /// (pair position, node) for every replayed node that was a successor of the
  /// pair's lower when it was cancelled: the direct owners the simplification
  /// could not see (for ResolveOwners). Sorted, without repeats.
  std::vector<std::pair<Id, Id>> ExtraOwners() const;

private:
  const FlowComplex& FC;
  const SimplificationResult* S;
  const Retriangulation& Re;
  std::vector<char> Deferred, Walked;
  std::unique_ptr<CancellationReplay> Replayer; ///< with a simplification
  std::vector<std::pair<Id, Id>> Owners;
};

/// Makes `fc` the whole (unsimplified) flow complex: every deferred patch is
/// walked on the triangulation of fc's samples, recomputed with the stored seed
/// (Retriangulation::OfStoredComplex), and its arcs are added. What the
/// persistence diagram needs; a no-op without deferred patches. `advice` says
/// what to do when the triangulation would not fit in memory.
void WalkEveryDeferredPatch(FlowComplex& fc, const Progress& progress, const std::string& advice);

} // namespace flowrecon

#endif
