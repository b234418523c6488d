// The side-of-diametral-sphere predicate, which the flow complex calls most,
// with a static floating-point filter in front of CGAL's exact one: evaluated in
// double with a bound on the rounding error, and delegated to CGAL (interval +
// exact) only when the double sign is not certain. Same answers as
// Side_of_bounded_sphere_3, for which CGAL has no static filter (its angle
// predicate has one, so CGAL::angle is used directly).
#ifndef flowrecon_FastPredicates_h
#define flowrecon_FastPredicates_h

#include "Delaunay.h"

#include <cmath>
#include <limits>

namespace flowrecon
{

/// Position of t relative to the diametral sphere of triangle pqr (the smallest
/// sphere through p, q, r), as Kernel::Side_of_bounded_sphere_3(p, q, r, t).
inline CGAL::Bounded_side FastSideOfDiametralSphere(
  const KPoint& p, const KPoint& q, const KPoint& r, const KPoint& t)
{
  // With u = q-p, v = r-p, w = t-p, n = u x v and c - p = (|u|^2 v - |v|^2 u) x n / (2|n|^2),
  // |t-c|^2 - |c-p|^2 has the sign of G = |w|^2 |n|^2 - w.((|u|^2 v - |v|^2 u) x n).
  const double ux = q.x() - p.x(), uy = q.y() - p.y(), uz = q.z() - p.z();
  const double vx = r.x() - p.x(), vy = r.y() - p.y(), vz = r.z() - p.z();
  const double wx = t.x() - p.x(), wy = t.y() - p.y(), wz = t.z() - p.z();
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  const double uu = ux * ux + uy * uy + uz * uz, vv = vx * vx + vy * vy + vz * vz;
  const double ww = wx * wx + wy * wy + wz * wz, nn = nx * nx + ny * ny + nz * nz;
  const double ax = uu * vx - vv * ux, ay = uu * vy - vv * uy, az = uu * vz - vv * uz;
  const double bx = ay * nz - az * ny, by = az * nx - ax * nz, bz = ax * ny - ay * nx;
  const double g = ww * nn - (wx * bx + wy * by + wz * bz);
  // The same expression on absolute values bounds every intermediate magnitude.
  const double Nx = std::fabs(uy * vz) + std::fabs(uz * vy), Ny = std::fabs(uz * vx) + std::fabs(ux * vz),
               Nz = std::fabs(ux * vy) + std::fabs(uy * vx);
  const double Ax = uu * std::fabs(vx) + vv * std::fabs(ux), Ay = uu * std::fabs(vy) + vv * std::fabs(uy),
               Az = uu * std::fabs(vz) + vv * std::fabs(uz);
  const double Bx = Ay * Nz + Az * Ny, By = Az * Nx + Ax * Nz, Bz = Ax * Ny + Ay * Nx;
  const double bound = ww * (Nx * Nx + Ny * Ny + Nz * Nz) +
    (std::fabs(wx) * Bx + std::fabs(wy) * By + std::fabs(wz) * Bz);
  // About 20 roundings on a path, each relative eps: 64 eps is a safe bound.
  if (bound > 1e-250 && bound < 1e250 &&
    std::fabs(g) > 64 * std::numeric_limits<double>::epsilon() * bound)
  {
    return g < 0 ? CGAL::ON_BOUNDED_SIDE : CGAL::ON_UNBOUNDED_SIDE;
  }
  return Kernel().side_of_bounded_sphere_3_object()(p, q, r, t);
}

} // namespace flowrecon

#endif
