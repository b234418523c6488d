// Parts that only long cells hold together. Two closed surfaces a few of the
// sparser one's spacings apart can be joined, before the sparser one closes,
// by a lump of tetrahedra or a sheet of triangles across the gap; two nested
// closed surfaces, by the solid filling the shell between them. No window of
// the topology profile has them apart then (the join comes first), so the
// rule cannot see it. The cells across such a gap are far longer than the
// spacing of the samples at their ends, which cells of a sampled surface,
// curve or volume are not: without them the answer falls apart into the
// surfaces the samples hold (Data/EXPERIMENTS.md, "Closed surfaces apart").
#ifndef flowrecon_LongJoins_h
#define flowrecon_LongJoins_h

#include "CompactReconstruction.h"
#include "FlowComplex.h"

#include <vector>

namespace flowrecon
{

/// For each sample with `wanted` set (all when `wanted` is empty), the
/// distance to its k-th nearest other sample at another place (duplicates
/// count once); 0 for the others, and the farthest there is when fewer than
/// k other places exist. Parallel; the same values on any thread count.
std::vector<double> NeighbourSpacing(const std::vector<Point3>& samples, const std::vector<char>& wanted, int k);

struct LongJoins
{
  /// The sizes (samples) of the parts of at least `smallest` samples that the
  /// answer's short edges hold together, largest first, when there are more
  /// such parts than the whole answer has; else empty.
  std::vector<Id> Parts;
  /// The long edge between two of those parts with the smallest ratio of its
  /// length to the spacing at its finer end, that ratio, and its midpoint.
  double Ratio = 0;
  Point3 Where{ { 0, 0, 0 } };
};

/// The parts of `cells` (a reconstruction on `samples`: ids of its vertices,
/// edges, triangles, tetrahedra) once every edge of theirs longer than
/// `factor` times the NeighbourSpacing (k) at one of its ends is taken out,
/// against the parts of all of `cells`; a part counts when it has at least
/// `smallest` samples, and at least `share` of the samples in `cells`. Ids
/// outside the samples are passed over. Time O(c + m log m) for c cells on m
/// samples.
LongJoins FindLongJoins(const std::vector<Point3>& samples, const CompactComplex& cells, double factor, int k,
  double share, Id smallest);

/// The same with each sample's spacing given (`spacing`: NeighbourSpacing of
/// at least the samples in `cells`), for a caller that measures many t_r on
/// one cloud. Time O(c) for c cells.
LongJoins FindLongJoins(const std::vector<Point3>& samples, const std::vector<double>& spacing,
  const CompactComplex& cells, double factor, double share, Id smallest);

} // namespace flowrecon

#endif
