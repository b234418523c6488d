// The peer of the whole-process benchmark (Benchmarks/whole_process.py): CGAL's
// advancing front surface reconstruction at its defaults (radius ratio bound 5,
// beta 0.52; the free function builds its own sequential EPICK Delaunay
// triangulation) of the points of an .xyz file, read as DelaunayBaseline reads
// them, written as an OFF file (every point, 17 digits, and the facets), as a
// process of its own so that its time and peak memory are measured like
// flowrecon's: read, reconstruct, write.
//   AdvancingFrontBaseline CLOUD.xyz OUT.off
#include <CGAL/Advancing_front_surface_reconstruction.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/read_points.h>

#include <array>
#include <cstddef>
#include <iostream>
#include <vector>

int main(int argc, char* argv[])
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  if (argc != 3)
  {
    std::cerr << "usage: AdvancingFrontBaseline CLOUD.xyz OUT.off\n";
    return 2;
  }
  std::vector<Kernel::Point_3> points;
  if (!CGAL::IO::read_points(argv[1], std::back_inserter(points)) || points.empty())
  {
    std::cerr << "AdvancingFrontBaseline: cannot read " << argv[1] << "\n";
    return 1;
  }
  std::vector<std::array<std::size_t, 3>> facets;
  CGAL::advancing_front_surface_reconstruction(points.begin(), points.end(),
                                               std::back_inserter(facets));
  if (!CGAL::IO::write_OFF(argv[2], points, facets, CGAL::parameters::stream_precision(17)))
  {
    std::cerr << "AdvancingFrontBaseline: cannot write " << argv[2] << "\n";
    return 1;
  }
  std::cout << points.size() << " vertices, " << facets.size() << " facets\n";
  return 0;
}
