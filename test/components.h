// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the tests of the components of the algorithm share.

#ifndef RRHT_TEST_COMPONENTS_H
#define RRHT_TEST_COMPONENTS_H

#include <CGAL/RRHT/internal/Random.h>

#include <CGAL/number_type_config.h>

#include <catch2/catch.hpp>

#include <Eigen/Core>

using namespace CGAL::RRHT;
using namespace CGAL::RRHT::internal;

namespace rrht_test {
// A direction drawn uniformly on the unit sphere.
inline Eigen::Vector3d random_direction(Random& rng)
{
  Eigen::Vector3d v;
  do
    v = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1);
  while(v.squaredNorm() > 1 || v.squaredNorm() < 1e-6);
  return v.normalized();
}
} // namespace rrht_test
using rrht_test::random_direction;

#endif // RRHT_TEST_COMPONENTS_H
