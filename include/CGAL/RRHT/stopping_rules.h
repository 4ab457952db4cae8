// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// When to stop drawing planes (paper, Section 3).

#ifndef CGAL_RRHT_STOPPING_RULES_H
#define CGAL_RRHT_STOPPING_RULES_H

#include <cmath>
#include <cstddef>
#include <stdexcept>

namespace CGAL {
namespace RRHT {

/// Global upper bound T_R on the number of planes to draw (eq. 7): the least
/// T such that, with probability at least `alpha`, the empirical vote share
/// of every one of the `number_of_bins` bins is within `delta` of its
/// probability (Hoeffding's inequality and a union bound over the bins):
///   T_R = ceil( ln(2 M / (1 - alpha)) / (2 delta^2) ).
/// With alpha = 0.95, delta = 0.08 and M = 171 it gives 690; the paper rounds
/// it to 700 (Section 6).
inline std::size_t hoeffding_number_of_planes(std::size_t number_of_bins, double alpha = 0.95, double delta = 0.08)
{
  if(number_of_bins == 0 || !(alpha > 0 && alpha < 1) || !(delta > 0 && delta < 1))
    throw std::invalid_argument("CGAL::RRHT::hoeffding_number_of_planes(): needs M > 0, 0 < alpha < 1 and 0 < delta < 1");
  return static_cast<std::size_t>(std::ceil(std::log(2. * number_of_bins / (1. - alpha)) / (2. * delta * delta)));
}

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

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_STOPPING_RULES_H
