/**
 * @class   vtkFlowComplexSimplification
 * @brief   Persistence-guided simplification of a flow complex (paper §3.3).
 *
 * Input: the multiblock of vtkFlowComplex (or the same read back from a .vtm).
 * Pairs (a, b) of incident critical points are cancelled in order of increasing
 * ratio V(b)/V(a) while that ratio does not exceed PersistenceThreshold (t_p);
 * the new arcs are In(b) x Out(a) counted modulo 2, and the stable manifolds of
 * the cancelled nodes go to the nodes of Out(a) (flowrecon::Simplify).
 *
 * Output: the same data contract as vtkFlowComplex, so that
 * vtkFlowReconstruction and saved files accept either:
 * - `CriticalPoints` keeps every node, with its original `NodeId` (later stages
 *   and the persistence pairs refer to original ids), plus the point array
 *   `Cancelled` (1 for the nodes of a cancelled pair). Its field data holds
 *   `OwnerOffsets` and `Owners`: compressed rows listing, for each cancelled
 *   node, the surviving nodes its stable manifold went to.
 * - `HasseDiagram` holds the simplified arcs.
 * - `StableManifolds` keeps every cell with `NodeId` = the node whose manifold
 *   it is, plus the cell array `Owner`: the node itself if it survives, else
 *   its first (smallest-id) owner, -1 when it has none. This keeps the geometry
 *   traceable to the original critical points while colouring by `Owner` shows
 *   the simplified cells; the complete owner lists are in the field data.
 * - `UnstableManifolds` unchanged.
 * - `PersistencePairs` (vtkPolyData): one line per cancelled pair from the
 *   lower to the upper critical point, in cancellation order, cell data
 *   `Ratio`, `Birth`, `Death`, `PairType` (index of the lower node),
 *   `LowerNodeId`, `UpperNodeId`.
 * - `SurvivingCriticalPoints` and `SurvivingGabrielEdges` (vtkPolyData): the
 *   points of `CriticalPoints` and the lines of `GabrielEdges` whose
 *   `Cancelled` is 0, with the same arrays: what ParaView shows by default, so
 *   that the picture differs from the flow complex's by what t_p removed. Later
 *   stages read the complete blocks only.
 * Field data (output and CriticalPoints): the flow-complex report plus
 * `PersistenceThreshold` and `CancelledPairCount`.
 *
 * With AutomaticPersistenceThreshold (the default), t_p is chosen from the
 * data among PersistenceCandidates (1.1, then 0), as `flowrecon reconstruct`
 * does on a cloud: each candidate's reconstructions are computed up to
 * MaximumThreshold, their Betti numbers read off the Hasse diagram, and the
 * candidate with the most stable topology is taken (AutomaticThresholds.h).
 * The output's field data then also holds `ThresholdsChosen` (0, 1),
 * `PersistenceCandidates` and `ThresholdWarnings` (one line when another
 * candidate gives other Betti numbers), which Flow Reconstruction carries on.
 *
 * The output's field data also holds `ReconstructionBars` and
 * `ReconstructionBarsBelow` (TopologyConversion.h): the Betti numbers of the
 * reconstructions of every t_r, read off the Hasse diagram of the chosen
 * t_p's run (ComputeTopology). Flow Reconstruction shows them as they are,
 * which spares it the persistent homology of its drawn cells: what gives
 * Betti numbers at 10^6 points and lets its compact output skip the exact
 * geometry.
 *
 * An input that is already simplified is rejected: simplify the flow complex
 * itself with the larger threshold instead.
 */
#ifndef vtkFlowComplexSimplification_h
#define vtkFlowComplexSimplification_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkMultiBlockDataSetAlgorithm.h"

class FLOWRECONFILTERS_EXPORT vtkFlowComplexSimplification : public vtkMultiBlockDataSetAlgorithm
{
public:
  static vtkFlowComplexSimplification* New();
  vtkTypeMacro(vtkFlowComplexSimplification, vtkMultiBlockDataSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The persistence threshold t_p: pairs with ratio V(b)/V(a) <= t_p are
   * cancelled. Ratios are at least 1, so any value below 1 (0 in particular)
   * cancels nothing. The paper finds t_p in [1.02, 1.2] useful. Used when
   * AutomaticPersistenceThreshold is off. Default 1.1.
   */
  vtkSetClampMacro(PersistenceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PersistenceThreshold, double);
  ///@}

  ///@{
  /**
   * Choose t_p from the data (then PersistenceThreshold is not used): the
   * candidate 1.1 or 0 (no simplification) whose reconstructions have the most
   * stable topology for t_r up to MaximumThreshold, 1.1 on ties. Regular
   * samples (lattices) lose patches to t_p 1.1; noisy ones need it. Costs two
   * reconstruction queues without geometry. Default on.
   */
  vtkSetMacro(AutomaticPersistenceThreshold, bool);
  vtkGetMacro(AutomaticPersistenceThreshold, bool);
  vtkBooleanMacro(AutomaticPersistenceThreshold, bool);
  ///@}

  ///@{
  /**
   * The largest t_r the automatic choice looks at: keep it equal to Flow
   * Reconstruction's MaximumThreshold, so that both see the same topology. At
   * most the input's DeferPatchesAbove. Default 5.
   */
  vtkSetClampMacro(MaximumThreshold, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumThreshold, double);
  ///@}

  ///@{
  /**
   * Whether to hand Flow Reconstruction the Betti numbers of every t_r of the
   * chosen t_p, read off the Hasse diagram (field data ReconstructionBars).
   * An automatic t_p has them from its choice; a given one costs one
   * reconstruction queue without geometry (and, for a complex with deferred
   * patches, the samples' triangulation). Off, with a given t_p, Flow
   * Reconstruction computes them from its drawn cells, up to its
   * MaximumTopologyCells. Default on.
   */
  vtkSetMacro(ComputeTopology, bool);
  vtkGetMacro(ComputeTopology, bool);
  vtkBooleanMacro(ComputeTopology, bool);
  ///@}

  /// Name of the block this filter adds.
  static const char* PersistencePairsBlockName() { return "PersistencePairs"; }

protected:
  vtkFlowComplexSimplification();
  ~vtkFlowComplexSimplification() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double PersistenceThreshold = 1.1;
  bool AutomaticPersistenceThreshold = true;
  bool ComputeTopology = true;
  double MaximumThreshold = 5;

private:
  vtkFlowComplexSimplification(const vtkFlowComplexSimplification&) = delete;
  void operator=(const vtkFlowComplexSimplification&) = delete;
};

#endif
