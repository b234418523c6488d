// Flow reconstruction (paper §3.1-3.2): stable manifolds are added in the order
// of a priority queue fed by regularization, upflow and horizontal extension.
#ifndef flowrecon_Reconstruction_h
#define flowrecon_Reconstruction_h

#include "FlowComplex.h"
#include "Progress.h"
#include "Simplification.h"

#include <cmath>
#include <functional>
#include <vector>

namespace flowrecon
{

/// How a node entered the reconstruction (the values are part of the product).
enum class Extension : int
{
  Initialization = 0,
  Regularization = 1,
  Upflow = 2,
  Horizontal = 3
};

/// What happened to one node. Step < 0: never inserted. 32 bytes (node ids
/// are 32-bit, FlowComplex.h): one per node, for each t_p candidate.
struct Insertion
{
  Id Step = -1;        ///< insertion order, 0-based; initialization edges first
  double Priority = 0; ///< the ratio that inserted it (1 for initialization)
  /// Running maximum of Priority over steps 0..Step. The reconstruction at any
  /// t_r > 1 is exactly the set of nodes with Threshold < t_r (see Reconstruct).
  double Threshold = 0;
  Extension Kind = Extension::Initialization;
  std::int32_t Sponsor = -1; ///< the node whose extension inserted it; -1 for initialization
};

struct ReconstructionResult
{
  std::vector<Insertion> Nodes; ///< one per node of the diagram
  std::vector<Id> Order;        ///< node id of each step
  /// Steps [0, InitializationCount) are initialization edges; the priorities
  /// of the later ones (Nodes[Order[k]].Priority) are the paper's
  /// reconstruction profile when t_r = inf.
  Id InitializationCount = 0;

  /// Whether `node` belongs to the reconstruction at threshold t (t > 1).
  bool Contains(Id node, double t) const
  {
    return this->Nodes[node].Step >= 0 && this->Nodes[node].Threshold < t;
  }
};

/// The reconstruction with threshold `tr` (HUGE_VAL for every possible step) of
/// the diagram (`nodes`, `arcs`), where `survives` flags the nodes left by the
/// simplification (all true without one) and `initializationEdges` lists index-1
/// nodes (cancelled ones are skipped, as the paper retains only the initial edges
/// that were not cancelled; duplicates are ignored).
///
/// The queue is keyed by (priority, regularization first, node id); a node's
/// priority is the least ratio over its sponsors in the reconstruction so far,
/// and the first sponsor reaching it is kept on ties. Regularization ratio is 1;
/// upflow ratio V(d)/V(c) for d in Out(c); horizontal ratio max(1, V(d)/V(c))
/// for index-1 nodes c, d with a common ancestor. Upflow and horizontal
/// sponsorships need ratio < tr; regularization is unconditional. The maximum at
/// infinity and cancelled nodes are never inserted.
///
/// Nestedness: the run at any finite tr > 1 equals the prefix of the tr = inf
/// run made of the nodes with Threshold < tr (same steps, priorities, kinds and
/// sponsors), so one tr = inf run serves every threshold.
///
/// Throws InputError for inconsistent input (sizes, ids, arcs that do not go up
/// one index or touch a cancelled node, initialization edges that are not
/// index-1 nodes, a NaN tr) and Aborted when `progress` asks to stop.
ReconstructionResult Reconstruct(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives, const std::vector<Id>& initializationEdges, double tr,
  const Progress& progress);

/// Index-2 nodes whose 1-2 arcs `arcs` lacks (deferred patches, see
/// DeferredPatches.h), and how to get them: Walk(ids) returns the arcs into
/// those nodes. Every ratio of their 1-2 arcs is at least Ratio.
/// A lower entering (Added) or leaving the In list of a maximum.
struct InListChange
{
  Id Lower = -1, Upper = -1;
  bool Added = true;
};

struct LateArcs
{
  std::vector<char> Deferred; ///< one flag per node
  double Ratio = HUGE_VAL;
  std::function<std::vector<Arc>(const std::vector<Id>&)> Walk;
  /// Optional: deferred flow lines (DeferredFlowLines.h). Called with each
  /// maximum about to be inserted and the run so far; returns the changes of
  /// the In lists of the maxima not inserted yet that the lines it follows
  /// make. Lines of nodes already inserted need not be followed: their
  /// regularization changes nothing.
  std::function<std::vector<InListChange>(Id, const std::vector<Insertion>&)> FlowLinesInto;
};

/// The same run, with the 1-2 arcs of `late.Deferred` nodes asked for when
/// they are needed: below Ratio such a node only enters by regularization from
/// a maximum, so their arcs are asked for (all of one maximum at once) when a
/// maximum is inserted. Needs tr <= late.Ratio (throws InputError otherwise);
/// then it equals the run on the complete diagram (same steps, priorities,
/// kinds, sponsors), by the argument of DeferredPatches.h. With FlowLinesInto,
/// the In list of a maximum is the one of `arcs` changed by those calls.
ReconstructionResult Reconstruct(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives, const std::vector<Id>& initializationEdges, double tr,
  const Progress& progress, const LateArcs& late);

/// The initialization edges: index-1 nodes whose simplex is {v, nn(v)} for an
/// index-0 node v. `nearestNeighbour[v]` is the index-0 node id of the nearest
/// neighbour of the index-0 node id v (-1: none; entries of other nodes are
/// ignored; the vector may stop after the last index-0 node). Pairs that are not
/// Gabriel edges are skipped. Returns sorted unique node ids, cancelled or not.
std::vector<Id> InitializationEdges(
  const std::vector<Node>& nodes, const std::vector<Id>& nearestNeighbour);

/// Nearest neighbours read off the Hasse diagram: the nearest neighbour of a
/// sample is the other end of its shortest Gabriel edge (that edge is always
/// Gabriel, and an edge's critical value is half its length). Ties go to the
/// smaller node id. Uses the 0 -> 1 arcs, which simplification never changes.
/// Returns one entry per node: -1 for other nodes and isolated samples.
std::vector<Id> NearestNeighboursFromDiagram(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

/// InitializationEdges(nodes, NearestNeighboursFromDiagram(nodes, arcs)) in
/// one linear pass: the shortest Gabriel edge of each sample is its
/// initialization edge, with no search of the edges by their samples (a sort
/// of every index-1 node, twice a cloud's run).
std::vector<Id> InitializationEdgesFromDiagram(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs);

/// For each index-1 node in the reconstruction at threshold t: the number of
/// reconstructed index-2 nodes it bounds, counting arc multiplicities (the
/// paper's "multiplicity" of Gabriel edges, Fig. 3d). 0 for every other node.
std::vector<int> EdgeMultiplicities(const std::vector<Node>& nodes,
  const std::vector<Arc>& arcs, const ReconstructionResult& reconstruction,
  double t = HUGE_VAL);

/// The node whose insertion brings each node's cells into the reconstruction:
/// the node itself when it survives and is inserted; for a node cancelled by
/// `simplification` (null: none), the earliest inserted of its owners (its
/// stable manifold went to them, paper §3.3); -1 when never inserted.
std::vector<Id> CellCarriers(
  const ReconstructionResult& run, const SimplificationResult* simplification);

/// The nodes of index 2 and 3 whose cells are in the reconstruction at threshold
/// `t` (their carrier is): the stable manifolds a stage showing it must draw.
std::vector<Id> NodesToDraw(const std::vector<Node>& nodes, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t);

} // namespace flowrecon

#endif
