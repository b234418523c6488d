// CGAL types of the core: exact predicates on the input points (EPICK), a 3D
// Delaunay triangulation whose vertices carry the input id and whose cells carry
// a dense 32-bit index (for per-cell memo tables; 8 bytes a cell less than an
// Id, a tenth of CGAL's cell). The triangulation is CGAL's
// concurrent one: the Delaunay triangulation is unique (CGAL breaks cospherical
// ties by symbolic perturbation), so building it in parallel changes only the
// order of cells in memory; their dense ids are then given in the order of
// their vertices (Triangulation.h), so that nothing depends on the schedule.
#ifndef flowrecon_Delaunay_h
#define flowrecon_Delaunay_h

#include "FlowComplex.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

namespace flowrecon
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using KPoint = Kernel::Point_3;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<Id, Kernel>;
using CellBase = CGAL::Triangulation_cell_base_with_info_3<std::int32_t, Kernel,
  CGAL::Delaunay_triangulation_cell_base_3<Kernel>>;
#ifndef CGAL_LINKED_WITH_TBB
#error "FlowRecon's core needs CGAL_LINKED_WITH_TBB (link CGAL::TBB_support)"
#endif
using Tds = CGAL::Triangulation_data_structure_3<VertexBase, CellBase, CGAL::Parallel_tag>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds, CGAL::Default,
  CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking>>;
using VertexHandle = Delaunay::Vertex_handle;
using CellHandle = Delaunay::Cell_handle;

} // namespace flowrecon

#endif
