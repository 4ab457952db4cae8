// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The two faces of a thin wedge that a neighborhood holds: the sides of a
// blade near its edge, or of a tapered tooth, which meet at a small angle.
// The offsets from one tangent plane, which tell parallel sheets apart
// (`Sheets`), do not tell these apart: the faces cross the plane.

#ifndef CGAL_RRHT_INTERNAL_WEDGE_H
#define CGAL_RRHT_INTERNAL_WEDGE_H

#include <CGAL/RRHT/internal/principal_axes.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The faces of a point's neighborhood when it holds the two sides of a thin
/// wedge: two planes, the point's own face among them, and on which face a
/// neighbor lies.
class Wedge
{
public:
  /// No wedge.
  Wedge() = default;

  /// The wedge of the points `points`, given relative to the point (which is
  /// at the origin, among them) and whose normals are parallel to the unit
  /// `axis`, if they lie on one.
  ///
  /// The points are split between two planes (k-planes: from the split at
  /// the median offset along `axis`, each plane is fitted to its points by
  /// least squares and each point goes to the nearer, until nothing moves).
  /// The split is a wedge when each plane holds an eighth of the points or
  /// more and
  /// - the two planes explain the points far better than one: the deviation
  ///   from one plane is over 3 times that from the nearer of two;
  /// - they are stacked, as the two sides of a thin part: their points'
  ///   centroids are within half the neighborhood's radius of each other
  ///   along the tangent plane, where a corner or a fillet puts them side
  ///   by side;
  /// - they face along `axis` (within 18 degrees), as the points' normals
  ///   do;
  /// - they are tilted: the offsets along `axis` within each plane spread
  ///   over twice the deviation from it, where parallel sheets would not.
  ///
  /// `deviation()` is then the deviation from one plane, which the caller
  /// compares with the noise.
  Wedge(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& axis)
  {
    const std::size_t n = points.size();
    if(n < min_points)
      return;
    std::vector<double> offsets(n);
    for(std::size_t t = 0; t < n; ++t)
      offsets[t] = axis.dot(points[t]);
    std::nth_element(offsets.begin(), offsets.begin() + std::ptrdiff_t(n / 2), offsets.end());
    const double median = offsets[n / 2];
    std::vector<int> face(n);
    for(std::size_t t = 0; t < n; ++t)
      face[t] = axis.dot(points[t]) > median;
    Plane planes[2];
    bool settled = false;
    for(int round = 0; round < max_rounds && !settled; ++round)
    {
      fit_faces(points, face, planes);
      if(planes[0].size < 3 || planes[1].size < 3)
        return;
      settled = true;
      for(std::size_t t = 0; t < n; ++t)
      {
        const int nearer = planes[0].distance(points[t]) <= planes[1].distance(points[t]) ? 0 : 1;
        settled = settled && nearer == face[t];
        face[t] = nearer;
      }
    }
    // Settled, the planes are already those of the faces.
    if(!settled)
    {
      fit_faces(points, face, planes);
    }
    const std::size_t min_face = (std::max)(std::size_t(3), n / 8);
    if(planes[0].size < min_face || planes[1].size < min_face)
      return;
    const Plane one(points);
    const double deviation_1 = std::sqrt(one.squared_deviation / double(n)),
                 deviation_2 = std::sqrt((planes[0].squared_deviation + planes[1].squared_deviation) / double(n));
    if(!(deviation_1 > separation * deviation_2))
      return;
    double radius = 0;
    for(const Eigen::Vector3d& p : points)
      radius = (std::max)(radius, p.norm());
    const Eigen::Vector3d apart = planes[0].centroid - planes[1].centroid;
    if((apart - axis.dot(apart) * axis).norm() > max_side_by_side * radius)
      return;
    if(std::abs(planes[0].normal.dot(axis)) < cos_facing || std::abs(planes[1].normal.dot(axis)) < cos_facing)
      return;
    double spread = 0;
    for(int g = 0; g < 2; ++g)
    {
      const double mean = axis.dot(planes[g].centroid);
      for(std::size_t t = 0; t < n; ++t)
        if(face[t] == g)
        {
          const double offset = axis.dot(points[t]);
          spread += (offset - mean) * (offset - mean);
        }
    }
    if(std::sqrt(spread / double(n)) < min_tilt * deviation_2)
      return;
    for(int g = 0; g < 2; ++g)
    {
      m_normals[g] = planes[g].normal;
      m_centroids[g] = planes[g].centroid;
    }
    m_deviation = deviation_1;
    m_own = face_of(Eigen::Vector3d::Zero());
    m_found = true;
  }

  /// Whether the neighborhood holds a wedge.
  bool found() const { return m_found; }

  /// The points' deviation from one plane (0 without a wedge).
  double deviation() const { return m_found ? m_deviation : 0.; }

  /// +1 if a point at `d` from the point is on the point's own face, -1 if
  /// on the other, 0 if it, or the point, is not twice nearer one face than
  /// the other.
  int side(const Eigen::Vector3d& d) const
  {
    const int face = face_of(d);
    return face < 0 || m_own < 0 ? 0 : face == m_own ? 1 : -1;
  }

private:
  static constexpr std::size_t min_points = 8;
  static constexpr int max_rounds = 15;
  static constexpr double separation = 3, max_side_by_side = 0.5, min_tilt = 2;
  static constexpr double cos_facing = 0.95; // 18 degrees

  /// The plane of least squared distances to some points: all of them
  /// (this constructor), or one face's (`fit_faces()`).
  struct Plane
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::UnitZ();
    double squared_deviation = 0;
    std::size_t size = 0;

    Plane() = default;
    explicit Plane(const std::vector<Eigen::Vector3d>& points)
    {
      const Principal_axes principal = principal_axes(points, [](std::size_t) { return true; });
      size = principal.count;
      if(size == 0)
        return;
      centroid = principal.centroid;
      normal = principal.axes.eigenvectors().col(0);
      squared_deviation = (std::max)(0., principal.axes.eigenvalues()(0));
    }

    double distance(const Eigen::Vector3d& p) const { return std::abs((p - centroid).dot(normal)); }
  };

  /// The planes of the two faces (`face[t]`, 0 or 1, for each point `t`),
  /// as `Plane` fits each: two passes over the points for both faces.
  static void fit_faces(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& face, Plane (&planes)[2])
  {
    Eigen::Vector3d centroids[2] = { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() };
    std::size_t counts[2] = { 0, 0 };
    for(std::size_t t = 0; t < points.size(); ++t)
      centroids[face[t]] += points[t], ++counts[face[t]];
    Eigen::Matrix3d covariances[2] = { Eigen::Matrix3d::Zero(), Eigen::Matrix3d::Zero() };
    for(int g = 0; g < 2; ++g)
      centroids[g] /= double(counts[g]);
    for(std::size_t t = 0; t < points.size(); ++t)
    {
      const Eigen::Vector3d q = points[t] - centroids[face[t]];
      add_outer_product(covariances[face[t]], q, q);
    }
    for(int g = 0; g < 2; ++g)
    {
      planes[g] = Plane();
      planes[g].size = counts[g];
      if(counts[g] == 0)
        continue;
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> axes(covariances[g]);
      planes[g].centroid = centroids[g];
      planes[g].normal = axes.eigenvectors().col(0);
      planes[g].squared_deviation = (std::max)(0., axes.eigenvalues()(0));
    }
  }

  /// The face (0 or 1) that a point at `d` is twice nearer than the other,
  /// or -1.
  int face_of(const Eigen::Vector3d& d) const
  {
    const double r0 = std::abs((d - m_centroids[0]).dot(m_normals[0])),
                 r1 = std::abs((d - m_centroids[1]).dot(m_normals[1]));
    return r0 < 0.5 * r1 ? 0 : r1 < 0.5 * r0 ? 1 : -1;
  }

  Eigen::Vector3d m_normals[2], m_centroids[2];
  double m_deviation = 0;
  int m_own = -1;
  bool m_found = false;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_WEDGE_H
