#include "CompactReconstruction.h"

#include "CellHomology.h"
#include "ParallelSlices.h"
#include "Retriangulation.h"
#include "StableManifold.h"
#include "SuccessorForest.h"
#include "UnionFind.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <numeric>
#include <limits>
#include <tuple>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace flowrecon
{

namespace
{

using Claim = CompactClaim;
using Neighbourhood = std::vector<std::array<std::int32_t, 4>>;

/// Cells, simplices or rows a task of the parallel passes below takes.
constexpr std::size_t CellBlock = 4096;

/// Sets a flag that other threads may set too (only ever to 1).
inline void Raise(std::atomic<std::uint8_t>& flag)
{
  if (flag.load(std::memory_order_relaxed) == 0)
  {
    flag.store(1, std::memory_order_relaxed);
  }
}

/// Each Delaunay cell's neighbours (CompactPieces::Neighbours).
Neighbourhood Neighbours(const Triangulation& tri)
{
  Neighbourhood neighbours(static_cast<std::size_t>(tri.NumberOfCells()));
  ParallelSlices(tri.NumberOfCells(), Id(1) << 16, Progress(), 0.0, 0.0, "compact cells",
    [&](Id first, Id last) {
      for (Id c = first; c < last; ++c)
      {
        const CellHandle cell = tri.Cell(c);
        for (int k = 0; k < 4; ++k)
        {
          const CellHandle next = cell->neighbor(k);
          neighbours[c][k] =
            tri.Dt().is_infinite(next) ? -1 : static_cast<std::int32_t>(tri.CellId(next));
        }
      }
    });
  return neighbours;
}

template <std::size_t N>
std::array<Id, N> InputSimplex(const Retriangulation& re, const std::array<Id, N>& vertices)
{
  std::array<Id, N> s;
  for (std::size_t k = 0; k < N; ++k)
  {
    s[k] = re.Prepared().InputId[vertices[k]];
  }
  std::sort(s.begin(), s.end());
  return s;
}

/// The Delaunay cells as the selection reads them: from the triangulation, or
/// from a CompactCells table made of it.
class CellView
{
public:
  explicit CellView(const Retriangulation& re)
    : Re(&re)
  {
  }
  explicit CellView(const CompactCells& cells)
    : Table(&cells)
  {
  }
  Id Count() const
  {
    return this->Re ? this->Re->Tri().NumberOfCells() : static_cast<Id>(this->Table->Vertices.size());
  }
  /// The cell's input ids, sorted.
  std::array<Id, 4> Tetrahedron(Id c) const
  {
    if (this->Re)
    {
      const Triangulation& tri = this->Re->Tri();
      return InputSimplex<4>(*this->Re, tri.SortedVertices(tri.Cell(c)));
    }
    const std::array<std::int32_t, 4>& v = this->Table->Vertices[c];
    return { { v[0], v[1], v[2], v[3] } };
  }
  std::vector<char> MaximumFlags() const
  {
    std::vector<char> flags(static_cast<std::size_t>(this->Count()), 0);
    if (this->Re)
    {
      for (const CriticalCell& c : this->Re->Critical().Cells)
      {
        flags[c.Cell] = 1;
      }
    }
    else
    {
      for (const std::int32_t c : this->Table->Maxima)
      {
        flags[c] = 1;
      }
    }
    return flags;
  }

private:
  const Retriangulation* Re = nullptr;
  const CompactCells* Table = nullptr;
};

/// Whether `node`'s simplex is `simplex` (input ids, sorted).
template <std::size_t N>
bool SameSimplex(const Node& node, const std::array<Id, N>& simplex)
{
  for (std::size_t k = 0; k < N; ++k)
  {
    if (node.Simplex[k] != simplex[k])
    {
      return false;
    }
  }
  return N == 4 || node.Simplex[N] < 0;
}

/// `claim` with the cells on the two sides of its triangle: the facet
/// `opposite` of `cell` (CGAL's facet search would mark cells: one thread at a
/// time; the walks know a cell of each triangle they cross).
Claim Sides(const Triangulation& tri, CellHandle cell, int opposite, Claim claim)
{
  for (int side = 0; side < 2; ++side)
  {
    if (!tri.Dt().is_infinite(cell))
    {
      claim.Cells[side] = static_cast<std::int32_t>(tri.CellId(cell));
      claim.Facets[side] = static_cast<std::int8_t>(opposite);
    }
    const CellHandle other = cell->neighbor(opposite);
    opposite = other->index(cell);
    cell = other;
  }
  return claim;
}

/// The claims of the walks of `patches` (index-2 node ids): each one's facet
/// and every triangle its walk crosses, sorted.
void WalkPatches(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& patches, const Progress& progress, CompactPieces& pieces)
{
  const CriticalSimplices& cs = re.Critical();
  const Id facets = static_cast<Id>(cs.Facets.size());
  std::vector<std::vector<Claim>> claims(patches.size());
  std::vector<Id> fallbacks(patches.size(), 0);
  std::vector<char> foreign(patches.size(), 0);
  const Triangulation& tri = re.Tri();
  const RecordedWalks& walks = re.Walks();
  ParallelSlices(static_cast<Id>(patches.size()), Id(1) << 14, progress, 0.0, 0.6,
    "compact patches", [&](Id first, Id last) {
      for (Id k = first; k < last; ++k)
      {
        const Id node = patches[k];
        const Id f = node - re.Base2();
        if (f < 0 || f >= facets)
        {
          foreign[k] = 1;
          continue;
        }
        const CriticalFacet& facet = cs.Facets[f];
        const std::array<Id, 3> own =
          InputSimplex<3>(re, { { facet.Vertices[0], facet.Vertices[1], facet.Vertices[2] } });
        if (!SameSimplex(nodes[node], own))
        {
          foreign[k] = 1;
          continue;
        }
        if (walks.Has(static_cast<std::size_t>(f)))
        {
          // As the build walked it (RecordedWalks.h): the same claims.
          const std::uint32_t begin = walks.Offsets[f], end = walks.Offsets[f + 1];
          fallbacks[k] = walks.FallbacksOf(static_cast<std::size_t>(f));
          claims[k].reserve(end - begin + 1);
          claims[k].push_back(Sides(tri, tri.Cell(facet.Cell), facet.Opposite, { own, node }));
          for (std::uint32_t j = begin; j < end; ++j)
          {
            const CellHandle cell = tri.Cell(RecordedWalks::CellOf(walks.Codes[j]));
            const int opposite = RecordedWalks::OppositeOf(walks.Codes[j]);
            std::array<Id, 3> t;
            for (int i = 0, n = 0; i < 4; ++i)
            {
              if (i != opposite)
              {
                t[n++] = cell->vertex(i)->info();
              }
            }
            claims[k].push_back(Sides(tri, cell, opposite, { InputSimplex<3>(re, t), node }));
          }
          continue;
        }
        const Patch patch = ComputeStableManifold(
          tri, cs, static_cast<std::size_t>(f), false, fallbacks[k], false, true);
        claims[k].reserve(patch.Walked.size() + 1);
        claims[k].push_back(Sides(tri, tri.Cell(facet.Cell), facet.Opposite, { own, node }));
        for (std::size_t j = 0; j < patch.Walked.size(); ++j)
        {
          const std::array<Id, 3>& t = patch.Walked[j];
          const CellHandle cell = patch.WalkedCells[j];
          claims[k].push_back(
            Sides(tri, cell, tri.OppositeOf(cell, t), { InputSimplex<3>(re, t), node }));
        }
      }
    });
  std::size_t total = 0;
  for (std::size_t k = 0; k < patches.size(); ++k)
  {
    if (foreign[k])
    {
      throw InputError(Retriangulation::Mismatch());
    }
    if (fallbacks[k] > 0)
    {
      pieces.ExactFallbacks.emplace_back(patches[k], fallbacks[k]);
    }
    total += claims[k].size();
  }
  // Gathered in turn, each patch's list freed once copied (this is a surface
  // sample's peak: the whole array filled at once would add to it), then
  // sorted in parallel, millions on a solid (a patch between every two of its
  // maxima; the order is total, so it is the sort's alone).
  pieces.Claims.reserve(pieces.Claims.size() + total);
  for (std::vector<Claim>& c : claims)
  {
    pieces.Claims.insert(pieces.Claims.end(), c.begin(), c.end());
    std::vector<Claim>().swap(c);
  }
  tbb::parallel_sort(pieces.Claims.begin(), pieces.Claims.end());
}

/// The triangles the walks of the selected patches cross, each kept once (for
/// the least node id).
void SelectTriangles(const CompactPieces& pieces, const std::vector<char>& isSelected,
  CompactComplex& out, std::vector<const Claim*>& written)
{
  for (const auto& f : pieces.ExactFallbacks)
  {
    out.ExactFallbacks += isSelected[f.first] ? f.second : 0;
  }
  const std::vector<Claim>& all = pieces.Claims;
  for (std::size_t k = 0; k < all.size();)
  {
    std::size_t end = k;
    Id first = -1, last = -1;
    int claims = 0;
    for (; end < all.size() && all[end].Triangle == all[k].Triangle; ++end)
    {
      const Id node = all[end].Node;
      if (!isSelected[node])
      {
        continue;
      }
      claims += node == last ? 0 : 1;
      first = first < 0 ? node : first;
      last = node;
    }
    if (first >= 0)
    {
      out.Triangles.push_back(all[k].Triangle);
      out.TriangleNode.push_back(first);
      out.TriangleClaims.push_back(claims);
      written.push_back(&all[k]);
    }
    k = end;
  }
}

/// The written triangles crossed by two selected walks or twice by one (a
/// triangle's claims follow its first one in pieces.Claims, by node).
void CountSharing(const CompactPieces& pieces, const std::vector<char>& isSelected,
  const std::vector<const Claim*>& written, CompactComplex& out)
{
  const Claim* end = pieces.Claims.data() + pieces.Claims.size();
  for (std::size_t k = 0; k < written.size(); ++k)
  {
    out.SharedTriangles += out.TriangleClaims[k] > 1 ? 1 : 0;
    Id last = -1;
    for (const Claim* c = written[k]; c != end && c->Triangle == written[k]->Triangle; ++c)
    {
      if (isSelected[c->Node] && c->Node == last)
      {
        ++out.RevisitedTriangles;
        break;
      }
      last = isSelected[c->Node] ? c->Node : last;
    }
  }
}

/// The maximum among `maxima` (index-3 node ids, sorted) that each Delaunay
/// cell's Voronoi vertex flows to, -1 for none.
void FlowCells(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& maxima, const Progress& progress, CompactPieces& pieces)
{
  const CriticalSimplices& cs = re.Critical();
  const Triangulation& tri = re.Tri();
  for (const Id node : maxima)
  {
    const Id c = node - re.Base3();
    if (c < 0 || c >= static_cast<Id>(cs.Cells.size()) ||
      !SameSimplex(nodes[node], InputSimplex<4>(re, { { cs.Cells[c].Vertices[0],
        cs.Cells[c].Vertices[1], cs.Cells[c].Vertices[2], cs.Cells[c].Vertices[3] } })))
    {
      throw InputError(Retriangulation::Mismatch());
    }
  }
  // d_P grows along the flow: a flow line that passes the largest value among
  // `maxima` cannot end at one of them, so it is stopped there (on surface
  // samples most lines run on to the medial axis). The margin covers rounding
  // and the perturbation of degenerate clouds (1e-6 of the diagonal).
  double largest = 0;
  for (const Id node : maxima)
  {
    largest = std::max(largest, nodes[node].Value);
  }
  const double limit = 1.01 * std::ldexp(largest, -re.Prepared().ScaleExponent) +
    1e-5 * re.Prepared().Diagonal;
  // The triangulation's own forest: the chains the run's flow lines walked
  // are not walked again.
  SuccessorForest& forest = re.Flow();
  std::vector<std::int32_t>& cellMaximum = pieces.CellMaximum;
  cellMaximum.assign(static_cast<std::size_t>(tri.NumberOfCells()), -1);
  ParallelSlices(tri.NumberOfCells(), Id(1) << 16, progress, 0.6, 0.9, "compact cells",
    [&](Id first, Id last) {
      for (Id c = first; c < last; ++c)
      {
        double bound = 0;
        const Id root = forest.RootBelow(c, limit * limit, &bound);
        cellMaximum[c] = static_cast<std::int32_t>(
          root >= 0 && std::binary_search(maxima.begin(), maxima.end(), root) ? root : -1);
      }
    });
}

/// The Delaunay cells that flow to a selected maximum; `cellNode` (per cell)
/// receives their maximum, -1 for the others. In cell order, as a sequential
/// pass would write them: each block of cells is counted, then written at its
/// offset (a volume sample's solid is millions of cells).
void SelectTetrahedra(const CellView& cells, const CompactPieces& pieces,
  const std::vector<char>& isSelected, CompactComplex& out, std::vector<std::int32_t>& cellNode)
{
  const std::size_t n = static_cast<std::size_t>(cells.Count());
  cellNode.assign(n, -1);
  const std::size_t blocks = (n + CellBlock - 1) / CellBlock;
  std::vector<std::size_t> offset(blocks + 1, 0);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    std::size_t count = 0;
    for (std::size_t c = b * CellBlock; c < std::min(n, (b + 1) * CellBlock); ++c)
    {
      const Id m = pieces.CellMaximum[c];
      if (m >= 0 && isSelected[m])
      {
        cellNode[c] = static_cast<std::int32_t>(m);
        ++count;
      }
    }
    offset[b + 1] = count;
  });
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  const std::size_t first = out.Tetrahedra.size();
  out.Tetrahedra.resize(first + offset.back());
  out.TetrahedronNode.resize(first + offset.back());
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    std::size_t k = first + offset[b];
    for (std::size_t c = b * CellBlock; c < std::min(n, (b + 1) * CellBlock); ++c)
    {
      if (cellNode[c] >= 0)
      {
        out.Tetrahedra[k] = cells.Tetrahedron(static_cast<Id>(c));
        out.TetrahedronNode[k++] = cellNode[c];
      }
    }
  });
}

/// The walls of the complement's regions: per cell, a bit per facet that is
/// a compact triangle. Which node each wall belongs to is read only around
/// the voids being filled (rare), so only their sides are sorted, once the
/// voids are known: every side, made for every search, was 64 MB at 10^6
/// surface points (most of the compact output's peak), and sorted, most of
/// the search for voids of a solid (every wall between its maxima).
struct Walls
{
  /// A triangle seen from one of its cells: (Cell, Facet), then its node.
  struct Side
  {
    std::int32_t Cell;
    std::int32_t Node;
    std::int8_t Facet;
    bool operator<(const Side& o) const
    {
      return std::tie(this->Cell, this->Facet, this->Node) < std::tie(o.Cell, o.Facet, o.Node);
    }
  };
  std::vector<std::uint8_t> Facets;

  /// Keeps the sides of the cells `keep` accepts, for NodeAt.
  template <class Keep>
  void KeepSides(const std::vector<const Claim*>& written, const CompactComplex& out, const Keep& keep)
  {
    this->Sides.clear();
    for (std::size_t k = 0; k < written.size(); ++k)
    {
      for (int side = 0; side < 2; ++side)
      {
        const std::int32_t cell = written[k]->Cells[side];
        if (cell >= 0 && keep(cell))
        {
          this->Sides.push_back(
            Side{ cell, static_cast<std::int32_t>(out.TriangleNode[k]), written[k]->Facets[side] });
        }
      }
    }
    std::sort(this->Sides.begin(), this->Sides.end());
  }

  /// The node of the triangle on facet `facet` of `cell` (a wall of a cell
  /// KeepSides kept); the least one when several triangles share it.
  Id NodeAt(Id cell, int facet) const
  {
    const Side key{ static_cast<std::int32_t>(cell), std::numeric_limits<std::int32_t>::min(),
      static_cast<std::int8_t>(facet) };
    return std::lower_bound(this->Sides.begin(), this->Sides.end(), key)->Node;
  }

private:
  std::vector<Side> Sides;
};

Walls FindWalls(Id cellCount, const std::vector<const Claim*>& written)
{
  Walls walls;
  walls.Facets.assign(static_cast<std::size_t>(cellCount), 0);
  for (const Claim* claim : written)
  {
    for (int side = 0; side < 2; ++side)
    {
      const Id cell = claim->Cells[side];
      if (cell >= 0)
      {
        walls.Facets[cell] |= static_cast<std::uint8_t>(1u << claim->Facets[side]);
      }
    }
  }
  return walls;
}

/// The region of the complement that holds cell `start` (cells joined across
/// facets that are not walls), searched until it is known to be unbounded: it
/// meets an infinite cell or a region searched before (`mark`: the search of
/// each cell, 0 for none; a bounded region is closed by walls, so another
/// search cannot reach it). Returns whether it is bounded; then `component`
/// holds its cells, `maximum` whether one is a maximum, and `walled` whether
/// it meets a wall or a cell of the complex. Millions of cells are crossed per
/// t_r: only what decides boundedness is read here (WallNode does the rest).
/// With `toVoid`, the search stops (false) at a maximum too: such a region is
/// not filled, and only counting the voids needs to know more.
bool SearchRegion(const std::vector<std::int32_t>& cellNode, const Walls& walls,
  const std::vector<char>& isMaximum, const Neighbourhood& neighbours, Id start,
  std::int32_t search, bool toVoid, std::vector<std::int32_t>& mark,
  std::vector<std::int32_t>& component, std::vector<std::int32_t>& stack, bool& walled, bool& maximum)
{
  walled = false;
  maximum = false;
  component.clear();
  stack.assign(1, static_cast<std::int32_t>(start)); // reused: most searches stop within a few cells
  mark[start] = search;
  while (!stack.empty())
  {
    const Id c = stack.back();
    stack.pop_back();
    if (!maximum && isMaximum[c] != 0)
    {
      maximum = true;
      if (toVoid)
      {
        return false;
      }
      // A region with a maximum is not filled: its cells are not needed (a
      // closed surface's inside is millions of them).
      component.clear();
      component.shrink_to_fit();
    }
    if (!maximum)
    {
      component.push_back(static_cast<std::int32_t>(c));
    }
    walled = walled || walls.Facets[c] != 0;
    for (int k = 0; k < 4; ++k)
    {
      if (walls.Facets[c] & (1u << k))
      {
        continue;
      }
      const Id n = neighbours[c][k];
      if (n < 0 || (mark[n] != 0 && mark[n] != search))
      {
        return false;
      }
      if (!cellNode.empty() && cellNode[n] >= 0)
      {
        walled = true;
        continue;
      }
      if (mark[n] == 0)
      {
        mark[n] = search;
        stack.push_back(static_cast<std::int32_t>(n));
      }
    }
  }
  return true;
}

/// The cells a search for voids starts from, in the order a pass over the
/// cells meets them: each cell outside the complex next to a wall, and each
/// neighbour outside the complex of a cell in it. Found in parallel, block by
/// block (a solid is millions of cells, a few of them on its boundary).
std::vector<std::int32_t> SearchStarts(const std::vector<std::int32_t>& cellNode, const Walls& walls,
  const Neighbourhood& neighbours)
{
  const std::size_t n = neighbours.size();
  const std::size_t blocks = (n + CellBlock - 1) / CellBlock;
  std::vector<std::vector<std::int32_t>> found(blocks);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    for (std::size_t c = b * CellBlock; c < std::min(n, (b + 1) * CellBlock); ++c)
    {
      const bool inside = !cellNode.empty() && cellNode[c] >= 0;
      if (!inside && walls.Facets[c] != 0)
      {
        found[b].push_back(static_cast<std::int32_t>(c));
      }
      for (int k = 0; inside && k < 4; ++k)
      {
        const std::int32_t next = neighbours[c][k];
        if (next >= 0 && cellNode[next] < 0)
        {
          found[b].push_back(next);
        }
      }
    }
  });
  std::vector<std::int32_t> starts;
  for (std::vector<std::int32_t>& f : found)
  {
    starts.insert(starts.end(), f.begin(), f.end());
    std::vector<std::int32_t>().swap(f);
  }
  return starts;
}

/// The node of largest value among the walls and complex cells around the
/// bounded region `component` (the least id on ties: no order matters).
Id WallNode(const std::vector<Node>& nodes, const std::vector<std::int32_t>& cellNode, const Walls& walls,
  const Neighbourhood& neighbours, const std::vector<std::int32_t>& component)
{
  Id wall = -1;
  auto meet = [&](Id node) {
    if (wall < 0 || nodes[node].Value > nodes[wall].Value ||
      (nodes[node].Value == nodes[wall].Value && node < wall))
    {
      wall = node;
    }
  };
  for (const Id c : component)
  {
    for (int k = 0; k < 4; ++k)
    {
      if (walls.Facets[c] & (1u << k))
      {
        meet(walls.NodeAt(c, k));
        continue;
      }
      const Id n = neighbours[c][k];
      if (!cellNode.empty() && cellNode[n] >= 0)
      {
        meet(cellNode[n]);
      }
    }
  }
  return wall;
}

/// The bounded regions of the complement of the compact complex (Delaunay
/// cells joined across facets that are not its triangles) that hold no
/// maximum, filled with their cells. Every bounded region of the complement
/// of the exact reconstruction holds the stable manifold of a maximum, hence
/// its Voronoi vertex, so these voids are not the exact one's: they appear
/// where two patches cross the Voronoi edges around a Voronoi vertex, the
/// region between them escaping through Voronoi facets, which no Delaunay
/// simplex stands for. The filling's cells go to the wall node of largest
/// value. Only regions next to a wall are searched, each until it is seen to
/// be unbounded; with `count`, the bounded ones with a maximum are counted in
/// out.Voids (else a search ends at its first maximum). `filled` receives the
/// filling's cells.
void FillVoidsWithoutMaximum(const CellView& cells, const std::vector<Node>& nodes,
  const std::vector<std::int32_t>& cellNode, const Neighbourhood& neighbours,
  const std::vector<const Claim*>& written, bool count, CompactComplex& out,
  std::vector<Id>& filled)
{
  Walls walls = FindWalls(cells.Count(), written);
  const std::vector<char> isMaximum = cells.MaximumFlags();
  std::vector<std::int32_t> mark(static_cast<std::size_t>(cells.Count()), 0);
  std::vector<std::int32_t> component, stack;
  std::int32_t search = 0;
  // Filled in a canonical order (regions by their least cell, cells sorted),
  // which CompactFamily, finding them another way, gives too.
  std::vector<std::pair<std::vector<std::int32_t>, Id>> fills;
  // A search from each cell next to a wall or to the complex's cells, in cell
  // order, as they are met.
  const auto searchFrom = [&](Id start) {
    if (mark[start] != 0)
    {
      return;
    }
    bool walled = false;
    bool maximum = false;
    if (!SearchRegion(cellNode, walls, isMaximum, neighbours, start, ++search, !count, mark,
          component, stack, walled, maximum) ||
      !walled)
    {
      return;
    }
    if (maximum)
    {
      ++out.Voids; // a void of the exact reconstruction too
      return;
    }
    ++out.FilledVoids;
    std::sort(component.begin(), component.end());
    fills.emplace_back(component, search); // its wall node below
  };
  for (const std::int32_t start : SearchStarts(cellNode, walls, neighbours))
  {
    searchFrom(start);
  }
  if (!fills.empty())
  {
    // A filled region's cells keep the mark of its search.
    std::vector<std::int32_t> fillOf(static_cast<std::size_t>(search) + 1, -1);
    for (std::size_t k = 0; k < fills.size(); ++k)
    {
      fillOf[static_cast<std::size_t>(fills[k].second)] = static_cast<std::int32_t>(k);
    }
    walls.KeepSides(written, out, [&](std::int32_t cell) { return fillOf[mark[cell]] >= 0; });
    for (auto& fill : fills)
    {
      fill.second = WallNode(nodes, cellNode, walls, neighbours, fill.first);
    }
  }
  std::sort(fills.begin(), fills.end());
  for (const auto& fill : fills)
  {
    for (const Id c : fill.first)
    {
      out.Tetrahedra.push_back(cells.Tetrahedron(c));
      out.TetrahedronNode.push_back(fill.second);
      filled.push_back(c);
    }
  }
}

/// Leaves out the triangles that are facets of a tetrahedron of `out` (a
/// Delaunay cell of a selected maximum, `cellNode`, or of a filled void,
/// `filled`): the tetrahedra hold them already, so the union is the same, and
/// a volume sample's solid is written as its tetrahedra alone instead of with
/// every wall between their maxima (about 7 triangles a sample more).
void DropCoveredTriangles(
  const std::vector<char>& solid, std::vector<const Claim*>& written, CompactComplex& out)
{
  if (out.Tetrahedra.empty())
  {
    return;
  }
  std::vector<char> covered(out.Triangles.size(), 0);
  for (std::size_t k = 0; k < out.Triangles.size(); ++k)
  {
    const Claim& claim = *written[k];
    covered[k] = (claim.Cells[0] >= 0 && solid[claim.Cells[0]]) ||
      (claim.Cells[1] >= 0 && solid[claim.Cells[1]]);
  }
  out.DropTriangles(covered, written);
}

/// Per cell, whether it is a tetrahedron of the output: it flows to a
/// selected maximum (`cellNode`) or fills a void (`filled`). Empty without
/// tetrahedra.
std::vector<char> SolidCells(
  Id cellCount, const std::vector<std::int32_t>& cellNode, const std::vector<Id>& filled)
{
  if (cellNode.empty() && filled.empty())
  {
    return {};
  }
  std::vector<char> solid(static_cast<std::size_t>(cellCount), 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, cellNode.size(), CellBlock),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t c = r.begin(); c != r.end(); ++c)
      {
        solid[c] = cellNode[c] >= 0 ? 1 : 0;
      }
    });
  for (const Id c : filled)
  {
    solid[c] = 1;
  }
  return solid;
}

/// The distinct facets of the solid cells: two cells of a triangulation share
/// a facet only across it, so each facet counts once, from its cell of least
/// id among the solid ones. Linear, where a sort of every facet of a solid's
/// tetrahedra (4 a cell) was a third of its Betti numbers.
Id SolidFacets(const std::vector<char>& solid, const Neighbourhood& neighbours)
{
  return tbb::parallel_reduce(tbb::blocked_range<std::size_t>(0, solid.size(), CellBlock), Id(0),
    [&](const tbb::blocked_range<std::size_t>& r, Id count) {
      for (std::size_t c = r.begin(); c != r.end(); ++c)
      {
        for (int k = 0; solid[c] && k < 4; ++k)
        {
          const std::int32_t n = neighbours[c][k];
          count += n < 0 || !solid[n] || static_cast<std::size_t>(n) > c ? 1 : 0;
        }
      }
      return count;
    },
    std::plus<Id>());
}

/// Index-1 and index-0 nodes whose edge or sample no triangle or tetrahedron
/// holds. Linear: the selected edges are grouped by their first vertex, which
/// each edge of a triangle or tetrahedron looks up (a sort of every such edge
/// took a third of a t_r change).
void AddEdgesAndSamples(
  const std::vector<Node>& nodes, const std::vector<Id>& selected, CompactComplex& out)
{
  Id points = 0; // input ids below it
  std::vector<Id> edgeNodes;
  for (const Id node : selected)
  {
    const Node& n = nodes[node];
    if (n.Index == 1 || (n.Index == 0 && !n.IsInfinity()))
    {
      points = std::max(points, static_cast<Id>(n.Simplex[n.Index]) + 1);
    }
    if (n.Index == 1)
    {
      edgeNodes.push_back(node);
    }
  }
  for (const std::array<Id, 3>& t : out.Triangles)
  {
    points = std::max(points, t[2] + 1);
  }
  for (const std::array<Id, 4>& t : out.Tetrahedra)
  {
    points = std::max(points, t[3] + 1);
  }
  // Selected edges by first vertex (counting sort), and whether each is held.
  std::vector<Id> row(static_cast<std::size_t>(points) + 1, 0);
  for (const Id node : edgeNodes)
  {
    ++row[nodes[node].Simplex[0] + 1];
  }
  for (std::size_t v = 1; v < row.size(); ++v)
  {
    row[v] += row[v - 1];
  }
  // With each edge's second vertex beside it: the holding test below reads
  // them row by row instead of the nodes at random.
  std::vector<Id> byFirst(edgeNodes.size()), secondByFirst(edgeNodes.size());
  {
    std::vector<Id> next(row.begin(), row.end() - 1);
    for (std::size_t e = 0; e < edgeNodes.size(); ++e)
    {
      const Node& n = nodes[edgeNodes[e]];
      const Id j = next[n.Simplex[0]]++;
      byFirst[j] = static_cast<Id>(e);
      secondByFirst[j] = n.Simplex[1];
    }
  }
  std::vector<std::atomic<std::uint8_t>> held(edgeNodes.size());
  std::vector<std::atomic<std::uint8_t>> used(static_cast<std::size_t>(points));
  auto hold = [&](const Id* v, int n) {
    for (int a = 0; a < n; ++a)
    {
      Raise(used[v[a]]);
      for (int b = a + 1; b < n; ++b) // sorted simplices: v[a] < v[b]
      {
        for (Id j = row[v[a]]; j < row[v[a] + 1]; ++j)
        {
          if (secondByFirst[j] == v[b])
          {
            Raise(held[byFirst[j]]);
          }
        }
      }
    }
  };
  // In parallel (a solid is millions of tetrahedra): flags are only raised,
  // so the order does not matter.
  const std::size_t triangles = out.Triangles.size();
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, triangles + out.Tetrahedra.size(), CellBlock),
    [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t k = r.begin(); k != r.end(); ++k)
      {
        if (k < triangles)
        {
          hold(out.Triangles[k].data(), 3);
        }
        else
        {
          hold(out.Tetrahedra[k - triangles].data(), 4);
        }
      }
    });
  for (std::size_t e = 0; e < edgeNodes.size(); ++e)
  {
    const Node& n = nodes[edgeNodes[e]];
    if (!held[e])
    {
      out.Edges.push_back({ { n.Simplex[0], n.Simplex[1] } });
      out.EdgeNode.push_back(edgeNodes[e]);
      used[n.Simplex[0]] = 1;
      used[n.Simplex[1]] = 1;
    }
  }
  for (const Id node : selected)
  {
    const Node& n = nodes[node];
    if (n.Index == 0 && !n.IsInfinity() && !used[n.Simplex[0]])
    {
      out.Vertices.push_back(n.Simplex[0]);
      out.VertexNode.push_back(node);
    }
  }
}

/// `selected` sorted, without repeats or the maximum at infinity; throws
/// InputError for an id out of range.
std::vector<Id> SortedNodes(const std::vector<Node>& nodes, const std::vector<Id>& selected)
{
  std::vector<Id> sorted;
  for (const Id node : selected)
  {
    if (node < 0 || node >= static_cast<Id>(nodes.size()))
    {
      throw InputError("compact reconstruction: node " + std::to_string(node) + " out of range");
    }
    if (!nodes[node].IsInfinity())
    {
      sorted.push_back(node);
    }
  }
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  return sorted;
}

/// The number of distinct keys among those `emit(i, add)` gives for the items
/// i in [0, items) (key = (first vertex, rest)): counting sort on the first
/// vertex, then each row sorted on its own. Both passes over the items run in
/// parallel, taking their slots atomically: the order within a row depends on
/// the schedule, its sorted content and so the count do not. A global sort of
/// every face of every tetrahedron (26 million at 10^6 volume samples) took
/// seconds and a gigabyte.
template <class Emit>
Id CountDistinct(Id points, std::size_t items, const Emit& emit)
{
  const auto overItems = [&](const auto& add) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, items, CellBlock),
      [&](const tbb::blocked_range<std::size_t>& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
        {
          emit(i, add);
        }
      });
  };
  // Per first vertex: its row's size, then the next free slot in its row.
  std::vector<std::atomic<Id>> slot(static_cast<std::size_t>(points) + 1);
  overItems([&](Id first, std::uint64_t) { slot[first + 1].fetch_add(1, std::memory_order_relaxed); });
  std::vector<Id> row(static_cast<std::size_t>(points) + 1, 0);
  for (std::size_t v = 1; v < row.size(); ++v)
  {
    row[v] = row[v - 1] + slot[v].load(std::memory_order_relaxed);
  }
  for (std::size_t v = 0; v < row.size(); ++v)
  {
    slot[v].store(row[v], std::memory_order_relaxed);
  }
  std::vector<std::uint64_t> rest(static_cast<std::size_t>(row.back()));
  overItems([&](Id first, std::uint64_t key) {
    rest[static_cast<std::size_t>(slot[first].fetch_add(1, std::memory_order_relaxed))] = key;
  });
  return tbb::parallel_reduce(tbb::blocked_range<Id>(0, points), Id(0),
    [&](const tbb::blocked_range<Id>& r, Id count) {
      for (Id v = r.begin(); v != r.end(); ++v)
      {
        const auto first = rest.begin() + row[v], last = rest.begin() + row[v + 1];
        std::sort(first, last);
        count += std::unique(first, last) - first;
      }
      return count;
    },
    std::plus<Id>());
}

/// b0 by union-find over the cells' vertices; b2 = out.Voids by Alexander
/// duality (the complex lies in a triangulation of R^3: its voids are the
/// bounded regions of the complement); b1 from the Euler characteristic
/// V - E + F - T = b0 - b1 + b2, counting the distinct faces of the cells
/// (`tetrahedronFacets`: those of the tetrahedra, SolidFacets).
/// Needs DropCoveredTriangles first: F adds the written triangles to the
/// tetrahedra's distinct facets, so none may be one of those facets.
/// Linear but for short per-vertex sorts, where cell homology of millions of
/// triangles reduces a large H1 matrix (50 s at 10^6 sphere points).
void SetBettiNumbers(CompactComplex& out, Id tetrahedronFacets)
{
  Id points = 0;
  for (const Id v : out.Vertices)
  {
    points = std::max(points, v + 1);
  }
  for (const auto& e : out.Edges)
  {
    points = std::max(points, e[1] + 1);
  }
  for (const auto& t : out.Triangles)
  {
    points = std::max(points, t[2] + 1);
  }
  for (const auto& t : out.Tetrahedra)
  {
    points = std::max(points, t[3] + 1);
  }
  // Simplices are sorted (input ids): an edge's first vertex is its least.
  const Id faces = static_cast<Id>(out.Triangles.size()) + tetrahedronFacets;
  const std::size_t triangles = out.Triangles.size();
  const Id edges = static_cast<Id>(out.Edges.size()) +
    CountDistinct(points, triangles + out.Tetrahedra.size(), [&](std::size_t i, const auto& add) {
      if (i < triangles)
      {
        const std::array<Id, 3>& t = out.Triangles[i];
        add(t[0], static_cast<std::uint64_t>(t[1]));
        add(t[0], static_cast<std::uint64_t>(t[2]));
        add(t[1], static_cast<std::uint64_t>(t[2]));
        return;
      }
      const std::array<Id, 4>& t = out.Tetrahedra[i - triangles];
      for (int a = 0; a < 4; ++a)
      {
        for (int b = a + 1; b < 4; ++b)
        {
          add(t[a], static_cast<std::uint64_t>(t[b]));
        }
      }
    });
  std::vector<char> used(static_cast<std::size_t>(points), 0);
  UnionFind components(static_cast<std::size_t>(points));
  JoinCells(out, points, used, components);
  Id vertices = 0, b0 = 0;
  for (Id v = 0; v < points; ++v)
  {
    vertices += used[v];
    b0 += used[v] && components.Find(static_cast<std::int32_t>(v)) == v ? 1 : 0;
  }
  const Id chi = vertices - edges + faces - static_cast<Id>(out.Tetrahedra.size());
  out.Betti = { { b0, b0 + out.Voids - chi, out.Voids, 0 } };
}

} // namespace

CompactPieces PrepareCompact(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& candidates, const Progress& progress, bool releaseFlow)
{
  std::vector<Id> patches, maxima;
  for (const Id node : SortedNodes(nodes, candidates))
  {
    if (nodes[node].Index == 2)
    {
      patches.push_back(node);
    }
    else if (nodes[node].Index == 3)
    {
      maxima.push_back(node);
    }
  }
  CompactPieces pieces;
  // The patches' walks do not follow the flow, the maxima's cells do: without
  // a maximum it goes first (13 bytes a cell; the walks' lists are a
  // surface sample's peak).
  if (releaseFlow && maxima.empty())
  {
    re.ReleaseFlow();
  }
  WalkPatches(re, nodes, patches, progress, pieces);
  if (releaseFlow)
  {
    re.ReleaseWalks();
  }
  if (!maxima.empty())
  {
    FlowCells(re, nodes, maxima, progress, pieces);
    if (releaseFlow)
    {
      re.ReleaseFlow();
    }
  }
  // After the walks, whose per-patch lists set that peak: 16 bytes a cell
  // less there.
  pieces.Neighbours = Neighbours(re.Tri());
  progress(1.0, "compact pieces");
  return pieces;
}

namespace
{

CompactComplex Select(const CellView& cells, const std::vector<Node>& nodes,
  const CompactPieces& pieces, const std::vector<Id>& selected, bool betti)
{
  const std::vector<Id> sorted = SortedNodes(nodes, selected);
  std::vector<char> isSelected(nodes.size(), 0);
  bool maximum = false;
  for (const Id node : sorted)
  {
    isSelected[node] = 1;
    maximum = maximum || nodes[node].Index == 3;
  }
  CompactComplex out;
  std::vector<const Claim*> written; // the claim of each triangle
  SelectTriangles(pieces, isSelected, out, written);
  std::vector<std::int32_t> cellNode; // empty without a selected maximum
  if (maximum && !pieces.CellMaximum.empty())
  {
    SelectTetrahedra(cells, pieces, isSelected, out, cellNode);
  }
  std::vector<Id> filled;
  FillVoidsWithoutMaximum(cells, nodes, cellNode, pieces.Neighbours, written, betti, out, filled);
  const std::vector<char> solid = SolidCells(cells.Count(), cellNode, filled);
  DropCoveredTriangles(solid, written, out);
  CountSharing(pieces, isSelected, written, out);
  AddEdgesAndSamples(nodes, sorted, out);
  if (betti)
  {
    SetBettiNumbers(out, solid.empty() ? 0 : SolidFacets(solid, pieces.Neighbours));
  }
  return out;
}

} // namespace

CompactComplex SelectCompact(const Retriangulation& re, const std::vector<Node>& nodes,
  const CompactPieces& pieces, const std::vector<Id>& selected, bool betti)
{
  return Select(CellView(re), nodes, pieces, selected, betti);
}

CompactComplex SelectCompact(const CompactCells& cells, const std::vector<Node>& nodes,
  const CompactPieces& pieces, const std::vector<Id>& selected, bool betti)
{
  return Select(CellView(cells), nodes, pieces, selected, betti);
}

namespace
{

std::array<std::int32_t, 4> VerticesOfCell(const Retriangulation& re, Id c)
{
  const Triangulation& tri = re.Tri();
  const std::array<Id, 4> t = InputSimplex<4>(re, tri.SortedVertices(tri.Cell(c)));
  return { { static_cast<std::int32_t>(t[0]), static_cast<std::int32_t>(t[1]),
    static_cast<std::int32_t>(t[2]), static_cast<std::int32_t>(t[3]) } };
}

void RequireNarrowIds(const Retriangulation& re)
{
  if (re.Prepared().InputId.size() > static_cast<std::size_t>(INT32_MAX))
  {
    throw InputError("compact output: more than 2^31 samples");
  }
}

} // namespace

CompactCells CellsOf(const Retriangulation& re)
{
  const Triangulation& tri = re.Tri();
  RequireNarrowIds(re);
  CompactCells cells;
  cells.Vertices.resize(static_cast<std::size_t>(tri.NumberOfCells()));
  ParallelSlices(tri.NumberOfCells(), Id(1) << 16, Progress(), 0.0, 0.0, "compact cells",
    [&](Id from, Id to) {
      for (Id c = from; c < to; ++c)
      {
        cells.Vertices[c] = VerticesOfCell(re, c);
      }
    });
  cells.Maxima = MaximumCells(re);
  return cells;
}

std::vector<std::array<std::int32_t, 4>> VerticesOfCells(
  const Retriangulation& re, const std::vector<std::int32_t>& ids)
{
  RequireNarrowIds(re);
  std::vector<std::array<std::int32_t, 4>> vertices(ids.size());
  ParallelSlices(static_cast<Id>(ids.size()), Id(1) << 16, Progress(), 0.0, 0.0, "compact cells",
    [&](Id from, Id to) {
      for (Id k = from; k < to; ++k)
      {
        vertices[static_cast<std::size_t>(k)] = VerticesOfCell(re, ids[static_cast<std::size_t>(k)]);
      }
    });
  return vertices;
}

std::vector<std::int32_t> MaximumCells(const Retriangulation& re)
{
  std::vector<std::int32_t> maxima;
  maxima.reserve(re.Critical().Cells.size());
  for (const CriticalCell& c : re.Critical().Cells)
  {
    maxima.push_back(static_cast<std::int32_t>(c.Cell));
  }
  return maxima;
}

CompactComplex CompactReconstruction(const Retriangulation& re, const std::vector<Node>& nodes,
  const std::vector<Id>& selected, const Progress& progress, bool releaseFlow)
{
  const CompactPieces pieces = PrepareCompact(re, nodes, selected, progress.Range(0, 0.9), releaseFlow);
  progress(0.9, "compact voids");
  CompactComplex out = SelectCompact(re, nodes, pieces, selected);
  progress(1.0, "compact output");
  return out;
}

std::array<Id, 4> CompactBettiNumbers(const CompactComplex& compact)
{
  FilteredCells cells;
  for (const Id& v : compact.Vertices)
  {
    cells.Add(&v, 1, 0);
  }
  for (const std::array<Id, 2>& e : compact.Edges)
  {
    cells.Add(e.data(), 2, 0);
  }
  for (const std::array<Id, 3>& t : compact.Triangles)
  {
    cells.Add(t.data(), 3, 0);
  }
  for (const std::array<Id, 4>& t : compact.Tetrahedra)
  {
    cells.Add(t.data(), 4, 0);
  }
  return BettiNumbersBelow(CellBarcode(cells), 1);
}

void JoinCells(const CompactComplex& cells, Id points, std::vector<char>& used, UnionFind& components)
{
  const auto hold = [&](const Id* v, int n) {
    for (int a = 0; a < n; ++a)
    {
      if (v[a] < 0 || v[a] >= points)
      {
        return;
      }
    }
    for (int a = 0; a < n; ++a)
    {
      used[static_cast<std::size_t>(v[a])] = 1;
      components.Merge(static_cast<std::int32_t>(v[0]), static_cast<std::int32_t>(v[a]));
    }
  };
  for (const Id& v : cells.Vertices)
  {
    hold(&v, 1);
  }
  for (const auto& e : cells.Edges)
  {
    hold(e.data(), 2);
  }
  for (const auto& t : cells.Triangles)
  {
    hold(t.data(), 3);
  }
  for (const auto& t : cells.Tetrahedra)
  {
    hold(t.data(), 4);
  }
}

} // namespace flowrecon
