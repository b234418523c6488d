// How flat a cloud is around its samples: what tells a sample of a surface
// from a sample of a volume without reconstructing anything. A reconstruction
// whose answer is a solid (no void) while the samples lie on a surface has
// filled that surface in (AutomaticThresholds.h, Filled).
#ifndef flowrecon_LocalFlatness_h
#define flowrecon_LocalFlatness_h

#include "FlowComplex.h"

#include <cstddef>
#include <vector>

namespace flowrecon
{

/// The median, over up to `probes` samples spread evenly over `points` (every
/// n/probes-th), of lambda_min / lambda_mid, the two smallest eigenvalues of
/// the covariance of the probe's `k` nearest samples: near 0 where the
/// samples lie on a surface or a curve, 0.6-0.8 inside a volume sampled
/// uniformly. 1 for fewer than k + 1 points.
double MedianFlatness(const std::vector<Point3>& points, int k = 30, std::size_t probes = 2000);

} // namespace flowrecon

#endif
