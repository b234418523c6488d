// The 1-2 cancellations of a simplification replayed on the In list of an
// index-2 node the simplification did not see (a deferred patch): what its
// In x Out updates would have done to that list, and which pairs would have
// handed their cells to it.
#ifndef flowrecon_CancellationReplay_h
#define flowrecon_CancellationReplay_h

#include "Simplification.h"

#include <utility>
#include <vector>

namespace flowrecon
{

class CancellationReplay
{
public:
  /// `simplification` must have been made with recordLowers (InputError
  /// otherwise). Keeps a reference to it.
  CancellationReplay(std::size_t nodeCount, const SimplificationResult& simplification);

  /// `in`: the (lower, multiplicity) arcs into index-2 node `y` before the
  /// simplification, which never had them; on return, the arcs into y in the
  /// simplified diagram (in no particular order; meaningless when y was
  /// cancelled: the arcs up to its cancellation). Appends (pair position, y) to
  /// `owners` for each pair whose lower had y as a successor when cancelled.
  /// Valid when no cancellation had y as its upper and none of y's lowers ever
  /// was a candidate with y (ratios above the threshold).
  void Replay(Id y, std::vector<std::pair<Id, int>>& in, std::vector<std::pair<Id, Id>>& owners) const;

private:
  const SimplificationResult& S;
  /// Per node: the pair that cancelled it as the lower of a 1-2 pair, and the
  /// pair that removed it (either role); -1 when none.
  std::vector<std::int32_t> LowerPair, RemovedBy;
};

} // namespace flowrecon

#endif
