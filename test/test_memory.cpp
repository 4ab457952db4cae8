// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Memory: no allocation per point beyond those of CGAL's kd-tree queries.

#include "allocation_counter.h"
#include "shapes.h"

#include <CGAL/rrht_estimate_normals.h>

#include <catch2/catch.hpp>

#include <cstddef>

using CGAL::RRHT::Sampling;

TEST_CASE("No allocation per point but the two of CGAL's k-nearest-neighbor query", "[api][memory]")
{
  if(!RRHT_TEST_COUNTS_ALLOCATIONS)
  {
    WARN("SKIPPED: allocations are not counted under AddressSanitizer");
    return;
  }
  auto allocations_per_point = [](unsigned int k, double radius, Sampling sampling, bool paper = true,
                                  std::size_t n = 2000) {
    auto count = [&](std::size_t n) {
      rrht_test::Cloud cloud = rrht_test::cube(n, 21);
      rrht_test::add_noise(cloud, 0.2, 22);
      const std::size_t before = rrht_test::number_of_allocations();
      CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(
        cloud, k,
        CGAL::RRHT::parameters::point_map(rrht_test::Point_of_sample())
          .normal_map(rrht_test::Normal_of_sample())
          .neighbor_radius(radius)
          .sampling(sampling)
          .least_squares_first(!paper)
          .adaptive(!paper));
      return double(rrht_test::number_of_allocations() - before);
    };
    // Set-up costs cancel out; what is left is the cost of one more point.
    return (count(2 * n) - count(n)) / double(n);
  };
  for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
  {
    INFO("sampling " << int(sampling));
    // Orthogonal_k_neighbor_search allocates its queue and a 3-vector per query.
    const double knn = allocations_per_point(30, 0., sampling);
    CHECK(knn <= 2.1);
    // The ball search through Fuzzy_sphere allocates nothing per query.
    const double ball = allocations_per_point(0, 0.2, sampling);
    CHECK(ball <= 0.1);
  }
  // The defaults keep the neighbors of a point from its first pass to its
  // third only, in lists reused from point to point: on a cloud of many
  // steps of the Hilbert curve, a list is allocated for few of the points.
  const double lists = allocations_per_point(30, 0., Sampling::POINTS, false, 40000) - 2;
  INFO("lists allocated per point " << lists);
  CHECK(lists <= 0.25);
  // Balls vary in size: a reused list grows where its ball holds more points
  // than the last one, yet fewer than once per point.
  CHECK(allocations_per_point(0, 0.2, Sampling::POINTS, false, 40000) <= 0.75);
}
