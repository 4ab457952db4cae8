// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the passes of `CGAL::rrht_estimate_normals()` over the cloud share:
// the cloud, the parameters, the per-thread memory, and where the results go.
// The results go through functions, so that the passes are compiled once
// whatever the input's range and property maps.

#ifndef CGAL_RRHT_INTERNAL_PASS_CONTEXT_H
#define CGAL_RRHT_INTERNAL_PASS_CONTEXT_H

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Scratch.h>
#include <CGAL/RRHT/internal/Settings.h>

#include <Eigen/Core>

#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Where the results of the point at a position of the search go: its
/// normal, its confidence and the radius of its support.
struct Pass_output
{
  std::function<void(std::size_t, const Eigen::Vector3d&)> normal;
  std::function<void(std::size_t, double)> confidence;
  std::function<void(std::size_t, double)> support;
};

/// The cloud and the parameters of the passes.
struct Pass_context
{
  const Neighbor_search& search;
  const Settings& settings;
  const Bin_layout& layout;
  const Cube_weights& cube_weights;
  const std::vector<bool>& neighbor_only; // by position in the input; empty: every point is estimated
  bool whole_cloud;                        // at most k points: every neighborhood is the whole cloud
  Pass_output output;

  /// A thread's working memory.
  Scratch make_scratch() const { return Scratch(layout, cube_weights, settings.presampling_factor); }

  /// Whether the normal of the point at position `i` is estimated and written
  /// (not for the points that are only neighbors).
  bool estimated(std::size_t i) const { return neighbor_only.empty() || !neighbor_only[search.input_index(i)]; }

  /// The radius of the ball that holds a neighborhood: infinite where it is
  /// the whole cloud, or where a k-neighborhood found fewer points than asked.
  double support_of(const Neighborhood& neighborhood) const
  {
    return whole_cloud || !neighborhood.complete ? std::numeric_limits<double>::infinity() : neighborhood.radius;
  }
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PASS_CONTEXT_H
