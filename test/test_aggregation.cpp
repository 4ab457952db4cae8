// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Combining the normals of the rotated accumulators: mean, best, cluster;
// and the confidence of the result.

#include <CGAL/RRHT/Aggregation.h>
#include <CGAL/RRHT/internal/aggregate.h>
#include <CGAL/RRHT/internal/confidence.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("Aggregation: mean, best and cluster", "[aggregation]")
{
  const Eigen::Vector3d z(0, 0, 1), x(1, 0, 0);
  const Eigen::Vector3d z10 = Eigen::Vector3d(std::sin(0.17), 0, std::cos(0.17)); // ~10 degrees from z
  const std::vector<Candidate_normal> candidates = { { x, 50, 100 }, { z, 30, 100 }, { -z10, 30, 100 }, { Eigen::Vector3d::Zero(), 0, 0 } };
  const double cos45 = std::cos(CGAL_PI / 4);

  CHECK(aggregate(candidates, Aggregation::BEST, cos45) == x);
  // The z cluster (60 votes) beats x (50); its mean lies between z and z10.
  const Eigen::Vector3d c = aggregate(candidates, Aggregation::CLUSTER, cos45);
  CHECK(std::abs(c.dot((z + z10).normalized())) == Approx(1).epsilon(1e-12));
  // The mean mixes everything, weighted by votes, signs aligned.
  const Eigen::Vector3d m = aggregate(candidates, Aggregation::MEAN, cos45);
  CHECK(m.norm() == Approx(1));
  CHECK(std::abs(m.dot(x)) > 0.5);
  CHECK(std::abs(m.dot(z)) > 0.5);
  // No run voted: the zero vector.
  CHECK(aggregate({ { Eigen::Vector3d::Zero(), 0, 0 } }, Aggregation::CLUSTER, cos45) == Eigen::Vector3d::Zero());
}

TEST_CASE("Confidence: the share of all votes won by bins that agree with the normal", "[aggregation][confidence]")
{
  const Eigen::Vector3d z(0, 0, 1), x(1, 0, 0);
  const Eigen::Vector3d z10 = Eigen::Vector3d(std::sin(0.17), 0, std::cos(0.17));
  const std::vector<Candidate_normal> candidates = { { x, 50, 100 }, { z, 30, 100 }, { -z10, 30, 100 }, { Eigen::Vector3d::Zero(), 0, 0 } };
  const double cos45 = std::cos(CGAL_PI / 4);

  // The z cluster: its two runs' winning bins took 60 of the 300 votes.
  const Eigen::Vector3d c = aggregate(candidates, Aggregation::CLUSTER, cos45);
  CHECK(confidence(candidates, c, cos45) == Approx(60. / 300));
  // The best run alone agrees with x; z and z10 are 80 degrees away.
  CHECK(confidence(candidates, x, cos45) == Approx(50. / 300));
  // a_cluster = 0: the run whose normal is returned still counts.
  CHECK(confidence(candidates, aggregate(candidates, Aggregation::BEST, 1.), 1.) == Approx(50. / 300));
  // Every winning bin agrees: the share of the winners.
  CHECK(confidence({ { z, 80, 100 }, { -z10, 90, 100 } }, z, cos45) == Approx(170. / 200));
  // No vote: 0.
  CHECK(confidence({ { Eigen::Vector3d::Zero(), 0, 0 } }, Eigen::Vector3d::Zero(), cos45) == 0);
}
