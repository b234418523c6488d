// The reconstruction queue on a flow complex whose far patches were deferred
// (BuildOptions::DeferPatchesAboveRatio): their 1-2 arcs are walked when a
// maximum below the cap regularizes them, and the simplification's owners
// completed by replaying its cancellations on them (DeferredPatches.h). The
// CLI's capped run and the Flow Reconstruction filter share it.
#ifndef flowrecon_DeferredReconstruction_h
#define flowrecon_DeferredReconstruction_h

#include "FlowComplex.h"
#include "Progress.h"
#include "Reconstruction.h"
#include "Simplification.h"

#include <vector>

namespace flowrecon
{

class DeferredFlowLines;
class Retriangulation;

struct DeferredReconstruction
{
  ReconstructionResult Run; ///< as the run on the complete diagram, up to the cap
  std::vector<Id> Carriers; ///< CellCarriers, exact for every carrier below the cap
  Id WalkedLate = 0;        ///< deferred patches walked
  Id ReplayedOwners = 0;    ///< owners of cancelled pairs found by the replays
};

/// `fc`: nodes and the (simplified, when `simplification` is given) diagram
/// without the arcs into fc.DeferredPatches; `simplification` made with
/// recordLowers below fc.DeferralRatio (its owners are completed in place);
/// `retriangulation`: of the points fc was built from; `cap` <= fc.DeferralRatio.
/// The arcs walked are added to fc.Arcs, which stays sorted by (Lower, Upper).
/// Throws InputError when these do not fit together, Degenerate when a late
/// walk meets a tie the build never saw (build again without deferral).
/// With `lines` (set up with the same simplification), the In lists of maxima
/// also follow the deferred flow lines (DeferredFlowLines.h); fc.Arcs then
/// lacks the 2-3 arcs of the lines not followed.
DeferredReconstruction ReconstructDeferred(FlowComplex& fc,
  SimplificationResult* simplification, const Retriangulation& retriangulation,
  const std::vector<Id>& initializationEdges, double cap, const Progress& progress,
  DeferredFlowLines* lines = nullptr);

} // namespace flowrecon

#endif
