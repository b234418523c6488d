// Parallel loops that report progress: TBB runs each slice, and between slices
// the calling thread reports progress and polls for abort (VTK observers and
// the CLI's progress line must not be called from worker threads).
#ifndef flowrecon_ParallelSlices_h
#define flowrecon_ParallelSlices_h

#include "FlowComplex.h"
#include "Progress.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace flowrecon
{

/// Runs body(first, last) over [0, n) in parallel, `slice` items at a time;
/// progress goes from `from` to `to` across the loop.
template <class Body>
void ParallelSlices(Id n, Id slice, const Progress& progress, double from, double to,
  const char* phase, const Body& body)
{
  for (Id begin = 0; begin < n; begin += slice)
  {
    progress(from + (to - from) * static_cast<double>(begin) / static_cast<double>(n), phase);
    tbb::parallel_for(tbb::blocked_range<Id>(begin, std::min(n, begin + slice)),
      [&](const tbb::blocked_range<Id>& r) { body(r.begin(), r.end()); });
  }
}

} // namespace flowrecon

#endif
