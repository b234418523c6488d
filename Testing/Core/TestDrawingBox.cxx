// Flow lines toward infinity are drawn inside a box around the samples
// (DrawingBox.h): known answers for the box and the clipping, and on a cloud
// with nearly flat hull cells (far Voronoi vertices) every drawn line to
// infinity stays in the box while its target is kept.
#include "Check.h"
#include "DrawingBox.h"
#include "FlowComplexBuilder.h"

#include <cmath>
#include <random>

using flowrecon::Point3;

int main()
{
  // The box of the unit cube's corners grown by a quarter of sqrt(3).
  const std::vector<Point3> corners = { { { 0, 0, 0 } }, { { 1, 1, 1 } } };
  const flowrecon::DrawingBox box = flowrecon::BoxAround(corners, 2, 0.25);
  const double m = 0.25 * std::sqrt(3.0);
  CHECK_NEAR(box.Lower[0], -m, 1e-15);
  CHECK_NEAR(box.Upper[2], 1 + m, 1e-15);

  // Inside: unchanged. Leaving through x = 1 + m: cut on that face.
  std::vector<Point3> inside = { { { 0.5, 0.5, 0.5 } }, { { 0.9, 0.1, 0.2 } } };
  CHECK(!flowrecon::ClipPolyline(inside, box) && inside.size() == 2);
  std::vector<Point3> out = { { { 0.5, 0.5, 0.5 } }, { { 0.6, 0.5, 0.5 } }, { { 100.6, 0.5, 0.5 } },
    { { 0.5, 0.5, 0.5 } } };
  CHECK(flowrecon::ClipPolyline(out, box));
  CHECK(out.size() == 3);
  CHECK_NEAR(out[2][0], 1 + m, 1e-12);
  CHECK_NEAR(out[2][1], 0.5, 1e-12);

  // A torus-like ring with a little noise has thin hull cells whose Voronoi
  // vertices lie far away: the drawn lines to infinity reach them unclipped.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 2 * M_PI), e(-1e-3, 1e-3);
  std::vector<Point3> points;
  for (int i = 0; i < 1500; ++i)
  {
    const double a = u(rng), b = u(rng);
    points.push_back({ { (1 + 0.35 * std::cos(b)) * std::cos(a) + e(rng),
      (1 + 0.35 * std::cos(b)) * std::sin(a) + e(rng), 0.35 * std::sin(b) } });
  }
  flowrecon::BuildOptions options;
  options.StableManifolds = false;
  const flowrecon::FlowComplex fc = flowrecon::BuildFlowComplex(points, options, {});
  const flowrecon::DrawingBox around = flowrecon::BoxAround(points, 1500, 0.25);
  flowrecon::Id toInfinity = 0, outside = 0;
  for (const flowrecon::FlowLine& line : fc.FlowLines)
  {
    if (line.Target != fc.InfinityNode)
      continue;
    ++toInfinity;
    for (const Point3& p : line.Points)
    {
      Point3 q = p;
      for (int k = 0; k < 3; ++k) // rounding of the cut point
        q[k] = std::min(around.Upper[k], std::max(around.Lower[k], q[k]));
      outside += (std::fabs(q[0] - p[0]) + std::fabs(q[1] - p[1]) + std::fabs(q[2] - p[2]) > 1e-12) ? 1 : 0;
    }
  }
  CHECK(toInfinity > 0);
  CHECK(outside == 0);
  return check::Finish("TestDrawingBox");
}
