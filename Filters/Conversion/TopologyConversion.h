// The topology outputs of Flow Reconstruction built from the core's results:
// the Betti numbers and topology profile at a threshold, and the under-sampling
// warnings. Shared by vtkFlowReconstruction and the command line.
#ifndef TopologyConversion_h
#define TopologyConversion_h

#include "AutomaticThresholds.h" // core data structure
#include "CellHomology.h"        // core data structure
#include "FlowComplex.h"  // core data structure

#include <string>
#include <vector>

class vtkFieldData;
class vtkPolyData;
class vtkTable;
class vtkUnstructuredGrid;

namespace flowrecon
{

/// Thresholds from here on are "no bound" in the charts' marks: the GUI's way
/// to say every step (its fields take no inf), which would squash a chart.
constexpr double Unbounded = 1e308;

/// The under-sampling warnings as points (vtkPolyData with vertices): one per
/// change, at the critical point of the node whose cell brings it
/// (`cellNodes`: the node of each cell of ReconstructionCells; empty when the
/// changes' cells are node ids, as HasseBarcode's are), point data
/// `Threshold` (the t_r above which it happens), `Dimension`, `Change` (+1 a
/// class appears, -1 one goes), `Spacing` (twice the node's critical value: the
/// diameter of the empty ball there) and `NodeId`.
void UnderSamplingToVTK(const std::vector<TopologyChange>& changes,
  const std::vector<Id>& cellNodes, const FlowComplex& fc, vtkPolyData* output);

/// Field data `BettiNumbers` (b0, b1, b2 of the cells below t) on `grid`, and
/// the topology profile in `table`: columns `Threshold`, `b0`, `b1`, `b2`, one
/// row per change, each holding for t_r in (Threshold, next row's Threshold]
/// (the last up to `limit`). The table's field data holds the same profile as
/// steps for a line chart: arrays `Threshold`, `b0`, `b1`, `b2` with two
/// points per row (the start and the end of its interval; a `limit` >= 1e308,
/// every step, ends the last at t or at its start) and two at x = `t` (none
/// for t >= 1e308), where `t_r` (NaN elsewhere) draws a vertical mark from 0
/// to the largest Betti number drawn. With a mark the steps start at t / 1.25
/// (the rows before are left out, the one across it starts there), so that
/// the chart's height is that of the Betti numbers around t.
void TopologyToVTK(const std::vector<Bar>& bars, double t, double limit,
  vtkUnstructuredGrid* grid, vtkTable* table);
/// The same with TopologyProfile(bars, 1, limit) given (a filter keeps it
/// for every t_r).
void TopologyToVTK(const std::vector<Bar>& bars, const std::vector<TopologyStep>& profile,
  double t, double limit, vtkUnstructuredGrid* grid, vtkTable* table);

/// The thresholds used, in the field data of `grid` (beside BettiNumbers; not
/// in the topology table's, whose field-data arrays are a chart's series):
/// PersistenceThreshold, ReconstructionThreshold, ThresholdsChosen (t_r, t_p:
/// 1 when chosen from the data) and, with `window`, StableWindow (From, To]:
/// where the reported Betti numbers hold.
void ThresholdsToVTK(double tp, double tr, bool tpChosen, bool trChosen,
  const StableWindow* window, vtkUnstructuredGrid* grid);

/// What the choice of the thresholds warns about, one line per value: the
/// string array ThresholdWarnings in the field data of `grid`.
void ThresholdWarningsToVTK(const std::vector<std::string>& lines, vtkUnstructuredGrid* grid);

/// The line saying what the reconstruction is (TopologyLine): the string array
/// Topology of one value in the field data of `grid`, and, when `text` is
/// given, a one-row table of a string column Topology holding the line cut
/// into short lines (what a render view draws in a corner): after the Betti
/// numbers, and at each "; ".
void TopologyTextToVTK(const std::string& line, vtkUnstructuredGrid* grid, vtkTable* text);

/// The bars of a complex's reconstructions (BarsOfStoredRun: node ids), exact
/// for t_r <= `below`, as the field-data arrays ReconstructionBars and
/// ReconstructionBarsBelow of `field` (what Flow Complex Simplification hands
/// to Flow Reconstruction: the Betti numbers of every t_r without a cell).
void ReconstructionBarsToVTK(const std::vector<Bar>& bars, double below, vtkFieldData* field);

/// Reads them back: false when `field` has none, or when they do not fit a
/// complex of `nodeCount` nodes (then `error` says why).
bool ReconstructionBarsFromVTK(vtkFieldData* field, Id nodeCount, std::vector<Bar>& bars,
  double& below, std::string& error);

} // namespace flowrecon

#endif
