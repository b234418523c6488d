// The primitive shared by the descending (stable manifold) and ascending
// (unstable manifold) walks: inside the Voronoi facet V(uv), a point z on a
// Voronoi edge V(g) moves along the line through the midpoint m of uv until a
// link sample s becomes equidistant (docs/algorithm.md §3.2).
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
#include <type_traits>
#include <utility>
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

/// The terms deciding where a walk point z = C + lambda N (on `frame`) leaves
/// V(uv) for candidate s: num = |z-s|^2 - |z-u|^2 >= 0 and den = +-(m - z).(s - u)
/// > 0 (away from m_uv when ascending); the exit parameter is num / (2 den), and
/// both terms are affine in lambda.
template <class FT>
struct ExitTerms
{
  const Frame<FT>& F;
  const Vec<FT>& Pu;
  const Vec<FT>& Cm; // C - m_uv
  const FT& Uu;      // |u|^2
  const FT& Lambda;
  bool Descending;

  FT Den(const Vec<FT>& ps) const
  {
    const Vec<FT> su = ps - this->Pu;
    const FT den = -(this->Cm.Dot(su) + this->Lambda * this->F.N.Dot(su)); // (m - z).(s - u)
    return this->Descending ? den : -den;
  }
  FT Num(const Vec<FT>& ps) const
  {
    return FT(2) * (this->F.C.Dot(this->Pu - ps) + this->Lambda * this->F.N.Dot(this->Pu - ps)) +
      (ps.SquaredLength() - this->Uu);
  }
};

/// Decides the comparisons of ChooseExit in the walk's own number type.
template <class FT>
class PlainJudge
{
public:
  PlainJudge(const Triangulation& tri, const ExitTerms<FT>& terms)
    : Tri(tri)
    , Terms(terms)
  {
  }
  int DenSign(Id s)
  {
    this->Ps = Vec<FT>::From(this->Tri.Coord(s));
    this->Den = this->Terms.Den(this->Ps);
    return CertainSign(this->Den);
  }
  int NumSign()
  {
    this->Num = this->Terms.Num(this->Ps);
    return CertainSign(this->Num);
  }
  /// Sign of (this candidate's exit parameter) - (the best one's).
  int CompareWithBest() const
  {
    return CertainSign(this->Num * this->BestDen - this->BestNum * this->Den);
  }
  void Accept()
  {
    this->BestNum = this->Num;
    this->BestDen = this->Den;
  }
  /// Sign of (the best exit parameter) - 1: whether the exit comes after m_uv.
  int BestBeyondMidpoint() const { return CertainSign(this->BestNum - FT(2) * this->BestDen); }

private:
  const Triangulation& Tri;
  const ExitTerms<FT>& Terms;
  Vec<FT> Ps;
  FT Num, Den, BestNum{ 0 }, BestDen{ 1 };
};

/// For exact walks: intervals around the exact lambda decide almost every
/// comparison, and only the others are made exactly. Lambda is an iterated
/// Moebius image whose terms grow with every step, so the exact products of the
/// candidates' terms were nearly all of an exact walk's cost (the bunny-mesh
/// sample of 10^7 points spent most of its 40 minutes there). The decisions are
/// the exact ones either way.
class FilteredJudge
{
public:
  FilteredJudge(const Triangulation& tri, const ExitTerms<ExactFT>& exact, const EdgePoint<ExactFT>& z,
    Id u, Id v)
    : Tri(tri)
    , Exact(exact)
  {
    const std::pair<double, double> n = z.Lambda.Numerator().to_interval();
    const std::pair<double, double> d = z.Lambda.Denominator().to_interval();
    const bool small = std::isfinite(n.first) && std::isfinite(n.second) &&
      std::isfinite(d.first) && std::isfinite(d.second) && d.first > 0;
    double low = 0, high = 0;
    if (!small)
    {
      // Terms past the range of doubles (long exact walks: their reduced terms
      // still grow with every step, and without this the rest of the walk was
      // exact throughout): the truncated quotient is within an ulp.
      const double x = z.Lambda.ToDouble();
      if (!std::isfinite(x))
      {
        return;
      }
      low = std::nextafter(x, -HUGE_VAL);
      high = std::nextafter(x, HUGE_VAL);
    }
    this->Usable = true;
    CGAL::Protect_FPU_rounding<true> protect;
    this->Lambda = small ? IntervalFT(n) / IntervalFT(d) : IntervalFT(low, high);
    this->F = CachedFrame<IntervalFT>(tri, z.G);
    this->Pu = Vec<IntervalFT>::From(tri.Coord(u));
    this->Cm = this->F.C - (this->Pu + Vec<IntervalFT>::From(tri.Coord(v))) / IntervalFT(2);
    this->Uu = this->Pu.SquaredLength();
    this->Usable = std::isfinite(this->Lambda.inf()) && std::isfinite(this->Lambda.sup());
  }
  int DenSign(Id s)
  {
    this->S = s;
    this->HasExact = false;
    if (this->Usable)
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const ExitTerms<IntervalFT> terms{ this->F, this->Pu, this->Cm, this->Uu, this->Lambda,
        this->Exact.Descending };
      this->Ps = Vec<IntervalFT>::From(this->Tri.Coord(s));
      this->Den = terms.Den(this->Ps);
      const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(this->Den);
      if (CGAL::is_certain(sign))
      {
        return static_cast<int>(CGAL::get_certain(sign));
      }
    }
    this->MakeExact();
    return CertainSign(this->EDen);
  }
  int NumSign()
  {
    if (!this->HasExact)
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const ExitTerms<IntervalFT> terms{ this->F, this->Pu, this->Cm, this->Uu, this->Lambda,
        this->Exact.Descending };
      this->Num = terms.Num(this->Ps);
      const CGAL::Uncertain<CGAL::Sign> sign = CGAL::sign(this->Num);
      if (CGAL::is_certain(sign))
      {
        return static_cast<int>(CGAL::get_certain(sign));
      }
      this->MakeExact();
    }
    return CertainSign(this->ENum);
  }
  int CompareWithBest()
  {
    if (!this->HasExact && !this->BestHasExact)
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const CGAL::Uncertain<CGAL::Sign> sign =
        CGAL::sign(this->Num * this->BestDen - this->BestNum * this->Den);
      if (CGAL::is_certain(sign))
      {
        return static_cast<int>(CGAL::get_certain(sign));
      }
    }
    this->MakeExact();
    this->MakeBestExact();
    return CertainSign(this->ENum * this->EBestDen - this->EBestNum * this->EDen);
  }
  void Accept()
  {
    this->Best = this->S;
    this->BestNum = this->Num;
    this->BestDen = this->Den;
    this->BestHasExact = this->HasExact;
    if (this->HasExact)
    {
      this->EBestNum = this->ENum;
      this->EBestDen = this->EDen;
    }
  }
  int BestBeyondMidpoint()
  {
    if (!this->BestHasExact)
    {
      CGAL::Protect_FPU_rounding<true> protect;
      const CGAL::Uncertain<CGAL::Sign> sign =
        CGAL::sign(this->BestNum - IntervalFT(2) * this->BestDen);
      if (CGAL::is_certain(sign))
      {
        return static_cast<int>(CGAL::get_certain(sign));
      }
    }
    this->MakeBestExact();
    return CertainSign(this->EBestNum - ExactFT(2) * this->EBestDen);
  }

private:
  void MakeExact()
  {
    if (!this->HasExact)
    {
      const Vec<ExactFT> ps = Vec<ExactFT>::From(this->Tri.Coord(this->S));
      this->EDen = this->Exact.Den(ps);
      this->ENum = this->Exact.Num(ps);
      this->HasExact = true;
    }
  }
  void MakeBestExact()
  {
    if (!this->BestHasExact)
    {
      const Vec<ExactFT> ps = Vec<ExactFT>::From(this->Tri.Coord(this->Best));
      this->EBestDen = this->Exact.Den(ps);
      this->EBestNum = this->Exact.Num(ps);
      this->BestHasExact = true;
    }
  }

  const Triangulation& Tri;
  const ExitTerms<ExactFT>& Exact;
  bool Usable = false;
  IntervalFT Lambda;
  Frame<IntervalFT> F;
  Vec<IntervalFT> Pu, Cm, Ps;
  IntervalFT Uu, Num, Den, BestNum{ 0 }, BestDen{ 1 };
  Id S = -1, Best = -1;
  bool HasExact = false, BestHasExact = false;
  ExactFT ENum, EDen, EBestNum, EBestDen;
};

/// The candidate of `link` (not in `excluded`) where the walk leaves V(uv)
/// first, or -1. Throws Degenerate on ties.
template <class Judge>
std::ptrdiff_t ChooseExit(Judge& judge, const std::vector<Id>& link, const std::vector<Id>& excluded)
{
  std::ptrdiff_t best = -1;
  for (std::size_t k = 0; k < link.size(); ++k)
  {
    const Id s = link[k];
    if (std::find(excluded.begin(), excluded.end(), s) != excluded.end())
    {
      continue;
    }
    if (judge.DenSign(s) <= 0)
    {
      continue;
    }
    if (judge.NumSign() <= 0)
    {
      throw Degenerate("walk starts on a Voronoi vertex");
    }
    if (best >= 0)
    {
      const int cmp = judge.CompareWithBest();
      if (cmp == 0)
      {
        throw Degenerate("walk meets a Voronoi vertex");
      }
      if (cmp > 0)
      {
        continue;
      }
    }
    best = static_cast<std::ptrdiff_t>(k);
    judge.Accept();
  }
  return best;
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
  const ExitTerms<FT> terms{ frame, pu, cm, uu, z.Lambda, descending };
  std::ptrdiff_t k = -1;
  bool beyond = false;
  if constexpr (std::is_same<FT, ExactFT>::value)
  {
    FilteredJudge judge(tri, terms, z, u, v);
    k = ChooseExit(judge, view.Samples, excluded);
    beyond = k >= 0 && descending && judge.BestBeyondMidpoint() >= 0;
  }
  else
  {
    PlainJudge<FT> judge(tri, terms);
    k = ChooseExit(judge, view.Samples, excluded);
    beyond = k >= 0 && descending && judge.BestBeyondMidpoint() >= 0;
  }
  if (k < 0)
  {
    return false;
  }
  if (beyond)
  {
    throw Degenerate("descending walk reaches the driver of a non-Gabriel edge");
  }
  const Id best = view.Samples[static_cast<std::size_t>(k)];
  // The exit point y = c' + lambda' n' of V(u v s) is collinear with m and z in
  // the bisector plane of uv (normal e): ((y - m) x (z - m)).e = 0.
  exitSample = best;
  exitCell = view.Cells[static_cast<std::size_t>(k)];
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
