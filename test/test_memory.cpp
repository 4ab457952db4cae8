// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Memory: no allocation per point, and the passes of the defaults streamed
// along the curve.

#include "allocation_counter.h"
#include "shapes.h"

#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/RRHT/internal/neighborhood_passes.h>

#include <catch2/catch.hpp>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

using CGAL::RRHT::Sampling;

TEST_CASE("No allocation per point", "[api][memory]")
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
    // A k-neighborhood is collected from the tree in a ball found from the
    // previous one's; CGAL's Orthogonal_k_neighbor_search, which allocates
    // its queue and a 3-vector, runs only where there is no previous one.
    const double knn = allocations_per_point(30, 0., sampling);
    CHECK(knn <= 0.1);
    // A ball is collected from the tree the same way.
    const double ball = allocations_per_point(0, 0.2, sampling);
    CHECK(ball <= 0.1);
  }
  // The defaults keep the neighbors of a point from its first pass to its
  // third only, in lists reused from point to point: on a cloud of many
  // steps of the Hilbert curve, a list is allocated for few of the points.
  const double lists = allocations_per_point(30, 0., Sampling::POINTS, false, 40000);
  INFO("lists allocated per point " << lists);
  CHECK(lists <= 0.25);
  // Balls vary in size: a reused list grows where its ball holds more points
  // than the last one, yet fewer than once per point.
  CHECK(allocations_per_point(0, 0.2, Sampling::POINTS, false, 40000) <= 0.75);
}

// A curve that folds back on itself: the neighbors of point i are the points
// next to it along the curve and its mirror n - 1 - i, many steps away
// unless it is near the middle.
template <typename ConcurrencyTag>
void check_streamed_passes()
{
  const std::size_t n = 40 * 4096 + 77;
  auto neighbors_of = [&](std::size_t i) {
    std::vector<std::uint32_t> neighbors{ std::uint32_t(i), std::uint32_t(n - 1 - i) };
    if(i > 0)
      neighbors.push_back(std::uint32_t(i - 1));
    if(i + 1 < n)
      neighbors.push_back(std::uint32_t(i + 1));
    return neighbors;
  };
  std::vector<std::atomic<unsigned char> > passes(n);
  for(auto& p : passes)
    p = 0;
  std::atomic<std::size_t> found_again(0), wrong(0);
  struct State
  {
    std::size_t of;
  };
  auto check = [&](std::size_t i, const std::vector<std::uint32_t>& neighbors, const State& state, unsigned char pass) {
    bool ok = neighbors == neighbors_of(i) && state.of == i && passes[i] == pass - 1;
    for(std::uint32_t j : neighbors)
      ok = ok && passes[j] >= pass - 1;
    wrong += !ok;
    passes[i] = pass;
  };
  const std::function<bool(double)> no_callback;
  CGAL::RRHT::internal::Progress progress(no_callback, 3 * n);
  CGAL::RRHT::internal::neighborhood_passes<ConcurrencyTag, State>(
    n, progress, []() { return 0; },
    [&](std::size_t i, std::vector<std::uint32_t>& neighbors, int) {
      ++found_again;
      neighbors = neighbors_of(i);
    },
    [&](std::size_t i, std::vector<std::uint32_t>& neighbors, State& state, int) {
      wrong += passes[i] != 0;
      neighbors = neighbors_of(i);
      state.of = i;
      passes[i] = 1;
    },
    [&](std::size_t i, std::vector<std::uint32_t>& neighbors, State& state, int) { check(i, neighbors, state, 2); },
    [&](std::size_t i, std::vector<std::uint32_t>& neighbors, State& state, int) { check(i, neighbors, state, 3); });
  std::size_t unfinished = 0;
  for(const auto& p : passes)
    unfinished += p != 3;
  CHECK(unfinished == 0);
  CHECK(wrong == 0);
  // The lists of the points whose mirror is far along the curve are let go
  // and found again, at most before each of their two later passes.
  INFO("lists found again " << found_again);
  CHECK(found_again >= n / 4);
  CHECK(found_again <= 2 * n);
}

TEST_CASE("Streamed passes: each after the passes it reads, with the list its first pass found", "[memory]")
{
  check_streamed_passes<CGAL::Sequential_tag>();
  check_streamed_passes<CGAL::Parallel_if_available_tag>();
}
