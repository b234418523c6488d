#include "Driver.h"

#include "FastPredicates.h"
#include "Progress.h"

namespace flowrecon
{

int ObtuseCorner(const KPoint& a, const KPoint& b, const KPoint& c)
{
  const KPoint* p[3] = { &a, &b, &c };
  int obtuse = -1;
  for (int i = 0; i < 3; ++i)
  {
    const CGAL::Angle angle = CGAL::angle(*p[(i + 1) % 3], *p[i], *p[(i + 2) % 3]);
    if (angle == CGAL::RIGHT)
    {
      throw Degenerate("right triangle");
    }
    if (angle == CGAL::OBTUSE)
    {
      obtuse = i;
    }
  }
  return obtuse;
}

bool IsSelfCentred(CellHandle c)
{
  for (int i = 0; i < 4; ++i)
  {
    const CGAL::Bounded_side side = FastSideOfDiametralSphere(c->vertex((i + 1) % 4)->point(),
      c->vertex((i + 2) % 4)->point(), c->vertex((i + 3) % 4)->point(), c->vertex(i)->point());
    if (side == CGAL::ON_BOUNDARY)
    {
      throw Degenerate("circumcentre on a facet");
    }
    if (side != CGAL::ON_UNBOUNDED_SIDE)
    {
      return false;
    }
  }
  return true;
}

CellDriver ClassifyCell(CellHandle c)
{
  const KPoint* p[4];
  for (int i = 0; i < 4; ++i)
  {
    p[i] = &c->vertex(i)->point();
  }
  // Lemma B.2: c_T is inside T iff every vertex is outside the diametral sphere
  // of the opposite facet; Lemma B.3: a facet whose apex is inside is visible.
  CGAL::Bounded_side apexSide[4];
  bool selfCentred = true;
  for (int i = 0; i < 4; ++i)
  {
    apexSide[i] = FastSideOfDiametralSphere(*p[(i + 1) % 4], *p[(i + 2) % 4], *p[(i + 3) % 4], *p[i]);
    if (apexSide[i] == CGAL::ON_BOUNDARY)
    {
      throw Degenerate("circumcentre on a facet");
    }
    selfCentred = selfCentred && apexSide[i] == CGAL::ON_UNBOUNDED_SIDE;
  }
  CellDriver d;
  if (selfCentred)
  {
    return d;
  }
  // Lemma C: the driver is the midpoint of ab iff both other vertices are inside
  // the diametral sphere of ab.
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      int inside = 0;
      for (int k = 0; k < 4; ++k)
      {
        if (k == i || k == j)
        {
          continue;
        }
        // k is inside the ball of diameter ij iff the angle at k is obtuse.
        const CGAL::Angle angle = CGAL::angle(*p[i], *p[k], *p[j]);
        if (angle == CGAL::RIGHT)
        {
          throw Degenerate("right triangle");
        }
        inside += angle == CGAL::OBTUSE ? 1 : 0;
      }
      if (inside == 2)
      {
        d.Type = CellDriver::Edge;
        d.A = i;
        d.B = j;
        return d;
      }
    }
  }
  for (int i = 0; i < 4; ++i)
  {
    if (apexSide[i] == CGAL::ON_BOUNDED_SIDE &&
      ObtuseCorner(*p[(i + 1) % 4], *p[(i + 2) % 4], *p[(i + 3) % 4]) < 0)
    {
      d.Type = CellDriver::Facet;
      d.A = i;
      return d;
    }
  }
  throw Degenerate("cell driver not found");
}

} // namespace flowrecon
