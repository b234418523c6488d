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
  double d = 0;
  for (int k = 0; k < 3; ++k)
  {
    d += (box.Upper[k] - box.Lower[k]) * (box.Upper[k] - box.Lower[k]);
  }
  d = margin * std::sqrt(d);
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
