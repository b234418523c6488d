// Column reduction over Z/2 with a pivot table: the standard algorithm of
// persistent homology (Edelsbrunner, Letscher, Zomorodian 2002). Over Z/2 a
// column is a sorted set of rows and adding two columns is their symmetric
// difference; each column in turn is added the reduced column that owns its
// pivot until its pivot is owned by none (it pairs the two) or it is zero.
#ifndef flowrecon_Z2ColumnReduction_h
#define flowrecon_Z2ColumnReduction_h

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <vector>

namespace flowrecon
{

/// Rows are 0..rows-1, of the signed integer type Row. The reduced columns are
/// kept back to back in one pool: millions of two- and three-entry columns
/// would otherwise be as many allocations. A caller may lend a pool that holds
/// its columns already, so that a column needing no addition stays where it is
/// (ReducePooled). Which columns are reduced, and in which order, is the
/// caller's: the filtration order for homology, its reverse for cohomology,
/// and clearing is skipping the columns known to reduce to zero.
template <class Row>
class Z2ColumnReduction
{
public:
  /// Which entry of a column is its pivot: the greatest row (homology, where
  /// it is the latest face) or the least (cohomology, with the cofaces' rows in
  /// filtration order: the earliest coface).
  enum class Pivot
  {
    Greatest,
    Least
  };

  /// `pool` (null: one of its own) receives the reduced columns.
  Z2ColumnReduction(std::size_t rows, Pivot pivot, std::vector<Row>* pool = nullptr)
    : Owner(rows)
    , Which(pivot)
    , Pool(pool ? pool : &this->OwnPool)
  {
  }
  Z2ColumnReduction(const Z2ColumnReduction&) = delete;
  Z2ColumnReduction& operator=(const Z2ColumnReduction&) = delete;

  /// Reduces `column` (sorted rows) against the columns reduced so far. Returns
  /// its pivot row, the column (left in `column`) being kept in the pool, or -1
  /// when it reduces to zero.
  Row Reduce(std::vector<Row>& column)
  {
    bool added = false;
    while (!column.empty())
    {
      const Row low = this->Which == Pivot::Greatest ? column.back() : column.front();
      const Stored other = this->Owner[low];
      if (other.Size == 0)
      {
        this->Owner[low] = { static_cast<std::int64_t>(this->Pool->size()),
          static_cast<Row>(column.size()) };
        this->Pool->insert(this->Pool->end(), column.begin(), column.end());
        return low;
      }
      if (!added)
      {
        ++this->Reduced;
        added = true;
      }
      ++this->Additions;
      const Row* add = this->Pool->data() + other.Begin;
      this->Sum.clear();
      std::set_symmetric_difference(
        column.begin(), column.end(), add, add + other.Size, std::back_inserter(this->Sum));
      column.swap(this->Sum);
    }
    return -1;
  }

  /// Reduces the column Pool[begin, begin + size) (sorted rows, size > 0), as
  /// Reduce; when it needs no addition it is kept in place, not copied.
  Row ReducePooled(std::int64_t begin, Row size)
  {
    const Row* column = this->Pool->data() + begin;
    const Row low = this->Which == Pivot::Greatest ? column[size - 1] : column[0];
    if (this->Owner[low].Size == 0)
    {
      this->Owner[low] = { begin, size };
      return low;
    }
    this->Work.assign(column, column + size);
    return this->Reduce(this->Work);
  }

  /// Column additions so far.
  std::int64_t NumberOfAdditions() const { return this->Additions; }
  /// Columns that needed at least one addition so far.
  std::int64_t NumberOfReducedColumns() const { return this->Reduced; }

private:
  /// A reduced column: Pool[Begin, Begin + Size); Size 0: none.
  struct Stored
  {
    std::int64_t Begin = 0;
    Row Size = 0;
  };
  std::vector<Stored> Owner; ///< per row: the reduced column whose pivot it is
  Pivot Which;
  std::vector<Row> OwnPool;
  std::vector<Row>* Pool;
  std::vector<Row> Work, Sum;
  std::int64_t Additions = 0;
  std::int64_t Reduced = 0;
};

} // namespace flowrecon

#endif
