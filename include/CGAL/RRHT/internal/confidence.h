// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far to trust the normal at a point, from what its rotated
// accumulators already know, or, where no vote ran, from a few of its
// triples (beyond the paper; measured in
// benchmark/results/confidence/confidence.md).

#ifndef CGAL_RRHT_INTERNAL_CONFIDENCE_H
#define CGAL_RRHT_INTERNAL_CONFIDENCE_H

#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>
#include <CGAL/RRHT/internal/aggregate.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The confidence of `normal`, the aggregate of `candidates`: the share of
/// all the planes that voted at the point, in the n_rot rotated
/// accumulators, that voted for a most voted bin within a_cluster
/// (`cos_cluster_angle`) of `normal`. In [0, 1]; 0 when no plane voted.
///
/// Where one plane holds the neighborhood, most triples are coplanar and
/// vote for the same bin, so the share is high; noise spreads the votes
/// over neighboring bins and lowers it evenly over a cloud. Near an edge,
/// triples across the two sides vote for scattered bins and each side takes
/// only part of the rest, and rotations that disagree lose their votes: the
/// share drops exactly where the most voted bin is least reliable. The
/// winning bin's share predicted errors above 10 degrees better than its
/// lead over the runner-up or the agreement of the rotations alone.
inline double confidence(const std::vector<Candidate_normal>& candidates, const Eigen::Vector3d& normal,
                         double cos_cluster_angle)
{
  // With a_cluster = 0, a rotation whose normal is the returned one up to
  // rounding still agrees.
  const double cos_agreement = (std::min)(cos_cluster_angle, 1 - 1e-9);
  std::size_t agreeing = 0, all = 0;
  for(const Candidate_normal& c : candidates)
  {
    all += c.all_votes;
    if(c.votes > 0 && std::abs(c.normal.dot(normal)) >= cos_agreement)
      agreeing += c.votes;
  }
  return all > 0 ? double(agreeing) / double(all) : 0.;
}

/// The confidence of `normal` (unit) where it was kept without a vote (a
/// least-squares normal), to rank with those of `confidence()`: the share of
/// `number_of_planes` triples of the neighbors `points` (relative to the
/// point), drawn by `sampler` with `rng` as RRHT_Points draws them into the
/// nonempty buffer `triples`, whose plane lies within the cap about `normal`
/// of solid angle 2 pi (1 - `cos_cap`). A vote would measure the share of
/// its most voted bin, at the cost of rotating the points and filling an
/// accumulator; the cap is centered on the normal, where a bin lies
/// anywhere about it, so it is taken larger than a bin
/// (`Least_squares_first_thresholds`) and holds more of the triples.
/// Triples whose edges make an angle below 1e-5 radians define no plane and
/// are not counted, as in a vote (`Plane_batch`'s test, in double
/// precision); 0 where no triple defines a plane.
template <typename Sampler>
double confidence_of_kept_normal(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                                 double cos_cap, std::size_t number_of_planes, Sampler& sampler, Random& rng,
                                 std::vector<Triple>& triples)
{
  const double squared_cos_cap = cos_cap * cos_cap;
  sampler.prepare(std::uint32_t(points.size()), number_of_planes);
  sampler.start_run();
  std::size_t agreeing = 0, planes = 0;
  for(std::size_t drawn = 0, got = 1; drawn < number_of_planes && got > 0; drawn += got)
  {
    got = sampler.draw(rng, (std::min)(number_of_planes - drawn, triples.size()), triples.data());
    for(std::size_t i = 0; i < got; ++i)
    {
      const Eigen::Vector3d& a = points[triples[i][0]];
      const Eigen::Vector3d u = points[triples[i][1]] - a, v = points[triples[i][2]] - a;
      const Eigen::Vector3d n = u.cross(v);
      const double squared_norm = n.squaredNorm(), along = n.dot(normal);
      const bool plane = squared_norm > 1e-10 * u.squaredNorm() * v.squaredNorm();
      planes += plane;
      agreeing += plane && along * along >= squared_cos_cap * squared_norm;
    }
  }
  return planes > 0 ? double(agreeing) / double(planes) : 0.;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CONFIDENCE_H
