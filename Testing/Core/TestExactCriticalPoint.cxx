// The exact critical point of a simplex (the values of perturbed runs) against
// CGAL's constructions over GMP rationals (the oracle): random edges, triangles
// and tetrahedra, of random doubles (the exact path) and of small integers (mostly
// the interval filter), give the truncation of the exact centre and squared radius;
// copies moved by exact motions give the same doubles (ties stay ties); four
// cocircular coplanar points give their circle; collinear points and coplanar
// points on no common circle give nothing.
#include "Check.h"

#include "ExactCriticalPoint.h"

#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <random>

using namespace flowrecon;

namespace
{

using QK = CGAL::Simple_cartesian<CGAL::Gmpq>;

QK::Point_3 Q(const Point3& p)
{
  return QK::Point_3(p[0], p[1], p[2]);
}

/// The oracle's centre and squared radius, truncated as GMP's mpq_get_d.
bool SameAsOracle(const Point3* p, int n, const ExactCriticalPoint& e)
{
  QK::Point_3 c;
  if (n == 2)
  {
    c = CGAL::midpoint(Q(p[0]), Q(p[1]));
  }
  else if (n == 3)
  {
    c = CGAL::circumcenter(Q(p[0]), Q(p[1]), Q(p[2]));
  }
  else
  {
    c = CGAL::circumcenter(Q(p[0]), Q(p[1]), Q(p[2]), Q(p[3]));
  }
  const CGAL::Gmpq r2 = CGAL::squared_distance(c, Q(p[0]));
  return e.SquaredRadius == r2.to_double() && e.Location[0] == c.x().to_double() &&
    e.Location[1] == c.y().to_double() && e.Location[2] == c.z().to_double() && !e.Flat;
}

} // namespace

int main()
{
  ExactCriticalPoint e;
  {
    const Point3 edge[2] = { { { 0, 0, 0 } }, { { 1, 2, 2 } } };
    CHECK((ExactCriticalPointOf(edge, 2, e) && e.SquaredRadius == 2.25 && e.Location == Point3{ { 0.5, 1, 1 } }));
    const Point3 right[3] = { { { 0, 0, 0 } }, { { 2, 0, 0 } }, { { 0, 2, 0 } } };
    CHECK((ExactCriticalPointOf(right, 3, e) && e.SquaredRadius == 2 && e.Location == Point3{ { 1, 1, 0 } }));
    const Point3 regular[4] = { { { 0, 0, 0 } }, { { 1, 1, 0 } }, { { 1, 0, 1 } }, { { 0, 1, 1 } } };
    CHECK((ExactCriticalPointOf(regular, 4, e) && e.SquaredRadius == 0.75 &&
      e.Location == Point3{ { 0.5, 0.5, 0.5 } } && !e.Flat));
  }
  {
    // A grid's square as a flat cell, in a crossing order: its circle.
    const Point3 square[4] = { { { 0, 0, 3 } }, { { 1, 1, 3 } }, { { 1, 0, 3 } }, { { 0, 1, 3 } } };
    CHECK((ExactCriticalPointOf(square, 4, e) && e.Flat && e.SquaredRadius == 0.5 &&
      e.Location == Point3{ { 0.5, 0.5, 3 } }));
    // A tilted square of side 3 (sides (1, 2, 2) and (2, 1, -2)).
    const Point3 tilted[4] = { { { 0, 0, 0 } }, { { 3, 3, 0 } }, { { 1, 2, 2 } }, { { 2, 1, -2 } } };
    CHECK((ExactCriticalPointOf(tilted, 4, e) && e.Flat && e.SquaredRadius == 4.5 &&
      e.Location == Point3{ { 1.5, 1.5, 0 } }));
    const Point3 kite[4] = { { { 0, 0, 0 } }, { { 1, 0, 0 } }, { { 0, 1, 0 } }, { { 2, 2, 0 } } };
    CHECK(!ExactCriticalPointOf(kite, 4, e));
    const Point3 collinear[3] = { { { 0, 0, 0 } }, { { 1, 1, 1 } }, { { 3, 3, 3 } } };
    CHECK(!ExactCriticalPointOf(collinear, 3, e));
    const Point3 collinearCell[4] = { { { 0, 0, 0 } }, { { 1, 1, 1 } }, { { 3, 3, 3 } }, { { 1, 0, 0 } } };
    CHECK(!ExactCriticalPointOf(collinearCell, 4, e));
  }

  std::mt19937_64 g(5);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> small(-6, 6);
  long mismatches = 0, untied = 0, trials = 0, filtered = 0;
  for (int trial = 0; trial < 20000; ++trial)
  {
    const int n = 2 + trial % 3;
    Point3 p[4];
    for (int i = 0; i < n; ++i)
    {
      for (double& x : p[i])
      {
        x = trial % 2 ? u(g) : std::ldexp(u(g), static_cast<int>(g() % 40) - 20);
      }
    }
    if (!ExactCriticalPointOf(p, n, e))
    {
      continue; // degenerate draw (not with random doubles)
    }
    ++trials;
    mismatches += !SameAsOracle(p, n, e);

    // Ties: a copy of a small integer simplex moved by an exact translation,
    // an axis permutation and a reflection has the same squared radius.
    Point3 s[4], t[4];
    const double shift[3] = { 1024.5 + small(g), -77.25, 0.125 * small(g) };
    const int axis = static_cast<int>(g() % 3);
    for (int i = 0; i < n; ++i)
    {
      for (int k = 0; k < 3; ++k)
      {
        s[i][k] = small(g);
      }
      for (int k = 0; k < 3; ++k)
      {
        t[i][k] = (k == 0 ? -1 : 1) * s[i][(k + axis) % 3] + shift[k];
      }
    }
    ExactCriticalPoint a, b;
    const bool sa = ExactCriticalPointOf(s, n, a), sb = ExactCriticalPointOf(t, n, b);
    untied += sa != sb || (sa && (a.SquaredRadius != b.SquaredRadius || a.Flat != b.Flat));
    // Small integers: mostly the interval filter's answers, which must be the same.
    if (sa && !a.Flat)
    {
      ++filtered;
      mismatches += !SameAsOracle(s, n, a) + !SameAsOracle(t, n, b);
    }
  }
  CHECK(trials > 19000);
  CHECK(filtered > 15000);
  CHECK(mismatches == 0);
  CHECK(untied == 0);
  std::cout << trials << " + " << 2 * filtered << " simplices, " << mismatches << " differ from the oracle, " << untied
            << " moved copies differ\n";
  return check::Finish("TestExactCriticalPoint");
}
