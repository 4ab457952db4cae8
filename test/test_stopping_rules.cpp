// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// When to stop drawing planes: eq. 7 and eq. 10.

#include <CGAL/RRHT/hoeffding_number_of_planes.h>
#include <CGAL/RRHT/internal/confidence_intervals.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("Eq. 7: the Hoeffding bound on the number of planes", "[stopping]")
{
  // ln(2 * 171 / 0.05) / (2 * 0.08^2) = 8.8306 / 0.0128 = 689.9
  CHECK(hoeffding_number_of_planes(171, 0.95, 0.08) == 690);
  CHECK(hoeffding_number_of_planes(172) == 691);
  // ln(2 * 100 / 0.1) / (2 * 0.1^2) = 7.6009 / 0.02 = 380.05
  CHECK(hoeffding_number_of_planes(100, 0.9, 0.1) == 381);
  CHECK_THROWS_AS(hoeffding_number_of_planes(0), std::invalid_argument);
  CHECK_THROWS_AS(hoeffding_number_of_planes(10, 1.0, 0.1), std::invalid_argument);
  CHECK_THROWS_AS(hoeffding_number_of_planes(10, 0.9, 0.0), std::invalid_argument);
}

TEST_CASE("Eq. 10: disjoint confidence intervals of the two most voted bins", "[stopping]")
{
  // p1 - p2 >= 2 / sqrt(T)
  CHECK(confidence_intervals_are_disjoint(4, 0, 4));     // 1 - 0 >= 2 / 2
  CHECK(!confidence_intervals_are_disjoint(3, 0, 4));    // 0.75 < 1
  CHECK(confidence_intervals_are_disjoint(60, 20, 100)); // 0.4 >= 0.2
  CHECK(!confidence_intervals_are_disjoint(39, 20, 100));// 0.19 < 0.2
  CHECK(confidence_intervals_are_disjoint(40, 20, 100)); // 0.2 >= 0.2
  CHECK(!confidence_intervals_are_disjoint(20, 20, 100));
  CHECK(!confidence_intervals_are_disjoint(0, 0, 0));
}

TEST_CASE("Eq. 10 cannot hold while the most voted bin has fewer than 2 sqrt(T) votes", "[stopping]")
{
  // Exhaustively for small counts: whenever the test holds, the necessary
  // condition the accumulator waits for holds too, and it is tight (one
  // bin with all the votes passes the test as soon as it holds).
  for(std::size_t votes = 0; votes <= 300; ++votes)
  {
    for(std::size_t first = 0; first <= votes; ++first)
      for(std::size_t second = 0; second <= (std::min)(first, votes - first); ++second)
        if(confidence_intervals_are_disjoint(first, second, votes))
        {
          INFO(first << " " << second << " of " << votes);
          REQUIRE(confidence_intervals_can_be_disjoint(first, votes));
        }
    if(votes > 0)
      REQUIRE(confidence_intervals_can_be_disjoint(votes, votes) == confidence_intervals_are_disjoint(votes, 0, votes));
  }
  CHECK(!confidence_intervals_can_be_disjoint(34, 300)); // 34^2 = 1156 < 1200
  CHECK(confidence_intervals_can_be_disjoint(35, 300));  // 1225 >= 1200
}
