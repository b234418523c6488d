#include "CompactFamily.h"

#include "Retriangulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace flowrecon
{

namespace
{

/// The least selected node among a triangle's claims (sorted by node), the
/// number of distinct selected ones, and whether one walk crosses it twice.
struct Claimers
{
  Id First = -1;
  int Count = 0;
  bool Revisited = false;
};

template <class In>
Claimers ClaimersOf(const CompactClaim* begin, const CompactClaim* end, const In& in)
{
  Claimers c;
  Id last = -1;
  for (const CompactClaim* k = begin; k != end; ++k)
  {
    if (!in(k->Node))
    {
      continue;
    }
    c.Revisited = c.Revisited || k->Node == last;
    c.Count += k->Node == last ? 0 : 1;
    c.First = c.First < 0 ? k->Node : c.First;
    last = k->Node;
  }
  return c;
}

} // namespace

CompactFamily::CompactFamily(const FlowComplex& fc, const std::vector<Id>& carriers,
  const ReconstructionResult& run, double tmax, std::unique_ptr<Retriangulation> re,
  const Progress& progress, const std::string& advice)
  : FC(fc)
  , Tmax(tmax)
{
  if (!re)
  {
    re = Retriangulation::OfStoredComplex(fc, progress.Range(0, 0.4), advice);
  }
  const std::vector<Node>& nodes = fc.Nodes;
  this->NodeEntry.assign(nodes.size(), HUGE_VAL);
  for (std::size_t i = 0; i < carriers.size() && i < nodes.size(); ++i)
  {
    if (carriers[i] >= 0 && run.Contains(carriers[i], tmax) && !nodes[i].IsInfinity())
    {
      this->NodeEntry[i] = run.Nodes[carriers[i]].Threshold;
      this->Candidates.push_back(static_cast<Id>(i));
    }
  }
  // The family is the triangulation's last user: its flow lines and recorded
  // walks go as soon as the pieces no longer read them (before the search for
  // voids, which runs while it is still held).
  this->Pieces = PrepareCompact(*re, nodes, this->Candidates, progress.Range(0.4, 0.85), true);

  // The claims of each triangle, and the threshold above which it is written.
  const std::vector<CompactClaim>& claims = this->Pieces.Claims;
  for (std::size_t k = 0; k < claims.size();)
  {
    std::size_t end = k;
    double entry = HUGE_VAL;
    for (; end < claims.size() && claims[end].Triangle == claims[k].Triangle; ++end)
    {
      entry = std::min(entry, this->NodeEntry[claims[end].Node]);
    }
    this->GroupStart.push_back(k);
    this->GroupEntry.push_back(entry);
    k = end;
  }
  this->GroupStart.push_back(claims.size());
  const std::vector<std::int32_t>& cellMaximum = this->Pieces.CellMaximum;
  const auto solidAbove = [&](std::int32_t c) {
    return c < 0 || cellMaximum.empty() || cellMaximum[c] < 0 ? HUGE_VAL
                                                              : this->NodeEntry[cellMaximum[c]];
  };
  this->GroupCover.resize(this->GroupEntry.size());
  for (std::size_t g = 0; g < this->GroupEntry.size(); ++g)
  {
    const std::array<std::int32_t, 2>& sides = claims[this->GroupStart[g]].Cells;
    this->GroupCover[g] = std::min(solidAbove(sides[0]), solidAbove(sides[1]));
  }
  for (std::size_t c = 0; c < cellMaximum.size(); ++c)
  {
    if (cellMaximum[c] >= 0)
    {
      this->SolidCells.push_back(static_cast<std::int32_t>(c));
    }
  }
  progress(0.9, "compact voids");

  VoidSweepInput sweep;
  sweep.Neighbours = &this->Pieces.Neighbours;
  sweep.CellMaximum = &cellMaximum;
  sweep.NodeEntry = &this->NodeEntry;
  sweep.Claims = &claims;
  sweep.GroupStart = &this->GroupStart;
  sweep.GroupEntry = &this->GroupEntry;
  const std::vector<std::int32_t> maxima = MaximumCells(*re);
  sweep.Maxima = &maxima;
  this->Voids = SweepVoids(sweep, progress.Range(0.9, 0.97));
  std::vector<std::array<std::int32_t, 4>>().swap(this->Pieces.Neighbours);
  // Of the cells, a t_r change writes the solid ones and those of voids: their
  // vertices are kept, not every cell's (10^6 torus points: 17 M cells, 0.27
  // GB, which a table made before the triangulation is freed added to the
  // filter's peak).
  this->SolidVertices = VerticesOfCells(*re, this->SolidCells);
  {
    std::vector<std::int32_t> voidCells(this->Voids.size());
    for (std::size_t v = 0; v < voidCells.size(); ++v)
    {
      voidCells[v] = this->Voids[v].Cell;
    }
    this->VoidVertices = VerticesOfCells(*re, voidCells);
  }
  re.reset(); // the tables above are what a t_r change reads

  // When a triangle or a solid cell holds each candidate edge, and when any
  // written cell or selected edge uses each candidate sample. Edges are found
  // from their first vertex (counting sort), as AddEdgesAndSamples does.
  // Every input id read below is under `points` (a stored complex is trusted
  // no further than its largest id).
  std::size_t points = static_cast<std::size_t>(std::max<Id>(fc.NumberOfInputPoints, 0));
  for (const Id node : this->Candidates)
  {
    const Node& n = nodes[node];
    if (n.Index <= 1)
    {
      (n.Index == 1 ? this->Edges : this->Samples)
        .push_back({ node, { { n.Simplex[0], n.Index == 1 ? n.Simplex[1] : -1 } },
          this->NodeEntry[node], HUGE_VAL });
      points = std::max(points, static_cast<std::size_t>(n.Simplex[n.Index]) + 1);
    }
  }
  for (const CompactClaim& c : claims)
  {
    points = std::max(points, static_cast<std::size_t>(c.Triangle[2]) + 1);
  }
  for (const auto& v : this->SolidVertices)
  {
    points = std::max(points, static_cast<std::size_t>(v[3]) + 1);
  }
  std::vector<double> usedAbove(points, HUGE_VAL);
  std::vector<std::size_t> row(points + 1, 0);
  for (const Lone& e : this->Edges)
  {
    ++row[e.Simplex[0] + 1];
    usedAbove[e.Simplex[0]] = std::min(usedAbove[e.Simplex[0]], e.Entry);
    usedAbove[e.Simplex[1]] = std::min(usedAbove[e.Simplex[1]], e.Entry);
  }
  for (std::size_t v = 1; v < row.size(); ++v)
  {
    row[v] += row[v - 1];
  }
  std::vector<std::pair<std::int32_t, std::size_t>> second(row.back()); // (vertex, edge)
  {
    std::vector<std::size_t> next(row.begin(), row.end() - 1);
    for (std::size_t k = 0; k < this->Edges.size(); ++k)
    {
      second[next[this->Edges[k].Simplex[0]]++] = { this->Edges[k].Simplex[1], k };
    }
  }
  const auto touch = [&](const auto& v, int count, double key) {
    for (int a = 0; a < count; ++a)
    {
      usedAbove[v[a]] = std::min(usedAbove[v[a]], key);
      for (int b = a + 1; b < count; ++b) // sorted simplices: v[a] < v[b]
      {
        for (std::size_t j = row[v[a]]; j < row[v[a] + 1]; ++j)
        {
          if (second[j].first == v[b])
          {
            double& held = this->Edges[second[j].second].HeldAbove;
            held = std::min(held, key);
          }
        }
      }
    }
  };
  for (std::size_t g = 0; g + 1 < this->GroupStart.size(); ++g)
  {
    touch(claims[this->GroupStart[g]].Triangle, 3, this->GroupEntry[g]);
  }
  for (std::size_t k = 0; k < this->SolidCells.size(); ++k)
  {
    touch(this->SolidVertices[k], 4, this->NodeEntry[cellMaximum[this->SolidCells[k]]]);
  }
  for (Lone& s : this->Samples)
  {
    s.HeldAbove = usedAbove[s.Simplex[0]];
  }
  progress(1.0, "compact pieces");
}

CompactFamily::~CompactFamily() = default;

CompactComplex CompactFamily::At(double tr, std::vector<double>& nodeThreshold) const
{
  CompactComplex out;
  this->At(tr, nodeThreshold, out);
  return out;
}

void CompactFamily::At(double tr, std::vector<double>& nodeThreshold, CompactComplex& out) const
{
  const double t = std::min(tr, this->Tmax);
  const std::vector<Node>& nodes = this->FC.Nodes;
  const auto in = [&](Id node) { return this->NodeEntry[node] < t; };
  const std::vector<std::int32_t>& cellMaximum = this->Pieces.CellMaximum;
  const auto solid = [&](std::int32_t c) {
    return c >= 0 && !cellMaximum.empty() && cellMaximum[c] >= 0 && in(cellMaximum[c]);
  };
  const auto tetrahedron = [](const std::array<std::int32_t, 4>& v) {
    return std::array<Id, 4>{ { v[0], v[1], v[2], v[3] } };
  };
  nodeThreshold.assign(nodes.size(), std::nan(""));
  for (const Id node : this->Candidates)
  {
    nodeThreshold[node] = in(node) ? this->NodeEntry[node] : nodeThreshold[node];
  }
  // Emptied, not freed.
  for (auto* v : { &out.Vertices, &out.VertexNode, &out.EdgeNode, &out.TriangleNode,
         &out.TetrahedronNode })
  {
    v->clear();
  }
  out.Edges.clear();
  out.Triangles.clear();
  out.TriangleClaims.clear();
  out.TriangleThreshold.clear();
  out.Tetrahedra.clear();
  out.SharedTriangles = out.RevisitedTriangles = out.FilledVoids = out.Voids = 0;
  out.Betti = { { 0, 0, 0, 0 } };
  out.ExactFallbacks = 0;
  for (const auto& f : this->Pieces.ExactFallbacks)
  {
    out.ExactFallbacks += in(f.first) ? f.second : 0;
  }

  // Triangles, in the claims' order, each for its least selected node.
  const CompactClaim* claims = this->Pieces.Claims.data();
  const std::size_t groups = this->GroupEntry.size();
  // Counted first: growing these by doubling copied and faulted in ~3 times
  // the memory of a surface's triangles.
  std::size_t triangles = 0, tetrahedra = 0;
  for (std::size_t g = 0; g < groups; ++g)
  {
    triangles += this->GroupEntry[g] < t ? 1 : 0;
  }
  for (const std::int32_t c : this->SolidCells)
  {
    tetrahedra += in(cellMaximum[c]) ? 1 : 0;
  }
  out.Triangles.reserve(triangles);
  out.TriangleNode.reserve(triangles);
  out.TriangleClaims.reserve(triangles);
  out.TriangleThreshold.reserve(triangles);
  out.Tetrahedra.reserve(tetrahedra);
  out.TetrahedronNode.reserve(tetrahedra);
  std::vector<std::size_t>& written = this->Written; // the group of each triangle
  written.clear();
  written.reserve(triangles);
  for (std::size_t g = 0; g < groups; ++g)
  {
    if (!(this->GroupEntry[g] < t))
    {
      continue;
    }
    const std::size_t b = this->GroupStart[g], e = this->GroupStart[g + 1];
    const Claimers c = e - b == 1 ? Claimers{ claims[b].Node, 1, false }
                                  : ClaimersOf(claims + b, claims + e, in);
    out.Triangles.push_back(claims[b].Triangle);
    out.TriangleNode.push_back(c.First);
    out.TriangleClaims.push_back(c.Count);
    out.TriangleThreshold.push_back(e - b == 1 ? this->GroupEntry[g] : this->NodeEntry[c.First]);
    written.push_back(g);
  }
  for (std::size_t k = 0; k < this->SolidCells.size(); ++k)
  {
    const std::int32_t c = this->SolidCells[k];
    if (in(cellMaximum[c]))
    {
      out.Tetrahedra.push_back(tetrahedron(this->SolidVertices[k]));
      out.TetrahedronNode.push_back(cellMaximum[c]);
    }
  }

  // The voids to fill at t: regions of the void cells in range, each written
  // in cell order for its wall node of largest value (least id on ties), in
  // the order of their least cell, as FillVoidsWithoutMaximum writes them.
  const std::vector<VoidCell>& voids = this->Voids;
  const auto active = [&](std::size_t i) { return voids[i].Low < t && t <= voids[i].High; };
  const auto indexOf = [&](std::int32_t cell) {
    const auto it = std::lower_bound(voids.begin(), voids.end(), cell,
      [](const VoidCell& v, std::int32_t c) { return v.Cell < c; });
    if (it == voids.end() || it->Cell != cell || !active(static_cast<std::size_t>(it - voids.begin())))
    {
      throw std::logic_error("compact family: a void reaches a cell outside the voids");
    }
    return static_cast<std::size_t>(it - voids.begin());
  };
  const auto wallAt = [&](std::int32_t g) { return g >= 0 && this->GroupEntry[g] < t; };
  std::vector<char> visited(voids.size(), 0);
  std::vector<std::size_t> region, stack;
  std::vector<std::int32_t> filled;   // their cells
  std::vector<std::size_t> filledAt; // and their places in voids
  for (std::size_t i = 0; i < voids.size(); ++i)
  {
    if (visited[i] || !active(i))
    {
      continue;
    }
    region.clear();
    stack.assign(1, i);
    visited[i] = 1;
    while (!stack.empty())
    {
      const std::size_t v = stack.back();
      stack.pop_back();
      region.push_back(v);
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t n = voids[v].Neighbours[k];
        if (wallAt(voids[v].Walls[k]) || solid(n))
        {
          continue;
        }
        if (n < 0)
        {
          throw std::logic_error("compact family: a void reaches the infinite cells");
        }
        const std::size_t j = indexOf(n);
        if (!visited[j])
        {
          visited[j] = 1;
          stack.push_back(j);
        }
      }
    }
    std::sort(region.begin(), region.end()); // voids are sorted by cell
    Id wall = -1;
    const auto meet = [&](Id node) {
      if (wall < 0 || nodes[node].Value > nodes[wall].Value ||
        (nodes[node].Value == nodes[wall].Value && node < wall))
      {
        wall = node;
      }
    };
    for (const std::size_t v : region)
    {
      for (int k = 0; k < 4; ++k)
      {
        const std::int32_t g = voids[v].Walls[k];
        if (wallAt(g))
        {
          meet(ClaimersOf(claims + this->GroupStart[g], claims + this->GroupStart[g + 1], in).First);
        }
        else if (solid(voids[v].Neighbours[k]))
        {
          meet(cellMaximum[voids[v].Neighbours[k]]);
        }
      }
    }
    ++out.FilledVoids;
    for (const std::size_t v : region)
    {
      out.Tetrahedra.push_back(tetrahedron(this->VoidVertices[v]));
      out.TetrahedronNode.push_back(wall);
      filled.push_back(voids[v].Cell);
      filledAt.push_back(v);
    }
  }
  std::sort(filled.begin(), filled.end());
  const auto isFilled = [&](std::int32_t c) {
    return !filled.empty() && std::binary_search(filled.begin(), filled.end(), c);
  };

  // Triangles that are facets of a written tetrahedron are left out.
  if (!out.Tetrahedra.empty())
  {
    std::vector<char>& drop = this->Drop;
    drop.assign(written.size(), 0);
    for (std::size_t k = 0; k < written.size(); ++k)
    {
      const std::array<std::int32_t, 2>& sides = claims[this->GroupStart[written[k]]].Cells;
      drop[k] = this->GroupCover[written[k]] < t ||
        (!filled.empty() && (isFilled(sides[0]) || isFilled(sides[1])));
    }
    out.DropTriangles(drop, written);
  }
  for (std::size_t k = 0; k < written.size(); ++k)
  {
    out.SharedTriangles += out.TriangleClaims[k] > 1 ? 1 : 0;
    const std::size_t g = written[k];
    if (this->GroupStart[g + 1] - this->GroupStart[g] > 1 &&
      ClaimersOf(claims + this->GroupStart[g], claims + this->GroupStart[g + 1], in).Revisited)
    {
      ++out.RevisitedTriangles;
    }
  }

  // Edges no written cell holds and samples no cell or edge uses, by node id;
  // a filled void's cells hold what they touch.
  std::vector<std::pair<std::int32_t, std::int32_t>> filledEdges;
  std::vector<std::int32_t> filledPoints;
  for (const std::size_t at : filledAt)
  {
    const auto& v = this->VoidVertices[at];
    for (int a = 0; a < 4; ++a)
    {
      filledPoints.push_back(v[a]);
      for (int b = a + 1; b < 4; ++b)
      {
        filledEdges.emplace_back(v[a], v[b]);
      }
    }
  }
  std::sort(filledEdges.begin(), filledEdges.end());
  std::sort(filledPoints.begin(), filledPoints.end());
  for (const Lone& e : this->Edges)
  {
    if (e.Entry < t && !(e.HeldAbove < t) &&
      !std::binary_search(filledEdges.begin(), filledEdges.end(),
        std::make_pair(e.Simplex[0], e.Simplex[1])))
    {
      out.Edges.push_back({ { e.Simplex[0], e.Simplex[1] } });
      out.EdgeNode.push_back(e.Node);
    }
  }
  for (const Lone& s : this->Samples)
  {
    if (s.Entry < t && !(s.HeldAbove < t) &&
      !std::binary_search(filledPoints.begin(), filledPoints.end(), s.Simplex[0]))
    {
      out.Vertices.push_back(s.Simplex[0]);
      out.VertexNode.push_back(s.Node);
    }
  }
}

} // namespace flowrecon
