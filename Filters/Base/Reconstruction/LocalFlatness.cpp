#include "LocalFlatness.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace flowrecon
{

namespace
{

double Median(std::vector<double>& values)
{
  if (values.empty())
  {
    return 1;
  }
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

/// lambda_min / lambda_mid of the covariance of `near`'s first k points;
/// negative when they are one place (duplicates: it says nothing either way);
/// 0 when they lie on a line (a curve's sample, flat: the ratio of two
/// rounding errors said anything from 0 to 1 there).
double Flatness(const std::vector<Eigen::Vector3d>& near, std::size_t k)
{
  if (std::all_of(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(k),
        [&near](const Eigen::Vector3d& p) { return p == near[0]; }))
  {
    return -1;
  }
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < k; ++i)
  {
    mean += near[i];
  }
  mean /= static_cast<double>(k);
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < k; ++i)
  {
    c += (near[i] - mean) * (near[i] - mean).transpose();
  }
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c, Eigen::EigenvaluesOnly).eigenvalues();
  return ev[1] > 1e-12 * ev[2] ? std::max(0.0, ev[0]) / ev[1] : 0.0;
}

} // namespace

const std::array<FlatnessScale, 3>& FlatnessScales()
{
  static const std::array<FlatnessScale, 3> scales{ { { 10, 0.46 }, { 30, 0.71 }, { 100, 0.83 } } };
  return scales;
}

std::vector<double> MedianFlatness(
  const std::vector<Point3>& points, const std::vector<int>& ks, std::size_t probes)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Search_traits_3<K>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  const std::size_t n = points.size();
  std::vector<double> medians(ks.size(), 1.0);
  int largest = 0;
  for (const int k : ks)
  {
    if (k >= 3 && n >= static_cast<std::size_t>(k) + 1)
    {
      largest = std::max(largest, k);
    }
  }
  if (largest == 0 || probes == 0)
  {
    return medians;
  }
  std::vector<K::Point_3> pts;
  pts.reserve(n);
  for (const Point3& p : points)
  {
    pts.emplace_back(p[0], p[1], p[2]);
  }
  const Search::Tree tree(pts.begin(), pts.end());
  const std::size_t step = std::max<std::size_t>(1, n / probes);
  std::vector<std::vector<double>> ratios(ks.size());
  std::vector<Eigen::Vector3d> near;
  std::size_t probed = 0;
  for (std::size_t i = 0; i < n && probed < probes; i += step, ++probed)
  {
    // Sorted by distance: each smaller neighbourhood is a prefix.
    const Search search(tree, pts[i], static_cast<unsigned>(largest));
    near.clear();
    for (const auto& hit : search)
    {
      near.emplace_back(hit.first.x(), hit.first.y(), hit.first.z());
    }
    for (std::size_t s = 0; s < ks.size(); ++s)
    {
      if (ks[s] >= 3 && ks[s] <= largest)
      {
        const double f = Flatness(near, static_cast<std::size_t>(ks[s]));
        if (f >= 0)
        {
          ratios[s].push_back(f);
        }
      }
    }
  }
  for (std::size_t s = 0; s < ks.size(); ++s)
  {
    if (ks[s] >= 3 && ks[s] <= largest)
    {
      medians[s] = Median(ratios[s]);
    }
  }
  return medians;
}

double MedianFlatness(const std::vector<Point3>& points, int k, std::size_t probes)
{
  return MedianFlatness(points, std::vector<int>{ k }, probes)[0];
}

namespace
{
/// A neighbourhood of more than a twentieth of the cloud sees its extent.
constexpr std::size_t ScalesPerCloud = 20;
}

std::size_t FlatnessMinimumPoints()
{
  std::size_t fewest = 0;
  for (const FlatnessScale& s : FlatnessScales())
  {
    const std::size_t n = static_cast<std::size_t>(s.K) * ScalesPerCloud;
    fewest = fewest == 0 ? n : std::min(fewest, n);
  }
  return fewest;
}

double RelativeFlatness(const std::vector<Point3>& points, std::size_t probes)
{
  std::vector<int> ks;
  for (const FlatnessScale& s : FlatnessScales())
  {
    if (static_cast<std::size_t>(s.K) * ScalesPerCloud <= points.size())
    {
      ks.push_back(s.K);
    }
  }
  const std::vector<double> medians = MedianFlatness(points, ks, probes);
  double smallest = 1;
  for (std::size_t s = 0; s < ks.size(); ++s)
  {
    for (const FlatnessScale& scale : FlatnessScales())
    {
      if (scale.K == ks[s])
      {
        smallest = std::min(smallest, medians[s] / scale.Volume);
      }
    }
  }
  return smallest;
}

} // namespace flowrecon
