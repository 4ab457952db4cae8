// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input's points in double precision, the coordinates that the
// neighborhood search and the estimators work with.

#ifndef CGAL_RRHT_INTERNAL_POINTS_IN_DOUBLE_H
#define CGAL_RRHT_INTERNAL_POINTS_IN_DOUBLE_H

#include <CGAL/RRHT/internal/Elements.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/for_each_block.h>

#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>

#include <cstddef>
#include <functional>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The point of each element of `points`, in the range's order, converted
/// with `CGAL::to_double()`, non-finite coordinates included. Over TBB's
/// threads with `Parallel_tag` when the range's iterators are random access:
/// the conversion is not free with an exact kernel, and the memory is first
/// written by the threads that fill it.
template <typename ConcurrencyTag, typename PointRange, typename PointMap>
std::vector<Neighbor_search::Point> points_in_double(PointRange& points, PointMap point_map)
{
  typedef Neighbor_search::Point Point;
  auto in_double = [&](const auto& element) {
    const auto& p = get(point_map, element);
    return Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
  };
  typedef typename PointRange::iterator Iterator;
  const Iterator begin = points.begin();
  std::vector<Point> out;
  if constexpr(is_random_access<Iterator>)
  {
    // Point's default constructor leaves the coordinates unset: the loop
    // below is the first to touch the vector's memory.
    out.resize(std::size_t(points.end() - begin));
    const std::function<bool(double)> no_callback;
    Progress silent(no_callback, out.size());
    for_each_block<ConcurrencyTag>(
      out.size(), silent, [] { return 0; }, [&](std::size_t first, std::size_t last, int) {
        for(std::size_t i = first; i < last; ++i)
          out[i] = in_double(*(begin + i));
      });
  }
  else
  {
    for(Iterator it = begin; it != points.end(); ++it)
      out.push_back(in_double(*it));
  }
  return out;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_POINTS_IN_DOUBLE_H
