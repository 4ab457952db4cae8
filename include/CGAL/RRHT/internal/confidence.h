// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How far to trust the normal at a point, from what its rotated
// accumulators already know (beyond the paper; measured in
// benchmark/results/confidence/confidence.md).

#ifndef CGAL_RRHT_INTERNAL_CONFIDENCE_H
#define CGAL_RRHT_INTERNAL_CONFIDENCE_H

#include <CGAL/RRHT/internal/aggregate.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
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

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CONFIDENCE_H
