#include "CriticalSimplices.h"

#include "Driver.h"
#include "FastPredicates.h"

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
  const auto first = this->Neighbours.begin() + this->Offsets[a];
  const auto last = this->Neighbours.begin() + this->Offsets[a + 1];
  const auto it = std::lower_bound(first, last, static_cast<std::int32_t>(b));
  return (it != last && *it == b) ? this->GabrielIndex[it - this->Neighbours.begin()] : -1;
}

namespace
{

template <std::size_t N>
std::array<Id, N> Sorted(std::array<Id, N> a)
{
  std::sort(a.begin(), a.end());
  return a;
}

/// Runs body(first, last) over [0, n) in parallel, in slices of `slice` items
/// so that progress is reported (and abort honoured) on the calling thread.
template <class Body>
void ParallelSlices(Id n, Id slice, const Progress& progress, double from, double to,
  const char* phase, const Body& body)
{
  for (Id begin = 0; begin < n; begin += slice)
  {
    progress(from + (to - from) * static_cast<double>(begin) / static_cast<double>(n), phase);
    tbb::parallel_for(tbb::blocked_range<Id>(begin, std::min(n, begin + slice)),
      [&](const tbb::blocked_range<Id>& r) { body(r.begin(), r.end()); });
  }
}

constexpr int EdgePairs[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
constexpr Id Slice = Id(1) << 20; // cells per progress report

/// All Delaunay edges (u < v) as sorted adjacency lists, collected from the cells
/// (CGAL's edge iterator circulates around every edge; this is much cheaper).
void BuildEdgeLists(const Triangulation& tri, CriticalSimplices& cs, const Progress& progress)
{
  const Id m = tri.NumberOfVertices(), nc = tri.NumberOfCells();
  auto forEachEdge = [&](Id cell, const auto& f) {
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
  cs.Offsets.assign(static_cast<std::size_t>(m + 1), 0);
  for (Id u = 0; u < m; ++u)
  {
    cs.Offsets[u + 1] = cs.Offsets[u] + fill[u + 1].load(std::memory_order_relaxed);
    fill[u].store(cs.Offsets[u], std::memory_order_relaxed);
  }
  cs.Neighbours.resize(static_cast<std::size_t>(cs.Offsets[m]));
  ParallelSlices(nc, Slice, progress, 0.22, 0.24, "critical points", [&](Id first, Id last) {
    for (Id id = first; id < last; ++id)
    {
      forEachEdge(id, [&](Id u, Id v) {
        cs.Neighbours[fill[u].fetch_add(1, std::memory_order_relaxed)] = static_cast<std::int32_t>(v);
      });
    }
  });
  std::vector<std::atomic<Id>>().swap(fill);
  std::vector<Id> length(static_cast<std::size_t>(m));
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      const auto first = cs.Neighbours.begin() + cs.Offsets[u];
      const auto last = cs.Neighbours.begin() + cs.Offsets[u + 1];
      std::sort(first, last);
      length[u] = std::unique(first, last) - first;
    }
  });
  // Compact in place (forward copies never overwrite unread entries).
  Id write = 0;
  for (Id u = 0; u < m; ++u)
  {
    const auto first = cs.Neighbours.begin() + cs.Offsets[u];
    cs.Offsets[u] = write;
    std::copy(first, first + length[u], cs.Neighbours.begin() + write);
    write += length[u];
  }
  cs.Offsets[m] = write;
  cs.Neighbours.resize(static_cast<std::size_t>(write));
  cs.Neighbours.shrink_to_fit();
}

struct FacetEntry
{
  std::array<Id, 3> Vertices;
  CellHandle Cell;
  int Opposite;
};

/// What one slice of cells contributes; slices are merged in order.
struct SliceResult
{
  std::vector<FacetEntry> Facets;
  std::vector<std::pair<std::array<Id, 4>, Id>> Cells;
  Id RightAngles = 0, ApexOnSphere = 0, CircumcentresOnFacet = 0;
};

/// Gathers the `member` lists of all slices sorted by their (distinct, sorted)
/// vertex arrays: a counting sort on the first vertex (< m), then a small sort
/// per bucket. Much faster than a comparison sort of the whole list.
template <class T, class Key>
std::vector<T> SortByVertices(
  std::vector<SliceResult>& slices, std::vector<T> SliceResult::*member, Id m, const Key& key)
{
  std::vector<std::atomic<Id>> fill(static_cast<std::size_t>(m + 1));
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, slices.size()), [&](const auto& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s)
    {
      for (const T& item : slices[s].*member)
      {
        fill[key(item)[0] + 1].fetch_add(1, std::memory_order_relaxed);
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
      for (const T& item : slices[s].*member)
      {
        sorted[fill[key(item)[0]].fetch_add(1, std::memory_order_relaxed)] = item;
      }
      std::vector<T>().swap(slices[s].*member);
    }
  });
  tbb::parallel_for(tbb::blocked_range<Id>(0, m), [&](const tbb::blocked_range<Id>& r) {
    for (Id u = r.begin(); u != r.end(); ++u)
    {
      std::sort(sorted.begin() + begin[u], sorted.begin() + begin[u + 1],
        [&](const T& a, const T& b) { return key(a) < key(b); });
    }
  });
  return sorted;
}

} // namespace

CriticalSimplices FindCriticalSimplices(const Triangulation& tri, const Progress& progress)
{
  const Delaunay& dt = tri.Dt();
  CriticalSimplices cs;
  BuildEdgeLists(tri, cs, progress);
  auto position = [&](Id u, Id v) {
    if (u > v)
    {
      std::swap(u, v);
    }
    const auto first = cs.Neighbours.begin() + cs.Offsets[u];
    return std::lower_bound(first, cs.Neighbours.begin() + cs.Offsets[u + 1],
             static_cast<std::int32_t>(v)) -
      cs.Neighbours.begin();
  };

  // One parallel pass over the cells; each facet is handled by the cell of
  // smaller id (or the finite one, on the hull). A facet obtuse at t puts t
  // strictly inside the diametral ball of the opposite edge, so that edge is not
  // Gabriel; every link vertex of an edge is the third vertex of one of its
  // facets, so the edges never marked are exactly the Gabriel edges (CGAL's
  // is_Gabriel, in one pass). The same pass finds the self-centred cells.
  std::vector<std::atomic<std::uint8_t>> notGabriel(cs.Neighbours.size());
  const Id nc = tri.NumberOfCells();
  const Id grain = 4096;
  std::vector<SliceResult> results(static_cast<std::size_t>((nc + grain - 1) / grain));
  const Id nChunks = static_cast<Id>(results.size());
  ParallelSlices(nChunks, Slice / grain, progress, 0.24, 0.32, "critical points", [&](Id first, Id last) {
    for (Id chunk = first; chunk < last; ++chunk)
    {
      SliceResult& out = results[chunk];
      for (Id id = chunk * grain; id < std::min(nc, (chunk + 1) * grain); ++id)
      {
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
            notGabriel[position(v[(obtuse + 1) % 3]->info(), v[(obtuse + 2) % 3]->info())].store(
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
            out.Facets.push_back(
              { Sorted<3>({ { v[0]->info(), v[1]->info(), v[2]->info() } }), c, i });
          }
        }
        // Index 3: self-centred cells (Lemma B.2).
        try
        {
          if (IsSelfCentred(c))
          {
            out.Cells.emplace_back(Sorted<4>({ { c->vertex(0)->info(), c->vertex(1)->info(),
                                     c->vertex(2)->info(), c->vertex(3)->info() } }),
              id);
          }
        }
        catch (const flowrecon::Degenerate&)
        {
          ++out.CircumcentresOnFacet;
        }
      }
    }
  });
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

  // Lists sorted by vertex ids: the order is independent of the (concurrent)
  // triangulation's cell order.
  {
    const std::vector<FacetEntry> facets = SortByVertices(results, &SliceResult::Facets,
      tri.NumberOfVertices(), [](const FacetEntry& f) -> const auto& { return f.Vertices; });
    cs.Facets.resize(facets.size());
    cs.FacetCells.resize(facets.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, facets.size()),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t k = r.begin(); k != r.end(); ++k)
        {
          cs.Facets[k] = facets[k].Vertices;
          cs.FacetCells[k] = { facets[k].Cell, facets[k].Opposite };
        }
      });
  }
  {
    const auto cells = SortByVertices(results, &SliceResult::Cells, tri.NumberOfVertices(),
      [](const std::pair<std::array<Id, 4>, Id>& c) -> const auto& { return c.first; });
    cs.Cells.resize(cells.size());
    cs.CellOfMaximum.resize(cells.size());
    for (std::size_t k = 0; k < cells.size(); ++k)
    {
      cs.Cells[k] = cells[k].first;
      cs.CellOfMaximum[k] = cells[k].second;
    }
  }

  // Gabriel edges in adjacency order: count per block of vertices, then fill.
  const Id m = tri.NumberOfVertices();
  const Id block = 4096, nBlocks = (m + block - 1) / block;
  std::vector<Id> start(static_cast<std::size_t>(nBlocks + 1), 0);
  tbb::parallel_for(tbb::blocked_range<Id>(0, nBlocks), [&](const tbb::blocked_range<Id>& r) {
    for (Id b = r.begin(); b != r.end(); ++b)
    {
      for (Id k = cs.Offsets[b * block]; k < cs.Offsets[std::min(m, (b + 1) * block)]; ++k)
      {
        start[b + 1] += notGabriel[k].load(std::memory_order_relaxed) ? 0 : 1;
      }
    }
  });
  for (Id b = 0; b < nBlocks; ++b)
  {
    start[b + 1] += start[b];
  }
  cs.Edges.resize(static_cast<std::size_t>(start[nBlocks]));
  cs.GabrielIndex.assign(cs.Neighbours.size(), -1);
  tbb::parallel_for(tbb::blocked_range<Id>(0, nBlocks), [&](const tbb::blocked_range<Id>& r) {
    for (Id b = r.begin(); b != r.end(); ++b)
    {
      Id next = start[b];
      for (Id u = b * block; u < std::min(m, (b + 1) * block); ++u)
      {
        for (Id k = cs.Offsets[u]; k < cs.Offsets[u + 1]; ++k)
        {
          if (!notGabriel[k].load(std::memory_order_relaxed))
          {
            cs.GabrielIndex[k] = static_cast<std::int32_t>(next);
            cs.Edges[next++] = { { u, cs.Neighbours[k] } };
          }
        }
      }
    }
  });
  return cs;
}

} // namespace flowrecon
