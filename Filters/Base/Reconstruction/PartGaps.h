// How far apart the parts of a reconstruction lie. A surface sampled far more
// finely along some lines than across them (scan lines, the long rows of a
// mesh) is read at its finest spacing: each line closes as a curve of its own
// long before the lines join, and the topology profile is stable on the
// curves (a sphere scanned along 52 parallels gives 52 52 0 over every t_r
// looked at). Separate parts that each have another within a few sample
// spacings are what such a sampling gives; parts of separate objects lie
// farther apart, or are warned already (the gaps of an i.i.d. curve). Rows
// sampled finer still along them are farther apart in spacings, but not
// against their own size: closed curves each a small fraction of their extent
// from the next (the rings of a cylinder's mesh) are read the same way.
#ifndef flowrecon_PartGaps_h
#define flowrecon_PartGaps_h

#include "CompactReconstruction.h"
#include "FlowComplex.h"

#include <vector>

namespace flowrecon
{

struct PartGaps
{
  Id Parts = 0; ///< connected components of the cells
  /// The largest, over the parts, of the distance to the nearest other part,
  /// halved (a node value); +inf when a part has no Gabriel edge to another.
  double Widest = 0;
  Point3 Where{ { 0, 0, 0 } }; ///< the midpoint of that part's edge to its nearest
  /// The largest, over the parts, of the distance to the nearest other part
  /// over the extent (bounding-box diagonal of the samples) of the larger of
  /// the two; +inf when a part has no Gabriel edge to another.
  double WidestSpan = 0;
  double SpanGap = 0;                 ///< that gap, halved (a node value)
  Point3 SpanWhere{ { 0, 0, 0 } }; ///< the midpoint of that gap
  /// Whether the cells are curves: edges and vertices, no triangle or tetrahedron.
  bool Curves = true;
};

/// The parts of `cells` (a reconstruction on the samples: its vertices,
/// edges, triangles and tetrahedra) and their gaps, from the Gabriel edges of
/// `nodes` (a flow complex's over `samples` input points). The closest pair
/// between one part and the others is a Gabriel edge (a sample inside its
/// diametral ball would be closer to one end), so the index-1 nodes give each
/// part's nearest other part without a search; the index-0 nodes give the
/// samples' positions for the extents. Ids outside 0..samples-1 are passed
/// over.
PartGaps FindPartGaps(const std::vector<Node>& nodes, Id samples, const CompactComplex& cells);

} // namespace flowrecon

#endif
