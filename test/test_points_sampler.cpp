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
#include <utility>
#include <vector>

TEST_CASE("RRHT_Points never draws the same triple twice in a run", "[sampling]")
{
  Points_sampler sampler;
  Random rng(3, 4);
  SECTION("listed, with the bitmap and with the Bloom filter")
  {
    // The draw of a run of `draws` triples among C(n,3): listed when C(n,3) <=
    // 4 draws, else drawn again on a repeat, which a bitmap finds when C(n,3) <
    // 256 draws and a Bloom filter otherwise.
    for(const auto& n_and_draws : { std::make_pair(18u, 691u),   // listed: C(18,3) = 816
                                    std::make_pair(30u, 1000u),  // bitmap: C(30,3) = 4060
                                    std::make_pair(200u, 1000u) }) // filter: C(200,3) = 1313400
    {
      const std::uint32_t n = n_and_draws.first, draws = n_and_draws.second;
      INFO("n = " << n << ", " << draws << " draws per run");
      sampler.prepare(n, draws);
      for(int run = 0; run < 3; ++run)
      {
        sampler.start_run();
        std::set<Triple> seen;
        Triple t;
        for(std::uint32_t i = 0; i < draws; ++i)
        {
          REQUIRE(sampler.draw(rng, 1, &t) == 1);
          REQUIRE(t[0] < t[1]);
          REQUIRE(t[1] < t[2]);
          REQUIRE(t[2] < n);
          REQUIRE(seen.insert(t).second);
        }
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
  SECTION("every triple equally likely (listed, and drawn by the vectorized loops of small neighborhoods)")
  {
    // C(12,3) = 220 triples, `draws` per run: each is in a run with
    // probability draws / 220. Listed with 100 draws, with the bitmap with 50.
    for(int draws : { 100, 50 })
    {
      INFO(draws << " draws per run");
      std::map<Triple, int> runs_with;
      const int runs = 2000;
      for(int run = 0; run < runs; ++run)
      {
        sampler.prepare(12, std::size_t(draws));
        sampler.start_run();
        Triple batch[100];
        REQUIRE(sampler.draw(rng, std::size_t(draws), batch) == std::size_t(draws));
        for(int i = 0; i < draws; ++i)
          ++runs_with[batch[i]];
      }
      REQUIRE(runs_with.size() == 220);
      const double p = draws / 220.;
      const double expected = runs * p, deviation = std::sqrt(runs * p * (1 - p));
      for(const auto& triple_and_runs : runs_with)
        REQUIRE(std::abs(triple_and_runs.second - expected) < 6 * deviation);
    }
  }
  SECTION("the bitmap and the Bloom filter draw the same triples")
  {
    // C(60,3) = 34220: under 256 * 134 draws (bitmap), not under 256 * 133 (filter).
    Points_sampler with_bitmap, with_filter;
    with_bitmap.prepare(60, 134);
    with_filter.prepare(60, 133);
    Random bitmap_rng(5, 6), filter_rng(5, 6);
    for(int run = 0; run < 100; ++run) // about 26 repeats drawn again
    {
      with_bitmap.start_run();
      with_filter.start_run();
      Triple from_bitmap[64], from_filter[64];
      for(std::size_t drawn = 0, count = 1; drawn < 133; drawn += count, count = count % 60 + 5)
      {
        count = (std::min)(count, std::size_t(133) - drawn);
        REQUIRE(with_bitmap.draw(bitmap_rng, count, from_bitmap) == count);
        REQUIRE(with_filter.draw(filter_rng, count, from_filter) == count);
        for(std::size_t i = 0; i < count; ++i)
        {
          INFO("run " << run << ", triple " << drawn + i);
          REQUIRE(from_bitmap[i] == from_filter[i]);
        }
      }
    }
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
