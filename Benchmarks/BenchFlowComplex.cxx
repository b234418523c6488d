// Benchmark (not a test): time of each flow-complex phase and its ratio to
// CGAL's Delaunay triangulation of the same points in the same run, with peak
// memory per point. Each case runs in a child process so that peak RSS is its own.
//   BenchFlowComplex [sizes...]      default: 10000 100000 1000000
// Two baselines: CGAL's sequential Delaunay triangulation (the default call) and
// its concurrent one (Parallel_tag, all cores), which the flow complex uses
// itself. The flow complex runs on all cores ("all") and, for a like-for-like
// ratio to the sequential baseline, on one thread ("1").
// Two modes per case: "hasse" computes everything the later stages need (critical
// points, all walks, the Hasse diagram with multiplicities); "full" also stores
// the manifold geometry for display, whose size grows faster than n on surfaces
// (index-2 patches spanning a tube), so it runs only up to 200000 points.
#include "FlowComplexBuilder.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <tbb/global_control.h>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using flowrecon::Point3;

namespace
{

std::vector<Point3> Make(const std::string& shape, long n)
{
  std::mt19937_64 g(12345);
  auto u = [&]() { return static_cast<double>(g() >> 11) * 0x1.0p-53; };
  std::vector<Point3> p(static_cast<std::size_t>(n));
  for (Point3& q : p)
  {
    if (shape == "cube")
    {
      q = { { u(), u(), u() } };
    }
    else // torus surface R = 1, r = 0.35, uniform in the angles
    {
      const double a = 2 * M_PI * u(), b = 2 * M_PI * u();
      q = { { (1 + 0.35 * std::cos(b)) * std::cos(a), (1 + 0.35 * std::cos(b)) * std::sin(a),
        0.35 * std::sin(b) } };
    }
  }
  return p;
}

long PeakKiB()
{
  rusage r{};
  getrusage(RUSAGE_SELF, &r);
  return r.ru_maxrss;
}

double Now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

/// Seconds to build CGAL's Delaunay triangulation of `pts`, sequential or concurrent.
double BaselineDelaunay(const std::vector<Point3>& pts, bool parallel)
{
  std::vector<K::Point_3> kp;
  kp.reserve(pts.size());
  CGAL::Bbox_3 box;
  for (const Point3& q : pts)
  {
    kp.emplace_back(q[0], q[1], q[2]);
    box += kp.back().bbox();
  }
  bool valid = false;
  double seconds = 0;
  if (parallel)
  {
    using Tds = CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
      CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>;
    using Dt = CGAL::Delaunay_triangulation_3<K, Tds, CGAL::Default,
      CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking>>;
    Dt::Lock_data_structure locks(box, 50);
    const double t0 = Now();
    Dt dt(kp.begin(), kp.end(), &locks);
    seconds = Now() - t0;
    valid = dt.number_of_vertices() == pts.size() && dt.is_valid(false);
  }
  else
  {
    const double t0 = Now();
    CGAL::Delaunay_triangulation_3<K> dt(kp.begin(), kp.end());
    seconds = Now() - t0;
    valid = dt.number_of_vertices() == pts.size() && dt.is_valid(false);
  }
  if (!valid)
  {
    std::fprintf(stderr, "invalid baseline triangulation\n");
    std::exit(1);
  }
  return seconds;
}

void RunCase(const std::string& shape, long n, bool full, bool oneThread)
{
  const std::vector<Point3> pts = Make(shape, n);
  const long before = PeakKiB();
  const double tSequential = BaselineDelaunay(pts, false);
  const long afterDt = PeakKiB();
  const double tParallel = BaselineDelaunay(pts, true);
  flowrecon::BuildOptions options;
  options.StableManifolds = full;
  options.UnstableManifolds = full;
  const tbb::global_control threads(
    tbb::global_control::max_allowed_parallelism, oneThread ? 1 : tbb::this_task_arena::max_concurrency());
  const double t0 = Now();
  const flowrecon::FlowComplex fc = flowrecon::BuildFlowComplex(pts, options, flowrecon::Progress());
  const double total = Now() - t0;
  const long peak = PeakKiB();
  const auto c = fc.CountByIndex();
  std::printf("| %-5s | %-5s | %-3s | %8ld | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f | %6.2f | **%5.2f** | **%5.2f** | %5.0f | %5.0f | %ld/%ld/%ld/%ld |\n",
    shape.c_str(), full ? "full" : "hasse", oneThread ? "1" : "all", n, tSequential, tParallel,
    fc.Time.Delaunay, fc.Time.CriticalPoints, fc.Time.StableManifolds, fc.Time.UnstableManifolds,
    fc.Time.Assembly, total, total / tSequential, total / tParallel,
    1024.0 * (afterDt - before) / n, 1024.0 * (peak - before) / n, static_cast<long>(c[0]),
    static_cast<long>(c[1]), static_cast<long>(c[2]), static_cast<long>(c[3]));
  std::fflush(stdout);
}

} // namespace

int main(int argc, char* argv[])
{
  std::vector<long> sizes;
  for (int i = 1; i < argc; ++i)
  {
    sizes.push_back(std::atol(argv[i]));
  }
  if (sizes.empty())
  {
    sizes = { 10000, 100000, 1000000 };
  }
  std::printf("Times in seconds. CGAL DT seq/par: CGAL's sequential and concurrent Delaunay\n"
              "triangulations of the same points; thr: threads of the flow complex; ratios =\n"
              "whole flow complex / each baseline. Memory in bytes per point (peak RSS growth):\n"
              "sequential Delaunay alone, whole flow complex.\n\n");
  std::printf("| shape | mode | thr | points | CGAL DT seq | CGAL DT par | FC: DT | crit | stable | unstable | assembly | FC total | ratio seq | ratio par | B/pt DT | B/pt FC | nodes 0/1/2/3 |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
  std::fflush(stdout);
  for (const char* shape : { "cube", "torus" })
  {
    for (const long n : sizes)
    {
      // (full, one thread): hasse on all cores, hasse on one, full on all cores.
      for (const auto& [full, oneThread] : { std::pair{ false, false }, { false, true }, { true, false } })
      {
        if (full && n > 200000)
        {
          continue;
        }
        if (oneThread && std::string(shape) == "torus" && n > 300000)
        {
          // The Hasse diagram of a surface sample has ~n^1.5 arcs (the index-2
          // patches span the tube), so this case takes minutes even on all cores.
          std::printf("| torus | hasse | 1 | %ld | skipped: ~n^1.5 work, see the all-core row |\n", n);
          continue;
        }
        const pid_t pid = fork();
        if (pid == 0)
        {
          RunCase(shape, n, full, oneThread);
          std::_Exit(0);
        }
        int status = 0;
        waitpid(pid, &status, 0);
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        {
          std::printf("| %s | %s | %s | %ld | failed (status %d) |\n", shape, full ? "full" : "hasse",
            oneThread ? "1" : "all", n, status);
        }
      }
    }
  }
  return 0;
}
