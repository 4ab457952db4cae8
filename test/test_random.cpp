// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The per-point random streams.

#include <CGAL/RRHT/internal/Random.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("Random streams depend only on the seed and the stream number", "[random]")
{
  Random a(42, 17), b(42, 17), c(42, 18), d(43, 17);
  const auto x = a();
  CHECK(x == b());
  CHECK(x != c());
  CHECK(x != d());
  // discard(n) moves the stream as n draws do.
  for(std::uint64_t n : { 0u, 1u, 63u, 1000u })
  {
    Random drawn(5, 9), discarded(5, 9);
    for(std::uint64_t i = 0; i < n; ++i)
      drawn();
    discarded.discard(n);
    CHECK(drawn() == discarded());
  }
  // Uniform indices are unbiased and in range.
  Random rng(1, 2);
  std::vector<int> counts(7, 0);
  for(int i = 0; i < 70000; ++i)
  {
    const std::uint32_t k = rng.uniform_index(7);
    REQUIRE(k < 7);
    ++counts[k];
  }
  for(int c7 : counts)
    CHECK(std::abs(c7 - 10000) < 500);
  // Rotations are rotations, and spread uniformly: the mean of R e_z vanishes.
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for(int i = 0; i < 20000; ++i)
  {
    const Eigen::Matrix3d r = rng.uniform_rotation();
    REQUIRE((r * r.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-12);
    REQUIRE(r.determinant() == Approx(1).epsilon(1e-12));
    mean += r.col(2);
  }
  CHECK((mean / 20000).norm() < 0.03);
}
