#include "CellHomology.h"

#include "MemoryGuard.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>
#include <type_traits>

namespace flowrecon
{

void FilteredCells::Add(const Id* points, int count, double value)
{
  this->Points.insert(this->Points.end(), points, points + count);
  this->Offsets.push_back(static_cast<Id>(this->Points.size()));
  this->Values.push_back(value);
}

namespace
{

/// Simplices of one dimension K-1 as keys: K vertex ids of 31 bits each, the
/// first in the most significant place, so that keys sort like vertex tuples.
template <int K>
struct Layer
{
  using Key = typename std::conditional<K <= 2, std::uint64_t, unsigned __int128>::type;
  struct Simplex
  {
    Key V;
    double Value;
    Id Cell; ///< the cell that brings it at Value (the first such cell)
  };
  std::vector<Simplex> S; ///< sorted by key once Finish() ran
  std::vector<Id> Rank;   ///< by position in S
  std::vector<Id> Order;  ///< position in S of the simplex of each rank

  static Key Pack(const Id* v)
  {
    Key key = 0;
    for (int i = 0; i < K; ++i)
    {
      key = (key << 31) | static_cast<Key>(v[i]);
    }
    return key;
  }
  static std::array<Id, K> Unpack(Key key)
  {
    std::array<Id, K> v{};
    for (int i = K - 1; i >= 0; --i)
    {
      v[i] = static_cast<Id>(key & 0x7FFFFFFF);
      key >>= 31;
    }
    return v;
  }
  void Add(const Id* v, double value, Id cell) { this->S.push_back({ Pack(v), value, cell }); }

  void Finish()
  {
    std::sort(this->S.begin(), this->S.end(), [](const Simplex& a, const Simplex& b) {
      return a.V < b.V || (a.V == b.V && (a.Value < b.Value || (a.Value == b.Value && a.Cell < b.Cell)));
    });
    // Equal keys are one simplex, present from its least value (the first).
    this->S.erase(std::unique(this->S.begin(), this->S.end(),
                    [](const Simplex& a, const Simplex& b) { return a.V == b.V; }),
      this->S.end());
    this->S.shrink_to_fit();
    this->Order.resize(this->S.size());
    std::iota(this->Order.begin(), this->Order.end(), Id(0));
    std::sort(this->Order.begin(), this->Order.end(), [this](Id a, Id b) {
      const Simplex &x = this->S[a], &y = this->S[b];
      return x.Value < y.Value || (x.Value == y.Value && x.V < y.V);
    });
    this->Rank.resize(this->S.size());
    for (std::size_t r = 0; r < this->Order.size(); ++r)
    {
      this->Rank[this->Order[r]] = static_cast<Id>(r);
    }
  }

  Id RankOf(const Id* v) const
  {
    const Key key = Pack(v);
    const auto it = std::lower_bound(this->S.begin(), this->S.end(), key,
      [](const Simplex& s, Key k) { return s.V < k; });
    return this->Rank[it - this->S.begin()];
  }
  const Simplex& OfRank(Id r) const { return this->S[this->Order[r]]; }
  double ValueOfRank(Id r) const { return this->OfRank(r).Value; }
  Id CellOfRank(Id r) const { return this->OfRank(r).Cell; }
};

/// Adds to `lower` the faces of every simplex of `upper` (each with its value).
template <int K>
void AddFaces(const Layer<K>& upper, Layer<K - 1>& lower)
{
  lower.S.reserve(lower.S.size() + K * upper.S.size());
  for (const auto& s : upper.S)
  {
    const std::array<Id, K> v = Layer<K>::Unpack(s.V);
    for (int skip = 0; skip < K; ++skip)
    {
      std::array<Id, K - 1> f{};
      for (int i = 0, k = 0; i < K; ++i)
      {
        if (i != skip)
        {
          f[k++] = v[i];
        }
      }
      lower.Add(f.data(), s.Value, s.Cell);
    }
  }
}

void Push(std::vector<Bar>& bars, int dimension, double birth, double death, Id birthCell,
  Id deathCell)
{
  if (birth < death)
  {
    bars.push_back(Bar{ dimension, birth, death, birthCell, deathCell });
  }
}

/// Z/2 reduction of coboundary columns (persistent cohomology, de Silva,
/// Morozov and Vejdemo-Johansson): columns are sorted coface ranks, the pivot is
/// the least one. Why cohomology: the boundary columns of cone tetrahedra fill
/// in (measured: 1.2 M entries added for 2·10^5 tetrahedra), while a triangle
/// has at most a few cofaces and its columns stay short.
class Reducer
{
public:
  explicit Reducer(std::size_t rows)
    : PivotColumn(rows, -1)
  {
  }

  /// Reduces `column` (sorted) against the columns reduced so far; returns its
  /// pivot row, or -1 when it reduces to zero. A non-zero column is kept.
  Id Reduce(std::vector<Id>& column)
  {
    while (!column.empty())
    {
      const Id low = column.front();
      const Id other = this->PivotColumn[low];
      if (other < 0)
      {
        this->PivotColumn[low] = static_cast<Id>(this->Columns.size());
        this->Columns.push_back(std::move(column));
        column.clear();
        return low;
      }
      const std::vector<Id>& add = this->Columns[other];
      this->Sum.clear();
      std::set_symmetric_difference(
        column.begin(), column.end(), add.begin(), add.end(), std::back_inserter(this->Sum));
      column.swap(this->Sum);
    }
    return -1;
  }

private:
  std::vector<Id> PivotColumn;
  std::vector<std::vector<Id>> Columns;
  std::vector<Id> Sum;
};

/// Cofaces by rank as compressed rows: for each simplex of `lower` (by rank),
/// the ranks in `upper` of the simplices it is a face of, sorted.
template <int K>
void Cofaces(const Layer<K>& upper, const Layer<K - 1>& lower, std::vector<Id>& offsets,
  std::vector<Id>& list)
{
  std::vector<std::pair<Id, Id>> pairs; // (face rank, coface rank)
  pairs.reserve(K * upper.S.size());
  for (Id r = 0; r < static_cast<Id>(upper.Order.size()); ++r)
  {
    const std::array<Id, K> v = Layer<K>::Unpack(upper.OfRank(r).V);
    for (int skip = 0; skip < K; ++skip)
    {
      std::array<Id, K - 1> f{};
      for (int i = 0, k = 0; i < K; ++i)
      {
        if (i != skip)
        {
          f[k++] = v[i];
        }
      }
      pairs.emplace_back(lower.RankOf(f.data()), r);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  offsets.assign(lower.S.size() + 1, 0);
  list.resize(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    ++offsets[pairs[k].first + 1];
    list[k] = pairs[k].second;
  }
  for (std::size_t i = 0; i < lower.S.size(); ++i)
  {
    offsets[i + 1] += offsets[i];
  }
}

/// One dimension of persistent cohomology: the simplices of `lower` from the
/// youngest to the eldest, skipping the `cleared` ones (deaths of the dimension
/// below); a pivot pairs the simplex (birth) with that coface (death). Marks the
/// deaths in `deaths` (for the next dimension) and pushes essential classes.
template <int K>
void CohomologyPass(const Layer<K>& upper, const Layer<K - 1>& lower,
  const std::vector<char>& cleared, std::vector<char>& deaths, std::vector<Bar>& bars,
  const Progress& progress, double from, double to)
{
  std::vector<Id> offsets, list;
  Cofaces(upper, lower, offsets, list);
  Reducer reducer(upper.S.size());
  deaths.assign(upper.S.size(), 0);
  std::vector<Id> column;
  const Id n = static_cast<Id>(lower.Order.size());
  for (Id r = n - 1; r >= 0; --r)
  {
    if ((r & 0xFFFF) == 0)
    {
      progress(from + (to - from) * static_cast<double>(n - r) / static_cast<double>(n),
        "Betti numbers");
    }
    if (cleared[r])
    {
      continue;
    }
    column.assign(list.begin() + offsets[r], list.begin() + offsets[r + 1]);
    const Id pivot = reducer.Reduce(column);
    if (pivot < 0)
    {
      Push(bars, K - 2, lower.ValueOfRank(r), HUGE_VAL, lower.CellOfRank(r), -1);
    }
    else
    {
      deaths[pivot] = 1;
      Push(bars, K - 2, lower.ValueOfRank(r), upper.ValueOfRank(pivot), lower.CellOfRank(r),
        upper.CellOfRank(pivot));
    }
  }
}

Id Find(std::vector<Id>& parent, Id x)
{
  while (parent[x] != x)
  {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

} // namespace

std::vector<Bar> CellBarcode(const FilteredCells& cells, const Progress& progress)
{
  if (cells.Offsets.size() != cells.Values.size() + 1 || cells.Offsets.back() != static_cast<Id>(cells.Points.size()))
  {
    throw InputError("cell homology: inconsistent cell arrays");
  }
  // Every face of every cell is listed before duplicates go: 376 bytes for a
  // tetrahedron, 152 for a triangle; then ranks and reduced columns.
  double bytes = 0;
  for (Id c = 0; c < cells.Size(); ++c)
  {
    const Id n = cells.Offsets[c + 1] - cells.Offsets[c];
    bytes += n >= 4 ? 376 : n == 3 ? 152 : n == 2 ? 56 : 16;
  }
  RequireMemory(1.6 * bytes, "the Betti numbers of " + std::to_string(cells.Size()) + " cells",
    "lower the reconstruction threshold (or MaximumThreshold)");
  Layer<1> l0;
  Layer<2> l1;
  Layer<3> l2;
  Layer<4> l3;
  progress(0, "Betti numbers");
  for (Id c = 0; c < cells.Size(); ++c)
  {
    const Id first = cells.Offsets[c], last = cells.Offsets[c + 1];
    const double value = cells.Values[c];
    if (last - first < 1 || last - first > 4 || std::isnan(value))
    {
      throw InputError("cell homology: cell " + std::to_string(c) +
        (std::isnan(value) ? " has no value" : " is not a vertex, segment, triangle or tetrahedron"));
    }
    std::array<Id, 4> p{};
    std::copy(cells.Points.begin() + first, cells.Points.begin() + last, p.begin());
    const auto end = p.begin() + (last - first);
    std::sort(p.begin(), end);
    // A cell with a repeated point spans a lower simplex.
    const int n = static_cast<int>(std::unique(p.begin(), end) - p.begin());
    if (p[0] < 0 || p[n - 1] > 0x7FFFFFFF)
    {
      throw InputError("cell homology: cell " + std::to_string(c) + " has a point id outside [0, 2^31)");
    }
    switch (n)
    {
      case 1: l0.Add(p.data(), value, c); break;
      case 2: l1.Add(p.data(), value, c); break;
      case 3: l2.Add(p.data(), value, c); break;
      default: l3.Add(p.data(), value, c); break;
    }
  }
  // Down one dimension at a time: the faces of the distinct simplices only.
  l3.Finish();
  AddFaces(l3, l2);
  l2.Finish();
  AddFaces(l2, l1);
  l1.Finish();
  AddFaces(l1, l0);
  l0.Finish();
  progress(0.2, "Betti numbers");
  std::vector<Bar> bars;

  // H0 by union-find: an edge joining two components kills the younger one.
  std::vector<Id> parent(l0.S.size());
  std::iota(parent.begin(), parent.end(), Id(0));
  std::vector<char> positiveEdge(l1.S.size(), 0);
  for (Id r = 0; r < static_cast<Id>(l1.Order.size()); ++r)
  {
    const auto& e = l1.OfRank(r);
    const std::array<Id, 2> ends = Layer<2>::Unpack(e.V);
    Id a = Find(parent, l0.RankOf(&ends[0])), b = Find(parent, l0.RankOf(&ends[1]));
    if (a == b)
    {
      positiveEdge[r] = 1;
      continue;
    }
    if (a < b)
    {
      std::swap(a, b); // b is the elder (smaller rank): it survives
    }
    Push(bars, 0, l0.ValueOfRank(a), e.Value, l0.CellOfRank(a), e.Cell);
    parent[a] = b;
  }
  for (Id v = 0; v < static_cast<Id>(parent.size()); ++v)
  {
    if (Find(parent, v) == v)
    {
      Push(bars, 0, l0.ValueOfRank(v), HUGE_VAL, l0.CellOfRank(v), -1);
    }
  }
  progress(0.4, "Betti numbers");

  // Cohomology upward with clearing: an edge that joined two components is no
  // birth of H1, a triangle that killed an H1 class no birth of H2.
  std::vector<char> deathEdges(l1.S.size(), 0), deathTriangles, deathTetrahedra;
  for (Id r = 0; r < static_cast<Id>(l1.S.size()); ++r)
  {
    deathEdges[r] = positiveEdge[r] ? 0 : 1;
  }
  CohomologyPass(l2, l1, deathEdges, deathTriangles, bars, progress, 0.4, 0.7);
  CohomologyPass(l3, l2, deathTriangles, deathTetrahedra, bars, progress, 0.7, 0.95);
  // No 4-simplices: a tetrahedron that killed no H2 class creates an H3 class.
  for (Id r = 0; r < static_cast<Id>(l3.S.size()); ++r)
  {
    if (!deathTetrahedra[r])
    {
      Push(bars, 3, l3.ValueOfRank(r), HUGE_VAL, l3.CellOfRank(r), -1);
    }
  }
  std::sort(bars.begin(), bars.end(), [](const Bar& a, const Bar& b) {
    return std::tie(a.Dimension, a.Birth, a.Death) < std::tie(b.Dimension, b.Birth, b.Death);
  });
  progress(1, "Betti numbers");
  return bars;
}

std::array<Id, 4> BettiNumbersBelow(const std::vector<Bar>& bars, double t)
{
  std::array<Id, 4> betti{ { 0, 0, 0, 0 } };
  for (const Bar& b : bars)
  {
    if (b.Birth < t && t <= b.Death)
    {
      ++betti[b.Dimension];
    }
  }
  return betti;
}

std::vector<TopologyStep> TopologyProfile(
  const std::vector<Bar>& bars, double start, double limit)
{
  // Events: a class is present for t in (Birth, Death].
  std::vector<std::pair<double, std::array<Id, 4>>> events;
  for (const Bar& b : bars)
  {
    std::array<Id, 4> up{ { 0, 0, 0, 0 } }, down{ { 0, 0, 0, 0 } };
    up[b.Dimension] = 1;
    down[b.Dimension] = -1;
    events.emplace_back(b.Birth, up);
    if (std::isfinite(b.Death))
    {
      events.emplace_back(b.Death, down);
    }
  }
  std::sort(events.begin(), events.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<TopologyStep> steps;
  TopologyStep current;
  current.Threshold = events.empty() ? start : std::min(start, events.front().first);
  std::size_t k = 0;
  // Row for t just above `at`: every event <= at applied.
  auto advance = [&](double at) {
    for (; k < events.size() && events[k].first <= at; ++k)
    {
      for (int d = 0; d < 4; ++d)
      {
        current.Betti[d] += events[k].second[d];
      }
    }
  };
  advance(current.Threshold);
  steps.push_back(current);
  while (k < events.size() && events[k].first < limit)
  {
    const double at = events[k].first;
    advance(at);
    if (current.Betti != steps.back().Betti)
    {
      current.Threshold = at;
      steps.push_back(current);
    }
  }
  return steps;
}

std::vector<TopologyChange> TopologyChangesAbove(
  const std::vector<Bar>& bars, double t, double factor)
{
  std::vector<TopologyChange> changes;
  const double limit = t * factor;
  for (const Bar& b : bars)
  {
    if (b.Birth >= t && b.Birth < limit)
    {
      changes.push_back(TopologyChange{ b.Dimension, b.Birth, +1, b.BirthCell });
    }
    if (b.Death >= t && b.Death < limit)
    {
      changes.push_back(TopologyChange{ b.Dimension, b.Death, -1, b.DeathCell });
    }
  }
  std::sort(changes.begin(), changes.end(), [](const TopologyChange& a, const TopologyChange& b) {
    return std::tie(a.Threshold, a.Dimension, a.Change, a.Cell) <
      std::tie(b.Threshold, b.Dimension, b.Change, b.Cell);
  });
  return changes;
}

} // namespace flowrecon
