// Betti numbers of a reconstruction and of its whole nested family: persistent
// homology over Z/2 of the simplicial complex the drawn cells span, filtered by
// the cells' Threshold. The complex is the one a mesh tool sees in
// the written file: cells glued where they share point ids, every face of a
// cell present with it.
#ifndef flowrecon_CellHomology_h
#define flowrecon_CellHomology_h

#include "FlowComplex.h"
#include "Progress.h"

#include <array>
#include <string>
#include <vector>

namespace flowrecon
{

/// Cells of 1 to 4 points (vertex, segment, triangle, tetrahedron), in
/// compressed rows, each with the value from which it is present.
struct FilteredCells
{
  std::vector<Id> Offsets{ 0 }; ///< cell c holds Points[Offsets[c] .. Offsets[c+1])
  std::vector<Id> Points;
  std::vector<double> Values;

  void Add(const Id* points, int count, double value);
  Id Size() const { return static_cast<Id>(this->Values.size()); }
};

struct Bar
{
  int Dimension = 0;
  double Birth = 0;
  double Death = 0;   ///< +inf for a class that never dies
  Id BirthCell = -1;  ///< the cell (index in FilteredCells) whose simplex creates the class
  Id DeathCell = -1;  ///< the cell whose simplex kills it, -1 if it never dies
};

/// The bars of positive length of the filtration: a simplex is present from the
/// least value of the cells it is a face of. Throws InputError for a cell of no
/// point or more than 4, a negative point id or a NaN value.
/// `maximumCells` (>= 0) refuses larger inputs with an InputError saying so: the
/// homology of millions of tetrahedra costs about twice the rest of a
/// reconstruction (cost follows the output, but the caller chooses how much).
std::vector<Bar> CellBarcode(const FilteredCells& cells, const Progress& progress = Progress(),
  Id maximumCells = -1);

/// The message of that refusal, for callers that count cells before gathering them.
std::string TooManyCells(Id cells, Id maximumCells);

/// b0..b3 of the cells with value < t (the reconstruction at t_r = t).
std::array<Id, 4> BettiNumbersBelow(const std::vector<Bar>& bars, double t);

/// Where the Betti numbers change: row k holds for every t in
/// (Threshold[k], Threshold[k+1]] (the last row up to `limit`). The first row
/// starts at the least bar end (or at `start` when that is smaller).
struct TopologyStep
{
  double Threshold = 0;
  std::array<Id, 4> Betti{ { 0, 0, 0, 0 } };
};
std::vector<TopologyStep> TopologyProfile(
  const std::vector<Bar>& bars, double start, double limit);

/// A change of the Betti numbers: in dimension `Dimension`, by `Change` (+1 or
/// -1), for t_r above `Threshold`, brought by the cell `Cell`.
struct TopologyChange
{
  int Dimension = 0;
  double Threshold = 0;
  int Change = 0;
  Id Cell = -1;
};

/// The changes for t_r in [t, factor * t): the topology at t that a slightly
/// larger t_r would not keep. On clouds of known topology (Data/EXPERIMENTS.md)
/// every wrong answer at the default t_r had one within 5 % above it and no
/// right answer within 20 %: the sign of an under-sampled region.
std::vector<TopologyChange> TopologyChangesAbove(
  const std::vector<Bar>& bars, double t, double factor);

} // namespace flowrecon

#endif
