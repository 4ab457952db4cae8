// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// When to stop drawing planes before T_R: the confidence intervals of the
// two most voted bins (paper, Section 3, eq. 9 and 10).

#ifndef CGAL_RRHT_INTERNAL_CONFIDENCE_INTERVALS_H
#define CGAL_RRHT_INTERNAL_CONFIDENCE_INTERVALS_H

#include <cstddef>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Confidence interval test (eq. 10): after `number_of_planes` planes, of
/// which `votes_first` went to the most voted bin and `votes_second` to the
/// second one, their 95% confidence intervals (eq. 9, z(r) = 2) are disjoint:
///   votes_first / T - votes_second / T >= 2 sqrt(1 / T),
/// evaluated exactly in integers as (votes_first - votes_second)^2 >= 4 T.
inline bool confidence_intervals_are_disjoint(std::size_t votes_first, std::size_t votes_second,
                                              std::size_t number_of_planes)
{
  if(number_of_planes == 0 || votes_first <= votes_second)
    return false;
  const std::size_t gap = votes_first - votes_second;
  return gap * gap >= 4 * number_of_planes;
}

/// Whether eq. 10 can hold when the most voted bin has `votes_first` of
/// `number_of_planes` votes: not while votes_first < 2 sqrt(T), since
///   (votes_first - votes_second)^2 <= votes_first^2 < 4 T.
inline bool confidence_intervals_can_be_disjoint(std::size_t votes_first, std::size_t number_of_planes)
{
  return votes_first * votes_first >= 4 * number_of_planes;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CONFIDENCE_INTERVALS_H
