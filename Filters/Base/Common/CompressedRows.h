// Compressed rows (CSR, like TTK's FlatJaggedArray): the rows of an adjacency
// or of a grouping stored back to back in one vector, with the offsets of the
// rows in another. Row r is Values[Offsets[r] .. Offsets[r+1]). Plain data, no VTK.
#ifndef flowrecon_CompressedRows_h
#define flowrecon_CompressedRows_h

#include "FlowComplex.h" // Id

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace flowrecon
{

/// One row: a range of values, valid while its CompressedRows is unchanged.
template <class T>
class RowRange
{
public:
  RowRange(const T* first, const T* last)
    : First(first)
    , Last(last)
  {
  }
  const T* begin() const { return this->First; }
  const T* end() const { return this->Last; }
  std::size_t size() const { return static_cast<std::size_t>(this->Last - this->First); }
  bool empty() const { return this->First == this->Last; }
  const T& operator[](std::size_t k) const { return this->First[k]; }

private:
  const T* First;
  const T* Last;
};

/// Offsets has one entry per row plus one, starts at 0 and never decreases;
/// its last entry is the number of values. Offsets are 64-bit by default (flow
/// complexes have more arcs than 2^31); O narrower when the caller knows the
/// values fit. The values' type is the caller's.
template <class T, class O = Id>
struct CompressedRows
{
  std::vector<O> Offsets{ 0 };
  std::vector<T> Values;

  Id RowCount() const { return static_cast<Id>(this->Offsets.size()) - 1; }
  Id ValueCount() const { return static_cast<Id>(this->Values.size()); }
  Id RowSize(Id r) const { return this->Offsets[r + 1] - this->Offsets[r]; }
  RowRange<T> Row(Id r) const
  {
    return RowRange<T>(this->Values.data() + this->Offsets[r], this->Values.data() + this->Offsets[r + 1]);
  }

  /// Adds a row after the last one (rows made one at a time, in order).
  template <class It>
  void AppendRow(It first, It last)
  {
    this->Values.insert(this->Values.end(), first, last);
    this->Offsets.push_back(static_cast<O>(this->ValueCount()));
  }

  /// The entries grouped by row (a counting sort): `forEach(emit)` must call
  /// emit(row, value) for every entry, 0 <= row < rows, the same entries in the
  /// same order both times it is called (once to count, once to place). Within
  /// a row the values keep that order. Needs no memory beyond the result.
  template <class ForEach>
  static CompressedRows Group(std::size_t rows, ForEach&& forEach)
  {
    CompressedRows c;
    std::vector<O>& o = c.Offsets;
    o.assign(rows + 1, 0);
    // Counted two rows on, so that after the prefix sum Offsets[r + 1] is where
    // row r starts: the cursor of row r while placing, its end afterwards.
    std::size_t total = 0;
    forEach([&](Id row, const T&) {
      ++total;
      if (static_cast<std::size_t>(row) + 2 <= rows)
      {
        ++o[static_cast<std::size_t>(row) + 2];
      }
    });
    for (std::size_t r = 2; r <= rows; ++r)
    {
      o[r] += o[r - 1];
    }
    c.Values.resize(total);
    forEach([&](Id row, T value) { c.Values[static_cast<std::size_t>(o[row + 1]++)] = std::move(value); });
    return c;
  }

  /// Sorts the values within each row (then the order of the entries given to
  /// Group does not matter).
  void SortRows()
  {
    for (Id r = 0; r < this->RowCount(); ++r)
    {
      std::sort(this->Values.begin() + this->Offsets[r], this->Values.begin() + this->Offsets[r + 1]);
    }
  }
};

/// The positions 0 .. rowOf.size()-1 of a list grouped by rowOf[position]
/// (each row increasing), e.g. the triangles of each node.
inline CompressedRows<Id> PositionsByRow(const std::vector<Id>& rowOf, std::size_t rows)
{
  return CompressedRows<Id>::Group(rows, [&](const auto& emit) {
    for (std::size_t k = 0; k < rowOf.size(); ++k)
    {
      emit(rowOf[k], static_cast<Id>(k));
    }
  });
}

} // namespace flowrecon

#endif
