#include "Reconstruction.h"

#include "CompressedRows.h"
#include "HasseDiagram.h"
#include "IndexedHeap.h"
#include "NodeIndices.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <tuple>
#include <stdexcept>
#include <unordered_map>

namespace flowrecon
{

namespace
{

void CheckArcs(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>* survives)
{
  // In parallel, on the indices by themselves (a Node is 56 bytes and every
  // arc reads two at random); the first bad arc then gives the message.
  const std::vector<std::int8_t> index = NodeIndices(nodes);
  const auto bad = [&](const Arc& a) {
    return !IsValidArc(index, a) ||
      (survives && a.Multiplicity > 0 && (!(*survives)[a.Lower] || !(*survives)[a.Upper]));
  };
  const std::size_t first = tbb::parallel_reduce(
    tbb::blocked_range<std::size_t>(0, arcs.size()), arcs.size(),
    [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
      for (std::size_t i = r.begin(); i < r.end() && i < found; ++i)
      {
        if (bad(arcs[i]))
        {
          return i;
        }
      }
      return found;
    },
    [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (first < arcs.size())
  {
    ValidateArc(nodes, arcs[first], first);
    throw InputError("Hasse diagram: arc " + std::to_string(first) + " touches a cancelled node");
  }
}

/// Static In/Out lists; arcs of multiplicity 0 are not arcs. Even arcs are
/// kept: the reconstruction follows incidences of the Hasse diagram (an orbit
/// from a to b exists), not their parity. Rows are sorted: the visiting order,
/// hence which sponsor wins a tie, does not depend on the order of the arcs.
/// Offsets are 32-bit, as node ids: 8 bytes a node less (checked).
struct Adjacency
{
  using Rows32 = CompressedRows<std::int32_t, std::uint32_t>;
  Rows32 In, Out;

  Adjacency(std::size_t n, const std::vector<Arc>& arcs)
    : In(Rows(n, arcs, &Arc::Upper, &Arc::Lower))
    , Out(Rows(n, arcs, &Arc::Lower, &Arc::Upper))
  {
  }

private:
  static Rows32 Rows(
    std::size_t n, const std::vector<Arc>& arcs, std::int32_t Arc::*row, std::int32_t Arc::*value)
  {
    if (arcs.size() > std::numeric_limits<std::uint32_t>::max())
    {
      throw InputError("reconstruction: more than 2^32 arcs");
    }
    auto rows = Rows32::Group(n, [&](const auto& emit) {
      for (const Arc& a : arcs)
      {
        if (a.Multiplicity > 0)
        {
          emit(a.*row, a.*value);
        }
      }
    });
    rows.SortRows();
    return rows;
  }
};

/// 16 bytes: with the adjacency and the insertions, the queue is most of the
/// run's memory.
struct Entry
{
  double Priority;
  std::int32_t Gated; ///< 0 for regularization: it precedes any extension of equal priority
  std::int32_t Node;
};

struct EntryLess
{
  bool operator()(const Entry& a, const Entry& b) const
  {
    return std::tie(a.Priority, a.Gated, a.Node) < std::tie(b.Priority, b.Gated, b.Node);
  }
};

/// Each node at most once, with its best offer: a better one lowers its key
/// in place. The keys are distinct (node ids break ties), so the order of the
/// insertions is the least key each time, whatever the heap.
using OfferQueue = IndexedHeap<Entry, &Entry::Node, EntryLess>;

static_assert(sizeof(Entry) == 16 && sizeof(Insertion) == 32, "per-node records of the run");

/// The best sponsorship of a node not yet inserted is kept in its Insertion
/// (Step -1), its Gated in Threshold, rather than in an array of its own (one
/// record per node less); nodes never inserted get Insertion() at the end.
Insertion NoOffer()
{
  Insertion none;
  none.Priority = HUGE_VAL;
  none.Threshold = 2; // Gated: larger than any real offer
  return none;
}

class Reconstructor
{
public:
  Reconstructor(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
    const std::vector<bool>& survives, double tr, const LateArcs* late)
    : Nodes(nodes)
    , Survives(survives)
    , Graph(nodes.size(), arcs)
    , Tr(tr)
    , Queue(nodes.size())
    , Late(late)
  {
  }

  ReconstructionResult Run(const std::vector<Id>& initializationEdges, const Progress& progress)
  {
    this->Result.Nodes.assign(this->Nodes.size(), NoOffer());
    this->Closed.resize(this->Nodes.size());
    for (std::size_t d = 0; d < this->Nodes.size(); ++d)
    {
      this->Closed[d] = !this->Survives[d] || this->Nodes[d].IsInfinity() ? 1 : 0;
    }
    std::vector<Id> edges = initializationEdges;
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (const Id e : edges)
    {
      if (e < 0 || e >= static_cast<Id>(this->Nodes.size()) || this->Nodes[e].Index != 1)
      {
        throw InputError("initialization edge " + std::to_string(e) + " is not an index-1 node");
      }
    }
    progress(0, "Reconstructing");
    // All initialization edges are in before any extension, so that none of
    // them is reported as sponsored by another.
    for (const Id e : edges)
    {
      if (this->Survives[e])
      {
        this->Insert(e, 1, Extension::Initialization, -1);
      }
    }
    this->Result.InitializationCount = static_cast<Id>(this->Result.Order.size());
    for (Id step = 0; step < this->Result.InitializationCount; ++step)
    {
      this->Extend(this->Result.Order[step]);
    }
    const double total = std::max<double>(1, static_cast<double>(this->Nodes.size()));
    while (!this->Queue.Empty())
    {
      const Entry top = this->Queue.Pop();
      const Insertion& best = this->Result.Nodes[top.Node];
      const double priority = best.Priority;
      this->Insert(top.Node, priority, best.Kind, best.Sponsor);
      this->Extend(top.Node);
      if (this->Result.Order.size() % 4096 == 0)
      {
        progress(static_cast<double>(this->Result.Order.size()) / total, "Reconstructing");
      }
    }
    for (Insertion& ins : this->Result.Nodes)
    {
      if (ins.Step < 0)
      {
        ins = Insertion(); // never offered
      }
    }
    progress(1, "Reconstructing");
    return std::move(this->Result);
  }

private:
  void Insert(Id node, double priority, Extension kind, Id sponsor)
  {
    this->Running = std::max(this->Running, priority);
    Insertion& ins = this->Result.Nodes[node];
    this->Closed[node] = 1;
    ins.Step = static_cast<Id>(this->Result.Order.size());
    ins.Priority = priority;
    ins.Threshold = this->Running;
    ins.Kind = kind;
    ins.Sponsor = static_cast<std::int32_t>(sponsor);
    this->Result.Order.push_back(node);
  }

  /// Regularization, upflow, horizontal extension, in this order (paper §3.2).
  void Extend(Id c)
  {
    const Adjacency& g = this->Graph;
    if (this->Late && this->Late->Deferred[c])
    {
      const auto it = this->LateIn.find(c);
      if (it == this->LateIn.end())
      {
        throw InputError("reconstruction: a deferred node entered other than by regularization");
      }
      for (const Id x : it->second)
      {
        this->Consider(x, 1, 0, Extension::Regularization, c);
      }
    }
    else if (this->Late && this->Nodes[c].Index == 3)
    {
      const std::vector<Id> in = this->InOfMaximum(c);
      this->FetchLateArcs(in);
      for (const Id x : in)
      {
        this->Consider(x, 1, 0, Extension::Regularization, c);
      }
    }
    else
    {
      for (const Id x : g.In.Row(c))
      {
        this->Consider(x, 1, 0, Extension::Regularization, c);
      }
    }
    const double vc = this->Nodes[c].Value;
    // Index-0 nodes have value 0: their upflow ratio is infinite, never < tr.
    if (!(vc > 0))
    {
      return;
    }
    for (const Id d : g.Out.Row(c))
    {
      if (!this->Closed[d])
      {
        this->Consider(d, PersistenceRatio(this->Nodes[d].Value, vc), 1, Extension::Upflow, c);
      }
    }
    // "Index one nodes sponsor nodes with the same dimension": siblings through
    // a common index-0 ancestor. A shorter sibling would give a ratio below 1;
    // ratios are >= 1 by definition, so it is clamped (such a sibling is as cheap
    // as it gets, like a regularization, but still needs 1 < tr).
    if (this->Nodes[c].Index != 1)
    {
      return;
    }
    for (const Id b : g.In.Row(c))
    {
      for (const Id d : g.Out.Row(b))
      {
        if (d != c && !this->Closed[d])
        {
          this->Consider(d, PersistenceRatioAtLeastOne(this->Nodes[d].Value, vc), 1, Extension::Horizontal, c);
        }
      }
    }
  }

  /// In(c) of maximum `c`, sorted, with the changes deferred flow lines make.
  std::vector<Id> InOfMaximum(Id c)
  {
    const auto row = this->Graph.In.Row(c);
    std::vector<Id> in(row.begin(), row.end());
    if (!this->Late->FlowLinesInto)
    {
      return in;
    }
    for (const InListChange& change : this->Late->FlowLinesInto(c, this->Result.Nodes))
    {
      if (change.Upper != c && this->Result.Nodes[change.Upper].Step >= 0)
      {
        throw std::logic_error("reconstruction: a flow line into a maximum already inserted");
      }
      this->FlowLineChanges[change.Upper].push_back(change);
    }
    const auto it = this->FlowLineChanges.find(c);
    if (it == this->FlowLineChanges.end())
    {
      return in;
    }
    for (const InListChange& change : it->second)
    {
      if (change.Added)
      {
        in.push_back(change.Lower);
      }
      else
      {
        in.erase(std::remove(in.begin(), in.end(), change.Lower), in.end());
      }
    }
    this->FlowLineChanges.erase(it);
    std::sort(in.begin(), in.end());
    in.erase(std::unique(in.begin(), in.end()), in.end());
    return in;
  }

  /// The In lists of the deferred faces in `in` (of a maximum) that its
  /// regularization is about to insert.
  void FetchLateArcs(const std::vector<Id>& in)
  {
    std::vector<Id> ask;
    for (const Id y : in)
    {
      if (this->Late->Deferred[y] && this->Survives[y] && this->Result.Nodes[y].Step < 0 &&
        this->LateIn.find(y) == this->LateIn.end())
      {
        ask.push_back(y);
      }
    }
    if (ask.empty())
    {
      return;
    }
    for (const Id y : ask)
    {
      this->LateIn[y]; // known from now on, even with no arcs
    }
    for (const Arc& a : this->Late->Walk(ask))
    {
      if (a.Multiplicity > 0 && this->LateIn.count(a.Upper))
      {
        this->LateIn[a.Upper].push_back(a.Lower);
      }
    }
    for (const Id y : ask)
    {
      std::vector<Id>& row = this->LateIn[y];
      std::sort(row.begin(), row.end());
      row.erase(std::unique(row.begin(), row.end()), row.end());
    }
  }

  void Consider(Id d, double ratio, int gated, Extension kind, Id sponsor)
  {
    if (this->Closed[d])
    {
      return;
    }
    if (gated && !(ratio < this->Tr))
    {
      return;
    }
    Insertion& best = this->Result.Nodes[d];
    // Strictly better only: the first sponsor found keeps ties.
    if (std::make_pair(ratio, static_cast<double>(gated)) < std::make_pair(best.Priority, best.Threshold))
    {
      best.Priority = ratio;
      best.Threshold = gated;
      best.Kind = kind;
      best.Sponsor = static_cast<std::int32_t>(sponsor);
      this->Queue.Push(Entry{ ratio, gated, static_cast<std::int32_t>(d) });
    }
  }

  const std::vector<Node>& Nodes;
  const std::vector<bool>& Survives;
  /// Per node, 1 once it can take no offer (inserted, cancelled, infinity):
  /// most neighbours an extension looks at are inserted already, and this
  /// byte, unlike their records and insertions, stays in the cache.
  std::vector<std::uint8_t> Closed;
  Adjacency Graph;
  double Tr;
  OfferQueue Queue;
  double Running = 1;
  ReconstructionResult Result;
  const LateArcs* Late;
  std::unordered_map<Id, std::vector<Id>> LateIn;
  std::unordered_map<Id, std::vector<InListChange>> FlowLineChanges;
};

} // namespace

ReconstructionResult Reconstruct(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives, const std::vector<Id>& initializationEdges, double tr,
  const Progress& progress)
{
  if (std::isnan(tr))
  {
    throw InputError("reconstruction threshold is not a number");
  }
  if (survives.size() != nodes.size())
  {
    throw InputError("reconstruction: " + std::to_string(survives.size()) +
      " survival flags for " + std::to_string(nodes.size()) + " nodes");
  }
  CheckArcs(nodes, arcs, &survives);
  Reconstructor r(nodes, arcs, survives, tr, nullptr);
  return r.Run(initializationEdges, progress);
}

ReconstructionResult Reconstruct(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives, const std::vector<Id>& initializationEdges, double tr,
  const Progress& progress, const LateArcs& late)
{
  if (std::isnan(tr) || !(tr <= late.Ratio))
  {
    throw InputError("reconstruction: the threshold must not exceed the deferral ratio");
  }
  if (late.Deferred.size() != nodes.size() || survives.size() != nodes.size() || !late.Walk)
  {
    throw InputError("reconstruction: deferred flags do not match the diagram");
  }
  CheckArcs(nodes, arcs, &survives);
  Reconstructor r(nodes, arcs, survives, tr, &late);
  return r.Run(initializationEdges, progress);
}

std::vector<Id> InitializationEdges(
  const std::vector<Node>& nodes, const std::vector<Id>& nearestNeighbour)
{
  // Index-1 nodes by their sorted pair of sample ids; binary search, so the
  // node order of the diagram does not matter.
  std::vector<std::tuple<Id, Id, Id>> edges;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (nodes[i].Index == 1 && !nodes[i].IsInfinity())
    {
      const Id a = nodes[i].Simplex[0], b = nodes[i].Simplex[1];
      edges.emplace_back(std::min(a, b), std::max(a, b), static_cast<Id>(i));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<Id> result;
  const std::size_t n = std::min(nodes.size(), nearestNeighbour.size());
  for (std::size_t v = 0; v < n; ++v)
  {
    const Id w = nearestNeighbour[v];
    if (nodes[v].Index != 0 || w < 0)
    {
      continue;
    }
    if (w >= static_cast<Id>(nodes.size()) || nodes[w].Index != 0)
    {
      throw InputError("nearest neighbour of node " + std::to_string(v) + " is not a sample");
    }
    const Id a = std::min(nodes[v].Simplex[0], nodes[w].Simplex[0]);
    const Id b = std::max(nodes[v].Simplex[0], nodes[w].Simplex[0]);
    const auto it = std::lower_bound(edges.begin(), edges.end(), std::make_tuple(a, b, Id(-1)));
    if (it != edges.end() && std::get<0>(*it) == a && std::get<1>(*it) == b)
    {
      result.push_back(std::get<2>(*it));
    }
  }
  std::sort(result.begin(), result.end());
  result.erase(std::unique(result.begin(), result.end()), result.end());
  return result;
}

namespace
{

/// Per node: the two samples of each Gabriel edge (by its 0-1 arcs), and the
/// shortest Gabriel edge of each sample (least (value, id); -1 for none).
struct ShortestEdges
{
  std::vector<std::array<Id, 2>> Ends;
  std::vector<Id> Shortest;
};

ShortestEdges FindShortestEdges(const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
{
  CheckArcs(nodes, arcs, nullptr);
  const std::size_t n = nodes.size();
  ShortestEdges r;
  r.Ends.assign(n, { { -1, -1 } });
  r.Shortest.assign(n, -1);
  for (const Arc& a : arcs)
  {
    if (a.Multiplicity <= 0 || nodes[a.Lower].Index != 0)
    {
      continue;
    }
    std::array<Id, 2>& e = r.Ends[a.Upper];
    if (e[0] < 0)
    {
      e[0] = a.Lower;
    }
    else if (e[0] != a.Lower)
    {
      e[1] = a.Lower;
    }
    Id& s = r.Shortest[a.Lower];
    if (s < 0 || std::make_pair(nodes[a.Upper].Value, static_cast<Id>(a.Upper)) < std::make_pair(nodes[s].Value, s))
    {
      s = a.Upper;
    }
  }
  return r;
}

} // namespace

std::vector<Id> NearestNeighboursFromDiagram(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
{
  const ShortestEdges edges = FindShortestEdges(nodes, arcs);
  std::vector<Id> nn(nodes.size(), -1);
  for (std::size_t v = 0; v < nodes.size(); ++v)
  {
    const Id e = edges.Shortest[v];
    if (e >= 0 && edges.Ends[e][1] >= 0)
    {
      nn[v] = edges.Ends[e][0] == static_cast<Id>(v) ? edges.Ends[e][1] : edges.Ends[e][0];
    }
  }
  return nn;
}

std::vector<Id> InitializationEdgesFromDiagram(
  const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
{
  const ShortestEdges edges = FindShortestEdges(nodes, arcs);
  std::vector<char> chosen(nodes.size(), 0);
  for (std::size_t v = 0; v < nodes.size(); ++v)
  {
    const Id e = edges.Shortest[v];
    if (e < 0 || edges.Ends[e][1] < 0)
    {
      continue;
    }
    // The edge node of the pair {v, nn(v)} is e itself when the node's simplex
    // is its samples' (InitializationEdges looks the pair up by simplex).
    const Id a = nodes[edges.Ends[e][0]].Simplex[0], b = nodes[edges.Ends[e][1]].Simplex[0];
    const Node& edge = nodes[e];
    if (edge.Index == 1 && edge.Simplex[0] == std::min(a, b) && edge.Simplex[1] == std::max(a, b))
    {
      chosen[e] = 1;
    }
  }
  std::vector<Id> result;
  for (std::size_t e = 0; e < nodes.size(); ++e)
  {
    if (chosen[e])
    {
      result.push_back(static_cast<Id>(e));
    }
  }
  return result;
}

std::vector<int> EdgeMultiplicities(const std::vector<Node>& nodes,
  const std::vector<Arc>& arcs, const ReconstructionResult& reconstruction, double t)
{
  if (reconstruction.Nodes.size() != nodes.size())
  {
    throw InputError("edge multiplicities: the reconstruction does not match the diagram");
  }
  CheckArcs(nodes, arcs, nullptr);
  std::vector<int> m(nodes.size(), 0);
  for (const Arc& a : arcs)
  {
    if (nodes[a.Lower].Index == 1 && reconstruction.Contains(a.Lower, t) &&
      reconstruction.Contains(a.Upper, t))
    {
      m[a.Lower] += a.Multiplicity;
    }
  }
  return m;
}

std::vector<Id> CellCarriers(
  const ReconstructionResult& run, const SimplificationResult* simplification)
{
  const auto& steps = run.Nodes;
  std::vector<Id> carrier(steps.size(), -1);
  for (std::size_t i = 0; i < steps.size(); ++i)
  {
    if (!simplification || simplification->Survives[i])
    {
      carrier[i] = steps[i].Step >= 0 ? static_cast<Id>(i) : -1;
      continue;
    }
    for (const Id o : simplification->OwnerRow(static_cast<Id>(i)))
    {
      const Id c = carrier[i];
      if (steps[o].Step >= 0 && (c < 0 || steps[o].Step < steps[c].Step))
      {
        carrier[i] = o;
      }
    }
  }
  return carrier;
}

std::vector<Id> NodesToDraw(const std::vector<Node>& nodes, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double t)
{
  std::vector<Id> draw;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (nodes[i].Index >= 2 && carriers[i] >= 0 && run.Contains(carriers[i], t))
    {
      draw.push_back(static_cast<Id>(i));
    }
  }
  return draw;
}

} // namespace flowrecon
