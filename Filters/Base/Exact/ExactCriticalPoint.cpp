#include "ExactCriticalPoint.h"

#include "ExactRational.h"

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

namespace flowrecon
{
namespace
{

// The same formulas over two number types. Mpzf (integers times powers of two:
// every double and every sum and product of them is exact, no gcd) decides
// everything, and its one division, the final truncation, gives the doubles.
// Intervals go first: where a result is a single double (grids: most radii and
// centres are dyadic), that double is the exact value, hence its truncation too;
// any other case (a sign or equality undecided, a result between two doubles) is
// redone exactly. Both give the same doubles: the filter only saves time.
using Z = CGAL::Mpzf;
using I = CGAL::Interval_nt_advanced; // in a Protect_FPU_rounding scope

/// Which sign: -1, 0, 1, or 2 when undecided (intervals only).
int SignOf(const Z& x)
{
  return static_cast<int>(x.sign());
}
int SignOf(const I& x)
{
  return x.inf() > 0 ? 1 : x.sup() < 0 ? -1 : (x.inf() == 0 && x.sup() == 0) ? 0 : 2;
}

/// n / d (d != 0) truncated to a double; false when undecided (intervals only).
bool Quotient(const Z& n, const Z& d, double& out)
{
  out = ExactRational(n, d).ToDouble();
  return true;
}
bool Quotient(const I& n, const I& d, double& out)
{
  const I q = n / d;
  out = q.inf();
  return q.inf() == q.sup();
}

template <class NT>
struct Formulas
{
  using V = std::array<NT, 3>;

  static V Minus(const Point3& p, const Point3& q)
  {
    return { { NT(p[0]) - NT(q[0]), NT(p[1]) - NT(q[1]), NT(p[2]) - NT(q[2]) } };
  }
  static NT Dot(const V& a, const V& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static V Cross(const V& a, const V& b)
  {
    return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
  }
  /// s a + t b
  static V Combine(const NT& s, const V& a, const NT& t, const V& b)
  {
    return { { s * a[0] + t * b[0], s * a[1] + t * b[1], s * a[2] + t * b[2] } };
  }
  /// p0 + x / d, each coordinate truncated once.
  static bool Offset(const Point3& p0, const V& x, const NT& d, Point3& c)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (!Quotient(NT(p0[k]) * d + x[k], d, c[k]))
      {
        return false;
      }
    }
    return true;
  }
  /// The circumcircle of p0, p0 + a, p0 + b (w = a x b, not 0): centre p0 + y / (2 |w|^2).
  static V CircleCentre(const V& a, const V& b, const V& w)
  {
    return Combine(Dot(a, a), Cross(b, w), Dot(b, b), Cross(w, a));
  }

  /// 1: found, 0: no limit, -1: undecided (intervals only).
  static int Evaluate(const Point3* p, int n, ExactCriticalPoint& out)
  {
    out = ExactCriticalPoint();
    const V a = Minus(p[1], p[0]);
    if (n == 2)
    {
      return Offset(p[0], a, NT(2), out.Location) && Quotient(Dot(a, a), NT(4), out.SquaredRadius) ? 1 : -1;
    }
    const V b = Minus(p[2], p[0]);
    const V w = Cross(a, b);
    const NT ww = Dot(w, w);
    const int collinear = SignOf(ww);
    if (collinear != 1)
    {
      return collinear == 0 ? 0 : -1;
    }
    if (n == 4)
    {
      const V c = Minus(p[3], p[0]);
      const V bc = Cross(b, c);
      const NT det = Dot(a, bc);
      const int flat = SignOf(det);
      if (flat == 2)
      {
        return -1;
      }
      if (flat != 0)
      {
        // Centre p0 + x / (2 det), x = |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b).
        const V cw = Combine(NT(1), Combine(Dot(a, a), bc, Dot(b, b), Cross(c, a)), Dot(c, c), w);
        const NT d = NT(2) * det;
        return Offset(p[0], cw, d, out.Location) && Quotient(Dot(cw, cw), d * d, out.SquaredRadius) ? 1 : -1;
      }
      // Coplanar: on the circle of the first three iff |c - y / (2|w|^2)| is its
      // radius |y| / (2|w|^2), i.e. |w|^2 |c|^2 = c . y.
      const int off = SignOf(ww * Dot(c, c) - Dot(c, CircleCentre(a, b, w)));
      if (off != 0)
      {
        return off == 2 ? -1 : 0;
      }
      out.Flat = true;
    }
    // A circle: centre p0 + y / (2 |w|^2), squared radius |a|^2 |b|^2 |a - b|^2 / (4 |w|^2).
    const V ab = Minus(p[2], p[1]);
    return Offset(p[0], CircleCentre(a, b, w), NT(2) * ww, out.Location) &&
        Quotient(Dot(a, a) * Dot(b, b) * Dot(ab, ab), NT(4) * ww, out.SquaredRadius)
      ? 1
      : -1;
  }
};

} // namespace

bool ExactCriticalPointOf(const Point3* p, int n, ExactCriticalPoint& out)
{
  {
    CGAL::Protect_FPU_rounding<true> rounding;
    const int filtered = Formulas<I>::Evaluate(p, n, out);
    if (filtered >= 0)
    {
      return filtered == 1;
    }
  }
  return Formulas<Z>::Evaluate(p, n, out) == 1;
}

} // namespace flowrecon
