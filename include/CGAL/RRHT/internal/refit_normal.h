// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Beyond the paper: a least-squares refit of the RRHT normal on
// the neighbors that lie on its plane. The Hough accumulator quantizes
// directions and its votes come from triples, noisier than a fit on all
// points; where the neighborhood is one smooth sheet within the noise, a
// fit of a quadric height field (as jet fitting does) removes both, and
// where it is two parallel sheets (the two sides of a thin part), a fit of
// two parallel planes does. Elsewhere (an edge, a corner) the RRHT normal
// is kept.

#ifndef CGAL_RRHT_INTERNAL_REFIT_NORMAL_H
#define CGAL_RRHT_INTERNAL_REFIT_NORMAL_H

#include <CGAL/RRHT/internal/nth_smallest.h>
#include <CGAL/RRHT/internal/principal_axes.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The thresholds of the refit, chosen on the benchmark's sharp shapes,
/// smooth clouds and thin parts (the design notes, "Beyond the paper, in detail").
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
  /// Where every neighbor lies within this many noise deviations of the
  /// quadric, the neighborhood is one sheet whatever the frame: it is fitted
  /// in the frame of its principal axes, as jet fitting does.
  static constexpr double one_sheet = 3;
  /// Two parallel sheets are kept where they are this many deviations of
  /// their residuals apart (two halves of one noisy sheet are about 2.7).
  static constexpr double sheets_apart = 4;
  /// ... where the smaller sheet holds at least this share of the neighbors,
  static constexpr double smaller_sheet = 0.25;
  /// ... lies under the point (its center within this share of the radius
  /// from the point, along the sheets), unlike a strip of another face, and
  /// not farther from it on average than the point's sheet, unlike the rim
  /// around a cap,
  static constexpr double off_center = 0.3;
  /// ... and each sheet alone is this close to parallel to the fit (degrees).
  static constexpr double parallel = 10;
};

/// Room for `refit_normal()`, kept between points.
struct Refit_scratch
{
  std::vector<Eigen::Vector3d> local; // the neighborhood in the frame of the fit, over the radius
  std::vector<double> residuals, work;
  std::vector<unsigned char> sheet;     // 1 for the sheet without the point
  std::vector<Eigen::Vector3d> nearest; // the nearest of the neighbors
  std::vector<Eigen::Vector3d> own;     // the neighbors on the point's own sheet
};

/// The first quartile of `values`, which it reorders.
inline double first_quartile(std::vector<double>& values)
{
  return nth_smallest(values, values.size() / 4);
}

/// The split of the sorted `values` (two or more) into two contiguous
/// groups of least squared deviation from their means (1D 2-means, exact):
/// the first position of the upper group, which may be a single value.
inline std::size_t split_in_two(const std::vector<double>& sorted)
{
  const std::size_t size = sorted.size();
  double sum = 0, squares = 0;
  for(double x : sorted)
    sum += x, squares += x * x;
  double least = std::numeric_limits<double>::infinity(), below = 0, below_squares = 0;
  std::size_t at = 1;
  for(std::size_t i = 1; i < size; ++i)
  {
    below += sorted[i - 1], below_squares += sorted[i - 1] * sorted[i - 1];
    const double n_below = double(i), n_above = double(size - i), above = sum - below;
    const double about_means =
      below_squares - below * below / n_below + (squares - below_squares) - above * above / n_above;
    if(about_means < least)
      least = about_means, at = i;
  }
  return at;
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

/// `points` (relative to the point) in the frame (u, v, `normal`) over `radius`.
inline void to_frame(const std::vector<Eigen::Vector3d>& points, double radius, const Eigen::Vector3d& normal,
                     const Eigen::Vector3d& u, const Eigen::Vector3d& v, std::vector<Eigen::Vector3d>& local)
{
  local.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    local[i] = Eigen::Vector3d(u.dot(points[i]), v.dot(points[i]), normal.dot(points[i])) / radius;
}

/// Fits `c`, the least-squares height field z = c . monomials(i) of the
/// points `local` where `use(i)`; false where fewer points than
/// coefficients are used or the system is singular.
template <int N, class Monomials, class Use>
bool fit_height_field(const std::vector<Eigen::Vector3d>& local, Monomials monomials, Use use,
                      Eigen::Matrix<double, N, 1>& c)
{
  typedef Eigen::Matrix<double, N, 1> Vector;
  Eigen::Matrix<double, N, N> normal_matrix = Eigen::Matrix<double, N, N>::Zero();
  Vector right_side = Vector::Zero();
  int used = 0;
  for(std::size_t i = 0; i < local.size(); ++i)
    if(use(i))
    {
      const Vector m = monomials(i);
      normal_matrix.noalias() += m * m.transpose(); // unrolled at these sizes, unlike rankUpdate()
      right_side += local[i].z() * m;
      ++used;
    }
  if(used < N)
    return false;
  c = normal_matrix.ldlt().solve(right_side);
  return c.allFinite();
}

/// The value of the quadric height field `c`, of the monomials
/// 1, x, y, x^2, xy, y^2, at a point of the frame.
inline double quadric_height(const Eigen::Matrix<double, 6, 1>& c, const Eigen::Vector3d& p)
{
  const double x = p.x(), y = p.y();
  return c[0] + x * (c[1] + c[3] * x + c[4] * y) + y * (c[2] + c[5] * y);
}

/// Fits `c`, the least-squares quadric height field (`quadric_height()`)
/// of the points `local` where `use(i)`; false where fewer than 6 points
/// are used or the system is singular. Its normal equations hold 15
/// distinct moments x^a y^b (a + b <= 4), each summed once as a scalar
/// rather than as the 36 products of a monomial vector
/// (`fit_height_field()`): the quadric is fitted at every point of the cloud.
template <class Use>
bool fit_quadric_height_field(const std::vector<Eigen::Vector3d>& local, Use use, Eigen::Matrix<double, 6, 1>& c)
{
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0, sxxx = 0, sxxy = 0, sxyy = 0, syyy = 0;
  double sxxxx = 0, sxxxy = 0, sxxyy = 0, sxyyy = 0, syyyy = 0;
  double sz = 0, sxz = 0, syz = 0, sxxz = 0, sxyz = 0, syyz = 0;
  for(std::size_t i = 0; i < local.size(); ++i)
    if(use(i))
    {
      const double x = local[i].x(), y = local[i].y(), z = local[i].z();
      const double xx = x * x, xy = x * y, yy = y * y;
      n += 1, sx += x, sy += y, sxx += xx, sxy += xy, syy += yy;
      sxxx += xx * x, sxxy += xx * y, sxyy += x * yy, syyy += yy * y;
      sxxxx += xx * xx, sxxxy += xx * xy, sxxyy += xx * yy, sxyyy += xy * yy, syyyy += yy * yy;
      sz += z, sxz += x * z, syz += y * z, sxxz += xx * z, sxyz += xy * z, syyz += yy * z;
    }
  if(n < 6)
    return false;
  Eigen::Matrix<double, 6, 6> normal_matrix;
  normal_matrix << n, sx, sy, sxx, sxy, syy, //
    sx, sxx, sxy, sxxx, sxxy, sxyy,          //
    sy, sxy, syy, sxxy, sxyy, syyy,          //
    sxx, sxxx, sxxy, sxxxx, sxxxy, sxxyy,    //
    sxy, sxxy, sxyy, sxxxy, sxxyy, sxyyy,    //
    syy, sxyy, syyy, sxxyy, sxyyy, syyyy;
  Eigen::Matrix<double, 6, 1> right_side;
  right_side << sz, sxz, syz, sxxz, sxyz, syyz;
  c = normal_matrix.ldlt().solve(right_side);
  return c.allFinite();
}

/// Whether two unit directions, sign ignored, are at most `degrees` apart.
inline bool within_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double degrees)
{
  return std::abs(a.dot(b)) >= std::cos(degrees * CGAL_PI / 180);
}

/// The outcome of `fit_one_sheet()`.
struct One_sheet
{
  Eigen::Matrix<double, 6, 1> quadric; // in the frame of the normal, over the radius
  double noise;                        // the noise deviation used, as a length
  double band;                         // the inlier band, over the radius
  std::size_t inliers;                 // neighbors within the band
};

/// The robust quadric height field of the neighbors `points` (relative to
/// the point) in the frame of `normal`: fitted on the neighbors within
/// `Refit_thresholds::band` noise deviations of the current fit,
/// `Refit_thresholds::iterations` times. The noise deviation is `noise`
/// when it is non-negative, else estimated at each iteration from the
/// residuals (`noise_of_residuals()`). Leaves the residuals of the last fit
/// in `scratch.residuals`; no inliers if the fit fails.
inline One_sheet fit_one_sheet(const std::vector<Eigen::Vector3d>& points, double radius, const Eigen::Vector3d& normal,
                               double noise, Refit_scratch& scratch)
{
  typedef Refit_thresholds T;
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  to_frame(points, radius, normal, u, v, scratch.local);
  const std::vector<Eigen::Vector3d>& local = scratch.local;
  std::vector<double>& residuals = scratch.residuals;
  residuals.resize(local.size());
  for(std::size_t i = 0; i < local.size(); ++i)
    residuals[i] = local[i].z();

  One_sheet fit{ Eigen::Matrix<double, 6, 1>::Zero(), 0, 0, 0 };
  for(int iteration = 0; iteration < T::iterations; ++iteration)
  {
    const double deviation = noise >= 0 ? noise / radius : noise_of_residuals(residuals, scratch.work);
    fit.noise = radius * (std::max)(deviation, T::least_noise);
    fit.band = T::band * fit.noise / radius;
    auto inlier = [&](std::size_t i) { return std::abs(residuals[i]) <= fit.band; };
    fit.inliers = 0;
    for(std::size_t i = 0; i < local.size(); ++i)
      fit.inliers += inlier(i);
    if(!fit_quadric_height_field(local, inlier, fit.quadric))
    {
      fit.inliers = 0;
      return fit;
    }
    for(std::size_t i = 0; i < local.size(); ++i)
      residuals[i] = local[i].z() - quadric_height(fit.quadric, local[i]);
  }
  return fit;
}

/// The normal of two parallel sheets fitted to the neighbors `points`
/// (relative to the point), from the frame of `normal`, with inliers within
/// `band` (over the radius), or the null vector where the neighborhood is
/// not two such sheets (`Refit_thresholds`). Each time, the heights are
/// split in two where the sum of squares about the two means is least (1D
/// 2-means), and one plane height field with one more constant for the
/// sheet without the point is fitted, on all neighbors, then on those in
/// the band.
inline Eigen::Vector3d fit_two_sheets(const std::vector<Eigen::Vector3d>& points, double radius, Eigen::Vector3d normal,
                                      double band, Refit_scratch& scratch)
{
  typedef Refit_thresholds T;
  typedef Eigen::Matrix<double, 4, 1> Vector4;
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  const std::size_t size = points.size();
  std::vector<Eigen::Vector3d>& local = scratch.local;
  std::vector<double>& residuals = scratch.residuals;
  std::vector<unsigned char>& sheet = scratch.sheet;
  std::vector<double>& heights = scratch.work;
  sheet.resize(size);
  Vector4 sheets = Vector4::Zero();
  auto monomials = [&](std::size_t i) { return Vector4(1, local[i].x(), local[i].y(), sheet[i]); };
  Eigen::Vector3d u, v;
  for(int iteration = 0; iteration < T::iterations; ++iteration)
  {
    u = normal.unitOrthogonal(), v = normal.cross(u);
    to_frame(points, radius, normal, u, v, local);
    heights.resize(size);
    for(std::size_t i = 0; i < size; ++i)
      heights[i] = local[i].z();
    std::sort(heights.begin(), heights.end());
    const std::size_t at = split_in_two(heights);
    const double split = 0.5 * (heights[at - 1] + heights[at]);
    for(std::size_t i = 0; i < size; ++i)
      sheet[i] = (local[i].z() > split) != (0 > split);

    auto use = [&](std::size_t i) { return iteration == 0 || std::abs(residuals[i]) <= band; };
    if(!fit_height_field<4>(local, monomials, use, sheets))
      return none;
    residuals.resize(size);
    for(std::size_t i = 0; i < size; ++i)
      residuals[i] = local[i].z() - sheets.dot(monomials(i));
    normal = (normal - sheets[1] * u - sheets[2] * v).normalized();
  }

  // The gate, on the last fit (in its frame: `local`, `residuals`).
  std::size_t outliers = 0, other = 0;
  double squares = 0, spread[2] = { 0, 0 }; // the sheets' sums of squared distances from the point, along them
  Eigen::Vector2d other_center = Eigen::Vector2d::Zero();
  for(std::size_t i = 0; i < size; ++i)
  {
    if(std::abs(residuals[i]) > band)
      ++outliers;
    else
      squares += residuals[i] * residuals[i];
    if(sheet[i])
      ++other, other_center += local[i].head<2>();
    spread[sheet[i]] += local[i].head<2>().squaredNorm();
  }
  const std::size_t smaller = (std::min)(other, size - other);
  if(double(outliers) > T::most_outliers * double(size) || std::abs(sheets[0]) > band ||
     double(smaller) < T::smaller_sheet * double(size) ||
     std::abs(sheets[3]) < T::sheets_apart * std::sqrt(squares / double(size - outliers)) ||
     other_center.norm() > T::off_center * double(other) ||
     spread[1] * double(size - other) > spread[0] * double(other))
    return none;
  for(unsigned char side = 0; side < 2; ++side)
    if(!within_angle(principal_normal(points, [&](std::size_t i) { return sheet[i] == side; }), normal, T::parallel))
      return none;
  return normal;
}

/// Refits `normal` (unit) at a point whose neighbors, the point itself
/// included, are `points`, relative to the point and within `radius`, with
/// the noise deviation `noise` (a length). Returns the refitted unit
/// normal, or the null vector where the RRHT normal is to be kept:
/// - two parallel sheets (`fit_two_sheets()`) give their normal;
/// - else one sheet (`fit_one_sheet()`) is accepted where nearly all
///   neighbors are inliers and the point itself lies within the band; where
///   every neighbor lies within `Refit_thresholds::one_sheet` deviations, its
///   normal is that of a quadric on all of them in the frame of their
///   principal axes (jet fitting's), which does not depend on the RRHT
///   normal's frame;
/// and in both cases the normal turns by at most `Refit_thresholds::largest_turn`.
inline Eigen::Vector3d refit_normal(const std::vector<Eigen::Vector3d>& points, double radius,
                                    const Eigen::Vector3d& normal, double noise, Refit_scratch& scratch)
{
  typedef Refit_thresholds T;
  const Eigen::Vector3d none = Eigen::Vector3d::Zero();
  const std::size_t size = points.size();
  auto turned = [&](const Eigen::Vector3d& n) {
    return n.allFinite() && n != none && within_angle(n, normal, T::largest_turn) ? n : none;
  };

  const One_sheet one = fit_one_sheet(points, radius, normal, noise, scratch);
  if(one.inliers == 0)
    return none;
  const double farthest = std::abs(*std::max_element(scratch.residuals.begin(), scratch.residuals.end(),
                                                     [](double a, double b) { return std::abs(a) < std::abs(b); }));
  const bool one_sheet_everywhere = farthest <= T::one_sheet * one.noise / radius;

  const Eigen::Vector3d two = turned(fit_two_sheets(points, radius, normal, one.band, scratch));
  if(two != none)
    return two;

  if(double(size - one.inliers) > T::most_outliers * double(size) || std::abs(one.quadric[0]) > one.band)
    return none;
  if(one_sheet_everywhere)
  {
    const Eigen::Vector3d axis = principal_normal(points, [](std::size_t) { return true; });
    const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
    to_frame(points, radius, axis, u, v, scratch.local);
    const std::vector<Eigen::Vector3d>& local = scratch.local;
    Eigen::Matrix<double, 6, 1> quadric;
    return fit_quadric_height_field(local, [](std::size_t) { return true; }, quadric)
             ? turned((axis - quadric[1] * u - quadric[2] * v).normalized())
             : none;
  }
  const Eigen::Vector3d u = normal.unitOrthogonal(), v = normal.cross(u);
  return turned((normal - one.quadric[1] * u - one.quadric[2] * v).normalized());
}

/// The noise deviation to refit with at a point: the first quartile of the
/// deviations estimated at its neighbors. Near an edge or on a curved patch
/// a point's own estimate grows with the other sheet or the curvature; its
/// cleanest neighbors tell the noise of the scan.
template <typename Positions, typename Deviation>
double noise_of_neighbors(const Positions& positions, const std::vector<Deviation>& noise, std::vector<double>& work)
{
  work.clear();
  for(auto p : positions)
    work.push_back(noise[p]);
  return first_quartile(work);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_REFIT_NORMAL_H
