// The baseline of the whole-process benchmark (Benchmarks/whole_process.py):
// CGAL's default Delaunay triangulation (sequential, EPICK) of the points of an
// .xyz file, read with CGAL's own reader, as a process of its own so that its
// time and peak memory are measured like flowrecon's.
//   DelaunayBaseline CLOUD.xyz
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/read_points.h>

#include <iostream>
#include <vector>

int main(int argc, char* argv[])
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  if (argc != 2)
  {
    std::cerr << "usage: DelaunayBaseline CLOUD.xyz\n";
    return 2;
  }
  std::vector<Kernel::Point_3> points;
  if (!CGAL::IO::read_points(argv[1], std::back_inserter(points)) || points.empty())
  {
    std::cerr << "DelaunayBaseline: cannot read " << argv[1] << "\n";
    return 1;
  }
  const CGAL::Delaunay_triangulation_3<Kernel> dt(points.begin(), points.end());
  std::cout << dt.number_of_vertices() << " vertices, " << dt.number_of_finite_cells()
            << " cells\n";
  return 0;
}
