// The compact complex (CompactReconstruction.h) as VTK: cells on the samples
// with the node each stands for. What `flowrecon reconstruct` writes by default.
#ifndef CompactConversion_h
#define CompactConversion_h

#include "CompactReconstruction.h" // core data structure
#include "FlowComplex.h"           // core data structure

#include <vector>

class vtkPoints;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// `grid` := the cells of `compact` over `samples` (all of them, in input
/// order: point k is input point k), with cell data NodeId, Index, Threshold
/// (`nodeThreshold[node]`) and Claims (how many index-2 nodes' walks cross a
/// triangle; 1 for other cells), and field data BettiNumbers (`betti`),
/// SharedTriangles, RevisitedTriangles and FilledVoids.
void CompactToVTK(const CompactComplex& compact, const std::vector<Point3>& samples,
  const std::vector<Node>& nodes, const std::vector<double>& nodeThreshold,
  const std::array<Id, 4>& betti, vtkUnstructuredGrid* grid);

/// `grid`'s cells and cell data := those of `compact`, as CompactToVTK's; its
/// field data (a filter's Betti numbers and thresholds) stays. `points`, when
/// given, are the samples' points, shared as they are: a filter that keeps
/// them between t_r changes spares ParaView their statistics each time.
void CompactCellsToVTK(const CompactComplex& compact, const std::vector<Point3>& samples,
  const std::vector<Node>& nodes, const std::vector<double>& nodeThreshold,
  vtkUnstructuredGrid* grid, vtkPoints* points = nullptr);

} // namespace flowrecon

#endif
