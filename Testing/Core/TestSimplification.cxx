// Simplification of the Hasse diagram (paper §3.3): hand-made diagrams with
// answers worked out by hand, then properties on real flow complexes: cancelled
// pairs are persistence pairs and the rest of the diagram is unchanged, the
// chain complex stays one (boundary of boundary is zero mod 2, Euler
// characteristic), the result matches a plain re-implementation of the rule,
// ownership is transitive and ends on survivors.
#include "Check.h"
#include "Invariants.h"
#include "ReconFixtures.h"

#include "FlowComplexBuilder.h"
#include "Persistence.h"
#include "Simplification.h"

#include <iostream>
#include <set>
#include <tuple>

using namespace flowrecon;
using namespace fixtures;

namespace
{

using ArcKey = std::pair<Id, Id>;

bool SamePair(const CancelledPair& p, Id lower, Id upper, double ratio)
{
  return p.Lower == lower && p.Upper == upper && std::fabs(p.Ratio - ratio) < 1e-12;
}

/// Fig. 1-2 of the paper (ReconFixtures.h).
void TestFigure2()
{
  std::cout << "-- Fig. 2\n";
  const Diagram d = Fig1();
  const auto original = ArcMap(d.Arcs);

  // Ratios of the candidates: (s2,M1) 1.3/1.2 = 1.0833, (s3,M1) 1.1818,
  // (s5,M2) 1.25, (s1,M1) 1.3, (s4,M2) 1.333, (s2,M2) 1.667; arcs to infinity
  // and from samples are never candidates. t_p = 0 and t_p = 1 cancel nothing.
  for (const double tp : { 0.0, 1.0, 1.08 })
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, tp, Progress());
    CHECK(r.Pairs.empty());
    CHECK(ArcMap(r.Arcs) == original);
    CHECK(std::count(r.Survives.begin(), r.Survives.end(), true) == 12);
    CHECK(r.Owners.Values.empty() && r.Owners.Offsets.size() == 13);
  }

  // t_p = 1.1: cancel (s2, M1). In(M1) \ s2 = {s1, s3}, Out(s2) \ M1 = {M2}: new
  // arcs s1->M2 and s3->M2; the stable manifolds of s2 and M1 go to M2 (the
  // paper's Fig. 2b). Next ratio is (s5,M2) = 1.25 > 1.1: stop.
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.1, Progress());
    CHECK(r.Pairs.size() == 1);
    CHECK(SamePair(r.Pairs[0], S2, M1, 1.3 / 1.2));
    CHECK(r.Pairs[0].Birth == 1.2 && r.Pairs[0].Death == 1.3 && r.Pairs[0].PairType == 1);
    CHECK(!r.Survives[S2] && !r.Survives[M1]);
    CHECK(std::count(r.Survives.begin(), r.Survives.end(), true) == 10);
    const std::map<ArcKey, int> expected = { { { P0, S1 }, 1 }, { { P1, S1 }, 1 },
      { { P0, S5 }, 1 }, { { P3, S5 }, 1 }, { { P1, S3 }, 1 }, { { P2, S3 }, 1 },
      { { P2, S4 }, 1 }, { { P3, S4 }, 1 }, { { S1, M2 }, 1 }, { { S1, Inf }, 1 },
      { { S5, M2 }, 1 }, { { S5, Inf }, 1 }, { { S3, M2 }, 1 }, { { S3, Inf }, 1 },
      { { S4, M2 }, 1 }, { { S4, Inf }, 1 } };
    CHECK(ArcMap(r.Arcs) == expected);
    CHECK(r.OwnersOf(S2) == std::vector<Id>{ M2 });
    CHECK(r.OwnersOf(M1) == std::vector<Id>{ M2 });
    CHECK(r.OwnersOf(M2).empty() && r.OwnersOf(P0).empty());
  }

  // t_p = 1.3 (and inf): then cancel (s5, M2), ratio 2/1.6 = 1.25. In(M2) \ s5 =
  // {s1, s3, s4}, Out(s5) \ M2 = {inf}: s1->inf, s3->inf, s4->inf already exist
  // with multiplicity 1, so modulo 2 all three disappear. Nothing is left but
  // samples and the edges s1, s3, s4 (a spanning tree: Euler characteristic 1).
  // Ownership is transitive: s2 and M1 went to M2, which went to infinity.
  for (const double tp : { 1.3, HUGE_VAL })
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, tp, Progress());
    CHECK(r.Pairs.size() == 2);
    if (r.Pairs.size() == 2)
    {
      CHECK(SamePair(r.Pairs[0], S2, M1, 1.3 / 1.2));
      CHECK(SamePair(r.Pairs[1], S5, M2, 2.0 / 1.6));
    }
    const std::map<ArcKey, int> expected = { { { P0, S1 }, 1 }, { { P1, S1 }, 1 },
      { { P1, S3 }, 1 }, { { P2, S3 }, 1 }, { { P2, S4 }, 1 }, { { P3, S4 }, 1 } };
    CHECK(ArcMap(r.Arcs) == expected);
    CHECK(r.Survives[Inf]);
    for (const Id n : { S2, M1, S5, M2 })
    {
      CHECK(!r.Survives[n]);
      CHECK(r.OwnersOf(n) == std::vector<Id>{ Inf });
    }
  }
}

/// Even arcs: they are never candidates, and an even contribution changes
/// nothing modulo 2. Owners include the even successors of a.
///   ids: e 0 (index 1, 1.0), f 1 (1, 1.05), s 2 (2, 1.1), s2 3 (2, 1.5),
///        s3 4 (2, 1.6), M 5 (3, 1.7), inf 6 (3).
///   arcs: e->s x2, f->s, f->s2, f->s3 x2, e->s2, s->M x2, s2->inf x2, s3->inf,
///         s3->M.
/// Candidates: (f,s) 1.0476, (s3,M) 1.0625, (f,s2) 1.4286, (e,s2) 1.5; e->s and
/// s->M are even.
void TestEvenArcs()
{
  std::cout << "-- even arcs\n";
  Diagram d;
  d.Nodes = { MakeNode(1, 1.0, { { 0, 1, -1, -1 } }), MakeNode(1, 1.05, { { 0, 2, -1, -1 } }),
    MakeNode(2, 1.1, { { 0, 1, 2, -1 } }), MakeNode(2, 1.5, { { 0, 1, 3, -1 } }),
    MakeNode(2, 1.6, { { 0, 2, 3, -1 } }), MakeNode(3, 1.7, { { 0, 1, 2, 3 } }), Infinity(3) };
  d.Link(0, 2, 2);
  d.Link(1, 2);
  d.Link(1, 3);
  d.Link(1, 4, 2);
  d.Link(0, 3);
  d.Link(2, 5, 2);
  d.Link(3, 6, 2);
  d.Link(4, 6);
  d.Link(4, 5);

  // t_p = 1.05: cancel (f, s). Odd In(s) \ f is empty (e->s is even: its
  // contribution 2 x 1 is 0 mod 2, so e->s2 keeps multiplicity 1); no new arc.
  // Owners of f and s: Out(f) \ s = {s2, s3}, s3 through an even arc.
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.05, Progress());
    CHECK(r.Pairs.size() == 1 && SamePair(r.Pairs[0], 1, 2, 1.1 / 1.05));
    const std::map<ArcKey, int> expected = { { { 0, 3 }, 1 }, { { 3, 6 }, 2 }, { { 4, 6 }, 1 },
      { { 4, 5 }, 1 } };
    CHECK(ArcMap(r.Arcs) == expected);
    CHECK(r.OwnersOf(1) == (std::vector<Id>{ 3, 4 }));
    CHECK(r.OwnersOf(2) == (std::vector<Id>{ 3, 4 }));
  }
  // t_p = 1.07: then (s3, M) at 1.0625: In(M) \ s3 is empty now, Out(s3) \ M =
  // {inf}. s3 and M go to infinity, so f and s now belong to {s2, inf}.
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.07, Progress());
    CHECK(r.Pairs.size() == 2);
    if (r.Pairs.size() == 2)
    {
      CHECK(SamePair(r.Pairs[1], 4, 5, 1.7 / 1.6));
      CHECK(r.Pairs[1].PairType == 2);
    }
    const std::map<ArcKey, int> expected = { { { 0, 3 }, 1 }, { { 3, 6 }, 2 } };
    CHECK(ArcMap(r.Arcs) == expected);
    CHECK(r.OwnersOf(1) == (std::vector<Id>{ 3, 6 }));
    CHECK(r.OwnersOf(2) == (std::vector<Id>{ 3, 6 }));
    CHECK(r.OwnersOf(4) == std::vector<Id>{ 6 });
    CHECK(r.OwnersOf(5) == std::vector<Id>{ 6 });
  }
  // The same diagram with every arc of multiplicity 2 given as two arcs of
  // multiplicity 1, in reverse order: repeats are merged (a saved file may hold
  // them), so the simplification is the same.
  {
    Diagram split = d;
    split.Arcs.clear();
    for (auto it = d.Arcs.rbegin(); it != d.Arcs.rend(); ++it)
    {
      for (int k = 0; k < it->Multiplicity; ++k)
      {
        split.Arcs.emplace_back(it->Lower, it->Upper, 1);
      }
    }
    CHECK(split.Arcs.size() == d.Arcs.size() + 4);
    const SimplificationResult a = Simplify(d.Nodes, d.Arcs, 1.07, Progress());
    const SimplificationResult b = Simplify(split.Nodes, split.Arcs, 1.07, Progress());
    CHECK(ArcMap(a.Arcs) == ArcMap(b.Arcs) && a.Pairs.size() == b.Pairs.size());
    CHECK(a.Survives == b.Survives && a.Owners.Values == b.Owners.Values);
    const SimplificationResult none = Simplify(split.Nodes, split.Arcs, 0, Progress());
    CHECK(ArcMap(none.Arcs) == ArcMap(d.Arcs));
  }
  // An even arc with the least ratio of all is not a candidate: here s->M would
  // be 1.7/1.1 = 1.545; with f->s and s3->M removed from the diagram the least
  // odd candidate is (f,s2) 1.4286, cancelled at t_p = 1.45 while s->M stays.
  {
    Diagram e = d;
    e.Arcs.erase(std::remove_if(e.Arcs.begin(), e.Arcs.end(),
                   [](const Arc& a) { return (a.Lower == 1 && a.Upper == 2) || (a.Lower == 4 && a.Upper == 5); }),
      e.Arcs.end());
    e.Nodes[5].Value = 1.12; // s->M ratio 1.018, even: still not a candidate
    const SimplificationResult r = Simplify(e.Nodes, e.Arcs, 1.45, Progress());
    CHECK(r.Pairs.size() == 1 && SamePair(r.Pairs[0], 1, 3, 1.5 / 1.05));
    CHECK(r.Survives[2] && r.Survives[5]);
  }
}

/// A cancellation creates an arc that is cancelled in its turn.
///   ids: x 0 (index 1, 0.9), a 1 (1, 1.0), b 2 (2, 1.02), y 3 (2, 1.3),
///        z 4 (2, 2.0), inf 5 (3). Arcs x->b, a->b, a->y, x->z, b/y/z->inf x2.
/// (a,b) 1.02 goes first and creates x->y (ratio 1.3/0.9 = 1.444); at t_p = 1.5
/// that new arc is cancelled next (x->b and a->y are stale by then). Owners: a
/// and b went to y, which went with x to z: all four end on z.
void TestNewArcCancelled()
{
  std::cout << "-- a new arc is cancelled\n";
  Diagram d;
  d.Nodes = { MakeNode(1, 0.9, { { 0, 1, -1, -1 } }), MakeNode(1, 1.0, { { 0, 2, -1, -1 } }),
    MakeNode(2, 1.02, { { 0, 1, 2, -1 } }), MakeNode(2, 1.3, { { 0, 1, 3, -1 } }),
    MakeNode(2, 2.0, { { 0, 2, 3, -1 } }), Infinity(3) };
  d.Link(0, 2);
  d.Link(1, 2);
  d.Link(1, 3);
  d.Link(0, 4);
  d.Link(2, 5, 2);
  d.Link(3, 5, 2);
  d.Link(4, 5, 2);
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.2, Progress());
    CHECK(r.Pairs.size() == 1 && SamePair(r.Pairs[0], 1, 2, 1.02));
    const std::map<ArcKey, int> expected = { { { 0, 3 }, 1 }, { { 0, 4 }, 1 }, { { 3, 5 }, 2 },
      { { 4, 5 }, 2 } };
    CHECK(ArcMap(r.Arcs) == expected);
  }
  {
    const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.5, Progress());
    CHECK(r.Pairs.size() == 2);
    if (r.Pairs.size() == 2)
    {
      CHECK(SamePair(r.Pairs[1], 0, 3, 1.3 / 0.9));
      CHECK(r.Pairs[0].Ratio <= r.Pairs[1].Ratio);
    }
    const std::map<ArcKey, int> expected = { { { 4, 5 }, 2 } };
    CHECK(ArcMap(r.Arcs) == expected);
    for (const Id n : { 0, 1, 2, 3 })
    {
      CHECK(r.OwnersOf(n) == std::vector<Id>{ 4 });
    }
  }
}

/// Equal ratios: the pair with the smaller lower id goes first, then the
/// smaller upper id. p 0 (1, 1.0), q 1 (1, 2.0), r 2 (2, 1.5), s 3 (2, 3.0),
/// u 4 (2, 1.5): p->r, p->u and q->s all have ratio exactly 1.5.
void TestTies()
{
  std::cout << "-- ties\n";
  Diagram d;
  d.Nodes = { MakeNode(1, 1.0, { { 0, 1, -1, -1 } }), MakeNode(1, 2.0, { { 0, 2, -1, -1 } }),
    MakeNode(2, 1.5, { { 0, 1, 2, -1 } }), MakeNode(2, 3.0, { { 0, 1, 3, -1 } }),
    MakeNode(2, 1.5, { { 0, 2, 3, -1 } }) };
  d.Link(1, 3);
  d.Link(0, 4);
  d.Link(0, 2);
  // (p, r) first: it creates no arc (In(r) = {p}); (p, u) is then stale; (q, s).
  const SimplificationResult r = Simplify(d.Nodes, d.Arcs, 1.5, Progress());
  CHECK(r.Pairs.size() == 2);
  if (r.Pairs.size() == 2)
  {
    CHECK(r.Pairs[0].Lower == 0 && r.Pairs[0].Upper == 2);
    CHECK(r.Pairs[1].Lower == 1 && r.Pairs[1].Upper == 3);
  }
  CHECK(r.Survives[4] && r.Arcs.empty());
  CHECK(r.OwnersOf(0) == std::vector<Id>{ 4 } && r.OwnersOf(3).empty() && r.OwnersOf(1).empty());
}

/// The maximum at infinity is never cancelled, whatever the threshold; index-0
/// nodes neither (their value 0 makes the ratio infinite).
void TestInfinity()
{
  std::cout << "-- infinity\n";
  Diagram d;
  d.Nodes = { Sample(0), Sample(1), Edge(0, 1, 0.5), MakeNode(2, 1.0, { { 0, 1, 2, -1 } }),
    Infinity(3) };
  d.Link(0, 2);
  d.Link(1, 2);
  d.Link(3, 4);
  const SimplificationResult r = Simplify(d.Nodes, d.Arcs, HUGE_VAL, Progress());
  CHECK(r.Pairs.empty());
  CHECK(ArcMap(r.Arcs) == ArcMap(d.Arcs));
}

void TestErrors()
{
  std::cout << "-- errors\n";
  const Diagram d = Fig1();
  auto throws = [](const std::vector<Node>& nodes, const std::vector<Arc>& arcs, double tp) {
    try
    {
      Simplify(nodes, arcs, tp, Progress());
    }
    catch (const InputError&)
    {
      return true;
    }
    return false;
  };
  CHECK(throws(d.Nodes, d.Arcs, std::nan("")));
  std::vector<Arc> bad = d.Arcs;
  bad.push_back(Arc{ P0, M1, 1 });
  CHECK(throws(d.Nodes, bad, 1.1));
  bad = d.Arcs;
  bad.push_back(Arc{ S1, 99, 1 });
  CHECK(throws(d.Nodes, bad, 1.1));
  bad = d.Arcs;
  bad[0].Multiplicity = -1;
  CHECK(throws(d.Nodes, bad, 1.1));
  bool aborted = false;
  Progress stop;
  stop.ShouldAbort = [] { return true; };
  try
  {
    Simplify(d.Nodes, d.Arcs, 1.1, stop);
  }
  catch (const Aborted&)
  {
    aborted = true;
  }
  CHECK(aborted);
}

// ---------------------------------------------------------------------------
// Properties on real flow complexes.

/// The rule of §3.3 written as plainly as possible: arcs in a std::map, the
/// least candidate found by a full scan at every step.
struct Reference
{
  std::vector<bool> Alive;
  std::map<ArcKey, int> Arcs;
  std::vector<std::tuple<Id, Id>> Pairs;
};

Reference PlainSimplify(const std::vector<Node>& nodes, const std::vector<Arc>& arcs, double tp)
{
  Reference ref;
  ref.Alive.assign(nodes.size(), true);
  ref.Arcs = ArcMap(arcs);
  for (;;)
  {
    bool found = false;
    std::tuple<double, Id, Id> best;
    for (const auto& a : ref.Arcs)
    {
      const Node& lo = nodes[a.first.first];
      const Node& up = nodes[a.first.second];
      if (a.second % 2 == 1 && lo.Index > 0 && !up.IsInfinity())
      {
        const auto key = std::make_tuple(up.Value / lo.Value, a.first.first, a.first.second);
        if (!found || key < best)
        {
          best = key;
          found = true;
        }
      }
    }
    if (!found || std::get<0>(best) > tp)
    {
      return ref;
    }
    const Id a = std::get<1>(best), b = std::get<2>(best);
    std::vector<Id> lowers, uppers;
    for (auto it = ref.Arcs.begin(); it != ref.Arcs.end();)
    {
      const Id lo = it->first.first, up = it->first.second;
      if (up == b && lo != a && it->second % 2 == 1)
        lowers.push_back(lo);
      if (lo == a && up != b && it->second % 2 == 1)
        uppers.push_back(up);
      if (lo == a || lo == b || up == a || up == b)
        it = ref.Arcs.erase(it);
      else
        ++it;
    }
    for (const Id x : lowers)
    {
      for (const Id y : uppers)
      {
        const auto it = ref.Arcs.find({ x, y });
        if (it == ref.Arcs.end())
          ref.Arcs[{ x, y }] = 1;
        else if (it->second % 2 == 1)
          ref.Arcs.erase(it);
        else
          it->second = 1;
      }
    }
    ref.Alive[a] = ref.Alive[b] = false;
    ref.Pairs.emplace_back(a, b);
  }
}

using PairSet = std::multiset<std::tuple<int, Id, Id>>;

/// Persistence pairs (dimension, birth, death) of the surviving part, in the
/// original node ids.
PairSet PersistenceOf(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives)
{
  std::vector<Node> kept;
  std::vector<Id> newId(nodes.size(), -1), oldId;
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (survives[i])
    {
      newId[i] = static_cast<Id>(kept.size());
      oldId.push_back(static_cast<Id>(i));
      kept.push_back(nodes[i]);
    }
  }
  std::vector<Arc> mapped;
  for (const Arc& a : arcs)
  {
    mapped.push_back(Arc{ newId[a.Lower], newId[a.Upper], a.Multiplicity });
  }
  PairSet s;
  for (const PersistencePair& p : ComputePersistence(kept, mapped))
  {
    s.insert({ p.Dimension, oldId[p.Birth], p.Death < 0 ? -1 : oldId[p.Death] });
  }
  return s;
}

void CheckProperties(const std::string& name, const std::vector<Point3>& cloud)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  const FlowComplex fc = BuildFlowComplex(cloud, options, Progress());
  const std::vector<Node>& nodes = fc.Nodes;
  const PairSet original = PersistenceOf(nodes, fc.Arcs, std::vector<bool>(nodes.size(), true));
  const bool ddInfinity = invariants::BoundaryOfBoundaryIsZero(nodes, fc.Arcs, true);
  std::cout << "-- " << name << ": " << nodes.size() << " nodes, " << fc.Arcs.size()
            << " arcs, dd = 0 with infinity: " << ddInfinity << "\n";
  std::size_t previous = 0;
  for (const double tp : { 0.0, 1.02, 1.1, 1.5, 3.0, HUGE_VAL })
  {
    const SimplificationResult r = Simplify(nodes, fc.Arcs, tp, Progress());
    std::cout << "   t_p " << tp << ": " << r.Pairs.size() << " pairs, " << r.Arcs.size()
              << " arcs\n";
    CHECK(r.Pairs.size() >= previous); // more cancellations as t_p grows
    previous = r.Pairs.size();
    CHECK(tp > 0 || r.Pairs.empty());

    // The pairs: incident, ordered by ratio, below the threshold, well described.
    bool pairsOk = true;
    std::set<Id> cancelled;
    for (std::size_t i = 0; i < r.Pairs.size(); ++i)
    {
      const CancelledPair& p = r.Pairs[i];
      pairsOk = pairsOk && nodes[p.Upper].Index == nodes[p.Lower].Index + 1 &&
        p.PairType == nodes[p.Lower].Index && p.Birth == nodes[p.Lower].Value &&
        p.Death == nodes[p.Upper].Value && p.Ratio == p.Death / p.Birth && p.Ratio <= tp &&
        p.Ratio > 1 && (i == 0 || r.Pairs[i - 1].Ratio <= p.Ratio) && p.PairType >= 1 &&
        !nodes[p.Upper].IsInfinity() && cancelled.insert(p.Lower).second &&
        cancelled.insert(p.Upper).second;
    }
    CHECK(pairsOk);
    bool survivorsOk = r.Survives.size() == nodes.size() && r.Survives.back();
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      survivorsOk = survivorsOk && r.Survives[i] == (cancelled.count(static_cast<Id>(i)) == 0);
    }
    CHECK(survivorsOk);

    // Same answer as the plain re-implementation.
    const Reference ref = PlainSimplify(nodes, fc.Arcs, tp);
    bool same = ref.Pairs.size() == r.Pairs.size() && ref.Arcs == ArcMap(r.Arcs);
    for (std::size_t i = 0; same && i < ref.Pairs.size(); ++i)
    {
      same = std::get<0>(ref.Pairs[i]) == r.Pairs[i].Lower && std::get<1>(ref.Pairs[i]) == r.Pairs[i].Upper;
    }
    CHECK(same);

    // Arcs: between survivors, up one index, increasing values, sorted, and no
    // candidate left below the threshold.
    bool arcsOk = std::is_sorted(r.Arcs.begin(), r.Arcs.end(), [](const Arc& a, const Arc& b) {
      return std::make_pair(a.Lower, a.Upper) < std::make_pair(b.Lower, b.Upper);
    });
    double least = HUGE_VAL;
    for (const Arc& a : r.Arcs)
    {
      arcsOk = arcsOk && r.Survives[a.Lower] && r.Survives[a.Upper] && a.Multiplicity >= 1 &&
        nodes[a.Upper].Index == nodes[a.Lower].Index + 1 &&
        nodes[a.Lower].Value < nodes[a.Upper].Value;
      if (a.Multiplicity % 2 == 1 && nodes[a.Lower].Index > 0 && !nodes[a.Upper].IsInfinity())
      {
        least = std::min(least, nodes[a.Upper].Value / nodes[a.Lower].Value);
      }
    }
    CHECK(arcsOk);
    CHECK(least == HUGE_VAL || least > tp);

    // Still a chain complex with the same Euler characteristic.
    CHECK(invariants::BoundaryOfBoundaryIsZero(nodes, r.Arcs, false));
    CHECK(invariants::BoundaryOfBoundaryIsZero(nodes, r.Arcs, true) == ddInfinity);
    Id euler = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
    {
      if (r.Survives[i] && !nodes[i].IsInfinity())
      {
        euler += nodes[i].Index % 2 == 0 ? 1 : -1;
      }
    }
    CHECK(euler == 1);

    // The paper's claim (§3.3): pairs are cancelled in persistence order, i.e.
    // every cancelled pair is a persistence pair, and the persistence of what is
    // left is the original minus those pairs.
    PairSet expected = original;
    bool allPersistencePairs = true;
    for (const CancelledPair& p : r.Pairs)
    {
      const auto it = expected.find({ p.PairType, p.Lower, p.Upper });
      allPersistencePairs = allPersistencePairs && it != expected.end();
      if (it != expected.end())
      {
        expected.erase(it);
      }
    }
    CHECK(allPersistencePairs);
    CHECK(PersistenceOf(nodes, r.Arcs, r.Survives) == expected);

    // Owners: cancelled nodes only, survivors only, sorted; count the empty ones.
    bool ownersOk = r.Owners.Offsets.size() == nodes.size() + 1;
    Id empty = 0, toInfinity = 0;
    for (std::size_t i = 0; ownersOk && i < nodes.size(); ++i)
    {
      const std::vector<Id> o = r.OwnersOf(static_cast<Id>(i));
      ownersOk = std::is_sorted(o.begin(), o.end()) &&
        std::adjacent_find(o.begin(), o.end()) == o.end() && (!r.Survives[i] || o.empty());
      for (const Id owner : o)
      {
        ownersOk = ownersOk && r.Survives[owner] && nodes[owner].Index >= nodes[i].Index;
        toInfinity += nodes[owner].IsInfinity() ? 1 : 0;
      }
      empty += !r.Survives[i] && o.empty() ? 1 : 0;
    }
    CHECK(ownersOk);
    if (!r.Pairs.empty())
    {
      std::cout << "   owners: " << empty << " cancelled nodes own nothing, " << toInfinity
                << " owner entries are infinity\n";
    }
  }
}

} // namespace

int main()
{
  TestFigure2();
  TestEvenArcs();
  TestNewArcCancelled();
  TestTies();
  TestInfinity();
  TestErrors();
  CheckProperties("cube 150", Cube(150, 31));
  CheckProperties("sphere 250", Sphere(250, 32));
  CheckProperties("torus 300", Torus(300, 33));
  return check::Finish("TestSimplification");
}
