// Flow reconstruction (paper §3.1-3.2, §7.4): hand-made diagrams whose runs are
// worked out by hand, then properties on real flow complexes: nestedness (the
// run at t_r equals the Threshold < t_r prefix of the t_r = inf run), closure
// under regularization, consistency of priorities and sponsors, agreement with a
// plain re-implementation that rescans every candidate at every step.
#include "Check.h"
#include "ReconFixtures.h"

#include "FlowComplexBuilder.h"
#include "Persistence.h"
#include "Reconstruction.h"
#include "Simplification.h"

#include <algorithm>
#include <iostream>
#include <iterator>
#include <set>
#include <string>
#include <tuple>

using namespace flowrecon;
using namespace fixtures;

namespace
{

const double Inf_ = HUGE_VAL;

bool Same(const Insertion& a, const Insertion& b)
{
  return a.Step == b.Step && a.Priority == b.Priority && a.Threshold == b.Threshold &&
    a.Kind == b.Kind && a.Sponsor == b.Sponsor;
}

/// The paper's reconstruction profile: the priorities of the steps after the
/// initialization edges, in order.
std::vector<double> ProfileOf(const ReconstructionResult& r)
{
  std::vector<double> profile;
  for (std::size_t k = static_cast<std::size_t>(r.InitializationCount); k < r.Order.size(); ++k)
  {
    profile.push_back(r.Nodes[r.Order[k]].Priority);
  }
  return profile;
}

/// The run at finite t equals the nodes of `full` (a t = inf run) with
/// Threshold < t, field by field.
bool IsPrefix(const ReconstructionResult& full, const ReconstructionResult& at, double t)
{
  bool ok = at.Nodes.size() == full.Nodes.size() &&
    at.InitializationCount == full.InitializationCount;
  Id count = 0;
  for (std::size_t i = 0; ok && i < full.Nodes.size(); ++i)
  {
    const Id n = static_cast<Id>(i);
    if (full.Contains(n, t))
    {
      ok = Same(full.Nodes[i], at.Nodes[i]);
      ++count;
    }
    else
    {
      ok = at.Nodes[i].Step < 0;
    }
  }
  ok = ok && count == static_cast<Id>(at.Order.size()) &&
    std::equal(at.Order.begin(), at.Order.end(), full.Order.begin());
  return ok;
}

void Expect(const ReconstructionResult& r, Id node, Id step, double priority, double threshold,
  Extension kind, Id sponsor)
{
  const Insertion& i = r.Nodes[node];
  CHECK(i.Step == step);
  CHECK_NEAR(i.Priority, priority, 1e-12);
  CHECK_NEAR(i.Threshold, threshold, 1e-12);
  CHECK(i.Kind == kind);
  CHECK(i.Sponsor == sponsor);
}

/// The 2D example of Fig. 1 (ReconFixtures.h), no simplification.
/// Initialization edges: nn(p0) = p1, nn(p1) = p0, nn(p2) = p1, nn(p3) = p2,
/// hence s1 = p0p1, s3 = p1p2, s4 = p2p3 (steps 0-2, in id order 4, 7, 8).
/// Their extensions offer (best so far, sponsor):
///   s1 (1.0): p0, p1 reg; M1 up 1.3; s2 hor 1.2; s5 hor 1.6.
///   s3 (1.1): p2 reg; M1 up 1.3/1.1 = 1.1818; s2 hor 1.2/1.1 = 1.0909.
///   s4 (1.5): p3 reg; M2 up 2/1.5 = 1.3333; s2 hor max(1, 1.2/1.5) = 1;
///             s5 hor 1.6/1.5 = 1.0667.
/// Pops: p0, p1, p2, p3 (reg, priority 1, id order), then s2 (1, hor from s4),
/// whose upflow offers M1 1.3/1.2 = 1.0833 (M2 2/1.2 = 1.667 is worse); s5
/// (1.0667), whose upflow offers M2 2/1.6 = 1.25; M1 (1.0833); M2 (1.25).
/// Infinity is never inserted.
void TestFigure1()
{
  std::cout << "-- Fig. 1\n";
  const Diagram d = Fig1();
  const std::vector<Id> nn = { P1, P0, P1, P2 };
  CHECK(InitializationEdges(d.Nodes, nn) == (std::vector<Id>{ S1, S3, S4 }));
  std::vector<Id> fromDiagram = NearestNeighboursFromDiagram(d.Nodes, d.Arcs);
  CHECK(std::vector<Id>(fromDiagram.begin(), fromDiagram.begin() + 4) == nn);
  CHECK(InitializationEdgesFromDiagram(d.Nodes, d.Arcs) == (std::vector<Id>{ S1, S3, S4 }));
  CHECK(std::count(fromDiagram.begin() + 4, fromDiagram.end(), Id(-1)) == 8);

  const std::vector<bool> all(d.Nodes.size(), true);
  const std::vector<Id> init = { S4, S1, S3, S1 }; // order and duplicates do not matter
  const ReconstructionResult r = Reconstruct(d.Nodes, d.Arcs, all, init, Inf_, Progress());
  CHECK(r.InitializationCount == 3);
  CHECK(r.Order == (std::vector<Id>{ S1, S3, S4, P0, P1, P2, P3, S2, S5, M1, M2 }));
  Expect(r, S1, 0, 1, 1, Extension::Initialization, -1);
  Expect(r, S3, 1, 1, 1, Extension::Initialization, -1);
  Expect(r, S4, 2, 1, 1, Extension::Initialization, -1);
  Expect(r, P0, 3, 1, 1, Extension::Regularization, S1);
  Expect(r, P1, 4, 1, 1, Extension::Regularization, S1);
  Expect(r, P2, 5, 1, 1, Extension::Regularization, S3);
  Expect(r, P3, 6, 1, 1, Extension::Regularization, S4);
  Expect(r, S2, 7, 1, 1, Extension::Horizontal, S4);
  Expect(r, S5, 8, 1.6 / 1.5, 1.6 / 1.5, Extension::Horizontal, S4);
  Expect(r, M1, 9, 1.3 / 1.2, 1.3 / 1.2, Extension::Upflow, S2);
  Expect(r, M2, 10, 2 / 1.6, 2 / 1.6, Extension::Upflow, S5);
  CHECK(r.Nodes[Inf].Step < 0);
  CHECK(ProfileOf(r) == (std::vector<double>{ 1, 1, 1, 1, 1, 1.6 / 1.5, 1.3 / 1.2, 2 / 1.6 }));

  // Nested family: each finite run is the Threshold < t prefix.
  for (const double t : { 1.05, 1.07, 1.1, 1.25, 1.3, 5.0 })
  {
    CHECK(IsPrefix(r, Reconstruct(d.Nodes, d.Arcs, all, init, t, Progress()), t));
  }
  CHECK(Reconstruct(d.Nodes, d.Arcs, all, init, 1.07, Progress()).Order.size() == 9);

  // Multiplicity of the Gabriel edges: reconstructed index-2 nodes above them.
  const std::vector<int> mInf = EdgeMultiplicities(d.Nodes, d.Arcs, r);
  CHECK(mInf == (std::vector<int>{ 0, 0, 0, 0, 1, 2, 1, 1, 1, 0, 0, 0 }));
  const std::vector<int> m11 = EdgeMultiplicities(d.Nodes, d.Arcs, r, 1.1);
  CHECK(m11 == (std::vector<int>{ 0, 0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 0 }));

  // After the simplification at t_p = 1.1 (s2 and M1 cancelled, s1->M2 and
  // s3->M2 created): s1 offers M2 2 and s5 1.6, s3 offers M2 1.818, s4 offers M2
  // 1.333 and s5 1.0667. Pops: p0..p3, s5 (1.0667, hor from s4), whose upflow
  // offers M2 1.25; M2 (1.25, up from s5). s2 and M1 are never inserted.
  const SimplificationResult s = Simplify(d.Nodes, d.Arcs, 1.1, Progress());
  const ReconstructionResult rs = Reconstruct(d.Nodes, s.Arcs, s.Survives, init, Inf_, Progress());
  CHECK(rs.Order == (std::vector<Id>{ S1, S3, S4, P0, P1, P2, P3, S5, M2 }));
  Expect(rs, S5, 7, 1.6 / 1.5, 1.6 / 1.5, Extension::Horizontal, S4);
  Expect(rs, M2, 8, 2 / 1.6, 2 / 1.6, Extension::Upflow, S5);
  CHECK(rs.Nodes[S2].Step < 0 && rs.Nodes[M1].Step < 0);
  CHECK(EdgeMultiplicities(d.Nodes, s.Arcs, rs) ==
    (std::vector<int>{ 0, 0, 0, 0, 1, 0, 1, 1, 1, 0, 0, 0 }));
  // A cancelled initialization edge is skipped (s2 as an extra one here).
  const std::vector<Id> withCancelled = { S1, S2, S3, S4 };
  CHECK(Reconstruct(d.Nodes, s.Arcs, s.Survives, withCancelled, Inf_, Progress()).Order == rs.Order);
}

/// Regularization and the running-maximum threshold.
///   samples a 0, b 1, c 2, d 3; edges ab 4 (1.0), ad 5 (2.9), bc 6 (3.0),
///   cd 7 (1.0); one index-2 patch P 8 (3.2) bounded by the four edges, whose
///   two unstable lines go to infinity 9.
/// Initialization: ab and cd. ab offers P up 3.2, ad hor 2.9, bc hor 3.0; cd
/// offers the same ratios, which do not beat the first sponsor. Pops: a, b (reg
/// from ab), c, d (reg from cd), ad (2.9, hor from ab), whose upflow offers P
/// 3.2/2.9 = 1.1034; P (1.1034, threshold still 2.9), whose regularization
/// offers bc at 1 (better than its horizontal 3.0); bc (1, reg from P,
/// threshold 2.9): inserted by regularization after P, with the same threshold.
void TestRegularization()
{
  std::cout << "-- regularization\n";
  Diagram d;
  for (Id p = 0; p < 4; ++p)
  {
    d.Nodes.push_back(Sample(p));
  }
  d.Nodes.push_back(Edge(0, 1, 1.0));
  d.Nodes.push_back(Edge(0, 3, 2.9));
  d.Nodes.push_back(Edge(1, 2, 3.0));
  d.Nodes.push_back(Edge(2, 3, 1.0));
  d.Nodes.push_back(MakeNode(2, 3.2, { { 0, 1, 2, 3 } }));
  d.Nodes.push_back(Infinity(3));
  const Id ends[4][3] = { { 4, 0, 1 }, { 5, 0, 3 }, { 6, 1, 2 }, { 7, 2, 3 } };
  for (const auto& e : ends)
  {
    d.Link(e[1], e[0]);
    d.Link(e[2], e[0]);
    d.Link(e[0], 8);
  }
  d.Link(8, 9, 2);
  const std::vector<Id> nn = NearestNeighboursFromDiagram(d.Nodes, d.Arcs);
  CHECK(std::vector<Id>(nn.begin(), nn.begin() + 4) == (std::vector<Id>{ 1, 0, 3, 2 }));
  const std::vector<Id> init = InitializationEdges(d.Nodes, nn);
  CHECK(init == (std::vector<Id>{ 4, 7 }));
  const std::vector<bool> all(d.Nodes.size(), true);
  const ReconstructionResult r = Reconstruct(d.Nodes, d.Arcs, all, init, Inf_, Progress());
  CHECK(r.Order == (std::vector<Id>{ 4, 7, 0, 1, 2, 3, 5, 8, 6 }));
  Expect(r, 0, 2, 1, 1, Extension::Regularization, 4);
  Expect(r, 2, 4, 1, 1, Extension::Regularization, 7);
  Expect(r, 5, 6, 2.9, 2.9, Extension::Horizontal, 4);
  Expect(r, 8, 7, 3.2 / 2.9, 2.9, Extension::Upflow, 5);
  Expect(r, 6, 8, 1, 2.9, Extension::Regularization, 8);
  CHECK(r.Nodes[9].Step < 0);
  CHECK(ProfileOf(r) == (std::vector<double>{ 1, 1, 1, 1, 2.9, 3.2 / 2.9, 1 }));
  for (const double t : { 1.5, 2.9, 2.95, 3.05, 4.0 })
  {
    CHECK(IsPrefix(r, Reconstruct(d.Nodes, d.Arcs, all, init, t, Progress()), t));
  }
  CHECK(Reconstruct(d.Nodes, d.Arcs, all, init, 2.9, Progress()).Order.size() == 6);
  CHECK(Reconstruct(d.Nodes, d.Arcs, all, init, 2.95, Progress()).Order.size() == 9);
  // At t_r <= 1 only the initialization edges and their samples: regularization
  // is unconditional. (Threshold selections are meant for t_r > 1, the paper's
  // range: these six nodes have Threshold 1.)
  CHECK(Reconstruct(d.Nodes, d.Arcs, all, init, 1.0, Progress()).Order.size() == 6);
  CHECK(Reconstruct(d.Nodes, d.Arcs, all, {}, Inf_, Progress()).Order.empty());
  CHECK(EdgeMultiplicities(d.Nodes, d.Arcs, r) == (std::vector<int>{ 0, 0, 0, 0, 1, 1, 1, 1, 0, 0 }));
}

void TestErrors()
{
  std::cout << "-- errors\n";
  const Diagram d = Fig1();
  const std::vector<bool> all(d.Nodes.size(), true);
  auto throws = [&](const std::vector<Arc>& arcs, const std::vector<bool>& survives,
                  const std::vector<Id>& init, double tr) {
    try
    {
      Reconstruct(d.Nodes, arcs, survives, init, tr, Progress());
    }
    catch (const InputError&)
    {
      return true;
    }
    return false;
  };
  CHECK(!throws(d.Arcs, all, { S1 }, 2));
  CHECK(throws(d.Arcs, all, { S1 }, std::nan("")));
  CHECK(throws(d.Arcs, std::vector<bool>(3, true), { S1 }, 2));
  CHECK(throws(d.Arcs, all, { P0 }, 2));
  CHECK(throws(d.Arcs, all, { 99 }, 2));
  std::vector<bool> cancelled = all;
  cancelled[M1] = false;
  CHECK(throws(d.Arcs, cancelled, { S1 }, 2));
  std::vector<Arc> bad = d.Arcs;
  bad.push_back(Arc{ P0, M1, 1 });
  CHECK(throws(bad, all, { S1 }, 2));
  // The arcs are checked in parallel: the message still names the first bad
  // arc of a long list, whatever its fault, and ids out of range are caught
  // before they are read.
  auto message = [&](const std::vector<Arc>& arcs, const std::vector<bool>& survives) {
    try
    {
      Reconstruct(d.Nodes, arcs, survives, { S1 }, 2, Progress());
    }
    catch (const InputError& e)
    {
      return std::string(e.what());
    }
    return std::string();
  };
  std::vector<Arc> many; // Fig. 1's arcs but M1's, again and again
  while (many.size() < 200000)
  {
    std::copy_if(d.Arcs.begin(), d.Arcs.end(), std::back_inserter(many),
      [](const Arc& x) { return x.Lower != M1 && x.Upper != M1; });
  }
  const std::size_t early = 70001, late = 150003;
  std::vector<Arc> cancelledFirst = many, indexFirst = many, outOfRange = many;
  cancelledFirst[early] = Arc{ S2, M1, 1 };
  cancelledFirst[late] = Arc{ P0, M1, 1 };
  indexFirst[early] = Arc{ P0, M1, 1 };
  indexFirst[late] = Arc{ S2, M1, 1 };
  outOfRange[early] = Arc{ 1 << 30, M1, 1 };
  outOfRange[late] = Arc{ P0, M1, 1 };
  const std::string a = message(cancelledFirst, cancelled);
  const std::string b = message(indexFirst, cancelled);
  const std::string c = message(outOfRange, all);
  CHECK(a == "Hasse diagram: arc 70001 touches a cancelled node");
  CHECK(b == "Hasse diagram: arc 70001 does not go up by one index");
  CHECK(c == "Hasse diagram: arc 70001 refers to a node that does not exist");
  std::cout << "   " << a << "; " << b << "; " << c << "\n";
  bool nnThrows = false;
  try
  {
    InitializationEdges(d.Nodes, { S1, P0, P1, P2 });
  }
  catch (const InputError&)
  {
    nnThrows = true;
  }
  CHECK(nnThrows);
}

// ---------------------------------------------------------------------------
// Properties on real flow complexes.

struct Lists
{
  std::vector<std::vector<Id>> In, Out;
  Lists(std::size_t n, const std::vector<Arc>& arcs)
    : In(n)
    , Out(n)
  {
    for (const Arc& a : arcs)
    {
      if (a.Multiplicity > 0)
      {
        this->In[a.Upper].push_back(a.Lower);
        this->Out[a.Lower].push_back(a.Upper);
      }
    }
  }
};

bool ShareSample(const Lists& g, Id c, Id d)
{
  for (const Id b : g.In[c])
  {
    if (std::find(g.In[d].begin(), g.In[d].end(), b) != g.In[d].end())
    {
      return true;
    }
  }
  return false;
}

/// §3.2 without a queue: at every step, every candidate node and every sponsor
/// in the reconstruction is looked at again. Key of a node: least (priority,
/// regularization first, sponsor's step); chosen node: least (priority,
/// regularization first, node id).
ReconstructionResult PlainReconstruct(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const std::vector<bool>& survives, std::vector<Id> init, double tr)
{
  const Lists g(nodes.size(), arcs);
  ReconstructionResult r;
  r.Nodes.assign(nodes.size(), Insertion());
  double running = 1;
  auto insert = [&](Id n, double priority, Extension kind, Id sponsor) {
    running = std::max(running, priority);
    r.Nodes[n] = Insertion{ static_cast<Id>(r.Order.size()), priority, running, kind,
      static_cast<std::int32_t>(sponsor) };
    r.Order.push_back(n);
  };
  std::sort(init.begin(), init.end());
  init.erase(std::unique(init.begin(), init.end()), init.end());
  for (const Id e : init)
  {
    if (survives[e])
    {
      insert(e, 1, Extension::Initialization, -1);
    }
  }
  r.InitializationCount = static_cast<Id>(r.Order.size());
  using Key = std::tuple<double, int, Id>; // priority, gated, sponsor step
  for (;;)
  {
    bool found = false;
    std::tuple<double, int, Id> bestNode;
    Key bestKey;
    Extension bestKind = Extension::Initialization;
    Id bestSponsor = -1;
    for (Id d = 0; d < static_cast<Id>(nodes.size()); ++d)
    {
      if (r.Nodes[d].Step >= 0 || !survives[d] || nodes[d].IsInfinity())
      {
        continue;
      }
      bool has = false;
      Key key;
      Extension kind = Extension::Initialization;
      Id sponsor = -1;
      auto offer = [&](double p, int gated, Extension k, Id c) {
        if (gated && !(p < tr))
          return;
        const Key candidate{ p, gated, r.Nodes[c].Step };
        if (!has || candidate < key)
        {
          has = true;
          key = candidate;
          kind = k;
          sponsor = c;
        }
      };
      for (const Id c : g.Out[d])
        if (r.Nodes[c].Step >= 0)
          offer(1, 0, Extension::Regularization, c);
      for (const Id c : g.In[d])
        if (r.Nodes[c].Step >= 0 && nodes[c].Value > 0)
          offer(nodes[d].Value / nodes[c].Value, 1, Extension::Upflow, c);
      if (nodes[d].Index == 1)
        for (const Id b : g.In[d])
          for (const Id c : g.Out[b])
            if (c != d && r.Nodes[c].Step >= 0)
              offer(std::max(1.0, nodes[d].Value / nodes[c].Value), 1, Extension::Horizontal, c);
      if (has)
      {
        const std::tuple<double, int, Id> candidate{ std::get<0>(key), std::get<1>(key), d };
        if (!found || candidate < bestNode)
        {
          found = true;
          bestNode = candidate;
          bestKey = key;
          bestKind = kind;
          bestSponsor = sponsor;
        }
      }
    }
    if (!found)
    {
      return r;
    }
    insert(std::get<2>(bestNode), std::get<0>(bestKey), bestKind, bestSponsor);
  }
}

bool SameRun(const ReconstructionResult& a, const ReconstructionResult& b)
{
  bool ok = a.Order == b.Order &&
    a.InitializationCount == b.InitializationCount && a.Nodes.size() == b.Nodes.size();
  for (std::size_t i = 0; ok && i < a.Nodes.size(); ++i)
  {
    ok = a.Nodes[i].Step < 0 ? b.Nodes[i].Step < 0 : Same(a.Nodes[i], b.Nodes[i]);
  }
  return ok;
}

/// Betti numbers (Z/2) of the reconstruction at t: essential classes of the
/// sub-complex (it is closed under faces, so the persistence of any filtration
/// of it gives its homology).
std::array<int, 4> Betti(const std::vector<Node>& nodes, const std::vector<Arc>& arcs,
  const ReconstructionResult& r, double t)
{
  std::vector<Node> kept;
  std::vector<Id> newId(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i)
  {
    if (r.Contains(static_cast<Id>(i), t))
    {
      newId[i] = static_cast<Id>(kept.size());
      kept.push_back(nodes[i]);
    }
  }
  std::vector<Arc> mapped;
  for (const Arc& a : arcs)
  {
    if (newId[a.Lower] >= 0 && newId[a.Upper] >= 0)
    {
      mapped.push_back(Arc{ newId[a.Lower], newId[a.Upper], a.Multiplicity });
    }
  }
  std::array<int, 4> betti{ { 0, 0, 0, 0 } };
  for (const PersistencePair& p : ComputePersistence(kept, mapped))
  {
    betti[p.Dimension] += p.Death < 0 ? 1 : 0;
  }
  return betti;
}

double Dist2(const Point3& a, const Point3& b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]);
}

void CheckProperties(const std::string& name, const std::vector<Point3>& cloud, bool plain)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  const FlowComplex fc = BuildFlowComplex(cloud, options, Progress());
  const std::vector<Node>& nodes = fc.Nodes;
  const Id n = static_cast<Id>(nodes.size());

  // Nearest neighbours by brute force on the samples (node ids of index-0 nodes).
  std::vector<Id> samples;
  for (Id i = 0; i < n; ++i)
  {
    if (nodes[i].Index == 0)
    {
      samples.push_back(i);
    }
  }
  std::vector<Id> nn(n, -1);
  for (const Id v : samples)
  {
    double best = HUGE_VAL;
    for (const Id w : samples)
    {
      const double d2 = Dist2(cloud[nodes[v].Simplex[0]], cloud[nodes[w].Simplex[0]]);
      if (w != v && d2 < best)
      {
        best = d2;
        nn[v] = w;
      }
    }
  }
  CHECK(NearestNeighboursFromDiagram(nodes, fc.Arcs) == nn);
  const std::vector<Id> init = InitializationEdges(nodes, nn);
  // The one-pass form gives the same edges as the lookup by simplex.
  CHECK(InitializationEdgesFromDiagram(nodes, fc.Arcs) == init);
  // Every nearest-neighbour pair is a Gabriel edge, found.
  std::set<std::pair<Id, Id>> pairs;
  for (const Id v : samples)
  {
    const Id a = nodes[v].Simplex[0], b = nodes[nn[v]].Simplex[0];
    pairs.insert({ std::min(a, b), std::max(a, b) });
  }
  CHECK(init.size() == pairs.size());
  std::cout << "-- " << name << ": " << n << " nodes, " << fc.Arcs.size() << " arcs, "
            << init.size() << " initialization edges\n";

  for (const double tp : { 0.0, 1.1 })
  {
    const SimplificationResult s = Simplify(nodes, fc.Arcs, tp, Progress());
    const std::vector<Arc>& arcs = s.Arcs;
    const Lists g(nodes.size(), arcs);
    const ReconstructionResult r = Reconstruct(nodes, arcs, s.Survives, init, Inf_, Progress());

    // Bookkeeping: steps, running maximum.
    bool books = r.Order.size() >= static_cast<std::size_t>(r.InitializationCount);
    double running = 1;
    for (std::size_t k = 0; books && k < r.Order.size(); ++k)
    {
      const Id node = r.Order[k];
      const Insertion& i = r.Nodes[node];
      running = std::max(running, i.Priority);
      books = i.Step == static_cast<Id>(k) && i.Threshold == running && i.Priority >= 1 &&
        s.Survives[node] && !nodes[node].IsInfinity() &&
        (k < static_cast<std::size_t>(r.InitializationCount)
            ? i.Kind == Extension::Initialization && i.Sponsor == -1 && i.Priority == 1
            : i.Kind != Extension::Initialization);
    }
    CHECK(books);
    Id inserted = 0;
    for (const Insertion& i : r.Nodes)
    {
      inserted += i.Step >= 0 ? 1 : 0;
    }
    CHECK(inserted == static_cast<Id>(r.Order.size()));

    // Sponsors: inserted earlier, related as their kind says, with that ratio.
    bool sponsors = true;
    for (std::size_t k = static_cast<std::size_t>(r.InitializationCount); k < r.Order.size(); ++k)
    {
      const Id d = r.Order[k];
      const Insertion& i = r.Nodes[d];
      const Id c = i.Sponsor;
      sponsors = sponsors && c >= 0 && r.Nodes[c].Step >= 0 && r.Nodes[c].Step < i.Step;
      if (!sponsors)
        break;
      const auto has = [](const std::vector<Id>& v, Id x) {
        return std::find(v.begin(), v.end(), x) != v.end();
      };
      switch (i.Kind)
      {
        case Extension::Regularization:
          sponsors = has(g.In[c], d) && i.Priority == 1;
          break;
        case Extension::Upflow:
          sponsors = has(g.Out[c], d) && i.Priority == nodes[d].Value / nodes[c].Value;
          break;
        case Extension::Horizontal:
          sponsors = nodes[c].Index == 1 && nodes[d].Index == 1 && ShareSample(g, c, d) &&
            i.Priority == std::max(1.0, nodes[d].Value / nodes[c].Value);
          break;
        default:
          sponsors = false;
      }
    }
    CHECK(sponsors);

    // Closure (regularization): ancestors are in, with a threshold no larger.
    bool closed = true;
    for (Id c = 0; c < n; ++c)
    {
      if (r.Nodes[c].Step >= 0)
      {
        for (const Id x : g.In[c])
        {
          closed = closed && r.Nodes[x].Step >= 0 && r.Nodes[x].Threshold <= r.Nodes[c].Threshold;
        }
      }
    }
    CHECK(closed);

    for (const double t : { 1.05, 1.3, 1.7, 2.0, 2.5 })
    {
      const ReconstructionResult at = Reconstruct(nodes, arcs, s.Survives, init, t, Progress());
      CHECK(IsPrefix(r, at, t));
      // Maximality: no extension with ratio < t leaves the reconstruction at t.
      bool maximal = true;
      for (Id c = 0; c < n; ++c)
      {
        if (!r.Contains(c, t))
          continue;
        auto out = [&](Id d, double ratio) {
          return !s.Survives[d] || nodes[d].IsInfinity() || r.Contains(d, t) || !(ratio < t);
        };
        for (const Id d : g.In[c])
          maximal = maximal && r.Contains(d, t);
        if (nodes[c].Value > 0)
          for (const Id d : g.Out[c])
            maximal = maximal && out(d, nodes[d].Value / nodes[c].Value);
        if (nodes[c].Index == 1)
          for (const Id b : g.In[c])
            for (const Id d : g.Out[b])
              maximal = maximal && (d == c || out(d, std::max(1.0, nodes[d].Value / nodes[c].Value)));
      }
      CHECK(maximal);
      // Edge multiplicities at t, counted directly.
      std::vector<int> m(nodes.size(), 0);
      for (const Arc& a : arcs)
        if (nodes[a.Lower].Index == 1 && r.Contains(a.Lower, t) && r.Contains(a.Upper, t))
          m[a.Lower] += a.Multiplicity;
      CHECK(EdgeMultiplicities(nodes, arcs, r, t) == m);
      if (t == 2.0)
      {
        const auto b = Betti(nodes, arcs, r, t);
        std::cout << "   t_p " << tp << ", t_r 2: " << at.Order.size() << " of " << r.Order.size()
                  << " nodes, Betti " << b[0] << " " << b[1] << " " << b[2] << " " << b[3] << "\n";
      }
    }
    if (plain)
    {
      CHECK(SameRun(r, PlainReconstruct(nodes, arcs, s.Survives, init, Inf_)));
      CHECK(SameRun(Reconstruct(nodes, arcs, s.Survives, init, 2.0, Progress()),
        PlainReconstruct(nodes, arcs, s.Survives, init, 2.0)));
    }
  }
}

/// End to end on quasi-uniform samples of shapes of known topology: the
/// reconstruction at t_r around 2 has the Betti numbers of the shape, with and
/// without simplification. (Random uniform samples are not rho-uniform: with
/// t_p = 1.1 they get holes where a surface patch is paired with a nearby
/// maximum whose other side is outside, the situation of the paper's §5.2.)
void CheckHomotopy(const std::string& name, const std::vector<Point3>& cloud, std::array<int, 4> expected)
{
  BuildOptions options;
  options.StableManifolds = false;
  options.UnstableManifolds = false;
  const FlowComplex fc = BuildFlowComplex(cloud, options, Progress());
  const std::vector<Id> init = InitializationEdges(fc.Nodes, NearestNeighboursFromDiagram(fc.Nodes, fc.Arcs));
  std::cout << "-- homotopy: " << name << "\n";
  for (const double tp : { 0.0, 1.05, 1.1 })
  {
    const SimplificationResult s = Simplify(fc.Nodes, fc.Arcs, tp, Progress());
    const ReconstructionResult r = Reconstruct(fc.Nodes, s.Arcs, s.Survives, init, Inf_, Progress());
    for (const double t : { 1.9, 2.0, 2.1 })
    {
      const auto b = Betti(fc.Nodes, s.Arcs, r, t);
      CHECK(b == expected);
      if (b != expected)
      {
        std::cout << "   t_p " << tp << ", t_r " << t << ": Betti " << b[0] << " " << b[1] << " "
                  << b[2] << " " << b[3] << "\n";
      }
    }
  }
}

} // namespace

int main()
{
  TestFigure1();
  TestRegularization();
  TestErrors();
  CheckProperties("cube 150", Cube(150, 41), true);
  CheckProperties("sphere 200", Sphere(200, 42), true);
  CheckProperties("torus 300", Torus(300, 43), true);
  CheckProperties("sphere 1500", Sphere(1500, 44), false);
  CheckHomotopy("sphere 800", FibonacciSphere(800, 45), { { 1, 0, 1, 0 } });
  CheckHomotopy("torus 40 x 14", GridTorus(40, 46), { { 1, 2, 1, 0 } });
  return check::Finish("TestReconstruction");
}
