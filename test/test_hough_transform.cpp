// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Hough transform near a sharp edge (paper, Section 2): the neighborhood
// of a point near, but not on, an edge is split by the edge in two planar
// parts, the part of the point's side being the larger. A triple drawn on the
// point's side gives its normal, a triple on the other side the other normal,
// a triple across the edge a plane that is spread over many bins: the
// point's normal has the most votes as soon as its side holds more of the
// neighbors than the other one (a^3 > (1 - a)^3 with a the share on its
// side).

#include <CGAL/RRHT/hoeffding_number_of_planes.h>
#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Points_sampler.h>
#include <CGAL/RRHT/internal/Scratch.h>
#include <CGAL/RRHT/internal/Settings.h>
#include <CGAL/RRHT/internal/estimate_normal.h>
#include <CGAL/RRHT/internal/hough_transform.h>

#include "components.h"

#include <Eigen/Geometry>

#include <CGAL/Random.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace {

const double degrees = 180. / 3.14159265358979323846;

// Unoriented angle between two directions, in degrees.
double angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  const double norm = a.norm() * b.norm();
  if(!(norm > 0))
    return 90;
  return std::acos((std::min)(1., std::abs(a.dot(b)) / norm)) * degrees;
}

// A dihedral edge of 90 degrees: the half-planes A = {z = 0, y >= 0}
// (normal e_z) and B = {y = 0, z >= 0} (normal e_y) meet along the x axis.
// The query point P = (0, d, 0) is on A at distance d from the edge; its
// neighborhood is P itself, `on_a` points drawn uniformly on A and `on_b` on
// B, all in the unit ball around P (a ball of uniform density gives about
// 60% of its points to A for d = 0.3, 53% for d = 0.1). The points are
// relative to P (as `Neighborhood` gives them) and turned by a fixed generic
// rotation, so that neither normal is on a bin border of the accumulator.
struct Edge_neighborhood
{
  std::vector<Eigen::Vector3d> points; // P (the origin) first
  Eigen::Vector3d normal_a, normal_b, bisector;
};

Edge_neighborhood edge_neighborhood(double d, int on_a, int on_b, std::uint64_t seed)
{
  const Eigen::Matrix3d rotation =
    (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) * Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
  Random rng(seed, 1);
  Edge_neighborhood n;
  n.points.push_back(Eigen::Vector3d::Zero());
  auto add = [&](int count, bool side_a) {
    for(int i = 0; i < count;)
    {
      const double x = 2 * rng.uniform_real() - 1, s = 2 * rng.uniform_real(); // s >= 0 off the edge
      const Eigen::Vector3d p = side_a ? Eigen::Vector3d(x, s - d, 0) : Eigen::Vector3d(x, -d, s);
      if(p.squaredNorm() <= 1)
      {
        n.points.push_back(rotation * p);
        ++i;
      }
    }
  };
  add(on_a, true);
  add(on_b, false);
  n.normal_a = rotation * Eigen::Vector3d::UnitZ();
  n.normal_b = rotation * Eigen::Vector3d::UnitY();
  n.bisector = (n.normal_a + n.normal_b).normalized();
  return n;
}

// The default settings of `CGAL::rrht_estimate_normals()` (T_R = 691,
// eq. 10, RRHT_Points, 5 rotations, clustering at 45 degrees), for a
// k-neighborhood of `k` neighbors.
Settings default_settings(const Bin_layout& layout, unsigned int k, std::uint64_t seed)
{
  Settings s;
  s.k = k;
  s.neighbor_radius = 0;
  s.number_of_planes = hoeffding_number_of_planes(layout.size());
  s.use_confidence_interval = true;
  s.sampling = Sampling::POINTS;
  s.presampling_factor = 4;
  s.number_of_rotations = 5;
  s.aggregation = Aggregation::CLUSTER;
  s.cos_cluster_angle = std::cos(45. / degrees);
  s.seed = seed;
  return s;
}

// What one run of the Hough transform (no rotation, RRHT_Points, the
// default T_R and eq. 10) finds on the neighborhood, over `runs` random
// streams: how many runs give a normal within `tolerance` degrees of
// `expected`, and the largest angle of those.
struct Runs
{
  int within = 0;
  double worst = 0;
};

Runs one_run(const Edge_neighborhood& n, const Eigen::Vector3d& expected, int runs, double tolerance)
{
  const Bin_layout layout(15);
  const Cube_weights cube_weights(1);
  Scratch scratch(layout, cube_weights, 4);
  const Settings settings = default_settings(layout, unsigned(n.points.size() - 1), 0);
  std::vector<Eigen::Vector3f> points;
  for(const Eigen::Vector3d& p : n.points)
    points.push_back(p.cast<float>());
  Points_sampler sampler;
  sampler.prepare(std::uint32_t(points.size()), settings.number_of_planes);
  Runs result;
  for(int run = 0; run < runs; ++run)
  {
    Random rng(42, std::uint64_t(run));
    const Candidate_normal c = hough_transform(points, sampler, rng, settings, scratch);
    const double a = angle(c.normal, expected);
    if(a < tolerance)
    {
      ++result.within;
      result.worst = (std::max)(result.worst, a);
    }
  }
  return result;
}

// `internal::estimate_normal()` at P (n_rot = 5 rotated runs, clustered),
// whose k-neighborhood is the whole configuration, for `seeds` seeds: the
// largest angle between the normal found and `expected`.
double worst_angle_of_estimate_normal(const Edge_neighborhood& n, const Eigen::Vector3d& expected, Sampling sampling,
                                      int seeds)
{
  std::vector<Neighbor_search::Point> cloud;
  for(std::size_t i = 0; i < n.points.size(); ++i)
    cloud.emplace_back(n.points[i].x(), n.points[i].y(), n.points[i].z());
  const Neighbor_search search(std::move(cloud), CGAL::Sequential_tag());
  std::size_t position = 0; // of P (input index 0) in the search's order
  while(search.input_index(position) != 0)
    ++position;
  const Bin_layout layout(15);
  const Cube_weights cube_weights(4);
  Scratch scratch(layout, cube_weights, 4);
  double worst = 0;
  for(int seed = 0; seed < seeds; ++seed)
  {
    Settings settings = default_settings(layout, unsigned(n.points.size() - 1), std::uint64_t(seed));
    settings.sampling = sampling;
    const Eigen::Vector3d normal = estimate_normal(position, search, settings, scratch).normal;
    worst = (std::max)(worst, angle(normal, expected));
  }
  return worst;
}

} // namespace

// The bin of the winning plane is about 12 degrees wide; its mean normal is
// that of the triples drawn on P's side, moved a little by the few triples
// across the edge that fall in the same bin (up to 2.2 degrees measured
// over 1000 runs). The bisector of the edge is 45 degrees away, the other
// side 90.
TEST_CASE("Hough transform near an edge: P's side, with 60% of the neighbors, wins", "[hough_transform]")
{
  // P at 0.3 from the edge, in a ball of radius 1 sampled uniformly: 60
  // neighbors on its side, 40 across the edge. Triples on P's side:
  // 0.6^3 = 22% of the draws; on the other side: 6%; across: 72%, spread.
  const Edge_neighborhood n = edge_neighborhood(0.3, 60, 40, 1);
  REQUIRE(angle(n.normal_a, n.normal_b) == Approx(90).margin(1e-9));
  REQUIRE(angle(n.normal_a, n.bisector) == Approx(45).margin(1e-9));

  const Runs runs = one_run(n, n.normal_a, 100, 4);
  WARN("one run, 100 random streams: " << runs.within << " within 4 degrees of P's normal, worst "
                                       << runs.worst << " degrees");
  CHECK(runs.within == 100);

  const double points = worst_angle_of_estimate_normal(n, n.normal_a, Sampling::POINTS, 20);
  const double cubes = worst_angle_of_estimate_normal(n, n.normal_a, Sampling::CUBES, 20);
  const double unif = worst_angle_of_estimate_normal(n, n.normal_a, Sampling::UNIF, 20);
  WARN("estimate_normal, 20 seeds: worst angle to P's normal " << points << " (Points), " << cubes << " (Cubes), "
                                                                << unif << " (Unif) degrees");
  CHECK(points < 3);
  CHECK(cubes < 3);
  CHECK(unif < 3);
}

// "When P is very close to the edge, drawn triples are likely to lie on both
// sides of the edge. However, as it leads to a random normal, the correct
// normal still is the one with the highest probability" (Section 2).
TEST_CASE("Hough transform very near an edge: P's side, with 53% of the neighbors, still wins", "[hough_transform]")
{
  // P at 0.1 from the edge: 53 neighbors on its side, 47 across. Triples on
  // its side: 14.9% of the draws, on the other side 10.4%: a single run
  // picks the other side now and then (0 to 13 runs in 1000 measured), the
  // 5 rotated runs of estimate_normal() outvote it.
  const Edge_neighborhood n = edge_neighborhood(0.1, 53, 47, 2);
  const Runs runs = one_run(n, n.normal_a, 1000, 4);
  WARN("one run, 1000 random streams: " << runs.within << " within 4 degrees of P's normal, worst "
                                        << runs.worst << " degrees");
  CHECK(runs.within >= 950);
  CHECK(runs.worst < 4);

  const double points = worst_angle_of_estimate_normal(n, n.normal_a, Sampling::POINTS, 100);
  WARN("estimate_normal, 100 seeds: worst angle to P's normal " << points << " degrees");
  CHECK(points < 3);
}

// The counter-test: with RRHT_Points, what decides is which side holds
// more neighbors, not where P is: with 40% of the neighbors on P's side
// (the other side 2.3 times as dense), the other side's normal wins.
// RRHT_Cubes and RRHT_Unif draw points uniformly in the ball, not among the
// neighbors (Section 5): for them P's side is still the larger one (its area
// in the ball is 2.16 against 1.43), and its normal wins.
TEST_CASE("Hough transform near an edge: with RRHT_Points, the side with fewer neighbors loses", "[hough_transform]")
{
  const Edge_neighborhood n = edge_neighborhood(0.3, 40, 60, 3);
  CHECK(one_run(n, n.normal_b, 100, 4).within == 100);
  CHECK(one_run(n, n.normal_a, 100, 4).within == 0);
  CHECK(worst_angle_of_estimate_normal(n, n.normal_b, Sampling::POINTS, 20) < 3);
  CHECK(worst_angle_of_estimate_normal(n, n.normal_a, Sampling::CUBES, 20) < 3);
  CHECK(worst_angle_of_estimate_normal(n, n.normal_a, Sampling::UNIF, 20) < 3);
}

namespace {

// The neighborhoods of Neighbor_search, found by going through all the
// points: the input positions of the k + 1 nearest to `query` (or, with
// `radius` > 0 and k = 0, of all within it), in order of squared distance
// (as CGAL's distance computes it), then of id, and the distance to the
// last one.
std::pair<std::vector<std::size_t>, double> neighbors_by_all_points(const std::vector<Neighbor_search::Point>& points,
                                                                    const std::vector<std::uint64_t>& ids,
                                                                    std::size_t query, unsigned int k, double radius)
{
  const Neighbor_search::Point& q = points[query];
  std::vector<std::tuple<double, std::uint64_t, std::size_t> > all;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    double d = CGAL::square(q.x() - points[i].x());
    d += CGAL::square(q.y() - points[i].y());
    d += CGAL::square(q.z() - points[i].z());
    if(radius == 0 || d <= radius * radius)
      all.emplace_back(d, ids[i], i);
  }
  std::sort(all.begin(), all.end());
  if(radius == 0 && all.size() > std::size_t(k) + 1)
    all.resize(std::size_t(k) + 1);
  std::vector<std::size_t> positions;
  for(const auto& neighbor : all)
    positions.push_back(std::get<2>(neighbor));
  return std::make_pair(positions, radius > 0 ? radius : std::sqrt(std::get<0>(all.back())));
}

} // namespace

// A k-neighborhood is first looked for in a ball a little wider than the
// previous query's, and the ball of a radius search is collected from the
// tree without CGAL's search: both give the neighborhoods of all the points,
// ties at the last distance settled by the ids, whatever order the queries
// come in.
TEST_CASE("Neighbor search: the k nearest and the points in a ball, ties settled by the ids, in any order of queries",
          "[neighbor_search]")
{
  CGAL::Random random(5);
  std::vector<Neighbor_search::Point> noisy, grid, duplicated, clusters;
  // The faces of a unit cube, a little noisy.
  for(int i = 0; i < 2000; ++i)
  {
    double c[3] = { random.get_double(), random.get_double(), random.get_double() };
    c[i % 3] = (i % 2) + 0.004 * (random.get_double() - 0.5);
    noisy.emplace_back(c[0], c[1], c[2]);
  }
  // A folded grid: many neighbors at the same distance, the last one too.
  for(int i = 0; i < 40; ++i)
    for(int j = 0; j < 40; ++j)
      grid.emplace_back(0.1 * i, 0.1 * j, i > 20 ? 0.05 * (i - 20) : 0.);
  // Points given three times, and two clusters of very different densities:
  // consecutive queries with neighborhoods of very different radii.
  for(int i = 0; i < 600; ++i)
  {
    const Neighbor_search::Point p(random.get_double(), random.get_double(), random.get_double());
    for(int copy = 0; copy < 3; ++copy)
      duplicated.push_back(p);
    clusters.emplace_back(random.get_double(), random.get_double(), 0.);
    clusters.emplace_back(5 + 0.01 * random.get_double(), 0.01 * random.get_double(), 0.01 * random.get_double());
  }
  for(const std::vector<Neighbor_search::Point>* cloud : { &noisy, &grid, &duplicated, &clusters })
  {
    const std::vector<Neighbor_search::Point>& points = *cloud;
    const std::size_t n = points.size();
    // Ids in another order than the positions, so that they, not the
    // positions, settle the ties.
    std::vector<std::uint64_t> ids(n);
    for(std::size_t i = 0; i < n; ++i)
      ids[i] = (i * 7919) % n;
    std::vector<std::uint32_t> input(n);
    std::iota(input.begin(), input.end(), std::uint32_t(0));
    const Neighbor_search search(std::vector<Neighbor_search::Point>(points), std::move(input), ids,
                                 CGAL::Sequential_tag());
    // Queries along the curve, as the passes make them, then in a random
    // order; one scratch for all, with k changing.
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::vector<std::size_t> shuffled = order;
    std::shuffle(shuffled.begin(), shuffled.end(), std::mt19937(7));
    Neighbor_search::Scratch scratch;
    Neighborhood found;
    std::size_t checked = 0;
    for(const std::vector<std::size_t>* queries : { &order, &shuffled })
      for(unsigned int k : { 1u, 12u, 40u })
        for(std::size_t j = 0; j < n; j += (queries == &order ? 1 : 3))
        {
          const std::size_t at = (*queries)[j];
          search.find(at, k, 0., found, scratch);
          const auto expected = neighbors_by_all_points(points, ids, search.input_index(at), k, 0.);
          std::vector<std::size_t> positions;
          for(std::size_t position : found.positions)
            positions.push_back(search.input_index(position));
          INFO("cloud of " << n << " points, k = " << k << ", query " << at);
          REQUIRE(positions == expected.first);
          REQUIRE(found.radius == expected.second);
          ++checked;
        }
    // A query far from the previous one, in the other cluster: the ball
    // that surely holds enough holds the whole cloud, and is given up.
    if(cloud == &clusters)
    {
      std::size_t in_square = 0, in_cube = 0;
      while(search.point(in_square).x() > 1)
        ++in_square;
      while(search.point(in_cube).x() < 4)
        ++in_cube;
      Neighbor_search::Scratch fresh;
      for(std::size_t at : { in_cube, in_square })
      {
        search.find(at, 1, 0., found, fresh);
        std::vector<std::size_t> positions;
        for(std::size_t position : found.positions)
          positions.push_back(search.input_index(position));
        REQUIRE(positions == neighbors_by_all_points(points, ids, search.input_index(at), 1, 0.).first);
      }
      CHECK(fresh.ball.capacity() < n / 2);
    }
    // Balls, of radii that hold from a few points to a few dozen.
    for(double radius : { 0.03, 0.12 })
      for(std::size_t at = 0; at < n; at += 5)
      {
        search.find(at, 0, radius, found, scratch);
        const auto expected = neighbors_by_all_points(points, ids, search.input_index(at), 0, radius);
        if(expected.first.size() < 3)
          continue; // the k nearest instead, as above
        std::vector<std::size_t> positions;
        for(std::size_t position : found.positions)
          positions.push_back(search.input_index(position));
        INFO("cloud of " << n << " points, ball of radius " << radius << ", query " << at);
        REQUIRE(positions == expected.first);
        REQUIRE(found.radius == radius);
        ++checked;
      }
    CHECK(checked > n * 3);
  }
}
