// The statically filtered diametral-sphere predicate agrees with CGAL's exact one, on random
// configurations and on nearly and exactly degenerate ones (right angles,
// cocircular and cospherical points, grids), where the filter must defer.
#include "Check.h"

#include "FastPredicates.h"

#include <random>

using namespace flowrecon;

int main()
{
  std::mt19937_64 g(7);
  auto u = [&]() { return static_cast<double>(g() >> 11) * 0x1.0p-53; };
  const auto sbs = Kernel().side_of_bounded_sphere_3_object();
  long spheres = 0, sphereMismatch = 0;
  for (int trial = 0; trial < 200000; ++trial)
  {
    KPoint p[4];
    const int kind = trial % 4;
    for (int k = 0; k < 4; ++k)
    {
      if (kind == 0) // random
        p[k] = KPoint(u(), u(), u());
      else if (kind == 1) // small integer grid: many exact right angles and cospherical sets
        p[k] = KPoint(double(g() % 3), double(g() % 3), double(g() % 3));
      else if (kind == 2) // grid jittered by a few ulps: near-degenerate
        p[k] = KPoint(double(g() % 3) + 1e-15 * (u() - 0.5), double(g() % 3) + 1e-15 * (u() - 0.5),
          double(g() % 3) + 1e-15 * (u() - 0.5));
      else // far from the origin, tiny triangle
        p[k] = KPoint(1e6 + 1e-3 * u(), -1e6 + 1e-3 * u(), 3e5 + 1e-3 * u());
    }
    if (p[0] == p[1] || p[0] == p[2] || p[1] == p[2])
      continue;
    if (CGAL::collinear(p[0], p[1], p[2]))
      continue;
    ++spheres;
    sphereMismatch +=
      FastSideOfDiametralSphere(p[0], p[1], p[2], p[3]) != sbs(p[0], p[1], p[2], p[3]) ? 1 : 0;
  }
  std::cout << spheres << " diametral spheres compared\n";
  CHECK(spheres > 100000);
  CHECK(sphereMismatch == 0);
  return check::Finish("TestFastPredicates");
}
