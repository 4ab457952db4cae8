// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The support of a refitted normal: the ball around the point that holds
// every point the refit read, for `support_radius_map`.

#ifndef CGAL_RRHT_INTERNAL_SUPPORT_RADIUS_H
#define CGAL_RRHT_INTERNAL_SUPPORT_RADIUS_H

#include <CGAL/RRHT/internal/Neighbor_search.h>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The radius of the ball centered on a point that holds the neighborhoods
/// of all its neighbors (`neighborhood`, relative to the point): the refit
/// reads the noise estimated in each of them. `radii` holds the radius of
/// each point's neighborhood, by position in the search's order.
inline double support_radius(const Neighborhood& neighborhood, const std::vector<double>& radii)
{
  double support = 0;
  for(std::size_t j = 0; j < neighborhood.points.size(); ++j)
    support = (std::max)(support, neighborhood.points[j].norm() + radii[neighborhood.positions[j]]);
  return support;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SUPPORT_RADIUS_H
