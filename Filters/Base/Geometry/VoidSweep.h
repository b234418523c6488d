// The voids a compact family fills, for every t_r at once. At a threshold t
// the complement of a compact complex is split into regions (Delaunay cells
// joined across facets that are not its triangles, solid cells left out);
// a bounded region that holds no maximum is filled (CompactReconstruction).
// Going down in t, walls and solid cells only leave, so regions only merge:
// one union-find sweep over the entry thresholds gives each cell the range of
// t over which its region is such a void, and a t_r change reads the ranges
// instead of searching millions of cells.
#ifndef flowrecon_VoidSweep_h
#define flowrecon_VoidSweep_h

#include "CompactReconstruction.h"
#include "Progress.h"

#include <array>
#include <cstdint>
#include <vector>

namespace flowrecon
{

/// A cell that lies in a void to fill for Low < t <= High, with what the
/// selection needs to group such cells into regions and name their wall.
struct VoidCell
{
  std::int32_t Cell = -1;
  double Low = 0, High = 0;
  /// The neighbour across each facet (-1: infinite).
  std::array<std::int32_t, 4> Neighbours{ { -1, -1, -1, -1 } };
  /// The claim group whose triangle is each facet, -1 for none.
  std::array<std::int32_t, 4> Walls{ { -1, -1, -1, -1 } };
};

/// What the sweep reads. A cell is solid for t > CellEntry(c); a facet is a
/// wall for t > the entry of its claim group.
struct VoidSweepInput
{
  const std::vector<std::array<std::int32_t, 4>>* Neighbours = nullptr;
  /// Per cell, the candidate maximum it flows to (-1: none); may be empty.
  const std::vector<std::int32_t>* CellMaximum = nullptr;
  /// Per node, the threshold it enters the reconstruction above (HUGE_VAL: never).
  const std::vector<double>* NodeEntry = nullptr;
  const std::vector<CompactClaim>* Claims = nullptr;
  /// Claim groups (one triangle each): Claims[GroupStart[g], GroupStart[g+1]).
  const std::vector<std::size_t>* GroupStart = nullptr;
  const std::vector<double>* GroupEntry = nullptr;
  /// The cells that hold a maximum (a region with one is not a void).
  const std::vector<std::int32_t>* Maxima = nullptr;
};

/// Every cell that is in a void for some t, sorted by cell. Time near-linear
/// in the cells; progress from 0 to 1 of `progress`.
std::vector<VoidCell> SweepVoids(const VoidSweepInput& in, const Progress& progress = Progress());

} // namespace flowrecon

#endif
