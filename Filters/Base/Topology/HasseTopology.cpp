#include "HasseTopology.h"

#include "NodeIndices.h"

#include "StableRadixSort.h"
#include "UnionFind.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <string>

namespace flowrecon
{

namespace
{

using Int = std::int32_t;

[[noreturn]] void NotClosed(const std::string& what)
{
  throw InputError("topology from the Hasse diagram: " + what);
}

/// Up to two odd-multiplicity neighbours of each inserted node (by position):
/// the ends of an edge (0-1 arcs) or the sides of a 2-cell (2-3 arcs).
std::vector<Int> PairsOf(const std::vector<std::int8_t>& index, const std::vector<Arc>& arcs,
  const std::vector<Int>& pos, int lowerIndex, std::size_t inserted)
{
  std::vector<Int> ends(2 * inserted, -1);
  for (const Arc& a : arcs)
  {
    if (a.Multiplicity % 2 == 0)
    {
      continue;
    }
    // Edges are found from their ends (the upper), 2-cells from themselves.
    const Id cell = lowerIndex == 0 ? a.Upper : a.Lower;
    const Id other = lowerIndex == 0 ? a.Lower : a.Upper;
    if (index[a.Lower] != lowerIndex || pos[cell] < 0)
    {
      continue;
    }
    Int* slot = &ends[2 * static_cast<std::size_t>(pos[cell])];
    if (slot[1] >= 0)
    {
      NotClosed("node " + std::to_string(cell) + " has more than two " +
        (lowerIndex == 0 ? "ends" : "sides"));
    }
    slot[slot[0] >= 0 ? 1 : 0] = static_cast<Int>(other);
  }
  return ends;
}

/// The barcode of the presence filtration, built in two passes over it (the
/// steps of HasseBarcode).
class Barcode
{
public:
  std::vector<Bar> Bars;

  Barcode(std::vector<std::int8_t> index, const std::vector<double>& presence)
    : Index(std::move(index))
    , Presence(presence)
  {
    this->SortFiltration();
  }

  /// Backwards, on the complement: maxima outside K_t joined by index-2 nodes
  /// outside it; a join that merges two components closes a void (H2).
  void Outside(const std::vector<Arc>& arcs, const std::vector<std::pair<Id, Id>>& joined)
  {
    UnionFind outside = this->OutsideAtInfinity(arcs, joined);
    const std::vector<Int> sides = PairsOf(this->Index, arcs, this->Pos, 2, this->Order.size());
    this->Separates.assign(this->Order.size(), 0);
    for (std::size_t p = this->Order.size(); p-- > 0;)
    {
      const Int s = this->Order[p];
      if (this->Index[s] != 2)
      {
        continue;
      }
      const Int a = sides[2 * p], b = sides[2 * p + 1];
      if ((a >= 0) != (b >= 0))
      {
        NotClosed("index-2 node " + std::to_string(s) + " has one side");
      }
      if (a < 0)
      {
        continue; // both sides in one maximum: the arcs cancelled mod 2
      }
      if (this->Before(a, p) || this->Before(b, p))
      {
        NotClosed("a maximum is inserted before its boundary node " + std::to_string(s));
      }
      const Int dies = outside.Merge(this->ElementOf[a], this->ElementOf[b]);
      if (dies >= 0)
      {
        this->Separates[p] = 1;
        const Int m = this->NodeOf[dies];
        this->Make(2, s, this->Pos[m] >= 0 ? m : -1);
      }
    }
  }

  /// Forwards, the components (H0): union-find over the edges' ends. Reads
  /// what Outside does not write, so the two run side by side. Leaves, per
  /// place of an edge, the place of the component it ends (-1: it closes a
  /// loop) for Inside, and the components never ended.
  void Components(const std::vector<Arc>& arcs)
  {
    this->Joins = PairsOf(this->Index, arcs, this->Pos, 0, this->Order.size());
    UnionFind inside(this->Order.size());
    for (std::size_t p = 0; p < this->Order.size(); ++p)
    {
      const Int v = this->Order[p];
      if (this->Index[v] != 1)
      {
        continue;
      }
      const Int a = this->Joins[2 * p], b = this->Joins[2 * p + 1];
      if ((a >= 0) != (b >= 0) ||
        (a >= 0 && (this->Pos[a] < 0 || this->Pos[b] < 0 || this->After(a, p) || this->After(b, p))))
      {
        NotClosed("edge " + std::to_string(v) + " is inserted before its ends");
      }
      // A component is named by its oldest vertex: the younger one dies.
      this->Joins[2 * p] = a >= 0 ? inside.Merge(this->Pos[a], this->Pos[b]) : -1;
    }
    for (std::size_t p = 0; p < this->Order.size(); ++p)
    {
      if (this->Index[this->Order[p]] == 0 && inside.Find(static_cast<Int>(p)) == static_cast<Int>(p))
      {
        this->Essential.push_back(this->Order[p]);
      }
    }
  }

  /// Forwards, after Outside and Components: the bars of H0, and the loops
  /// as they close, each filled by a 2-cell that does not separate (H1).
  void Inside()
  {
    std::vector<Int> loops; // edges of the open loops, latest last
    for (std::size_t p = 0; p < this->Order.size(); ++p)
    {
      const Int v = this->Order[p];
      const int dimension = this->Index[v];
      if (dimension == 1)
      {
        const Int dies = this->Joins[2 * p];
        if (dies >= 0)
        {
          this->Make(0, this->Order[dies], v);
        }
        else
        {
          loops.push_back(v);
        }
      }
      else if (dimension == 2 && !this->Separates[p])
      {
        if (loops.empty())
        {
          NotClosed("2-cell " + std::to_string(v) + " fills no loop");
        }
        this->Make(1, loops.back(), v);
        loops.pop_back();
      }
    }
    std::vector<Int>().swap(this->Joins);
    for (const Int v : this->Essential)
    {
      this->Make(0, v, -1);
    }
    for (const Int e : loops)
    {
      this->Make(1, e, -1);
    }
  }

private:
  const std::vector<std::int8_t> Index;
  const std::vector<double>& Presence;
  std::vector<Int> Order, Pos; ///< the inserted nodes in filtration order; a node's place in it or -1
  std::vector<Int> ElementOf, NodeOf; ///< maxima as elements of the complement's union-find
  std::vector<char> Separates; ///< by place: an index-2 node that joins two components outside
  std::vector<Int> Joins;      ///< by place of an edge: its ends, then the place it ends (Components)
  std::vector<Int> Essential;  ///< vertices whose component never ends

  bool Before(Int v, std::size_t p) const { return this->Pos[v] >= 0 && this->Pos[v] < static_cast<Int>(p); }
  bool After(Int v, std::size_t p) const { return this->Pos[v] > static_cast<Int>(p); }

  /// The filtration: by presence, faces before cofaces, then by node id. The
  /// present nodes are listed by (index, id), a counting pass, then sorted
  /// stably by presence alone (StableRadixSort.h): a comparison sort of the
  /// three keys was half of HasseBarcode's time at 10^6 points.
  void SortFiltration()
  {
    // 12 bytes, not 16: the sort holds two copies of every present node.
    struct Entry
    {
      std::uint32_t Low, High;
      Int Node;
      std::uint64_t Key() const { return (std::uint64_t(this->High) << 32) | this->Low; }
    };
    const std::size_t n = this->Index.size();
    std::array<std::size_t, 257> start{};
    for (std::size_t v = 0; v < n; ++v)
    {
      start[static_cast<std::size_t>(this->Index[v] + 128) + 1] += this->Presence[v] < HUGE_VAL ? 1 : 0;
    }
    for (std::size_t b = 1; b < start.size(); ++b)
    {
      start[b] += start[b - 1];
    }
    std::vector<Entry> entries(start.back());
    for (std::size_t v = 0; v < n; ++v)
    {
      if (this->Presence[v] < HUGE_VAL)
      {
        const std::uint64_t key = OrderedBits(this->Presence[v]);
        entries[start[static_cast<std::size_t>(this->Index[v] + 128)]++] = Entry{
          static_cast<std::uint32_t>(key), static_cast<std::uint32_t>(key >> 32), static_cast<Int>(v) };
      }
    }
    StableRadixSort(entries, [](const Entry& e) { return e.Key(); });
    this->Order.resize(entries.size());
    for (std::size_t p = 0; p < entries.size(); ++p)
    {
      this->Order[p] = entries[p].Node;
    }
    std::vector<Entry>().swap(entries);
    this->Pos.assign(n, -1);
    for (std::size_t p = 0; p < this->Order.size(); ++p)
    {
      this->Pos[this->Order[p]] = static_cast<Int>(p);
    }
  }

  /// The complement at t_r = inf: its maxima as elements by age in the
  /// backward direction (never inserted first, then by decreasing place),
  /// merged where `joined` says so and across the index-2 nodes never present.
  UnionFind OutsideAtInfinity(const std::vector<Arc>& arcs, const std::vector<std::pair<Id, Id>>& joined)
  {
    const std::size_t n = this->Index.size();
    this->ElementOf.assign(n, -1);
    for (std::size_t v = 0; v < n; ++v)
    {
      if (this->Index[v] == 3 && this->Pos[v] < 0)
      {
        this->ElementOf[v] = static_cast<Int>(this->NodeOf.size());
        this->NodeOf.push_back(static_cast<Int>(v));
      }
    }
    for (std::size_t p = this->Order.size(); p-- > 0;)
    {
      if (this->Index[this->Order[p]] == 3)
      {
        this->ElementOf[this->Order[p]] = static_cast<Int>(this->NodeOf.size());
        this->NodeOf.push_back(this->Order[p]);
      }
    }
    UnionFind outside(this->NodeOf.size());
    for (const auto& [a, b] : joined)
    {
      if (a < 0 || b < 0 || a >= static_cast<Id>(n) || b >= static_cast<Id>(n) || this->Index[a] != 3 ||
        this->Index[b] != 3 || this->Pos[a] >= 0 || this->Pos[b] >= 0)
      {
        NotClosed("joined nodes that are not maxima outside every reconstruction");
      }
      outside.Merge(this->ElementOf[a], this->ElementOf[b]);
    }
    for (std::size_t k = 0; k < arcs.size();)
    {
      const Id s = arcs[k].Lower;
      Int sides[3] = { -1, -1, -1 };
      int count = 0;
      for (; k < arcs.size() && arcs[k].Lower == s; ++k)
      {
        if (this->Index[s] == 2 && arcs[k].Multiplicity % 2 != 0)
        {
          sides[std::min(count++, 2)] = arcs[k].Upper;
        }
      }
      if (this->Index[s] != 2 || this->Pos[s] >= 0 || count == 0)
      {
        continue;
      }
      if (count != 2)
      {
        NotClosed("index-2 node " + std::to_string(s) + " has " + std::to_string(count) +
          " sides (its 2-3 arcs are incomplete or not grouped by lower node)");
      }
      if (this->Pos[sides[0]] >= 0 || this->Pos[sides[1]] >= 0)
      {
        NotClosed("a maximum is inserted before its boundary node " + std::to_string(s));
      }
      outside.Merge(this->ElementOf[sides[0]], this->ElementOf[sides[1]]);
    }
    return outside;
  }

  /// Most classes die where they are born: only bars of positive length are made.
  void Make(int dimension, Int birth, Int death)
  {
    const double born = this->Presence[birth];
    const double dies = death >= 0 ? this->Presence[death] : HUGE_VAL;
    if (born < dies)
    {
      Bar bar;
      bar.Dimension = dimension;
      bar.Birth = born;
      bar.BirthCell = birth;
      bar.Death = dies;
      bar.DeathCell = death;
      this->Bars.push_back(bar);
    }
  }
};

} // namespace

std::vector<double> PresenceTimes(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<Id>& carriers, const ReconstructionResult& run)
{
  const std::size_t n = nodes.size();
  if (carriers.size() != n || run.Nodes.size() != n)
  {
    NotClosed("the carriers, the run and the diagram have different nodes");
  }
  std::vector<double> presence(n, HUGE_VAL);
  for (std::size_t v = 0; v < n; ++v)
  {
    if (carriers[v] >= 0)
    {
      presence[v] = run.Nodes[carriers[v]].Threshold;
    }
  }
  // Every face of a drawn cell is drawn with it: from the maxima down.
  const std::vector<std::int8_t> index = NodeIndices(nodes);
  for (int upper = 3; upper >= 1; --upper)
  {
    for (const Arc& a : rawArcs)
    {
      if (index[a.Upper] == upper)
      {
        presence[a.Lower] = std::min(presence[a.Lower], presence[a.Upper]);
      }
    }
  }
  return presence;
}

std::vector<Bar> HasseBarcode(const std::vector<Node>& nodes, const std::vector<Arc>& rawArcs,
  const std::vector<double>& presence, const std::vector<std::pair<Id, Id>>& joined)
{
  if (presence.size() != nodes.size())
  {
    NotClosed("the presence times and the diagram have different nodes");
  }
  Barcode code(NodeIndices(nodes), presence);
  // Two passes of union-find, each bound by its random reads: side by side.
  // Their errors are reported in a fixed order (the output is deterministic).
  std::exception_ptr outside, components;
  tbb::parallel_invoke(
    [&] {
      try
      {
        code.Outside(rawArcs, joined);
      }
      catch (...)
      {
        outside = std::current_exception();
      }
    },
    [&] {
      try
      {
        code.Components(rawArcs);
      }
      catch (...)
      {
        components = std::current_exception();
      }
    });
  for (const std::exception_ptr& e : { outside, components })
  {
    if (e)
    {
      std::rethrow_exception(e);
    }
  }
  code.Inside();
  return std::move(code.Bars);
}

} // namespace flowrecon
