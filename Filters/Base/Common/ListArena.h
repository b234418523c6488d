// Storage for millions of short lists that grow and die one by one (the In and
// Out lists of a Hasse diagram under cancellations). A malloc per list cost a
// call and a scattered block each, and a 24-byte vector header per list; here
// the first lists are carved back to back from one block (the order they are
// built in is the order they are read in), a list that outgrows its block moves
// to one of the next power of two, and freed blocks are reused by size class.
// Blocks never move: pointers into them stay valid until the arena goes.
#ifndef flowrecon_ListArena_h
#define flowrecon_ListArena_h

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace flowrecon
{

template <class T>
class ListArena
{
public:
  /// `count` contiguous elements of a new block, for the caller to cut into
  /// lists of exact capacities (Release takes them back piece by piece).
  T* Carve(std::size_t count)
  {
    if (count == 0)
    {
      return nullptr;
    }
    this->Blocks.emplace_back(new T[count]); // not value-initialised: no page is touched yet
    return this->Blocks.back().get();
  }

  /// A block of at least `needed` (> 0) elements; its capacity, a power of two,
  /// is written to `capacity`.
  T* Allocate(std::uint32_t needed, std::uint32_t& capacity)
  {
    int k = 0;
    while ((std::uint64_t(1) << k) < needed)
    {
      ++k;
    }
    capacity = static_cast<std::uint32_t>(std::uint64_t(1) << k);
    if (static_cast<std::size_t>(k) < this->Free.size() && !this->Free[k].empty())
    {
      T* block = this->Free[k].back();
      this->Free[k].pop_back();
      return block;
    }
    if (this->Left < capacity)
    {
      const std::size_t size = std::max<std::size_t>(capacity, Chunk);
      this->Next = this->Carve(size);
      this->Left = size;
    }
    T* block = this->Next;
    this->Next += capacity;
    this->Left -= capacity;
    return block;
  }

  /// Takes back a block of `capacity` elements (any size: it serves later
  /// requests of the largest power of two it holds).
  void Release(T* block, std::uint32_t capacity)
  {
    if (block == nullptr || capacity == 0)
    {
      return;
    }
    int k = 0;
    while ((std::uint64_t(2) << k) <= capacity)
    {
      ++k;
    }
    if (this->Free.size() <= static_cast<std::size_t>(k))
    {
      this->Free.resize(static_cast<std::size_t>(k) + 1);
    }
    this->Free[k].push_back(block);
  }

  /// Frees everything: every pointer into the arena is invalid after.
  void Clear()
  {
    std::vector<std::unique_ptr<T[]>>().swap(this->Blocks);
    std::vector<std::vector<T*>>().swap(this->Free);
    this->Next = nullptr;
    this->Left = 0;
  }

private:
  static constexpr std::size_t Chunk = std::size_t(1) << 18; ///< elements of a growth block
  std::vector<std::unique_ptr<T[]>> Blocks;
  std::vector<std::vector<T*>> Free; ///< Free[k]: blocks of at least 2^k elements
  T* Next = nullptr;                 ///< the unused rest of the last growth block
  std::size_t Left = 0;
};

} // namespace flowrecon

#endif
