#include "StoredCriticalSimplices.h"

#include "Driver.h"
#include "FastPredicates.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>

namespace flowrecon
{

namespace
{

/// The nodes of one index as sorted triangulation vertex ids, with the rows of
/// their first vertex (the lists are sorted, so each row is a run).
template <std::size_t N>
struct Keys
{
  std::vector<std::array<std::int32_t, N>> Simplices;
  std::vector<Id> Offsets; // per vertex, where its run starts; one past the last vertex
};

template <std::size_t N>
bool MakeKeys(const std::vector<Node>& nodes, Id first, Id count, const std::vector<std::int32_t>& vertexOf,
  Id vertices, Keys<N>& keys)
{
  keys.Simplices.resize(static_cast<std::size_t>(count));
  std::atomic<bool> ok{ true };
  tbb::parallel_for(tbb::blocked_range<Id>(0, count), [&](const tbb::blocked_range<Id>& r) {
    for (Id k = r.begin(); k != r.end(); ++k)
    {
      const Node& node = nodes[static_cast<std::size_t>(first + k)];
      std::array<std::int32_t, N>& s = keys.Simplices[static_cast<std::size_t>(k)];
      if (node.Index != static_cast<int>(N) - 1)
      {
        ok = false;
        return;
      }
      for (std::size_t i = 0; i < N; ++i)
      {
        const std::int32_t id = node.Simplex[i];
        if (id < 0 || static_cast<std::size_t>(id) >= vertexOf.size() || vertexOf[id] < 0)
        {
          ok = false;
          return;
        }
        s[i] = vertexOf[id];
      }
      std::sort(s.begin(), s.end());
    }
  });
  if (!ok)
  {
    return false;
  }
  keys.Offsets.assign(static_cast<std::size_t>(vertices + 1), 0);
  for (std::size_t k = 0; k < keys.Simplices.size(); ++k)
  {
    const auto& s = keys.Simplices[k];
    // Strictly increasing: the builder's order, and no simplex twice.
    if (k > 0 && !(keys.Simplices[k - 1] < s))
    {
      return false;
    }
    for (std::size_t i = 1; i < N; ++i)
    {
      if (s[i - 1] == s[i])
      {
        return false;
      }
    }
    ++keys.Offsets[static_cast<std::size_t>(s[0]) + 1];
  }
  for (Id v = 0; v < vertices; ++v)
  {
    keys.Offsets[static_cast<std::size_t>(v + 1)] += keys.Offsets[static_cast<std::size_t>(v)];
  }
  return true;
}

/// Position of `key` in the run of its least vertex, -1 when absent (runs are
/// a few entries long).
template <std::size_t N>
Id Find(const Keys<N>& keys, const std::array<std::int32_t, N>& key)
{
  const std::size_t v = static_cast<std::size_t>(key[0]);
  for (Id k = keys.Offsets[v]; k < keys.Offsets[v + 1]; ++k)
  {
    const std::array<std::int32_t, N>& s = keys.Simplices[static_cast<std::size_t>(k)];
    bool same = true;
    for (std::size_t i = 1; i < N; ++i)
    {
      same = same && s[i] == key[i];
    }
    if (same)
    {
      return k;
    }
  }
  return -1;
}

} // namespace

CriticalSimplices StoredCriticalSimplices(const Triangulation& tri, const std::vector<Node>& nodes,
  const std::vector<Id>& inputId, const char* mismatch, const Progress& progress)
{
  const Id m = tri.NumberOfVertices();
  std::array<Id, 4> n{ { 0, 0, 0, 0 } };
  for (const Node& node : nodes)
  {
    if (!node.IsInfinity() && node.Index >= 0 && node.Index <= 3)
    {
      ++n[static_cast<std::size_t>(node.Index)];
    }
  }
  const Id finite = n[0] + n[1] + n[2] + n[3];
  // Morse's relation for d_P on R^3: a node missing alone shows here.
  if (tri.Dimension() < 3 || static_cast<Id>(inputId.size()) != m || n[0] != m ||
    static_cast<Id>(nodes.size()) != finite + 1 || !nodes.back().IsInfinity() ||
    n[0] - n[1] + n[2] - n[3] != 1)
  {
    throw InputError(mismatch);
  }
  std::vector<std::int32_t> vertexOf;
  for (Id k = 0; k < m; ++k)
  {
    const Id id = inputId[static_cast<std::size_t>(k)];
    if (id < 0 || id >= INT32_MAX)
    {
      throw InputError(mismatch);
    }
    if (static_cast<std::size_t>(id) >= vertexOf.size())
    {
      vertexOf.resize(static_cast<std::size_t>(id) + 1, -1);
    }
    vertexOf[static_cast<std::size_t>(id)] = static_cast<std::int32_t>(k);
    const Node& sample = nodes[static_cast<std::size_t>(k)];
    if (sample.Index != 0 || sample.Simplex[0] != id)
    {
      throw InputError(mismatch);
    }
  }
  Keys<2> edges;
  Keys<3> facets;
  Keys<4> cells;
  if (!MakeKeys(nodes, m, n[1], vertexOf, m, edges) ||
    !MakeKeys(nodes, m + n[1], n[2], vertexOf, m, facets) ||
    !MakeKeys(nodes, m + n[1] + n[2], n[3], vertexOf, m, cells))
  {
    throw InputError(mismatch);
  }
  CriticalSimplices cs;
  cs.Edges.Offsets = edges.Offsets;
  cs.Edges.Values.reserve(edges.Simplices.size());
  for (const auto& e : edges.Simplices)
  {
    cs.Edges.Values.push_back({ { e[0], e[1] } });
  }
  cs.Facets.resize(facets.Simplices.size());
  cs.Cells.resize(cells.Simplices.size());
  // One pass over the cells, as FindCriticalSimplices makes, but the
  // predicates only on what the nodes name: each node edge's facets (none
  // obtuse against it), each node facet from the cell that handles it (the
  // finite one of least id: acute, apices strictly outside its diametral
  // ball), each node cell (self-centred).
  std::vector<std::atomic<std::uint8_t>> seen(edges.Simplices.size() + facets.Simplices.size() +
    cells.Simplices.size());
  const Delaunay& dt = tri.Dt();
  const std::size_t facetSeen = edges.Simplices.size();
  const std::size_t cellSeen = facetSeen + facets.Simplices.size();
  std::atomic<bool> ok{ true };
  tbb::parallel_for(tbb::blocked_range<Id>(0, tri.NumberOfCells(), 4096), [&](const tbb::blocked_range<Id>& r) {
    try
    {
      for (Id id = r.begin(); id != r.end() && ok.load(std::memory_order_relaxed); ++id)
      {
        const CellHandle c = tri.Cell(id);
        std::array<std::int32_t, 4> v;
        std::array<int, 4> local; // v[k] is c->vertex(local[k])
        for (int i = 0; i < 4; ++i)
        {
          v[i] = static_cast<std::int32_t>(c->vertex(i)->info());
          local[i] = i;
        }
        std::sort(local.begin(), local.end(), [&](int a, int b) { return v[a] < v[b]; });
        std::sort(v.begin(), v.end());
        const auto point = [&](int k) -> const KPoint& { return c->vertex(local[k])->point(); };
        for (int a = 0; a < 4; ++a)
        {
          for (int b = a + 1; b < 4; ++b)
          {
            const Id e = Find(edges, { { v[a], v[b] } });
            if (e < 0)
            {
              continue;
            }
            seen[static_cast<std::size_t>(e)].store(1, std::memory_order_relaxed);
            for (int w = 0; w < 4; ++w)
            {
              if (w != a && w != b && ObtuseCorner(point(a), point(b), point(w)) == 2)
              {
                ok = false; // a facet obtuse against it: not Gabriel
              }
            }
          }
        }
        for (int skip = 0; skip < 4; ++skip)
        {
          const int i = local[skip]; // the facet opposite c->vertex(i)
          const CellHandle other = c->neighbor(i);
          const Id otherId = tri.CellId(other);
          if (otherId >= 0 && otherId < id)
          {
            continue; // handled by the other side
          }
          std::array<std::int32_t, 3> f;
          std::array<int, 3> at;
          for (int k = 0, j = 0; k < 4; ++k)
          {
            if (k != skip)
            {
              f[j] = v[k];
              at[j++] = k;
            }
          }
          const Id k = Find(facets, f);
          if (k < 0)
          {
            continue;
          }
          seen[facetSeen + static_cast<std::size_t>(k)].store(1, std::memory_order_relaxed);
          bool critical = ObtuseCorner(point(at[0]), point(at[1]), point(at[2])) < 0;
          const VertexHandle apex[2] = { c->vertex(i), other->vertex(other->index(c)) };
          for (const VertexHandle x : apex)
          {
            if (!critical || dt.is_infinite(x))
            {
              continue;
            }
            const CGAL::Bounded_side side =
              FastSideOfDiametralSphere(point(at[0]), point(at[1]), point(at[2]), x->point());
            if (side == CGAL::ON_BOUNDARY)
            {
              throw Degenerate("apex on a diametral sphere");
            }
            critical = side == CGAL::ON_UNBOUNDED_SIDE;
          }
          if (!critical)
          {
            ok = false;
          }
          cs.Facets[static_cast<std::size_t>(k)] = { f, static_cast<std::int32_t>(id), i };
        }
        const Id k = Find(cells, v);
        if (k >= 0)
        {
          seen[cellSeen + static_cast<std::size_t>(k)].store(1, std::memory_order_relaxed);
          if (!IsSelfCentred(c))
          {
            ok = false;
          }
          cs.Cells[static_cast<std::size_t>(k)] = { v, static_cast<std::int32_t>(id) };
        }
      }
    }
    catch (const Degenerate&)
    {
      ok = false; // a tie the build's perturbation had removed: other points
    }
  });
  if (!ok || std::any_of(seen.begin(), seen.end(),
               [](const std::atomic<std::uint8_t>& x) { return x.load(std::memory_order_relaxed) == 0; }))
  {
    throw InputError(mismatch);
  }
  progress(0.32, "critical points");
  return cs;
}

} // namespace flowrecon
