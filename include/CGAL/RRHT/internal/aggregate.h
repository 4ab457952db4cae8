// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Combining the normals found with the n_rot randomly rotated accumulators
// into one normal (paper, Section 4).

#ifndef CGAL_RRHT_INTERNAL_AGGREGATE_H
#define CGAL_RRHT_INTERNAL_AGGREGATE_H

#include <CGAL/RRHT/Aggregation.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The outcome of one run of the Hough transform: the normal of its most
/// voted bin, the votes of that bin and the votes of all bins.
struct Candidate_normal
{
  Eigen::Vector3d normal;
  std::size_t votes;
  std::size_t all_votes;
};

// Vote-weighted mean of the candidates `members` says to take, each turned to
// agree with `reference` since normals are unoriented.
template <typename Members>
Eigen::Vector3d weighted_mean(const std::vector<Candidate_normal>& candidates,
                              const Eigen::Vector3d& reference, Members members)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < candidates.size(); ++i)
    if(members(i))
    {
      const Eigen::Vector3d& n = candidates[i].normal;
      sum += double(candidates[i].votes) * (n.dot(reference) >= 0 ? n : Eigen::Vector3d(-n));
    }
  const double norm = sum.norm();
  return norm > 0 ? Eigen::Vector3d(sum / norm) : reference;
}
/// Combines the candidates (runs that drew no plane have 0 votes and are
/// ignored) into a unit normal, or the zero vector if no run voted.
/// `cos_cluster_angle` is the cosine of a_cluster, used by `CLUSTER` only:
/// each candidate defines the cluster of the candidates within a_cluster of it
/// (in unoriented angle), the cluster with the most votes wins (the first one
/// on ties) and its vote-weighted mean is returned.
inline Eigen::Vector3d aggregate(const std::vector<Candidate_normal>& candidates, Aggregation aggregation,
                                 double cos_cluster_angle)
{
  std::size_t best = candidates.size();
  for(std::size_t i = 0; i < candidates.size(); ++i)
    if(candidates[i].votes > 0 && (best == candidates.size() || candidates[i].votes > candidates[best].votes))
      best = i;
  if(best == candidates.size())
    return Eigen::Vector3d::Zero();
  const Eigen::Vector3d& best_normal = candidates[best].normal;

  switch(aggregation)
  {
  case Aggregation::BEST:
    return best_normal;
  case Aggregation::MEAN:
    return weighted_mean(candidates, best_normal, [&](std::size_t i) { return candidates[i].votes > 0; });
  case Aggregation::CLUSTER:
  default:
    {
      auto close = [&](std::size_t i, std::size_t j) {
        return candidates[j].votes > 0 && std::abs(candidates[i].normal.dot(candidates[j].normal)) >= cos_cluster_angle;
      };
      std::size_t center = best, center_votes = 0;
      for(std::size_t i = 0; i < candidates.size(); ++i)
      {
        if(candidates[i].votes == 0)
          continue;
        std::size_t votes = 0;
        for(std::size_t j = 0; j < candidates.size(); ++j)
          if(close(i, j))
            votes += candidates[j].votes;
        if(votes > center_votes)
        {
          center = i;
          center_votes = votes;
        }
      }
      return weighted_mean(candidates, candidates[center].normal,
                                     [&](std::size_t j) { return close(center, j); });
    }
  }
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_AGGREGATE_H
