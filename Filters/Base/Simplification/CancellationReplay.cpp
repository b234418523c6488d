#include "CancellationReplay.h"

#include <functional>
#include <queue>
#include <unordered_map>

namespace flowrecon
{

CancellationReplay::CancellationReplay(std::size_t nodeCount, const SimplificationResult& s)
  : S(s)
  , LowerPair(nodeCount, -1)
  , RemovedBy(nodeCount, -1)
{
  if (s.Survives.size() != nodeCount || !s.HasLowers || s.Lowers.RowCount() != static_cast<Id>(s.Pairs.size()))
  {
    throw InputError("replay: the simplification did not record what a replay needs");
  }
  for (std::size_t p = 0; p < s.Pairs.size(); ++p)
  {
    const CancelledPair& pair = s.Pairs[p];
    if (pair.Lower < 0 || pair.Upper < 0 || static_cast<std::size_t>(pair.Lower) >= nodeCount ||
      static_cast<std::size_t>(pair.Upper) >= nodeCount)
    {
      throw InputError("replay: a cancelled pair out of range");
    }
    if (pair.PairType == 1)
    {
      this->LowerPair[pair.Lower] = static_cast<std::int32_t>(p);
    }
    this->RemovedBy[pair.Lower] = this->RemovedBy[pair.Upper] = static_cast<std::int32_t>(p);
  }
}

void CancellationReplay::Replay(
  Id y, std::vector<std::pair<Id, int>>& in, std::vector<std::pair<Id, Id>>& owners) const
{
  const SimplificationResult& s = this->S;
  // Pairs cancelled after y went do not touch it.
  const Id stop = this->RemovedBy[y] >= 0 ? this->RemovedBy[y] : static_cast<Id>(s.Pairs.size());
  using Event = std::pair<Id, Id>; // (pair, lower)
  std::priority_queue<Event, std::vector<Event>, std::greater<Event>> events;
  auto schedule = [&](Id x) {
    const Id p = this->LowerPair[x];
    if (p >= 0 && p < stop)
    {
      events.emplace(p, x);
    }
  };
  for (const auto& e : in)
  {
    schedule(e.first);
  }
  // Positions in `in`, so that each flip costs O(1) rather than a scan of the list.
  std::unordered_map<Id, std::size_t> where;
  where.reserve(in.size() * 2);
  for (std::size_t i = 0; i < in.size(); ++i)
  {
    where.emplace(in[i].first, i);
  }
  auto remove = [&](std::unordered_map<Id, std::size_t>::iterator it) {
    const std::size_t i = it->second;
    where.erase(it);
    if (i + 1 != in.size())
    {
      in[i] = in.back();
      where[in[i].first] = i;
    }
    in.pop_back();
  };
  // Cancellations in their order. A lower x of b joins y's list only while x is
  // alive, so x's own cancellation comes later: the queue only moves on.
  while (!events.empty())
  {
    const Event e = events.top();
    events.pop();
    const auto a = where.find(e.second);
    if (a == where.end())
    {
      continue; // flipped away before its cancellation (or a repeat)
    }
    // Every successor of a gets its cells, even arcs too (Simplification.cpp).
    owners.emplace_back(e.first, y);
    if (in[a->second].second % 2 == 1)
    {
      // d'y = dy + <dy, a> db over Z/2: y's incidence with each odd lower of b flips.
      for (const Id x : s.Lowers.Row(e.first))
      {
        const auto it = where.find(x);
        if (it == where.end())
        {
          where.emplace(x, in.size());
          in.emplace_back(x, 1);
          schedule(x);
        }
        else if (in[it->second].second % 2 == 1)
        {
          remove(it);
        }
        else
        {
          in[it->second].second = 1;
        }
      }
    }
    const auto gone = where.find(e.second); // a itself may be among b's lowers
    if (gone != where.end())
    {
      remove(gone);
    }
  }
}

} // namespace flowrecon
