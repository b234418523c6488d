#include "InputPreparation.h"

#include "Delaunay.h"
#include "DrawingBox.h"
#include "Progress.h"

#include <CGAL/Spatial_sort_traits_adapter_3.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/property_map.h>

#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

namespace flowrecon
{

PreparedInput PrepareInput(const std::vector<Point3>& points)
{
  PreparedInput in;
  const Id n = static_cast<Id>(points.size());
  Point3 lo{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, hi{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (Id i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (!std::isfinite(points[i][k]))
      {
        throw InputError("point " + std::to_string(i) + " has a non-finite coordinate");
      }
      lo[k] = std::min(lo[k], points[i][k]);
      hi[k] = std::max(hi[k], points[i][k]);
    }
  }
  // Sort ids by coordinates so that equal points are adjacent; the first
  // occurrence (smallest id) represents the others.
  std::vector<Id> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Id(0));
  // The id breaks ties: a total order, so the parallel sort is deterministic.
  tbb::parallel_sort(order.begin(), order.end(),
    [&](Id a, Id b) { return points[a] < points[b] || (points[a] == points[b] && a < b); });
  in.Representative.assign(static_cast<std::size_t>(n), -1);
  for (std::size_t i = 0; i < order.size();)
  {
    std::size_t j = i;
    while (j < order.size() && points[order[j]] == points[order[i]])
    {
      in.Representative[order[j]] = order[i];
      ++j;
    }
    i = j;
  }
  // The distinct points in coordinate order, not in input order: the Hilbert
  // order breaks ties between equal coordinates (grids) by position, and the
  // perturbation of degenerate input goes by position, so any other order would
  // make the result depend on the order of the input lines.
  for (const Id i : order)
  {
    if (in.Representative[i] == i)
    {
      in.InputId.push_back(i);
      in.Unique.push_back(points[i]);
    }
  }
  if (in.Unique.size() < 4)
  {
    throw InputError("need at least 4 distinct points, got " + std::to_string(in.Unique.size()));
  }
  for (int k = 0; k < 3; ++k)
  {
    in.Centre[k] = 0.5 * lo[k] + 0.5 * hi[k]; // halves: no overflow near the largest doubles
  }
  in.Diagonal = BoxDiagonal(lo, hi);
  return in;
}

namespace
{
// SplitMix64: a tiny generator whose output is fixed by the standard, unlike
// std:: distributions.
std::uint64_t SplitMix(std::uint64_t& state)
{
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

/// Renumbers the distinct points along a Hilbert curve. Every per-vertex table
/// (adjacency, walks, node lists) is then visited with spatial locality, which
/// matters more than anything else for large clouds; hilbert_sort is
/// deterministic (unlike spatial_sort, which shuffles), also in parallel: the
/// median splits of disjoint ranges do not depend on the schedule.
void SpatialOrder(PreparedInput& in)
{
  std::vector<KPoint> pts;
  pts.reserve(in.Unique.size());
  for (const Point3& p : in.Unique)
  {
    pts.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::size_t> order(pts.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  using Map = CGAL::Pointer_property_map<KPoint>::const_type;
  const Map map = CGAL::make_property_map(static_cast<const std::vector<KPoint>&>(pts));
  CGAL::hilbert_sort<CGAL::Parallel_tag>(
    order.begin(), order.end(), CGAL::Spatial_sort_traits_adapter_3<Kernel, Map>(map));
  std::vector<Point3> unique(order.size());
  std::vector<Id> ids(order.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    unique[i] = in.Unique[order[i]];
    ids[i] = in.InputId[order[i]];
  }
  in.Unique.swap(unique);
  in.InputId.swap(ids);
}

} // namespace

PreparedInput PrepareForTriangulation(const std::vector<Point3>& points)
{
  PreparedInput in = PrepareInput(points);
  SpatialOrder(in);
  // A cloud far from the origin next to its extent (a georeferenced scan: 10^6
  // m away, 100 m wide) leaves the floating-point filters of the predicates
  // little precision, and nearly every test of a degenerate sample falls back
  // to exact arithmetic (the flow lines of a 2 * 10^4-point quantized terrain
  // took 30 times longer). An axis whose coordinates all lie in [lo, 2 lo]
  // (or [2 hi, hi] below 0) is moved by lo (hi), which is exact (Sterbenz):
  // the triangulated cloud is the input's, translated.
  Point3 lo{ { HUGE_VAL, HUGE_VAL, HUGE_VAL } }, hi{ { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (const Point3& p : in.Unique)
  {
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  for (int k = 0; k < 3; ++k)
  {
    in.Translation[k] = lo[k] > 0 && hi[k] <= 2 * lo[k] ? lo[k]
      : hi[k] < 0 && lo[k] >= 2 * hi[k]                  ? hi[k]
                                                          : 0.0;
  }
  if (in.Translation != Point3{ { 0, 0, 0 } })
  {
    for (Point3& p : in.Unique)
    {
      for (int k = 0; k < 3; ++k)
      {
        p[k] -= in.Translation[k];
      }
    }
  }
  // The constructions square and multiply coordinates, which would overflow or
  // underflow for clouds measured in units near 1e+-60 and beyond: work at
  // magnitudes about 1 (outputs are scaled back by the caller).
  double largest = 0;
  for (const Point3& p : in.Unique)
  {
    for (const double x : p)
    {
      largest = std::max(largest, std::fabs(x));
    }
  }
  in.ScaleExponent = largest > 0 ? std::ilogb(largest) : 0;
  lo = { { HUGE_VAL, HUGE_VAL, HUGE_VAL } };
  hi = { { -HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
  for (Point3& p : in.Unique)
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = std::ldexp(p[k], -in.ScaleExponent);
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  in.Diagonal = BoxDiagonal(lo, hi); // in scaled units
  return in;
}

double PerturbationMagnitude(const PreparedInput& in, int attempt)
{
  if (attempt <= 1)
  {
    return 0;
  }
  // Relative to the cloud size, never below a few ulps of the coordinates.
  // Degenerate configurations split their critical values only at second order
  // in the perturbation, so 1e-6 of the diagonal keeps those gaps (~1e-12) well
  // above double precision: values stay strictly ordered.
  double maxAbs = 0;
  for (const Point3& p : in.Unique)
  {
    for (const double x : p)
    {
      maxAbs = std::max(maxAbs, std::fabs(x));
    }
  }
  const double floor = 64 * std::numeric_limits<double>::epsilon() * maxAbs;
  return std::max(1e-6 * in.Diagonal * std::ldexp(1.0, attempt - 2), floor);
}

std::vector<Point3> AttemptCoordinates(const PreparedInput& in, int attempt, std::uint64_t seed)
{
  if (attempt <= 1)
  {
    return in.Unique;
  }
  return Perturb(in.Unique, PerturbationMagnitude(in, attempt), seed * 0x100000001B3ull + attempt);
}

std::vector<Point3> Perturb(const std::vector<Point3>& points, double magnitude, std::uint64_t seed)
{
  std::uint64_t state = seed;
  std::vector<Point3> out(points);
  for (Point3& p : out)
  {
    for (double& x : p)
    {
      const double u = static_cast<double>(SplitMix(state) >> 11) * 0x1.0p-53; // [0,1)
      x += magnitude * (2 * u - 1);
    }
  }
  return out;
}

} // namespace flowrecon
