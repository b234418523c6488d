#include "DeferredFlowLines.h"

#include "Retriangulation.h"
#include "SuccessorForest.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <tuple>
#include <string>

namespace flowrecon
{

namespace
{

// Node values are doubles rounded from exact quantities: comparisons that a
// proof rests on keep this relative margin.
constexpr double Margin = 1e-9;

/// The arcs of `lower` in `arcs` sorted by (Lower, Upper): [first, last).
std::pair<std::size_t, std::size_t> RowOf(const std::vector<Arc>& arcs, Id lower)
{
  const auto first = std::lower_bound(arcs.begin(), arcs.end(), lower,
    [](const Arc& a, Id x) { return a.Lower < x; });
  const auto last = std::upper_bound(first, arcs.end(), lower,
    [](Id x, const Arc& a) { return x < a.Lower; });
  return { static_cast<std::size_t>(first - arcs.begin()),
    static_cast<std::size_t>(last - arcs.begin()) };
}

} // namespace

DeferredFlowLines::DeferredFlowLines(
  const FlowComplex& fc, const std::vector<Arc>& rawArcs, const Retriangulation& re)
  : Re(re)
  , Values(fc.Nodes.size())
  , Base3(re.Base3())
  , InfinityNode(fc.InfinityNode)
{
  for (std::size_t v = 0; v < fc.Nodes.size(); ++v)
  {
    this->Values[v] = fc.Nodes[v].Value;
  }
  if (this->InfinityNode + 1 != static_cast<Id>(fc.Nodes.size()) || this->Base3 > this->InfinityNode)
  {
    throw InputError("deferred flow lines: the complex does not fit its triangulation");
  }
  this->Lines.reserve(fc.PendingFlowLines.size());
  for (const PendingFlowLine& p : fc.PendingFlowLines)
  {
    if (p.Node < re.Base2() || p.Node >= re.Base3() || (p.Side != 0 && p.Side != 1) ||
      !(p.Bound >= 0))
    {
      throw InputError("deferred flow lines: a line that is not one of an index-2 node");
    }
    if (!this->Lines.empty() &&
      std::make_pair(this->Lines.back().Node, this->Lines.back().Side) >= std::make_pair(p.Node, p.Side))
    {
      throw InputError("deferred flow lines: lines not sorted");
    }
    this->Lines.push_back(Line{ p.Node, p.Side, p.Bound, -1 });
    if (this->Pending.empty() || this->Pending.back() != p.Node)
    {
      this->Pending.push_back(p.Node);
      this->PendingBegin.push_back(static_cast<Id>(this->Lines.size()) - 1);
    }
  }
  this->PendingBegin.push_back(static_cast<Id>(this->Lines.size()));
  this->Other.assign(this->Pending.size(), -1);
  this->Done.assign(this->Pending.size(), 0);
  // The followed line of a node with one pending line: its raw arc.
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    const Id x = this->Pending[k];
    const auto first = std::lower_bound(rawArcs.begin(), rawArcs.end(), x,
      [](const Arc& a, Id v) { return a.Lower < v; });
    for (auto a = first; a != rawArcs.end() && a->Lower == x; ++a)
    {
      if (this->PendingBegin[k + 1] - this->PendingBegin[k] != 1 || a->Multiplicity != 1 ||
        this->Other[k] >= 0)
      {
        throw InputError("deferred flow lines: the arcs do not match the pending lines");
      }
      this->Other[k] = a->Upper;
    }
  }
}

DeferredFlowLines::~DeferredFlowLines() = default;

std::size_t DeferredFlowLines::Position(Id node) const
{
  const auto it = std::lower_bound(this->Pending.begin(), this->Pending.end(), node);
  return it != this->Pending.end() && *it == node ? static_cast<std::size_t>(it - this->Pending.begin())
                                                  : std::string::npos;
}

bool DeferredFlowLines::IsPending(Id node) const
{
  const std::size_t k = this->Position(node);
  return k != std::string::npos && !this->Done[k];
}

double DeferredFlowLines::LeastBound(std::size_t k) const
{
  double b = HUGE_VAL;
  for (Id l = this->PendingBegin[k]; l < this->PendingBegin[k + 1]; ++l)
  {
    b = std::min(b, static_cast<double>(this->Lines[l].Bound));
  }
  return b;
}

void DeferredFlowLines::Follow(const std::vector<Id>& nodes)
{
  std::vector<Id> todo; // line positions
  for (const Id x : nodes)
  {
    const std::size_t k = this->Position(x);
    if (k == std::string::npos || this->Done[k])
    {
      continue;
    }
    this->Done[k] = 1;
    if (this->Simplified)
    {
      this->FollowedSince.push_back(x);
    }
    for (Id l = this->PendingBegin[k]; l < this->PendingBegin[k + 1]; ++l)
    {
      todo.push_back(l);
    }
  }
  if (todo.empty())
  {
    return;
  }
  const CriticalSimplices& cs = this->Re.Critical();
  const Triangulation& tri = this->Re.Tri();
  this->MakeForest();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size()),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        Line& line = this->Lines[static_cast<std::size_t>(todo[k])];
        const auto& facet = cs.Facets[static_cast<std::size_t>(line.Node - this->Re.Base2())];
        const CellHandle side = FlowLineSides(tri, facet.Cell, facet.Opposite)[line.Side];
        // A line to infinity is never pending (its arc is known at once).
        line.Target = static_cast<std::int32_t>(this->Forest->Root(tri.CellId(side)));
      }
    });
  for (const Id l : todo)
  {
    if (this->Lines[l].Target < 0 ||
      static_cast<double>(this->Lines[l].Bound) > this->Values[this->Lines[l].Target])
    {
      throw InputError("deferred flow lines: a line ends below its bound");
    }
  }
  this->Followed += static_cast<Id>(todo.size());
}

void DeferredFlowLines::MakeForest()
{
  if (!this->Forest)
  {
    if (this->Re.Base3() + static_cast<Id>(this->Re.Critical().Cells.size()) != this->InfinityNode)
    {
      throw InputError("deferred flow lines: the complex does not fit its triangulation");
    }
    this->Forest = &this->Re.Flow();
  }
}

std::vector<DeferredFlowLines::Ends> DeferredFlowLines::EndsAbove(
  double levelSq, const std::vector<char>* only, EndMemo* memo)
{
  const Triangulation& tri = this->Re.Tri();
  if (memo && (memo->LevelSq != levelSq || memo->Triangulation != tri.Serial() ||
                memo->End.size() != this->Lines.size()))
  {
    memo->LevelSq = levelSq;
    memo->Triangulation = tri.Serial();
    memo->End.assign(this->Lines.size(), -1);
  }
  std::vector<Ends> out;
  std::vector<Id> todo; // line positions
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    if (this->Done[k] || (only && !(*only)[static_cast<std::size_t>(this->Pending[k])]))
    {
      continue;
    }
    Ends e;
    e.Node = this->Pending[k];
    e.End = { this->Other[k], this->Other[k] };
    for (Id l = this->PendingBegin[k]; l < this->PendingBegin[k + 1]; ++l)
    {
      todo.push_back(l);
    }
    out.push_back(e);
  }
  if (todo.empty())
  {
    return out;
  }
  const CriticalSimplices& cs = this->Re.Critical();
  this->MakeForest();
  std::vector<Id> end(todo.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, todo.size()),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        const std::size_t l = static_cast<std::size_t>(todo[k]);
        if (memo && memo->End[l] != -1)
        {
          end[k] = memo->End[l];
          continue;
        }
        const Line& line = this->Lines[l];
        const auto& facet = cs.Facets[static_cast<std::size_t>(line.Node - this->Re.Base2())];
        const CellHandle side = FlowLineSides(tri, facet.Cell, facet.Opposite)[line.Side];
        double boundSq = 0;
        Id stop = -1;
        const Id root = this->Forest->RootBelow(tri.CellId(side), levelSq, &boundSq, &stop);
        end[k] = root == SuccessorForest::Pending ? -2 - stop : root;
        if (memo)
        {
          memo->End[l] = static_cast<std::int32_t>(end[k]); // one line, one thread
        }
      }
    });
  std::size_t e = 0;
  for (std::size_t k = 0; k < todo.size(); ++k)
  {
    const Line& line = this->Lines[static_cast<std::size_t>(todo[k])];
    while (out[e].Node != line.Node)
    {
      ++e;
    }
    out[e].End[line.Side] = end[k];
  }
  return out;
}

void DeferredFlowLines::FollowBoundsUpTo(double value)
{
  std::vector<Id> nodes;
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    if (!this->Done[k] && !(this->LeastBound(k) > value))
    {
      nodes.push_back(this->Pending[k]);
    }
  }
  this->Follow(nodes);
}

void DeferredFlowLines::AppendRawRow(std::size_t k, std::vector<Arc>& arcs) const
{
  std::int32_t ends[2] = { -1, -1 };
  for (Id l = this->PendingBegin[k]; l < this->PendingBegin[k + 1]; ++l)
  {
    ends[this->Lines[l].Side] = this->Lines[l].Target;
  }
  const std::int32_t other = this->Other[k];
  for (std::int32_t& e : ends)
  {
    e = e >= 0 ? e : other;
  }
  const Id x = this->Pending[k];
  if (ends[0] == ends[1])
  {
    arcs.emplace_back(x, ends[0], 2);
  }
  else
  {
    arcs.emplace_back(x, ends[0], 1);
    arcs.emplace_back(x, ends[1], 1);
  }
}

std::vector<Arc> DeferredFlowLines::FollowedRawArcs() const
{
  std::vector<Arc> arcs;
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    if (this->Done[k])
    {
      this->AppendRawRow(k, arcs);
    }
  }
  return arcs;
}

void DeferredFlowLines::CompleteRawArcs(std::vector<Arc>& arcs) const
{
  const std::vector<Arc> followed = this->FollowedRawArcs();
  if (followed.empty())
  {
    return;
  }
  // The 2-3 group is the tail, by lower node: merge the followed nodes in.
  std::size_t tail = arcs.size();
  while (tail > 0 && arcs[tail - 1].Upper >= this->Base3)
  {
    --tail;
  }
  ReplaceRows(arcs, tail, followed);
}

void ReplaceRows(std::vector<Arc>& arcs, std::size_t tail, const std::vector<Arc>& rows)
{
  std::vector<Arc> merged;
  merged.reserve(arcs.size() - tail + rows.size());
  std::size_t f = 0;
  for (std::size_t i = tail; i < arcs.size(); ++i)
  {
    while (f < rows.size() && rows[f].Lower < arcs[i].Lower)
    {
      merged.push_back(rows[f++]);
    }
    if (f < rows.size() && rows[f].Lower == arcs[i].Lower)
    {
      continue; // replaced by its row
    }
    merged.push_back(arcs[i]);
  }
  merged.insert(merged.end(), rows.begin() + static_cast<std::ptrdiff_t>(f), rows.end());
  arcs.resize(tail);
  arcs.insert(arcs.end(), merged.begin(), merged.end());
}

void DeferredFlowLines::SetSimplification(const SimplificationResult* s, double persistenceThreshold)
{
  const std::size_t n = this->Values.size();
  this->RemovedAt.assign(n, -1);
  this->Uppers = CompressedRows<Id>();
  this->Survives.assign(n, true);
  std::vector<double> low(this->Values);
  if (s)
  {
    if (!s->HasUppers || s->Uppers.RowCount() != static_cast<Id>(s->Pairs.size()) ||
      s->Survives.size() != n)
    {
      throw InputError("deferred flow lines: the simplification did not record its pairs");
    }
    this->Uppers = s->Uppers;
    this->Survives = s->Survives;
    for (std::size_t p = 0; p < s->Pairs.size(); ++p)
    {
      const CancelledPair& pair = s->Pairs[p];
      if (pair.PairType != 2)
      {
        continue;
      }
      // Its Out list went to the lowers of its upper: it must be the eager one.
      const std::size_t k = this->Position(pair.Lower);
      if (k != std::string::npos && !this->Done[k])
      {
        throw Degenerate("deferred flow lines: a cancellation moved a pending line");
      }
      this->RemovedAt[pair.Upper] = static_cast<std::int32_t>(p);
    }
    // LowExp: the least value a replay from a maximum passes, in reverse order
    // (what a pair hands on was cancelled later, if at all).
    for (std::size_t p = s->Pairs.size(); p-- > 0;)
    {
      if (s->Pairs[p].PairType == 2)
      {
        double& l = low[s->Pairs[p].Upper];
        for (const Id y : this->Uppers.Row(static_cast<Id>(p)))
        {
          l = std::min(l, low[y]);
        }
      }
    }
  }
  std::vector<std::pair<double, double>> maxima; // (value, LowExp)
  for (Id v = this->Base3; v <= this->InfinityNode; ++v)
  {
    maxima.emplace_back(this->Values[v], low[v]);
  }
  std::sort(maxima.begin(), maxima.end());
  this->SortedValues.resize(maxima.size());
  this->SuffixLow.resize(maxima.size() + 1);
  this->SuffixLow.back() = HUGE_VAL;
  for (std::size_t i = maxima.size(); i-- > 0;)
  {
    this->SortedValues[i] = maxima[i].first;
    this->SuffixLow[i] = std::min(this->SuffixLow[i + 1], maxima[i].second);
  }
  // No arc a pending line may change is a candidate (ratio <= t_p).
  if (s && persistenceThreshold >= 1)
  {
    for (const Id x : this->NodesBelowRatio(persistenceThreshold))
    {
      throw Degenerate("deferred flow lines: node " + std::to_string(x) +
        " may have had a candidate arc the simplification did not see");
    }
  }
  this->Simplified = true;
  this->FollowedSince.clear();
  this->ByLowerBound.clear();
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    if (!this->Done[k])
    {
      this->ByLowerBound.emplace_back(this->LowerBound(this->LeastBound(k)), k);
    }
  }
  // Distinct keys (the second member): any sort gives the same order.
  tbb::parallel_sort(this->ByLowerBound.begin(), this->ByLowerBound.end());
  this->NextByBound = 0;
}

double DeferredFlowLines::LowerBound(double bound) const
{
  const auto it = std::lower_bound(this->SortedValues.begin(), this->SortedValues.end(), bound);
  return this->SuffixLow[static_cast<std::size_t>(it - this->SortedValues.begin())];
}

std::vector<Id> DeferredFlowLines::NodesBelowRatio(double ratio) const
{
  std::vector<Id> nodes;
  for (std::size_t k = 0; k < this->Pending.size(); ++k)
  {
    if (!this->Done[k] &&
      !(this->LowerBound(this->LeastBound(k)) > ratio * this->Values[this->Pending[k]] * (1 + Margin)))
    {
      nodes.push_back(this->Pending[k]);
    }
  }
  return nodes;
}

std::vector<std::pair<Id, int>> DeferredFlowLines::FinalArcs(Id x) const
{
  const std::size_t k = this->Position(x);
  if (k == std::string::npos || !this->Done[k])
  {
    throw std::logic_error("deferred flow lines: final arcs of a node not followed");
  }
  // The row of x through the 2-3 cancellations, as the simplifier changes it
  // (HasseDiagram::FlipParity: odd -> gone, even -> 1), in pair order.
  std::map<Id, std::pair<int, bool>> row; // maximum -> (multiplicity, touched)
  std::vector<Arc> raw; // x's own raw row: all the raw arcs would make the callers quadratic
  this->AppendRawRow(k, raw);
  for (const Arc& a : raw)
  {
    row[a.Upper].first += a.Multiplicity;
  }
  std::map<std::int32_t, Id> queue; // pair -> the maximum it removes
  for (const auto& e : row)
  {
    if (this->RemovedAt[e.first] >= 0)
    {
      queue.emplace(this->RemovedAt[e.first], e.first);
    }
  }
  while (!queue.empty())
  {
    const std::int32_t p = queue.begin()->first;
    const Id b = queue.begin()->second;
    queue.erase(queue.begin());
    const auto it = row.find(b);
    const bool odd = it != row.end() && it->second.first % 2 == 1;
    if (it != row.end())
    {
      row.erase(it);
    }
    if (!odd)
    {
      continue;
    }
    for (const Id y : this->Uppers.Row(p))
    {
      auto& e = row[y];
      e = e.first % 2 == 1 ? std::make_pair(0, true) : std::make_pair(1, true);
      if (e.first == 0)
      {
        row.erase(y);
      }
      else if (this->RemovedAt[y] >= 0)
      {
        if (this->RemovedAt[y] <= p)
        {
          throw InputError("deferred flow lines: a cancellation hands on a removed node");
        }
        queue.emplace(this->RemovedAt[y], y);
      }
    }
  }
  std::vector<std::pair<Id, int>> arcs;
  for (const auto& e : row)
  {
    if (this->Survives[e.first] && e.second.first > 0)
    {
      arcs.emplace_back(e.first, e.second.first);
    }
  }
  return arcs;
}

void DeferredFlowLines::CompleteSimplifiedArcs(std::vector<Arc>& simplifiedArcs)
{
  std::vector<Id> nodes;
  nodes.swap(this->FollowedSince);
  std::sort(nodes.begin(), nodes.end());
  std::vector<Arc> added;
  for (const Id x : nodes)
  {
    if (this->Survives[x])
    {
      for (const auto& e : this->FinalArcs(x))
      {
        added.emplace_back(x, e.first, e.second);
      }
    }
  }
  if (nodes.empty())
  {
    return;
  }
  // One merge pass: the rows of `nodes` (all 2-3 arcs) are replaced.
  std::vector<Arc> merged;
  merged.reserve(simplifiedArcs.size() + added.size());
  std::size_t k = 0, a = 0;
  for (const Arc& arc : simplifiedArcs)
  {
    while (a < added.size() && std::tie(added[a].Lower, added[a].Upper) < std::tie(arc.Lower, arc.Upper))
    {
      merged.push_back(added[a++]);
    }
    while (k < nodes.size() && nodes[k] < arc.Lower)
    {
      ++k;
    }
    if (k < nodes.size() && nodes[k] == arc.Lower && arc.Upper >= this->Base3)
    {
      continue;
    }
    merged.push_back(arc);
  }
  merged.insert(merged.end(), added.begin() + static_cast<std::ptrdiff_t>(a), added.end());
  simplifiedArcs.swap(merged);
}

std::vector<InListChange> DeferredFlowLines::InChangesUpTo(
  double value, const std::vector<Arc>& simplifiedArcs, const std::vector<Insertion>* run)
{
  std::vector<Id> nodes;
  while (this->NextByBound < this->ByLowerBound.size())
  {
    const std::size_t k = this->ByLowerBound[this->NextByBound].second;
    if (this->ByLowerBound[this->NextByBound].first > value * (1 + Margin))
    {
      break;
    }
    ++this->NextByBound;
    if (!this->Done[k] && !(run && (*run)[static_cast<std::size_t>(this->Pending[k])].Step >= 0))
    {
      nodes.push_back(this->Pending[k]);
    }
  }
  this->Follow(nodes);
  this->FollowedSince.clear(); // their changes are returned
  std::vector<InListChange> changes;
  for (const Id x : nodes)
  {
    if (!this->Survives[x])
    {
      continue;
    }
    std::vector<Id> before;
    const auto range = RowOf(simplifiedArcs, x);
    for (std::size_t i = range.first; i < range.second; ++i)
    {
      if (simplifiedArcs[i].Upper >= this->Base3)
      {
        before.push_back(simplifiedArcs[i].Upper);
      }
    }
    std::vector<Id> after;
    for (const auto& e : this->FinalArcs(x))
    {
      after.push_back(e.first);
    }
    std::vector<Id> gone, come;
    std::set_difference(before.begin(), before.end(), after.begin(), after.end(), std::back_inserter(gone));
    std::set_difference(after.begin(), after.end(), before.begin(), before.end(), std::back_inserter(come));
    for (const Id y : gone)
    {
      changes.push_back(InListChange{ x, y, false });
    }
    for (const Id y : come)
    {
      changes.push_back(InListChange{ x, y, true });
    }
  }
  return changes;
}

} // namespace flowrecon
