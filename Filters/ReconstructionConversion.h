// The outputs of Flow Reconstruction built from the core's results: the cells
// of the reconstruction at a threshold, the profile and the sponsor arrows.
// Shared by vtkFlowReconstruction and the command line's direct core path.
#ifndef ReconstructionConversion_h
#define ReconstructionConversion_h

#include "FlowComplex.h"    // core data structure
#include "Reconstruction.h" // core data structure

#include <vector>

class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// The cells of each node: positions into a cell list (fc.Triangles or
/// fc.Tetrahedra), grouped by node as compressed rows.
struct CellsByNode
{
  std::vector<Id> Offsets, List;
  CellsByNode() = default;
  CellsByNode(const std::vector<Id>& cellNode, std::size_t nodes);
};

/// Port 0 (`grid`): the cells of the nodes whose carrier (CellCarriers) is in
/// the reconstruction at `t`, over the points they use (samples keep their input
/// id in vtkOriginalPointIds), with the insertion arrays; port 1 (`profile`) the
/// whole run; port 2 (`arrows`) the sponsor arrows at `t`. `fc` holds the drawn
/// geometry of those nodes, grouped by `triangles` and `tetrahedra`.
void ReconstructionToVTK(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkUnstructuredGrid* grid, vtkTable* profile, vtkPolyData* arrows);

} // namespace flowrecon

#endif
