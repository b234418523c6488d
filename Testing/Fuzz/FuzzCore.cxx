// libFuzzer target: the core pipeline on a small point cloud made from the
// input bytes, with the invariants of docs/design.md §3 checked after each stage
// (a violation aborts, which libFuzzer reports as a crash).
//
// Input layout (every byte string is a valid input):
//   byte 0, bits 0-1  how coordinates are read from the rest:
//                       0: 1 byte each, 0..7 (a 8x8x8 grid: duplicates, ties,
//                          cospherical and coplanar sets, right angles)
//                       1: 1 byte each, signed -128..127
//                       2: 2 bytes each, 0..65535 / 65536
//                       3: 8 bytes each, raw IEEE doubles (NaN, inf, denormals)
//           bit 2     eager build (stable and unstable manifolds drawn with the
//                     Hasse diagram) instead of the CLI's path (Hasse diagram
//                     only, then the reconstruction's cells drawn on demand)
//           bits 3-4  persistence threshold t_p: 0, 1.05, 1.1, 1.5
//           bits 5-6  cap T_max of the output-sensitive run: 1.6, 2, 3, 4
//   byte 1            scale: (signed) s with |s| < 100 means 1, else
//                     2^(sign(s) * (|s| - 99) * 40), up to 2^±1160 (overflow and
//                     underflow to denormals and zero)
//   bytes 2..         coordinates, at most 64 points; a trailing partial point
//                     is dropped.
//
// Invariants (abort on violation):
//   - Euler relation n0 - n1 + n2 - n3 = 1 (the maximum at infinity not counted);
//   - critical values: 0 for samples, positive and finite otherwise, at finite
//     locations;
//   - arcs go up one index with multiplicity >= 1 and non-decreasing values
//     (strictly increasing in exact arithmetic, but the doubles may tie);
//     index-1 nodes have two arrivals, index-2 nodes two departures;
//   - boundary of boundary = 0 mod 2 over the odd-multiplicity arcs (arcs to the
//     maximum at infinity excluded), before and after simplification; the
//     survivors still have Euler characteristic 1;
//   - the reconstruction is closed under faces at t_r = infinity (every node with
//     Step >= 0) and at t_r = 2: every arc x -> c of the (simplified) diagram
//     into a reconstructed c has x reconstructed with Threshold(x) <=
//     Threshold(c), as TestReconstruction checks; with t_p = 0 this is closure
//     over the original arcs. The bookkeeping (steps, running maximum, profile)
//     is checked too.
//   - the eager build: every index-2 patch is bounded by its Gabriel edges,
//     each used as often as the arc's multiplicity.
//   - without the eager build, the output-sensitive run (ReconstructBelow,
//     deferred patches) equals the eager one below its cap: the same nodes
//     with the same Step, Priority, Threshold, Kind and Sponsor, and the same
//     cell carriers where they are below the cap (-1 elsewhere).
//   - a run and its carriers, packed as a held t_p candidate is (PackedRun),
//     come back field for field.
//   - the eager build, closure as a set (CheckSetClosure): a face of a drawn
//     cell that is not drawn by then lies inside that cell's drawn geometry.
//     Through simplification owners the node-level closure holds on the
//     simplified diagram only (parity can turn a face into a seam inside the
//     merged stable manifold), see regressions/core/README.md; set
//     FLOWRECON_FUZZ_CARRIER_REPORT=1 to print how often.
//
// Any InputError (non-finite coordinates, fewer than 4 distinct points,
// coplanar points, too degenerate) is an acceptable outcome.
#include "Invariants.h"

#include "AutomaticThresholds.h"
#include "CappedReconstruction.h"
#include "CellHomology.h"
#include "HasseTopology.h"
#include "LocalFlatness.h"
#include "FlowComplexBuilder.h"
#include "Reconstruction.h"
#include "Simplification.h"
#include "StableManifoldGeometry.h"
#include "TopologyInput.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <vector>

using namespace flowrecon;

namespace
{

[[noreturn]] void Fail(const char* what)
{
  std::fprintf(stderr, "FuzzCore: invariant violated: %s\n", what);
  std::abort();
}

#define REQUIRE(cond)                                                                          \
  do                                                                                           \
  {                                                                                            \
    if (!(cond))                                                                               \
      Fail(#cond);                                                                             \
  } while (0)

std::vector<Point3> CloudOf(const std::uint8_t* data, std::size_t size, int& flags)
{
  std::vector<Point3> cloud;
  if (size < 2)
  {
    return cloud;
  }
  flags = data[0];
  const int mode = flags & 3;
  const int s = static_cast<signed char>(data[1]);
  const int exponent = std::abs(s) < 100 ? 0 : (s > 0 ? 1 : -1) * (std::abs(s) - 99) * 40;
  const std::size_t width = mode == 3 ? 8 : mode == 2 ? 2 : 1;
  data += 2;
  size -= 2;
  const std::size_t n = std::min<std::size_t>(size / (3 * width), 64);
  cloud.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const std::uint8_t* b = data + (3 * i + k) * width;
      double x = 0;
      switch (mode)
      {
        case 0:
          x = b[0] & 7;
          break;
        case 1:
          x = static_cast<signed char>(b[0]);
          break;
        case 2:
          x = (b[0] | (b[1] << 8)) / 65536.0;
          break;
        default:
          std::memcpy(&x, b, 8);
      }
      cloud[i][k] = std::ldexp(x, exponent);
    }
  }
  return cloud;
}

void CheckComplex(const FlowComplex& fc)
{
  const auto n = fc.CountByIndex();
  REQUIRE(n[0] - n[1] + n[2] - n[3] == 1);
  REQUIRE(!fc.Nodes.empty() && fc.Nodes.back().IsInfinity() &&
    fc.InfinityNode == static_cast<Id>(fc.Nodes.size()) - 1);
  const Id count = static_cast<Id>(fc.Nodes.size());
  // Critical values are distances: 0 for samples, positive and finite for the
  // other finite nodes, at finite locations.
  for (const Node& node : fc.Nodes)
  {
    if (node.IsInfinity())
      continue;
    REQUIRE(std::isfinite(node.Location[0]) && std::isfinite(node.Location[1]) &&
      std::isfinite(node.Location[2]));
    REQUIRE(node.Index == 0 ? node.Value == 0 : (node.Value > 0 && std::isfinite(node.Value)));
  }
  std::vector<int> down(fc.Nodes.size(), 0), up(fc.Nodes.size(), 0);
  for (const Arc& a : fc.Arcs)
  {
    REQUIRE(a.Lower >= 0 && a.Lower < count && a.Upper >= 0 && a.Upper < count);
    const Node& lower = fc.Nodes[a.Lower];
    const Node& upper = fc.Nodes[a.Upper];
    REQUIRE(upper.Index == lower.Index + 1);
    REQUIRE(a.Multiplicity >= 1);
    // Strictly increasing in exact arithmetic; the doubles may tie (the builder
    // makes them non-decreasing), also without perturbation: a triangle within
    // an ulp of a right angle has its circumradius equal to half its edge.
    REQUIRE(lower.Value <= upper.Value);
    down[a.Upper] += a.Multiplicity;
    if (lower.Index == 2)
      up[a.Lower] += a.Multiplicity;
  }
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    if (fc.Nodes[i].Index == 1)
      REQUIRE(down[i] == 2);
    if (fc.Nodes[i].Index == 2)
      REQUIRE(up[i] == 2 && down[i] >= 1);
  }
  REQUIRE(invariants::BoundaryOfBoundaryIsZero(fc.Nodes, fc.Arcs, false));
}

/// Patches are bounded by their Gabriel edges, used as often as the arc's
/// multiplicity; other edges of a patch are shared by two of its triangles.
void CheckPatches(const FlowComplex& fc)
{
  REQUIRE(invariants::PatchesBoundedByGabrielEdges(fc, invariants::PatchEdgeUse(fc)));
}

/// The reconstruction at t is closed as a set: a face x of a drawn cell u (an
/// original arc x -> u) that is not drawn itself by then lies inside u's drawn
/// geometry. (Through simplification owners the node-level closure holds on the
/// simplified diagram only: parity can take x out of the merged boundary, where
/// it becomes a seam of the merged stable manifold; see regressions/core/README.md.)
void CheckSetClosure(const FlowComplex& fc, const ReconstructionResult& run,
  const std::vector<Id>& carriers, double t, Id& seams)
{
  auto drawnAt = [&](Id node) {
    const Id c = carriers[node];
    return c >= 0 && (std::isinf(t) ? run.Nodes[c].Step >= 0 : run.Contains(c, t));
  };
  std::map<Id, std::vector<std::array<Id, 3>>> triangles;
  std::map<Id, std::vector<std::array<Id, 4>>> tetrahedra;
  for (std::size_t i = 0; i < fc.Triangles.size(); ++i)
  {
    std::array<Id, 3> tr = fc.Triangles[i];
    std::sort(tr.begin(), tr.end());
    triangles[fc.TriangleNode[i]].push_back(tr);
  }
  for (std::size_t i = 0; i < fc.Tetrahedra.size(); ++i)
  {
    std::array<Id, 4> te = fc.Tetrahedra[i];
    std::sort(te.begin(), te.end());
    tetrahedra[fc.TetrahedronNode[i]].push_back(te);
  }
  auto contains = [](const auto& big, const auto& small) {
    return std::includes(big.begin(), big.end(), small.begin(), small.end());
  };
  for (const Arc& a : fc.Arcs)
  {
    const Node& x = fc.Nodes[a.Lower];
    const Node& u = fc.Nodes[a.Upper];
    if (u.IsInfinity() || !drawnAt(a.Upper))
      continue;
    const Id cu = carriers[a.Upper], cx = carriers[a.Lower];
    if (cx >= 0 && drawnAt(a.Lower) && run.Nodes[cx].Threshold <= run.Nodes[cu].Threshold)
      continue;
    ++seams;
    if (x.Index == 0)
    {
      REQUIRE(x.Simplex[0] == u.Simplex[0] || x.Simplex[0] == u.Simplex[1]);
    }
    else if (x.Index == 1)
    {
      // The sample segment is an edge of one of u's triangles.
      const std::array<Id, 2> edge{ { std::min(x.Simplex[0], x.Simplex[1]),
        std::max(x.Simplex[0], x.Simplex[1]) } };
      bool found = false;
      for (const auto& tr : triangles[a.Upper])
        found = found || contains(tr, edge);
      REQUIRE(found);
    }
    else
    {
      // Every triangle of x's patch is a face of one of u's tetrahedra.
      REQUIRE(!triangles[a.Lower].empty());
      for (const auto& tr : triangles[a.Lower])
      {
        bool found = false;
        for (const auto& te : tetrahedra[a.Upper])
          found = found || contains(te, tr);
        REQUIRE(found);
      }
    }
  }
}

void CheckSimplification(const FlowComplex& fc, const SimplificationResult& s, double tp)
{
  REQUIRE(s.Survives.size() == fc.Nodes.size() && s.Survives.back());
  std::vector<bool> cancelled(fc.Nodes.size(), false);
  double previous = 0;
  for (const CancelledPair& p : s.Pairs)
  {
    REQUIRE(p.Ratio <= tp && p.Ratio >= previous);
    previous = p.Ratio;
    REQUIRE(fc.Nodes[p.Upper].Index == fc.Nodes[p.Lower].Index + 1);
    REQUIRE(!cancelled[p.Lower] && !cancelled[p.Upper]);
    cancelled[p.Lower] = cancelled[p.Upper] = true;
  }
  Id euler = 0;
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    REQUIRE(s.Survives[i] == !cancelled[i]);
    if (s.Survives[i] && !fc.Nodes[i].IsInfinity())
      euler += fc.Nodes[i].Index % 2 == 0 ? 1 : -1;
  }
  REQUIRE(euler == 1);
  for (const Arc& a : s.Arcs)
  {
    REQUIRE(s.Survives[a.Lower] && s.Survives[a.Upper] && a.Multiplicity >= 1);
    REQUIRE(fc.Nodes[a.Upper].Index == fc.Nodes[a.Lower].Index + 1);
  }
  REQUIRE(invariants::BoundaryOfBoundaryIsZero(fc.Nodes, s.Arcs, false));
}

void CheckReconstruction(const FlowComplex& fc, const std::vector<Arc>& arcs,
  const SimplificationResult& s, const ReconstructionResult& r, double tp)
{
  const std::vector<Node>& nodes = fc.Nodes;
  REQUIRE(r.Nodes.size() == nodes.size());
  REQUIRE(r.InitializationCount >= 0 &&
    static_cast<std::size_t>(r.InitializationCount) <= r.Order.size());
  double running = 1;
  for (std::size_t k = 0; k < r.Order.size(); ++k)
  {
    const Id node = r.Order[k];
    REQUIRE(node >= 0 && node < static_cast<Id>(nodes.size()));
    const Insertion& i = r.Nodes[node];
    running = std::max(running, i.Priority);
    REQUIRE(i.Step == static_cast<Id>(k) && i.Threshold == running && i.Priority >= 1);
    REQUIRE(s.Survives[node] && !nodes[node].IsInfinity());
  }
  Id inserted = 0;
  for (const Insertion& i : r.Nodes)
    inserted += i.Step >= 0 ? 1 : 0;
  REQUIRE(inserted == static_cast<Id>(r.Order.size()));

  // Closure under faces at t_r = inf and at t_r = 2.
  for (const double t : { HUGE_VAL, 2.0 })
  {
    for (const Arc& a : arcs)
    {
      const bool upperIn = std::isinf(t) ? r.Nodes[a.Upper].Step >= 0 : r.Contains(a.Upper, t);
      if (upperIn)
      {
        REQUIRE(r.Nodes[a.Lower].Step >= 0);
        REQUIRE(r.Nodes[a.Lower].Threshold <= r.Nodes[a.Upper].Threshold);
      }
    }
  }

  // Node-level closure through owners: a report (see CheckSetClosure).
  static const bool report = std::getenv("FLOWRECON_FUZZ_CARRIER_REPORT") != nullptr;
  if (report)
  {
    const std::vector<Id> carriers = CellCarriers(r, tp >= 1 ? &s : nullptr);
    Id never = 0, later = 0, checked = 0;
    for (const Arc& a : fc.Arcs)
    {
      if (a.Multiplicity % 2 == 0 || nodes[a.Upper].IsInfinity() || carriers[a.Upper] < 0)
        continue;
      ++checked;
      const Id cu = carriers[a.Upper], cl = carriers[a.Lower];
      if (cl >= 0 && r.Nodes[cl].Threshold <= r.Nodes[cu].Threshold)
        continue;
      if (never + later == 0)
      {
        std::fprintf(stderr, "carrier closure: face %d (index %d, %s, carrier %lld) of %d (index %d, "
          "%s, carrier %lld at threshold %.17g) is %s\n", a.Lower, nodes[a.Lower].Index,
          s.Survives[a.Lower] ? "survives" : "cancelled", static_cast<long long>(cl), a.Upper,
          nodes[a.Upper].Index, s.Survives[a.Upper] ? "survives" : "cancelled",
          static_cast<long long>(cu), r.Nodes[cu].Threshold,
          cl < 0 ? "never drawn" : "drawn later");
      }
      ++(cl < 0 ? never : later);
    }
    std::fprintf(stderr, "carrier closure: t_p %g, of %lld odd arcs into drawn cells, %lld have "
      "their face never drawn, %lld drawn later\n", tp, static_cast<long long>(checked),
      static_cast<long long>(never), static_cast<long long>(later));
  }
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // One thread: the campaign runs beside other work, and the output does not
  // depend on the number of threads (tested elsewhere).
  static tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  return 0;
}

/// The Betti numbers `profile` gives at t_r = t (row k holds for t_r in
/// (Threshold_k, Threshold_k+1]); false before its first row.
bool BettiAt(const std::vector<TopologyStep>& profile, double t, std::array<Id, 3>& betti)
{
  bool found = false;
  for (const TopologyStep& step : profile)
  {
    if (step.Threshold < t)
    {
      betti = { { step.Betti[0], step.Betti[1], step.Betti[2] } };
      found = true;
    }
  }
  return found;
}

/// The automatic thresholds on the profiles of a fuzzed cloud (AutomaticThresholds.h):
/// t_r inside the chosen window, the window's Betti numbers those of the chosen
/// profile at t_r, a stable window as long as the rule asks, the same answer
/// twice; a given t_r picks a candidate with the Betti numbers there; the
/// flatness of any cloud is a number in [0, 1].
void CheckAutomatic(const std::vector<std::vector<TopologyStep>>& profiles, double cap,
  const std::vector<Point3>& cloud)
{
  const ThresholdRule rule;
  if (!(cap > rule.Lowest))
  {
    return;
  }
  const ThresholdChoice c = ChooseThresholds(profiles, cap);
  const ThresholdChoice again = ChooseThresholds(profiles, cap);
  REQUIRE(c.Candidate == again.Candidate && c.ReconstructionThreshold == again.ReconstructionThreshold &&
    c.Window.From == again.Window.From && c.Window.To == again.Window.To && c.Window.Betti == again.Window.Betti);
  REQUIRE(c.Candidate < profiles.size());
  const double tr = c.ReconstructionThreshold;
  REQUIRE(std::isfinite(tr) && tr > rule.Lowest && tr <= cap);
  if (c.Window.Length() > 0)
  {
    REQUIRE(c.Window.From < tr && tr <= c.Window.To && c.Window.To <= cap);
    std::array<Id, 3> betti{};
    REQUIRE(BettiAt(profiles[c.Candidate], tr, betti) && betti == c.Window.Betti);
    REQUIRE(c.Unstable() || c.Window.To >= rule.Stable * c.Window.From * (1 - 1e-12));
    const ThresholdChoice p = ChoosePersistence(profiles, tr, cap);
    std::array<Id, 3> there{};
    REQUIRE(p.Candidate < profiles.size() && BettiAt(profiles[p.Candidate], tr, there));
  }
  const double flat = RelativeFlatness(cloud);
  REQUIRE(flat >= 0 && flat <= 1);
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  int flags = 0;
  const std::vector<Point3> cloud = CloudOf(data, size, flags);
  const bool eager = (flags & 4) != 0;
  static const double thresholds[4] = { 0.0, 1.05, 1.1, 1.5 };
  const double tp = thresholds[(flags >> 3) & 3];

  BuildOptions options;
  options.StableManifolds = eager;
  options.UnstableManifolds = eager;
  FlowComplex fc;
  try
  {
    fc = BuildFlowComplex(cloud, options, Progress());
  }
  catch (const InputError&)
  {
    return 0;
  }
  CheckComplex(fc);
  if (eager)
  {
    CheckPatches(fc);
    for (const FlowLine& line : fc.FlowLines)
    {
      REQUIRE(line.Node >= 0 && line.Node < static_cast<Id>(fc.Nodes.size()));
      REQUIRE(fc.Nodes[line.Node].Index == 2);
      REQUIRE(line.Target >= 0 && fc.Nodes[line.Target].Index == 3);
    }
  }

  // The CLI's path (Filters/CloudReconstruction.cxx, ReconstructCloud).
  const SimplificationResult s = Simplify(fc.Nodes, fc.Arcs, tp, Progress());
  CheckSimplification(fc, s, tp);
  const std::vector<Arc>& arcs = tp >= 1 ? s.Arcs : fc.Arcs;
  const std::vector<bool> survives = tp >= 1 ? s.Survives : std::vector<bool>(fc.Nodes.size(), true);
  if (tp < 1)
  {
    REQUIRE(s.Pairs.empty());
  }
  const std::vector<Id> init =
    InitializationEdges(fc.Nodes, NearestNeighboursFromDiagram(fc.Nodes, arcs));
  const ReconstructionResult run = Reconstruct(fc.Nodes, arcs, survives, init, HUGE_VAL, Progress());
  CheckReconstruction(fc, arcs, s, run, tp);
  // Nestedness: the run at t_r = 2 is the Threshold < 2 prefix.
  const ReconstructionResult at2 = Reconstruct(fc.Nodes, arcs, survives, init, 2.0, Progress());
  for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
  {
    REQUIRE((at2.Nodes[i].Step >= 0) == run.Contains(static_cast<Id>(i), 2.0));
  }
  const std::vector<Id> carriers = CellCarriers(run, tp >= 1 ? &s : nullptr);
  {
    ReconstructionResult back;
    std::vector<Id> backCarriers;
    Unpack(Pack(run, carriers), back, backCarriers);
    REQUIRE(back.Order == run.Order && back.InitializationCount == run.InitializationCount &&
      back.Nodes.size() == run.Nodes.size() && backCarriers == carriers);
    for (std::size_t i = 0; i < run.Nodes.size(); ++i)
    {
      const Insertion& a = run.Nodes[i];
      const Insertion& b = back.Nodes[i];
      REQUIRE(a.Step == b.Step && a.Priority == b.Priority && a.Threshold == b.Threshold &&
        a.Kind == b.Kind && a.Sponsor == b.Sponsor);
    }
  }
  if (eager)
  {
    Id seams = 0;
    for (const double t : { HUGE_VAL, 2.0 })
      CheckSetClosure(fc, run, carriers, t, seams);
    if (std::getenv("FLOWRECON_FUZZ_CARRIER_REPORT"))
      std::fprintf(stderr, "set closure: t_p %g, %lld faces not drawn with their cell, all inside it\n",
        tp, static_cast<long long>(seams));
  }
  else
  {
    // The output-sensitive run against this eager one, its oracle.
    static const double caps[4] = { 1.6, 2.0, 3.0, 4.0 };
    const double cap = caps[(flags >> 5) & 3];
    CappedReconstruction capped;
    try
    {
      capped = ReconstructBelow(cloud, options, tp, cap, true, Progress(), true);
    }
    catch (const InputError& e)
    {
      std::fprintf(stderr, "FuzzCore: the capped run refused what the eager one took: %s\n", e.what());
      std::abort();
    }
    REQUIRE(capped.Complex.Nodes.size() == fc.Nodes.size());
    for (std::size_t i = 0; i < fc.Nodes.size(); ++i)
    {
      const Insertion& e = run.Nodes[i];
      const Insertion& l = capped.Run.Nodes[i];
      const bool below = run.Contains(static_cast<Id>(i), cap);
      REQUIRE((l.Step >= 0) == below);
      if (below)
      {
        REQUIRE(l.Step == e.Step && l.Priority == e.Priority && l.Threshold == e.Threshold &&
          l.Kind == e.Kind && l.Sponsor == e.Sponsor);
      }
      const Id c = carriers[i];
      REQUIRE(capped.Carriers[i] == (c >= 0 && run.Contains(c, cap) ? c : -1));
    }

    // The Betti numbers of every reconstruction below the cap: the capped run's
    // (its pending lines ended in regions of the complement, TopologyInput.h)
    // against the eager diagram's, where every line is followed.
    auto profile = [&](auto&& bars, std::vector<TopologyStep>& out) {
      try
      {
        out = TopologyProfile(bars(), 1, cap);
        return true;
      }
      catch (const InputError&)
      {
        return false;
      }
    };
    std::vector<TopologyStep> lazy, full;
    bool lazyOk = false;
    try
    {
      lazyOk = profile([&] {
        const TopologyInput input = TopologyOfCappedRun(capped);
        return HasseBarcode(capped.Complex.Nodes, input.Arcs, input.Presence, input.Joined);
      }, lazy);
    }
    catch (const Degenerate&)
    {
      lazyOk = false; // a tie in a late walk: the CLI builds again eagerly
      lazy.clear();
    }
    const bool fullOk = profile(
      [&] { return HasseBarcode(fc.Nodes, fc.Arcs, PresenceTimes(fc.Nodes, fc.Arcs, carriers, run)); },
      full);
    if (lazyOk && fullOk)
    {
      REQUIRE(lazy.size() == full.size());
      for (std::size_t k = 0; k < lazy.size(); ++k)
      {
        REQUIRE(lazy[k].Threshold == full[k].Threshold && lazy[k].Betti == full[k].Betti);
      }
    }
    if (fullOk)
    {
      // With the eager profile as a second candidate's: ties settle the same.
      CheckAutomatic({ full }, cap, cloud);
      if (lazyOk)
      {
        CheckAutomatic({ lazy, full }, cap, cloud);
      }
    }

    // Draw what `flowrecon reconstruct --tr 2` writes.
    const std::vector<Id> draw = NodesToDraw(fc.Nodes, carriers, run, 2.0);
    try
    {
      DrawStableManifolds(cloud, options, draw, fc, Progress(), "fuzz");
    }
    catch (const InputError& e)
    {
      std::fprintf(stderr, "FuzzCore: DrawStableManifolds refused its own complex: %s\n", e.what());
      std::abort();
    }
    for (std::size_t t = 0; t < fc.Triangles.size(); ++t)
    {
      for (const Id p : fc.Triangles[t])
        REQUIRE(p >= 0 && p < static_cast<Id>(fc.Points.size()));
      REQUIRE(std::find(draw.begin(), draw.end(), fc.TriangleNode[t]) != draw.end());
    }
    for (std::size_t t = 0; t < fc.Tetrahedra.size(); ++t)
    {
      for (const Id p : fc.Tetrahedra[t])
        REQUIRE(p >= 0 && p < static_cast<Id>(fc.Points.size()));
    }
  }
  return 0;
}
