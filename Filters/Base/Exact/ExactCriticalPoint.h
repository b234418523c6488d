// The critical point and critical value of a critical simplex, evaluated exactly
// on given coordinates. A perturbed run (docs/algorithm.md §2.3) takes its
// critical simplices from the perturbed points and their values from the points
// before the perturbation, through this.
#ifndef flowrecon_ExactCriticalPoint_h
#define flowrecon_ExactCriticalPoint_h

#include "FlowComplex.h"

namespace flowrecon
{

struct ExactCriticalPoint
{
  Point3 Location{ { 0, 0, 0 } }; ///< each coordinate the truncation of the exact one
  /// The truncation of the exact squared radius (as GMP's mpq_get_d): equal
  /// exact values give equal doubles, so ties stay ties.
  double SquaredRadius = 0;
  bool Flat = false; ///< four coplanar points on one circle: that circle
};

/// The centre and squared radius of the smallest sphere through the n = 2, 3 or 4
/// points `p`, its centre in their affine hull: the midpoint of an edge, the
/// circumcentre of a triangle in its plane, of a tetrahedron. Four coplanar
/// points on one circle give that circle (Flat): it is where the circumcentre of
/// a perturbed copy goes when the perturbation shrinks to 0 while the copy
/// contains it (a self-centred cell squashed flat). False when there is no such
/// limit: three collinear points, four coplanar points on no common circle.
bool ExactCriticalPointOf(const Point3* p, int n, ExactCriticalPoint& out);

} // namespace flowrecon

#endif
