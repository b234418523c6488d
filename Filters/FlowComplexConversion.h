// Conversions between VTK data and the core's plain structures: samples in,
// the flow complex out as the named blocks of DESIGN.md §1. No geometry here.
#ifndef FlowComplexConversion_h
#define FlowComplexConversion_h

#include "FlowComplex.h"
#include "Progress.h"    // core data structure
#include "Simplification.h" // core data structure

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkDataObject;
class vtkMultiBlockDataSet;
class vtkFieldData;

namespace flowrecon
{

/// Sample coordinates of a vtkDataSet (its points) or a vtkTable (columns named
/// x/y/z or Points:0..2, else the first three numeric columns). Returns false and
/// sets `error` (one line) if there is nothing usable.
bool ExtractSamples(vtkDataObject* input, std::vector<Point3>& points, std::string& error);

/// Fills `output` with the blocks CriticalPoints, HasseDiagram, StableManifolds and
/// UnstableManifolds (the last two empty when not computed) and the report arrays.
/// Reports progress per block and every 2^16 cells (the copy of millions of
/// cells takes seconds), and throws Aborted when asked to stop.
void ToMultiBlock(
  const FlowComplex& fc, vtkMultiBlockDataSet* output, const Progress& progress = Progress());

/// Refuses (InputError, one line) to convert a flow complex whose VTK copy
/// would not fit in memory: about 60 bytes per arc, 150 per node and 200 per
/// drawn cell, on top of the core's copy.
void RequireMemoryForVTK(const FlowComplex& fc);

/// The report arrays (NodeCountByIndex, EulerCharacteristic, ..., Timings).
void AddReport(const FlowComplex& fc, vtkFieldData* fd);

/// The inverse of ToMultiBlock, enough for a round trip through a .vtm file:
/// nodes (CriticalPoints in NodeId order: Index, CriticalValue, Simplex, point
/// coordinates as Location), arcs (HasseDiagram cell data LowerNodeId,
/// UpperNodeId, Multiplicity), InfinityNode (the node with a negative simplex),
/// manifold geometry (StableManifolds points, triangles and tetrahedra with
/// NodeId; UnstableManifolds polylines) and the report arrays. The arcs are the
/// ones stored, i.e. the simplified ones for a simplified complex. Returns false
/// and sets `error` (one line) when a block or an array is missing or invalid.
/// With `diagramOnly`, the manifold geometry and the flow lines are checked but
/// not read (fc.Points, Triangles, Tetrahedra, FlowLines stay empty): what a
/// stage that works on the Hasse diagram alone needs, without the geometry's copy.
bool FromMultiBlock(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error,
  bool diagramOnly = false);

/// `output` as `input` with the HasseDiagram block made from fc.Arcs: every
/// other block (and the field data) is a shallow copy, so a stage that changes
/// only the arcs costs what the arcs cost, not what the drawn geometry costs.
void ReplaceHasseDiagram(
  vtkMultiBlockDataSet* input, const FlowComplex& fc, vtkMultiBlockDataSet* output);

/// What vtkFlowComplexSimplification adds to a flow complex: the point array
/// `Cancelled` of CriticalPoints, the field arrays `OwnerOffsets`, `Owners`
/// (SimplificationResult's compressed rows) and `PersistenceThreshold` of
/// CriticalPoints and of the output, the cell array `Owner` of StableManifolds
/// (the node itself for survivors, the first owner of a cancelled node, -1 for
/// none) and the block `PersistencePairs`.
void AddSimplification(const FlowComplex& fc, const SimplificationResult& s, double threshold,
  vtkMultiBlockDataSet* output);

/// Reads back what AddSimplification stored. Returns false (with `error` empty)
/// when `input` is not simplified: then every node survives and owns nothing.
/// Returns false with `error` set when the stored arrays are inconsistent. The
/// pairs and what a replay on deferred patches needs (HasLowers) are read when
/// the simplification stored them.
bool SimplificationFromMultiBlock(vtkMultiBlockDataSet* input, Id nodeCount,
  SimplificationResult& s, std::string& error);

/// Makes Index the active scalars of CriticalPoints (points), StableManifolds and
/// GabrielEdges (cells), and PersistencePairs have none: what a VTK mapper, or ParaView once a
/// block is extracted, colours by. (On the whole multiblock ParaView 5.11 picks
/// no default: it merges the blocks' active scalars, which are empty unless
/// every block agrees; without this PersistencePairs' Ratio was the only one.)
void SetDefaultScalars(vtkMultiBlockDataSet* output);

/// The block named `name` of `input`, or nullptr.
vtkDataObject* NamedBlock(vtkMultiBlockDataSet* input, const char* name);

/// A new, empty array of type A named `name` (the arrays of the data contract).
template <class A>
vtkSmartPointer<A> NamedArray(const char* name, int components = 1)
{
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  return a;
}

} // namespace flowrecon

#endif
