/**
 * @class   vtkPersistenceDiagram
 * @brief   The persistence diagram of a flow complex, in TTK's layout, and its
 *          persistence curve.
 *
 * Input: the multiblock of vtkFlowComplex (or the same read back from a .vtm),
 * not a simplified one: the diagram is that of the whole flow-complex
 * filtration (flowrecon::ComputePersistence, the core's fast persistence), which
 * equals the alpha-complex diagram. Values are distances (radii), not squared
 * radii. Pairs of zero persistence are left out, as `flowrecon diagram` does.
 *
 * Output port 0 (vtkUnstructuredGrid): the diagram in TTK's layout, the same
 * grid as `flowrecon diagram -o PD.vtu` (flowrecon::DiagramToVTK): pair i is
 * the line (birth, birth, 0)-(birth, death, 0), essential classes end at the
 * largest finite value; then the diagonal (PairIdentifier and PairType -1) and,
 * for PersistenceThreshold >= 1, the line death = t_p x birth (PairIdentifier
 * and PairType -2): the pairs above it have a persistence ratio above t_p.
 * Cell data `PairIdentifier`, `PairType` (homology dimension), `Persistence`,
 * `Birth`, `IsFinite`. The data lie in the plane z = 0: a render view of
 * their own switches to 2D (ParaView's automatic interaction mode).
 *
 * Output port 1 (vtkTable): the persistence curve, the number of finite pairs
 * with death / birth >= x for x = 1 and every distinct ratio above
 * (flowrecon::PersistenceCurveToVTK): columns `Ratio`, `Pairs`, `PairsH0`,
 * `PairsH1`, `PairsH2` and `t_p`, NaN except on two rows at x = t_p, where it
 * goes from 0 to the top of the highest curve of finite ratios: a vertical
 * mark in a line chart. H0 pairs are born at 0: their ratio is infinite, so
 * PairsH0 is constant.
 *
 * Both outputs have field data `PersistenceThreshold`. An empty input (the
 * other ranks of a parallel run) gives empty outputs.
 */
#ifndef vtkPersistenceDiagram_h
#define vtkPersistenceDiagram_h

#include "FlowReconFiltersModule.h" // for export macro
#include "vtkUnstructuredGridAlgorithm.h"

class FLOWRECONFILTERS_EXPORT vtkPersistenceDiagram : public vtkUnstructuredGridAlgorithm
{
public:
  static vtkPersistenceDiagram* New();
  vtkTypeMacro(vtkPersistenceDiagram, vtkUnstructuredGridAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The persistence threshold t_p, as in vtkFlowComplexSimplification; here it
   * only marks the diagram and the curve (nothing is cancelled). Below 1 it is
   * not drawn. Default 1.1.
   */
  vtkSetClampMacro(PersistenceThreshold, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(PersistenceThreshold, double);
  ///@}

  enum OutputPorts
  {
    DIAGRAM = 0,
    CURVE = 1
  };

protected:
  vtkPersistenceDiagram();
  ~vtkPersistenceDiagram() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double PersistenceThreshold = 1.1;

private:
  vtkPersistenceDiagram(const vtkPersistenceDiagram&) = delete;
  void operator=(const vtkPersistenceDiagram&) = delete;
};

#endif
