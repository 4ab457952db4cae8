// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bins of the accumulator (paper, Section 3): their number, areas and lookup.

#include <CGAL/RRHT/internal/Bin_layout.h>

#include "components.h"
#include "reference_bins.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("Accumulator size M is within 15% of the paper's Fig. 4", "[accumulator]")
{
  const std::map<unsigned int, double> figure_4 = { { 5, 23 }, { 10, 82 }, { 15, 171 }, { 20, 290 }, { 25, 441 } };
  for(const auto& entry : figure_4)
  {
    const Bin_layout layout(entry.first);
    INFO("n_phi = " << entry.first << ", M = " << layout.size() << ", paper " << entry.second);
    CHECK(std::abs(layout.size() - entry.second) <= 0.15 * entry.second);
  }
  CHECK(Bin_layout(15).size() == 172); // the documented value for the default
}

TEST_CASE("Accumulator bins have areas within 10% of each other and tile the half sphere", "[accumulator]")
{
  for(unsigned int slices : { 1u, 2u, 3u, 5u, 10u, 15u, 20u, 25u, 40u, 60u })
  {
    const Bin_layout layout(slices);
    double total = 0, smallest = layout.area(0), largest = layout.area(0);
    for(std::size_t b = 0; b < layout.size(); ++b)
    {
      total += layout.area(b);
      smallest = (std::min)(smallest, layout.area(b));
      largest = (std::max)(largest, layout.area(b));
    }
    INFO("n_phi = " << slices);
    CHECK(total == Approx(2 * CGAL_PI).epsilon(1e-12));
    CHECK(smallest / largest >= 0.9);
  }
}

TEST_CASE("Every direction maps to a valid bin, n and -n to the same one", "[accumulator]")
{
  Random rng(7, 0);
  for(unsigned int slices : { 1u, 2u, 5u, 14u, 15u, 25u })
  {
    const Bin_layout layout(slices);
    std::vector<int> hits(layout.size(), 0);
    for(int i = 0; i < 200000; ++i)
    {
      const Eigen::Vector3d n = random_direction(rng);
      const std::size_t b = layout.bin(n);
      REQUIRE(b < layout.size());
      REQUIRE(layout.bin(-n) == b);
      REQUIRE(layout.bin(3.5 * n) == b);
      ++hits[b];
    }
    // Random directions hit every bin in proportion to its area.
    INFO("n_phi = " << slices);
    for(std::size_t b = 0; b < layout.size(); ++b)
    {
      const double expected = 200000 * layout.area(b) / (2 * CGAL_PI);
      CHECK(std::abs(hits[b] - expected) < 6 * std::sqrt(expected) + 1);
    }
  }
  // Directions on the boundaries: poles, equator, axes.
  const Bin_layout layout(15);
  for(const Eigen::Vector3d& n : { Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0),
                                   Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(1, -1, 0),
                                   Eigen::Vector3d(0, 1e-300, -1) })
  {
    REQUIRE(layout.bin(n) < layout.size());
    REQUIRE(layout.bin(n) == layout.bin(-n));
  }
}


TEST_CASE("The bin lookup tables give the bins defined by the angles", "[accumulator]")
{
  Random rng(11, 0);
  for(unsigned int slices : { 1u, 2u, 5u, 14u, 15u, 25u, 100u })
  {
    const Bin_layout layout(slices);
    const Reference_bins reference(layout);
    REQUIRE(reference.first_of_slice.size() == (slices + 1) / 2 + 1);
    for(int i = 0; i < 100000; ++i)
    {
      const Eigen::Vector3d n = random_direction(rng);
      double to_boundary = 0;
      const std::size_t expected = reference.bin(n, to_boundary);
      if(to_boundary < 1e-6)
        continue; // the tables hold single precision boundaries: rounding decides
      INFO("n_phi = " << slices << ", n = " << n.transpose());
      REQUIRE(layout.bin(n) == expected);
    }
  }
}
