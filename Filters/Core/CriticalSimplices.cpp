#include "CriticalSimplices.h"

#include "Driver.h"
#include "FastPredicates.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

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
} // namespace

CriticalSimplices FindCriticalSimplices(const Triangulation& tri, const Progress& progress)
{
  const Delaunay& dt = tri.Dt();
  CriticalSimplices cs;
  const double total = static_cast<double>(dt.number_of_finite_facets() + 1);
  std::size_t done = 0;
  auto tick = [&]() {
    if ((++done & 0xFFFF) == 0)
    {
      progress(0.2 + 0.12 * done / total, "critical points");
    }
  };
  // All edges as sorted adjacency lists (u < v), collected from the cells:
  // CGAL's edge iterator circulates around every edge, this is much cheaper.
  const Id m = tri.NumberOfVertices();
  cs.Offsets.assign(static_cast<std::size_t>(m + 1), 0);
  static const int pairs[6][2] = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 } };
  for (int pass = 0; pass < 2; ++pass)
  {
    std::vector<Id> fill;
    if (pass == 1)
    {
      for (Id u = 0; u < m; ++u)
      {
        cs.Offsets[u + 1] += cs.Offsets[u];
      }
      cs.Neighbours.resize(static_cast<std::size_t>(cs.Offsets[m]));
      fill.assign(cs.Offsets.begin(), cs.Offsets.end() - 1);
    }
    for (Id id = 0; id < tri.NumberOfCells(); ++id)
    {
      const CellHandle c = tri.Cell(id);
      for (const auto& p : pairs)
      {
        Id u = c->vertex(p[0])->info(), v = c->vertex(p[1])->info();
        if (u > v)
        {
          std::swap(u, v);
        }
        if (pass == 0)
        {
          ++cs.Offsets[u + 1];
        }
        else
        {
          cs.Neighbours[fill[u]++] = static_cast<std::int32_t>(v);
        }
      }
    }
  }
  {
    // Sort and deduplicate each list in place, compacting the arrays.
    Id write = 0;
    for (Id u = 0; u < m; ++u)
    {
      const auto first = cs.Neighbours.begin() + cs.Offsets[u];
      const auto last = cs.Neighbours.begin() + cs.Offsets[u + 1];
      std::sort(first, last);
      const auto end = std::unique(first, last);
      cs.Offsets[u] = write;
      write = static_cast<Id>(std::copy(first, end, cs.Neighbours.begin() + write) - cs.Neighbours.begin());
    }
    cs.Offsets[m] = write;
    cs.Neighbours.resize(static_cast<std::size_t>(write));
    cs.Neighbours.shrink_to_fit();
  }
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
  std::vector<char> gabrielEdge(cs.Neighbours.size(), 1);

  // One pass over the facets. A facet obtuse at t puts t strictly inside the
  // diametral ball of the opposite edge, so that edge is not Gabriel; every link
  // vertex of an edge is the third vertex of one of its facets, so the edges
  // never marked are exactly the Gabriel edges (CGAL's is_Gabriel, in one pass).
  std::vector<std::pair<std::array<Id, 3>, std::pair<CellHandle, int>>> facets;
  facets.reserve(dt.number_of_finite_facets() * 2 / 5); // ~36% are critical: no doubling
  for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f)
  {
    tick();
    const CellHandle c = f->first;
    const int i = f->second;
    const VertexHandle v[3] = { c->vertex((i + 1) % 4), c->vertex((i + 2) % 4),
      c->vertex((i + 3) % 4) };
    int obtuse = -1;
    try
    {
      obtuse = ObtuseCorner(v[0]->point(), v[1]->point(), v[2]->point());
    }
    catch (const flowrecon::Degenerate&)
    {
      ++cs.RightAngles;
      continue;
    }
    if (obtuse >= 0)
    {
      gabrielEdge[position(v[(obtuse + 1) % 3]->info(), v[(obtuse + 2) % 3]->info())] = 0;
      continue; // an obtuse facet is not self-centred
    }
    // Acute: critical iff both apices lie strictly outside its diametral ball.
    bool gabriel = true;
    const CellHandle n = c->neighbor(i);
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
        ++cs.ApexOnSphere;
      }
      gabriel = gabriel && side == CGAL::ON_UNBOUNDED_SIDE;
    }
    if (gabriel)
    {
      facets.push_back({ Sorted<3>({ { v[0]->info(), v[1]->info(), v[2]->info() } }), { c, i } });
    }
  }
  if (cs.Degenerate())
  {
    return cs; // the caller perturbs and starts again
  }
  std::sort(facets.begin(), facets.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& f : facets)
  {
    cs.Facets.push_back(f.first);
    cs.FacetCells.push_back(f.second);
  }

  cs.GabrielIndex.assign(cs.Neighbours.size(), -1);
  for (Id u = 0; u < m; ++u)
  {
    for (Id k = cs.Offsets[u]; k < cs.Offsets[u + 1]; ++k)
    {
      if (gabrielEdge[k])
      {
        cs.GabrielIndex[k] = static_cast<std::int32_t>(cs.Edges.size());
        cs.Edges.push_back({ { u, cs.Neighbours[k] } });
      }
    }
  }

  // Index 3: self-centred cells (Lemma B.2).
  // The predicates run in parallel (read-only triangulation); Degenerate
  // propagates out of parallel_for to the caller.
  progress(0.33, "critical points");
  std::vector<char> selfCentred(static_cast<std::size_t>(tri.NumberOfCells()), 0);
  tbb::parallel_for(tbb::blocked_range<Id>(0, tri.NumberOfCells()), [&](const tbb::blocked_range<Id>& r) {
    for (Id id = r.begin(); id != r.end(); ++id)
    {
      selfCentred[id] = IsSelfCentred(tri.Cell(id)) ? 1 : 0;
    }
  });
  std::vector<std::pair<std::array<Id, 4>, Id>> cells;
  for (Id id = 0; id < tri.NumberOfCells(); ++id)
  {
    const CellHandle c = tri.Cell(id);
    if (selfCentred[id])
    {
      cells.emplace_back(Sorted<4>({ { c->vertex(0)->info(), c->vertex(1)->info(),
                           c->vertex(2)->info(), c->vertex(3)->info() } }),
        id);
    }
  }
  std::sort(cells.begin(), cells.end());
  for (const auto& cell : cells)
  {
    cs.Cells.push_back(cell.first);
    cs.CellOfMaximum.push_back(cell.second);
  }
  return cs;
}

} // namespace flowrecon
