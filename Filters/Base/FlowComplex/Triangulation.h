// The Delaunay triangulation of the (deduplicated) samples, with the queries the
// flow-complex walks need: vertex handles by sample index, dense cell ids, the
// link of an edge and the cells of a facet.
#ifndef flowrecon_Triangulation_h
#define flowrecon_Triangulation_h

#include "Delaunay.h"
#include "Progress.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace flowrecon
{

class Triangulation
{
public:
  /// Builds the triangulation of `points` (inserted with spatial sorting); vertex
  /// info is the index into `points`. Points must be pairwise distinct, and must
  /// outlive the triangulation (they are referenced, not copied).
  /// `progress` (fractions of this phase) is reported during the insertion
  /// and may abort (it throws Aborted).
  explicit Triangulation(const std::vector<Point3>& points, const Progress& progress = Progress());

  const Delaunay& Dt() const { return this->DT; }
  /// Distinct for every triangulation built in this process: keys caches that
  /// must not outlive it (a later one may reuse the address and the ids).
  std::uint64_t Serial() const { return this->SerialNumber; }
  int Dimension() const { return this->DT.dimension(); }
  const Point3& Coord(Id k) const { return this->Coords[k]; }
  const KPoint& KCoord(Id k) const { return this->Vertices[k]->point(); }
  VertexHandle Vertex(Id k) const { return this->Vertices[k]; }
  Id NumberOfVertices() const { return static_cast<Id>(this->Vertices.size()); }

  /// Dense ids 0..NumberOfCells()-1 of the finite cells; -1 for infinite ones.
  Id CellId(CellHandle c) const { return c->info(); }
  CellHandle Cell(Id id) const { return this->Cells[id]; }
  Id NumberOfCells() const { return static_cast<Id>(this->Cells.size()); }

  /// The vertex ids of a finite cell in increasing order. Constructions from a
  /// cell (its circumcentre) use this order: the order of vertices inside a cell
  /// depends on how the concurrent triangulation was built, and rounding would
  /// follow it.
  std::array<Id, 4> SortedVertices(CellHandle c) const
  {
    std::array<Id, 4> v{ { c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
      c->vertex(3)->info() } };
    std::sort(v.begin(), v.end());
    return v;
  }

  /// The index in `cell` of its vertex not in the triangle `t` (vertex ids),
  /// which the cell must hold.
  int OppositeOf(CellHandle cell, const std::array<Id, 3>& t) const
  {
    int sum = 0;
    for (const Id v : t)
    {
      int i = 0;
      if (!cell->has_vertex(this->Vertices[v], i))
      {
        throw std::logic_error("triangulation: a cell misses a triangle said to be its facet");
      }
      sum += i;
    }
    return 6 - sum;
  }

  /// Appends to `out` the finite vertices s such that (u, v, s) is a Delaunay facet,
  /// and to `cells` (if given) a cell containing (u, v, s) for each. `hint`, if
  /// not null, is a cell known to contain uv (saves the search for the edge).
  /// Returns false if uv is not a Delaunay edge.
  bool Link(Id u, Id v, std::vector<Id>& out, std::vector<CellHandle>* cells = nullptr,
    CellHandle hint = CellHandle()) const;

private:
  /// One thread at a time (below 4 threads), or with CGAL's lock grid.
  void InsertInOrder(const std::vector<Point3>& points, const Progress& progress);
  void InsertInParallel(const std::vector<Point3>& points, const Progress& progress);
  /// Cell ids in the order of the cells' sorted vertex ids.
  void NumberCellsByVertices();

  const std::vector<Point3>& Coords;
  std::uint64_t SerialNumber;
  Delaunay DT;
  std::vector<VertexHandle> Vertices;
  std::vector<CellHandle> Cells;
};

} // namespace flowrecon

#endif
