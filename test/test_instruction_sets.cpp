// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The loops compiled for AVX2 against the baseline ones, bit for bit.

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Cubes_sampler.h>
#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Plane_batch.h>
#include <CGAL/RRHT/internal/Points_sampler.h>
#include <CGAL/RRHT/internal/Unif_sampler.h>
#include <CGAL/RRHT/internal/rotate.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

TEST_CASE("The AVX2 loops give the same planes and triples as the baseline ones, bit for bit", "[accumulator][sampling]")
{
  if(best_instruction_set() != Instruction_set::avx2)
  {
    WARN("SKIPPED: this build or processor has no AVX2 loops (CGAL_RRHT_AVX2_KERNELS = " << CGAL_RRHT_AVX2_KERNELS
         << "): nothing to compare");
    return;
  }
  Random rng(14, 0);
  std::vector<Eigen::Vector3f> points;
  for(int i = 0; i < 101; ++i)
    points.push_back(random_direction(rng).cast<float>() * float(rng.uniform_real()));
  points.emplace_back(0.f, 0.f, 0.f); // with half of point 1 and point 1: a collinear triple
  points.emplace_back(points[1] * 0.5f);
  Plane_batch baseline(Instruction_set::baseline), avx2(Instruction_set::avx2);
  std::size_t compared = 0;
  for(unsigned int slices : { 1u, 6u, 15u, 25u })
  {
    const Bin_layout layout(slices);
    for(int round = 0; round < 200; ++round)
    {
      // Every count, so that every tail of the vectorized loops is run.
      const std::size_t count = 1 + std::size_t(round) % Plane_batch::capacity;
      std::vector<Triple> triples;
      for(std::size_t i = 0; i < count; ++i)
        triples.push_back(Triple{{ rng.uniform_index(103), rng.uniform_index(103), rng.uniform_index(103) }});
      triples.back() = Triple{{ 101, 102, 1 }};
      baseline.compute(points, triples.data(), count, layout);
      avx2.compute(points, triples.data(), count, layout);
      for(std::size_t i = 0; i < count; ++i)
      {
        INFO("n_phi = " << slices << ", plane " << i << " of " << count);
        REQUIRE(baseline.bin(i) == avx2.bin(i));
        if(baseline.bin(i) != Plane_batch::no_plane) // else no normal
        {
          REQUIRE(baseline.normal(i) == avx2.normal(i));
          ++compared;
        }
      }
    }
  }
  CHECK(compared > 20000);
  for(std::uint32_t n : { 5u, 20u, 30u, 101u, 4096u }) // listed, bitmap, filter; C(20,3) = 1140, C(30,3) = 4060
  {
    Points_sampler baseline_sampler(Instruction_set::baseline), avx2_sampler(Instruction_set::avx2);
    baseline_sampler.prepare(n, 300);
    avx2_sampler.prepare(n, 300);
    Random baseline_rng(15, n), avx2_rng(15, n);
    for(int run = 0; run < 20; ++run)
    {
      baseline_sampler.start_run();
      avx2_sampler.start_run();
      Triple baseline_triples[64], avx2_triples[64];
      for(std::size_t drawn = 0, count = 1; drawn < 300; drawn += count, count = count % 64 + 7)
      {
        const std::size_t wanted = (std::min)(count, std::size_t(300) - drawn);
        const std::size_t got = baseline_sampler.draw(baseline_rng, wanted, baseline_triples);
        REQUIRE(avx2_sampler.draw(avx2_rng, wanted, avx2_triples) == got);
        for(std::size_t i = 0; i < got; ++i)
        {
          INFO("n = " << n << ", run " << run << ", triple " << drawn + i);
          REQUIRE(baseline_triples[i] == avx2_triples[i]);
        }
      }
    }
  }
  // RRHT_Cubes, batches of every size up to two chunks.
  {
    std::vector<Eigen::Vector3d> neighborhood;
    for(int i = 0; i < 150; ++i)
      neighborhood.push_back(random_direction(rng) * rng.uniform_real());
    const Cube_weights weights(4);
    Cubes_sampler baseline_sampler(weights, Instruction_set::baseline), avx2_sampler(weights, Instruction_set::avx2);
    baseline_sampler.prepare(neighborhood, 1.);
    avx2_sampler.prepare(neighborhood, 1.);
    Random baseline_rng(17, 4), avx2_rng(17, 4);
    std::vector<Triple> baseline_triples(130), avx2_triples(130);
    for(std::size_t count = 1; count <= 130; ++count)
    {
      REQUIRE(baseline_sampler.draw(baseline_rng, count, baseline_triples.data()) == count);
      REQUIRE(avx2_sampler.draw(avx2_rng, count, avx2_triples.data()) == count);
      for(std::size_t i = 0; i < count; ++i)
      {
        INFO("RRHT_Cubes, batch of " << count << ", triple " << i);
        REQUIRE(baseline_triples[i] == avx2_triples[i]);
      }
    }
  }
  // RRHT_Unif: its probabilities come from loops of each instruction set
  // too (the spans of the lattice), from c = 1 to the largest c.
  for(unsigned int c : { 1u, 2u, 4u, 8u, 32u })
  {
    std::vector<Eigen::Vector3d> neighborhood;
    for(int i = 0; i < 150; ++i)
      neighborhood.push_back(random_direction(rng) * rng.uniform_real());
    Unif_sampler baseline_sampler(c, Instruction_set::baseline), avx2_sampler(c, Instruction_set::avx2);
    Random baseline_rng(16, c), avx2_rng(16, c);
    baseline_sampler.prepare(neighborhood, 1., baseline_rng);
    avx2_sampler.prepare(neighborhood, 1., avx2_rng);
    Triple baseline_triples[64], avx2_triples[64];
    for(int batch = 0; batch < 50; ++batch)
    {
      REQUIRE(baseline_sampler.draw(baseline_rng, 64, baseline_triples) == 64);
      REQUIRE(avx2_sampler.draw(avx2_rng, 64, avx2_triples) == 64);
      for(std::size_t i = 0; i < 64; ++i)
      {
        INFO("RRHT_Unif, c = " << c << ", batch " << batch << ", triple " << i);
        REQUIRE(baseline_triples[i] == avx2_triples[i]);
      }
    }
  }
}

TEST_CASE("The neighborhood rotated into the unit ball: Eigen's product in single precision, with each instruction set", "[instruction-sets]")
{
  Random rng(21, 22);
  std::vector<Eigen::Vector3d> points;
  for(int i = 0; i < 103; ++i) // an odd number: the vectorized loop has a tail
    points.emplace_back(rng.uniform_real() - 0.5, 1e3 * rng.uniform_real(), -1e-3 * rng.uniform_real());
  std::vector<Instruction_set> instruction_sets = { Instruction_set::baseline };
  if(best_instruction_set() == Instruction_set::avx2)
    instruction_sets.push_back(Instruction_set::avx2);
  for(int round = 0; round < 20; ++round)
  {
    const Eigen::Matrix3d matrix = rng.uniform_rotation() / (0.1 + rng.uniform_real());
    for(Instruction_set instruction_set : instruction_sets)
    {
      std::vector<Eigen::Vector3f> rotated(points.size());
      rotate(points, matrix, rotated, instruction_set);
      for(std::size_t i = 0; i < points.size(); ++i)
      {
        INFO("round " << round << ", point " << i << ", instruction set " << int(instruction_set));
        REQUIRE(rotated[i] == (matrix * points[i]).cast<float>().eval());
      }
    }
  }
}
