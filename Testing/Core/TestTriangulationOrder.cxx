// The triangulation's dense cell ids do not depend on the schedule: with 4
// threads or more CGAL inserts in parallel and leaves its cells in an order that
// varies from run to run, so the ids are then given in the order of the cells'
// sorted vertex ids. Built twice in a 4-thread arena (parallel insertion even on
// a 2-core machine), the ids must list the same cells, in increasing vertex
// order, and the cells must be those of the sequential build. Points that
// coincide (callers pass distinct ones) are refused with an InputError rather
// than leaving a point without its vertex.
#include "Check.h"
#include "Clouds.h"
#include "Triangulation.h"

#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <iostream>
#include <vector>

using namespace flowrecon;

namespace
{

std::vector<std::array<Id, 4>> CellsById(const std::vector<Point3>& points, int threads)
{
  std::vector<std::array<Id, 4>> cells;
  // Above the machine's cores too: the triangulation reads both limits.
  const tbb::global_control allow(tbb::global_control::max_allowed_parallelism, threads);
  tbb::task_arena arena(threads);
  arena.execute([&] {
    const Triangulation tri(points);
    for (Id c = 0; c < tri.NumberOfCells(); ++c)
    {
      CHECK(tri.Cell(c)->info() == c);
      cells.push_back(tri.SortedVertices(tri.Cell(c)));
    }
  });
  return cells;
}

void TestParallelOrder(const char* name, const std::vector<Point3>& points)
{
  std::cout << "-- " << name << "\n";
  const auto first = CellsById(points, 4);
  const auto second = CellsById(points, 4);
  CHECK(first.size() > 10000);
  CHECK(first == second);
  CHECK(std::is_sorted(first.begin(), first.end()));
  auto sequential = CellsById(points, 1);
  std::sort(sequential.begin(), sequential.end());
  CHECK(sequential == first);
}

void TestCoincidingPoints()
{
  std::cout << "-- coinciding points\n";
  std::vector<Point3> points = clouds::Cube(200, 43);
  points.push_back(points[17]);
  CHECK_THROWS(const Triangulation tri(points), InputError);
}

} // namespace

int main()
{
  TestParallelOrder("cube 20000", clouds::Cube(20000, 41));
  TestParallelOrder("sphere 8000", clouds::Sphere(8000, 42));
  TestCoincidingPoints();
  return check::Finish("TestTriangulationOrder");
}
