// Samples apart from the rest of the cloud: outliers of a scan, or a region
// sampled far more sparsely than the others. The reconstruction grows through
// them like through any sample, so a few stray points inside a closed surface
// can fill it into a solid; the topology profile then looks like a volume
// sample's, and no window warns. Measured on the Gabriel edges (the index-1
// nodes), which the flow complex has anyway: no neighbour search.
#ifndef flowrecon_FarSamples_h
#define flowrecon_FarSamples_h

#include "FlowComplex.h"

#include <vector>

namespace flowrecon
{

struct FarSamples
{
  Id Count = 0;        ///< samples whose nearest sample is over the factor
  double Median = 0;   ///< the median nearest-sample distance, halved (a node value)
  double Largest = 0;  ///< the largest nearest-sample distance over the median
  Point3 Farthest{ { 0, 0, 0 } }; ///< the sample of the largest
};

/// Counts the samples whose nearest sample is over `factor` times the median
/// nearest-sample distance away. A sample's shortest Gabriel edge joins it to
/// its nearest sample (no sample can lie in that edge's diametral ball), so
/// the index-1 nodes give every distance. Two stray samples close together
/// hide each other; strays a few spacings from the surface are noise, not
/// counted. `nodes`: a flow complex's (index-0 nodes give the places) over
/// `samples` input points; ids outside 0..samples-1 (a damaged file) are
/// passed over.
FarSamples FindFarSamples(const std::vector<Node>& nodes, Id samples, double factor);

} // namespace flowrecon

#endif
