// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The votes of a run of the Hough transform: the two most voted bins, eq. 10.

#include <CGAL/RRHT/internal/Accumulator.h>
#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Plane_batch.h>
#include <CGAL/RRHT/internal/confidence_intervals.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("The accumulator keeps the two most voted bins and the mean normal of the first", "[accumulator]")
{
  const Bin_layout layout(15);
  Accumulator accumulator(layout);
  const Eigen::Vector3d a = Eigen::Vector3d(0.1, 0.2, 1).normalized(), b = Eigen::Vector3d(1, 0.05, 0.1).normalized();
  REQUIRE(layout.bin(a) != layout.bin(b));
  for(int i = 0; i < 5; ++i)
    accumulator.vote(i % 2 ? a : Eigen::Vector3d(-2 * a)); // either sign, any length
  for(int i = 0; i < 3; ++i)
    accumulator.vote(b);
  CHECK(accumulator.number_of_votes() == 8);
  CHECK(accumulator.most_voted_bin() == layout.bin(a));
  CHECK(accumulator.votes_of_most_voted_bin() == 5);
  CHECK(accumulator.votes_of_second_most_voted_bin() == 3);
  CHECK(std::abs(accumulator.normal_of_most_voted_bin().dot(a)) == Approx(1).epsilon(1e-12));
  for(int i = 0; i < 3; ++i)
    accumulator.vote(b);
  CHECK(accumulator.most_voted_bin() == layout.bin(b));
  CHECK(accumulator.votes_of_second_most_voted_bin() == 5);
  accumulator.clear();
  CHECK(accumulator.number_of_votes() == 0);
  CHECK(accumulator.normal_of_most_voted_bin() == Eigen::Vector3d::Zero());
}

namespace {
// Planes given by their bins only, in the interface of Plane_batch.
struct Bins_of_planes
{
  static constexpr std::uint32_t no_plane = Plane_batch::no_plane;
  std::vector<std::uint32_t> bins;
  std::uint32_t bin(std::size_t i) const { return bins[i]; }
  Eigen::Vector3d normal(std::size_t) const { return Eigen::Vector3d(0, 0, 1); }
};
} // namespace

TEST_CASE("The accumulator stops at the vote at which eq. 10 first holds, whatever the batches", "[accumulator]")
{
  // Votes of planes of random bins, skewed towards a few, given in batches
  // of random sizes: the accumulator calls the test at every vote at which
  // it can hold, and its two most voted bins are those of a plain count.
  const Bin_layout layout(15);
  Accumulator accumulator(layout);
  typedef Bins_of_planes Planes;
  Random rng(5, 6);
  std::size_t stopped_early = 0;
  for(int run = 0; run < 300; ++run)
  {
    accumulator.clear();
    std::vector<unsigned int> count(layout.size(), 0);
    const std::uint32_t spread = 2 + rng.uniform_index(40), skew = rng.uniform_index(4); // skew / 8 of the votes to bin 0
    std::size_t votes = 0, stop_at = 0;
    bool stopped = false;
    while(!stopped && votes < 700)
    {
      Planes planes;
      const std::size_t size = 1 + rng.uniform_index(64);
      for(std::size_t i = 0; i < size; ++i)
      {
        const std::uint32_t kind = rng.uniform_index(8);
        planes.bins.push_back(kind == 7 ? Planes::no_plane : kind < skew ? 0 : rng.uniform_index(spread));
      }
      std::size_t tests = 0;
      const std::size_t looked_at = accumulator.vote(planes, size, [&](unsigned int first, unsigned int second, std::size_t n) {
        ++tests;
        return stopped = confidence_intervals_are_disjoint(first, second, n);
      });
      // The same votes, counted plainly.
      for(std::size_t i = 0; i < looked_at; ++i)
      {
        if(planes.bins[i] == Planes::no_plane)
          continue;
        ++count[planes.bins[i]];
        ++votes;
        const unsigned int first = *std::max_element(count.begin(), count.end());
        std::vector<unsigned int> others = count;
        others.erase(std::max_element(others.begin(), others.end()));
        const unsigned int second = *std::max_element(others.begin(), others.end());
        if(stop_at == 0 && confidence_intervals_are_disjoint(first, second, votes))
          stop_at = votes;
      }
      REQUIRE(tests <= looked_at);
      REQUIRE(accumulator.number_of_votes() == votes);
      const unsigned int first = *std::max_element(count.begin(), count.end());
      REQUIRE(accumulator.votes_of_most_voted_bin() == first);
      REQUIRE(count[accumulator.most_voted_bin()] == first);
      std::vector<unsigned int> others = count;
      others.erase(others.begin() + std::ptrdiff_t(accumulator.most_voted_bin()));
      REQUIRE(accumulator.votes_of_second_most_voted_bin() == *std::max_element(others.begin(), others.end()));
    }
    // It stopped exactly at the first vote at which eq. 10 held.
    REQUIRE(stopped == (stop_at != 0));
    if(stopped)
    {
      REQUIRE(votes == stop_at);
      ++stopped_early;
    }
  }
  CHECK(stopped_early > 100); // both outcomes are tested
  CHECK(stopped_early < 250);
}
