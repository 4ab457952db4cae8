// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal at one point (paper, Section 2): n_rot runs of the Hough
// transform on its neighborhood, in randomly rotated accumulators
// (Section 4), with the sampling of Section 5.

#ifndef CGAL_RRHT_INTERNAL_ESTIMATE_NORMAL_H
#define CGAL_RRHT_INTERNAL_ESTIMATE_NORMAL_H

#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Scratch.h>
#include <CGAL/RRHT/internal/Settings.h>
#include <CGAL/RRHT/internal/adaptive.h>
#include <CGAL/RRHT/internal/aggregate.h>
#include <CGAL/RRHT/internal/confidence.h>
#include <CGAL/RRHT/internal/hough_transform.h>
#include <CGAL/RRHT/internal/rotate.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// A unit normal and its confidence in [0, 1] (`confidence()`), or the zero
/// vector and 0 where no plane could be formed.
struct Estimated_normal
{
  Eigen::Vector3d normal;
  double confidence;
};

/// The normal of a neighborhood from n_rot randomly rotated accumulators
/// (Section 4): each run sees the points rotated, its normal is rotated back,
/// and the normals are aggregated.
template <typename Sampler>
Estimated_normal rotated_hough_transforms(const Neighborhood& neighborhood, Sampler& sampler, Random& rng,
                                         const Settings& settings, Scratch& scratch)
{
  const std::vector<Eigen::Vector3d>& points = neighborhood.points;
  scratch.candidates.clear();
  scratch.rotated.resize(points.size());
  for(unsigned int r = 0; r < settings.number_of_rotations; ++r)
  {
    // Rotated and scaled to the unit ball: normals do not depend on the
    // scale, and single precision keeps its relative accuracy.
    const Eigen::Matrix3d rotation = rng.uniform_rotation();
    rotate(points, rotation / neighborhood.radius, scratch.rotated, best_instruction_set());
    Candidate_normal candidate = hough_transform(scratch.rotated, sampler, rng, settings, scratch);
    candidate.normal = rotation.transpose() * candidate.normal; // back to the frame of the cloud
    scratch.candidates.push_back(candidate);
  }
  const Eigen::Vector3d normal = aggregate(scratch.candidates, settings.aggregation, settings.cos_cluster_angle);
  return Estimated_normal{ normal, confidence(scratch.candidates, normal, settings.cos_cluster_angle) };
}

/// The normal of the neighborhood in `scratch.neighborhood`, of the point
/// whose id is `id`, with `settings` (Section 2): draws plane hypotheses with
/// n_rot randomly rotated accumulators and combines their winners.
inline Estimated_normal estimate_normal_of_neighborhood(std::uint64_t id, const Settings& settings, Scratch& scratch)
{
  const Neighborhood& neighborhood = scratch.neighborhood;
  const std::vector<Eigen::Vector3d>& points = neighborhood.points;
  // One random stream per point, keyed by its id: the same normals whatever
  // the threads, and whatever part of the cloud holds its neighborhood.
  Random rng(settings.seed, id);

  switch(settings.sampling)
  {
  case Sampling::CUBES:
    scratch.cubes.prepare(points, neighborhood.radius);
    return rotated_hough_transforms(neighborhood, scratch.cubes, rng, settings, scratch);
  case Sampling::UNIF:
    scratch.unif.prepare(points, neighborhood.radius, rng);
    return rotated_hough_transforms(neighborhood, scratch.unif, rng, settings, scratch);
  case Sampling::POINTS:
  default:
    scratch.points.prepare(std::uint32_t(points.size()), settings.number_of_planes);
    return rotated_hough_transforms(neighborhood, scratch.points, rng, settings, scratch);
  }
}

/// The adaptive setting's normal of the neighborhood in
/// `scratch.neighborhood`, of the point whose id is `id`, whose normal with
/// the cheap stage is `cheap` (`Adaptive_stages`).
inline Estimated_normal recheck(std::uint64_t id, const Estimated_normal& cheap, const Adaptive_stages& stages,
                                Scratch& scratch)
{
  if(cheap.confidence >= Adaptive_stages::recheck_below)
    return cheap;
  if(cheap.confidence >= Adaptive_stages::spatial_below)
    return estimate_normal_of_neighborhood(id, stages.precise, scratch);
  // Spatial drawing sharpens the votes along a sharp feature, whose two
  // sides have uneven densities. Where its votes agree less than the cheap
  // ones, it drew the outliers or the heavy noise that fill the ball, and
  // the precise normal drawn among the points wins if its votes agree more.
  const Estimated_normal spatial = estimate_normal_of_neighborhood(id, stages.spatial, scratch);
  if(spatial.confidence >= cheap.confidence)
    return spatial;
  const Estimated_normal precise = estimate_normal_of_neighborhood(id, stages.precise, scratch);
  return precise.confidence > spatial.confidence ? precise : spatial;
}

/// The normal of the neighborhood in `scratch.neighborhood`, of the point
/// whose id is `id`: with `settings`, or, if `stages` is not null, with the
/// adaptive setting (`Adaptive_stages`). Returns the zero vector when no
/// plane can be formed.
inline Estimated_normal estimate_normal_of_found(std::uint64_t id, const Settings& settings, Scratch& scratch,
                                                 const Adaptive_stages* stages = nullptr)
{
  const Neighborhood& neighborhood = scratch.neighborhood;
  // Fewer than 3 distinct points, or a ball too small or too large to
  // compute on.
  if(neighborhood.points.size() < 3 || !has_computable_radius(neighborhood.radius))
    return Estimated_normal{ Eigen::Vector3d::Zero(), 0. };
  if(stages == nullptr)
    return estimate_normal_of_neighborhood(id, settings, scratch);
  return recheck(id, estimate_normal_of_neighborhood(id, stages->cheap, scratch), *stages, scratch);
}

/// The normal at the point at `position` in the search's order, as
/// `estimate_normal_of_found()` does on its neighborhood.
inline Estimated_normal estimate_normal(std::size_t position, const Neighbor_search& search,
                                        const Settings& settings, Scratch& scratch,
                                        const Adaptive_stages* stages = nullptr)
{
  search.find(position, settings.k, settings.neighbor_radius, scratch.neighborhood, scratch.search);
  return estimate_normal_of_found(search.id(position), settings, scratch, stages);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ESTIMATE_NORMAL_H
