#include "Triangulation.h"

#include "Progress.h"

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>

namespace flowrecon
{

namespace
{
std::uint64_t NextSerial()
{
  static std::atomic<std::uint64_t> serial{ 0 };
  return ++serial;
}
} // namespace

Triangulation::Triangulation(const std::vector<Point3>& points, const Progress& progress)
  : Coords(points)
  , SerialNumber(NextSerial())
{
  const std::size_t threads = std::min<std::size_t>(
    tbb::this_task_arena::max_concurrency(),
    tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism));
  // Without a lock grid CGAL inserts sequentially, which is faster below 4
  // threads: measured on 2 cores (10^5 points), the locks cost what the second
  // core gains on a uniform cube (0.65 s against 0.68 s) and make a sphere's
  // surface sample 2.4 times slower (3.18 s against 1.35 s: the interior cells
  // of a surface sample span the whole shape, so concurrent insertions keep
  // meeting on their locks).
  if (threads >= 4)
  {
    this->InsertInParallel(points, progress);
  }
  else
  {
    this->InsertInOrder(points, progress);
  }
  // Each point must be a vertex of its own (the Vertices table below): two
  // points that coincide (the callers pass distinct ones) end here in one line.
  if (this->DT.number_of_vertices() != points.size())
  {
    throw InputError("Delaunay triangulation: " + std::to_string(points.size()) +
      " points gave " + std::to_string(this->DT.number_of_vertices()) + " vertices (coinciding points)");
  }
  this->Vertices.assign(points.size(), VertexHandle());
  for (auto v = this->DT.finite_vertices_begin(); v != this->DT.finite_vertices_end(); ++v)
  {
    this->Vertices[v->info()] = v;
  }
  // Per-cell tables, the lists of critical simplices and the cells' own ids
  // are 32-bit.
  if (this->DT.number_of_cells() >= static_cast<std::size_t>(INT32_MAX))
  {
    throw InputError("the Delaunay triangulation of this many points exceeds 2^31 cells");
  }
  // One pass: dense ids for finite cells, -1 for the infinite ones (CGAL's
  // number_of_finite_cells() is itself a pass over the cells).
  this->Cells.reserve(this->DT.number_of_cells());
  for (auto c = this->DT.all_cells_begin(); c != this->DT.all_cells_end(); ++c)
  {
    if (this->DT.is_infinite(c))
    {
      c->info() = -1;
    }
    else
    {
      c->info() = static_cast<std::int32_t>(this->Cells.size());
      this->Cells.push_back(c);
    }
  }
  if (threads >= 4)
  {
    this->NumberCellsByVertices();
  }
}

void Triangulation::InsertInOrder(const std::vector<Point3>& points, const Progress& progress)
{
  // What CGAL's range insertion does sequentially (one spatial sort of the
  // whole cloud, its randomized rounds included, then each point from the
  // last vertex), point by point so that the phase reports progress and can
  // be aborted. Range insertions of consecutive runs of the points cost 1.3-1.5
  // times that on 10^6 bunny and cube points: most of each run's points fall
  // outside the triangulation of the runs before, and inserting outside the
  // hull is slow.
  std::vector<KPoint> kpoints;
  kpoints.reserve(points.size());
  for (const Point3& p : points)
  {
    kpoints.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  using Map = CGAL::Pointer_property_map<KPoint>::const_type;
  const Map map = CGAL::make_property_map(static_cast<const std::vector<KPoint>&>(kpoints));
  CGAL::spatial_sort<CGAL::Parallel_tag>(
    order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<Kernel, Map>(map));
  VertexHandle hint;
  const std::size_t step = std::max<std::size_t>(1, order.size() / 64);
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    if (k % step == 0)
    {
      progress(static_cast<double>(k) / static_cast<double>(order.size() + 1), "Delaunay triangulation");
    }
    // The points are distinct (PrepareInput): each one is a new vertex.
    hint = this->DT.insert(kpoints[order[k]], hint);
    hint->info() = static_cast<Id>(order[k]);
  }
}

void Triangulation::InsertInParallel(const std::vector<Point3>& points, const Progress& progress)
{
  // Consecutive runs of the points, one range insertion each (spatially
  // sorted, then inserted in parallel), so that the phase reports progress and
  // can be aborted; the builder hands the points in a spatial order, so a run
  // is a region. The lock grid serves only while inserting.
  const std::size_t rounds = points.size() >= (std::size_t(1) << 16) ? 8 : 1;
  std::vector<std::pair<KPoint, Id>> items;
  items.reserve(points.size());
  CGAL::Bbox_3 box;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    items.emplace_back(KPoint(points[i][0], points[i][1], points[i][2]), static_cast<Id>(i));
    box += items.back().first.bbox();
  }
  Delaunay::Lock_data_structure locks(box, 50);
  this->DT.set_lock_data_structure(&locks);
  std::size_t begin = 0;
  for (std::size_t r = 1; r <= rounds; ++r)
  {
    progress(static_cast<double>(begin) / static_cast<double>(items.size() + 1),
      "Delaunay triangulation");
    const std::size_t end = points.size() * r / rounds;
    this->DT.insert(items.begin() + static_cast<std::ptrdiff_t>(begin),
      items.begin() + static_cast<std::ptrdiff_t>(end));
    begin = end;
  }
  this->DT.set_lock_data_structure(nullptr);
}

void Triangulation::NumberCellsByVertices()
{
  // A parallel insertion leaves its cells in an order that depends on the
  // schedule; numbered by their sorted vertex ids instead, they come out the
  // same from run to run (the compact output lists a solid's tetrahedra by
  // cell id).
  struct Keyed
  {
    std::array<std::int32_t, 4> Key;
    CellHandle Cell;
  };
  std::vector<Keyed> keyed(this->Cells.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, keyed.size()),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        const CellHandle c = this->Cells[k];
        std::array<std::int32_t, 4> key{};
        for (int i = 0; i < 4; ++i)
        {
          key[i] = static_cast<std::int32_t>(c->vertex(i)->info());
        }
        std::sort(key.begin(), key.end());
        keyed[k] = Keyed{ key, c };
      }
    });
  tbb::parallel_sort(keyed.begin(), keyed.end(),
    [](const Keyed& a, const Keyed& b) { return a.Key < b.Key; });
  for (std::size_t k = 0; k < keyed.size(); ++k)
  {
    this->Cells[k] = keyed[k].Cell;
    keyed[k].Cell->info() = static_cast<std::int32_t>(k);
  }
}

bool Triangulation::Link(Id u, Id v, std::vector<Id>& out, std::vector<CellHandle>* cells,
  CellHandle hint) const
{
  const VertexHandle vu = this->Vertices[u], vv = this->Vertices[v];
  CellHandle cell;
  int i = 0, j = 0;
  if (hint != CellHandle() && hint->has_vertex(vu, i) && hint->has_vertex(vv, j))
  {
    cell = hint;
  }
  else if (!this->DT.is_edge(vu, vv, cell, i, j))
  {
    return false;
  }
  // Consecutive cells around the edge share one link vertex: collect each once.
  // Around the edge the link vertices form a cycle w0 w1 ... and cell i holds
  // w_i and w_i+1, so a repeat is one of the last two vertices collected (the
  // cell's new one may come first) or of the first two; no search of the list.
  const std::size_t first = out.size();
  auto start = this->DT.incident_cells(Delaunay::Edge(cell, i, j));
  auto cc = start;
  do
  {
    for (int k = 0; k < 4; ++k)
    {
      const VertexHandle w = cc->vertex(k);
      if (w == vu || w == vv || this->DT.is_infinite(w))
      {
        continue;
      }
      const Id id = w->info();
      const std::size_t count = out.size() - first;
      const bool seen = count > 0 &&
        (out.back() == id || out[first] == id ||
          (count > 1 && (out[out.size() - 2] == id || out[first + 1] == id)));
      if (!seen)
      {
        out.push_back(id);
        if (cells)
        {
          cells->push_back(cc);
        }
      }
    }
  } while (++cc != start);
  return true;
}

} // namespace flowrecon
