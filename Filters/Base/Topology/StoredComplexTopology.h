// The topology of a stored flow complex's reconstructions for a few t_p, from
// its Hasse diagram alone (HasseTopology.h): what lets a pipeline stage choose
// t_p from the data as the command line does on a cloud (AutomaticThresholds.h).
#ifndef flowrecon_StoredComplexTopology_h
#define flowrecon_StoredComplexTopology_h

#include "CellHomology.h"
#include "FlowComplex.h"
#include "Reconstruction.h"
#include "Progress.h"

#include <string>
#include <vector>

namespace flowrecon
{

class Retriangulation;

/// The Betti numbers of every reconstruction of one t_p.
struct StoredTopology
{
  double PersistenceThreshold = 0;
  std::vector<Bar> Bars;             ///< HasseBarcode (node ids), exact below the cap
  std::vector<TopologyStep> Profile; ///< TopologyProfile from 1 up to the cap
  std::string Error;                 ///< why there is no profile ("" when there is)
  std::vector<double> MaximumThresholds; ///< of the run (AutomaticThresholds.h)
};

/// The bars of the raw cells that `run` draws (PresenceTimes, HasseBarcode),
/// exact for t_r below `cap`. `fc`: as built (unsimplified arcs), except that
/// its Arcs may already hold the 1-2 arcs of some deferred patches (a run on
/// it walked them, ReconstructDeferred); `carriers`: CellCarriers of `run`;
/// `retriangulation`: of fc's samples, needed when patches were deferred
/// (those drawn below the cap and not walked yet are walked). Throws
/// InputError when the diagram is not a closed decomposition, Aborted on
/// request.
std::vector<Bar> BarsOfStoredRun(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, const Retriangulation* retriangulation,
  const Progress& progress);

/// `fc`: a flow complex as built (unsimplified arcs, none into
/// fc.DeferredPatches), simplified at `tp` (below 1: not simplified) and
/// reconstructed up to `cap` (at most fc.DeferralRatio when patches were
/// deferred); `retriangulation`: of fc's samples, needed only then (the
/// deferred patches drawn below the cap are walked). The topology of the raw
/// cells each reconstruction draws (PresenceTimes, HasseBarcode). Throws
/// InputError for a cap above the deferral ratio, Aborted on request; a
/// diagram that is not a closed decomposition is reported in Error.
StoredTopology TopologyOfStoredComplex(const FlowComplex& fc, double tp, double cap,
  const Retriangulation* retriangulation, const Progress& progress);

} // namespace flowrecon

#endif
