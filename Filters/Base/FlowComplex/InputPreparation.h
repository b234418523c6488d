// Turning raw samples into triangulation input: validation, merging of
// duplicate points, and the deterministic perturbation used when the input is
// not in general position (docs/algorithm.md §2.3).
#ifndef flowrecon_InputPreparation_h
#define flowrecon_InputPreparation_h

#include "FlowComplex.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace flowrecon
{

struct PreparedInput
{
  std::vector<Point3> Unique;  ///< distinct points, in coordinate (lexicographic) order
  std::vector<Id> InputId;     ///< input id of each unique point
  std::vector<Id> Representative; ///< per input point: the input id standing for it
  double Diagonal = 0;         ///< bounding-box diagonal (BuildFlowComplex rescales it with Unique)
  Point3 Centre{ { 0, 0, 0 } };
  /// Unique and Diagonal are in units of 2^ScaleExponent, Unique moved by
  /// -Translation first (see PrepareForTriangulation): a point of the cloud is
  /// ldexp(u, ScaleExponent) + Translation.
  int ScaleExponent = 0;
  Point3 Translation{ { 0, 0, 0 } };

  /// A point of the triangulation's frame in the cloud's.
  Point3 BackScaled(Point3 p) const
  {
    for (int k = 0; k < 3; ++k)
    {
      p[k] = std::ldexp(p[k], this->ScaleExponent);
      if (this->Translation[k] != 0)
      {
        p[k] += this->Translation[k]; // not when 0: -0 + 0 would be +0
      }
    }
    return p;
  }
};

/// Checks coordinates (finite), merges exact duplicates and requires at least 4
/// distinct points. Throws InputError with a one-line message.
PreparedInput PrepareInput(const std::vector<Point3>& points);

/// PrepareInput, then the distinct points renumbered along a Hilbert curve,
/// moved next to the origin where that is exact, and scaled by a power of two
/// (exact) to magnitudes about 1: what every attempt of the builder
/// triangulates, and what a later stage recomputes from the same samples
/// (geometry on demand), so both must come from this one function.
PreparedInput PrepareForTriangulation(const std::vector<Point3>& points);

/// The coordinates triangulated by attempt `attempt` (1: the points themselves;
/// later ones: perturbed by PerturbationMagnitude(in, attempt), in scaled units).
std::vector<Point3> AttemptCoordinates(const PreparedInput& in, int attempt, std::uint64_t seed);
double PerturbationMagnitude(const PreparedInput& in, int attempt);

/// `points` moved by a pseudo-random amount of at most `magnitude` per coordinate;
/// the same seed always gives the same result on every platform.
std::vector<Point3> Perturb(const std::vector<Point3>& points, double magnitude, std::uint64_t seed);

} // namespace flowrecon

#endif
