// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// When to stop drawing planes (paper, Section 3).

#ifndef CGAL_RRHT_STOPPING_RULES_H
#define CGAL_RRHT_STOPPING_RULES_H

#include <algorithm>
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

/// The least number d >= 1 of further votes after which the test of eq. 10
/// can hold, when it does not hold now: a vote raises one bin by one, so it
/// widens the gap between the two most voted bins by at most one, and the
/// test fails until (gap + d)^2 >= 4 (number_of_planes + d), that is until
///   d >= 2 - gap + 2 sqrt(1 - gap + number_of_planes).
/// Testing only after that many votes stops at the same vote as testing
/// after every vote (RRHT draws in batches of that size).
inline std::size_t votes_before_intervals_can_be_disjoint(std::size_t votes_first, std::size_t votes_second,
                                                          std::size_t number_of_planes)
{
  const std::size_t gap = votes_first > votes_second ? votes_first - votes_second : 0;
  const double root = 2. - double(gap) + 2. * std::sqrt((std::max)(0., 1. - double(gap) + double(number_of_planes)));
  std::size_t d = root > 1 ? static_cast<std::size_t>(root) : 1;
  auto can_hold = [&](std::size_t votes) {
    return (gap + votes) * (gap + votes) >= 4 * (number_of_planes + votes);
  };
  while(d > 1 && can_hold(d - 1)) // the square root was rounded up
    --d;
  while(!can_hold(d))             // or down
    ++d;
  return d;
}

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_STOPPING_RULES_H
