// Betti numbers of filtered cells: known answers (spheres, a torus,
// the projective plane over Z/2) and, on random complexes, Betti numbers from
// the ranks of the boundary matrices (an independent computation) at many t.
#include "CellHomology.h"
#include "Check.h"

#include <map>
#include <random>
#include <set>
#include <vector>

using flowrecon::Id;

namespace
{

using Cell = std::vector<Id>;

flowrecon::FilteredCells Cells(const std::vector<Cell>& cells, const std::vector<double>& values)
{
  flowrecon::FilteredCells out;
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    out.Add(cells[i].data(), static_cast<int>(cells[i].size()), values[i]);
  }
  return out;
}

std::array<Id, 4> Betti(const std::vector<Cell>& cells, double t = 2)
{
  const std::vector<double> ones(cells.size(), 1.0);
  return flowrecon::BettiNumbersBelow(flowrecon::CellBarcode(Cells(cells, ones)), t);
}

bool Is(const std::array<Id, 4>& b, Id b0, Id b1, Id b2, Id b3 = 0)
{
  const bool same = b[0] == b0 && b[1] == b1 && b[2] == b2 && b[3] == b3;
  if (!same)
  {
    std::cout << "  got " << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << "\n";
  }
  return same;
}

/// A triangulated torus: the 3 x 3 grid with opposite sides identified (9
/// vertices, 18 triangles); with `twist` the identification of one pair of sides
/// is reversed (a Klein bottle).
std::vector<Cell> GridSurface(int n, bool twist)
{
  auto v = [n, twist](int i, int j) {
    int ii = (i % n + n) % n, jj = j;
    if (twist && i >= n)
    {
      jj = n - 1 - j; // crossing the seam reverses the other direction
    }
    jj = (jj % n + n) % n;
    return static_cast<Id>(ii * n + jj);
  };
  std::vector<Cell> t;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      t.push_back({ v(i, j), v(i + 1, j), v(i + 1, j + 1) });
      t.push_back({ v(i, j), v(i, j + 1), v(i + 1, j + 1) });
    }
  }
  return t;
}

/// The 6-vertex projective plane (10 triangles).
std::vector<Cell> ProjectivePlane()
{
  return { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 5 }, { 0, 5, 1 }, { 1, 2, 4 },
    { 2, 3, 5 }, { 3, 4, 1 }, { 4, 5, 2 }, { 5, 1, 3 } };
}

/// Rank over Z/2 of a set of rows given as bit sets (Gaussian elimination).
Id Rank(std::vector<std::vector<char>> rows)
{
  Id rank = 0;
  const std::size_t width = rows.empty() ? 0 : rows[0].size();
  for (std::size_t col = 0; col < width && rank < static_cast<Id>(rows.size()); ++col)
  {
    std::size_t pivot = static_cast<std::size_t>(rank);
    while (pivot < rows.size() && !rows[pivot][col])
    {
      ++pivot;
    }
    if (pivot == rows.size())
    {
      continue;
    }
    std::swap(rows[pivot], rows[static_cast<std::size_t>(rank)]);
    for (std::size_t r = 0; r < rows.size(); ++r)
    {
      if (r != static_cast<std::size_t>(rank) && rows[r][col])
      {
        for (std::size_t c = 0; c < width; ++c)
        {
          rows[r][c] ^= rows[static_cast<std::size_t>(rank)][c];
        }
      }
    }
    ++rank;
  }
  return rank;
}

/// b_k = dim C_k - rank d_k - rank d_{k+1} of the closure of the cells with value < t.
std::array<Id, 4> BruteForceBetti(const std::vector<Cell>& cells, const std::vector<double>& values, double t)
{
  std::vector<std::set<Cell>> simplices(4);
  for (std::size_t i = 0; i < cells.size(); ++i)
  {
    if (!(values[i] < t))
    {
      continue;
    }
    std::set<Id> unique(cells[i].begin(), cells[i].end());
    const Cell c(unique.begin(), unique.end());
    for (int mask = 1; mask < (1 << c.size()); ++mask)
    {
      Cell f;
      for (std::size_t k = 0; k < c.size(); ++k)
      {
        if (mask & (1 << k))
        {
          f.push_back(c[k]);
        }
      }
      simplices[f.size() - 1].insert(f);
    }
  }
  std::vector<std::map<Cell, std::size_t>> index(4);
  for (int k = 0; k < 4; ++k)
  {
    for (const Cell& s : simplices[k])
    {
      index[k].emplace(s, index[k].size());
    }
  }
  std::array<Id, 5> rank{ { 0, 0, 0, 0, 0 } }; // rank[k] = rank of d_k : C_k -> C_{k-1}
  for (int k = 1; k < 4; ++k)
  {
    std::vector<std::vector<char>> rows;
    for (const Cell& s : simplices[k])
    {
      std::vector<char> row(simplices[k - 1].size(), 0);
      for (std::size_t skip = 0; skip < s.size(); ++skip)
      {
        Cell f;
        for (std::size_t j = 0; j < s.size(); ++j)
        {
          if (j != skip)
          {
            f.push_back(s[j]);
          }
        }
        row[index[k - 1].at(f)] = 1;
      }
      rows.push_back(row);
    }
    rank[k] = Rank(rows);
  }
  std::array<Id, 4> betti{};
  for (int k = 0; k < 4; ++k)
  {
    betti[k] = static_cast<Id>(simplices[k].size()) - rank[k] - rank[k + 1];
  }
  return betti;
}

void KnownAnswers()
{
  CHECK(Is(Betti({ { 0, 1, 2, 3 } }), 1, 0, 0));                                    // solid tetrahedron
  CHECK(Is(Betti({ { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } }), 1, 0, 1)); // its boundary
  CHECK(Is(Betti({ { 0, 1 }, { 1, 2 }, { 2, 0 }, { 5 } }), 2, 1, 0));                // a circle and a point
  CHECK(Is(Betti(GridSurface(4, false)), 1, 2, 1));                                   // torus
  CHECK(Is(Betti(GridSurface(4, true)), 1, 2, 1));                                    // Klein bottle over Z/2
  CHECK(Is(Betti(ProjectivePlane()), 1, 1, 1));                                       // RP^2 over Z/2
  // The boundary of a 4-simplex (a 3-sphere made of 5 tetrahedra).
  CHECK(Is(Betti({ { 0, 1, 2, 3 }, { 0, 1, 2, 4 }, { 0, 1, 3, 4 }, { 0, 2, 3, 4 }, { 1, 2, 3, 4 } }),
    1, 0, 0, 1));
  // Repeated points: a "triangle" (0, 0, 1) is the segment 0-1.
  CHECK(Is(Betti({ { 0, 0, 1 }, { 1, 2 }, { 2, 0 } }), 1, 1, 0));
  CHECK(Is(Betti({}), 0, 0, 0));
}

void Filtration()
{
  // The boundary of a tetrahedron whose edges come at 1.5 and faces at 3: K4 (b1
  // = 3) for t in (1.5, 3], then a sphere.
  std::vector<Cell> cells = { { 0, 1 }, { 0, 2 }, { 0, 3 }, { 1, 2 }, { 1, 3 }, { 2, 3 },
    { 0, 1, 2 }, { 0, 1, 3 }, { 0, 2, 3 }, { 1, 2, 3 } };
  std::vector<double> values = { 1.5, 1.5, 1.5, 1.5, 1.5, 1.5, 3, 3, 3, 3 };
  const auto bars = flowrecon::CellBarcode(Cells(cells, values));
  CHECK(Is(flowrecon::BettiNumbersBelow(bars, 1.5), 0, 0, 0));
  CHECK(Is(flowrecon::BettiNumbersBelow(bars, 1.6), 1, 3, 0));
  CHECK(Is(flowrecon::BettiNumbersBelow(bars, 3), 1, 3, 0));
  CHECK(Is(flowrecon::BettiNumbersBelow(bars, 3.01), 1, 0, 1));
  const auto profile = flowrecon::TopologyProfile(bars, 1, 10);
  CHECK(profile.size() == 3);
  if (profile.size() == 3)
  {
    CHECK(profile[0].Threshold == 1 && Is(profile[0].Betti, 0, 0, 0));
    CHECK(profile[1].Threshold == 1.5 && Is(profile[1].Betti, 1, 3, 0));
    CHECK(profile[2].Threshold == 3 && Is(profile[2].Betti, 1, 0, 1));
  }
  // Beyond `limit` nothing is reported.
  CHECK(flowrecon::TopologyProfile(bars, 1, 2).size() == 2);
}

void RandomComplexes()
{
  std::mt19937_64 rng(7);
  int compared = 0;
  for (int trial = 0; trial < 300; ++trial)
  {
    const int vertices = 4 + static_cast<int>(rng() % 8);
    const int count = 1 + static_cast<int>(rng() % 14);
    std::vector<Cell> cells;
    std::vector<double> values;
    for (int c = 0; c < count; ++c)
    {
      const int size = 1 + static_cast<int>(rng() % 4);
      Cell cell;
      for (int k = 0; k < size; ++k)
      {
        cell.push_back(static_cast<Id>(rng() % vertices)); // repeats allowed
      }
      cells.push_back(cell);
      values.push_back(1 + static_cast<double>(rng() % 5) * 0.5); // ties on purpose
    }
    const auto bars = flowrecon::CellBarcode(Cells(cells, values));
    for (double t : { 1.0, 1.2, 1.5, 1.7, 2.0, 2.2, 2.5, 3.0, 3.1, 10.0 })
    {
      const auto fast = flowrecon::BettiNumbersBelow(bars, t);
      const auto slow = BruteForceBetti(cells, values, t);
      CHECK(fast == slow);
      ++compared;
    }
    // The profile agrees with the pointwise numbers just above each change.
    const auto profile = flowrecon::TopologyProfile(bars, 1, 100);
    for (std::size_t k = 0; k < profile.size(); ++k)
    {
      CHECK(flowrecon::BettiNumbersBelow(bars, profile[k].Threshold + 1e-9) == profile[k].Betti);
    }
  }
  std::cout << compared << " Betti numbers compared with ranks of boundary matrices\n";
}

void BadInput()
{
  flowrecon::FilteredCells cells;
  const Id five[5] = { 0, 1, 2, 3, 4 };
  cells.Add(five, 5, 1);
  bool thrown = false;
  try
  {
    flowrecon::CellBarcode(cells);
  }
  catch (const flowrecon::InputError&)
  {
    thrown = true;
  }
  CHECK(thrown);
}

} // namespace

int main()
{
  KnownAnswers();
  Filtration();
  RandomComplexes();
  BadInput();
  return check::Finish("TestCellHomology");
}
