// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The paper's estimation, point by point (Section 2), and, beyond the paper,
// the least-squares refit of each of its normals: what
// `CGAL::rrht_estimate_normals()` runs without least squares first.

#ifndef CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_PASSES_H
#define CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_PASSES_H

#include <CGAL/RRHT/internal/Pass_context.h>
#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/adaptive.h>
#include <CGAL/RRHT/internal/estimate_normal.h>
#include <CGAL/RRHT/internal/for_each_block.h>
#include <CGAL/RRHT/internal/refit_normal.h>
#include <CGAL/RRHT/internal/support_radius.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// At each point, the planes through random triples of its neighbors vote
/// in n_rot randomly rotated accumulators, and the normals of their most
/// voted bins are combined (`estimate_normal()`), with the context's
/// settings or the adaptive `stages`. Points are processed along the
/// Hilbert curve, each with the random stream of its id. With `refit`, a
/// second pass refits each normal by least squares, with the noise
/// deviation of its cleanest neighbors (`refit_normal()`).
template <typename ConcurrencyTag>
void hough_transform_passes(const Pass_context& context, const Adaptive_stages* stages, bool refit,
                            bool with_supports, Progress& progress)
{
  const Neighbor_search& search = context.search;
  const Settings& settings = context.settings;
  const Pass_output& output = context.output;
  const std::size_t size = search.size();
  auto make_scratch = [&context]() { return context.make_scratch(); };

  // With `refit`, each normal is kept, with the noise deviation estimated
  // around it (and the radius of its neighborhood, for the supports), for
  // the second pass.
  std::vector<Eigen::Vector3d> normals(refit ? size : 0);
  std::vector<double> noise(refit ? size : 0);
  std::vector<double> radii(refit && with_supports ? size : 0);

  auto estimate = [&](std::size_t begin, std::size_t end, Scratch& scratch) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const bool written = context.estimated(i);
      if(!written && !refit)
        continue;
      const Estimated_normal e = estimate_normal(i, search, settings, scratch, stages);
      if(written)
      {
        output.normal(i, e.normal);
        output.confidence(i, e.confidence);
      }
      if(!refit)
        output.support(i, context.support_of(scratch.neighborhood));
      else if(with_supports)
        radii[i] = context.support_of(scratch.neighborhood);
      if(refit)
      {
        normals[i] = e.normal;
        noise[i] = e.normal == Eigen::Vector3d::Zero()
                     ? std::numeric_limits<double>::infinity()
                     : fit_one_sheet(scratch.neighborhood.points, scratch.neighborhood.radius, e.normal, -1,
                                     scratch.refit).noise;
      }
    }
  };

  auto refit_normals = [&](std::size_t begin, std::size_t end, Scratch& scratch) {
    for(std::size_t i = begin; i < end; ++i)
    {
      if(!context.estimated(i))
        continue;
      if(normals[i] == Eigen::Vector3d::Zero())
      {
        if(with_supports)
          output.support(i, radii[i]);
        continue;
      }
      Neighborhood& neighborhood = scratch.neighborhood;
      search.find(i, settings.k, settings.neighbor_radius, neighborhood, scratch.search);
      if(with_supports)
        output.support(i, support_radius(neighborhood, radii));
      const double deviation = noise_of_neighbors(neighborhood.positions, noise, scratch.refit.work);
      if(!std::isfinite(deviation))
        continue;
      const Eigen::Vector3d refitted =
        refit_normal(neighborhood.points, neighborhood.radius, normals[i], deviation, scratch.refit);
      if(refitted != Eigen::Vector3d::Zero())
        output.normal(i, refitted);
    }
  };

  for_each_block<ConcurrencyTag>(size, progress, make_scratch, estimate);
  if(refit)
    for_each_block<ConcurrencyTag>(size, progress, make_scratch, refit_normals);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_HOUGH_TRANSFORM_PASSES_H
