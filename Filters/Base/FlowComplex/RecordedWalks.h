// The Delaunay triangles each patch's descending walk crossed, as the build
// walked them: the compact output's pieces (CompactReconstruction.h) without
// walking the patches a second time.
#ifndef flowrecon_RecordedWalks_h
#define flowrecon_RecordedWalks_h

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace flowrecon
{

/// Per critical facet (index-2 node), the triangles its walk crossed
/// (Patch::Walked), each as its exit cell and the index of that cell's vertex
/// opposite it: 4 bytes a triangle rather than the 48 of a compact claim.
struct RecordedWalks
{
  /// Code of a triangle: cell id * 4 + opposite (cell ids below 2^30). An exit
  /// cell that is infinite (no id) is named by its finite neighbour across the
  /// triangle: which of its two cells names a triangle does not matter (the
  /// walk's own exit cell depends on the link cache, VoronoiWalk.h).
  static constexpr std::int64_t CellLimit = std::int64_t(1) << 30;
  static std::uint32_t Code(std::int64_t cell, int opposite)
  {
    return static_cast<std::uint32_t>(cell * 4 + opposite);
  }
  static std::int64_t CellOf(std::uint32_t code) { return code >> 2; }
  static int OppositeOf(std::uint32_t code) { return static_cast<int>(code & 3); }

  std::vector<std::uint32_t> Offsets; ///< per facet, where its codes start (facets + 1)
  std::vector<std::uint32_t> Codes;
  std::vector<bool> Known; ///< per facet: walked by the build (not deferred)
  /// (facet, walks redone in exact arithmetic) where there were any, by facet.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> Fallbacks;

  bool Has(std::size_t facet) const { return facet < this->Known.size() && this->Known[facet]; }
  std::uint32_t FallbacksOf(std::size_t facet) const
  {
    const auto it = std::lower_bound(this->Fallbacks.begin(), this->Fallbacks.end(),
      std::make_pair(static_cast<std::uint32_t>(facet), std::uint32_t(0)));
    return it != this->Fallbacks.end() && it->first == facet ? it->second : 0;
  }
};

} // namespace flowrecon

#endif
