// Flow Reconstruction of a point cloud straight through the core: the flow
// complex stays in the core's compact form (a VTK copy of its Hasse diagram
// would be most of the memory), it is exact below a cap (the patches that
// cannot matter below it are walked only when needed, docs/design.md "Cost follows
// the output"), and only the cells written are drawn. The outputs are
// vtkFlowReconstruction's (the tests compare the two paths). What
// `flowrecon reconstruct` runs on a cloud.
#ifndef CloudReconstruction_h
#define CloudReconstruction_h

#include "AutomaticThresholds.h" // core data structure
#include "CompactReconstruction.h" // core data structure
#include "FlowComplex.h"         // core data structure
#include "Progress.h"    // core progress

#include <functional>
#include <string>
#include <vector>

class vtkInformationVector;
class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

struct CloudReconstructionSettings
{
  double PersistenceThreshold = 1.1;   ///< t_p (below 1: no simplification)
  /// t_p chosen among PersistenceCandidates (needs Topology): the candidate
  /// whose topology is the most stable (AutomaticThresholds.h). The order is
  /// the preference on ties.
  bool AutomaticPersistence = false;
  std::vector<double> PersistenceCandidates{ { 1.1, 0 } };
  double ReconstructionThreshold = 2;  ///< t_r, whose under-sampling is reported
  /// t_r chosen from the topology profile (needs Topology); then the output
  /// and drawn thresholds below are raised to it at least.
  bool AutomaticReconstruction = false;
  double OutputThreshold = 2;          ///< the grid holds the cells below it (>= t_r)
  double DrawThreshold = 2;            ///< nodes drawn
  double Cap = 4;                      ///< exact below it, and the topology profile's end
  double UnderSamplingWindow = 1.1;    ///< changes in [t_r, window t_r) are reported
  bool Topology = true;                ///< Betti numbers, topology profile, under-sampling
  std::string Advice = "lower the threshold"; ///< for a run that would not fit in memory
  /// The compact complex of the reconstruction at t_r (CompactReconstruction.h),
  /// from the run's own triangulation, instead of the stable manifolds: the
  /// grid then holds the samples and Gabriel edges only.
  bool Compact = false;
};

/// vtkFlowReconstruction's ports 0, 1, 3 and 4, all required. The grid's
/// field data also states the thresholds (ThresholdsToVTK).
struct CloudReconstructionOutputs
{
  vtkUnstructuredGrid* Grid = nullptr;
  vtkTable* Profile = nullptr;
  vtkTable* Topology = nullptr;
  vtkPolyData* UnderSampling = nullptr;
};

/// The outputs on ports 0, 1, 3 and 4 of `outputVector`: where both
/// reconstruction filters (vtkFlowReconstruction, vtkPointCloudReconstruction)
/// put the grid, the profile, the topology profile and the under-sampling points.
CloudReconstructionOutputs ReconstructionPorts(vtkInformationVector* outputVector);

struct CloudReconstructionReport
{
  std::vector<Node> Nodes;   ///< of the simplified complex: what the profile's NodeId names
  std::string TopologyError; ///< why there are no Betti numbers ("" when there are)
  std::string Work;          ///< patches deferred and walked late, and the core's timings
  double PersistenceThreshold = 0;    ///< t_p used (chosen or given)
  double ReconstructionThreshold = 0; ///< t_r used (chosen or given)
  /// With an automatic threshold: the choice, its window and each
  /// candidate's (in PersistenceCandidates order).
  ThresholdChoice Choice;
  bool Automatic = false;
  /// With settings.Compact: the compact complex at t_r, and each node's
  /// Threshold (NaN for the nodes not in it).
  CompactComplex Compact;
  std::vector<double> NodeThreshold;
};

/// Reconstructs `samples` into `outputs`. `phaseDone(name)` is called at the
/// end of each phase (for timings). Throws the core's exceptions (InputError,
/// Aborted, std::bad_alloc).
CloudReconstructionReport ReconstructCloud(const std::vector<Point3>& samples,
  const CloudReconstructionSettings& settings, const CloudReconstructionOutputs& outputs,
  const Progress& progress, const std::function<void(const char*)>& phaseDone);

} // namespace flowrecon

#endif
