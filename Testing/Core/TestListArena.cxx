// ListArena against a simulation of many lists: random pushes that grow lists
// (moving them to larger blocks), removals that give blocks back, carved
// first lists of exact sizes. Every live list keeps its own contents (a block
// handed to two lists at once would overwrite one), capacities are powers of
// two at least the request, and a released block is handed out again.
#include "Check.h"
#include "ListArena.h"

#include <cstdint>
#include <random>
#include <vector>

namespace
{

struct List
{
  std::uint64_t* Data = nullptr;
  std::uint32_t Size = 0, Capacity = 0;
};

/// The value at position k of list i: any overlap of two blocks shows.
std::uint64_t Tag(std::size_t list, std::size_t k)
{
  return (static_cast<std::uint64_t>(list) << 32) | k;
}

void TestManyLists()
{
  flowrecon::ListArena<std::uint64_t> arena;
  std::mt19937 random(7);
  const std::size_t count = 3000;
  std::vector<List> lists(count);
  // First lists carved back to back, 0 to 4 elements each (0: no block).
  std::vector<std::uint32_t> first(count);
  std::size_t total = 0;
  for (std::uint32_t& d : first)
  {
    d = static_cast<std::uint32_t>(random() % 5);
    total += d;
  }
  std::uint64_t* next = arena.Carve(total);
  for (std::size_t i = 0; i < count; ++i)
  {
    if (first[i] > 0)
    {
      lists[i].Data = next;
      lists[i].Capacity = first[i];
      next += first[i];
    }
  }
  std::size_t reused = 0, moves = 0;
  std::vector<std::uint64_t*> released;
  for (int step = 0; step < 200000; ++step)
  {
    List& l = lists[random() % count];
    const std::size_t i = static_cast<std::size_t>(&l - lists.data());
    if (random() % 50 == 0)
    {
      arena.Release(l.Data, l.Capacity);
      if (l.Data && l.Capacity >= 4)
      {
        released.push_back(l.Data);
      }
      l = List();
      continue;
    }
    if (l.Size == l.Capacity)
    {
      std::uint32_t capacity = 0;
      const std::uint32_t needed = l.Size + 1 + (random() % 3 == 0 ? 40 : 0);
      std::uint64_t* moved = arena.Allocate(needed, capacity);
      CHECK(capacity >= needed && (capacity & (capacity - 1)) == 0);
      for (const std::uint64_t* r : released)
      {
        reused += r == moved;
      }
      for (std::uint32_t k = 0; k < l.Size; ++k)
      {
        moved[k] = l.Data[k];
      }
      arena.Release(l.Data, l.Capacity);
      l.Data = moved;
      l.Capacity = capacity;
      ++moves;
    }
    l.Data[l.Size] = Tag(i, l.Size);
    ++l.Size;
  }
  std::size_t wrong = 0, elements = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    for (std::uint32_t k = 0; k < lists[i].Size; ++k)
    {
      wrong += lists[i].Data[k] != Tag(i, k);
      ++elements;
    }
  }
  CHECK(wrong == 0);
  CHECK(elements > 50000);
  CHECK(moves > 1000);
  CHECK(reused > 0); // released blocks serve later lists
  arena.Clear();
  std::uint32_t capacity = 0;
  CHECK(arena.Allocate(1, capacity) != nullptr && capacity == 1);
  CHECK(arena.Carve(0) == nullptr);
}

} // namespace

int main()
{
  TestManyLists();
  return check::Finish("TestListArena");
}
