/**
 * @class   vtkFlowComplex
 * @brief   The flow complex of the distance function to a point cloud.
 *
 * Input: any vtkPointSet (its points are the samples; cells are ignored) or a
 * vtkTable whose first three numeric columns (or columns named x, y, z) are the
 * coordinates. Output: a vtkMultiBlockDataSet with the blocks
 * - `CriticalPoints` (vtkPolyData): one point per Hasse node with point data
 *   `NodeId`, `Index`, `CriticalValue`, `Simplex`, `StableManifoldPointId` (the
 *   critical point's id among the StableManifolds points, -1 where that block
 *   has none); the maximum at infinity is the last point (value +inf) and has
 *   no vertex cell, so it is never drawn.
 * - `HasseDiagram` (vtkPolyData): one line per arc, cell data `Multiplicity`,
 *   `Ratio`, `LowerNodeId`, `UpperNodeId`; point data `NodeId`. Arcs to infinity
 *   end on a short outward stub.
 * - `StableManifolds` (vtkUnstructuredGrid): vertices, Gabriel edges, triangulated
 *   index-2 patches and index-3 cones, cell data `NodeId`, `Index`,
 *   `CriticalValue`; point data `vtkOriginalPointIds` (-1 for constructed points).
 * - `UnstableManifolds` (vtkPolyData): polylines from each index-2 point to its
 *   maxima, cell data `NodeId`, `TargetNodeId`.
 * The field data of the output and of `CriticalPoints` report node counts, the
 * degeneracy handling (duplicates, perturbation) and timings.
 *
 * In a parallel (MPI) pipeline the flow complex is global: every rank requests the
 * whole input, rank 0 (piece 0) computes it and the other pieces are empty, so
 * the result is the same as in serial.
 *
 * The computation is exact (see docs/algorithm.md): predicates use
 * CGAL's exact-predicates kernel, walks are interval-filtered with an exact
 * rational fallback; degenerate input is perturbed deterministically and says so.
 */
#ifndef vtkFlowComplex_h
#define vtkFlowComplex_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

class FLOWRECONFILTERS_EXPORT vtkFlowComplex : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkFlowComplex* New();
  vtkTypeMacro(vtkFlowComplex, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Build the triangulated stable manifolds of index-2 points (and the index-3
   * cones over them). Off gives only critical points and the Hasse diagram,
   * which is enough for simplification and persistence. Default on.
   */
  vtkSetMacro(ComputeStableManifolds, bool);
  vtkGetMacro(ComputeStableManifolds, bool);
  vtkBooleanMacro(ComputeStableManifolds, bool);
  ///@}

  ///@{
  /**
   * With ComputeStableManifolds: the most triangles and tetrahedra to draw, or
   * -1 for all. The full complex of a surface sample with tubes has ~n^1.5 cells,
   * so by default only the nodes that come first in filtration order (critical
   * value, index) are drawn while their cells fit: the picture is the flow
   * complex below a value, closed under faces. The drawing comes after the Hasse
   * diagram, from a second Delaunay triangulation. Default 2,000,000 (every cell
   * of clouds up to some 10^4 points).
   */
  vtkSetClampMacro(MaximumStableManifoldCells, vtkIdType, -1, VTK_ID_MAX);
  vtkGetMacro(MaximumStableManifoldCells, vtkIdType);
  ///@}

  ///@{
  /**
   * Output-sensitive Hasse diagram (the paper's §6 outlook): the patches of
   * index-2 nodes whose value is at least this ratio times the largest Gabriel
   * edge value are not walked, so the HasseDiagram block lacks their 1-2 arcs,
   * all of ratio at least this (CriticalPoints gets the point array Deferred and
   * the field data DeferralRatio). On samples of surfaces with tubes those
   * patches hold most of the arcs (~n^1.5). Flow Reconstruction walks the ones
   * it needs, exactly, for any Maximum Threshold up to this value; Persistence
   * Diagram walks them all. Default 5, Flow Reconstruction's default Maximum
   * Threshold; 0 or anything up to 1: every patch.
   */
  vtkSetClampMacro(DeferPatchesAbove, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(DeferPatchesAbove, double);
  ///@}

  ///@{
  /**
   * Record the polylines of the unstable manifolds of index-2 points. The 2->3
   * arcs are always computed. Default on.
   */
  vtkSetMacro(ComputeUnstableManifolds, bool);
  vtkGetMacro(ComputeUnstableManifolds, bool);
  vtkBooleanMacro(ComputeUnstableManifolds, bool);
  ///@}

  ///@{
  /**
   * Seed of the deterministic perturbation applied when the input is degenerate
   * (grids, cospherical points, right angles). Default 1.
   */
  vtkSetMacro(PerturbationSeed, int);
  vtkGetMacro(PerturbationSeed, int);
  ///@}

  /// Names of the output blocks, in order.
  static const char* BlockName(int block);
  enum Blocks
  {
    CRITICAL_POINTS = 0,
    HASSE_DIAGRAM = 1,
    STABLE_MANIFOLDS = 2,
    UNSTABLE_MANIFOLDS = 3,
    GABRIEL_EDGES = 4,
    NUMBER_OF_BLOCKS = 5
  };

protected:
  vtkFlowComplex();
  ~vtkFlowComplex() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool ComputeStableManifolds = true;
  double DeferPatchesAbove = 5;
  vtkIdType MaximumStableManifoldCells = 2000000;
  bool ComputeUnstableManifolds = true;
  int PerturbationSeed = 1;

private:
  vtkFlowComplex(const vtkFlowComplex&) = delete;
  void operator=(const vtkFlowComplex&) = delete;
};

#endif
