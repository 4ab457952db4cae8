// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Cubes and RRHT_Unif: points drawn spatially uniformly in the ball.

#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Cubes_sampler.h>
#include <CGAL/RRHT/internal/Unif_sampler.h>
#include <CGAL/RRHT/internal/Weighted_points_sampler.h>
#include <CGAL/RRHT/internal/draw_distinct_triple.h>

#include "components.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace {
// A dense and a sparse cluster of points in the unit ball: a point-uniform
// draw favors the dense one, a space-uniform draw does not.
std::vector<Eigen::Vector3d> dense_and_sparse()
{
  std::vector<Eigen::Vector3d> points;
  Random rng(5, 5);
  for(int i = 0; i < 900; ++i) // dense: around (-0.5, 0, 0)
    points.emplace_back(-0.5 + 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real());
  for(int i = 0; i < 100; ++i) // sparse: around (0.3, 0, 0)
    points.emplace_back(0.3 + 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real(), 0.2 * rng.uniform_real());
  return points;
}
} // namespace

TEST_CASE("RRHT_Cubes and RRHT_Unif draw points uniformly in space, not among points", "[sampling]")
{
  const std::vector<Eigen::Vector3d> points = dense_and_sparse();
  Random rng(9, 9);
  auto sparse_share = [&](auto& sampler) {
    int sparse = 0;
    for(int i = 0; i < 20000; ++i)
      sparse += (sampler.draw_point(rng) >= 900);
    return sparse / 20000.;
  };
  const Cube_weights weights(4);
  Cubes_sampler cubes(weights);
  cubes.prepare(points, 1.0);
  Unif_sampler unif(4);
  unif.prepare(points, 1.0, rng);
  // Both clusters fill one cube of side 0.5 (resp. similar small-ball
  // volumes), so each gets about half of the draws, against 10% for points.
  CHECK(sparse_share(cubes) == Approx(0.5).margin(0.05));
  CHECK(sparse_share(unif) == Approx(0.5).margin(0.1));

  Triple t = {{ 0, 0, 0 }};
  for(int i = 0; i < 1000; ++i)
  {
    draw_distinct_triple(cubes, 1000, rng, t);
    REQUIRE((t[0] != t[1] && t[1] != t[2] && t[0] != t[2]));
  }
}

TEST_CASE("RRHT_Cubes draws each point with the weight of its cube over the points of the cube", "[sampling]")
{
  // 40 points spread over a few cubes of the unit ball, unevenly: point p of
  // cube C has probability w(C) / (W |C|), W the weight of the cubes that
  // hold points. Each frequency over 10^6 draws is within 6 sigma of it.
  std::vector<Eigen::Vector3d> points;
  Random rng(11, 12);
  for(int i = 0; i < 40; ++i)
  {
    const double spread = (i < 25) ? 0.2 : 0.9; // a dense cluster and sparse points
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(rng.uniform_real(), rng.uniform_real(), rng.uniform_real()) * 2 * spread -
          Eigen::Vector3d::Constant(spread);
    while(p.norm() > 1);
    points.push_back(p);
  }
  const unsigned int c = 4;
  const Cube_weights weights(c);
  Cubes_sampler cubes(weights);
  cubes.prepare(points, 1.0);

  auto cube_of = [&](const Eigen::Vector3d& p) {
    std::size_t index = 0;
    for(int d = 0; d < 3; ++d)
      index = index * c + std::size_t((std::min)(c - 1., std::floor((p[d] + 1) / (2. / c))));
    return index;
  };
  std::map<std::size_t, int> points_of_cube;
  for(const Eigen::Vector3d& p : points)
    ++points_of_cube[cube_of(p)];
  double total = 0;
  for(const auto& cube : points_of_cube)
    total += weights.weight(cube.first);
  REQUIRE(points_of_cube.size() > 5);

  const int draws = 1000000;
  std::vector<int> count(points.size(), 0);
  for(int i = 0; i < draws; ++i)
    ++count[cubes.draw_point(rng)];
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const std::size_t cube = cube_of(points[i]);
    const double probability = weights.weight(cube) / (total * points_of_cube[cube]);
    const double sigma = std::sqrt(draws * probability * (1 - probability));
    INFO("point " << i << " of cube " << cube << ": " << count[i] << " draws, expected " << draws * probability);
    REQUIRE(std::abs(count[i] - draws * probability) <= 6 * sigma);
  }
}

namespace {
// Whether sampler.draw() (prepared for `n` points) gives the triples of
// draw_distinct_triple(): with `orders`, the frequency of each of the 6
// orders of 3 points; else each point's frequency at each place of the
// triple. Over 3 10^5 triples of each, in batches of 1 to 150, each
// frequency within 6 sigma of the other's.
template <typename Sampler>
void require_batches_as_draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng)
{
  const bool orders = (n == 3);
  auto category = [&](const Triple& t, int place) {
    REQUIRE((t[0] != t[1] && t[0] != t[2] && t[1] != t[2]));
    REQUIRE(t[place] < n);
    return orders ? std::size_t(t[0] * 3 + t[1]) : std::size_t(place) * n + t[place];
  };
  const int triples = 300000;
  const std::size_t categories = 3 * std::size_t(n);
  std::vector<int> batches(categories, 0), one_by_one(categories, 0);
  std::vector<Triple> batch(150);
  for(int drawn = 0, count = 1; drawn < triples; drawn += count, count = count % 150 + 1)
  {
    count = (std::min)(count, triples - drawn);
    REQUIRE(sampler.draw(rng, std::size_t(count), batch.data()) == std::size_t(count));
    for(int i = 0; i < count; ++i)
      for(int place = 0; place < (orders ? 1 : 3); ++place)
        ++batches[category(batch[i], place)];
  }
  for(int i = 0; i < triples; ++i)
  {
    Triple t;
    draw_distinct_triple(sampler, n, rng, t);
    for(int place = 0; place < (orders ? 1 : 3); ++place)
      ++one_by_one[category(t, place)];
  }
  std::size_t seen = 0;
  for(std::size_t k = 0; k < categories; ++k)
  {
    const double p = (batches[k] + one_by_one[k]) / (2. * triples);
    const double sigma = std::sqrt(2. * triples * p * (1 - p));
    INFO((orders ? "order " : "place and point ") << k << ": " << batches[k] << " in batches, " << one_by_one[k]
                                                     << " by draw_distinct_triple()");
    REQUIRE(std::abs(batches[k] - one_by_one[k]) <= 6 * sigma + 1);
    seen += (batches[k] > 0);
  }
  CHECK(seen >= (orders ? 6 : categories * 4 / 5));
}

// 40 points of the unit ball, 25 of them in a dense cluster.
std::vector<Eigen::Vector3d> spread_neighborhood(Random& rng)
{
  std::vector<Eigen::Vector3d> points;
  for(int i = 0; i < 40; ++i)
  {
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1) *
          (i < 25 ? 0.3 : 1.);
    while(p.norm() > 1);
    points.push_back(p);
  }
  return points;
}

// 3 points: one near the center, two close to each other at the boundary.
const std::vector<Eigen::Vector3d> concentrated_neighborhood = {
  Eigen::Vector3d(0.1, 0.1, 0.1), Eigen::Vector3d(0.53, 0.53, 0.53), Eigen::Vector3d(0.55, 0.52, 0.54)
};
} // namespace

TEST_CASE("RRHT_Cubes and RRHT_Unif draw their batches of triples as draw_distinct_triple() does", "[sampling]")
{
  // The batches of Weighted_points_sampler::draw(), which both use, take
  // the three draws of a triple from a chunk computed in advance, and go on
  // with draw_point() only when they are not distinct. The triples must
  // have the distribution of draw_distinct_triple(): in a spread
  // neighborhood (few repeats), and in a neighborhood of 3 points where one
  // has almost all the probability (many repeats, and after 64 of them a
  // uniform draw).
  Random rng(19, 20);
  const std::vector<Eigen::Vector3d> spread = spread_neighborhood(rng);
  // RRHT_Cubes: for the 3 points, the cube around the center, of weight
  // 1/64 (the whole cube), and a cube at the boundary of the ball, of
  // weight about 3 10^-5.
  const Cube_weights weights(4);
  for(const std::vector<Eigen::Vector3d>* points : { &spread, &concentrated_neighborhood })
  {
    Cubes_sampler sampler(weights);
    sampler.prepare(*points, 1.);
    require_batches_as_draw_distinct_triple(sampler, std::uint32_t(points->size()), rng);
  }
  // RRHT_Unif, with the probabilities of its lattice: c = 2 and 3 for the
  // 40 points, c = 1 for the 3.
  for(unsigned int c : { 1u, 2u, 3u })
  {
    const std::vector<Eigen::Vector3d>& points = (c == 1) ? concentrated_neighborhood : spread;
    Unif_sampler sampler(c);
    sampler.prepare(points, 1., rng);
    require_batches_as_draw_distinct_triple(sampler, std::uint32_t(points.size()), rng);
  }
}

TEST_CASE("RRHT_Unif draws each point about as often as the paper's procedure does", "[sampling]")
{
  // The paper's procedure, literally (Section 5): a center uniform in the
  // ball B_P (by rejection from its cube), redrawn while the small ball of
  // radius r/c around it holds no point, then a point of the small ball
  // uniformly. Against it, the sampler, whose probabilities come from the
  // midpoint rule over a randomly shifted lattice (`Unif_sampler`): 60
  // points, c = 2 to 5. Over 10^6 draws of each, the total variation
  // distance between their frequencies is below 0.03 (the frequencies
  // alone are about 0.005 apart), and the points drawn uniformly would be
  // more than 0.2 away.
  std::vector<Eigen::Vector3d> points;
  Random rng(17, 18);
  for(int i = 0; i < 60; ++i)
  {
    const double spread = (i < 40) ? 0.25 : 1.; // a dense cluster off center, and sparse points
    Eigen::Vector3d p;
    do
      p = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1) * spread +
          Eigen::Vector3d(i < 40 ? 0.4 : 0., 0., 0.);
    while(p.norm() > 1);
    points.push_back(p);
  }
  const int draws = 1000000;
  for(unsigned int c : { 2u, 3u, 4u, 5u })
  {
    const double small_radius = 1. / c;
    std::vector<int> paper(points.size(), 0), sampler_count(points.size(), 0);
    std::vector<std::uint32_t> in_small_ball;
    for(int d = 0; d < draws; ++d)
    {
      in_small_ball.clear();
      while(in_small_ball.empty())
      {
        Eigen::Vector3d center;
        do
          center = Eigen::Vector3d(2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1, 2 * rng.uniform_real() - 1);
        while(center.squaredNorm() > 1);
        for(std::uint32_t i = 0; i < points.size(); ++i)
          if((points[i] - center).norm() <= small_radius)
            in_small_ball.push_back(i);
      }
      ++paper[in_small_ball[rng.uniform_index(std::uint32_t(in_small_ball.size()))]];
    }
    Unif_sampler sampler(c);
    sampler.prepare(points, 1., rng);
    for(int d = 0; d < draws; ++d)
      ++sampler_count[sampler.draw_point(rng)];
    double distance = 0, uniform_distance = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      distance += std::abs(sampler_count[i] - paper[i]) / (2. * draws);
      uniform_distance += std::abs(double(paper[i]) / draws - 1. / double(points.size())) / 2;
    }
    INFO("c = " << c << ": total variation distance " << distance << ", " << uniform_distance << " for uniform draws");
    CHECK(distance < 0.03);
    CHECK(uniform_distance > 0.2);
  }
}

TEST_CASE("Cube weights are the volume of the cubes inside the ball", "[sampling]")
{
  for(unsigned int c : { 1u, 2u, 4u, 7u })
  {
    const Cube_weights weights(c);
    double volume = 0;
    for(std::size_t i = 0; i < std::size_t(c) * c * c; ++i)
      volume += weights.weight(i) * (8. / (c * c * c));
    INFO("c = " << c);
    CHECK(volume == Approx(4. / 3. * CGAL_PI).epsilon(0.01));
  }
  const Cube_weights four(4);
  CHECK(four.weight((1 * 4 + 1) * 4 + 1) == Approx(1)); // an inner cube
  CHECK(four.weight(0) > 0);                              // a corner cube meets the ball
  CHECK(four.weight(0) < 0.1);
}
