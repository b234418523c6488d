// How flat a cloud is around its samples: what tells a sample of a surface
// from a sample of a volume without reconstructing anything. A reconstruction
// whose answer is a solid (no void) while the samples lie on a surface has
// filled that surface in (AutomaticThresholds.h, Filled).
#ifndef flowrecon_LocalFlatness_h
#define flowrecon_LocalFlatness_h

#include "FlowComplex.h"

#include <array>
#include <cstddef>
#include <vector>

namespace flowrecon
{

/// One neighbourhood size of the flatness test and what a volume gives there:
/// the median lambda_min / lambda_mid of `K` nearest samples around interior
/// samples of a uniform i.i.d. volume sample (small neighbourhoods of a
/// volume are far from isotropic, so each size has its own reference).
struct FlatnessScale
{
  int K;
  double Volume;
};

/// The sizes tried, 10, 30 and 100 samples: a surface sample is flat at the
/// spacing, a noisy one only over a neighbourhood several times its noise, a
/// thin tube only under its diameter. The volume medians were measured on
/// 4 000 interior probes of 2·10^5 uniform points (Data/EXPERIMENTS.md).
const std::array<FlatnessScale, 3>& FlatnessScales();

/// The median, over up to `probes` samples spread evenly over `points` (every
/// n/probes-th), of lambda_min / lambda_mid, the two smallest eigenvalues of
/// the covariance of the probe's `k` nearest samples (the probe included):
/// near 0 where the samples lie on a surface or a curve, 0.6-0.8 inside a
/// volume sampled uniformly (k 30); 0 for a neighbourhood on one line, and a
/// neighbourhood that is one place (duplicates) is left out. 1 for fewer than
/// k + 1 points.
double MedianFlatness(const std::vector<Point3>& points, int k = 30, std::size_t probes = 2000);

/// MedianFlatness for several neighbourhood sizes at once (one search per
/// probe, for the largest): entry i for ks[i], 1 where the cloud is too small.
std::vector<double> MedianFlatness(
  const std::vector<Point3>& points, const std::vector<int>& ks, std::size_t probes = 2000);

/// The smallest, over the FlatnessScales whose K is at most a twentieth of
/// the cloud (a larger neighbourhood sees the shape's extent, not its local
/// dimension), of MedianFlatness at K over the volume's median there: about 1
/// or more for a volume sample, near 0 for a surface's or a curve's at some
/// scale. 1 when the cloud is too small for any scale.
double RelativeFlatness(const std::vector<Point3>& points, std::size_t probes = 2000);

/// The fewest points RelativeFlatness measures (twenty times the smallest
/// scale's K): below, it cannot tell a surface's sample from a volume's.
std::size_t FlatnessMinimumPoints();

} // namespace flowrecon

#endif
