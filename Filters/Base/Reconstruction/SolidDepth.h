// How deep a solid reconstruction is, counted in samples: what tells a solid
// sampled through its volume from a surface whose noise thickened it into a
// shell. A volume sample's depth grows with the cloud (about n^(1/3) / 2
// edges for a ball of n samples); a noisy surface's stays near its noise
// over the spacing whatever its size, and a solid only a few samples deep
// cannot be told from it (Data/EXPERIMENTS.md, the shallow-solid warning).
#ifndef flowrecon_SolidDepth_h
#define flowrecon_SolidDepth_h

#include "FlowComplex.h"

#include <array>
#include <vector>

namespace flowrecon
{

/// The largest number of edges of `tetrahedra` (ids of samples) between a
/// sample of theirs and the nearest sample on their boundary (a vertex of a
/// triangle that is a face of exactly one of them): 0 when every sample is on
/// the boundary, -1 without tetrahedra. The search stops past `limit` edges
/// (then returns limit + 1): a caller that only asks whether the solid is at
/// most that deep does not walk a large volume. Time O(t log d) for t
/// tetrahedra of at most d around a sample. Throws InputError on a tetrahedron with a negative or repeated id.
Id SolidDepth(const std::vector<std::array<Id, 4>>& tetrahedra, Id limit);

} // namespace flowrecon

#endif
