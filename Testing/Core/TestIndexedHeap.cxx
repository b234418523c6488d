// IndexedHeap against a brute-force oracle: random offers that only lower an
// id's key, interleaved with pops, must pop exactly what a scan of the current
// best offers gives (the least key each time), and a raised key is refused.
#include "Check.h"
#include "IndexedHeap.h"

#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace
{
struct Item
{
  double Key;
  std::int32_t Id;
};
struct ItemLess
{
  bool operator()(const Item& a, const Item& b) const
  {
    return std::tie(a.Key, a.Id) < std::tie(b.Key, b.Id);
  }
};
using Heap = flowrecon::IndexedHeap<Item, &Item::Id, ItemLess>;
} // namespace

int main()
{
  std::mt19937 rng(7);
  for (int round = 0; round < 20; ++round)
  {
    const int ids = 1 + static_cast<int>(rng() % 300);
    Heap heap(static_cast<std::size_t>(ids));
    const double none = std::numeric_limits<double>::infinity();
    std::vector<double> best(static_cast<std::size_t>(ids), none); // queued key, inf: not queued
    std::vector<char> taken(static_cast<std::size_t>(ids), 0);
    int mismatches = 0;
    for (int step = 0; step < 4000; ++step)
    {
      if (rng() % 3 != 0)
      {
        const std::int32_t id = static_cast<std::int32_t>(rng() % static_cast<unsigned>(ids));
        // Coarse keys, so that ties between ids are frequent.
        const double key = static_cast<double>(rng() % 50);
        if (!taken[id] && key < best[id])
        {
          best[id] = key;
          heap.Push({ key, id });
        }
        continue;
      }
      // The oracle's least queued (key, id).
      std::int32_t expected = -1;
      for (std::int32_t i = 0; i < ids; ++i)
      {
        if (best[i] < none && (expected < 0 || best[i] < best[expected]))
        {
          expected = i;
        }
      }
      CHECK(heap.Empty() == (expected < 0));
      if (expected < 0)
      {
        continue;
      }
      const Item top = heap.Pop();
      mismatches += top.Id == expected && top.Key == best[expected] ? 0 : 1;
      best[expected] = none;
      taken[expected] = 1;
    }
    CHECK(mismatches == 0);
  }

  // A larger key for a queued id is refused; an equal one is accepted.
  Heap heap(4);
  heap.Push({ 2.0, 1 });
  bool refused = false;
  try
  {
    heap.Push({ 3.0, 1 });
  }
  catch (const std::logic_error&)
  {
    refused = true;
  }
  CHECK(refused);
  heap.Push({ 2.0, 1 });
  heap.Push({ 1.0, 3 });
  CHECK(heap.Size() == 2);
  CHECK(heap.Pop().Id == 3);
  CHECK(heap.Pop().Id == 1);
  CHECK(heap.Empty());
  return check::Finish("TestIndexedHeap");
}
