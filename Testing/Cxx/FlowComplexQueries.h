// Look-ups on a core flow complex shared by the C++ tests.
#ifndef flowrecon_FlowComplexQueries_h
#define flowrecon_FlowComplexQueries_h

#include "FlowComplex.h"

#include <algorithm>
#include <vector>

namespace queries
{
using flowrecon::FlowComplex;
using flowrecon::Id;

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
