// The outputs of Flow Reconstruction built from the core's results: the cells
// of the reconstruction at a threshold, the profile and the sponsor arrows.
// Shared by vtkFlowReconstruction and the command line's direct core path.
#ifndef ReconstructionConversion_h
#define ReconstructionConversion_h

#include "CellHomology.h"   // core data structure
#include "CompressedRows.h" // core data structure
#include "FlowComplex.h"    // core data structure
#include "Reconstruction.h" // core data structure

#include <cstddef>
#include <string>
#include <vector>

class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// The cells of each node: positions into a cell list (fc.Triangles or
/// fc.Tetrahedra) grouped by node, PositionsByRow(fc.TriangleNode, nodes).
using CellsByNode = CompressedRows<Id>;

/// Port 0 (`grid`): the cells of the nodes whose carrier (CellCarriers) is in
/// the reconstruction at `t`, over the points they use (samples keep their input
/// id in vtkOriginalPointIds), with the insertion arrays; port 1 (`profile`) the
/// whole run, one row per step, and a column `t_r` equal to `t` on every row
/// (a horizontal mark in its chart; NaN, no mark, for t >= 1e308: every step);
/// port 2 (`arrows`) the sponsor arrows at `t`. `fc` holds the drawn
/// geometry of those nodes, grouped by `triangles` and `tetrahedra`.
/// A null `grid`, `profile` or `arrows` is skipped. Throws InputError, ending
/// with `advice`, when the grid would not fit in memory (VTK would abort).
void ReconstructionToVTK(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, vtkUnstructuredGrid* grid, vtkTable* profile, vtkPolyData* arrows,
  const std::string& advice = "lower the reconstruction threshold (or MaximumThreshold)");

/// Sets the profile's column `t_r` (the mark of `t` in its chart, the last
/// column): with it, a profile made at one t_r serves every other.
void MarkProfile(vtkTable* profile, double t);

/// Sets the field data of `profile` (the table of `run`'s steps) to its
/// `count` largest jumps (LargestJumps of Threshold), largest first, one tuple
/// each: JumpStep, JumpThresholdBefore, JumpThresholdAfter (Threshold at the
/// step before and at the step), JumpNodeId, JumpIndex, JumpCriticalValue and
/// JumpLocation (the node inserted at that step and its critical point): what
/// `flowrecon reconstruct --jumps` prints. No arrays for `count` 0.
void ProfileJumpsToVTK(const FlowComplex& fc, const ReconstructionResult& run, std::size_t count, vtkTable* profile);

/// ReconstructionToVTK's grid at `t` cut out of its grid `full` at some T >= t,
/// without drawing anything: cells come in insertion order and Threshold is a
/// running maximum, so the cells with Threshold < t are a prefix of full's, and
/// points are numbered by first use, so theirs are a prefix too. `out` shares
/// full's arrays (reference-counted buffers cut to those lengths, no copy); only
/// Multiplicity, which grows with t, is new (`multiplicity`: EdgeMultiplicities
/// at t, per node). What makes a change of t_r below T_max instant in ParaView.
void GridBelow(
  vtkUnstructuredGrid* full, double t, const std::vector<int>& multiplicity, vtkUnstructuredGrid* out);

/// The cells ReconstructionToVTK writes at `t` (fc's point ids), each with the
/// Threshold of its carrier: the filtration of the nested family below t.
/// Throws InputError, before gathering anything, when there are more than
/// `maximumCells` (>= 0) of them: the Betti numbers are then skipped.
FilteredCells ReconstructionCells(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t, const CellsByNode& triangles,
  const CellsByNode& tetrahedra, std::vector<Id>* cellNodes = nullptr, Id maximumCells = -1);

} // namespace flowrecon

#endif
