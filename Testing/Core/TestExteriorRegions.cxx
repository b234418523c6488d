// ExteriorRegions against CGAL's alpha shapes: at alpha = r^2 the cells of
// circumradius > r are the EXTERIOR cells, and a Voronoi edge between two of
// them lies in {d > r} exactly when their facet is EXTERIOR too (a facet is in
// the alpha complex when it is Gabriel with R_f^2 <= alpha, or when a cell
// incident to it is). So the regions must be the components of the exterior
// cells joined across exterior facets, infinity being one exterior "cell":
// the same partition of the cells, computed by another library's code. And
// regions descended from a higher level must be those computed anew.
#include "Check.h"
#include "Clouds.h"
#include "ExteriorRegions.h"
#include "Triangulation.h"

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

using namespace flowrecon;

namespace
{

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
// Exact comparisons of alpha values, as the regions' predicates are exact.
using Vb = CGAL::Alpha_shape_vertex_base_3<K, CGAL::Triangulation_vertex_base_with_info_3<Id, K>,
  CGAL::Tag_true>;
using Cb = CGAL::Alpha_shape_cell_base_3<K, CGAL::Default, CGAL::Tag_true>;
using AlphaTds = CGAL::Triangulation_data_structure_3<Vb, Cb>;
using AlphaDt = CGAL::Delaunay_triangulation_3<K, AlphaTds>;
using AlphaShape = CGAL::Alpha_shape_3<AlphaDt, CGAL::Tag_true>;

struct Components
{
  std::vector<Id> Parent;
  explicit Components(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), Id(0));
  }
  Id Find(Id x)
  {
    while (this->Parent[x] != x)
    {
      x = this->Parent[x] = this->Parent[this->Parent[x]];
    }
    return x;
  }
  void Join(Id a, Id b) { this->Parent[this->Find(a)] = this->Find(b); }
};

std::array<Id, 4> Key(const AlphaDt::Cell_handle& c)
{
  std::array<Id, 4> k{ { c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(),
    c->vertex(3)->info() } };
  std::sort(k.begin(), k.end());
  return k;
}

/// The regions at `levelSq` must partition the cells as the alpha shape does.
/// Returns the number of regions.
int Compare(const std::string& name, const std::vector<Point3>& points, double levelSq)
{
  const Triangulation tri(points);
  const ExteriorRegions regions(tri, levelSq);

  std::vector<std::pair<K::Point_3, Id>> input;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    input.emplace_back(K::Point_3(points[i][0], points[i][1], points[i][2]), static_cast<Id>(i));
  }
  AlphaShape alpha(input.begin(), input.end(), levelSq, AlphaShape::GENERAL);
  // The oracle's cells by their vertices; infinity is element 0.
  std::map<std::array<Id, 4>, Id> element;
  std::vector<AlphaDt::Cell_handle> cells;
  for (auto c = alpha.finite_cells_begin(); c != alpha.finite_cells_end(); ++c)
  {
    element[Key(c)] = static_cast<Id>(cells.size()) + 1;
    cells.push_back(c);
  }
  Components oracle(cells.size() + 1);
  auto exterior = [&](const AlphaDt::Cell_handle& c) {
    return alpha.is_infinite(c) || alpha.classify(c) == AlphaShape::EXTERIOR;
  };
  for (const AlphaDt::Cell_handle& c : cells)
  {
    for (int i = 0; i < 4; ++i)
    {
      const AlphaDt::Cell_handle d = c->neighbor(i);
      if (exterior(c) && exterior(d) && alpha.classify(AlphaDt::Facet(c, i)) == AlphaShape::EXTERIOR)
      {
        oracle.Join(element[Key(c)], alpha.is_infinite(d) ? 0 : element[Key(d)]);
      }
    }
  }

  const std::string what = name + " at r^2 = " + std::to_string(levelSq);
  CHECK(static_cast<std::size_t>(tri.NumberOfCells()) == cells.size());
  // The same partition: a bijection between regions and oracle components.
  std::map<Id, Id> toOracle, fromOracle;
  auto match = [&](Id region, Id component) {
    const auto a = toOracle.emplace(region, component).first->second;
    const auto b = fromOracle.emplace(component, region).first->second;
    return a == component && b == region;
  };
  int mismatches = 0;
  for (Id cell = 0; cell < tri.NumberOfCells(); ++cell)
  {
    const CellHandle h = tri.Cell(cell);
    std::array<Id, 4> k{ { h->vertex(0)->info(), h->vertex(1)->info(), h->vertex(2)->info(),
      h->vertex(3)->info() } };
    std::sort(k.begin(), k.end());
    const auto it = element.find(k);
    if (it == element.end())
    {
      ++mismatches;
      continue;
    }
    const bool above = regions.RegionOf(cell) >= 0;
    if (above != exterior(cells[it->second - 1]) ||
      (above && !match(regions.RegionOf(cell), oracle.Find(it->second))))
    {
      ++mismatches;
    }
  }
  // Infinity, and the count (every oracle component holds a cell or infinity).
  CHECK(match(regions.InfiniteRegion(), oracle.Find(0)));
  CHECK(static_cast<std::int32_t>(toOracle.size()) == regions.Count());
  if (mismatches != 0)
  {
    std::cout << what << ": " << mismatches << " cells differ from the alpha shape\n";
    ++check::Failures();
  }
  std::cout << what << ": " << regions.Count() << " regions, " << regions.CellsAbove()
            << " cells above\n";
  return regions.Count();
}

/// Squared circumradii of the cells at the given quantiles.
std::vector<double> Levels(const std::vector<Point3>& points, std::initializer_list<double> q)
{
  const Triangulation tri(points);
  std::vector<double> r2;
  for (Id c = 0; c < tri.NumberOfCells(); ++c)
  {
    // Exact constructions: flat cells of the icosahedron's faces have no
    // circumcentre in doubles.
    const CellHandle h = tri.Cell(c);
    std::array<Exact::Point_3, 4> p;
    for (int k = 0; k < 4; ++k)
    {
      const KPoint& q = h->vertex(k)->point();
      p[k] = Exact::Point_3(q.x(), q.y(), q.z());
    }
    r2.push_back(CGAL::to_double(CGAL::squared_radius(p[0], p[1], p[2], p[3])));
  }
  std::sort(r2.begin(), r2.end());
  std::vector<double> out;
  for (const double f : q)
  {
    out.push_back(r2[static_cast<std::size_t>(f * static_cast<double>(r2.size() - 1))]);
  }
  return out;
}

/// Regions descended level by level (highest first) must be those computed
/// anew at each level: the same region of every cell (their ids are given in
/// one canonical order), count, infinity's region and cells above.
void CompareDescent(const std::string& name, const std::vector<Point3>& points, std::vector<double> levels)
{
  std::sort(levels.rbegin(), levels.rend());
  const Triangulation tri(points);
  ExteriorRegions descended(tri, levels.front(), true);
  for (std::size_t l = 1; l < levels.size(); ++l)
  {
    descended.Descend(levels[l]);
    const ExteriorRegions fresh(tri, levels[l]);
    Id differ = 0;
    for (Id cell = 0; cell < tri.NumberOfCells(); ++cell)
    {
      differ += descended.RegionOf(cell) != fresh.RegionOf(cell) ? 1 : 0;
    }
    const std::string what = name + " descended from r^2 = " + std::to_string(levels[l - 1]) +
      " to " + std::to_string(levels[l]);
    if (differ != 0)
    {
      std::cout << what << ": " << differ << " cells in other regions than anew\n";
      ++check::Failures();
    }
    CHECK(descended.Count() == fresh.Count());
    CHECK(descended.InfiniteRegion() == fresh.InfiniteRegion());
    CHECK(descended.CellsAbove() == fresh.CellsAbove());
    CHECK(descended.Level() == levels[l]);
    std::cout << what << ": " << descended.Count() << " regions, as anew\n";
  }
  // Only down, and only when kept for it.
  bool refused = false;
  try
  {
    descended.Descend(levels.front());
  }
  catch (const std::logic_error&)
  {
    refused = true;
  }
  CHECK(refused || levels.front() == levels.back());
  ExteriorRegions once(tri, levels.back());
  refused = false;
  try
  {
    once.Descend(levels.back());
  }
  catch (const std::logic_error&)
  {
    refused = true;
  }
  CHECK(refused);
}

} // namespace

int main()
{
  const std::vector<std::pair<std::string, std::vector<Point3>>> clouds = {
    { "sphere", clouds::Sphere(3000, 3) },
    { "torus", clouds::Torus(3000, 5) },
    { "cube", clouds::Cube(1500, 7) },
    { "icosahedron", clouds::Icosahedron(2000, 11) },
  };
  int most = 0;
  for (const auto& [name, points] : clouds)
  {
    for (const double level : Levels(points, { 0.05, 0.3, 0.6, 0.9 }))
    {
      most = std::max(most, Compare(name, points, level));
    }
  }
  // A unit grid: cospherical cells, Gabriel facets on the level's boundary.
  std::vector<Point3> grid;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 6; ++k)
        grid.push_back({ { double(i), double(j), double(k) } });
  for (const double level : { 0.5, 0.6, 0.74, 0.75 })
  {
    Compare("grid", grid, level);
  }
  for (const auto& [name, points] : clouds)
  {
    CompareDescent(name, points, Levels(points, { 0.02, 0.05, 0.1, 0.3, 0.6, 0.9 }));
  }
  CompareDescent("grid", grid, { 0.5, 0.6, 0.74, 0.75, 0.76 });
  // The levels are not all trivial: some split space in many regions.
  CHECK(most > 10);
  return check::Finish("TestExteriorRegions");
}
