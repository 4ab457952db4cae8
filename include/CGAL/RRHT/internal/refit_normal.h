// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the paper (issue 18): a least-squares refit of the RRHT normal on
// the neighbors that lie on its plane. The Hough accumulator quantizes
// directions and its votes come from triples, noisier than a fit on all
// points; where the neighborhood is one smooth sheet within the noise, a
// fit of a quadric height field (as jet fitting does) removes both, and
// where it is not (an edge, a corner) the RRHT normal is kept.

#ifndef CGAL_RRHT_INTERNAL_REFIT_NORMAL_H
#define CGAL_RRHT_INTERNAL_REFIT_NORMAL_H

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The outcome of `refit_normal()`.
struct Refit
{
  /// The refitted unit normal, or the RRHT normal when `accepted` is false.
  Eigen::Vector3d normal;
  /// The noise deviation used for the inlier band, as a length.
  double noise;
  /// Whether the neighborhood is one sheet within the noise, so that the
  /// refitted normal replaces the RRHT normal.
  bool accepted;
};

/// The thresholds of the refit, chosen on the clouds of
/// `benchmark/results/issue18` (its README: "The least-squares refit that
/// landed").
struct Refit_thresholds
{
  /// Inliers lie within `band` noise deviations of the fitted surface.
  static constexpr double band = 2.5;
  /// The noise deviation is at least this share of the radius, so that a
  /// noise-free cloud still has a band of inliers.
  static constexpr double least_noise = 0.004;
  /// At most this share of the neighbors may lie outside the band.
  static constexpr double most_outliers = 0.05;
  /// The refit may turn the RRHT normal by at most this angle (degrees).
  static constexpr double largest_turn = 20;
  /// The band and the fit are refined this many times.
  static constexpr int iterations = 3;
};

/// The first quartile of `values`, which it reorders.
inline double first_quartile(std::vector<double>& values)
{
  const auto quartile = values.begin() + std::ptrdiff_t(values.size() / 4);
  std::nth_element(values.begin(), quartile, values.end());
  return *quartile;
}

/// The noise deviation of residuals from the nearest quarter of their
/// absolute values, which neighbors of another sheet do not reach: for a
/// centered Gaussian, the first quartile of |x| is 0.3186 sigma.
inline double noise_of_residuals(const std::vector<double>& residuals, std::vector<double>& work)
{
  work.resize(residuals.size());
  std::transform(residuals.begin(), residuals.end(), work.begin(), [](double x) { return std::abs(x); });
  return first_quartile(work) / 0.3186;
}

/// Refits `normal` (unit) at a point whose neighbors, the point itself
/// included, are `points`, relative to the point and within `radius`. The
/// height of each neighbor above the plane of `normal` is fitted by least
/// squares with a quadric of the two other coordinates, on the neighbors
/// within `Refit_thresholds::band` noise deviations of the current fit,
/// `Refit_thresholds::iterations` times. The noise deviation is `noise`
/// when it is non-negative, else estimated at each iteration from the
/// residuals (`noise_of_residuals()`). The fit is accepted where nearly all
/// neighbors are inliers, the point itself lies within the band and the
/// normal turns by at most `Refit_thresholds::largest_turn`.
inline Refit refit_normal(const std::vector<Eigen::Vector3d>& points, double radius, const Eigen::Vector3d& normal,
                          double noise, std::vector<Eigen::Vector3d>& local, std::vector<double>& residuals,
                          std::vector<double>& work)
{
  typedef Refit_thresholds T;
  typedef Eigen::Matrix<double, 6, 1> Vector6;
  // The neighbors in the frame (u, v, normal), over the radius.
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  const std::size_t size = points.size();
  local.resize(size);
  residuals.resize(size);
  for(std::size_t i = 0; i < size; ++i)
  {
    local[i] = Eigen::Vector3d(u.dot(points[i]), v.dot(points[i]), normal.dot(points[i])) / radius;
    residuals[i] = local[i].z();
  }

  // The monomials of a quadric height field at a point of the frame.
  auto monomials = [](const Eigen::Vector3d& p) {
    Vector6 m;
    m << 1, p.x(), p.y(), p.x() * p.x(), p.x() * p.y(), p.y() * p.y();
    return m;
  };
  Refit refit{ normal, noise, false };
  Vector6 quadric = Vector6::Zero();
  double band = 0; // over the radius
  std::size_t inliers = 0;
  for(int iteration = 0; iteration < T::iterations; ++iteration)
  {
    const double deviation = noise >= 0 ? noise / radius : noise_of_residuals(residuals, work);
    refit.noise = radius * (std::max)(deviation, T::least_noise);
    band = T::band * refit.noise / radius;
    Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
    Vector6 right_side = Vector6::Zero();
    inliers = 0;
    for(std::size_t i = 0; i < size; ++i)
      if(std::abs(residuals[i]) <= band)
      {
        const Vector6 m = monomials(local[i]);
        normal_matrix.selfadjointView<Eigen::Lower>().rankUpdate(m);
        right_side += local[i].z() * m;
        ++inliers;
      }
    if(inliers < 6)
      return refit;
    quadric = normal_matrix.selfadjointView<Eigen::Lower>().ldlt().solve(right_side);
    if(!quadric.allFinite())
      return refit;
    for(std::size_t i = 0; i < size; ++i)
    {
      const double x = local[i].x(), y = local[i].y();
      residuals[i] = local[i].z() - (quadric[0] + quadric[1] * x + quadric[2] * y + quadric[3] * x * x +
                                     quadric[4] * x * y + quadric[5] * y * y);
    }
  }

  const Eigen::Vector3d fitted = (normal - quadric[1] * u - quadric[2] * v).normalized();
  const double cos_largest_turn = std::cos(T::largest_turn * 3.14159265358979323846 / 180);
  if(double(size - inliers) <= T::most_outliers * double(size) && std::abs(quadric[0]) <= band &&
     std::abs(fitted.dot(normal)) >= cos_largest_turn && fitted.allFinite())
  {
    refit.normal = fitted;
    refit.accepted = true;
  }
  return refit;
}

/// The noise deviation to refit with at a point: the first quartile of the
/// deviations estimated at its neighbors. Near an edge or on a curved patch
/// a point's own estimate grows with the other sheet or the curvature; its
/// cleanest neighbors tell the noise of the scan.
inline double noise_of_neighbors(const std::vector<std::size_t>& positions, const std::vector<double>& noise,
                                 std::vector<double>& work)
{
  work.clear();
  for(std::size_t p : positions)
    work.push_back(noise[p]);
  return first_quartile(work);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_REFIT_NORMAL_H
