// Random clouds shared by the C++ tests: uniform in the unit cube, on the unit
// sphere and on a torus (R = 1, r = 0.35), from a seed.
#ifndef flowrecon_Clouds_h
#define flowrecon_Clouds_h

#include "FlowComplex.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace clouds
{
using flowrecon::Point3;

// Clouds come from a fixed generator and our own mapping to [0,1), so that they
// are the same on every platform (std distributions are not).
struct Rng
{
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed)
    : g(seed)
  {
  }
  double U() { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
  double N()
  {
    const double u = std::max(this->U(), 1e-300), v = this->U();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
  }
};

inline std::vector<Point3> Cube(int n, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c(n);
  for (Point3& p : c)
  {
    p = { { r.U(), r.U(), r.U() } };
  }
  return c;
}

inline std::vector<Point3> Sphere(int n, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c(n);
  for (Point3& p : c)
  {
    const double x = r.N(), y = r.N(), z = r.N(), l = std::sqrt(x * x + y * y + z * z);
    p = { { x / l, y / l, z / l } };
  }
  return c;
}

inline std::vector<Point3> Torus(int n, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c(n);
  for (Point3& p : c)
  {
    const double u = 2 * M_PI * r.U(), v = 2 * M_PI * r.U();
    p = { { (1 + 0.35 * std::cos(v)) * std::cos(u), (1 + 0.35 * std::cos(v)) * std::sin(u),
      0.35 * std::sin(v) } };
  }
  return c;
}

} // namespace clouds

#endif
