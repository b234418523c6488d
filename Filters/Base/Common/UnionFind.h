// Union-find whose root is always the smallest element of its component.
//
// Why one rule for every use: in 0-dimensional persistence (elements numbered by
// age) the smallest is the eldest, so a merge names the component that dies; in
// concurrent flooding (ExteriorRegions) it makes the result independent of the
// order of the unions. Sequential (Find, Merge) and concurrent (FindConcurrent,
// UnionConcurrent) calls keep that invariant; they are not to be mixed in one
// parallel phase.
#ifndef flowrecon_UnionFind_h
#define flowrecon_UnionFind_h

#include "HugePages.h"

#include <tbb/parallel_for.h>

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace flowrecon
{

class UnionFind
{
public:
  explicit UnionFind(std::size_t n)
  {
    if (n < (std::size_t(1) << 16))
    {
      // The many small ones (a cone's sheets) skip the parallel set-up.
      this->Parent.resize(n);
      std::iota(this->Parent.begin(), this->Parent.end(), 0);
      return;
    }
    ReserveHugePopulated(this->Parent, n);
    this->Parent.resize(n);
    tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) { this->Parent[i] = static_cast<std::int32_t>(i); });
  }

  /// The smallest element of x's component (path halving).
  std::int32_t Find(std::int32_t x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }

  /// Joins the components of a and b. Returns the root of the one that loses its
  /// name (the larger root), or -1 when a and b were already in one component.
  std::int32_t Merge(std::int32_t a, std::int32_t b)
  {
    a = this->Find(a);
    b = this->Find(b);
    if (a == b)
    {
      return -1;
    }
    if (a > b)
    {
      std::swap(a, b);
    }
    this->Parent[b] = a;
    return b;
  }

  /// Find, safe beside other concurrent calls.
  std::int32_t FindConcurrent(std::int32_t x)
  {
    while (true)
    {
      std::int32_t p = __atomic_load_n(&this->Parent[x], __ATOMIC_RELAXED);
      if (p == x)
      {
        return x;
      }
      const std::int32_t g = __atomic_load_n(&this->Parent[p], __ATOMIC_RELAXED);
      if (g != p)
      {
        // Halving; losing the race only leaves a longer path.
        __atomic_compare_exchange_n(&this->Parent[x], &p, g, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED);
      }
      x = p;
    }
  }

  /// Merge, safe beside other concurrent calls.
  void UnionConcurrent(std::int32_t a, std::int32_t b)
  {
    while (true)
    {
      a = this->FindConcurrent(a);
      b = this->FindConcurrent(b);
      if (a == b)
      {
        return;
      }
      if (a < b)
      {
        std::swap(a, b);
      }
      // Link the larger root under the smaller, if it is still a root.
      std::int32_t expected = a;
      if (__atomic_compare_exchange_n(&this->Parent[a], &expected, b, false, __ATOMIC_RELAXED, __ATOMIC_RELAXED))
      {
        return;
      }
    }
  }

private:
  // Plain integers under GCC's atomic built-ins: a vector of std::atomic
  // cannot be sized after a reserve (for huge pages).
  std::vector<std::int32_t> Parent;
};

} // namespace flowrecon

#endif
