// The nodes' indices side by side: passes over millions of arcs read the
// index of each end at random, and a Node is 56 bytes (at 10^6 surface points
// the nodes are some 200 MB, their indices 4 MB).
#ifndef flowrecon_NodeIndices_h
#define flowrecon_NodeIndices_h

#include "FlowComplex.h"

#include <tbb/parallel_for.h>

#include <cstdint>
#include <vector>

namespace flowrecon
{

inline std::vector<std::int8_t> NodeIndices(const std::vector<Node>& nodes)
{
  std::vector<std::int8_t> index(nodes.size());
  tbb::parallel_for(std::size_t(0), nodes.size(),
    [&](std::size_t v) { index[v] = static_cast<std::int8_t>(nodes[v].Index); });
  return index;
}

} // namespace flowrecon

#endif
