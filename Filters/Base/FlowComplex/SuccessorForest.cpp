#include "SuccessorForest.h"

#include "VoronoiWalk.h"
#include "Driver.h"
#include "DrawingBox.h"
#include "ParallelSlices.h"
#include "Progress.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace flowrecon
{

namespace
{

Point3 Along(const Point3& from, Point3 dir, double length)
{
  const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  if (!(n > 0) || !std::isfinite(n))
  {
    return from;
  }
  return Point3{ { from[0] + dir[0] / n * length, from[1] + dir[1] / n * length,
    from[2] + dir[2] / n * length } };
}

/// Result of a walk across Voronoi facets started at a Voronoi vertex.
struct WalkEnd
{
  Id Cell = -1;          // cell whose Voronoi vertex is reached, or -1 for infinity
  std::vector<Point3> Points; // exit points met on the way
  Point3 Escape{ { 0, 0, 0 } }; // direction to infinity when Cell == -1
};

// FACET_WALK of §5.2: x lies in V(ab) and moves radially away from m_ab until a
// link sample becomes equidistant; then either slides along the Voronoi edge of
// an acute triangle to a Voronoi vertex, or continues in another Voronoi facet.
template <class FT>
WalkEnd FacetWalk(const Triangulation& tri, EdgePoint<FT> x, Id a, Id b, std::vector<Id> excl,
  CellHandle hint, bool record, double scale)
{
  WalkEnd end;
  for (Id steps = 0;; ++steps)
  {
    if (steps > 4 * tri.NumberOfCells() + 16)
    {
      throw std::runtime_error("ascending walk did not terminate");
    }
    Id s = -1;
    EdgePoint<FT> y;
    CellHandle cell;
    if (!FirstExit(tri, x, a, b, excl, false, hint, s, y, cell))
    {
      // Unbounded Voronoi facet: the flow goes to infinity, away from m_ab.
      if (!record)
      {
        return end;
      }
      const Point3 p = Frame<FT>(tri, x.G).At(x.Lambda).ToDouble();
      const Point3 &pa = tri.Coord(a), &pb = tri.Coord(b);
      end.Escape = { { p[0] - 0.5 * (pa[0] + pb[0]), p[1] - 0.5 * (pa[1] + pb[1]),
        p[2] - 0.5 * (pa[2] + pb[2]) } };
      return end;
    }
    if (record) // the polyline only; the walk needs no coordinates
    {
      end.Points.push_back(DrawnPoint(CachedFrame<FT>(tri, y.G).At(y.Lambda), scale));
    }
    const int obtuse = ObtuseCorner(tri.KCoord(a), tri.KCoord(b), tri.KCoord(s));
    if (obtuse == 2)
    {
      throw Degenerate("ascending walk exits through a triangle obtuse at the new sample");
    }
    if (obtuse >= 0)
    {
      // Obtuse at b (resp. a): the driver is the midpoint of a s (resp. b s).
      excl.assign(1, obtuse == 1 ? b : a);
      (obtuse == 1 ? b : a) = s;
      x = y;
      hint = cell;
      continue;
    }
    // abs is acute: slide along its Voronoi edge away from c_abs, i.e. along
    // sign(lambda) n, to the Voronoi vertex of the cell whose apex lies ahead.
    const int side = CertainSign(y.Lambda);
    if (side == 0)
    {
      throw Degenerate("ascending walk stops at a critical point");
    }
    const int opposite =
      6 - cell->index(tri.Vertex(a)) - cell->index(tri.Vertex(b)) - cell->index(tri.Vertex(s));
    const CellHandle sides[2] = { cell, cell->neighbor(opposite) };
    const VertexHandle apex[2] = { cell->vertex(opposite),
      sides[1]->vertex(sides[1]->index(cell)) };
    for (int k = 0; k < 2; ++k)
    {
      if (tri.Dt().is_infinite(apex[k]))
      {
        continue;
      }
      // sign(n . (t - g0)) is an exact orientation test on input points.
      const int o = static_cast<int>(CGAL::orientation(tri.KCoord(y.G[0]), tri.KCoord(y.G[1]),
        tri.KCoord(y.G[2]), apex[k]->point()));
      if (o * side > 0)
      {
        end.Cell = tri.CellId(sides[k]);
        return end;
      }
    }
    // No finite apex ahead: the Voronoi edge is a ray to infinity.
    const Point3 n = CachedFrame<FT>(tri, y.G).N.ToDouble();
    end.Escape = { { side * n[0], side * n[1], side * n[2] } };
    return end;
  }
}

} // namespace

std::array<CellHandle, 2> FlowLineSides(const Triangulation& tri, Id cell, int opposite)
{
  const CellHandle c = tri.Cell(cell);
  std::array<CellHandle, 2> sides{ { c, c->neighbor(opposite) } };
  const VertexHandle a0 = c->vertex(opposite);
  const VertexHandle a1 = sides[1]->vertex(sides[1]->index(c));
  const bool i0 = tri.Dt().is_infinite(a0), i1 = tri.Dt().is_infinite(a1);
  if (std::make_pair(i1, i1 ? Id(0) : a1->info()) < std::make_pair(i0, i0 ? Id(0) : a0->info()))
  {
    std::swap(sides[0], sides[1]);
  }
  return sides;
}

SuccessorForest::SuccessorForest(const Triangulation& tri,
  const std::vector<std::int32_t>& maximumOfCell, Id infinity, double stub, bool record,
  bool exactOnly)
  : Tri(tri)
  , MaximumOfCell(maximumOfCell)
  , Infinity(infinity)
  , Stub(stub)
  , Record(record)
  , ExactOnly(exactOnly)
  , Steps(record ? static_cast<std::size_t>(tri.NumberOfCells()) : 0)
  , Roots(static_cast<std::size_t>(tri.NumberOfCells()))
  , FellBack(static_cast<std::size_t>(tri.NumberOfCells()))
{
  for (auto& f : this->FellBack)
  {
    f.store(0, std::memory_order_relaxed);
  }
  for (auto& r : this->Roots)
  {
    r.store(-1, std::memory_order_relaxed);
  }
}

Id SuccessorForest::ExactFallbacks() const
{
  Id count = 0;
  for (const auto& f : this->FellBack)
  {
    count += f.load(std::memory_order_relaxed);
  }
  return count;
}

namespace
{

/// The circumcentre of a finite cell as P + Num / Den in doubles, P its vertex
/// of least id (so that rounding does not depend on the cell's vertex order).
struct CircumOffset
{
  Point3 P;
  Kernel::Vector_3 Num;
  double Den, LongestEdge;
};

CircumOffset OffsetOf(const Triangulation& tri, Id cell)
{
  const std::array<Id, 4> v = tri.SortedVertices(tri.Cell(cell));
  const KPoint& p = tri.KCoord(v[0]);
  const Kernel::Vector_3 a = tri.KCoord(v[1]) - p, b = tri.KCoord(v[2]) - p, c = tri.KCoord(v[3]) - p;
  return CircumOffset{ { { p.x(), p.y(), p.z() } },
    a.squared_length() * CGAL::cross_product(b, c) + b.squared_length() * CGAL::cross_product(c, a) +
      c.squared_length() * CGAL::cross_product(a, b),
    2 * CGAL::determinant(a, b, c),
    std::sqrt(std::max({ a.squared_length(), b.squared_length(), c.squared_length() })) };
}

} // namespace

Point3 SuccessorForest::CircumcentreOf(Id cell) const
{
  // In doubles, for drawing only (the flow lines' targets are exact). A flat
  // cell can cancel the denominator to 0 (found by fuzzing: CGAL's own
  // construction asserts then): its point is left out of the polyline, as
  // non-finite points are (see the builder).
  const CircumOffset o = OffsetOf(this->Tri, cell);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return o.Den != 0 && std::isfinite(o.Den)
    ? Point3{ { o.P[0] + o.Num.x() / o.Den, o.P[1] + o.Num.y() / o.Den, o.P[2] + o.Num.z() / o.Den } }
    : Point3{ { nan, nan, nan } };
}

Point3 SuccessorForest::Circumcentre(Id cell)
{
  if (this->Centres.empty())
  {
    this->Centres.resize(this->Roots.size());
    this->HasCentre.assign(this->Roots.size(), false);
  }
  if (!this->HasCentre[cell])
  {
    this->Centres[cell] = this->CircumcentreOf(cell);
    this->HasCentre[cell] = true;
  }
  return this->Centres[cell];
}

void SuccessorForest::PrecomputeSteps(
  const std::vector<Id>& starts, const Progress& progress, double from, double to)
{
  if (!this->Record)
  {
    throw std::logic_error("PrecomputeSteps is for forests that record polylines");
  }
  const std::size_t slots = static_cast<std::size_t>(tbb::this_task_arena::max_concurrency());
  if (slots > std::numeric_limits<std::uint16_t>::max())
  {
    throw std::logic_error("too many threads for the flow-line buffers");
  }
  if (this->Paths.size() < slots)
  {
    this->Paths.resize(slots);
  }
  // 0: free, 1: claimed. A chain stops at a cell another thread claimed: that
  // thread follows the rest of it.
  std::vector<std::atomic<std::int8_t>> claimed(this->Steps.size());
  for (std::size_t c = 0; c < claimed.size(); ++c)
  {
    claimed[c].store(this->Steps[c].Kind == Unknown ? 0 : 1, std::memory_order_relaxed);
  }
  const Id n = static_cast<Id>(starts.size());
  ParallelSlices(n, Id(1) << 16, progress, from, to, "unstable manifolds", [&](Id first, Id last) {
    const std::size_t buffer = static_cast<std::size_t>(tbb::this_task_arena::current_thread_index());
    for (Id k = first; k < last; ++k)
    {
      Id id = starts[k];
      for (std::size_t guard = 0; guard <= this->Steps.size(); ++guard)
      {
        std::int8_t expected = 0;
        if (!claimed[id].compare_exchange_strong(expected, 1, std::memory_order_relaxed))
        {
          break;
        }
        // Only this thread writes Steps[id]; readers come after the loop.
        const Step step = this->ComputeNext(id, buffer);
        this->Steps[id] = step;
        if (step.Kind != ToCell)
        {
          break;
        }
        id = step.Target;
      }
    }
  });
}

const SuccessorForest::Step& SuccessorForest::Next(Id cell)
{
  Step& step = this->Steps[cell];
  if (step.Kind == Unknown)
  {
    step = this->ComputeNext(cell);
  }
  return step;
}

SuccessorForest::Step SuccessorForest::ComputeNext(Id id, std::size_t buffer)
{
  if (this->Record && this->Paths.empty())
  {
    this->Paths.resize(1);
  }
  std::vector<Point3>* paths = this->Record ? &this->Paths[buffer] : nullptr;
  if (paths && paths->size() >= std::numeric_limits<std::uint32_t>::max())
  {
    throw std::runtime_error("too many unstable-manifold points to record");
  }
  Step step;
  step.Buffer = static_cast<std::uint16_t>(buffer);
  step.PathBegin = paths ? static_cast<std::uint32_t>(paths->size()) : 0;
  if (this->MaximumOfCell[id] >= 0)
  {
    step.Kind = ToMaximum;
    step.Target = static_cast<std::int32_t>(this->MaximumOfCell[id]);
    return step;
  }
  const CellHandle c = this->Tri.Cell(id);
  const CellDriver driver = ClassifyCell(c);
  if (driver.Type == CellDriver::Facet)
  {
    // The facet is visible from c_T: the flow slides along its Voronoi edge.
    const CellHandle next = c->neighbor(driver.A);
    if (this->Tri.Dt().is_infinite(next))
    {
      // The hull facet's vertices in id order, so that rounding is canonical.
      std::array<Id, 3> f{ { c->vertex((driver.A + 1) % 4)->info(),
        c->vertex((driver.A + 2) % 4)->info(), c->vertex((driver.A + 3) % 4)->info() } };
      std::sort(f.begin(), f.end());
      const KPoint& apex = c->vertex(driver.A)->point();
      const KPoint& p = this->Tri.KCoord(f[0]);
      const KPoint& q = this->Tri.KCoord(f[1]);
      const KPoint& r = this->Tri.KCoord(f[2]);
      Kernel::Vector_3 n = CGAL::cross_product(q - p, r - p);
      if (n * (apex - p) > 0)
      {
        n = -n;
      }
      step.Kind = ToInfinity;
      step.Target = static_cast<std::int32_t>(this->Infinity);
      if (paths)
      {
        paths->push_back(Along(this->CircumcentreOf(id), { { n.x(), n.y(), n.z() } }, this->Stub));
        step.PathCount = 1;
      }
      return step;
    }
    step.Kind = ToCell;
    step.Target = static_cast<std::int32_t>(this->Tri.CellId(next));
    return step;
  }
  if (driver.Type == CellDriver::Cell)
  {
    throw std::logic_error("self-centred cell without a maximum");
  }
  const Id a = c->vertex(driver.A)->info();
  const Id b = c->vertex(driver.B)->info();
  std::vector<Id> excl;
  for (int k = 0; k < 4; ++k)
  {
    if (k != driver.A && k != driver.B)
    {
      excl.push_back(c->vertex(k)->info());
    }
  }
  // c_T is written on the Voronoi edge of (a, b, min excl): a choice that does
  // not depend on the order of vertices inside the cell (rounding would).
  std::sort(excl.begin(), excl.end());
  const std::array<Id, 4> vertices = this->Tri.SortedVertices(c);
  Id fallbacks = 0;
  WalkEnd end = Filtered(
    [&](auto ft) {
      using FT = decltype(ft);
      // c_T lies on the Voronoi edge of (a, b, excl[0]): find its lambda there.
      EdgePoint<FT> start{ SortedTriangle(a, b, excl[0]), FT(0) };
      const Frame<FT> frame(this->Tri, start.G);
      auto P = [&](int i) { return Vec<FT>::From(this->Tri.Coord(vertices[i])); };
      const Vec<FT> centre = Circumcenter(P(0), P(1), P(2), P(3));
      start.Lambda = (centre - frame.C).Dot(frame.N) / frame.N.SquaredLength();
      return FacetWalk<FT>(this->Tri, start, a, b, excl, c, this->Record, this->Stub / RayStub);
    },
    fallbacks, this->ExactOnly);
  if (fallbacks > 0)
  {
    this->FellBack[id].store(1, std::memory_order_relaxed);
  }
  if (!this->Record)
  {
    step.Kind = end.Cell < 0 ? ToInfinity : ToCell;
    step.Target = static_cast<std::int32_t>(end.Cell < 0 ? this->Infinity : end.Cell);
    return step;
  }
  paths->insert(paths->end(), end.Points.begin(), end.Points.end());
  if (end.Cell < 0)
  {
    const Point3 from = end.Points.empty() ? this->CircumcentreOf(id) : end.Points.back();
    paths->push_back(Along(from, end.Escape, this->Stub));
    step.Kind = ToInfinity;
    step.Target = static_cast<std::int32_t>(this->Infinity);
  }
  else
  {
    step.Kind = ToCell;
    step.Target = static_cast<std::int32_t>(end.Cell);
  }
  step.PathCount = static_cast<std::uint32_t>(paths->size() - step.PathBegin);
  return step;
}

Id SuccessorForest::Root(Id cell)
{
  return this->RootBelow(cell, HUGE_VAL, nullptr);
}

Id SuccessorForest::RootBelow(Id cell, double limitSq, double* boundSq, Id* stopCell)
{
  // Without recording, NEXT is not walked twice: the chain stops at the first
  // cell whose ROOT is known, and a stopped chain leaves its NEXTs behind.
  // Threads racing on one chain compute the same values.
  std::vector<Id> chain;
  Id id = cell;
  Id root = -1;
  while (true)
  {
    const std::int32_t known = this->Roots[id].load(std::memory_order_relaxed);
    if (known >= 0)
    {
      root = known;
      break;
    }
    if (chain.size() > this->Roots.size())
    {
      throw std::logic_error("the successor structure has a cycle");
    }
    // Which lines stop can depend on the roots other threads found first (a
    // known root is used): the counts may vary, the arcs and output do not.
    if (limitSq < HUGE_VAL && this->MaximumOfCell[id] < 0)
    {
      const double r2 = this->SquaredRadiusAtLeast(id);
      if (r2 >= limitSq)
      {
        *boundSq = r2;
        if (stopCell)
        {
          *stopCell = id;
        }
        return Pending;
      }
    }
    chain.push_back(id);
    if (known <= -2)
    {
      id = -2 - known;
      continue;
    }
    const Step step = this->Record ? this->Next(id) : this->ComputeNext(id);
    if (step.Kind != ToCell)
    {
      root = step.Target;
      break;
    }
    this->Roots[id].store(-2 - step.Target, std::memory_order_relaxed);
    id = step.Target;
  }
  for (const Id c : chain)
  {
    this->Roots[c].store(static_cast<std::int32_t>(root), std::memory_order_relaxed);
  }
  return root;
}

double SuccessorForest::SquaredRadiusAtLeast(Id cell) const
{
  const CircumOffset o = OffsetOf(this->Tri, cell);
  const double l = o.LongestEdge, den = std::abs(o.Den);
  const double r = std::sqrt(o.Num.squared_length()) / den;
  // Rounding of the offset Num/Den from P (the radius): about 70 eps l^4 in
  // Num and 40 eps l^3 in Den, first order; four times that is the margin.
  const double eps = std::numeric_limits<double>::epsilon();
  const double error = (300 * eps * l * l * l * l + 160 * eps * l * l * l * r) / den;
  if (!(den != 0) || !std::isfinite(r) || !std::isfinite(error) || !(error < 0.25 * r))
  {
    return 0;
  }
  const double low = (r - error) * (1 - 8 * eps);
  return low * low * (1 - 8 * eps);
}

void SuccessorForest::AppendPath(Id cell, std::vector<Point3>& out, bool shareTails)
{
  if (!this->Record)
  {
    throw std::logic_error("AppendPath needs a forest that records polylines");
  }
  if (this->Drawn.empty())
  {
    this->Drawn.assign(this->Roots.size(), false);
  }
  Id id = cell;
  for (std::size_t guard = 0; guard <= this->Roots.size(); ++guard)
  {
    if (shareTails)
    {
      if (this->Drawn[id])
      {
        return; // the rest of this flow line is already drawn
      }
      this->Drawn[id] = true;
    }
    const Step& step = this->Next(id);
    const std::vector<Point3>& paths = this->Paths[step.Buffer];
    out.insert(out.end(), paths.begin() + step.PathBegin,
      paths.begin() + step.PathBegin + step.PathCount);
    if (step.Kind == ToMaximum || step.Kind == ToInfinity)
    {
      return; // c_T of a maximum is already in the polyline
    }
    id = step.Target;
    out.push_back(this->Circumcentre(id));
  }
  throw std::logic_error("the successor structure has a cycle");
}

} // namespace flowrecon
