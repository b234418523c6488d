// The names of the data contract (docs/data-contract.md): blocks of a flow
// complex and the arrays every stage writes and reads. Filters, the CLI and C++
// tests use these; changing one changes the product.
#ifndef FlowReconNames_h
#define FlowReconNames_h

namespace flowrecon
{
namespace names
{
// Blocks of Flow Complex and Flow Complex Simplification.
constexpr const char* CriticalPoints = "CriticalPoints";
constexpr const char* HasseDiagram = "HasseDiagram";
constexpr const char* StableManifolds = "StableManifolds";
constexpr const char* UnstableManifolds = "UnstableManifolds";
constexpr const char* GabrielEdges = "GabrielEdges";
constexpr const char* PersistencePairs = "PersistencePairs";
// Of Flow Complex Simplification only: the parts of CriticalPoints and
// GabrielEdges whose Cancelled is 0, which its display shows.
constexpr const char* SurvivingCriticalPoints = "SurvivingCriticalPoints";
constexpr const char* SurvivingGabrielEdges = "SurvivingGabrielEdges";

// Nodes, arcs and cells.
constexpr const char* NodeId = "NodeId";
constexpr const char* Index = "Index";
constexpr const char* CriticalValue = "CriticalValue";
constexpr const char* Simplex = "Simplex";
// Point of CriticalPoints: the id of the node's critical point among the
// StableManifolds points, -1 where that block has none.
constexpr const char* StableManifoldPointId = "StableManifoldPointId";
constexpr const char* Multiplicity = "Multiplicity";
constexpr const char* Ratio = "Ratio";
constexpr const char* LowerNodeId = "LowerNodeId";
constexpr const char* UpperNodeId = "UpperNodeId";
constexpr const char* TargetNodeId = "TargetNodeId";
constexpr const char* Cancelled = "Cancelled";
constexpr const char* Owner = "Owner";
// Deferred patches (point array, field data) and what replaying the
// cancellations on them needs (field data, compressed rows per pair).
constexpr const char* Deferred = "Deferred";
constexpr const char* DeferralRatio = "DeferralRatio";
constexpr const char* PairLowerOffsets = "PairLowerOffsets";
constexpr const char* PairLowers = "PairLowers";
constexpr const char* PairOwnerOffsets = "PairOwnerOffsets";
constexpr const char* PairOwners = "PairOwners";
constexpr const char* NodeCountByIndex = "NodeCountByIndex";
constexpr const char* OriginalPointIds = "vtkOriginalPointIds";

// Reconstruction.
constexpr const char* Step = "Step";
constexpr const char* Priority = "Priority";
constexpr const char* Threshold = "Threshold";
constexpr const char* Extension = "Extension";
constexpr const char* Sponsor = "Sponsor";
constexpr const char* Direction = "Direction";
// The largest jumps of the profile (its field data, one tuple per jump).
constexpr const char* JumpStep = "JumpStep";
constexpr const char* JumpThresholdBefore = "JumpThresholdBefore";
constexpr const char* JumpThresholdAfter = "JumpThresholdAfter";
constexpr const char* JumpNodeId = "JumpNodeId";
constexpr const char* JumpIndex = "JumpIndex";
constexpr const char* JumpCriticalValue = "JumpCriticalValue";
constexpr const char* JumpLocation = "JumpLocation";

// Persistence pairs and diagrams (TTK's layout).
constexpr const char* Birth = "Birth";
constexpr const char* Death = "Death";
constexpr const char* PairType = "PairType";
constexpr const char* Persistence = "Persistence";
constexpr const char* PairIdentifier = "PairIdentifier";
constexpr const char* IsFinite = "IsFinite";

// Topology.
constexpr const char* BettiNumbers = "BettiNumbers";
// The thresholds a reconstruction used (field data of port 0): each a one-value array, the window two values (From, To]
// and the flags (t_r chosen, t_p chosen) 1 when chosen from the data.
constexpr const char* UsedReconstructionThreshold = "ReconstructionThreshold";
constexpr const char* UsedPersistenceThreshold = "PersistenceThreshold";
constexpr const char* StableWindow = "StableWindow";
constexpr const char* ThresholdsChosen = "ThresholdsChosen";
// What an automatic choice warns about, one line per value (a string array in
// the field data of Flow Complex Simplification's output and of the
// reconstruction's port 0).
constexpr const char* ThresholdWarnings = "ThresholdWarnings";
// What the reconstruction's topology is, in one line for people (a string
// array of one value in the field data of port 0, and the column of the
// one-row table of the topology text port, which a render view draws).
constexpr const char* Topology = "Topology";
// The bars of the reconstructions of Flow Complex Simplification's output
// (field data): one tuple per bar (Dimension, Birth, Death, BirthNode,
// DeathNode; Death 1e308 and DeathNode -1 for a class that never dies), the
// Betti numbers of every t_r from its Hasse diagram, exact for t_r up to the
// one value of ReconstructionBarsBelow (1e308: every t_r).
constexpr const char* ReconstructionBars = "ReconstructionBars";
constexpr const char* ReconstructionBarsBelow = "ReconstructionBarsBelow";
// The t_p candidates an automatic t_p chose among, in order of preference.
constexpr const char* PersistenceCandidates = "PersistenceCandidates";
constexpr const char* Dimension = "Dimension";
constexpr const char* Change = "Change";
constexpr const char* Spacing = "Spacing";
// The compact output (what `flowrecon reconstruct` writes by default), field
// data: Delaunay triangles crossed by the walks of two index-2 nodes, twice by
// one walk, and the voids without a maximum it filled.
constexpr const char* SharedTriangles = "SharedTriangles";
constexpr const char* RevisitedTriangles = "RevisitedTriangles";
constexpr const char* FilledVoids = "FilledVoids";
// Cell data of the compact output: how many index-2 nodes claim a triangle.
constexpr const char* Claims = "Claims";
} // namespace names
} // namespace flowrecon

#endif
