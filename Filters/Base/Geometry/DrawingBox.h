// Where drawn flow lines toward infinity stop. They pass through the Voronoi
// vertices of nearly flat cells at the hull, which can be arbitrarily far away
// (67,549 units for a torus 2.7 units wide), so ParaView's Reset Camera showed a
// dot. Lines to finite maxima need no box: the distance to the samples grows
// along a flow line, and a maximum is inside the hull, so they stay within the
// hull grown by its diagonal.
#ifndef flowrecon_DrawingBox_h
#define flowrecon_DrawingBox_h

#include "FlowComplex.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flowrecon
{

struct DrawingBox
{
  Point3 Lower{ { 0, 0, 0 } };
  Point3 Upper{ { 0, 0, 0 } };

  bool Contains(const Point3& p) const
  {
    for (int k = 0; k < 3; ++k)
    {
      if (!(p[k] >= this->Lower[k] && p[k] <= this->Upper[k]))
      {
        return false;
      }
    }
    return true;
  }
};

/// The length of the diagonal of the box [lo, hi]; the one place the samples'
/// scale is measured. Halves and hypot: no overflow even for coordinates near
/// the largest doubles.
inline double BoxDiagonal(const Point3& lo, const Point3& hi)
{
  return 2 * std::hypot(0.5 * hi[0] - 0.5 * lo[0], 0.5 * hi[1] - 0.5 * lo[1], 0.5 * hi[2] - 0.5 * lo[2]);
}

/// The diagonal of the samples' bounding box, from the index-0 nodes (the
/// distinct samples), so that it needs no geometry; 0 without nodes.
inline double SamplesDiagonal(const FlowComplex& fc)
{
  Point3 lo{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, hi{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (const Node& node : fc.Nodes)
  {
    for (int k = 0; node.Index == 0 && k < 3; ++k)
    {
      lo[k] = std::min(lo[k], node.Location[k]);
      hi[k] = std::max(hi[k], node.Location[k]);
    }
  }
  return hi[0] >= lo[0] ? BoxDiagonal(lo, hi) : 0;
}

/// What is drawn toward the maximum at infinity, in samples' diagonals: the flow
/// line of a hull facet (a ray, cut at this length; the drawing box's margin, so
/// that such stubs fit) and a Hasse-diagram arc (a short tick beside its node).
constexpr double RayStub = 0.25;
constexpr double ArcStub = 0.05;

/// The bounding box of points[0, n) grown on every side by `margin` times its
/// diagonal (the stub length of a hull facet's ray, so that stubs fit).
inline DrawingBox BoxAround(const std::vector<Point3>& points, Id n, double margin)
{
  DrawingBox box;
  if (n <= 0)
  {
    return box;
  }
  box.Lower = box.Upper = points[0];
  for (Id i = 1; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      box.Lower[k] = std::min(box.Lower[k], points[i][k]);
      box.Upper[k] = std::max(box.Upper[k], points[i][k]);
    }
  }
  const double d = margin * BoxDiagonal(box.Lower, box.Upper);
  for (int k = 0; k < 3; ++k)
  {
    box.Lower[k] -= d;
    box.Upper[k] += d;
  }
  return box;
}

/// Cuts a polyline that starts inside the box at its first exit: the segment
/// leaving the box ends on the box's face. Returns whether it was cut.
inline bool ClipPolyline(std::vector<Point3>& line, const DrawingBox& box)
{
  for (std::size_t i = 1; i < line.size(); ++i)
  {
    if (box.Contains(line[i]))
    {
      continue;
    }
    if (!box.Contains(line[i - 1]))
    {
      line.resize(i); // began outside: nothing to clip against
      return true;
    }
    // The largest s in [0, 1] with a + s (b - a) in the box.
    const Point3& a = line[i - 1];
    const Point3& b = line[i];
    double s = 1;
    for (int k = 0; k < 3; ++k)
    {
      const double step = b[k] - a[k];
      if (step > 0 && b[k] > box.Upper[k])
        s = std::min(s, (box.Upper[k] - a[k]) / step);
      else if (step < 0 && b[k] < box.Lower[k])
        s = std::min(s, (box.Lower[k] - a[k]) / step);
    }
    if (!(s >= 0)) // NaN coordinates: drop the rest
      s = 0;
    Point3 exit;
    for (int k = 0; k < 3; ++k)
    {
      exit[k] = std::min(box.Upper[k], std::max(box.Lower[k], a[k] + s * (b[k] - a[k])));
    }
    line.resize(i);
    line.push_back(exit);
    return true;
  }
  return false;
}

} // namespace flowrecon

#endif
