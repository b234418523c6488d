#include "Simplification.h"

#include "HasseDiagram.h"
#include "MemoryGuard.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <tuple>

#include <tbb/parallel_sort.h>

namespace flowrecon
{

namespace
{

struct Candidate
{
  double Ratio;
  Id Lower, Upper;
  /// Reversed, so that std::priority_queue pops the least (ratio, lower, upper).
  bool operator<(const Candidate& o) const
  {
    return std::tie(this->Ratio, this->Lower, this->Upper) >
      std::tie(o.Ratio, o.Lower, o.Upper);
  }
};

/// The candidates in increasing (ratio, lower, upper): the initial ones sorted
/// once and read in order, the ones cancellations make in a heap. One heap of
/// all of them cost a cache miss per level at every pop (a fifth of the
/// simplification of a 3·10^5-point volume sample); the initial ones are most.
/// Equal candidates may come from both: either is popped first, and the
/// second then finds its nodes gone, as with one heap.
class CandidateQueue
{
public:
  explicit CandidateQueue(std::vector<Candidate>&& initial)
    : Initial(std::move(initial))
  {
    tbb::parallel_sort(this->Initial.begin(), this->Initial.end(),
      [](const Candidate& a, const Candidate& b) { return b < a; });
  }
  bool Empty() const { return this->Next == this->Initial.size() && this->Fresh.empty(); }
  const Candidate& Top() const
  {
    if (this->Next == this->Initial.size())
    {
      return this->Fresh.top();
    }
    return this->Fresh.empty() || this->Fresh.top() < this->Initial[this->Next]
      ? this->Initial[this->Next]
      : this->Fresh.top();
  }
  void Pop()
  {
    if (this->Next < this->Initial.size() &&
      (this->Fresh.empty() || this->Fresh.top() < this->Initial[this->Next]))
    {
      ++this->Next;
    }
    else
    {
      this->Fresh.pop();
    }
  }
  void Push(const Candidate& c) { this->Fresh.push(c); }

private:
  std::vector<Candidate> Initial;
  std::size_t Next = 0;
  std::priority_queue<Candidate> Fresh;
};

class Simplifier
{
public:
  Simplifier(const std::vector<Node>& nodes, const std::vector<Arc>& arcs)
    : Nodes(nodes)
    , Diagram(nodes, arcs)
    , Alive(nodes.size(), true)
    , Value(nodes.size())
  {
    // What Offer reads of a node, 8 bytes instead of a 56-byte Node: most of
    // its reads miss the cache. Index-0 nodes never are the lower node of a
    // candidate (value 0), nor the maximum at infinity the upper (ratio +inf).
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      const Node& v = nodes[i];
      this->Value[i] = v.IsInfinity() ? HUGE_VAL : v.Index == 0 ? 0 : v.Value;
    }
  }

  SimplificationResult Run(
    double threshold, const Progress& progress, bool recordLowers, bool recordUppers)
  {
    this->Threshold = threshold;
    this->RecordLowers = recordLowers;
    this->RecordUppers = recordUppers;
    SimplificationResult result;
    this->Result = &result;
    std::vector<Candidate> initial;
    for (Id lower = 0; lower < this->Diagram.NodeCount(); ++lower)
    {
      for (const HasseDiagram::HalfArc& h : this->Diagram.Out(lower))
      {
        this->Offer(lower, h.Node, h.Multiplicity, initial);
      }
    }
    const double expected = std::max<double>(1, static_cast<double>(initial.size()));
    CandidateQueue queue(std::move(initial));
    std::vector<Candidate> fresh;
    std::size_t pops = 0;
    progress(0, "Simplifying the Hasse diagram");
    // t_p < 1 is the paper's "no persistence" (t_p = 0): say so explicitly rather
    // than rely on every ratio of the input being >= 1.
    while (threshold >= 1 && !queue.Empty())
    {
      const Candidate top = queue.Top();
      if (top.Ratio > threshold)
      {
        break;
      }
      queue.Pop();
      if (++pops % 16384 == 0)
      {
        progress(std::min(1.0, static_cast<double>(pops) / expected),
          "Simplifying the Hasse diagram");
      }
      // Lazy deletion: the entry is stale when a node went away or the arc
      // became even since it was pushed. Its ratio cannot have changed (it only
      // depends on the two nodes), so a valid entry is a valid candidate.
      if (!this->Alive[top.Lower] || !this->Alive[top.Upper] ||
        this->Diagram.Multiplicity(top.Lower, top.Upper) % 2 == 0)
      {
        continue;
      }
      fresh.clear();
      this->Cancel(top.Lower, top.Upper, fresh);
      for (const Candidate& c : fresh)
      {
        queue.Push(c);
      }
      CancelledPair pair;
      pair.Lower = top.Lower;
      pair.Upper = top.Upper;
      pair.Ratio = top.Ratio;
      pair.Birth = this->Nodes[top.Lower].Value;
      pair.Death = this->Nodes[top.Upper].Value;
      pair.PairType = this->Nodes[top.Lower].Index;
      result.Pairs.push_back(pair);
    }
    result.Survives = this->Alive;
    result.Arcs = this->Diagram.TakeArcs(); // frees the diagram before the owners
    if (!this->RecordLowers)
    {
      result.Lowers.Offsets.assign(result.Pairs.size() + 1, 0);
    }
    if (!this->RecordUppers)
    {
      result.Uppers.Offsets.assign(result.Pairs.size() + 1, 0);
    }
    result.HasLowers = this->RecordLowers;
    result.HasUppers = this->RecordUppers;
    ResolveOwners(result, {});
    progress(1, "Simplifying the Hasse diagram");
    return result;
  }

private:
  /// Pushes (lower, upper) when it may be cancelled. Only odd arcs qualify: a
  /// cancellation needs an invertible incidence coefficient, and over Z/2 an even
  /// multiplicity is the coefficient 0. Index-0 nodes have value 0 (infinite
  /// ratio) and the maximum at infinity is never cancelled.
  void Offer(Id lower, Id upper, int multiplicity, std::vector<Candidate>& out) const
  {
    const double a = this->Value[lower];
    if (multiplicity % 2 == 0 || !(a > 0))
    {
      return;
    }
    const double ratio = PersistenceRatio(this->Value[upper], a);
    // A pair above the threshold is never cancelled (its ratio depends on its
    // two nodes only): keeping it out of the queue keeps the queue small.
    if (std::isfinite(ratio) && ratio <= this->Threshold)
    {
      out.push_back(Candidate{ ratio, lower, upper });
    }
  }

  /// The elementary reduction of (a, b): every x with an odd arc x -> b gets its
  /// Z/2 incidence with every y with an odd arc a -> y flipped, then a and b go.
  /// That is the paper's "add In(b) x Out(a), counting multiplicities modulo 2",
  /// i.e. d'y = dy + <dy, a> db over Z/2. Even arcs contribute an even count,
  /// which changes nothing modulo 2, so they are left alone.
  void Cancel(Id a, Id b, std::vector<Candidate>& fresh)
  {
    this->Lowers.clear();
    for (const HasseDiagram::HalfArc& x : this->Diagram.In(b))
    {
      if (x.Node != a && x.Multiplicity % 2 == 1 && !this->Diagram.IsRemoved(x.Node))
      {
        this->Lowers.push_back(x.Node);
      }
    }
    this->Uppers.clear();
    std::vector<Id>& owners = this->Owners;
    owners.clear();
    for (const HasseDiagram::HalfArc& y : this->Diagram.Out(a))
    {
      if (y.Node == b || this->Diagram.IsRemoved(y.Node))
      {
        continue;
      }
      // Stable manifolds go to every successor of a (even arcs too: a lies in
      // the boundary of y's manifold either way, so b's manifold glues to it).
      owners.push_back(y.Node);
      if (y.Multiplicity % 2 == 1)
      {
        this->Uppers.push_back(y.Node);
      }
    }
    std::sort(owners.begin(), owners.end());
    SimplificationResult& r = *this->Result;
    r.DirectOwners.AppendRow(owners.begin(), owners.end());
    const bool edge = this->Nodes[a].Index == 1;
    if (this->RecordLowers)
    {
      // Rows of 2-3 pairs stay empty; the row is sorted in place.
      const std::vector<Id>& lowers = this->Lowers;
      const Id start = r.Lowers.ValueCount();
      r.Lowers.AppendRow(lowers.begin(), edge ? lowers.end() : lowers.begin());
      std::sort(r.Lowers.Values.begin() + start, r.Lowers.Values.end());
    }
    if (this->RecordUppers)
    {
      // Rows of 1-2 pairs stay empty.
      const Id first = r.Uppers.ValueCount();
      r.Uppers.AppendRow(this->Uppers.begin(), edge ? this->Uppers.begin() : this->Uppers.end());
      std::sort(r.Uppers.Values.begin() + first, r.Uppers.Values.end());
    }
    this->Diagram.Remove(a);
    this->Diagram.Remove(b);
    this->Alive[a] = false;
    this->Alive[b] = false;
    for (const Id x : this->Lowers)
    {
      for (const Id y : this->Uppers)
      {
        const int m = this->Diagram.FlipParity(x, y);
        if (m != 0)
        {
          this->Offer(x, y, m, fresh);
        }
      }
    }
  }

  const std::vector<Node>& Nodes;
  HasseDiagram Diagram;
  std::vector<bool> Alive;
  std::vector<double> Value; ///< of each node, 0 for index 0, +inf for infinity
  SimplificationResult* Result = nullptr;
  bool RecordLowers = false, RecordUppers = false;
  double Threshold = 0;
  std::vector<Id> Lowers, Uppers, Owners;
};

} // namespace

SimplificationResult Simplify(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  double persistenceThreshold, const Progress& progress)
{
  std::vector<Arc> copy(arcs);
  return Simplify(nodes, std::move(copy), persistenceThreshold, progress);
}

void ResolveOwners(SimplificationResult& result, const std::vector<std::pair<Id, Id>>& extra)
{
  const std::size_t pairs = result.Pairs.size();
  if (result.DirectOwners.RowCount() != static_cast<Id>(pairs))
  {
    throw InputError("simplification: direct owners do not match the pairs");
  }
  std::vector<std::pair<Id, Id>> more(extra);
  for (const auto& e : more)
  {
    if (e.first < 0 || static_cast<std::size_t>(e.first) >= pairs)
    {
      throw InputError("simplification: owner of a pair out of range");
    }
  }
  std::sort(more.begin(), more.end());
  // Owners are transitive: a direct owner that was cancelled later hands over
  // its own owners. Direct owners were alive at the cancellation, so they were
  // cancelled later if at all: resolving in reverse cancellation order finds
  // them already resolved.
  // One row per pair, back to back in reverse order (a vector per node cost
  // an allocation and a free for each cancelled node: a third of the
  // owners' time on 10^6 volume points); both nodes of a pair share it.
  const std::size_t n = result.Survives.size();
  std::vector<std::int32_t> pairOf(n, -1);
  for (std::size_t p = 0; p < pairs; ++p)
  {
    pairOf[result.Pairs[p].Lower] = pairOf[result.Pairs[p].Upper] = static_cast<std::int32_t>(p);
  }
  std::vector<Id> values;
  std::vector<std::pair<Id, Id>> rowOf(pairs, { 0, 0 }); // [begin, end) in values
  std::vector<Id> merged;
  auto add = [&](Id d) {
    if (d < 0 || static_cast<std::size_t>(d) >= n)
    {
      throw InputError("simplification: owner out of range");
    }
    if (result.Survives[d])
    {
      merged.push_back(d);
    }
    else if (pairOf[d] >= 0)
    {
      const std::pair<Id, Id> row = rowOf[static_cast<std::size_t>(pairOf[d])];
      merged.insert(merged.end(), values.begin() + row.first, values.begin() + row.second);
    }
  };
  auto extraBegin = more.end();
  for (std::size_t p = pairs; p-- > 0;)
  {
    merged.clear();
    for (const Id d : result.DirectOwners.Row(static_cast<Id>(p)))
    {
      add(d);
    }
    auto first = std::lower_bound(more.begin(), extraBegin, std::make_pair(static_cast<Id>(p), Id(-1)));
    for (auto e = first; e != extraBegin; ++e)
    {
      add(e->second);
    }
    extraBegin = first;
    std::sort(merged.begin(), merged.end());
    merged.erase(std::unique(merged.begin(), merged.end()), merged.end());
    rowOf[p] = { static_cast<Id>(values.size()), static_cast<Id>(values.size() + merged.size()) };
    values.insert(values.end(), merged.begin(), merged.end());
  }
  CompressedRows<Id>& owners = result.Owners;
  owners = CompressedRows<Id>();
  owners.Offsets.reserve(n + 1);
  owners.Values.reserve(2 * values.size());
  for (std::size_t v = 0; v < n; ++v)
  {
    if (pairOf[v] >= 0 && !result.Survives[v])
    {
      const std::pair<Id, Id> row = rowOf[static_cast<std::size_t>(pairOf[v])];
      owners.AppendRow(values.begin() + row.first, values.begin() + row.second);
    }
    else
    {
      owners.Offsets.push_back(owners.ValueCount());
    }
  }
}

SimplificationResult Simplify(const std::vector<Node>& nodes, std::vector<Arc>&& arcs,
  double persistenceThreshold, const Progress& progress, bool recordLowers, bool recordUppers)
{
  if (std::isnan(persistenceThreshold))
  {
    throw InputError("persistence threshold is not a number");
  }
  // Two 12-byte half-arcs per arc and two lists per node, plus the queue and
  // the result's 12-byte copy of the arcs (the input's are freed once read).
  RequireMemory(40.0 * static_cast<double>(arcs.size()) + 80.0 * static_cast<double>(nodes.size()),
    "simplifying a Hasse diagram of " + std::to_string(arcs.size()) + " arcs",
    "use t_p 0 (no simplification) or fewer points");
  Simplifier simplifier(nodes, arcs);
  std::vector<Arc>().swap(arcs);
  return simplifier.Run(persistenceThreshold, progress, recordLowers, recordUppers);
}

} // namespace flowrecon
