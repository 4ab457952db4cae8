// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The principal axes of a set of points: the frame of jet fitting's quadric,
// and the least-squares plane of the points (its normal the smallest axis).

#ifndef CGAL_RRHT_INTERNAL_PRINCIPAL_AXES_H
#define CGAL_RRHT_INTERNAL_PRINCIPAL_AXES_H

#include <CGAL/RRHT/internal/outer_product.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The centroid of some points, their number, and their principal axes.
struct Principal_axes
{
  Eigen::Vector3d centroid;
  std::size_t count;
  /// The eigenvectors of the points' covariance about their centroid, by
  /// increasing eigenvalue.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes;
};

/// The principal axes of `points` where `use(i)`. Without such a point, the
/// count is 0 and the centroid and axes are undefined.
template <class Use>
Principal_axes principal_axes(const std::vector<Eigen::Vector3d>& points, Use use)
{
  Principal_axes result{ Eigen::Vector3d::Zero(), 0, {} };
  for(std::size_t i = 0; i < points.size(); ++i)
    if(use(i))
      result.centroid += points[i], ++result.count;
  result.centroid /= double(result.count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for(std::size_t i = 0; i < points.size(); ++i)
    if(use(i))
    {
      const Eigen::Vector3d q = points[i] - result.centroid;
      add_outer_product(covariance, q, q);
    }
  result.axes.compute(covariance);
  return result;
}

/// The unit normal of the least-squares plane of `points` where `use(i)`:
/// their smallest principal axis.
template <class Use>
Eigen::Vector3d principal_normal(const std::vector<Eigen::Vector3d>& points, Use use)
{
  return principal_axes(points, use).axes.eigenvectors().col(0);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PRINCIPAL_AXES_H
