// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The neighbors' planes as hypotheses (beyond the paper): near a sharp
// feature, the faces that meet there are known already, as the
// least-squares normals of the neighbors whose neighborhood is one smooth
// sheet. Each is a plane through the point, scored by a few dozen distance
// tests as the Hough transform's votes score theirs (Section 2), and the
// best one is refitted to the points of its face: cheaper evidence than a
// second, precise vote.

#ifndef CGAL_RRHT_INTERNAL_NEIGHBOR_PLANES_H
#define CGAL_RRHT_INTERNAL_NEIGHBOR_PLANES_H

#include <CGAL/RRHT/internal/outer_product.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The thresholds of the neighbors' planes, chosen on the benchmark's noisy
/// CAD parts (the cube, gear, drilled block and finned part; 100k points,
/// 0.2% noise, k = 100).
struct Neighbor_planes_thresholds
{
  /// Hypotheses within 5 degrees (this cosine) of one already kept are left
  /// out: the refit places the plane more closely than that.
  static constexpr double cos_distinct = 0.99619469809174553;
  /// A point at the distance d of a plane scores 1 - (d / b)^2 where d < b,
  /// the band: `band_noise` noise deviations of the scan, or, on a cloud
  /// with next to no noise, `band_radius` times the neighborhood's radius.
  static constexpr double band_noise = 3;
  static constexpr double band_radius = 0.01;
  /// The best plane is refitted this many times, each on its points within
  /// the band, weighted by Tukey's biweight.
  static constexpr int refits = 3;
  /// It is taken where its points score at least `strong` of the
  /// neighborhood, without a vote: on one face, next to another.
  static constexpr double strong = 0.85;
  /// Elsewhere, where it is within 5 degrees (this cosine) of the normal of
  /// the Hough transform's cheap stage: the vote found the same face, which
  /// the fit on all its points places better than a second vote would.
  static constexpr double cos_agree = 0.99619469809174553;
  /// ... and where the quadric of the whole neighborhood misses its points
  /// by at least `crease` times the radius (root mean square): across a
  /// crease. Below that, the neighborhood is a sheet too curved for the
  /// quadric, or a mild feature, where a neighbor's plane is turned from
  /// the point's own by the curvature between them and the second vote is
  /// nearer.
  static constexpr double crease = 0.1;
};

/// The band of the planes at a point whose neighborhood has the radius
/// `radius` in a scan whose noise deviation there is `noise` (lengths).
inline double plane_band(double noise, double radius)
{
  typedef Neighbor_planes_thresholds T;
  return (std::max)(T::band_noise * noise, T::band_radius * radius);
}

/// The scores of the planes through the point of unit normals `normals`,
/// in `scores`: for each, the sum, over the neighbors `points` (relative to
/// the point), of 1 - (d / `band`)^2 where their distance d to the plane is
/// below the band, in the order of the points. The points are the outer
/// loop, so that the sums of the planes advance side by side, in a loop
/// that the compiler vectorizes, rather than each waiting on its last
/// addition; `distances` holds a point's distances to the planes.
inline void plane_scores(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                         double band, std::vector<double>& distances, std::vector<double>& scores)
{
  const double inverse = 1 / (band * band);
  const std::size_t planes = normals.size();
  distances.resize(planes);
  scores.assign(planes, 0.);
  double* const d = distances.data();
  double* const score = scores.data();
  for(const Eigen::Vector3d& p : points)
  {
    for(std::size_t k = 0; k < planes; ++k)
      d[k] = normals[k].dot(p);
    for(std::size_t k = 0; k < planes; ++k)
      score[k] += (std::max)(0., 1 - d[k] * d[k] * inverse);
  }
}

/// The working memory of `best_neighbor_plane()` and
/// `refit_neighbor_plane()`, reused from point to point.
struct Neighbor_planes_scratch
{
  std::vector<Eigen::Vector3d> distinct; // the distinct planes of the neighbors
  std::vector<double> distances;         // a point's distances to them
  std::vector<double> scores;            // their scores
  std::vector<double> weights;           // the weights of the points in a refit
};

/// A plane hypothesis and the share of the neighborhood it scores.
struct Scored_plane
{
  Eigen::Vector3d normal; // the null vector where there was no hypothesis
  double share;
};

/// The best scored (`plane_scores()`) of the planes through the point whose
/// normals are the unit vectors `normal_of(j)` of the neighbors j in
/// `neighbors` where `use(j)`, nearest first, those within
/// `Neighbor_planes_thresholds::cos_distinct` of one before left out
/// (`scratch.distinct` holds the others); the first of the best, if several are.
template <typename Neighbors, typename Use, typename Normal_of>
Scored_plane best_neighbor_plane(const std::vector<Eigen::Vector3d>& points, const Neighbors& neighbors, Use use,
                                 Normal_of normal_of, double band, Neighbor_planes_scratch& scratch)
{
  std::vector<Eigen::Vector3d>& distinct = scratch.distinct;
  distinct.clear();
  for(auto j : neighbors)
  {
    if(!use(j))
      continue;
    const Eigen::Vector3d n = normal_of(j);
    if(std::none_of(distinct.begin(), distinct.end(), [&](const Eigen::Vector3d& d) {
         return std::abs(d.dot(n)) > Neighbor_planes_thresholds::cos_distinct;
       }))
      distinct.push_back(n);
  }
  plane_scores(points, distinct, band, scratch.distances, scratch.scores);
  Scored_plane best{ Eigen::Vector3d::Zero(), 0. };
  double best_score = -1;
  for(std::size_t k = 0; k < distinct.size(); ++k)
    if(scratch.scores[k] > best_score)
      best_score = scratch.scores[k], best.normal = distinct[k];
  if(!points.empty() && best_score > 0)
    best.share = best_score / double(points.size());
  return best;
}

/// The normal of the plane `normal` (through the point) refitted to the
/// neighbors `points` (relative to the point) within `band` of it,
/// `Neighbor_planes_thresholds::refits` times: the smallest principal axis
/// of their covariance weighted by Tukey's biweight (1 - (d / band)^2)^2,
/// about their weighted mean, which the next distances are taken from. The
/// null vector where no point lies within the band.
inline Eigen::Vector3d refit_neighbor_plane(const std::vector<Eigen::Vector3d>& points, Eigen::Vector3d normal,
                                            double band, Neighbor_planes_scratch& scratch)
{
  const double inverse = 1 / (band * band);
  std::vector<double>& weights = scratch.weights;
  weights.resize(points.size());
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for(int refit = 0; refit < Neighbor_planes_thresholds::refits; ++refit)
  {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    double sum = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const double d = normal.dot(points[i] - center), u = 1 - d * d * inverse;
      const double w = u > 0 ? u * u : 0.;
      weights[i] = w;
      mean += w * points[i], sum += w;
    }
    if(!(sum > 0))
      return Eigen::Vector3d::Zero();
    mean /= sum;
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const Eigen::Vector3d q = points[i] - mean;
      add_outer_product(covariance, weights[i] * q, q);
    }
    normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(0);
    center = mean;
  }
  return normal.allFinite() ? normal : Eigen::Vector3d::Zero();
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NEIGHBOR_PLANES_H
