#include "LocalFlatness.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace flowrecon
{

double MedianFlatness(const std::vector<Point3>& points, int k, std::size_t probes)
{
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Traits = CGAL::Search_traits_3<K>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;
  const std::size_t n = points.size();
  if (k < 3 || probes == 0 || n < static_cast<std::size_t>(k) + 1)
  {
    return 1;
  }
  std::vector<K::Point_3> pts;
  pts.reserve(n);
  for (const Point3& p : points)
  {
    pts.emplace_back(p[0], p[1], p[2]);
  }
  const Search::Tree tree(pts.begin(), pts.end());
  const std::size_t step = std::max<std::size_t>(1, n / probes);
  std::vector<double> ratios;
  for (std::size_t i = 0; i < n && ratios.size() < probes; i += step)
  {
    const Search search(tree, pts[i], static_cast<unsigned>(k));
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> near;
    for (const auto& hit : search)
    {
      near.emplace_back(hit.first.x(), hit.first.y(), hit.first.z());
      mean += near.back();
    }
    mean /= static_cast<double>(near.size());
    Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
    for (const Eigen::Vector3d& q : near)
    {
      c += (q - mean) * (q - mean).transpose();
    }
    const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(c, Eigen::EigenvaluesOnly).eigenvalues();
    // Duplicates make a degenerate neighbourhood: it says nothing either way.
    if (ev[1] > 0)
    {
      ratios.push_back(std::max(0.0, ev[0]) / ev[1]);
    }
  }
  if (ratios.empty())
  {
    return 1;
  }
  const auto mid = ratios.begin() + static_cast<std::ptrdiff_t>(ratios.size() / 2);
  std::nth_element(ratios.begin(), mid, ratios.end());
  return *mid;
}

} // namespace flowrecon
