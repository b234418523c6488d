// Number types for the walks through Voronoi faces. Walk points are iterated
// rational constructions, so predicates on them are evaluated with interval
// arithmetic first and redone with exact rationals when an interval cannot
// decide (docs/algorithm.md §4.4).
#ifndef flowrecon_Arithmetic_h
#define flowrecon_Arithmetic_h

#include "FlowComplex.h"

#include "ExactRational.h"

#include <CGAL/FPU.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Uncertain.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace flowrecon
{

using IntervalFT = CGAL::Interval_nt_advanced; // needs a Protect_FPU_rounding scope
using ExactFT = ExactRational;

inline double ToDouble(const IntervalFT& x)
{
  return CGAL::to_double(x);
}
inline double ToDouble(const ExactFT& x)
{
  return x.ToDouble();
}

// Inlined: the walks spend most of their time in these (with intervals, a
// call each cost about a fifth of the unstable manifolds).
#define FLOWRECON_INLINE inline __attribute__((always_inline))

template <class FT>
struct Vec
{
  FT X, Y, Z;

  static Vec From(const Point3& p) { return Vec{ FT(p[0]), FT(p[1]), FT(p[2]) }; }
  FLOWRECON_INLINE Vec operator+(const Vec& o) const { return Vec{ X + o.X, Y + o.Y, Z + o.Z }; }
  FLOWRECON_INLINE Vec operator-(const Vec& o) const { return Vec{ X - o.X, Y - o.Y, Z - o.Z }; }
  FLOWRECON_INLINE Vec operator*(const FT& s) const { return Vec{ X * s, Y * s, Z * s }; }
  Vec operator/(const FT& s) const { return Vec{ X / s, Y / s, Z / s }; }
  FLOWRECON_INLINE FT Dot(const Vec& o) const { return X * o.X + Y * o.Y + Z * o.Z; }
  FLOWRECON_INLINE FT SquaredLength() const { return this->Dot(*this); }
  FLOWRECON_INLINE Vec Cross(const Vec& o) const
  {
    return Vec{ Y * o.Z - Z * o.Y, Z * o.X - X * o.Z, X * o.Y - Y * o.X };
  }
  Point3 ToDouble() const { return Point3{ { flowrecon::ToDouble(X), flowrecon::ToDouble(Y), flowrecon::ToDouble(Z) } }; }
};

/// Sign of x; throws CGAL::Uncertain_conversion_exception if an interval cannot tell.
inline int CertainSign(const IntervalFT& x)
{
  return static_cast<int>(CGAL::sign(x).make_certain());
}
inline int CertainSign(const ExactFT& x)
{
  return static_cast<int>(x.Sign());
}

/// Circumcentre of triangle abc inside its own plane.
template <class FT>
Vec<FT> Circumcenter(const Vec<FT>& a, const Vec<FT>& b, const Vec<FT>& c)
{
  const Vec<FT> u = b - a, v = c - a;
  const Vec<FT> n = u.Cross(v);
  return a + (v * u.SquaredLength() - u * v.SquaredLength()).Cross(n) / (FT(2) * n.SquaredLength());
}

/// Circumcentre of tetrahedron abcd.
template <class FT>
Vec<FT> Circumcenter(const Vec<FT>& a, const Vec<FT>& b, const Vec<FT>& c, const Vec<FT>& d)
{
  const Vec<FT> u = b - a, v = c - a, w = d - a;
  const Vec<FT> num =
    v.Cross(w) * u.SquaredLength() + w.Cross(u) * v.SquaredLength() + u.Cross(v) * w.SquaredLength();
  return a + num / (FT(2) * u.Dot(v.Cross(w)));
}

/// Run f<IntervalFT>() under directed rounding; if an interval comparison is
/// undecided, run f<ExactFT>(). `fallbacks` counts the exact reruns. With
/// `exactOnly` (tests of the exact path) the interval stage is skipped. The flag
/// is passed, not global, so that concurrent builds cannot change each other.
template <class F>
auto Filtered(F&& f, Id& fallbacks, bool exactOnly)
{
  if (!exactOnly)
  {
    try
    {
      CGAL::Protect_FPU_rounding<true> protect;
      return f(IntervalFT());
    }
    catch (CGAL::Uncertain_conversion_exception&)
    {
    }
  }
  ++fallbacks;
  return f(ExactFT());
}

inline bool IsTight(const IntervalFT& x)
{
  const double w = x.sup() - x.inf();
  return std::isfinite(w) && w <= 1e-13 * std::max(std::fabs(x.inf()), std::fabs(x.sup()));
}

/// The double value of a constructed point; from intervals only when they are
/// tight (else the caller's exact fallback recomputes it), so that output
/// geometry is as accurate as the combinatorics.
inline Point3 RequireTight(const Vec<IntervalFT>& p)
{
  // Widths are judged against the point's magnitude, so that a coordinate near
  // zero does not count as loose.
  const double mag = std::max({ std::fabs(p.X.inf()), std::fabs(p.X.sup()), std::fabs(p.Y.inf()),
    std::fabs(p.Y.sup()), std::fabs(p.Z.inf()), std::fabs(p.Z.sup()) });
  const double w = std::max({ p.X.sup() - p.X.inf(), p.Y.sup() - p.Y.inf(), p.Z.sup() - p.Z.inf() });
  if (!(std::isfinite(w) && w <= 1e-9 * mag))
  {
    throw CGAL::Uncertain_conversion_exception("loose constructed point");
  }
  return p.ToDouble();
}
inline Point3 RequireTight(const Vec<ExactFT>& p)
{
  return p.ToDouble();
}

/// A point that is drawn only (a flow line's polyline): its double value when
/// within 1e-9 of its magnitude or 1e-6 of `scale` (the cloud's size: below a
/// pixel on any screen), else NaN, which the caller leaves out of the drawing.
/// Unlike RequireTight it never sends a walk to exact arithmetic: the walks the
/// combinatorics can decide in intervals (their targets are certified either
/// way) were measured at 20 ms each in exact arithmetic on flat scans, a
/// hundred times the rest of the flow complex.
inline Point3 DrawnPoint(const Vec<IntervalFT>& p, double scale)
{
  const double mag = std::max({ std::fabs(p.X.inf()), std::fabs(p.X.sup()), std::fabs(p.Y.inf()),
    std::fabs(p.Y.sup()), std::fabs(p.Z.inf()), std::fabs(p.Z.sup()) });
  const double w = std::max({ p.X.sup() - p.X.inf(), p.Y.sup() - p.Y.inf(), p.Z.sup() - p.Z.inf() });
  if (std::isfinite(w) && (w <= 1e-9 * mag || w <= 1e-6 * scale))
  {
    return p.ToDouble();
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return Point3{ { nan, nan, nan } };
}
inline Point3 DrawnPoint(const Vec<ExactFT>& p, double)
{
  return p.ToDouble();
}

/// Doubles within a relative 1e-13 of the exact values of a rational construction
/// f<FT>() -> std::array<FT, N>: interval values when tight, else exact ones.
template <std::size_t N, class F>
std::array<double, N> Certified(F&& f)
{
  {
    CGAL::Protect_FPU_rounding<true> protect;
    const std::array<IntervalFT, N> r = f(IntervalFT());
    bool tight = true;
    for (const IntervalFT& x : r)
    {
      tight = tight && IsTight(x);
    }
    if (tight)
    {
      std::array<double, N> out;
      for (std::size_t i = 0; i < N; ++i)
      {
        out[i] = ToDouble(r[i]);
      }
      return out;
    }
  }
  const std::array<ExactFT, N> r = f(ExactFT());
  std::array<double, N> out;
  for (std::size_t i = 0; i < N; ++i)
  {
    out[i] = ToDouble(r[i]);
  }
  return out;
}

} // namespace flowrecon

#endif
