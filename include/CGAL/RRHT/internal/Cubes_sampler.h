// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Cubes (paper, Section 5): points drawn spatially uniformly in the
// neighborhood ball B_P through the small cubes that cover it.

#ifndef CGAL_RRHT_INTERNAL_CUBES_SAMPLER_H
#define CGAL_RRHT_INTERNAL_CUBES_SAMPLER_H

#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>
#include <CGAL/RRHT/internal/Weighted_points_sampler.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// RRHT_Cubes: pick one of the c^3 small cubes covering the ball with a
/// probability proportional to its weight, among those holding points (the
/// same as picking among all and picking again an empty one), then a point
/// of that cube uniformly.
///
/// That is a fixed distribution over the neighbors: a point of cube C is
/// drawn with probability w(C) / (W |C|), W being the total weight of the
/// cubes that hold points and |C| the number of points of C. The points are
/// drawn with these probabilities by `Weighted_points_sampler` (Walker's
/// alias method over the points: one table read per point drawn). The cube
/// of each point is found without sorting the points by cube.
class Cubes_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the triples are the same
  /// with each, see `Instruction_set.h`).
  explicit Cubes_sampler(const Cube_weights& weights, Instruction_set instruction_set = best_instruction_set())
    : m_weights(&weights), m_points(instruction_set)
  {}

  void prepare(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    const std::uint32_t n = std::uint32_t(points.size());
    const unsigned int c = m_weights->cubes_per_axis();
    if(m_points_in_cube.empty())
      m_points_in_cube.assign(std::size_t(c) * c * c, 0);

    // The cube of each point, and the number of points of each cube.
    m_cube_of_point.resize(n);
    const double to_cubes = c / (2 * radius), last = c - 1;
    for(std::uint32_t i = 0; i < n; ++i)
    {
      std::uint32_t cube = 0;
      for(int d = 0; d < 3; ++d)
      {
        // Clamped to the cubes, then truncated: the floor of a number >= 0.
        const double x = (points[i][d] + radius) * to_cubes;
        cube = cube * c + std::uint32_t((std::min)((std::max)(x, 0.), last));
      }
      m_cube_of_point[i] = cube;
      ++m_points_in_cube[cube];
    }

    // The probability of each point, times n (a mean of 1): w(C) / (W |C|).
    double total = 0;
    for(std::size_t cube = 0; cube < m_points_in_cube.size(); ++cube)
      total += m_points_in_cube[cube] != 0 ? m_weights->weight(cube) : 0.;
    m_scaled.resize(n);
    for(std::uint32_t i = 0; i < n; ++i)
    {
      const std::uint32_t cube = m_cube_of_point[i];
      m_scaled[i] = m_weights->weight(cube) / (total * m_points_in_cube[cube]) * n;
    }
    for(std::uint32_t cube : m_cube_of_point)
      m_points_in_cube[cube] = 0;
    m_points.prepare(m_scaled);
  }

  void start_run() {}

  /// Writes `count` triples of distinct points to `out`; returns `count`.
  std::size_t draw(Random& rng, std::size_t count, Triple* out) { return m_points.draw(rng, count, out); }

  /// One point (for `draw_distinct_triple()`): the draw of `draw()`.
  std::uint32_t draw_point(Random& rng) { return m_points.draw_point(rng); }

private:
  const Cube_weights* m_weights;
  std::vector<std::uint32_t> m_cube_of_point;
  std::vector<std::uint32_t> m_points_in_cube; // per cube: 0 between neighborhoods
  std::vector<double> m_scaled;                // probabilities times n
  Weighted_points_sampler m_points;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CUBES_SAMPLER_H
