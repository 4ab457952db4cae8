// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Points: triples drawn uniformly among the neighbors, never twice in a run.

#include <CGAL/RRHT/internal/Points_sampler.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("RRHT_Points never draws the same triple twice in a run", "[sampling]")
{
  Points_sampler sampler;
  Random rng(3, 4);
  SECTION("more triples than draws: the filtered list of drawn triples")
  {
    sampler.prepare(30, 1000); // C(30,3) = 4060 > 1000
    for(int run = 0; run < 3; ++run)
    {
      sampler.start_run();
      std::set<Triple> seen;
      Triple t;
      for(int i = 0; i < 1000; ++i)
      {
        REQUIRE(sampler.draw(rng, 1, &t) == 1);
        REQUIRE(t[0] < t[1]);
        REQUIRE(t[1] < t[2]);
        REQUIRE(t[2] < 30);
        REQUIRE(seen.insert(t).second);
      }
    }
  }
  SECTION("large neighborhoods (the draw with Random::uniform_index), batches")
  {
    const std::uint32_t n = 5000;
    sampler.prepare(n, 2000);
    std::vector<int> uses(n, 0);
    for(int run = 0; run < 100; ++run)
    {
      sampler.start_run();
      std::set<Triple> seen;
      Triple batch[64];
      for(int drawn = 0; drawn < 2000; drawn += 50)
      {
        REQUIRE(sampler.draw(rng, 50, batch) == 50);
        for(int i = 0; i < 50; ++i)
        {
          REQUIRE(batch[i][0] < batch[i][1]);
          REQUIRE(batch[i][1] < batch[i][2]);
          REQUIRE(batch[i][2] < n);
          REQUIRE(seen.insert(batch[i]).second);
          for(std::uint32_t p : batch[i])
            ++uses[p];
        }
      }
    }
    // Each point is in a triple with probability 3 / n: 120 times expected.
    for(std::uint32_t p = 0; p < n; ++p)
      REQUIRE(std::abs(uses[p] - 120) < 6 * std::sqrt(120.) + 1);
  }
  SECTION("every triple equally likely (the vectorized draw of small neighborhoods)")
  {
    // C(12,3) = 220 triples, 100 per run: each is in a run with probability 100 / 220.
    std::map<Triple, int> runs_with;
    const int runs = 2000;
    for(int run = 0; run < runs; ++run)
    {
      sampler.prepare(12, 100);
      sampler.start_run();
      Triple batch[100];
      REQUIRE(sampler.draw(rng, 100, batch) == 100);
      for(const Triple& t : batch)
        ++runs_with[t];
    }
    REQUIRE(runs_with.size() == 220);
    const double expected = runs * 100. / 220., deviation = std::sqrt(runs * (100. / 220.) * (120. / 220.));
    for(const auto& triple_and_runs : runs_with)
      REQUIRE(std::abs(triple_and_runs.second - expected) < 6 * deviation);
  }
  SECTION("fewer triples than draws: each triple once, then the run ends")
  {
    sampler.prepare(10, 1000); // C(10,3) = 120
    sampler.start_run();
    std::set<Triple> seen;
    Triple batch[50];
    std::size_t got = 0;
    while((got = sampler.draw(rng, 50, batch)) > 0) // batches of 50, 50, then 20
      for(std::size_t i = 0; i < got; ++i)
        REQUIRE(seen.insert(batch[i]).second);
    CHECK(seen.size() == 120);
    sampler.start_run();
    CHECK(sampler.draw(rng, 1, batch) == 1); // a new run starts over
  }
}
