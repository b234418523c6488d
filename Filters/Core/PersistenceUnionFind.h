// Union-find with the elder rule, the tool of 0-dimensional persistence: every
// component is named by its oldest element, so a merge says which component dies.
#ifndef flowrecon_PersistenceUnionFind_h
#define flowrecon_PersistenceUnionFind_h

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace flowrecon
{

/// Elements are 0..n-1 and their index is their age: a smaller index is older.
/// Each component's root is its oldest element.
class ElderUnionFind
{
public:
  explicit ElderUnionFind(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }

  /// The oldest element of x's component (path halving).
  std::int32_t Find(std::int32_t x)
  {
    while (this->Parent[x] != x)
    {
      this->Parent[x] = this->Parent[this->Parent[x]];
      x = this->Parent[x];
    }
    return x;
  }

  /// Joins the components of a and b. Returns the root of the younger one (the
  /// component that dies), or -1 when a and b were already in one component.
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

private:
  std::vector<std::int32_t> Parent;
};

} // namespace flowrecon

#endif
