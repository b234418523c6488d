// Look-ups on a core flow complex shared by the C++ tests.
#ifndef flowrecon_FlowComplexQueries_h
#define flowrecon_FlowComplexQueries_h

#include "Check.h"
#include "FlowComplexBuilder.h"

#include <algorithm>
#include <array>
#include <vector>

namespace queries
{
using flowrecon::FlowComplex;
using flowrecon::Id;

/// The flow complex of `p` with the default options.
inline FlowComplex Build(const std::vector<flowrecon::Point3>& p)
{
  return flowrecon::BuildFlowComplex(p, flowrecon::BuildOptions(), flowrecon::Progress());
}

/// Finite node counts by index equal `expected` (which must satisfy Euler's relation).
inline void CheckCounts(const FlowComplex& fc, std::array<Id, 4> expected)
{
  const auto n = fc.CountByIndex();
  for (int i = 0; i < 4; ++i)
  {
    CHECK(n[i] == expected[i]);
  }
  CHECK(n[0] - n[1] + n[2] - n[3] == 1);
}

/// The node whose nearest samples are `simplex` (input ids, any order), or -1.
inline Id NodeOf(const FlowComplex& fc, std::vector<Id> simplex)
{
  std::sort(simplex.begin(), simplex.end());
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    const flowrecon::Node& n = fc.Nodes[i];
    if (n.Index == static_cast<int>(simplex.size()) - 1 &&
      std::equal(simplex.begin(), simplex.end(), n.Simplex.begin()))
    {
      return static_cast<Id>(i);
    }
  }
  return -1;
}

/// Multiplicity of the arc lower -> upper, 0 if there is none.
inline int Multiplicity(const FlowComplex& fc, Id lower, Id upper)
{
  for (const flowrecon::Arc& a : fc.Arcs)
  {
    if (a.Lower == lower && a.Upper == upper)
    {
      return a.Multiplicity;
    }
  }
  return 0;
}

} // namespace queries

#endif
