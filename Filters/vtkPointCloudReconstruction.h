/**
 * @class   vtkPointCloudReconstruction
 * @brief   The whole FlowRecon pipeline on a point cloud in one filter, at the
 *          automatic thresholds: what `flowrecon reconstruct CLOUD` computes.
 *
 * Input: any vtkDataSet (its points are the samples) or a vtkTable of x, y, z
 * columns, as for vtkFlowComplex. The flow complex, its simplification and the
 * reconstruction are computed through the core in one pass
 * (flowrecon::ReconstructCloud, the memory-lean path of the command line: the
 * flow complex never becomes VTK data, its far patches are walked only when
 * needed, and only the cells written are drawn), with t_p chosen among 1.1 and
 * 0 and t_r chosen in (1.5, MaximumThreshold] as the most stable topology.
 * Nothing is kept between runs: any change runs everything again (the
 * step-by-step filters Flow Complex, Flow Complex Simplification and Flow
 * Reconstruction are the way to move t_r afterwards).
 *
 * The outputs have Flow Reconstruction's names, contents and port numbers
 * where it has them:
 * - port 0 (vtkUnstructuredGrid) `Reconstruction`: the cells of the
 *   reconstruction at the chosen t_r, with their cell data and the field data
 *   BettiNumbers, ReconstructionThreshold, PersistenceThreshold,
 *   ThresholdsChosen, StableWindow, ThresholdWarnings and Topology;
 * - port 1 (vtkTable) `Profile`: the reconstruction profile (Step, NodeId,
 *   Index, Priority, Threshold, Extension, Sponsor, t_r) up to MaximumThreshold;
 * - port 2 (vtkUnstructuredGrid) `Persistence Diagram`: the persistence
 *   diagram of the cloud (vtkPersistenceDiagram's port 0: TTK's layout, the
 *   t_p line at the chosen t_p and the chart's series in field data), empty
 *   when ComputePersistenceDiagram is off. Flow Reconstruction's port 2, the
 *   sponsor arrows, is not made here (the memory-lean path draws none);
 * - port 3 (vtkTable) `Topology Profile`, port 4 (vtkPolyData) `Under
 *   Sampling`, port 5 (vtkTable) `Topology Text`: as Flow Reconstruction's.
 *
 * Progress goes through UpdateProgress and AbortExecute stops the core at its
 * next progress report (every output empty, a warning).
 */
#ifndef vtkPointCloudReconstruction_h
#define vtkPointCloudReconstruction_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class FLOWRECONFILTERS_EXPORT vtkPointCloudReconstruction : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkPointCloudReconstruction* New();
  vtkTypeMacro(vtkPointCloudReconstruction, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * T_max: the automatic t_r is chosen in (1.5, MaximumThreshold], the topology
   * profile and the reconstruction profile end there, and the reconstruction is
   * exact below it (`flowrecon reconstruct --tr-max`). Default 5.
   */
  vtkSetClampMacro(MaximumThreshold, double, 1.5, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumThreshold, double);
  ///@}

  ///@{
  /**
   * Under-sampling warnings (port 4) mark every change of the Betti numbers
   * for a t_r in [t_r, window x t_r) (`--warn-window`). Default 1.1; 1 for none.
   */
  vtkSetClampMacro(UnderSamplingWindow, double, 1.0, 100.0);
  vtkGetMacro(UnderSamplingWindow, double);
  ///@}

  ///@{
  /**
   * Compute the persistence diagram (port 2): a second flow complex of the
   * cloud, with every patch walked (what `flowrecon diagram` does), before the
   * reconstruction; about as long again as the reconstruction, with a peak
   * below the reconstruction's. Default on.
   */
  vtkSetMacro(ComputePersistenceDiagram, bool);
  vtkGetMacro(ComputePersistenceDiagram, bool);
  vtkBooleanMacro(ComputePersistenceDiagram, bool);
  ///@}

  ///@{
  /**
   * The cells of port 0, as vtkFlowReconstruction's Geometry: the exact stable
   * manifolds (GEOMETRY_EXACT, the default) or Delaunay simplices on the
   * samples standing for them (GEOMETRY_COMPACT, ParaView's default).
   */
  vtkSetClampMacro(Geometry, int, GEOMETRY_EXACT, GEOMETRY_COMPACT);
  vtkGetMacro(Geometry, int);
  ///@}

  enum Geometries
  {
    GEOMETRY_EXACT = 0,
    GEOMETRY_COMPACT = 1
  };

  ///@{
  /// The thresholds of the last output (chosen from the data).
  vtkGetMacro(UsedReconstructionThreshold, double);
  vtkGetMacro(UsedPersistenceThreshold, double);
  ///@}

  enum OutputPorts
  {
    RECONSTRUCTION = 0,
    PROFILE = 1,
    PERSISTENCE_DIAGRAM = 2,
    TOPOLOGY_PROFILE = 3,
    UNDER_SAMPLING = 4,
    TOPOLOGY_TEXT = 5
  };

protected:
  vtkPointCloudReconstruction();
  ~vtkPointCloudReconstruction() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double MaximumThreshold = 5.0;
  double UnderSamplingWindow = 1.1;
  bool ComputePersistenceDiagram = true;
  int Geometry = GEOMETRY_EXACT;
  double UsedReconstructionThreshold = 0;
  double UsedPersistenceThreshold = 0;

private:
  vtkPointCloudReconstruction(const vtkPointCloudReconstruction&) = delete;
  void operator=(const vtkPointCloudReconstruction&) = delete;
};

#endif
