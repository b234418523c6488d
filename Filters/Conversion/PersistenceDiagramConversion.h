// The persistence diagram of a flow complex as VTK data: TTK's layout (the grid
// `flowrecon diagram -o PD.vtu` writes), the t_p line over it and the
// persistence curve. Shared by vtkPersistenceDiagram and the command line.
#ifndef PersistenceDiagramConversion_h
#define PersistenceDiagramConversion_h

#include "FlowComplex.h" // core data structure
#include "Persistence.h" // core data structure

#include <vector>

class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// The pairs of the diagram: ComputePersistence's, in its order, without the
/// zero-length ones (death == birth), which carry no feature.
std::vector<PersistencePair> DiagramPairs(const FlowComplex& fc);

/// TTK's persistence-diagram layout in `grid`: pair i is the line from point 2i
/// = (birth, birth, 0) to point 2i+1 = (birth, death, 0), essential classes
/// ending at the largest finite value; the last cell is the diagonal from
/// (0, 0, 0) to that value. Cell data `PairIdentifier` (i, -1 for the
/// diagonal), `PairType` (dimension, -1), `Persistence`, `Birth` and
/// `IsFinite` (0 for essential classes and the diagonal).
void DiagramToVTK(const std::vector<PersistencePair>& pairs, vtkUnstructuredGrid* grid);

/// Appends to a DiagramToVTK grid the line death = threshold x birth, from the
/// origin to the top of the diagonal's range, as a cell with PairIdentifier
/// and PairType -2 (Persistence, Birth, IsFinite 0): pairs above it have a
/// persistence ratio above the threshold. No line for a threshold below 1,
/// which cancels nothing (ratios are at least 1). Field data
/// `PersistenceThreshold` either way.
void AddThresholdLine(double threshold, vtkUnstructuredGrid* grid);

/// The diagram as the series of a line chart against `Birth`, in the field
/// data of `grid` (doubles, one row per pair in order of birth, a row at 0 and
/// one at the top of the range, and one where the t_p line reaches it): `Birth`,
/// `H0`, `H1`, `H2` (the death of the row's pair in its dimension, NaN in the
/// others and on the added rows; essential classes at the top), `Diagonal`
/// (= Birth) and `t_p` (threshold x Birth up to the top, NaN above or for a
/// threshold below 1).
void DiagramChartToVTK(
  const std::vector<PersistencePair>& pairs, double threshold, vtkUnstructuredGrid* grid);

/// The persistence curve in `table`: the number of finite pairs whose ratio
/// death / birth is at least x, one row per x in 1 and the distinct finite
/// ratios above 1, increasing. Columns `Ratio` (x), `Pairs` (all dimensions),
/// `PairsH0`, `PairsH1`, `PairsH2` (one dimension each; H0 pairs are born at 0,
/// so their ratio is infinite and they count at every x). Two more rows at
/// x = threshold (when it is >= 1) carry the column `t_p` = 0 and the largest
/// number of pairs of finite ratio (not born at 0) in one dimension, NaN
/// elsewhere: a line chart draws them as a vertical mark as high as the
/// highest of those curves.
/// Field data `PersistenceThreshold`, and the same six columns for a chart
/// with logarithmic axes: doubles, a zero count NaN, the mark from 1 up.
void PersistenceCurveToVTK(
  const std::vector<PersistencePair>& pairs, double threshold, vtkTable* table);

} // namespace flowrecon

#endif
