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
/// `benchmark/results/issue18` (README, section "refit").
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

/// The noise deviation of residuals from the nearest quarter of their
/// absolute values, which neighbors of another sheet do not reach: for a
/// centered Gaussian, the first quartile of |x| is 0.3186 sigma.
inline double noise_of_residuals(const std::vector<double>& residuals, std::vector<double>& work)
{
  work.resize(residuals.size());
  std::transform(residuals.begin(), residuals.end(), work.begin(), [](double x) { return std::abs(x); });
  const auto quarter = work.begin() + std::ptrdiff_t(work.size() / 4);
  std::nth_element(work.begin(), quarter, work.end());
  return *quarter / 0.3186;
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

  Refit refit{ normal, noise, false };
  Vector6 quadric = Vector6::Zero();
  double band = 0; // over the radius
  std::size_t inliers = 0;
  for(int iteration = 0; iteration < T::iterations; ++iteration)
  {
    const double deviation = noise >= 0 ? noise / radius : noise_of_residuals(residuals, work);
    refit.noise = radius * (std::max)(deviation, T::least_noise);
    band = T::band * refit.noise / radius;
    // The normal equations of the quadric from the moments of the inliers:
    // sum of x^a y^b (a + b <= 4) and of h x^a y^b (a + b <= 2).
    double mxy[5][5] = {}, mh[3][3] = {};
    inliers = 0;
    for(std::size_t i = 0; i < size; ++i)
      if(std::abs(residuals[i]) <= band)
      {
        const double x = local[i].x(), y = local[i].y(), h = local[i].z();
        const double px[5] = { 1, x, x * x, x * x * x, x * x * x * x };
        const double py[5] = { 1, y, y * y, y * y * y, y * y * y * y };
        for(int a = 0; a <= 4; ++a)
          for(int b = 0; a + b <= 4; ++b)
            mxy[a][b] += px[a] * py[b];
        for(int a = 0; a <= 2; ++a)
          for(int b = 0; a + b <= 2; ++b)
            mh[a][b] += h * px[a] * py[b];
        ++inliers;
      }
    static const int exponent[6][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 }, { 2, 0 }, { 1, 1 }, { 0, 2 } };
    Eigen::Matrix<double, 6, 6> normal_matrix;
    Vector6 right_side;
    for(int r = 0; r < 6; ++r)
    {
      for(int c = 0; c < 6; ++c)
        normal_matrix(r, c) = mxy[exponent[r][0] + exponent[c][0]][exponent[r][1] + exponent[c][1]];
      right_side[r] = mh[exponent[r][0]][exponent[r][1]];
    }
    if(inliers < 6)
      return refit;
    quadric = normal_matrix.ldlt().solve(right_side);
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
  const auto quartile = work.begin() + std::ptrdiff_t(work.size() / 4);
  std::nth_element(work.begin(), quartile, work.end());
  return *quartile;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_REFIT_NORMAL_H
