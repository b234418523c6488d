/**
 * @class   vtkFlowReconstruction
 * @brief   Flow reconstruction of a compact set from its flow complex (paper §3.1-3.2).
 *
 * Input: the multiblock of vtkFlowComplex or of vtkFlowComplexSimplification
 * (or either read back from a .vtm). Stable manifolds are added in the order of
 * a priority queue started from the initialization edges (Gabriel edges to a
 * nearest neighbour) and fed by regularization, upflow and horizontal extension
 * (flowrecon::Reconstruct). The queue runs once with t_r = infinity: every
 * reconstruction is the prefix of that run made of the nodes with Threshold <
 * t_r, so the run is cached (keyed on the input's modification time) and
 * changing only ReconstructionThreshold re-selects cells without rerunning it.
 *
 * Output port 0 (vtkUnstructuredGrid): the stable-manifold cells of the
 * reconstructed nodes, in insertion order: sample vertices, Gabriel edges,
 * triangulated index-2 patches and the index-3 cones (tetrahedra) of
 * reconstructed maxima. Their geometry is drawn on demand, once per input and
 * MaximumThreshold, for the nodes with Threshold < MaximumThreshold only
 * (recomputing the Delaunay triangulation of the samples when the input does
 * not hold it). Points are the samples and constructed points the cells use,
 * with `vtkOriginalPointIds` (input id, -1 for constructed points). Cell data: `NodeId`, `Index`, `CriticalValue` (of the
 * node whose stable manifold the cell belongs to), `Step`, `Priority`,
 * `Threshold`, `Extension` (0 initialization, 1 regularization, 2 upflow,
 * 3 horizontal), `Sponsor` (node id, -1 for initialization), `Owner` (the node
 * whose insertion brought the cell) and `Multiplicity` (for edges: how many
 * reconstructed patches they bound, counting arc multiplicities; 0 for other
 * cells). For a simplified input, the cells of a cancelled node go with its
 * owners: they are present as soon as one owner is, and take the insertion
 * data (Step, Priority, ...) of the earliest reconstructed owner, which is
 * also their `Owner`.
 *
 * Output port 1 (vtkTable): the reconstruction profile of the whole
 * t_r = infinity run, one row per step: `Step`, `NodeId`, `Index`, `Priority`,
 * `Threshold`, `Extension`, `Sponsor`, and `t_r` (the current t_r on every
 * row, for a horizontal mark in a chart). Steps with Threshold < t_r form the
 * current reconstruction; jumps of Threshold point at under-sampled regions.
 * Its field data holds the NumberOfJumps largest jumps, one tuple each:
 * `JumpStep`, `JumpThresholdBefore`, `JumpThresholdAfter`, `JumpNodeId`,
 * `JumpIndex`, `JumpCriticalValue`, `JumpLocation`.
 *
 * Output port 2 (vtkPolyData): sponsor arrows of the current reconstruction,
 * one line from the sponsor's critical point to the node's critical point for
 * each node inserted by an extension, cell data `Extension`, `Priority`,
 * `Step`, `NodeId`, `Sponsor`.
 *
 * Betti numbers (over Z/2) of the simplicial complex the output cells span
 * (cells glued where they share points, with all their faces), for every t_r
 * at once, read off the Hasse diagram without geometry (HasseTopology.h): the
 * input's `ReconstructionBars` (handed on by vtkFlowComplexSimplification),
 * or computed with the queue when the input is not simplified. Where neither
 * holds (a T_max above the bars' ReconstructionBarsBelow, a simplified input
 * saved without them, Compute Topology turned on after the queue ran), from
 * one persistent-homology computation over the drawn family filtered by
 * `Threshold` (flowrecon::CellBarcode). Port 0 has field data `BettiNumbers`
 * (b0, b1, b2 at the current t_r), and output port 3 (vtkTable) is the
 * topology profile: columns `Threshold`, `b0`, `b1`, `b2`, one row per change,
 * each holding for t_r in (Threshold, next Threshold] up to MaximumThreshold;
 * its field data draws the same profile as steps, with a vertical mark `t_r`
 * at the current t_r (flowrecon::TopologyToVTK), for a line chart.
 *
 * Output port 4 (vtkPolyData): under-sampling warnings, one point per change of
 * the Betti numbers for t_r in [t_r, UnderSamplingWindow x t_r), at the
 * critical point of the node bringing it, point data `Threshold`, `Dimension`,
 * `Change` (+1 / -1), `Spacing` (diameter of the empty ball there), `NodeId`.
 *
 * Output port 5 (vtkTable): the topology text, one row of a string column
 * `Topology`: what the reconstruction is, in words (its Betti numbers, the
 * thresholds and whether they were chosen, the range of t_r over which the
 * Betti numbers hold, how many warnings), one clause per line; port 0 has the
 * same as a one-line field data string `Topology` (flowrecon::TopologyLine).
 */
#ifndef vtkFlowReconstruction_h
#define vtkFlowReconstruction_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkMultiBlockDataSet;

class FLOWRECONFILTERS_EXPORT vtkFlowReconstruction : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkFlowReconstruction* New();
  vtkTypeMacro(vtkFlowReconstruction, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The reconstruction threshold t_r > 1: the output holds the nodes inserted
   * before the first popped priority >= t_r. VTK_DOUBLE_MAX (or infinity) keeps
   * every possible step. The paper finds t_r in [1.9, 2.1] useful. Used when
   * AutomaticReconstructionThreshold is off. Default 2.
   */
  vtkSetClampMacro(ReconstructionThreshold, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ReconstructionThreshold, double);
  ///@}

  ///@{
  /**
   * Choose t_r from the data (then ReconstructionThreshold is not used): among
   * the windows of t_r in (1.5, MaximumThreshold] where the Betti numbers stay
   * the same over at least 10 %, the one with the most voids (b2), then an
   * even b1 when it has voids, then the most closed surfaces apart, then the
   * longest; a solid answer on samples
   * that lie on a surface gives way to a window with a void (PreferSurface);
   * t_r is 10 % above its start, at most its middle
   * (AutomaticThresholds.h, what `flowrecon reconstruct` does). Needs
   * ComputeTopology. The choice is in the field data of port 0 (the
   * topology profile's chart marks t_r): ReconstructionThreshold, PersistenceThreshold,
   * ThresholdsChosen, StableWindow and ThresholdWarnings. Default on.
   */
  vtkSetMacro(AutomaticReconstructionThreshold, bool);
  vtkGetMacro(AutomaticReconstructionThreshold, bool);
  vtkBooleanMacro(AutomaticReconstructionThreshold, bool);
  ///@}

  /// The t_r of the last output: the chosen one, or ReconstructionThreshold.
  vtkGetMacro(UsedReconstructionThreshold, double);

  ///@{
  /**
   * Show every step up to MaximumThreshold, whatever ReconstructionThreshold
   * says (ParaView's "Every Step" box beside the t_r slider). Default off.
   */
  vtkSetMacro(EveryStep, bool);
  vtkGetMacro(EveryStep, bool);
  vtkBooleanMacro(EveryStep, bool);
  ///@}

  ///@{
  /**
   * T_max, the largest t_r the output can show: the stable manifolds of the
   * nodes with Threshold < T_max are drawn once (when the input or T_max
   * changes), so any ReconstructionThreshold <= T_max is a selection; a larger
   * one shows the reconstruction at T_max, with a warning. Nothing above T_max
   * is drawn, which is what keeps large surface samples in memory.
   * VTK_DOUBLE_MAX draws every step. Default 5, the range the automatic t_r
   * is chosen in.
   */
  vtkSetClampMacro(MaximumThreshold, double, 1.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumThreshold, double);
  ///@}

  ///@{
  /**
   * Under-sampling warnings (output port 4) mark every place where the Betti
   * numbers change for a t_r in [ReconstructionThreshold, window x
   * ReconstructionThreshold): topology that a slightly larger t_r would not
   * keep. On 42 clouds of known topology at t_r = 2 (Data/EXPERIMENTS.md), every
   * wrong answer had such a change within 5 % and no right answer within 20 %.
   * Default 1.1; 1 for none. The window stops at MaximumThreshold.
   */
  vtkSetClampMacro(UnderSamplingWindow, double, 1.0, 100.0);
  vtkGetMacro(UnderSamplingWindow, double);
  ///@}

  ///@{
  /**
   * Whether to compute the Betti numbers (field data, port 3) and the
   * under-sampling warnings (port 4). On solids of millions of tetrahedra they
   * cost about as much as the rest of the filter. Default on.
   */
  vtkSetMacro(ComputeTopology, bool);
  vtkGetMacro(ComputeTopology, bool);
  vtkBooleanMacro(ComputeTopology, bool);
  ///@}

  ///@{
  /**
   * When the Betti numbers come from the drawn cells (not from the Hasse
   * diagram), the most cells of the family below MaximumThreshold they are
   * computed for; above it they are skipped with a warning. -1 for no limit.
   * Default 4e6 (about 20 s).
   */
  vtkSetClampMacro(MaximumTopologyCells, vtkIdType, -1, VTK_ID_MAX);
  vtkGetMacro(MaximumTopologyCells, vtkIdType);
  ///@}

  ///@{
  /**
   * The number of largest jumps of the profile's Threshold reported as the
   * field data of the profile (port 1): JumpStep, JumpThresholdBefore,
   * JumpThresholdAfter, JumpNodeId, JumpIndex, JumpCriticalValue and
   * JumpLocation, one tuple per jump, largest first (what `flowrecon
   * reconstruct --jumps K` prints). A large jump is where the sampling is
   * poorest. 0 for none. Default 5.
   */
  vtkSetClampMacro(NumberOfJumps, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfJumps, int);
  ///@}

  ///@{
  /**
   * The cells of port 0. GEOMETRY_EXACT (the default): the stable manifolds
   * themselves, over the samples and points constructed on Voronoi edges, with
   * the insertion data of every cell (all the arrays below). GEOMETRY_COMPACT:
   * Delaunay simplices on the samples standing for them (docs/compact-output.md),
   * about 2 triangles a sample on a surface instead of about 9 cells, with cell
   * data NodeId, Index, Threshold and Claims only; the walks they come from are
   * made once per input and MaximumThreshold, so that a new t_r only selects.
   * The Betti numbers, profiles and warnings are the same in both; with the
   * Betti numbers from the Hasse diagram the exact cells are never drawn. A
   * solid answer, or one of three parts or more without a void, at the
   * automatic t_r also makes the compact walks with the exact geometry: the
   * shallow-solid and side-by-side warnings measure their cells.
   */
  vtkSetClampMacro(Geometry, int, GEOMETRY_EXACT, GEOMETRY_COMPACT);
  vtkGetMacro(Geometry, int);
  void SetGeometryToExact() { this->SetGeometry(GEOMETRY_EXACT); }
  void SetGeometryToCompact() { this->SetGeometry(GEOMETRY_COMPACT); }
  ///@}

  ///@{
  /**
   * Whether to fill port 2, the sponsor arrows of the steps up to t_r. They
   * are about 3 arrows a sample, rebuilt at each t_r: in ParaView their
   * statistics alone took a third of a t_r change at 10^5 samples. Off, port 2
   * is empty. Default on (ParaView's default is off).
   */
  vtkSetMacro(SponsorArrows, bool);
  vtkGetMacro(SponsorArrows, bool);
  vtkBooleanMacro(SponsorArrows, bool);
  ///@}

  enum Geometries
  {
    GEOMETRY_EXACT = 0,
    GEOMETRY_COMPACT = 1
  };

  /// How many times the priority queue has run (once per new input).
  vtkGetMacro(NumberOfQueueRuns, int);

  enum OutputPorts
  {
    RECONSTRUCTION = 0,
    PROFILE = 1,
    SPONSOR_ARROWS = 2,
    TOPOLOGY_PROFILE = 3,
    UNDER_SAMPLING = 4,
    TOPOLOGY_TEXT = 5
  };

protected:
  vtkFlowReconstruction();
  ~vtkFlowReconstruction() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ReconstructionThreshold = 2.0;
  bool EveryStep = false;
  double MaximumThreshold = 5.0;
  bool AutomaticReconstructionThreshold = true;
  double UsedReconstructionThreshold = 2.0;
  double UnderSamplingWindow = 1.1;
  bool ComputeTopology = true;
  vtkIdType MaximumTopologyCells = 4000000;
  int NumberOfJumps = 5;
  int Geometry = GEOMETRY_EXACT;
  bool SponsorArrows = true;
  int NumberOfQueueRuns = 0;

private:
  vtkFlowReconstruction(const vtkFlowReconstruction&) = delete;
  void operator=(const vtkFlowReconstruction&) = delete;

  struct Cache;
  std::unique_ptr<Cache> Cached; // the t_r = infinity run of the last input
  struct Selection;
  /// Runs the priority queue (t_r = infinity) on a new input into the cache
  /// (false: failed, an error reported, or aborted, `aborted` set).
  bool RunQueue(vtkMultiBlockDataSet* input, bool& aborted);
  /// The bars of the run in `cache` read off its unsimplified Hasse diagram
  /// (false: failed, an error reported, or aborted, `aborted` set; a diagram
  /// they cannot be read from leaves them to the drawn cells, with a warning).
  bool HasseTopology(Cache& cache, bool& aborted);
  /// Draws the cells of the nodes below `tmax` into the cache (reading the
  /// input's own first, when they were not read) (false: failed or aborted).
  bool DrawGeometry(vtkMultiBlockDataSet* input, double tmax);
  /// The Betti numbers of the drawn family into the cache (an error there is
  /// kept as its TopologyError: the reconstruction is still shown).
  void ComputeBettiNumbers(double tmax);
  /// The compact family below `tmax` into the cache, unless it is there
  /// (false: failed or aborted). `forWarning`: with the exact geometry only the
  /// shallow-solid and side-by-side warnings need it, so a failure warns and returns true with
  /// no family (an abort still returns false).
  bool PrepareCompact(double tmax, bool forWarning = false);
  /// The t_r shown below `tmax`, chosen automatically or given (false: it
  /// cannot be chosen, an error reported).
  bool SelectThreshold(double tmax, Selection& selection);
  /// The five outputs at the selected t_r, from the cache.
  void FillOutputs(vtkMultiBlockDataSet* input, double tmax, const Selection& selection,
    vtkInformationVector* outputVector);
};

#endif
