// The automatic choice of t_r and t_p on hand-made topology profiles with
// known answers: the windows of constant Betti numbers, the stable window
// with the most voids, t_r just above its start, the flags behind the
// warnings, and the choice of t_p for a given t_r. The local flatness of
// clouds of known dimension, and the filled-surface check built on it. The
// depth of a solid in edges on lattices whose answer is known, and the
// shallow-solid check built on it. The preference for a surface when a
// solid answer is filled in, and for closed surfaces apart over those joined.
// The samples apart from the rest, on hand-made Gabriel edges.
#include "AutomaticThresholds.h"
#include "Check.h"
#include "Clouds.h"
#include "LocalFlatness.h"
#include "LongJoins.h"
#include "PartGaps.h"
#include "SolidDepth.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace flowrecon;

namespace
{

/// The n x n x n unit cubes from `corner` cut into 6 tetrahedra each along
/// their main diagonal (Kuhn's subdivision), vertices numbered in the
/// (m + 1)^3 lattice: every edge moves each coordinate by 0 or 1, so the
/// depth of lattice point x is min over axes of min(x_c, n - x_c) edges, and the
/// solid's depth floor(n / 2).
void KuhnCubes(int n, std::array<int, 3> corner, int m, std::vector<std::array<Id, 4>>& tets)
{
  const auto id = [m](int x, int y, int z) { return static_cast<Id>(x + (m + 1) * (y + (m + 1) * z)); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
      {
        std::array<int, 3> axes{ { 0, 1, 2 } };
        do
        {
          std::array<int, 3> p{ { corner[0] + i, corner[1] + j, corner[2] + k } };
          std::array<Id, 4> t;
          t[0] = id(p[0], p[1], p[2]);
          for (int s = 0; s < 3; ++s)
          {
            ++p[axes[s]];
            t[s + 1] = id(p[0], p[1], p[2]);
          }
          tets.push_back(t);
        } while (std::next_permutation(axes.begin(), axes.end()));
      }
}

std::vector<TopologyStep> Profile(const std::vector<std::pair<double, std::array<Id, 3>>>& rows)
{
  std::vector<TopologyStep> p;
  for (const auto& r : rows)
  {
    TopologyStep s;
    s.Threshold = r.first;
    s.Betti = { { r.second[0], r.second[1], r.second[2], 0 } };
    p.push_back(s);
  }
  return p;
}

// A closed surface: holes close one by one (the last but one leaves a disk),
// then the void appears at 2.1.
const std::vector<TopologyStep> Sphere = Profile({ { 1.0, { 1, 5, 0 } }, { 1.6, { 1, 3, 0 } },
  { 1.8, { 1, 1, 0 } }, { 1.95, { 1, 0, 0 } }, { 2.1, { 1, 0, 1 } } });

// A torus whose tube is filled at 2.5: the surface holds over (2.0, 2.5] only,
// the solid torus over (2.5, 6].
const std::vector<TopologyStep> Torus = Profile({ { 1.0, { 3, 20, 0 } }, { 1.7, { 1, 4, 0 } },
  { 2.0, { 1, 2, 1 } }, { 2.5, { 1, 1, 0 } } });

} // namespace

int main()
{
  // Windows: equal neighbours merge, the range clips, those below it go.
  {
    const auto w = StableWindows(Profile({ { 1.0, { 2, 0, 0 } }, { 1.4, { 1, 0, 0 } },
                                   { 2.0, { 1, 0, 0 } }, { 3.0, { 1, 1, 0 } } }),
      1.5, 6);
    CHECK(w.size() == 2);
    CHECK(w[0].From == 1.5 && w[0].To == 3.0 && w[0].Betti[0] == 1 && w[0].Betti[1] == 0);
    CHECK(w[1].From == 3.0 && w[1].To == 6.0 && w[1].Betti[1] == 1);
    CHECK_NEAR(w[1].Length(), std::log(2.0), 1e-15);
  }
  // The window around t equals the one StableWindows lists: random profiles
  // with repeated rows, at the rows' thresholds, between them and outside.
  {
    std::uint64_t state = 7;
    const auto next = [&]() {
      state = state * 6364136223846793005ULL + 1442695040888963407ULL;
      return static_cast<int>(state >> 60);
    };
    int compared = 0, found = 0;
    for (int trial = 0; trial < 300; ++trial)
    {
      std::vector<TopologyStep> p;
      double at = 0.8 + 0.1 * next();
      for (int k = 0, n = 1 + next(); k < n; ++k)
      {
        TopologyStep s;
        s.Threshold = at;
        s.Betti = { { 1, next() % 3, next() % 2, 0 } };
        p.push_back(s);
        at += 0.05 * (1 + next());
      }
      const double lo = 1 + 0.1 * (next() % 4), hi = lo + 0.2 * (1 + next());
      std::vector<double> ts{ lo, hi, 0.5, hi + 1 };
      for (const TopologyStep& s : p)
      {
        ts.push_back(s.Threshold);
        ts.push_back(s.Threshold + 0.01);
      }
      for (const double t : ts)
      {
        StableWindow listed;
        for (const StableWindow& w : StableWindows(p, lo, hi))
        {
          listed = w.From < t && t <= w.To ? w : listed;
        }
        const StableWindow w = StableWindowAt(p, lo, hi, t);
        ++compared;
        found += w.Length() > 0 ? 1 : 0;
        CHECK(w.From == listed.From && w.To == listed.To && w.Betti == listed.Betti);
      }
    }
    CHECK(compared > 1000 && found > compared / 4);
  }
  // The sphere: its last window, t_r 10 % above 2.1.
  {
    const ThresholdChoice c = ChooseThresholds({ Sphere }, 6);
    CHECK(c.Window.Betti[2] == 1 && c.Window.From == 2.1 && c.Window.To == 6);
    CHECK_NEAR(c.ReconstructionThreshold, 2.31, 1e-12);
    CHECK(!c.Short() && !c.Unstable() && c.ChangesAtStart == 1);
  }
  // The torus: the surface (one void) over the longer solid, flagged short,
  // and the longer window named.
  {
    const ThresholdChoice c = ChooseThresholds({ Torus }, 6);
    CHECK(c.Window.Betti[1] == 2 && c.Window.Betti[2] == 1);
    CHECK(c.Short() && !c.Unstable());
    CHECK(c.Longest.Betti[1] == 1 && c.Longest.Betti[2] == 0 && c.Longest.From == 2.5);
    // 10 % above the start, below the window's middle sqrt(2 * 2.5).
    CHECK_NEAR(c.ReconstructionThreshold, 2.2, 1e-12);
    // Two classes changed at 2.0 (a loop closed, the void appeared).
    CHECK(c.ChangesAtStart == 3);
  }
  // No window spans 10 %: the longest is taken and flagged.
  {
    std::vector<std::pair<double, std::array<Id, 3>>> rows;
    for (int k = 0; k < 30; ++k)
    {
      rows.push_back({ 1.5 * std::pow(1.05, k), { 1, static_cast<Id>(30 - k), 0 } });
    }
    const ThresholdChoice c = ChooseThresholds({ Profile(rows) }, 6);
    CHECK(c.Unstable());
    CHECK(c.Window.Length() > 0 && c.Window.To / c.Window.From < 1.1);
  }
  // Two t_p: the lattice broken by the simplification (7 9 0) against the
  // sphere without it; the sphere wins, and the candidates disagree.
  {
    const auto broken = Profile({ { 1.0, { 7, 9, 0 } }, { 2.19, { 5, 7, 0 } } });
    const auto whole = Profile({ { 1.0, { 1, 0, 1 } } });
    const ThresholdChoice c = ChooseThresholds({ broken, whole }, 6);
    CHECK(c.Candidate == 1 && c.Window.Betti[2] == 1 && c.CandidatesDisagree());
    CHECK_NEAR(c.ReconstructionThreshold, 1.65, 1e-12);
  }
  // Equal windows: the first candidate (the preference).
  {
    const ThresholdChoice c = ChooseThresholds({ Sphere, Sphere }, 6);
    CHECK(c.Candidate == 0 && !c.CandidatesDisagree());
  }
  // No profile above 1.5: the first candidate at 1.65, unstable.
  {
    const ThresholdChoice c = ChooseThresholds({ Profile({ { 1.0, { 1, 0, 0 } }, { 1.4, { 2, 0, 0 } } }) }, 1.45 + 0.1);
    CHECK(c.Window.Betti[0] == 2); // (1.5, 1.55]: a window, but not stable
    CHECK(c.Unstable());
  }
  // No window at all: t_r 1.65, but never past the cap, where the run stops.
  {
    CHECK(ChooseThresholds({ std::vector<TopologyStep>() }, 6).ReconstructionThreshold == 1.5 * 1.1);
    CHECK(ChooseThresholds({ std::vector<TopologyStep>() }, 1.6).ReconstructionThreshold == 1.6);
  }
  // A given t_r: the t_p whose window around it is longest.
  {
    const ThresholdChoice c = ChoosePersistence({ Torus, Sphere }, 2.2, 6);
    CHECK(c.Candidate == 1 && c.ReconstructionThreshold == 2.2);
    CHECK(c.Window.From == 2.1 && c.Window.To == 6);
    const ThresholdChoice d = ChoosePersistence({ Torus, Sphere }, 1.9, 6);
    CHECK(d.Candidate == 0 && d.Window.From == 1.7); // (1.7, 2.0] beats (1.8, 1.95]
  }
  // Samples apart: a 3 x 3 grid of samples 1 apart (Gabriel edges between
  // grid neighbours, node value 0.5) and one sample 20 away, whose only edge
  // (value 10) goes to a corner: the median nearest distance is 0.5 and the
  // lone one is 20 times it, found at factor 10, not at 25. A second stray
  // sample 1 from the first hides it: two strays together are not apart.
  {
    std::vector<Node> nodes;
    auto sample = [&](Id id, Point3 at) {
      Node n;
      n.Index = 0;
      n.Simplex = { { static_cast<std::int32_t>(id), -1, -1, -1 } };
      n.Location = at;
      nodes.push_back(n);
    };
    auto edge = [&](Id a, Id b, double value) {
      Node n;
      n.Index = 1;
      n.Value = value;
      n.Simplex = { { static_cast<std::int32_t>(std::min(a, b)), static_cast<std::int32_t>(std::max(a, b)), -1, -1 } };
      nodes.push_back(n);
    };
    for (int i = 0; i < 9; ++i)
    {
      sample(i, { { static_cast<double>(i % 3), static_cast<double>(i / 3), 0 } });
      if (i % 3 < 2)
      {
        edge(i, i + 1, 0.5);
      }
      if (i < 6)
      {
        edge(i, i + 3, 0.5);
      }
    }
    sample(9, { { 22, 2, 0 } });
    edge(8, 9, 10);
    FarSamples far = FindFarSamples(nodes, 10, 10);
    CHECK(far.Count == 1 && far.Median == 0.5);
    CHECK_NEAR(far.Largest, 20, 1e-12);
    CHECK(far.Farthest[0] == 22 && far.Farthest[1] == 2);
    CHECK(FindFarSamples(nodes, 10, 25).Count == 0);
    // Ids past the samples (a damaged file) are passed over, not indexed:
    // an edge to sample 10^9 neither allocates nor counts.
    Node damaged;
    damaged.Index = 1;
    damaged.Value = 100;
    damaged.Simplex = { { 3, 1000000000, -1, -1 } };
    nodes.push_back(damaged);
    CHECK(FindFarSamples(nodes, 10, 10).Count == 1);
    nodes.pop_back();
    // Through the choice, with the rule's factor; none on the grid alone.
    ThresholdChoice c = ChooseThresholds({ Sphere }, 6);
    CheckFar(c, nodes, 10);
    CHECK(c.Far.Count == 1);
    sample(10, { { 23, 2, 0 } });
    edge(9, 10, 0.5);
    CHECK(FindFarSamples(nodes, 11, 10).Count == 0);
    nodes.resize(21); // the 9 samples and their 12 edges
    CheckFar(c, nodes, 9);
    CHECK(c.Far.Count == 0 && c.Far.Median == 0.5);
  }
  // Parts side by side: three rows of three samples (edges of half-length 1
  // along them), the rows 3 and 4 apart (Gabriel edges across, half-lengths
  // 1.5 and 2); the widest gap from a row to its nearest is 2, 4 median
  // distances. Warned under a factor of 10, not under 3; not when the answer
  // has a void, fewer than three parts, or no window.
  {
    std::vector<Node> nodes;
    CompactComplex cells;
    const auto edge = [&](Id a, Id b, double half, bool inside) {
      Node n;
      n.Index = 1;
      n.Value = half;
      n.Simplex = { { static_cast<int>(std::min(a, b)), static_cast<int>(std::max(a, b)), -1, -1 } };
      n.Location = { { static_cast<double>(a), static_cast<double>(b), 0 } };
      nodes.push_back(n);
      if (inside)
      {
        cells.Edges.push_back({ { a, b } });
      }
    };
    for (Id row = 0; row < 3; ++row)
    {
      edge(3 * row, 3 * row + 1, 1, true);
      edge(3 * row + 1, 3 * row + 2, 1, true);
    }
    edge(1, 4, 1.5, false);
    edge(4, 7, 2, false);
    edge(2, 8, 3.5, false); // not the nearest of either
    const PartGaps gaps = FindPartGaps(nodes, 9, cells);
    CHECK(gaps.Parts == 3 && gaps.Widest == 2 && gaps.Where[0] == 4 && gaps.Where[1] == 7);
    ThresholdChoice c = ChooseThresholds({ Profile({ { 1.0, { 9, 0, 0 } }, { 1.4, { 3, 0, 0 } } }) }, 5);
    CHECK(c.NeedsRows() == false); // CheckFar first: no median yet
    CheckFar(c, nodes, 9);
    CHECK(c.Far.Median == 1 && c.NeedsRows());
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 3 && c.RowGap == 2 && c.RowPlace[0] == 4);
    c.Rule.RowFactor = 1.9;
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 0);
    c.Rule.RowFactor = 10;
    c.Window.Betti = { { 3, 0, 1 } };
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 0);
    c.Window.Betti = { { 2, 0, 0 } };
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 0);
    // Two rows joined into one part by a cell: two parts, nothing to warn.
    cells.Edges.push_back({ { 1, 4 } });
    CHECK(FindPartGaps(nodes, 9, cells).Parts == 2);
    // Ids past the samples are passed over.
    edge(5, 1000000000, 0.1, true);
    CHECK(FindPartGaps(nodes, 9, cells).Parts == 2);
  }
  // Closed curves side by side: three loops of three samples on circles of
  // radius 1 (extent: the diagonal of a 1.5 x sqrt(3) box, sqrt(5.25)),
  // `d` apart on one axis, each sample's Gabriel edge to the next loop's
  // across. With the spacing rule off (RowFactor 0.5), warned by their extent
  // when 0.4 apart (0.4 / 2.29 = 0.175 <= 0.25), not when 2 apart (0.87),
  // nor when the window is not loops (b1 != b0) or the parts have triangles.
  for (const double d : { 0.4, 2.0 })
  {
    std::vector<Node> nodes;
    CompactComplex cells;
    const double pi = std::acos(-1.0);
    for (Id s = 0; s < 9; ++s)
    {
      Node n;
      n.Index = 0;
      n.Value = 0;
      n.Simplex = { { static_cast<int>(s), -1, -1, -1 } };
      n.Location = { { std::cos(2 * pi * static_cast<double>(s % 3) / 3),
        std::sin(2 * pi * static_cast<double>(s % 3) / 3), d * static_cast<double>(s / 3) } };
      nodes.push_back(n);
    }
    const auto edge = [&](Id a, Id b, double half, bool inside) {
      Node n;
      n.Index = 1;
      n.Value = half;
      n.Simplex = { { static_cast<int>(a), static_cast<int>(b), -1, -1 } };
      const Point3& p = nodes[static_cast<std::size_t>(a)].Location;
      const Point3& q = nodes[static_cast<std::size_t>(b)].Location;
      n.Location = { { (p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2 } };
      nodes.push_back(n);
      if (inside)
      {
        cells.Edges.push_back({ { a, b } });
      }
    };
    for (Id loop = 0; loop < 3; ++loop)
    {
      for (Id k = 0; k < 3; ++k)
      {
        edge(3 * loop + k, 3 * loop + (k + 1) % 3, std::sqrt(3.0) / 2, true);
        if (loop < 2)
        {
          edge(3 * loop + k, 3 * loop + 3 + k, d / 2, false);
        }
      }
    }
    const PartGaps gaps = FindPartGaps(nodes, 9, cells);
    const double span = d / std::sqrt(5.25);
    CHECK(gaps.Parts == 3 && gaps.Curves && std::abs(gaps.WidestSpan - span) < 1e-12 && gaps.SpanGap == d / 2);
    ThresholdChoice c = ChooseThresholds({ Profile({ { 1.0, { 9, 0, 0 } }, { 1.4, { 3, 3, 0 } } }) }, 5);
    CheckFar(c, nodes, 9);
    c.Rule.RowFactor = 0.5;
    CheckRows(c, nodes, 9, cells);
    if (d < 1)
    {
      CHECK(c.Rows == 3 && std::abs(c.RowGapOfExtent - span) < 1e-12 && c.RowGap == d / 2 / c.Far.Median &&
        c.RowPlace[2] == d / 2);
    }
    else
    {
      CHECK(c.Rows == 0 && c.RowGapOfExtent == 0);
    }
    c.Window.Betti = { { 3, 0, 0 } };
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 0);
    c.Window.Betti = { { 3, 3, 0 } };
    cells.Triangles.push_back({ { 0, 1, 2 } });
    CHECK(!FindPartGaps(nodes, 9, cells).Curves);
    CheckRows(c, nodes, 9, cells);
    CHECK(c.Rows == 0);
  }
  // Bad input.
  {
    bool threw = false;
    try
    {
      ChooseThresholds({}, 6);
    }
    catch (const InputError&)
    {
      threw = true;
    }
    CHECK(threw);
  }
  // Local flatness: a surface sample is flat, a volume sample is not, a few
  // points say nothing; the filled-surface check needs a solid
  // reconstruction (with or without voids) and flat samples.
  {
    const std::vector<Point3> sphere = clouds::Sphere(3000, 3), cube = clouds::Cube(3000, 5);
    const double flatSphere = MedianFlatness(sphere), flatCube = MedianFlatness(cube);
    CHECK(flatSphere < 0.1);
    CHECK(flatCube > 0.5);
    CHECK(MedianFlatness(clouds::Sphere(20, 7)) == 1);
    ThresholdChoice c = ChooseThresholds({ Torus }, 6); // the surface, one void
    CheckFilled(c, sphere, 100); // a few slivers beside the void
    CHECK(!c.Filled && c.Flatness == 1);
    CheckFilled(c, sphere, 3000); // solid around its void: nested surfaces' gap filled
    CHECK(c.Filled);
    c.Window.Betti = { { 1, 1, 0 } }; // a solid torus
    CheckFilled(c, sphere, 100);      // a few slivers only: not solid
    CHECK(!c.Filled && c.Flatness == 1);
    CheckFilled(c, sphere, 1000);
    CHECK(c.Filled && c.Flatness == RelativeFlatness(sphere) && c.Maxima == 1000 && c.Samples == 3000);
    CHECK(c.Flatness <= flatSphere / FlatnessScales()[1].Volume);
    CheckFilled(c, cube, 1000);       // a volume sample's solid is no surface filled
    CHECK(!c.Filled);
  }
  // Too few samples to tell: under FlatnessMinimumPoints (200: 20 times the
  // smallest scale's 10 neighbours) any answer without a void is TooFew, not
  // Filled, whatever the share of maxima, and PreferSurface takes the window
  // with a void as for a filled surface, on whichever candidate has it. At
  // 200 samples, or with a void, it is not TooFew; without a window with a
  // void the answer stays.
  {
    CHECK(FlatnessMinimumPoints() == 200);
    const auto solid = Profile({ { 1.0, { 4, 9, 0 } }, { 1.75, { 1, 0, 1 } }, { 1.8, { 1, 0, 0 } } });
    const auto solidOnly = Profile({ { 1.0, { 4, 9, 0 } }, { 1.8, { 1, 0, 0 } } });
    ThresholdChoice c = ChooseThresholds({ solidOnly, solid }, 5);
    CHECK(c.Window.Betti == (std::array<Id, 3>{ { 1, 0, 0 } }) && c.Candidate == 0);
    CheckFilled(c, clouds::Sphere(199, 3), 0); // no maximum: an open surface's answer too
    CHECK(c.TooFew && !c.Filled && c.Flatness == 1 && !c.NeedsDepth());
    CHECK(PreferSurface(c, { solidOnly, solid }, 5));
    CHECK(c.Resurfaced && c.Candidate == 1 && c.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }) &&
      c.Window.From == 1.75 && c.Window.To == 1.8 && c.Solid.From == 1.8);
    ThresholdChoice d = ChooseThresholds({ solidOnly }, 5);
    CheckFilled(d, clouds::Sphere(30, 3), 2);
    CHECK(d.TooFew && !PreferSurface(d, { solidOnly }, 5) && !d.Resurfaced &&
      d.Window.Betti == (std::array<Id, 3>{ { 1, 0, 0 } }));
    ThresholdChoice e = ChooseThresholds({ solidOnly, solid }, 5);
    CheckFilled(e, clouds::Sphere(200, 3), 0);
    CHECK(!e.TooFew && !PreferSurface(e, { solidOnly, solid }, 5) && e.Candidate == 0);
    ThresholdChoice f = ChooseThresholds({ Torus }, 6);
    CheckFilled(f, clouds::Sphere(30, 3), 2);
    CHECK(!f.TooFew);
  }
  // Among stable windows with as many voids, an even b1 (closed surfaces)
  // beats a longer odd one: a torus whose hole a membrane spans (1 1 1) over
  // (2.2, 5] is not taken over the torus (1 2 1) over (1.8, 2.2]; without voids
  // parity does not matter (the longest); with more voids the odd one wins.
  {
    const auto membrane = Profile({ { 1.0, { 3, 20, 0 } }, { 1.8, { 1, 2, 1 } }, { 2.2, { 1, 1, 1 } } });
    ThresholdChoice c = ChooseThresholds({ membrane }, 5);
    CHECK(c.Window.Betti == (std::array<Id, 3>{ { 1, 2, 1 } }) && c.Window.From == 1.8 && c.Window.To == 2.2);
    CHECK(c.Longest.Betti == (std::array<Id, 3>{ { 1, 1, 1 } }));
    // The same windows on two candidates: the even one wins across them too.
    const auto odd = Profile({ { 1.0, { 3, 20, 0 } }, { 2.0, { 1, 1, 1 } } });
    const auto even = Profile({ { 1.0, { 3, 20, 0 } }, { 2.0, { 1, 0, 1 } }, { 3.0, { 1, 0, 0 } } });
    ThresholdChoice d = ChooseThresholds({ odd, even }, 5);
    CHECK(d.Candidate == 1 && d.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }));
    const auto curve = Profile({ { 1.0, { 3, 20, 0 } }, { 1.6, { 1, 2, 0 } }, { 2.0, { 1, 1, 0 } } });
    ThresholdChoice e = ChooseThresholds({ curve }, 5);
    CHECK(e.Window.Betti == (std::array<Id, 3>{ { 1, 1, 0 } }));
    const auto two = Profile({ { 1.0, { 3, 20, 0 } }, { 1.8, { 1, 1, 2 } }, { 2.0, { 1, 0, 1 } } });
    ThresholdChoice f = ChooseThresholds({ two }, 5);
    CHECK(f.Window.Betti == (std::array<Id, 3>{ { 1, 1, 2 } }));
  }
  // Separate closed surfaces: two spheres apart over (1.5, 2.35] and joined by
  // a bridge over the longer (2.35, 5], their voids kept (2 0 2, then 1 0 2),
  // are taken apart, across candidates too; a nested pair of spheres (2 0 2)
  // likewise. A part that cannot bound a void of its own (b0 > b2: a curve
  // beside a sphere, 2 0 1) is not preferred: the longest, joined, wins; nor
  // is an odd b1 (2 1 2), which the parity rule already puts after.
  {
    const auto bridged = Profile({ { 1.0, { 228, 36, 0 } }, { 1.42, { 2, 0, 2 } }, { 2.35, { 1, 0, 2 } } });
    ThresholdChoice c = ChooseThresholds({ bridged }, 5);
    CHECK(c.Window.Betti == (std::array<Id, 3>{ { 2, 0, 2 } }) && c.Window.From == 1.5 && c.Window.To == 2.35);
    CHECK(c.Longest.Betti == (std::array<Id, 3>{ { 1, 0, 2 } }));
    const auto joined = Profile({ { 1.0, { 228, 36, 0 } }, { 1.42, { 1, 0, 2 } } });
    ThresholdChoice d = ChooseThresholds({ joined, bridged }, 5);
    CHECK(d.Candidate == 1 && d.Window.Betti == (std::array<Id, 3>{ { 2, 0, 2 } }) && d.CandidatesDisagree());
    const auto curve = Profile({ { 1.0, { 40, 3, 0 } }, { 1.42, { 2, 0, 1 } }, { 2.35, { 1, 0, 1 } } });
    ThresholdChoice e = ChooseThresholds({ curve }, 5);
    CHECK(e.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }) && e.Window.From == 2.35);
    const auto odd = Profile({ { 1.0, { 40, 3, 0 } }, { 1.42, { 2, 1, 2 } }, { 2.35, { 1, 0, 2 } } });
    ThresholdChoice f = ChooseThresholds({ odd }, 5);
    CHECK(f.Window.Betti == (std::array<Id, 3>{ { 1, 0, 2 } }));
  }
  // Closed surfaces apart only below the windows looked at (or too briefly
  // to be stable), then joined (2 0 2 over (1.42, 1.46], 1 0 2 after): the
  // joined answer stays, and Apart names the window where they were apart,
  // the last one below the answer, on the chosen candidate only. Not when
  // they joined before closing (touching spheres: 2 0 0, 1 0 1, 1 0 2), when
  // a part cannot bound a void (2 0 1, then 1 0 1), when b1 differs (2 2 2
  // then 1 0 2: a torus filled as it joined), nor when the answer has them
  // apart.
  {
    const auto brief = Profile({ { 1.0, { 228, 36, 0 } }, { 1.2, { 3, 0, 2 } }, { 1.3, { 2, 1, 2 } },
      { 1.35, { 2, 0, 2 } }, { 1.42, { 2, 0, 2 } }, { 1.455, { 1, 0, 2 } }, { 4.1, { 1, 0, 1 } } });
    const ThresholdChoice c = ChooseThresholds({ brief }, 5);
    CHECK(c.Window.Betti == (std::array<Id, 3>{ { 1, 0, 2 } }) && c.Apart.Length() > 0);
    CHECK(c.Apart.Betti == (std::array<Id, 3>{ { 2, 0, 2 } }) && c.Apart.From == 1.35 && c.Apart.To == 1.455);
    const auto touching = Profile({ { 1.0, { 228, 36, 0 } }, { 1.2, { 2, 0, 0 } }, { 1.3, { 1, 0, 1 } },
      { 1.4, { 1, 0, 2 } } });
    CHECK(ChooseThresholds({ touching }, 5).Apart.Length() == 0);
    const ThresholdChoice d = ChooseThresholds({ touching, brief }, 5);
    CHECK(d.Candidate == 0 && d.Apart.Length() == 0); // the chosen candidate's profile only
    const auto curve = Profile({ { 1.0, { 40, 3, 0 } }, { 1.3, { 2, 0, 1 } }, { 1.45, { 1, 0, 1 } } });
    CHECK(ChooseThresholds({ curve }, 5).Apart.Length() == 0);
    const auto filled = Profile({ { 1.0, { 40, 3, 0 } }, { 1.3, { 2, 2, 2 } }, { 1.45, { 1, 0, 2 } } });
    CHECK(ChooseThresholds({ filled }, 5).Apart.Length() == 0);
    const auto bridged = Profile({ { 1.0, { 228, 36, 0 } }, { 1.3, { 2, 0, 2 } }, { 2.35, { 1, 0, 2 } } });
    const ThresholdChoice e = ChooseThresholds({ bridged }, 5);
    CHECK(e.Window.Betti == (std::array<Id, 3>{ { 2, 0, 2 } }) && e.Apart.Length() == 0);
  }
  // Preferring a surface: a surface sample whose stable answer is a solid
  // torus (1 1 0) over (1.8, 5] takes the torus (1 2 1) that closes briefly
  // before it, on whichever candidate has it; unstable windows only when no
  // stable one has a void; the most voids first; nothing without Filled or
  // without a void anywhere.
  {
    const std::vector<Point3> sphere = clouds::Sphere(3000, 3);
    const auto solid = Profile({ { 1.0, { 4, 9, 0 } }, { 1.75, { 1, 2, 1 } }, { 1.8, { 1, 1, 0 } } });
    const auto solidOnly = Profile({ { 1.0, { 4, 9, 0 } }, { 1.8, { 1, 1, 0 } } });
    ThresholdChoice c = ChooseThresholds({ solidOnly, solid }, 5);
    CHECK(c.Window.Betti == (std::array<Id, 3>{ { 1, 1, 0 } }));
    CHECK(!PreferSurface(c, { solidOnly, solid }, 5)); // not Filled: kept
    CheckFilled(c, sphere, 1000);
    CHECK(c.Filled);
    CHECK(PreferSurface(c, { solidOnly, solid }, 5));
    CHECK(c.Resurfaced && c.Candidate == 1 && c.Window.Betti == (std::array<Id, 3>{ { 1, 2, 1 } }));
    CHECK(c.Window.From == 1.75 && c.Window.To == 1.8 && c.Solid.From == 1.8 && c.Solid.To == 5);
    CHECK(c.ReconstructionThreshold > 1.75 && c.ReconstructionThreshold <= 1.8);
    CHECK(!c.NeedsDepth());
    CHECK(!PreferSurface(c, { solidOnly, solid }, 5)); // once
    // No window with a void: kept, still Filled.
    ThresholdChoice d = ChooseThresholds({ solidOnly }, 5);
    CheckFilled(d, sphere, 1000);
    CHECK(d.Filled && !PreferSurface(d, { solidOnly }, 5) && !d.Resurfaced &&
      d.Window.Betti == (std::array<Id, 3>{ { 1, 1, 0 } }));
    // A stable window with a void beats a shorter unstable one with more
    // (ChooseThresholds would not leave it: a choice made by hand).
    const auto two = Profile({ { 1.0, { 4, 9, 0 } }, { 1.55, { 1, 0, 2 } }, { 1.56, { 1, 0, 1 } },
      { 1.9, { 1, 0, 0 } } });
    ThresholdChoice e;
    e.Filled = true;
    e.Window = StableWindows(two, 1.5, 5).back();
    CHECK(e.Window.Betti == (std::array<Id, 3>{ { 1, 0, 0 } }));
    CHECK(PreferSurface(e, { two }, 5) && e.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }));
    // Among unstable windows, the most voids.
    const auto brief = Profile({ { 1.0, { 4, 9, 0 } }, { 1.6, { 1, 0, 1 } }, { 1.61, { 1, 0, 2 } },
      { 1.62, { 1, 0, 0 } } });
    ThresholdChoice f = ChooseThresholds({ brief }, 5);
    CheckFilled(f, sphere, 1000);
    CHECK(PreferSurface(f, { brief }, 5) && f.Window.Betti == (std::array<Id, 3>{ { 1, 0, 2 } }));
    // Solid around a void (two nested surfaces whose gap filled): only a
    // window with more voids is taken; one with as many is not.
    const auto nested = Profile({ { 1.0, { 9, 40, 0 } }, { 1.7, { 2, 0, 2 } }, { 1.75, { 1, 0, 1 } } });
    ThresholdChoice g = ChooseThresholds({ nested }, 5);
    CHECK(g.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }));
    CheckFilled(g, sphere, 1000);
    CHECK(g.Filled && PreferSurface(g, { nested }, 5) && g.Resurfaced &&
      g.Window.Betti == (std::array<Id, 3>{ { 2, 0, 2 } }) && g.Solid.Betti[2] == 1);
    const auto shell = Profile({ { 1.0, { 9, 40, 0 } }, { 1.7, { 1, 1, 1 } }, { 1.75, { 1, 0, 1 } } });
    ThresholdChoice h = ChooseThresholds({ shell }, 5);
    CheckFilled(h, sphere, 1000);
    CHECK(h.Filled && !PreferSurface(h, { shell }, 5) && h.Window.Betti == (std::array<Id, 3>{ { 1, 0, 1 } }));
  }
  // Several scales: the two walls of a thin tube (0.1 apart, 10^4 points, about
  // 0.05 apart on each wall) are flat within 10 samples and look like a volume
  // within 30, where both walls are in reach; the multi-scale test sees the
  // surface, a volume sample is a volume at every scale.
  {
    clouds::Rng r(11);
    std::vector<Point3> tube(10000);
    for (Point3& p : tube)
    {
      const double rho = r.U() < 1.0 / 1.9 ? 1.0 : 0.9, u = 2 * M_PI * r.U(), z = 2 * r.U() - 1;
      p = { { rho * std::cos(u), rho * std::sin(u), z } };
    }
    const std::vector<double> m = MedianFlatness(tube, { 10, 30, 100 });
    CHECK(m.size() == 3 && m[0] == MedianFlatness(tube, 10) && m[1] == MedianFlatness(tube, 30) &&
      m[2] == MedianFlatness(tube, 100));
    CHECK(m[0] < 0.1 && m[1] > ThresholdRule().SurfaceFlatness * FlatnessScales()[1].Volume);
    CHECK(RelativeFlatness(tube) == m[0] / FlatnessScales()[0].Volume);
    const std::vector<Point3> volume = clouds::Cube(10000, 12);
    CHECK(RelativeFlatness(volume) > 0.8);
    // Under 20 samples per neighbourhood size no scale is tried.
    CHECK(RelativeFlatness(clouds::Sphere(199, 5)) == 1 && RelativeFlatness(clouds::Sphere(200, 5)) < 0.1);
    ThresholdChoice c = ChooseThresholds({ Torus }, 6);
    c.Window.Betti = { { 1, 1, 0 } };
    CheckFilled(c, tube, 5000);
    CHECK(c.Filled);
    CheckFilled(c, volume, 5000);
    CHECK(!c.Filled && c.Flatness > 0.8);
  }
  // Solid depth: known answers on cube lattices, the search's limit, and two
  // solids apart (the deeper counts).
  {
    CHECK(SolidDepth({}, 2) == -1);
    CHECK(SolidDepth({ { { 4, 1, 7, 9 } } }, 2) == 0); // one tetrahedron: all boundary
    for (int n = 1; n <= 7; ++n)
    {
      std::vector<std::array<Id, 4>> tets;
      KuhnCubes(n, { { 0, 0, 0 } }, n, tets);
      CHECK(SolidDepth(tets, 10) == n / 2);
      CHECK(SolidDepth(tets, 1) == std::min(n / 2, 2)); // stops past the limit
    }
    std::vector<std::array<Id, 4>> two;
    KuhnCubes(2, { { 0, 0, 0 } }, 12, two);
    KuhnCubes(6, { { 5, 5, 5 } }, 12, two); // apart: depth 1 and 3
    CHECK(SolidDepth(two, 10) == 3);
    bool threw = false;
    try
    {
      SolidDepth({ { { 1, 2, 2, 3 } } }, 2);
    }
    catch (const InputError&)
    {
      threw = true;
    }
    CHECK(threw);
    // The shallow check: only a solid answer (no void, enough maxima) that is
    // not already Filled is measured, and it is shallow at depth <= 2.
    std::vector<std::array<Id, 4>> shallow, deep;
    KuhnCubes(4, { { 0, 0, 0 } }, 4, shallow); // depth 2
    KuhnCubes(6, { { 0, 0, 0 } }, 6, deep);    // depth 3
    ThresholdChoice c = ChooseThresholds({ Torus }, 6);
    c.Window.Betti = { { 1, 0, 0 } };
    c.Samples = 1000;
    c.Maxima = 500;
    CheckShallow(c, shallow);
    CHECK(c.Shallow && c.Depth == 2);
    CheckShallow(c, deep);
    CHECK(!c.Shallow && c.Depth == 3);
    c.Maxima = 100; // a few slivers: not a solid
    CheckShallow(c, shallow);
    CHECK(!c.Shallow && c.Depth == -1);
    c.Maxima = 500;
    c.Filled = true; // warned already
    CheckShallow(c, shallow);
    CHECK(!c.Shallow && c.Depth == -1);
    c.Filled = false;
    c.Window.Betti = { { 1, 0, 1 } }; // a void: a surface
    CheckShallow(c, shallow);
    CHECK(!c.Shallow && c.Depth == -1);
  }
  // Parts held together only by long edges. The spacing is the k-th nearest
  // other place: on a unit grid an inner sample's 6th is sqrt(2) (4 at 1, 4
  // at sqrt(2)), a corner's sqrt(5) (1, 1, sqrt(2), 2, 2, sqrt(5)).
  {
    std::vector<Point3> line;
    for (int x = 0; x < 10; ++x)
    {
      line.push_back({ { static_cast<double>(x), 0, 0 } });
    }
    line.push_back(line[0]); // a duplicate is no neighbour
    const std::vector<double> s = NeighbourSpacing(line, {}, 2);
    CHECK(s[0] == 2 && s[5] == 1 && s[9] == 2 && s[10] == 2);
    CHECK(NeighbourSpacing(line, {}, 50)[0] == 9); // fewer places than k: the farthest
    std::vector<char> wanted(line.size(), 0);
    wanted[3] = 1;
    const std::vector<double> only = NeighbourSpacing(line, wanted, 2);
    CHECK(only[3] == 1 && only[0] == 0);

    // Two 10 x 10 unit grids, triangulated, `gap` apart along z, and a
    // triangle from the first's (5, 5) to the second's (5, 5) and (6, 5).
    const auto grids = [](double gap, std::vector<Point3>& points, CompactComplex& cells) {
      points.clear();
      cells = CompactComplex();
      for (int g = 0; g < 2; ++g)
      {
        for (int y = 0; y < 10; ++y)
        {
          for (int x = 0; x < 10; ++x)
          {
            points.push_back({ { static_cast<double>(x), static_cast<double>(y), g * gap } });
          }
        }
        for (Id y = 0; y < 9; ++y)
        {
          for (Id x = 0; x < 9; ++x)
          {
            const Id v = 100 * g + 10 * y + x;
            cells.Triangles.push_back({ { v, v + 1, v + 11 } });
            cells.Triangles.push_back({ { v, v + 10, v + 11 } });
          }
        }
      }
      cells.Triangles.push_back({ { 55, 155, 156 } });
    };
    std::vector<Point3> points;
    CompactComplex cells;
    grids(10, points, cells);
    LongJoins j = FindLongJoins(points, cells, 3, 6, 0.01, 10);
    CHECK(j.Parts == std::vector<Id>({ 100, 100 }));
    CHECK(std::abs(j.Ratio - 10 / std::sqrt(2.0)) < 1e-12 && j.Where[0] == 5 && j.Where[2] == 5);
    CHECK(FindLongJoins(points, cells, 7.5, 6, 0.01, 10).Parts.empty()); // 7.07 is short then
    {
      // The spacing given, as a filter measuring many t_r does: the same.
      const std::vector<double> spacing = NeighbourSpacing(points, {}, 6);
      CHECK(spacing[55] == std::sqrt(2.0) && spacing[0] == std::sqrt(5.0));
      const LongJoins given = FindLongJoins(points, spacing, cells, 3, 0.01, 10);
      CHECK(given.Parts == j.Parts && given.Ratio == j.Ratio && given.Where == j.Where);
    }
    CHECK(FindLongJoins(points, cells, 3, 6, 0.01, 101).Parts.empty()); // parts too small
    CHECK(FindLongJoins(points, cells, 3, 6, 0.6, 10).Parts.empty());   // under 60 % each
    grids(4, points, cells); // 4 / sqrt(2) = 2.83: held by the bridge
    CHECK(FindLongJoins(points, cells, 3, 6, 0.01, 10).Parts.empty());
    // A small piece hung on a long edge is not a part.
    grids(10, points, cells);
    cells.Triangles.pop_back();
    cells.Triangles.push_back({ { 55, 56, 155 } }); // the grids' bridge
    for (int k = 0; k < 3; ++k)
    {
      points.push_back({ { 40.0 + k, 0, 0 } });
    }
    cells.Triangles.push_back({ { 0, 200, 201 } });
    cells.Triangles.push_back({ { 200, 201, 202 } });
    j = FindLongJoins(points, cells, 3, 6, 0.01, 10);
    CHECK(j.Parts == std::vector<Id>({ 100, 100 }) && std::abs(j.Ratio - 10 / std::sqrt(2.0)) < 1e-12);
    // Another long edge, between the corners (10 / sqrt(5) = 4.5): still apart.
    cells.Edges.push_back({ { 99, 199 } });
    CHECK(FindLongJoins(points, cells, 3, 6, 0.01, 10).Parts.size() == 2);
    CHECK(FindLongJoins(points, cells, 4.5, 6, 0.01, 10).Parts.empty()); // short at 4.5

    // A sparser second grid (spacing 3): the edge is long against the finer
    // end (17.3 / sqrt(2) = 12.2), though not against the coarser (17.3 /
    // (3 sqrt(2)) = 4.1), as a dense surface bridged to a sparse one is.
    grids(10, points, cells);
    for (std::size_t v = 100; v < 200; ++v)
    {
      points[v][0] *= 3;
      points[v][1] *= 3;
    }
    CHECK(FindLongJoins(points, cells, 5, 6, 0.01, 10).Parts.size() == 2);
    CHECK(FindLongJoins(points, cells, 13, 6, 0.01, 10).Parts.empty());

    // CheckJoins measures only where the profile cannot tell: voids that share
    // a part, or a solid answer.
    grids(10, points, cells);
    ThresholdChoice c = ChooseThresholds({ Torus }, 6);
    c.Window.Betti = { { 1, 0, 2 } };
    CheckJoins(c, points, cells);
    CHECK(c.Joined == std::vector<Id>({ 100, 100 }) && c.JoinPlace[2] == 5);
    std::vector<double> kept; // filled on the first measure, then read
    CHECK(CheckJoins(c, points, cells, &kept) && kept.size() == points.size() && c.Joined.size() == 2);
    kept.assign(points.size(), 100.0); // every edge short against this spacing
    CHECK(CheckJoins(c, points, cells, &kept) && c.Joined.empty());
    c.Window.Betti = { { 2, 0, 2 } }; // each part with its void
    CheckJoins(c, points, cells);
    CHECK(c.Joined.empty() && c.JoinRatio == 0);
    c.Window.Betti = { { 1, 0, 1 } };
    CheckJoins(c, points, cells);
    CHECK(c.Joined.empty());
    c.Filled = true; // solid around its void
    CheckJoins(c, points, cells);
    CHECK(c.Joined.size() == 2);
    c.Filled = false;
    for (int k = 0; k < 25; ++k) // 25 tetrahedra for 200 samples: SolidShare
    {
      cells.Tetrahedra.push_back({ { k, k + 1, k + 10, k + 11 } });
    }
    CheckJoins(c, points, cells);
    CHECK(c.Joined.size() == 2);
    c.Window.Betti = { { 1, 0, 0 } }; // no void
    CheckJoins(c, points, cells);
    CHECK(c.Joined.empty());

    // Voids sharing a part that no long edge holds together: warned only in a
    // noisy sample. Flat grids measure 0; the same grids moved along z by up
    // to one spacing are about as far from flat as a volume sample at 10
    // neighbours (its 0.46); by 0.02 of it, not noisy.
    const auto shaken = [&grids](double amplitude, std::vector<Point3>& points, CompactComplex& cells) {
      grids(10, points, cells);
      std::mt19937 random(7);
      std::uniform_real_distribution<double> offset(-amplitude, amplitude);
      for (Point3& p : points)
      {
        p[2] += offset(random);
      }
    };
    ThresholdChoice n = ChooseThresholds({ Torus }, 6);
    n.Window.Betti = { { 1, 0, 2 } };
    grids(10, points, cells);
    kept.assign(points.size(), 100.0);
    CHECK(CheckJoins(n, points, cells, &kept) && n.Joined.empty());
    CHECK(!n.NoisyJoin && n.NoiseFlatness >= 0 && n.NoiseFlatness < 1e-9);
    shaken(1, points, cells);
    CHECK(CheckJoins(n, points, cells, &kept) && n.Joined.empty());
    CHECK(n.NoisyJoin && n.NoiseFlatness > 0.5);
    shaken(0.02, points, cells);
    CheckJoins(n, points, cells, &kept);
    CHECK(!n.NoisyJoin && n.NoiseFlatness >= 0 && n.NoiseFlatness < n.Rule.NoisyFlatness / 10);
    shaken(1, points, cells);
    n.Window.Betti = { { 2, 0, 2 } }; // each part with its void: not measured
    CheckJoins(n, points, cells, &kept);
    CHECK(!n.NoisyJoin && n.NoiseFlatness == -1);
    n.Window.Betti = { { 1, 0, 2 } };
    kept.clear(); // the grids' own spacing: the bridge is long, which says it already
    CheckJoins(n, points, cells, &kept);
    CHECK(n.Joined.size() == 2 && !n.NoisyJoin && n.NoiseFlatness == -1);
    // Kept across calls as the spacing is: read, not measured again.
    kept.assign(points.size(), 100.0);
    double noise = 0.125;
    CheckJoins(n, points, cells, &kept, &noise);
    CHECK(n.Joined.empty() && n.NoiseFlatness == 0.125 && !n.NoisyJoin && noise == 0.125);
    noise = -1;
    CheckJoins(n, points, cells, &kept, &noise);
    CHECK(n.NoisyJoin && noise == n.NoiseFlatness && noise > 0.5);
    // Neighbourhoods that say nothing of noise are not noisy: samples on
    // lines 100 times finer along than across (each 10 nearest on one line:
    // flat, 0, where the ratio of two rounding errors used to stand), and
    // each sample given 12 times (its copies fill its neighbourhood: the
    // places are measured).
    {
      std::vector<Point3> rows, copies;
      for (int line = 0; line < 20; ++line)
      {
        for (int k = 0; k < 20; ++k)
        {
          rows.push_back({ { 0.01 * k + 0.003 * line, 1.0 * line, 0.5 * (line % 3) } });
        }
      }
      CHECK(MedianFlatness(rows, 10) == 0);
      n.Window.Betti = { { 1, 0, 2 } };
      std::vector<double> none(rows.size(), 100.0);
      CheckJoins(n, rows, CompactComplex(), &none);
      CHECK(n.NoiseFlatness == 0 && !n.NoisyJoin);
      shaken(0.02, points, cells);
      for (const Point3& p : points)
      {
        copies.insert(copies.end(), 12, p);
      }
      std::vector<double> far(copies.size(), 100.0);
      CheckJoins(n, copies, CompactComplex(), &far);
      CHECK(n.NoiseFlatness >= 0 && n.NoiseFlatness < n.Rule.NoisyFlatness / 10 && !n.NoisyJoin);
    }
    points.resize(150); // under FlatnessMinimumPoints: not measured
    cells = CompactComplex();
    kept.clear();
    CheckJoins(n, points, cells, &kept);
    CHECK(n.Joined.empty() && !n.NoisyJoin && n.NoiseFlatness == -1);
  }
  return check::Finish("TestAutomaticThresholds");
}
