// A stored flow complex (a .vtm file, or a pipeline's multiblock) read back into
// the core's FlowComplex, with every block checked: bad files give one line.
#ifndef FlowComplexFromVTK_h
#define FlowComplexFromVTK_h

#include "FlowComplex.h"

#include <string>
#include <vector>

class vtkMultiBlockDataSet;

namespace flowrecon
{

/// The inverse of ToMultiBlock, enough for a round trip through a .vtm file:
/// nodes (CriticalPoints in NodeId order: Index, CriticalValue, Simplex, point
/// coordinates as Location), arcs (HasseDiagram cell data LowerNodeId,
/// UpperNodeId, Multiplicity), InfinityNode (the node with a negative simplex),
/// manifold geometry (StableManifolds points, triangles and tetrahedra with
/// NodeId, and each node's point among them, NodePoint, from the CriticalPoints
/// array StableManifoldPointId: without it, as in files written before it, the
/// samples' points alone; UnstableManifolds polylines) and the report arrays. The arcs are the
/// ones stored, i.e. the simplified ones for a simplified complex. Returns false
/// and sets `error` (one line) when a block or an array is missing or invalid.
/// With `diagramOnly`, the manifold geometry and the flow lines are checked but
/// not read (fc.Points, Triangles, Tetrahedra, FlowLines stay empty): what a
/// stage that works on the Hasse diagram alone needs, without the geometry's copy.
/// Without `flowLines`, the flow lines are checked but not read: no stage
/// after the flow complex uses them (they are ~40 % of the copy of a surface
/// sample's complex).
bool FromMultiBlock(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error,
  bool diagramOnly = false, bool flowLines = true);

/// The samples (the first fc.NumberOfInputPoints points of StableManifolds)
/// into fc.Points, after a diagramOnly read: what recomputing the samples'
/// triangulation needs (Retriangulation::OfStoredComplex).
bool ReadSamples(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error);

/// The manifold geometry (fc.Points, Triangles, Tetrahedra and their nodes,
/// NodePoint) after a diagramOnly read of the same input: what drawing the
/// exact cells reads when the input holds them. The nodes and arcs stay.
bool ReadManifoldGeometry(vtkMultiBlockDataSet* input, FlowComplex& fc, std::string& error);

/// The samples and the Gabriel edges of a stored flow complex's GabrielEdges
/// block (point k is sample k; each line's CriticalValue, half its length) as
/// index-0 and index-1 nodes: what FindFarSamples reads, without the rest of the
/// diagram. Empty when the block or its array is missing.
std::vector<Node> GabrielEdgeNodes(vtkMultiBlockDataSet* input);

} // namespace flowrecon

#endif
