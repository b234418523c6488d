// StableRadixSort against std::stable_sort on keys that tie often, span every
// digit, and come from doubles of both signs (OrderedBits): the same sequence,
// items of equal keys in their first order.
#include "Check.h"
#include "StableRadixSort.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace
{

struct Item
{
  double Value;
  int Place; ///< the position before sorting: what stability keeps in order
};

std::vector<Item> Items(std::mt19937_64& random, std::size_t count)
{
  std::vector<double> pool = { -0.0, 0.0, 1.0, 1.0 + 1e-15, -1.0, 3.25, 1e300, -1e-300,
    5e-324, HUGE_VAL, -HUGE_VAL, 2.0, 0.5 };
  std::uniform_real_distribution<double> wide(-1e6, 1e6);
  for (int k = 0; k < 200; ++k)
  {
    pool.push_back(wide(random)); // a few hundred values repeated: many ties
  }
  std::vector<Item> items(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    items[i] = Item{ pool[random() % pool.size()], static_cast<int>(i) };
  }
  return items;
}

void TestAgainstStableSort(std::size_t count, std::uint64_t seed)
{
  std::mt19937_64 random(seed);
  std::vector<Item> items = Items(random, count);
  std::vector<Item> expected = items;
  // -0 before +0, as OrderedBits orders them.
  std::stable_sort(expected.begin(), expected.end(), [](const Item& a, const Item& b) {
    return a.Value < b.Value || (a.Value == b.Value && std::signbit(a.Value) && !std::signbit(b.Value));
  });
  flowrecon::StableRadixSort(items, [](const Item& i) { return flowrecon::OrderedBits(i.Value); });
  bool same = items.size() == expected.size();
  for (std::size_t i = 0; same && i < items.size(); ++i)
  {
    same = items[i].Place == expected[i].Place;
  }
  CHECK(same);
}

void TestDigitsSkippedAndUsed()
{
  // Keys that differ only in their top 16 bits, then only in their lowest:
  // the skipped digits must not reorder, the used ones must.
  for (const int shift : { 48, 0 })
  {
    std::vector<std::uint64_t> keys;
    for (std::uint64_t k = 0; k < 1000; ++k)
    {
      keys.push_back(((k * 7919) % 1000) << shift);
    }
    flowrecon::StableRadixSort(keys, [](std::uint64_t k) { return k; });
    CHECK(std::is_sorted(keys.begin(), keys.end()));
  }
  std::vector<std::uint64_t> none;
  flowrecon::StableRadixSort(none, [](std::uint64_t k) { return k; });
  CHECK(none.empty());
}

} // namespace

int main()
{
  TestAgainstStableSort(1, 1);
  TestAgainstStableSort(1000, 2);
  TestAgainstStableSort(200000, 3);
  TestDigitsSkippedAndUsed();
  return check::Finish("TestStableRadixSort");
}
