#include "CellHomology.h"

#include "CompressedRows.h"
#include "MemoryGuard.h"
#include "Z2ColumnReduction.h"

#include <tbb/parallel_sort.h>

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
    Id From; ///< while listing: K' x position + slot in the layer above, -1 for a cell
  };
  std::vector<Simplex> S; ///< sorted by key once Finish() ran
  std::vector<Id> Rank;   ///< by position in S
  std::vector<Id> Order;  ///< position in S of the simplex of each rank
  /// The ranks of the K faces of each simplex (by position), once the layer
  /// below has finished: found while sorting, not searched for.
  std::vector<Id> Faces;

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
  void Add(const Id* v, double value, Id cell, Id from = -1)
  {
    this->S.push_back({ Pack(v), value, cell, from });
  }

  /// Sorts and merges the listed simplices; `above` (the layer whose faces were
  /// listed here, or null) learns the rank of each of its faces. (Sorted in
  /// parallel: entries equal under the order are copies of one simplex from one
  /// cell, which get the same rank whichever comes first.)
  void Finish(std::vector<Id>* above)
  {
    tbb::parallel_sort(this->S.begin(), this->S.end(), [](const Simplex& a, const Simplex& b) {
      return a.V < b.V || (a.V == b.V && (a.Value < b.Value || (a.Value == b.Value && a.Cell < b.Cell)));
    });
    // Equal keys are one simplex, present from its least value (the first).
    std::size_t unique = 0;
    for (std::size_t i = 0; i < this->S.size(); ++i)
    {
      if (i > 0 && this->S[i].V == this->S[unique - 1].V)
      {
        if (above && this->S[i].From >= 0)
        {
          (*above)[this->S[i].From] = static_cast<Id>(unique - 1);
        }
        continue;
      }
      if (above && this->S[i].From >= 0)
      {
        (*above)[this->S[i].From] = static_cast<Id>(unique);
      }
      this->S[unique++] = this->S[i];
    }
    this->S.resize(unique);
    this->S.shrink_to_fit();
    // Filtration order: by value, then key (= position): sorted directly.
    std::vector<std::pair<double, Id>> order(this->S.size());
    for (std::size_t i = 0; i < this->S.size(); ++i)
    {
      order[i] = { this->S[i].Value, static_cast<Id>(i) };
    }
    tbb::parallel_sort(order.begin(), order.end());
    this->Order.resize(this->S.size());
    this->Rank.resize(this->S.size());
    for (std::size_t r = 0; r < order.size(); ++r)
    {
      this->Order[r] = order[r].second;
      this->Rank[order[r].second] = static_cast<Id>(r);
    }
    if (above)
    {
      for (Id& f : *above)
      {
        f = this->Rank[f];
      }
    }
  }

  const Simplex& OfRank(Id r) const { return this->S[this->Order[r]]; }
  double ValueOfRank(Id r) const { return this->OfRank(r).Value; }
  Id CellOfRank(Id r) const { return this->OfRank(r).Cell; }
  /// The ranks below of the faces of the simplex of rank r.
  const Id* FacesOfRank(Id r) const { return this->Faces.data() + K * this->Order[r]; }
};

/// Adds to `lower` the faces of every simplex of `upper` (each with its value),
/// remembering where each comes from (see Layer::Finish).
template <int K>
void AddFaces(Layer<K>& upper, Layer<K - 1>& lower)
{
  if (lower.S.capacity() < lower.S.size() + K * upper.S.size())
  {
    lower.S.reserve(lower.S.size() + K * upper.S.size());
  }
  upper.Faces.assign(K * upper.S.size(), -1);
  for (std::size_t p = 0; p < upper.S.size(); ++p)
  {
    const auto& s = upper.S[p];
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
      lower.Add(f.data(), s.Value, s.Cell, static_cast<Id>(K * p + skip));
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

using Reduction = Z2ColumnReduction<Id>;

/// Cofaces by rank: for each simplex of `lower` (by rank), the ranks in `upper`
/// of the simplices it is a face of, increasing (they are listed by rank).
template <int K>
CompressedRows<Id> Cofaces(const Layer<K>& upper, const Layer<K - 1>& lower)
{
  return CompressedRows<Id>::Group(lower.S.size(), [&](const auto& emit) {
    for (Id r = 0; r < static_cast<Id>(upper.Order.size()); ++r)
    {
      const Id* faces = upper.FacesOfRank(r);
      for (int k = 0; k < K; ++k)
      {
        emit(faces[k], r);
      }
    }
  });
}

/// The (triangle, tetrahedron) pairs by persistent cohomology: the triangles
/// from the youngest to the eldest, each column its cofaces; a pivot pairs the
/// triangle (birth of an H2 class) with that tetrahedron (its death). Why
/// cohomology: the boundary columns of cone tetrahedra fill in (measured: 1.2 M
/// entries added for 2·10^5 tetrahedra), while a triangle has few cofaces. No
/// clearing (the triangles that kill H1 classes are not known yet): their
/// columns reduce to zero, so zero columns say nothing here.
void TrianglePairs(const Layer<4>& tets, const Layer<3>& triangles, std::vector<char>& born,
  std::vector<char>& killer, std::vector<Bar>& bars, const Progress& progress)
{
  const CompressedRows<Id> cofaces = Cofaces(tets, triangles);
  Reduction reduction(tets.S.size(), Reduction::Pivot::Least);
  born.assign(triangles.S.size(), 0);
  killer.assign(tets.S.size(), 0);
  std::vector<Id> column;
  const Id n = static_cast<Id>(triangles.Order.size());
  for (Id r = n - 1; r >= 0; --r)
  {
    if ((r & 0xFFFF) == 0)
    {
      progress(0.4 + 0.3 * static_cast<double>(n - r) / static_cast<double>(n), "Betti numbers");
    }
    const RowRange<Id> row = cofaces.Row(r);
    if (row.empty())
    {
      continue;
    }
    column.assign(row.begin(), row.end());
    const Id pivot = reduction.Reduce(column);
    if (pivot >= 0)
    {
      born[r] = 1;
      killer[pivot] = 1;
      Push(bars, 2, triangles.ValueOfRank(r), tets.ValueOfRank(pivot), triangles.CellOfRank(r),
        tets.CellOfRank(pivot));
    }
  }
}

/// The (edge, triangle) pairs by homology with clearing: the boundary columns
/// of the triangles, in filtration order, skipping those that create an H2
/// class that dies (`born`: their columns would reduce to zero). A triangle
/// whose column reduces to zero and that no tetrahedron pairs creates an H2
/// class that never dies.
void EdgePairs(const Layer<3>& triangles, const Layer<2>& edges, const std::vector<char>& born,
  std::vector<char>& killed, std::vector<Bar>& bars, const Progress& progress)
{
  Reduction reduction(edges.S.size(), Reduction::Pivot::Greatest);
  killed.assign(edges.S.size(), 0);
  std::vector<Id> column;
  const Id n = static_cast<Id>(triangles.Order.size());
  for (Id r = 0; r < n; ++r)
  {
    if ((r & 0xFFFF) == 0)
    {
      progress(0.7 + 0.25 * static_cast<double>(r) / static_cast<double>(n), "Betti numbers");
    }
    if (born[r])
    {
      continue;
    }
    const Id* e = triangles.FacesOfRank(r);
    column.assign(e, e + 3);
    std::sort(column.begin(), column.end());
    const Id pivot = reduction.Reduce(column);
    if (pivot < 0)
    {
      Push(bars, 2, triangles.ValueOfRank(r), HUGE_VAL, triangles.CellOfRank(r), -1);
    }
    else
    {
      killed[pivot] = 1;
      Push(bars, 1, edges.ValueOfRank(pivot), triangles.ValueOfRank(r), edges.CellOfRank(pivot),
        triangles.CellOfRank(r));
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

/// The simplicial complex the cells span: its simplices by dimension, each
/// present from the least value of the cells it is a face of.
struct CellComplex
{
  Layer<1> Vertices;
  Layer<2> Edges;
  Layer<3> Triangles;
  Layer<4> Tetrahedra;
};

/// Lists the cells as simplices, then their faces, down one dimension at a time.
void ListSimplices(const FilteredCells& cells, CellComplex& complex)
{
  Layer<1>& l0 = complex.Vertices;
  Layer<2>& l1 = complex.Edges;
  Layer<3>& l2 = complex.Triangles;
  Layer<4>& l3 = complex.Tetrahedra;
  // Reserved once: growing lists of tens of millions by doubling copied them
  // and faulted their pages in again (a third of the time on solids).
  {
    std::array<std::size_t, 5> count{};
    for (Id c = 0; c < cells.Size(); ++c)
    {
      ++count[static_cast<std::size_t>(std::min<Id>(4, std::max<Id>(0, cells.Offsets[c + 1] - cells.Offsets[c])))];
    }
    l3.S.reserve(count[4]);
    l2.S.reserve(count[3] + 4 * count[4]);
    l1.S.reserve(count[2] + 3 * count[3] + 6 * count[4]);
    l0.S.reserve(count[1] + 2 * count[2] + 3 * count[3] + 4 * count[4]);
  }
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
  l3.Finish(nullptr);
  AddFaces(l3, l2);
  l2.Finish(&l3.Faces);
  AddFaces(l2, l1);
  l1.Finish(&l2.Faces);
  AddFaces(l1, l0);
  l0.Finish(&l1.Faces);
}

/// H0 by union-find: an edge joining two components kills the younger one.
/// `positiveEdge` marks the edges that join none (they create H1 classes).
void VertexPairs(const Layer<1>& vertices, const Layer<2>& edges,
  std::vector<char>& positiveEdge, std::vector<Bar>& bars)
{
  std::vector<Id> parent(vertices.S.size());
  std::iota(parent.begin(), parent.end(), Id(0));
  positiveEdge.assign(edges.S.size(), 0);
  for (Id r = 0; r < static_cast<Id>(edges.Order.size()); ++r)
  {
    const auto& e = edges.OfRank(r);
    const Id* ends = edges.FacesOfRank(r);
    Id a = Find(parent, ends[0]), b = Find(parent, ends[1]);
    if (a == b)
    {
      positiveEdge[r] = 1;
      continue;
    }
    if (a < b)
    {
      std::swap(a, b); // b is the elder (smaller rank): it survives
    }
    Push(bars, 0, vertices.ValueOfRank(a), e.Value, vertices.CellOfRank(a), e.Cell);
    parent[a] = b;
  }
  for (Id v = 0; v < static_cast<Id>(parent.size()); ++v)
  {
    if (Find(parent, v) == v)
    {
      Push(bars, 0, vertices.ValueOfRank(v), HUGE_VAL, vertices.CellOfRank(v), -1);
    }
  }
}

} // namespace

std::string TooManyCells(Id cells, Id maximumCells)
{
  return "skipped for " + std::to_string(cells) + " cells, more than " +
    std::to_string(maximumCells) + " (flowrecon --betti-max-cells, MaximumTopologyCells)";
}

std::vector<Bar> CellBarcode(const FilteredCells& cells, const Progress& progress, Id maximumCells)
{
  if (maximumCells >= 0 && cells.Size() > maximumCells)
  {
    throw InputError(TooManyCells(cells.Size(), maximumCells));
  }
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
  CellComplex complex;
  progress(0, "Betti numbers");
  ListSimplices(cells, complex);
  progress(0.2, "Betti numbers");
  std::vector<Bar> bars;
  std::vector<char> positiveEdge;
  VertexPairs(complex.Vertices, complex.Edges, positiveEdge, bars);
  progress(0.4, "Betti numbers");

  // H2 pairs by cohomology, then H1 pairs by homology with clearing.
  const Layer<2>& l1 = complex.Edges;
  const Layer<4>& l3 = complex.Tetrahedra;
  std::vector<char> bornTriangles, killerTetrahedra, killedEdges;
  TrianglePairs(l3, complex.Triangles, bornTriangles, killerTetrahedra, bars, progress);
  EdgePairs(complex.Triangles, l1, bornTriangles, killedEdges, bars, progress);
  for (Id r = 0; r < static_cast<Id>(l1.S.size()); ++r)
  {
    if (positiveEdge[r] && !killedEdges[r])
    {
      Push(bars, 1, l1.ValueOfRank(r), HUGE_VAL, l1.CellOfRank(r), -1);
    }
  }
  // No 4-simplices: a tetrahedron that killed no H2 class creates an H3 class.
  for (Id r = 0; r < static_cast<Id>(l3.S.size()); ++r)
  {
    if (!killerTetrahedra[r])
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
  // Events: a class is present for t in (Birth, Death]; (threshold, dimension
  // and sign) in 16 bytes, as a filter redraws this for every t_r.
  std::vector<std::pair<double, int>> events;
  events.reserve(2 * bars.size());
  for (const Bar& b : bars)
  {
    events.emplace_back(b.Birth, 4 + b.Dimension);
    if (std::isfinite(b.Death))
    {
      events.emplace_back(b.Death, b.Dimension);
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
      current.Betti[events[k].second & 3] += events[k].second >= 4 ? 1 : -1;
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
