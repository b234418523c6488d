// The primitive shared by the descending (stable manifold) and ascending
// (unstable manifold) walks: inside the Voronoi facet V(uv), a point z on a
// Voronoi edge V(g) moves along the line through the midpoint m of uv until a
// link sample s becomes equidistant (flow-complex-algorithm.md §3.2).
//
// Why this form: a walk point is written z = c_g + lambda * n_g, where c_g and
// n_g (circumcentre and normal of the triangle g) depend on input points only.
// The next point's lambda is then a Moebius function of this one, and every
// predicate is a polynomial of degree <= 2 in lambda with coefficients computed
// from the inputs. Interval enclosures therefore widen only with the true
// conditioning of the flow, not with the length of the walk, and the exact
// fallback handles one growing rational instead of three.
#ifndef flowrecon_VoronoiWalk_h
#define flowrecon_VoronoiWalk_h

#include "Arithmetic.h"
#include "Progress.h"
#include "Triangulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace flowrecon
{

/// A point on the Voronoi edge of triangle G (sorted vertex indices).
template <class FT>
struct EdgePoint
{
  std::array<Id, 3> G;
  FT Lambda;
};

/// Circumcentre and normal (v1 - v0) x (v2 - v0) of the sorted triangle g.
template <class FT>
struct Frame
{
  Vec<FT> C, N;

  Frame() = default;
  Frame(const Triangulation& tri, const std::array<Id, 3>& g)
  {
    const Vec<FT> a = Vec<FT>::From(tri.Coord(g[0])), b = Vec<FT>::From(tri.Coord(g[1])),
                  c = Vec<FT>::From(tri.Coord(g[2]));
    this->C = Circumcenter(a, b, c);
    this->N = (b - a).Cross(c - a);
  }
  Vec<FT> At(const FT& lambda) const { return this->C + this->N * lambda; }
};

/// Frame of g through a small per-thread cache: a walk meets each Voronoi edge
/// several times (as an exit, then as the start of both branches), and the
/// circumcentre is the most expensive part of a step. Keyed by the
/// triangulation's serial number, so never stale.
template <class FT>
Frame<FT> CachedFrame(const Triangulation& tri, const std::array<Id, 3>& g)
{
  struct Entry
  {
    std::uint64_t Serial = 0;
    std::array<Id, 3> G{ { -1, -1, -1 } };
    Frame<FT> F;
  };
  constexpr std::size_t Size = 1024; // a power of two
  thread_local std::vector<Entry> cache(Size);
  const std::size_t slot =
    static_cast<std::size_t>((g[0] * 73856093) ^ (g[1] * 19349663) ^ (g[2] * 83492791)) & (Size - 1);
  Entry& e = cache[slot];
  if (e.Serial != tri.Serial() || e.G != g)
  {
    e.F = Frame<FT>(tri, g);
    e.G = g;
    e.Serial = tri.Serial();
  }
  return e.F;
}

/// Link of uv (Triangulation::Link) through a small per-thread cache: walks ask
/// for the same edges again and again (measured: about half of the requests on
/// surface samples repeat within 4096 edges). Which cell is recorded for a link
/// sample may differ from an uncached call with another hint; every user only
/// needs some cell containing (u, v, s). The references stay valid until this
/// thread's next call.
struct LinkView
{
  const std::vector<Id>& Samples;
  const std::vector<CellHandle>& Cells;
};
inline LinkView CachedLink(const Triangulation& tri, Id u, Id v, CellHandle hint)
{
  struct Entry
  {
    std::uint64_t Serial = 0;
    Id U = -1, V = -1;
    std::vector<Id> Samples;
    std::vector<CellHandle> Cells;
  };
  constexpr std::size_t Size = 4096; // a power of two
  thread_local std::vector<Entry> cache(Size);
  const Id a = std::min(u, v), b = std::max(u, v);
  Entry& e = cache[static_cast<std::size_t>((a * 73856093) ^ (b * 19349663)) & (Size - 1)];
  if (e.Serial != tri.Serial() || e.U != a || e.V != b)
  {
    e.Samples.clear();
    e.Cells.clear();
    tri.Link(a, b, e.Samples, &e.Cells, hint);
    // In id order: where the circulation starts depends on the hint and on the
    // (concurrently built) triangulation, and the order of candidates decides
    // which interval comparisons a walk meets, hence when it falls back to exact.
    for (std::size_t i = 1; i < e.Samples.size(); ++i)
    {
      for (std::size_t j = i; j > 0 && e.Samples[j] < e.Samples[j - 1]; --j)
      {
        std::swap(e.Samples[j], e.Samples[j - 1]);
        std::swap(e.Cells[j], e.Cells[j - 1]);
      }
    }
    e.U = a;
    e.V = b;
    e.Serial = tri.Serial();
  }
  return { e.Samples, e.Cells };
}

inline std::array<Id, 3> SortedTriangle(Id a, Id b, Id c)
{
  std::array<Id, 3> g{ { a, b, c } };
  std::sort(g.begin(), g.end());
  return g;
}

/// f(lambda) = -(a + b lambda) / (c + d lambda) over an interval: f is monotone
/// where the denominator keeps its sign, so the hull of the end values encloses it.
inline IntervalFT Moebius(const IntervalFT& a, const IntervalFT& b, const IntervalFT& c,
  const IntervalFT& d, const IntervalFT& lambda)
{
  if (CertainSign(c + d * lambda) == 0)
  {
    throw Degenerate("walk runs parallel to a Voronoi edge");
  }
  const IntervalFT lo(lambda.inf()), hi(lambda.sup());
  const IntervalFT flo = -(a + b * lo) / (c + d * lo), fhi = -(a + b * hi) / (c + d * hi);
  return IntervalFT(std::min(flo.inf(), fhi.inf()), std::max(flo.sup(), fhi.sup()));
}
/// Exactly, on numerators and denominators: with lambda = p / q, the result is
/// -(a q + b p) / (c q + d p) up to the denominators of a..d. Its terms grow by
/// a constant per step of a walk; past about 1024 bits (a double overflows)
/// they are reduced, which costs a gcd that most walks, a few steps long, do
/// not need.
inline ExactFT Moebius(
  const ExactFT& a, const ExactFT& b, const ExactFT& c, const ExactFT& d, const ExactFT& lambda)
{
  const ExactFT q(lambda.Denominator(), CGAL::Mpzf(1)), p(lambda.Numerator(), CGAL::Mpzf(1));
  const ExactFT top = a * q + b * p, bottom = c * q + d * p;
  if (bottom.Sign() == CGAL::ZERO)
  {
    throw Degenerate("walk runs parallel to a Voronoi edge");
  }
  const ExactFT next = -top / bottom;
  const bool large = !std::isfinite(next.Numerator().to_double()) ||
    !std::isfinite(next.Denominator().to_double());
  return large ? next.Reduced() : next;
}

/// The first exit of the walk from z (on V(z.G), inside V(uv)) along the line
/// through m_uv: toward m_uv if `descending`, away from it otherwise. Candidates
/// are link samples of uv not in `excluded`. Returns false if no sample is met
/// (the walk leaves an unbounded Voronoi facet). Throws Degenerate on ties and
/// CGAL::Uncertain_conversion_exception when intervals cannot decide.
/// With `descending`, also requires the exit to come before m_uv (t < 1).
/// `hint` is a cell containing uv (or null); `exitCell` receives a cell containing
/// the exit triangle (u, v, s).
template <class FT>
bool FirstExit(const Triangulation& tri, const EdgePoint<FT>& z, Id u, Id v,
  const std::vector<Id>& excluded, bool descending, CellHandle hint, Id& exitSample,
  EdgePoint<FT>& exitPoint, CellHandle& exitCell)
{
  const Frame<FT> frame = CachedFrame<FT>(tri, z.G);
  const Vec<FT> pu = Vec<FT>::From(tri.Coord(u)), pv = Vec<FT>::From(tri.Coord(v));
  const Vec<FT> m = (pu + pv) / FT(2);
  const Vec<FT> cm = frame.C - m; // z - m = cm + lambda N
  const FT uu = pu.SquaredLength();
  const LinkView view = CachedLink(tri, u, v, hint);
  const std::vector<Id>& link = view.Samples;
  const std::vector<CellHandle>& linkCells = view.Cells;
  Id best = -1;
  CellHandle bestCell;
  // For candidate s: num = |z-s|^2 - |z-u|^2 >= 0 and D = +-(m - z).(s - u) > 0;
  // the exit parameter is num / (2 D). Both are affine in lambda.
  FT bestNum(0), bestDen(1);
  for (std::size_t k = 0; k < link.size(); ++k)
  {
    const Id s = link[k];
    if (std::find(excluded.begin(), excluded.end(), s) != excluded.end())
    {
      continue;
    }
    const Vec<FT> ps = Vec<FT>::From(tri.Coord(s));
    const Vec<FT> su = ps - pu;
    FT den = -(cm.Dot(su) + z.Lambda * frame.N.Dot(su)); // (m - z).(s - u)
    if (!descending)
    {
      den = -den;
    }
    if (CertainSign(den) <= 0)
    {
      continue;
    }
    const FT num = FT(2) * (frame.C.Dot(pu - ps) + z.Lambda * frame.N.Dot(pu - ps)) +
      (ps.SquaredLength() - uu);
    if (CertainSign(num) <= 0)
    {
      throw Degenerate("walk starts on a Voronoi vertex");
    }
    if (best >= 0)
    {
      const int cmp = CertainSign(num * bestDen - bestNum * den);
      if (cmp == 0)
      {
        throw Degenerate("walk meets a Voronoi vertex");
      }
      if (cmp > 0)
      {
        continue;
      }
    }
    best = s;
    bestCell = linkCells[k];
    bestNum = num;
    bestDen = den;
  }
  if (best < 0)
  {
    return false;
  }
  if (descending && CertainSign(bestNum - FT(2) * bestDen) >= 0)
  {
    throw Degenerate("descending walk reaches the driver of a non-Gabriel edge");
  }
  // The exit point y = c' + lambda' n' of V(u v s) is collinear with m and z in
  // the bisector plane of uv (normal e): ((y - m) x (z - m)).e = 0.
  exitSample = best;
  exitCell = bestCell;
  exitPoint.G = SortedTriangle(u, v, best);
  const Frame<FT> next = CachedFrame<FT>(tri, exitPoint.G);
  const Vec<FT> e = pv - pu;
  const Vec<FT> cm2 = next.C - m;
  const FT a = cm2.Cross(cm).Dot(e), b = cm2.Cross(frame.N).Dot(e);
  const FT c = next.N.Cross(cm).Dot(e), d = next.N.Cross(frame.N).Dot(e);
  exitPoint.Lambda = Moebius(a, b, c, d, z.Lambda);
  return true;
}

} // namespace flowrecon

#endif
