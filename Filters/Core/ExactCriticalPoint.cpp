#include "ExactCriticalPoint.h"

#include "ExactRational.h"

#include <CGAL/Mpzf.h>

namespace flowrecon
{
namespace
{

// Integers times powers of two: every double and every sum and product of them
// is exact, and no gcd is taken (the one division is the final truncation).
using Z = CGAL::Mpzf;
using V = std::array<Z, 3>;

V Minus(const Point3& p, const Point3& q)
{
  return { { Z(p[0]) - Z(q[0]), Z(p[1]) - Z(q[1]), Z(p[2]) - Z(q[2]) } };
}

Z Dot(const V& a, const V& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

V Cross(const V& a, const V& b)
{
  return { { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] } };
}

/// s a + t b + u c
V Combine(const Z& s, const V& a, const Z& t, const V& b, const Z& u, const V& c)
{
  V r;
  for (int k = 0; k < 3; ++k)
  {
    r[k] = s * a[k] + t * b[k] + u * c[k];
  }
  return r;
}

/// p0 + x / d, each coordinate truncated once.
Point3 Offset(const Point3& p0, const V& x, const Z& d)
{
  Point3 c;
  for (int k = 0; k < 3; ++k)
  {
    c[k] = ExactRational(Z(p0[k]) * d + x[k], d).ToDouble();
  }
  return c;
}

/// The circumcircle of p0, p0 + a, p0 + b (w = a x b, not 0): centre p0 + y / (2 |w|^2).
V CircleCentre(const V& a, const V& b, const V& w)
{
  const Z zero(0);
  return Combine(Dot(a, a), Cross(b, w), Dot(b, b), Cross(w, a), zero, a);
}

} // namespace

bool ExactCriticalPointOf(const Point3* p, int n, ExactCriticalPoint& out)
{
  out = ExactCriticalPoint();
  const V a = Minus(p[1], p[0]);
  if (n == 2)
  {
    out.Location = Offset(p[0], a, Z(2));
    out.SquaredRadius = ExactRational(Dot(a, a), Z(4)).ToDouble();
    return true;
  }
  const V b = Minus(p[2], p[0]);
  const V w = Cross(a, b);
  const Z ww = Dot(w, w);
  if (ww.is_zero())
  {
    return false; // collinear: no circle
  }
  if (n == 4)
  {
    const V c = Minus(p[3], p[0]);
    const V bc = Cross(b, c);
    const Z det = Dot(a, bc);
    if (!det.is_zero())
    {
      // Centre p0 + x / (2 det), x = |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b).
      const V x = Combine(Dot(a, a), bc, Dot(b, b), Cross(c, a), Dot(c, c), w);
      const Z d = Z(2) * det;
      out.Location = Offset(p[0], x, d);
      out.SquaredRadius = ExactRational(Dot(x, x), d * d).ToDouble();
      return true;
    }
    // Coplanar: on the circle of the first three iff |c - y / (2|w|^2)| is its
    // radius |y| / (2|w|^2) (y of CircleCentre), i.e. |w|^2 |c|^2 = c . y.
    if (!(ww * Dot(c, c) == Dot(c, CircleCentre(a, b, w))))
    {
      return false;
    }
    out.Flat = true;
  }
  // A circle: centre p0 + y / (2 |w|^2), squared radius |a|^2 |b|^2 |a - b|^2 / (4 |w|^2).
  out.Location = Offset(p[0], CircleCentre(a, b, w), Z(2) * ww);
  const V ab = Minus(p[2], p[1]);
  out.SquaredRadius = ExactRational(Dot(a, a) * Dot(b, b) * Dot(ab, ab), Z(4) * ww).ToDouble();
  return true;
}

} // namespace flowrecon
