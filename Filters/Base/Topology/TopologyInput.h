// What the Betti numbers of a capped run's reconstructions need
// (HasseBarcode): the unsimplified diagram's arcs, the presence times, and
// where the deferred flow lines that no reconstruction below the cap meets
// end, up to the complement's components.
//
// Why those lines need not be followed to their maxima. The reconstructions
// below the cap lie at distance <= r* from the samples, r* the largest value
// of a node they hold (the presence times without the pending lines: a line
// that ends at a maximum they hold is walked to it below). A pending line is
// walked until it enters {d > r*}; there it is in the component of {d > r*}
// (ExteriorRegions.h) of its maximum, since the distance grows along the flow,
// and that component lies inside one component of every reconstruction's
// complement. The line's side is given the first maximum of that component,
// and the component's maxima are joined at every threshold. On the surface
// samples of a sphere this replaces the walk of 10^6 lines through the nearly
// cospherical Voronoi vertices at its centre by a flood of cheap radius tests.
//
// A node present from t on needs less: only the complements of the
// reconstructions before it, within r(t), the largest value present by t. Its
// line is walked until {d > L} for a level L above r(t) (a few levels r*/2^k
// serve all), and given the first maximum of its region there. No join is
// needed: HasseBarcode's union-find, run from the largest threshold down,
// holds the components of the complement at t when it reaches the node, and
// the maxima of one region of {d > L} are in one of them. When the run
// inserts the inner maxima of a surface sample (t_p 0), nearly every patch is
// present before them: its lines stop near the surface, not at the medial axis.
#ifndef flowrecon_TopologyInput_h
#define flowrecon_TopologyInput_h

#include "CappedReconstruction.h"
#include "ExteriorRegions.h"

#include <memory>
#include <utility>
#include <vector>

namespace flowrecon
{

struct TopologyInput
{
  /// The 0-1 arcs, the 1-2 arcs of every index-2 node drawn below the cap,
  /// every 2-3 arc (a line not followed: to its region's first maximum),
  /// grouped by lower node.
  std::vector<Arc> Arcs;
  std::vector<double> Presence; ///< PresenceTimes
  /// Maxima in one component of the complement of every reconstruction.
  std::vector<std::pair<Id, Id>> Joined;
  Id LinesFollowed = 0; ///< lines followed to their maxima for the topology
  Id LinesToRegions = 0; ///< lines ended at a region of {d > r*} or of a lower level
  /// Of those, the lines ended below r*: of nodes present at some t, at a
  /// level above the values present by t.
  Id LinesToLowerLevels = 0;
  /// Of those, the lines ended at another candidate's r* (SharedRegions).
  Id LinesToSharedLevel = 0;
  /// A level's premise failed to be shown: every line was followed instead
  /// (right, but the walks the regions spare are all made).
  bool FollowedEveryLine = false;
  Id Regions = 0;
  std::int64_t CellsAbove = 0; ///< cells whose Voronoi vertex is in {d > r*}
};

/// What the runs of one build's t_p candidates share for their topology: they
/// often have the same r*, so the regions at that level and where the pending
/// lines end there serve each of them.
struct SharedRegions
{
  std::unique_ptr<ExteriorRegions> Regions;
  DeferredFlowLines::EndMemo Ends; ///< at Regions' level
  double Reached = -1; ///< the r* Regions were made for (their level, before the margins)
};

/// Needs r from keepRawPatchArcs; moves RawPatchArcs out. The lines stay
/// pending for the drawing (CompleteCones). `shared` (if given) keeps the
/// regions computed for another run of the same build, reused when their
/// level is high enough, with the ends of the lines walked there.
TopologyInput TopologyOfCappedRun(CappedReconstruction& r, SharedRegions* shared = nullptr);

} // namespace flowrecon

#endif
