// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One run of the Robust Randomized Hough Transform (paper, Section 3).

#ifndef CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_H
#define CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_H

#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Scratch.h>
#include <CGAL/RRHT/internal/Settings.h>
#include <CGAL/RRHT/internal/aggregate.h>
#include <CGAL/RRHT/internal/confidence_intervals.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// One run of the Robust Randomized Hough Transform (Section 3): draws planes
/// through triples of `points` until T_R triples have been drawn (eq. 7) or
/// the confidence intervals of the two most voted bins separate (eq. 10), and
/// returns the mean normal of the most voted bin (Section 4). Triples of
/// (nearly) collinear or repeated points define no plane and cast no vote;
/// the paper does not check near-collinearity (Section 2), we only leave out
/// triples whose two edges make an angle below 1e-5 radians, which would
/// give no direction in single precision (see `Plane_batch`).
///
/// Triples are drawn, and their planes computed (`Plane_batch`), in
/// batches; they vote one by one, and eq. 10 is tested after each vote at
/// which it can hold (see `Accumulator`), so the run stops at the same vote
/// as when drawing one triple at a time. A batch is half the votes so far
/// plus 8 (at most `Plane_batch::capacity`, which it is without eq. 10): a run of 300 planes that does not stop early takes 9 batches
/// rather than 20, and a run that stops wastes at most that many planes,
/// drawn and not voted.
template <typename Sampler>
Candidate_normal hough_transform(const std::vector<Eigen::Vector3f>& points, Sampler& sampler, Random& rng,
                                 const Settings& settings, Scratch& scratch)
{
  Accumulator& accumulator = scratch.accumulator;
  accumulator.clear();
  sampler.start_run();
  std::size_t drawn = 0;
  bool stop = false;
  while(!stop && drawn < settings.number_of_planes)
  {
    const std::size_t batch =
      settings.use_confidence_interval ? accumulator.number_of_votes() / 2 + 8 : scratch.triples.size();
    const std::size_t wanted = (std::min)({ settings.number_of_planes - drawn, scratch.triples.size(), batch });
    const std::size_t got = sampler.draw(rng, wanted, scratch.triples.data());
    scratch.planes.compute(points, scratch.triples.data(), got, accumulator.layout());
    accumulator.vote(scratch.planes, got, [&](unsigned int first, unsigned int second, std::size_t votes) {
      return stop = settings.use_confidence_interval && confidence_intervals_are_disjoint(first, second, votes);
    });
    drawn += got;
    stop |= (got < wanted); // every triple of the neighborhood has voted
  }
  return Candidate_normal{ accumulator.normal_of_most_voted_bin(), accumulator.votes_of_most_voted_bin(),
                           accumulator.number_of_votes() };
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_H
