#include "CriticalSimplices.h"

#include "Driver.h"

#include <algorithm>

namespace flowrecon
{

Id CriticalSimplices::FindEdge(Id u, Id v) const
{
  const std::array<Id, 2> key{ { std::min(u, v), std::max(u, v) } };
  const auto it = std::lower_bound(this->Edges.begin(), this->Edges.end(), key);
  return (it != this->Edges.end() && *it == key) ? static_cast<Id>(it - this->Edges.begin()) : -1;
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
  const auto sbs3 = Kernel().side_of_bounded_sphere_3_object();
  CriticalSimplices cs;
  const double total = static_cast<double>(dt.number_of_finite_edges() +
    dt.number_of_finite_facets() + dt.number_of_finite_cells() + 1);
  std::size_t done = 0;
  auto tick = [&]() {
    if ((++done & 0xFFFF) == 0)
    {
      progress(0.2 + 0.15 * done / total, "critical points");
    }
  };

  // Index 1: Gabriel edges (CGAL's test: no link vertex strictly inside the
  // diametral ball; a vertex on it is a right angle, counted with the facets).
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e)
  {
    tick();
    if (dt.is_Gabriel(*e))
    {
      const Id u = e->first->vertex(e->second)->info();
      const Id v = e->first->vertex(e->third)->info();
      cs.Edges.push_back(Sorted<2>({ { u, v } }));
    }
  }
  std::sort(cs.Edges.begin(), cs.Edges.end());

  // Index 2: acute facets whose diametral ball has both apices strictly outside.
  for (auto f = dt.finite_facets_begin(); f != dt.finite_facets_end(); ++f)
  {
    tick();
    const CellHandle c = f->first;
    const int i = f->second;
    const KPoint& a = c->vertex((i + 1) % 4)->point();
    const KPoint& b = c->vertex((i + 2) % 4)->point();
    const KPoint& d = c->vertex((i + 3) % 4)->point();
    int obtuse = -1;
    try
    {
      obtuse = ObtuseCorner(a, b, d);
    }
    catch (const flowrecon::Degenerate&)
    {
      ++cs.RightAngles;
      continue;
    }
    bool gabriel = true;
    const CellHandle cells[2] = { c, c->neighbor(i) };
    for (const CellHandle cell : cells)
    {
      const VertexHandle apex = (cell == c) ? c->vertex(i) : cell->vertex(cell->index(c));
      if (dt.is_infinite(apex))
      {
        continue;
      }
      const CGAL::Bounded_side side = sbs3(a, b, d, apex->point());
      if (side == CGAL::ON_BOUNDARY)
      {
        ++cs.ApexOnSphere;
      }
      gabriel = gabriel && side == CGAL::ON_UNBOUNDED_SIDE;
    }
    if (obtuse < 0 && gabriel)
    {
      cs.Facets.push_back(Sorted<3>({ { c->vertex((i + 1) % 4)->info(),
        c->vertex((i + 2) % 4)->info(), c->vertex((i + 3) % 4)->info() } }));
    }
  }
  std::sort(cs.Facets.begin(), cs.Facets.end());
  if (cs.Degenerate())
  {
    return cs; // the cell classification below would only throw
  }

  // Index 3: self-centred cells.
  std::vector<std::pair<std::array<Id, 4>, Id>> cells;
  for (Id id = 0; id < tri.NumberOfCells(); ++id)
  {
    tick();
    const CellHandle c = tri.Cell(id);
    if (ClassifyCell(c).Type == CellDriver::Cell)
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
