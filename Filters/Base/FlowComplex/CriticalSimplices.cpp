#include "CriticalSimplices.h"

#include "CompressedRows.h"
#include "Driver.h"
#include "FastPredicates.h"
#include "ParallelSlices.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>

namespace flowrecon
{

Id CriticalSimplices::FindEdge(Id u, Id v) const
{
  const Id a = std::min(u, v), b = std::max(u, v);
  const RowRange<std::array<Id, 2>> row = this->Edges.Row(a);
  const auto it = std::lower_bound(
    row.begin(), row.end(), b, [](const std::array<Id, 2>& e, Id value) { return e[1] < value; });
  return (it != row.end() && (*it)[1] == b) ? it - this->Edges.Values.data() : -1;
}

namespace
{

template <std::size_t N>
std::array<std::int32_t, N> Sorted(std::array<std::int32_t, N> a)
{
  std::sort(a.begin(), a.end());
  return a;
}

std::int32_t VertexId(const CellHandle c, int i)
{
  return static_cast<std::int32_t>(c->vertex(i)->info());
}

constexpr int EdgePairs[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
constexpr Id Slice = Id(1) << 20; // cells per progress report
constexpr Id Ahead = 8;            // cells between a prefetch and its use

/// All Delaunay edges (u < v) as adjacency lists: row u holds the v, sorted.
/// 32-bit values: the largest table here.
using EdgeLists = CompressedRows<std::int32_t>;

/// Position of edge uv in lists.Values (which must hold it).
Id EdgePosition(const EdgeLists& lists, Id u, Id v)
{
  if (u > v)
  {
    std::swap(u, v);
  }
  const RowRange<std::int32_t> row = lists.Row(u);
  return std::lower_bound(row.begin(), row.end(), static_cast<std::int32_t>(v)) - lists.Values.data();
}

/// Collected from the cells (CGAL's edge iterator circulates around every edge;
/// this is much cheaper).
void BuildEdgeLists(const Triangulation& tri, EdgeLists& lists, const Progress& progress)
{
  const Id m = tri.NumberOfVertices(), nc = tri.NumberOfCells();
  auto forEachEdge = [&](Id cell, const auto& f) {
    // The vertices' ids: a cache miss each, asked for a few cells ahead.
    if (cell + Ahead < nc)
    {
      const CellHandle ahead = tri.Cell(cell + Ahead);
      for (int i = 0; i < 4; ++i)
      {
        __builtin_prefetch(&ahead->vertex(i)->info());
      }
    }
    const CellHandle c = tri.Cell(cell);
    for (const auto& p : EdgePairs)
    {
      const Id u = c->vertex(p[0])->info(), v = c->vertex(p[1])->info();
      f(std::min(u, v), std::max(u, v));
    }
  };
  // Each edge is seen once per incident cell: count, place, then sort and
  // deduplicate each list (the order within a list is then canonical).
  std::vector<std::atomic<Id>> fill(static_cast<std::size_t>(m + 1));
  ParallelSlices(nc, Slice, progress, 0.20, 0.22, "critical points", [&](Id first, Id last) {
    for (Id id = first; id < last; ++id)
    {
      forEachEdge(id, [&](Id u, Id) { fill[u + 1].fetch_add(1, std::memory_order_relaxed); });
    }
  });
  lists.Offsets.assign(static_cast<std::size_t>(m + 1), 0);
  for (Id u = 0; u < m; ++u)
  {
    lists.Offsets[u + 1] = lists.Offsets[u] + fill[u + 1].load(std::memory_order_relaxed);
    fill[u].store(lists.Offsets[u], std::memory_order_relaxed);
  }
  lists.Values.resize(static_cast<std::size_t>(lists.Offsets[m]));
  ParallelSlices(nc, Slice, progress, 0.22, 0.24, "critical points", [&](Id first, Id last) {
    for (Id id = first; id < last; ++id)
    {
      forEachEdge(id, [&](Id u, Id v) {
        lists.Values[fill[u].fetch_add(1, std::memory_order_relaxed)] = static_cast<std::int32_t>(v);
      });
    }
  });
  std::vector<std::atomic<Id>>().swap(fill);
  std::vector<Id> length(static_cast<std::size_t>(m));
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      const auto first = lists.Values.begin() + lists.Offsets[u];
      const auto last = lists.Values.begin() + lists.Offsets[u + 1];
      std::sort(first, last);
      length[u] = std::unique(first, last) - first;
    }
  });
  // Compact in place (forward copies never overwrite unread entries).
  Id write = 0;
  for (Id u = 0; u < m; ++u)
  {
    const auto first = lists.Values.begin() + lists.Offsets[u];
    lists.Offsets[u] = write;
    std::copy(first, first + length[u], lists.Values.begin() + write);
    write += length[u];
  }
  lists.Offsets[m] = write;
  lists.Values.resize(static_cast<std::size_t>(write)); // no shrink: short-lived
}

/// What one slice of cells contributes; slices are merged in order. Compact
/// codes (cell id and facet index) rather than vertex lists: these lists are
/// written once and read once, and memory that is touched costs time.
struct SliceResult
{
  std::vector<std::array<std::int32_t, 2>> Facets;
  std::vector<std::int32_t> Cells;
  Id RightAngles = 0, ApexOnSphere = 0, CircumcentresOnFacet = 0;
};

/// Expands the `member` codes of all slices with make(code) and returns the items
/// sorted by their (distinct, sorted) Vertices: a counting sort on the first
/// vertex (< m), then a small sort per bucket. Much faster than a comparison
/// sort of the whole list.
template <class T, class Code, class Make>
std::vector<T> GatherSorted(
  std::vector<SliceResult>& slices, std::vector<Code> SliceResult::*member, Id m, const Make& make)
{
  std::vector<std::atomic<Id>> fill(static_cast<std::size_t>(m + 1));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, slices.size()), [&](const auto& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s)
    {
      for (const Code& code : slices[s].*member)
      {
        fill[make(code).Vertices[0] + 1].fetch_add(1, std::memory_order_relaxed);
      }
    }
  });
  std::vector<Id> begin(static_cast<std::size_t>(m + 1), 0);
  for (Id u = 0; u < m; ++u)
  {
    begin[u + 1] = begin[u] + fill[u + 1].load(std::memory_order_relaxed);
    fill[u].store(begin[u], std::memory_order_relaxed);
  }
  std::vector<T> sorted(static_cast<std::size_t>(begin[m]));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, slices.size()), [&](const auto& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s)
    {
      for (const Code& code : slices[s].*member)
      {
        const T item = make(code);
        sorted[fill[item.Vertices[0]].fetch_add(1, std::memory_order_relaxed)] = item;
      }
      std::vector<Code>().swap(slices[s].*member);
    }
  });
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      std::sort(sorted.begin() + begin[u], sorted.begin() + begin[u + 1],
        [](const T& a, const T& b) { return a.Vertices < b.Vertices; });
    }
  });
  return sorted;
}

/// The Delaunay facets that cell `id` handles (each facet is handled by the cell
/// of smaller id, or the finite one on the hull): an obtuse one marks the edge
/// opposite its obtuse corner not Gabriel, an acute one is critical when both
/// apices lie strictly outside its diametral ball. Then the cell itself, if
/// self-centred. Degeneracies are counted in `out`.
void ClassifySimplicesOfCell(const Triangulation& tri, const EdgeLists& edges, Id id,
  std::vector<std::atomic<std::uint8_t>>& notGabriel, SliceResult& out)
{
  const Delaunay& dt = tri.Dt();
  const CellHandle c = tri.Cell(id);
  for (int i = 0; i < 4; ++i)
  {
    const CellHandle n = c->neighbor(i);
    const Id nid = n->info(); // -1 for the infinite cells
    if (nid >= 0 && nid < id)
    {
      continue;
    }
    const VertexHandle v[3] = { c->vertex((i + 1) % 4), c->vertex((i + 2) % 4),
      c->vertex((i + 3) % 4) };
    int obtuse = -1;
    try
    {
      obtuse = ObtuseCorner(v[0]->point(), v[1]->point(), v[2]->point());
    }
    catch (const flowrecon::Degenerate&)
    {
      ++out.RightAngles;
      continue;
    }
    if (obtuse >= 0)
    {
      notGabriel[EdgePosition(edges, v[(obtuse + 1) % 3]->info(), v[(obtuse + 2) % 3]->info())].store(
        1, std::memory_order_relaxed);
      continue; // an obtuse facet is not self-centred
    }
    // Acute: critical iff both apices lie strictly outside its diametral ball.
    bool gabriel = true;
    const VertexHandle apex[2] = { c->vertex(i), n->vertex(n->index(c)) };
    for (const VertexHandle a : apex)
    {
      if (dt.is_infinite(a))
      {
        continue;
      }
      const CGAL::Bounded_side side =
        FastSideOfDiametralSphere(v[0]->point(), v[1]->point(), v[2]->point(), a->point());
      if (side == CGAL::ON_BOUNDARY)
      {
        ++out.ApexOnSphere;
      }
      gabriel = gabriel && side == CGAL::ON_UNBOUNDED_SIDE;
    }
    if (gabriel)
    {
      out.Facets.push_back({ { static_cast<std::int32_t>(id), i } });
    }
  }
  // Index 3: self-centred cells (Lemma B.2).
  try
  {
    if (IsSelfCentred(c))
    {
      out.Cells.push_back(static_cast<std::int32_t>(id));
    }
  }
  catch (const flowrecon::Degenerate&)
  {
    ++out.CircumcentresOnFacet;
  }
}

/// One parallel pass over the cells (ClassifySimplicesOfCell). A facet obtuse
/// at t puts t strictly inside the diametral ball of the opposite edge, so that
/// edge is not Gabriel; every link vertex of an edge is the third vertex of one
/// of its facets, so the edges never marked are exactly the Gabriel edges
/// (CGAL's is_Gabriel, in one pass). The same pass finds the self-centred cells.
std::vector<SliceResult> ClassifySimplices(const Triangulation& tri, const EdgeLists& edges,
  std::vector<std::atomic<std::uint8_t>>& notGabriel, const Progress& progress)
{
  const Id nc = tri.NumberOfCells();
  const Id grain = 4096;
  std::vector<SliceResult> results(static_cast<std::size_t>((nc + grain - 1) / grain));
  const Id nChunks = static_cast<Id>(results.size());
  ParallelSlices(nChunks, Slice / grain, progress, 0.24, 0.32, "critical points", [&](Id first, Id last) {
    for (Id chunk = first; chunk < last; ++chunk)
    {
      SliceResult& out = results[chunk];
      const Id end = std::min(nc, (chunk + 1) * grain);
      for (Id id = chunk * grain; id < end; ++id)
      {
        // The neighbours' ids decide which cell handles a facet: a cache
        // miss each (cells are scattered in memory), asked for ahead.
        if (id + Ahead < end)
        {
          const CellHandle ahead = tri.Cell(id + Ahead);
          for (int i = 0; i < 4; ++i)
          {
            __builtin_prefetch(&ahead->neighbor(i)->info());
          }
        }
        ClassifySimplicesOfCell(tri, edges, id, notGabriel, out);
      }
    }
  });
  return results;
}

/// The critical facets and cells of all slices, sorted by vertex ids: the order
/// is independent of the (concurrent) triangulation's cell order.
void SortCriticalSimplices(const Triangulation& tri, std::vector<SliceResult>& results,
  CriticalSimplices& cs)
{
  cs.Facets = GatherSorted<CriticalFacet>(results, &SliceResult::Facets, tri.NumberOfVertices(),
    [&](const std::array<std::int32_t, 2>& code) {
      const CellHandle c = tri.Cell(code[0]);
      const int i = code[1];
      return CriticalFacet{ Sorted<3>({ { VertexId(c, (i + 1) % 4), VertexId(c, (i + 2) % 4),
                              VertexId(c, (i + 3) % 4) } }),
        code[0], i };
    });
  cs.Cells = GatherSorted<CriticalCell>(
    results, &SliceResult::Cells, tri.NumberOfVertices(), [&](std::int32_t id) {
      const CellHandle c = tri.Cell(id);
      return CriticalCell{ Sorted<4>({ { VertexId(c, 0), VertexId(c, 1), VertexId(c, 2),
                             VertexId(c, 3) } }),
        id };
    });
}

/// The Gabriel edges (those never marked) in adjacency order: count per
/// vertex, then fill.
void GabrielEdges(const EdgeLists& edges, const std::vector<std::atomic<std::uint8_t>>& notGabriel,
  Id m, CompressedRows<std::array<Id, 2>>& gabriel)
{
  std::vector<Id>& offsets = gabriel.Offsets;
  offsets.assign(static_cast<std::size_t>(m + 1), 0);
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      Id count = 0;
      for (Id k = edges.Offsets[u]; k < edges.Offsets[u + 1]; ++k)
      {
        count += notGabriel[k].load(std::memory_order_relaxed) ? 0 : 1;
      }
      offsets[u + 1] = count;
    }
  });
  for (Id u = 0; u < m; ++u)
  {
    offsets[u + 1] += offsets[u];
  }
  gabriel.Values.resize(static_cast<std::size_t>(offsets[m]));
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      Id next = offsets[u];
      for (Id k = edges.Offsets[u]; k < edges.Offsets[u + 1]; ++k)
      {
        if (!notGabriel[k].load(std::memory_order_relaxed))
        {
          gabriel.Values[next++] = { { u, edges.Values[k] } };
        }
      }
    }
  });
}

} // namespace

CriticalSimplices FindCriticalSimplices(const Triangulation& tri, const Progress& progress)
{
  CriticalSimplices cs;
  EdgeLists edges;
  BuildEdgeLists(tri, edges, progress);
  std::vector<std::atomic<std::uint8_t>> notGabriel(edges.Values.size());
  std::vector<SliceResult> results = ClassifySimplices(tri, edges, notGabriel, progress);
  Id circumcentresOnFacet = 0;
  for (const SliceResult& r : results)
  {
    cs.RightAngles += r.RightAngles;
    cs.ApexOnSphere += r.ApexOnSphere;
    circumcentresOnFacet += r.CircumcentresOnFacet;
  }
  if (cs.Degenerate())
  {
    return cs; // the caller perturbs and starts again
  }
  if (circumcentresOnFacet > 0)
  {
    // An apex on the diametral sphere of an obtuse facet: not a counted kind.
    throw Degenerate("circumcentre on a facet");
  }
  progress(0.32, "critical points");
  SortCriticalSimplices(tri, results, cs);
  GabrielEdges(edges, notGabriel, tri.NumberOfVertices(), cs.Edges);
  return cs;
}

} // namespace flowrecon
