// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Cubes and RRHT_Unif (paper, Section 5): points drawn spatially
// uniformly in the neighborhood ball B_P rather than uniformly among the
// points, so that a densely sampled patch does not outvote a sparse one.

#ifndef CGAL_RRHT_BALL_SAMPLING_H
#define CGAL_RRHT_BALL_SAMPLING_H

#include <CGAL/RRHT/Points_sampling.h>
#include <CGAL/RRHT/Random.h>

#include <Eigen/Core>

#include <algorithm>
#include <initializer_list>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {

/// Draws three distinct points with `sampler.draw_point(rng)`, redrawing a
/// point equal to one already drawn. After 64 failed draws of one point (a
/// neighborhood whose spatial distribution hides all but one or two of its
/// points), that point is drawn uniformly among the others instead.
template <typename Sampler>
void draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng, Triple& t);

/// What RRHT_Cubes and RRHT_Unif share: a run is any number of triples of
/// distinct points, each drawn with `Derived::draw_point()`. The interface
/// is that of `Points_sampler`.
template <typename Derived>
class Ball_sampler
{
public:
  void start_run() {}

  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    Derived& self = static_cast<Derived&>(*this);
    for(std::size_t i = 0; i < count; ++i)
      draw_distinct_triple(self, m_n, rng, out[i]);
    return count;
  }

protected:
  std::uint32_t m_n = 0;
};

template <typename Sampler>
void draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng, Triple& t)
{
  for(int i = 0; i < 3; ++i)
  {
    int attempts = 0;
    for(;;)
    {
      std::uint32_t p = (attempts < 64) ? sampler.draw_point(rng) : rng.uniform_index(n);
      ++attempts;
      if((i > 0 && p == t[0]) || (i > 1 && p == t[1]))
        continue;
      t[i] = p;
      break;
    }
  }
}

/// The points of a neighborhood bucketed in a regular grid of
/// `cells_per_axis`^3 cells covering [-radius, radius]^3 (a counting sort:
/// the points of cell c are `point(i)` for i in `points_in(c)`).
class Grid_of_neighborhood
{
public:
  void build(const std::vector<Eigen::Vector3d>& points, double radius, std::uint32_t cells_per_axis)
  {
    m_cells_per_axis = cells_per_axis;
    m_cell_size = 2 * radius / cells_per_axis;
    m_radius = radius;
    const std::size_t cells = std::size_t(cells_per_axis) * cells_per_axis * cells_per_axis;
    m_first.assign(cells + 1, 0);
    m_cell_of_point.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      m_cell_of_point[i] = cell(points[i]);
      ++m_first[m_cell_of_point[i] + 1];
    }
    for(std::size_t c = 0; c < cells; ++c)
      m_first[c + 1] += m_first[c];
    m_sorted.resize(points.size());
    m_fill.assign(m_first.begin(), m_first.end() - 1);
    for(std::uint32_t i = 0; i < points.size(); ++i)
      m_sorted[m_fill[m_cell_of_point[i]]++] = i;
  }

  /// Coordinate of the cell holding `x` along one axis (clamped to the grid).
  std::uint32_t coordinate(double x) const
  {
    const double c = std::floor((x + m_radius) / m_cell_size);
    return static_cast<std::uint32_t>((std::min)((std::max)(c, 0.), double(m_cells_per_axis - 1)));
  }

  std::size_t cell(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    return (std::size_t(i) * m_cells_per_axis + j) * m_cells_per_axis + k;
  }

  std::size_t cell(const Eigen::Vector3d& p) const
  {
    return cell(coordinate(p.x()), coordinate(p.y()), coordinate(p.z()));
  }

  std::size_t number_of_cells() const { return m_first.size() - 1; }

  /// Positions, in the order of the sort, of the points of cell `c`.
  std::pair<std::uint32_t, std::uint32_t> points_in(std::size_t c) const
  {
    return std::make_pair(m_first[c], m_first[c + 1]);
  }

  /// The index in the neighborhood of the point at position `i` of the sort.
  std::uint32_t point(std::uint32_t i) const { return m_sorted[i]; }

private:
  std::uint32_t m_cells_per_axis = 1;
  double m_cell_size = 1, m_radius = 1;
  std::vector<std::uint32_t> m_first, m_fill, m_sorted;
  std::vector<std::size_t> m_cell_of_point;
};

/// Weights of the c^3 small cubes that cover the ball (paper, Fig. 5): the
/// fraction of each cube's volume inside the ball. They depend on c only
/// (the ball is scaled to the unit ball) and are computed once, by the
/// midpoint rule on m^3 sub-cubes per cube (m = max(8, 128 / c), i.e. 32^3
/// for c = 4). A cube that meets the ball always keeps a positive weight, so
/// that every point of the neighborhood can be drawn.
class Cube_weights
{
public:
  explicit Cube_weights(unsigned int c) : m_c(c), m_weights(std::size_t(c) * c * c, 0.)
  {
    const unsigned int m = (std::max)(8u, 128u / c);
    const double side = 2. / c, sub = side / m;
    for(unsigned int i = 0; i < c; ++i)
      for(unsigned int j = 0; j < c; ++j)
        for(unsigned int k = 0; k < c; ++k)
        {
          const double lo[3] = { -1 + i * side, -1 + j * side, -1 + k * side };
          // Squared distance from the center of the ball to the cube.
          double nearest = 0;
          for(int d = 0; d < 3; ++d)
          {
            const double gap = (std::max)({ lo[d], -(lo[d] + side), 0. });
            nearest += gap * gap;
          }
          if(nearest >= 1)
            continue;
          std::size_t inside = 0;
          for(unsigned int a = 0; a < m; ++a)
            for(unsigned int b = 0; b < m; ++b)
              for(unsigned int e = 0; e < m; ++e)
              {
                const double x = lo[0] + (a + 0.5) * sub, y = lo[1] + (b + 0.5) * sub, z = lo[2] + (e + 0.5) * sub;
                inside += (x * x + y * y + z * z <= 1);
              }
          m_weights[(std::size_t(i) * c + j) * c + k] = (std::max)(double(inside), 0.5) / (double(m) * m * m);
        }
  }

  unsigned int cubes_per_axis() const { return m_c; }
  double weight(std::uint64_t cube) const { return m_weights[cube]; }

private:
  unsigned int m_c;
  std::vector<double> m_weights;
};

/// RRHT_Cubes: pick one of the c^3 small cubes covering the ball with a
/// probability proportional to its weight, among those holding points (the
/// same as picking among all and picking again an empty one), then a point
/// of that cube uniformly.
///
/// That is a fixed distribution over the neighbors: a point of cube C is
/// drawn with probability w(C) / (W |C|), W being the total weight of the
/// cubes that hold points and |C| the number of points of C. It is drawn in
/// constant time with Walker's alias method over the points: one random
/// word gives a point and whether to keep it or take its alias, with one
/// table read. With a binary search over the cumulated weights of the cubes,
/// RRHT_Cubes took 2.4 times as long as RRHT_Points; with an alias table
/// over the cubes and then a uniform point of the cube (two dependent reads
/// and two draws per point), 1.2 to 1.4 times; over the points, the
/// single-thread run at the fast setting on the 100k-point noisy cube takes
/// 2.13 s instead of 2.35 s (RRHT_Points: 1.85 s).
class Cubes_sampler : public Ball_sampler<Cubes_sampler>
{
public:
  explicit Cubes_sampler(const Cube_weights& weights) : m_weights(&weights) {}

  void prepare(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    m_n = std::uint32_t(points.size());
    m_grid.build(points, radius, m_weights->cubes_per_axis());
    double total = 0;
    for(std::size_t c = 0; c < m_grid.number_of_cells(); ++c)
      if(m_grid.points_in(c).first != m_grid.points_in(c).second)
        total += m_weights->weight(c);

    // The probability of each point, times n (a mean of 1).
    m_scaled.resize(m_n);
    for(std::size_t c = 0; c < m_grid.number_of_cells(); ++c)
    {
      const auto range = m_grid.points_in(c);
      for(std::uint32_t e = range.first; e < range.second; ++e)
        m_scaled[m_grid.point(e)] = m_weights->weight(c) / (total * (range.second - range.first)) * m_n;
    }

    // Walker's alias table (Vose's construction): point i is kept with
    // probability `keep` / 2^21, else replaced by its `alias`.
    m_table.resize(m_n);
    m_small.clear();
    m_large.clear();
    for(std::uint32_t i = 0; i < m_n; ++i)
      (m_scaled[i] < 1 ? m_small : m_large).push_back(i);
    while(!m_small.empty() && !m_large.empty())
    {
      const std::uint32_t small = m_small.back(), large = m_large.back();
      m_small.pop_back();
      m_table[small] = Entry{ static_cast<std::uint32_t>(m_scaled[small] * Random::bits21_limit), large };
      m_scaled[large] -= 1 - m_scaled[small];
      if(m_scaled[large] < 1)
      {
        m_large.pop_back();
        m_small.push_back(large);
      }
    }
    for(std::uint32_t i : m_small) // 1 up to rounding
      m_table[i] = Entry{ Random::bits21_limit, i };
    for(std::uint32_t i : m_large)
      m_table[i] = Entry{ Random::bits21_limit, i };
    m_threshold = m_n < Random::bits21_limit ? Random::rejection_threshold21(m_n) : 0;
  }

  /// A point with the alias method: one random word (a 21-bit number for the
  /// point and 21 bits for the choice of its alias), one table read. The
  /// choice is made with a mask: a branch would be mispredicted at random.
  std::uint32_t draw_point(Random& rng)
  {
    for(;;)
    {
      const std::uint64_t word = rng();
      std::uint32_t i;
      if(m_n >= Random::bits21_limit)
        i = rng.uniform_index(m_n);
      else if(!Random::draw21(word, m_n, m_threshold, i))
        continue;
      const Entry entry = m_table[i];
      const std::uint32_t alias_mask = 0u - std::uint32_t(std::uint32_t((word >> 21) & (Random::bits21_limit - 1)) >= entry.keep);
      return (entry.alias & alias_mask) | (i & ~alias_mask);
    }
  }

private:
  // An entry of the alias table: point i is kept with probability
  // keep / 2^21, else its alias is taken.
  struct Entry
  {
    std::uint32_t keep, alias;
  };

  const Cube_weights* m_weights;
  Grid_of_neighborhood m_grid;
  std::vector<Entry> m_table;
  std::uint32_t m_threshold = 0;
  std::vector<double> m_scaled;                // probabilities times n
  std::vector<std::uint32_t> m_small, m_large; // Vose's work lists
};

/// RRHT_Unif: pick a small ball B of radius s = r/c centered uniformly in the
/// neighborhood ball B_P, redraw it while it holds no point, then pick a
/// point of B uniformly.
///
/// Redrawing until B is not empty makes B's center uniform over U, the part
/// of B_P within s of some neighbor. Two exact ways to draw from U are used,
/// whichever is cheaper:
/// - rejection, as in the paper, but from the live cells rather than from
///   all of B_P: the neighborhood is cut into a grid of cells of side s, and
///   a cell is live when it or one of its 26 neighbors holds a point (a
///   center outside the live cells has an empty small ball). A center is
///   drawn uniformly in the live cells that meet B_P and kept if in B_P and
///   if its small ball is not empty: about vol(live) / vol(U) draws, against
///   vol(B_P) / vol(U);
/// - from the neighbors: pick a neighbor q, a center x uniform in the ball of
///   radius s around q (kept if in B_P), and keep x with probability 1/m, m
///   being the number of neighbors within s of x (the balls around them
///   overlap at x): about (n vol(s-ball)) / vol(U) draws for n neighbors.
/// The second is used when the neighbors are fewer than c^3 (small
/// neighborhoods, or a large c).
///
/// Each live cell lists the points of its 27 cells next to each other (with
/// their coordinates), so that the points of a small ball are found by one
/// scan of a short contiguous list. With the live cells, this made RRHT_Unif
/// 4 times as fast as drawing centers in all of B_P and looking through the
/// 27 cells around each (100k-point cube, fast setting: 10 s against 39 s).
/// After 100 000 failed draws (only possible through rounding) a point is
/// drawn uniformly instead.
class Unif_sampler : public Ball_sampler<Unif_sampler>
{
public:
  explicit Unif_sampler(unsigned int presampling_factor) : m_c(presampling_factor) {}

  void prepare(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    m_n = std::uint32_t(points.size());
    m_points = &points;
    m_radius = radius;
    m_small_radius = radius / m_c;
    const std::uint32_t side = 2 * m_c;
    m_grid.build(points, radius, side);
    m_from_neighbors = double(points.size()) < double(m_c) * m_c * m_c;

    // The candidates of each live cell, and the live cells that meet B_P.
    const std::size_t cells = m_grid.number_of_cells();
    m_first_candidate.assign(cells + 1, 0);
    m_candidates.clear();
    m_live_cells.clear();
    for(std::uint32_t i = 0; i < side; ++i)
      for(std::uint32_t j = 0; j < side; ++j)
        for(std::uint32_t k = 0; k < side; ++k)
        {
          const std::size_t cell = m_grid.cell(i, j, k);
          for(std::uint32_t a = (i > 0 ? i - 1 : 0); a <= (std::min)(i + 1, side - 1); ++a)
            for(std::uint32_t b = (j > 0 ? j - 1 : 0); b <= (std::min)(j + 1, side - 1); ++b)
            {
              // Cells (a, b, k - 1 .. k + 1) are consecutive in the grid's order.
              const std::size_t low = m_grid.cell(a, b, k > 0 ? k - 1 : 0);
              const std::size_t high = m_grid.cell(a, b, (std::min)(k + 1, side - 1));
              for(std::uint32_t e = m_grid.points_in(low).first; e < m_grid.points_in(high).second; ++e)
                m_candidates.push_back(Candidate{ points[m_grid.point(e)], m_grid.point(e) });
            }
          m_first_candidate[cell + 1] = static_cast<std::uint32_t>(m_candidates.size());
          if(m_first_candidate[cell + 1] > m_first_candidate[cell] && cell_meets_ball(i, j, k))
            m_live_cells.push_back(Live_cell{ corner(i), corner(j), corner(k), static_cast<std::uint32_t>(cell) });
        }
    m_live_threshold = Random::rejection_threshold21(std::uint32_t((std::max)(std::size_t(1), m_live_cells.size())));
    std::uint32_t longest = 0;
    for(std::size_t c = 0; c < cells; ++c)
      longest = (std::max)(longest, m_first_candidate[c + 1] - m_first_candidate[c]);
    m_in_ball.resize(longest);
  }

  std::uint32_t draw_point(Random& rng)
  {
    const std::uint32_t n = std::uint32_t(m_points->size());
    const std::uint32_t live = std::uint32_t(m_live_cells.size());
    if(live == 0) // cannot happen: the cell of each point is live and meets B_P
      return rng.uniform_index(n);
    const double r2 = m_small_radius * m_small_radius;
    for(int attempt = 0; attempt < 100000; ++attempt)
    {
      Eigen::Vector3d center;
      std::size_t cell;
      if(m_from_neighbors)
      {
        center = (*m_points)[rng.uniform_index(n)] + m_small_radius * uniform_in_unit_ball(rng);
        if(center.squaredNorm() > m_radius * m_radius)
          continue;
        cell = m_grid.cell(center);
      }
      else
      {
        std::uint32_t i;
        if(!Random::draw21(rng(), live, m_live_threshold, i))
          continue;
        const Live_cell& c = m_live_cells[i];
        center = Eigen::Vector3d(c.x, c.y, c.z) + (m_small_radius / 2) * (uniform_in_cube(rng) + Eigen::Vector3d::Ones());
        if(center.squaredNorm() > m_radius * m_radius)
          continue;
        cell = c.cell;
      }

      // The points of the small ball, from the cell's candidates (kept
      // without a branch: whether a candidate is in the ball is random).
      std::uint32_t m = 0;
      for(std::uint32_t e = m_first_candidate[cell]; e < m_first_candidate[cell + 1]; ++e)
      {
        m_in_ball[m] = m_candidates[e].index;
        m += ((m_candidates[e].point - center).squaredNorm() <= r2);
      }
      if(m == 0 || (m_from_neighbors && rng.uniform_index(m) != 0))
        continue;
      return m_in_ball[rng.uniform_index(m)];
    }
    return rng.uniform_index(n);
  }

private:
  struct Candidate
  {
    Eigen::Vector3d point;
    std::uint32_t index;
  };
  struct Live_cell
  {
    double x, y, z; // lowest corner
    std::uint32_t cell;
  };

  // Cells are s wide: 2c of them cover [-r, r].
  double corner(std::uint32_t i) const { return -m_radius + i * m_small_radius; }

  bool cell_meets_ball(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    double nearest = 0;
    for(double low : { corner(i), corner(j), corner(k) })
    {
      const double gap = (std::max)({ low, -(low + m_small_radius), 0. });
      nearest += gap * gap;
    }
    return nearest <= m_radius * m_radius;
  }

  // Uniform in [-1, 1]^3, the three coordinates from one random word: 21
  // bits each, a grid of step 2^-20, far below the size of the small balls.
  static Eigen::Vector3d uniform_in_cube(Random& rng)
  {
    const double step = 1. / (1u << 20);
    const std::uint64_t word = rng();
    const std::uint64_t low = Random::bits21_limit - 1;
    return Eigen::Vector3d(double(word & low) * step - 1 + step / 2, double((word >> 21) & low) * step - 1 + step / 2,
                           double((word >> 42) & low) * step - 1 + step / 2);
  }

  static Eigen::Vector3d uniform_in_unit_ball(Random& rng)
  {
    Eigen::Vector3d x;
    do
      x = uniform_in_cube(rng);
    while(x.squaredNorm() > 1);
    return x;
  }

  unsigned int m_c;
  const std::vector<Eigen::Vector3d>* m_points = nullptr;
  double m_radius = 1, m_small_radius = 1;
  bool m_from_neighbors = false;
  Grid_of_neighborhood m_grid;
  std::vector<std::uint32_t> m_first_candidate; // per cell, into m_candidates
  std::vector<Candidate> m_candidates;
  std::vector<Live_cell> m_live_cells;
  std::uint32_t m_live_threshold = 0;
  std::vector<std::uint32_t> m_in_ball;
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_BALL_SAMPLING_H
