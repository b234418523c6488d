// Clouds shared by the C++ tests and the fuzzers: uniform in the unit cube, on the
// unit sphere, on a torus (R = 1, r = 0.35) and on an icosahedron's faces, from a
// seed; integer grids (jittered or exact), cospherical integer points, duplicates.
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

/// I.i.d. area-uniform points on the faces of a regular icosahedron: flat
/// triangles in general position, as in scans sampled from meshes, where many
/// Voronoi vertices are ill-conditioned.
inline std::vector<Point3> Icosahedron(int n, std::uint64_t seed)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double v[12][3] = { { -1, t, 0 }, { 1, t, 0 }, { -1, -t, 0 }, { 1, -t, 0 }, { 0, -1, t },
    { 0, 1, t }, { 0, -1, -t }, { 0, 1, -t }, { t, 0, -1 }, { t, 0, 1 }, { -t, 0, -1 }, { -t, 0, 1 } };
  const int f[20][3] = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 }, { 0, 10, 11 },
    { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 }, { 3, 4, 2 },
    { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 }, { 8, 6, 7 },
    { 9, 8, 1 } };
  Rng r(seed);
  std::vector<Point3> c(n);
  for (Point3& p : c)
  {
    const int* face = f[std::min(19, static_cast<int>(20 * r.U()))];
    double a = r.U(), b = r.U();
    if (a + b > 1)
    {
      a = 1 - a;
      b = 1 - b;
    }
    for (int k = 0; k < 3; ++k)
    {
      p[k] = v[face[0]][k] + a * (v[face[1]][k] - v[face[0]][k]) + b * (v[face[2]][k] - v[face[0]][k]);
    }
  }
  return c;
}

/// The k x k x k integer grid, each coordinate moved by up to jitter / 2.
inline std::vector<Point3> Grid(int k, double jitter, std::uint64_t seed)
{
  Rng r(seed);
  std::vector<Point3> c;
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j)
      for (int l = 0; l < k; ++l)
        c.push_back({ { i + jitter * (r.U() - 0.5), j + jitter * (r.U() - 0.5),
          l + jitter * (r.U() - 0.5) } });
  return c;
}

/// Exactly cospherical points with integer coordinates on the sphere of radius 5.
inline std::vector<Point3> Cospherical()
{
  std::vector<Point3> c;
  for (int x = -5; x <= 5; ++x)
    for (int y = -5; y <= 5; ++y)
      for (int z = -5; z <= 5; ++z)
        if (x * x + y * y + z * z == 25)
          c.push_back({ { double(x), double(y), double(z) } });
  return c;
}

/// c with every third point given again at the end.
inline std::vector<Point3> WithDuplicates(std::vector<Point3> c)
{
  const std::size_t n = c.size();
  for (std::size_t i = 0; i < n; i += 3)
    c.push_back(c[i]);
  return c;
}

} // namespace clouds

#endif
