#include "SuccessorForest.h"

#include "Arithmetic.h"
#include "Driver.h"
#include "Progress.h"

#include <cmath>
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
WalkEnd FacetWalk(const Triangulation& tri, const Vec<FT>& start, Id a, Id b, std::vector<Id> excl)
{
  auto P = [&](Id k) { return Vec<FT>::From(tri.Coord(k)); };
  const Delaunay& dt = tri.Dt();
  WalkEnd end;
  Vec<FT> x = start;
  std::vector<Id> link;
  for (Id steps = 0;; ++steps)
  {
    if (steps > 4 * tri.NumberOfCells() + 16)
    {
      throw std::runtime_error("ascending walk did not terminate");
    }
    const Vec<FT> pa = P(a);
    const Vec<FT> w = x - (pa + P(b)) / FT(2);
    const FT xa = (x - pa).SquaredLength();
    link.clear();
    tri.Link(a, b, link);
    Id best = -1;
    FT bestNum(0), bestDen(1);
    for (const Id s : link)
    {
      bool excluded = false;
      for (const Id e : excl)
      {
        excluded = excluded || e == s;
      }
      if (excluded)
      {
        continue;
      }
      const Vec<FT> ps = P(s);
      const FT den = w.Dot(ps - pa);
      if (CertainSign(den) <= 0)
      {
        continue;
      }
      const FT num = (x - ps).SquaredLength() - xa;
      if (CertainSign(num) <= 0)
      {
        throw Degenerate("ascending walk starts on a degenerate Voronoi vertex");
      }
      if (best >= 0)
      {
        const int cmp = CertainSign(num * bestDen - bestNum * den);
        if (cmp == 0)
        {
          throw Degenerate("ascending walk meets a Voronoi vertex");
        }
        if (cmp > 0)
        {
          continue;
        }
      }
      best = s;
      bestNum = num;
      bestDen = den;
    }
    if (best < 0)
    {
      end.Escape = w.ToDouble(); // unbounded Voronoi facet
      return end;
    }
    const Vec<FT> y = x + w * (bestNum / (FT(2) * bestDen));
    end.Points.push_back(y.ToDouble());
    const Id s = best;
    const int obtuse = ObtuseCorner(tri.KCoord(a), tri.KCoord(b), tri.KCoord(s));
    if (obtuse == 2)
    {
      throw Degenerate("ascending walk exits through a triangle obtuse at the new sample");
    }
    if (obtuse == 1) // obtuse at b: driver is the midpoint of a s
    {
      excl.assign(1, b);
      b = s;
      x = y;
      continue;
    }
    if (obtuse == 0) // obtuse at a: driver is the midpoint of b s
    {
      excl.assign(1, a);
      a = s;
      x = y;
      continue;
    }
    // abs is acute: slide along its Voronoi edge away from c_abs to the Voronoi
    // vertex of the cell on that side (the apex t with w'.(t - a) > 0).
    CellHandle cell;
    int opposite = 0;
    if (!tri.Facet(a, b, s, cell, opposite))
    {
      throw std::runtime_error("ascending walk lost its Voronoi edge");
    }
    const Vec<FT> w2 = y - Circumcenter(pa, P(b), P(s));
    const CellHandle sides[2] = { cell, cell->neighbor(opposite) };
    const VertexHandle apex[2] = { cell->vertex(opposite),
      sides[1]->vertex(sides[1]->index(cell)) };
    for (int k = 0; k < 2; ++k)
    {
      // Exactly one apex lies ahead (they are on opposite sides of the plane).
      const int ahead = dt.is_infinite(apex[k])
        ? -1
        : CertainSign(w2.Dot(P(apex[k]->info()) - pa));
      if (ahead == 0)
      {
        throw Degenerate("ascending walk stops at a critical point");
      }
      if (ahead > 0)
      {
        end.Cell = tri.CellId(sides[k]);
        return end;
      }
    }
    // No finite apex ahead: the Voronoi edge is a ray to infinity.
    end.Escape = w2.ToDouble();
    return end;
  }
}

} // namespace

SuccessorForest::SuccessorForest(
  const Triangulation& tri, const std::vector<Id>& maximumOfCell, Id infinity, double stub)
  : Tri(tri)
  , MaximumOfCell(maximumOfCell)
  , Infinity(infinity)
  , Stub(stub)
  , Steps(static_cast<std::size_t>(tri.NumberOfCells()))
  , Roots(static_cast<std::size_t>(tri.NumberOfCells()), -1)
{
}

Point3 SuccessorForest::Circumcentre(Id cell) const
{
  const CellHandle c = this->Tri.Cell(cell);
  return Certified<3>([&](auto ft) {
    using FT = decltype(ft);
    auto P = [&](int i) { return Vec<FT>::From(this->Tri.Coord(c->vertex(i)->info())); };
    const Vec<FT> o = Circumcenter(P(0), P(1), P(2), P(3));
    return std::array<FT, 3>{ { o.X, o.Y, o.Z } };
  });
}

const SuccessorForest::Step& SuccessorForest::Next(Id cell)
{
  Step& step = this->Steps[cell];
  if (step.Kind == Unknown)
  {
    this->ComputeNext(cell, step);
  }
  return step;
}

void SuccessorForest::ComputeNext(Id id, Step& step)
{
  step.PathBegin = static_cast<std::int64_t>(this->Paths.size());
  if (this->MaximumOfCell[id] >= 0)
  {
    step.Kind = ToMaximum;
    step.Target = this->MaximumOfCell[id];
    return;
  }
  const CellHandle c = this->Tri.Cell(id);
  const CellDriver driver = ClassifyCell(c);
  if (driver.Type == CellDriver::Facet)
  {
    // The facet is visible from c_T: the flow slides along its Voronoi edge.
    const CellHandle next = c->neighbor(driver.A);
    if (this->Tri.Dt().is_infinite(next))
    {
      const KPoint& apex = c->vertex(driver.A)->point();
      const KPoint& p = c->vertex((driver.A + 1) % 4)->point();
      const KPoint& q = c->vertex((driver.A + 2) % 4)->point();
      const KPoint& r = c->vertex((driver.A + 3) % 4)->point();
      Kernel::Vector_3 n = CGAL::cross_product(q - p, r - p);
      if (n * (apex - p) > 0)
      {
        n = -n;
      }
      step.Kind = ToInfinity;
      step.Target = this->Infinity;
      this->Paths.push_back(Along(this->Circumcentre(id), { { n.x(), n.y(), n.z() } }, this->Stub));
      step.PathCount = 1;
      return;
    }
    step.Kind = ToCell;
    step.Target = this->Tri.CellId(next);
    return;
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
  WalkEnd end = Filtered(
    [&](auto ft) {
      using FT = decltype(ft);
      auto P = [&](int i) { return Vec<FT>::From(this->Tri.Coord(c->vertex(i)->info())); };
      return FacetWalk<FT>(this->Tri, Circumcenter(P(0), P(1), P(2), P(3)), a, b, excl);
    },
    this->ExactFallbacks);
  this->Paths.insert(this->Paths.end(), end.Points.begin(), end.Points.end());
  if (end.Cell < 0)
  {
    const Point3 from = end.Points.empty() ? this->Circumcentre(id) : end.Points.back();
    this->Paths.push_back(Along(from, end.Escape, this->Stub));
    step.Kind = ToInfinity;
    step.Target = this->Infinity;
  }
  else
  {
    step.Kind = ToCell;
    step.Target = end.Cell;
  }
  step.PathCount = static_cast<std::uint32_t>(this->Paths.size() - step.PathBegin);
}

Id SuccessorForest::Root(Id cell)
{
  std::vector<Id> chain;
  Id id = cell;
  while (this->Roots[id] < 0)
  {
    if (chain.size() > this->Steps.size())
    {
      throw std::logic_error("the successor structure has a cycle");
    }
    chain.push_back(id);
    const Step& step = this->Next(id);
    if (step.Kind != ToCell)
    {
      this->Roots[id] = step.Target;
      break;
    }
    id = step.Target;
  }
  const Id root = this->Roots[id];
  for (const Id c : chain)
  {
    this->Roots[c] = root;
  }
  return root;
}

void SuccessorForest::AppendPath(Id cell, std::vector<Point3>& out)
{
  Id id = cell;
  for (std::size_t guard = 0; guard <= this->Steps.size(); ++guard)
  {
    const Step& step = this->Next(id);
    out.insert(out.end(), this->Paths.begin() + step.PathBegin,
      this->Paths.begin() + step.PathBegin + step.PathCount);
    if (step.Kind == ToMaximum)
    {
      return; // c_T is the maximum itself, already in the polyline
    }
    if (step.Kind == ToInfinity)
    {
      return;
    }
    id = step.Target;
    out.push_back(this->Circumcentre(id));
  }
  throw std::logic_error("the successor structure has a cycle");
}

} // namespace flowrecon
