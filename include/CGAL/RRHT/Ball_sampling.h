// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Cubes and RRHT_Unif (paper, Section 5): points drawn spatially
// uniformly in the neighborhood ball B_P rather than uniformly among the
// points, so that a densely sampled patch does not outvote a sparse one.

#ifndef CGAL_RRHT_BALL_SAMPLING_H
#define CGAL_RRHT_BALL_SAMPLING_H

#include <CGAL/RRHT/Instruction_set.h>
#include <CGAL/RRHT/Points_sampling.h>
#include <CGAL/RRHT/Random.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace CGAL {
namespace RRHT {

namespace internal {
/// After this many draws of one point of a triple that repeat a point
/// already in it, `other_point()` gives that point.
constexpr int max_repeated_draws = 64;

/// A point of [0, n) other than `a` and `b`, drawn uniformly: the point of a
/// triple after `max_repeated_draws` repeats (a neighborhood whose spatial
/// distribution hides all but one or two of its points).
inline std::uint32_t other_point(std::uint32_t n, Random& rng, std::uint32_t a, std::uint32_t b)
{
  for(;;)
  {
    const std::uint32_t p = rng.uniform_index(n);
    if(p != a && p != b)
      return p;
  }
}

/// The triple of `draw_distinct_triple()` made from draws given one at a
/// time to `add()`.
class Distinct_triple
{
public:
  /// Adds the draw `p` (or, after `max_repeated_draws` draws that repeat a
  /// point of the triple, a point of [0, n) drawn with `other_point()`);
  /// true when the triple is complete: it is then `triple()`, and the next
  /// draw starts another.
  bool add(std::uint32_t p, std::uint32_t n, Random& rng)
  {
    if(m_size > 0 && (p == m_triple[0] || p == m_triple[m_size - 1]))
    {
      if(++m_repeats < max_repeated_draws)
        return false;
      p = other_point(n, rng, m_triple[0], m_triple[m_size - 1]);
    }
    m_repeats = 0;
    m_triple[m_size++] = p;
    if(m_size < 3)
      return false;
    m_size = 0;
    return true;
  }

  const Triple& triple() const { return m_triple; }

private:
  Triple m_triple = {{ 0, 0, 0 }};
  std::uint32_t m_size = 0; // points of the triple so far
  int m_repeats = 0;        // draws that repeated one of them since the last
};
} // namespace internal

/// Draws three distinct points of a neighborhood of `n` points with
/// `sampler.draw_point(rng)`, drawing again a point equal to one already
/// drawn; after `internal::max_repeated_draws` such draws of one point, that
/// point is drawn uniformly among the others instead.
template <typename Sampler>
void draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng, Triple& t)
{
  internal::Distinct_triple triple;
  while(!triple.add(sampler.draw_point(rng), n, rng))
    ;
  t = triple.triple();
}

namespace internal {
/// Squared distance from the origin (the center of B_P) to the cube
/// [low[0], low[0] + side] x [low[1], ...] x [low[2], ...]; 0 inside.
inline double squared_distance_to_cube(const double low[3], double side)
{
  double squared_distance = 0;
  for(int d = 0; d < 3; ++d)
  {
    const double gap = (std::max)({ low[d], -(low[d] + side), 0. });
    squared_distance += gap * gap;
  }
  return squared_distance;
}
} // namespace internal

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
          if(internal::squared_distance_to_cube(lo, side) >= 1)
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
///
/// A triple is three draws, a draw equal to a point already in the triple
/// being drawn again (`draw_distinct_triple()`). A draw costs one random
/// word, for neighborhoods of at most 2^12 points (`small_limit`): 16 bits
/// for the point (Lemire's method, rejected with probability below
/// n / 2^16) and 30 bits for the choice of its alias. `draw()` computes the
/// three draws of 64 triples at a time with loops without branches, which
/// the compiler vectorizes (and compiles for AVX2, see `Instruction_set.h`),
/// and goes on drawing only for the few triples whose three draws are not
/// distinct (see `draw_triples()`). Measured on the 100k-point noisy cube,
/// fast setting, one thread (`rrht_normals --planes 300 --rotations 2
/// --threads 1 --sampling cubes`, the min of 9 interleaved runs): 1.96 s
/// instead of 2.09 s with a call of `draw_point()` per draw (1.61e9 instead
/// of 1.84e9 instructions on 10k points, callgrind); RRHT_Points takes
/// 1.53 s.
///
/// `prepare()` makes the alias table without sorting the points by cube and
/// without branches on the probabilities, which are mispredicted at random:
/// 1.87 s instead of 1.96 s in the same runs (11% of the samples of `perf`
/// were in `prepare()` before).
class Cubes_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the triples are the same
  /// with each, see `Instruction_set.h`).
  explicit Cubes_sampler(const Cube_weights& weights, Instruction_set instruction_set = best_instruction_set())
    : m_weights(&weights), m_instruction_set(instruction_set)
  {}

  void prepare(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    m_n = std::uint32_t(points.size());
    const unsigned int c = m_weights->cubes_per_axis();
    if(m_points_in_cube.empty())
      m_points_in_cube.assign(std::size_t(c) * c * c, 0);

    // The cube of each point, and the number of points of each cube.
    m_cube_of_point.resize(m_n);
    const double to_cubes = c / (2 * radius), last = c - 1;
    for(std::uint32_t i = 0; i < m_n; ++i)
    {
      std::uint32_t cube = 0;
      for(int d = 0; d < 3; ++d)
      {
        // Clamped, then truncated: the floor, without a call to
        // `std::floor()`, which has no SSE2 instruction.
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
    m_scaled.resize(m_n);
    for(std::uint32_t i = 0; i < m_n; ++i)
    {
      const std::uint32_t cube = m_cube_of_point[i];
      m_scaled[i] = m_weights->weight(cube) / (total * m_points_in_cube[cube]) * m_n;
    }
    for(std::uint32_t cube : m_cube_of_point)
      m_points_in_cube[cube] = 0;

    // Walker's alias table (Vose's construction): point i is kept with
    // probability keep[i] / 2^30, else replaced by alias[i]. The lists of
    // points of probability below and above the mean are made and consumed
    // without branches, which would be mispredicted at random.
    m_keep.resize(m_n);
    m_alias.resize(m_n);
    m_small.resize(m_n);
    m_large.resize(m_n);
    std::uint32_t smalls = 0, larges = 0;
    for(std::uint32_t i = 0; i < m_n; ++i)
    {
      const bool small = m_scaled[i] < 1;
      m_small[smalls] = i;
      m_large[larges] = i;
      smalls += small;
      larges += !small;
    }
    while(smalls != 0 && larges != 0)
    {
      const std::uint32_t small = m_small[--smalls], large = m_large[larges - 1];
      m_keep[small] = static_cast<std::int32_t>(m_scaled[small] * always_keep);
      m_alias[small] = std::int32_t(large);
      m_scaled[large] -= 1 - m_scaled[small];
      // If the large one is now small, it moves to the other list.
      const bool now_small = m_scaled[large] < 1;
      m_small[smalls] = large;
      smalls += now_small;
      larges -= now_small;
    }
    for(std::uint32_t s = 0; s < smalls; ++s) // 1 up to rounding
      set_always_kept(m_small[s]);
    for(std::uint32_t l = 0; l < larges; ++l)
      set_always_kept(m_large[l]);
    m_rejection_threshold = (m_n != 0 && m_n <= small_limit) ? Random::rejection_threshold16(m_n) : 0;
  }

  void start_run() {}

  /// Writes `count` triples of distinct points to `out`; returns `count`.
  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    if(m_n > small_limit)
    {
      for(std::size_t i = 0; i < count; ++i)
        draw_distinct_triple(*this, m_n, rng, out[i]);
      return count;
    }
    run_with(m_instruction_set, [&] { draw_triples(rng, count, out); });
    return count;
  }

  /// One point (for `draw_distinct_triple()`): the draw of `draw()`.
  std::uint32_t draw_point(Random& rng)
  {
    if(m_n > small_limit)
    {
      const std::uint32_t i = rng.uniform_index(m_n);
      return choose(std::int32_t(i), std::uint32_t(rng() >> 32), m_keep.data(), m_alias.data());
    }
    for(;;)
    {
      const std::uint64_t word = rng();
      std::int32_t i;
      if(Random::draw16(std::uint32_t(word), std::int32_t(m_n), m_rejection_threshold, i))
        return choose(i, std::uint32_t(word >> 32), m_keep.data(), m_alias.data());
    }
  }

private:
  // Point i is kept when the 30 bits of `choice` are below keep[i] (out of
  // 2^30), else its alias is taken. With a mask rather than a branch, which
  // would be mispredicted at random.
  static std::uint32_t choose(std::int32_t i, std::uint32_t choice, const std::int32_t* keep, const std::int32_t* alias)
  {
    const std::int32_t alias_mask = -std::int32_t(std::int32_t(choice >> 2) >= keep[i]);
    return std::uint32_t((alias[i] & alias_mask) | (i & ~alias_mask));
  }

  // The triples of `draw()` when n <= small_limit, a chunk of T triples at
  // a time. The first draws of the T triples come first, then their second
  // draws, then their third ones; they are computed by loops without
  // branches (the table reads are gathers with AVX2). When the three draws
  // of a triple are accepted and distinct, they are the triple, as
  // `draw_distinct_triple()` would make it from them; otherwise, rarely,
  // `draw_distinct_triple()` goes on from them with further draws. Each
  // triple thus has draws of its own, and the distribution of
  // `draw_distinct_triple()`. The chunk is in local arrays, which the
  // compiler knows the tables cannot alias (with members it would not
  // vectorize the loops).
  void draw_triples(Random& rng, std::size_t count, Triple* out)
  {
    std::uint32_t low_bits[3 * chunk], high_bits[3 * chunk];
    std::int32_t point[3 * chunk], accepted[3 * chunk];
    std::int32_t is_triple[chunk]; // its three draws are the triple
    const std::int32_t n = std::int32_t(m_n), threshold = m_rejection_threshold;
    const std::int32_t *keep = m_keep.data(), *alias = m_alias.data();
    for(std::size_t written = 0; written < count;)
    {
      const std::size_t triples = (std::min)(chunk, count - written), draws = 3 * triples;
      for(std::size_t j = 0; j < draws; ++j)
      {
        const std::uint64_t word = rng();
        low_bits[j] = std::uint32_t(word);
        high_bits[j] = std::uint32_t(word >> 32);
      }
      for(std::size_t j = 0; j < draws; ++j)
      {
        std::int32_t i;
        accepted[j] = Random::draw16(low_bits[j], n, threshold, i);
        point[j] = std::int32_t(choose(i, high_bits[j], keep, alias));
      }
      const std::int32_t *first = point, *second = point + triples, *third = point + 2 * triples;
      for(std::size_t k = 0; k < triples; ++k)
        is_triple[k] = (accepted[k] & accepted[k + triples] & accepted[k + 2 * triples]) & (first[k] != second[k]) &
                       (first[k] != third[k]) & (second[k] != third[k]);
      for(std::size_t k = 0; k < triples; ++k)
      {
        const std::array<std::int32_t, 3> drawn = {{ first[k], second[k], third[k] }};
        if(is_triple[k] != 0)
          out[written++] = Triple{{ std::uint32_t(drawn[0]), std::uint32_t(drawn[1]), std::uint32_t(drawn[2]) }};
        else
          out[written++] = complete_triple(rng, drawn, { accepted[k], accepted[k + triples], accepted[k + 2 * triples] });
      }
    }
  }

  // `draw_distinct_triple()` from the three draws `points` (those that are
  // `accepted`), then from draws of `draw_point()`.
  Triple complete_triple(Random& rng, const std::array<std::int32_t, 3>& points,
                         const std::array<std::int32_t, 3>& accepted)
  {
    internal::Distinct_triple triple;
    for(int d = 0; d < 3; ++d)
      if(accepted[d] != 0 && triple.add(std::uint32_t(points[d]), m_n, rng))
        return triple.triple();
    while(!triple.add(draw_point(rng), m_n, rng))
      ;
    return triple.triple();
  }

  void set_always_kept(std::uint32_t i)
  {
    m_keep[i] = always_keep;
    m_alias[i] = std::int32_t(i);
  }

  static constexpr std::int32_t always_keep = 1 << 30;
  static constexpr std::uint32_t small_limit = 1u << 12;
  static constexpr std::size_t chunk = 64; // triples computed at a time

  const Cube_weights* m_weights;
  Instruction_set m_instruction_set;
  std::uint32_t m_n = 0;
  std::vector<std::uint32_t> m_cube_of_point;
  std::vector<std::uint32_t> m_points_in_cube; // per cube: 0 between neighborhoods
  std::vector<std::int32_t> m_keep, m_alias;   // the alias table
  std::int32_t m_rejection_threshold = 0;
  std::vector<double> m_scaled;                // probabilities times n
  std::vector<std::uint32_t> m_small, m_large; // Vose's work lists
};

namespace internal {
/// For each byte: how many of its bits are set, and where its r-th set bit
/// is (r from 0), so that masks of 8 candidates are counted and searched
/// without a loop over their bits.
struct Bits_of_bytes
{
  std::uint8_t count[256];
  std::uint8_t position[256][8];

  constexpr Bits_of_bytes() : count(), position()
  {
    for(unsigned int byte = 0; byte < 256; ++byte)
      for(unsigned int bit = 0; bit < 8; ++bit)
        if(byte & (1u << bit))
          position[byte][count[byte]++] = std::uint8_t(bit);
  }
};

inline const Bits_of_bytes& bits_of_bytes()
{
  static constexpr Bits_of_bytes table;
  return table;
}
} // namespace internal

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
/// Each live cell lists the points of its 27 cells (its candidates), and the
/// points of a small ball are found by one pass over that list: the inner
/// loop of RRHT_Unif (on the 100k-point noisy cube at the fast setting and
/// c = 4: 2.2 centers per point drawn, of which 1.7 in B_P, each with a list
/// of 1.9 blocks holding 2 points of its small ball). So the lists are
/// stored for that pass: in blocks of 8 candidates, one array per
/// coordinate, in single precision and in units of s, padded with far-away
/// points. A block is tested by a loop without branches, which the compiler
/// vectorizes, into a mask of 8 bits; the masks are counted, and the chosen
/// point found, with a table (`internal::Bits_of_bytes`). The lists are made
/// by scattering each point to the lists of its 27 cells, and only the cells
/// that receive points exist (they are the live cells, in the order in which
/// the points reach them). The center of a small ball comes from one random
/// word: 21 bits for the live cell (16 in the batches of `draw()`), 14 bits
/// per coordinate (a grid of step s / 2^14 in the cell).
///
/// The draws of one batch are compiled for AVX2 as well (`run_with()`): 8
/// candidates per instruction instead of 4, the same points drawn. Measured
/// on the 100k-point noisy cube, fast setting, one thread, against the
/// former lists (candidates in double precision kept one by one, and all
/// (2c)^3 cells visited to make them): 12.7 s instead of 16.4 s (3% of it
/// from AVX2); with k = 20 (points drawn from the neighbors), 14.4 s instead
/// of 20.9 s; with c = 16 (30k points), 3.8 s instead of 17.7 s.
///
/// When the centers are drawn in the live cells, `draw()` computes 64 of
/// them at a time, with their random words, in loops without branches that
/// the compiler vectorizes (`draw_triples()`); only the scans of the kept
/// centers remain one by one. On the same cloud: 11.5 s instead of 12.6 s
/// (the min of 5 runs), 5.97e9 instead of 6.79e9 instructions on 10k points
/// (callgrind).
///
/// After 100 000 failed draws (only possible through rounding) a point is
/// drawn uniformly instead.
///
/// Memory, kept from one point to the next: 9 bytes per cell of the grid,
/// (2c + 2)^3 cells (9 kB at c = 4, 2.6 MB at c = 32), allocated at the
/// first neighborhood; 16 bytes per candidate, 27 candidates per point.
class Unif_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the points are the same
  /// with each, see `Instruction_set.h`).
  explicit Unif_sampler(unsigned int presampling_factor, Instruction_set instruction_set = best_instruction_set())
    : m_c(presampling_factor), m_instruction_set(instruction_set)
  {}

  void start_run() {}

  /// Writes `count` triples of distinct points to `out`; returns `count`.
  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    run_with(m_instruction_set, [&] {
      if(m_from_neighbors || m_live.empty() || m_live.size() > max_live_cells_of_batches)
        for(std::size_t i = 0; i < count; ++i)
          draw_distinct_triple(*this, m_n, rng, out[i]);
      else
        draw_triples(rng, count, out);
    });
    return count;
  }

  void prepare(const std::vector<Eigen::Vector3d>& points, double radius)
  {
    if(m_meets_ball.empty())
      build_grid();
    for(const Live_cell& cell : m_live) // the previous neighborhood's
      m_live_index[cell.cell] = no_cell;
    m_live.clear();
    m_n = std::uint32_t(points.size());
    m_from_neighbors = double(points.size()) < double(m_c) * m_c * m_c;

    // The points in units of s, and the number of candidates of each cell
    // (cells are live in the order in which points reach them).
    const double to_grid = m_c / radius;
    m_scaled.resize(points.size());
    m_home.resize(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      m_scaled[i] = (points[i] * to_grid).cast<float>();
      m_home[i] = cell_of(m_scaled[i]);
      for(std::int32_t offset : m_neighbor_offsets)
      {
        const std::uint32_t cell = std::uint32_t(std::int32_t(m_home[i]) + offset);
        if(m_meets_ball[cell] && m_count[cell]++ == 0)
          m_live.push_back(Live_cell{ 0, 0, 0, cell, 0, 0 });
      }
    }

    // Blocks of the lists; from now on, m_count[cell] is the next free place.
    std::uint32_t blocks = 0, longest = 0;
    for(std::uint32_t l = 0; l < m_live.size(); ++l)
    {
      Live_cell& live = m_live[l];
      const std::uint32_t cell = live.cell, g = m_cells_per_axis;
      live.x = float(cell / (g * g)) - 1.f - float(m_c);
      live.y = float(cell / g % g) - 1.f - float(m_c);
      live.z = float(cell % g) - 1.f - float(m_c);
      live.first_block = blocks;
      live.blocks = (m_count[cell] + 7) / 8;
      longest = (std::max)(longest, live.blocks);
      m_count[cell] = blocks * 8;
      blocks += live.blocks;
      m_live_index[cell] = l;
    }
    if(m_blocks.size() < blocks)
      m_blocks.resize(blocks);
    m_masks.resize(longest);

    for(std::uint32_t i = 0; i < m_n; ++i)
      for(std::int32_t offset : m_neighbor_offsets)
      {
        const std::uint32_t cell = std::uint32_t(std::int32_t(m_home[i]) + offset);
        if(m_meets_ball[cell])
          m_blocks[m_count[cell] / 8].set(m_count[cell]++ % 8, m_scaled[i], i);
      }
    for(const Live_cell& live : m_live)
    {
      for(std::uint32_t place = m_count[live.cell]; place < (live.first_block + live.blocks) * 8; ++place)
        m_blocks[place / 8].set(place % 8, Eigen::Vector3f(far_away, 0, 0), 0);
      m_count[live.cell] = 0;
    }
    const std::uint32_t lives = std::uint32_t((std::max)(std::size_t(1), m_live.size()));
    m_live_threshold = Random::rejection_threshold21(lives);
    m_live_threshold16 = Random::rejection_threshold16(lives);
  }

  std::uint32_t draw_point(Random& rng)
  {
    const std::uint32_t live = std::uint32_t(m_live.size());
    if(live == 0) // cannot happen: the cell of a point is live (and there are at most (2c)^3 < 2^21)
      return rng.uniform_index(m_n);
    const float ball = float(m_c) * float(m_c);
    for(int attempt = 0; attempt < 100000; ++attempt)
    {
      Eigen::Vector3f center;
      std::uint32_t l;
      if(m_from_neighbors)
      {
        center = m_scaled[rng.uniform_index(m_n)] + uniform_in_unit_ball(rng);
        if(center.squaredNorm() > ball)
          continue;
        l = m_live_index[cell_of(center)];
        if(l == no_cell) // only through rounding: the center is within s of a point
          continue;
      }
      else
      {
        const std::uint64_t word = rng();
        if(!Random::draw21(word, live, m_live_threshold, l))
          continue;
        const Live_cell& cell = m_live[l];
        center = Eigen::Vector3f(cell.x + fraction(word >> 21), cell.y + fraction(word >> 35),
                                 cell.z + fraction(word >> 49));
        if(center.squaredNorm() > ball)
          continue;
      }

      // The points of the small ball: their number, then one of them.
      const Live_cell& cell = m_live[l];
      const std::uint32_t m = points_in_small_ball(cell, center);
      if(m == 0 || (m_from_neighbors && rng.uniform_index(m) != 0))
        continue;
      return point_of_small_ball(cell, rng.uniform_index(m));
    }
    return rng.uniform_index(m_n);
  }

private:
  static constexpr std::uint32_t no_cell = ~std::uint32_t(0);
  static constexpr float far_away = 1e10f; // a padding candidate's x, in units of s
  static constexpr std::size_t chunk = 64; // centers of `draw_triples()` at a time
  // Live cells drawn from 16 bits (products below 2^31, rejection below 1/16).
  static constexpr std::size_t max_live_cells_of_batches = 1u << 12;
  static constexpr int max_failed_centers = 100000; // as `draw_point()`

  // Eight candidates of a live cell.
  struct Block
  {
    float x[8], y[8], z[8];
    std::uint32_t index[8];

    void set(std::uint32_t lane, const Eigen::Vector3f& p, std::uint32_t i)
    {
      x[lane] = p.x();
      y[lane] = p.y();
      z[lane] = p.z();
      index[lane] = i;
    }

    // Bit j is set when candidate j is within s (1) of the center. The loop,
    // without branches and on floats, is vectorized (8 or 4 lanes) as long
    // as GCC does not unroll it first; the bits come from a table because
    // SSE2 has no shift by a different amount per lane.
    std::uint8_t in_small_ball(const Eigen::Vector3f& center) const
    {
      static constexpr std::uint32_t bit[8] = { 1, 2, 4, 8, 16, 32, 64, 128 };
      const float cx = center.x(), cy = center.y(), cz = center.z();
      std::uint32_t mask = 0;
#if defined(__GNUC__)
#pragma GCC unroll 1
#endif
      for(std::uint32_t j = 0; j < 8; ++j)
      {
        const float dx = x[j] - cx, dy = y[j] - cy, dz = z[j] - cz;
        mask += (dx * dx + dy * dy + dz * dz <= 1.f) ? bit[j] : 0u;
      }
      return std::uint8_t(mask);
    }
  };

  struct Live_cell
  {
    float x, y, z;      // lowest corner, in units of s
    std::uint32_t cell; // in the grid
    std::uint32_t first_block, blocks;
  };

  // The number of points within s of `center`, a point of `cell`; their
  // masks are kept for `point_of_small_ball()`.
  std::uint32_t points_in_small_ball(const Live_cell& cell, const Eigen::Vector3f& center)
  {
    const Block* blocks = m_blocks.data() + cell.first_block;
    const internal::Bits_of_bytes& bits = internal::bits_of_bytes();
    std::uint32_t m = 0;
    for(std::uint32_t b = 0; b < cell.blocks; ++b)
    {
      m_masks[b] = blocks[b].in_small_ball(center);
      m += bits.count[m_masks[b]];
    }
    return m;
  }

  // The point of rank `rank` among those of the last `points_in_small_ball()`.
  std::uint32_t point_of_small_ball(const Live_cell& cell, std::uint32_t rank) const
  {
    const Block* blocks = m_blocks.data() + cell.first_block;
    const internal::Bits_of_bytes& bits = internal::bits_of_bytes();
    std::uint32_t b = 0;
    while(rank >= bits.count[m_masks[b]])
      rank -= bits.count[m_masks[b++]];
    return blocks[b].index[bits.position[m_masks[b]][rank]];
  }

  // The triples of `draw()` when the centers are drawn in the live cells,
  // 64 centers at a time. Their random words, live cells, coordinates and
  // whether they are kept (a live cell accepted by Lemire's method on 16
  // bits, a center in B_P) are computed by loops without branches that the
  // compiler vectorizes (with gathers for AVX2); then the kept centers are
  // taken in order, as `draw_point()` takes them: a small ball without
  // points is skipped, else one of its points is drawn, and the points
  // make triples as in `draw_distinct_triple()`. Each point is the first
  // success of a sequence of independent centers, as with `draw_point()`,
  // so the triples have the distribution of `draw_distinct_triple()`. The
  // chunk is in local arrays, which the compiler knows the live cells cannot
  // alias (with members it would not vectorize the loops).
  void draw_triples(Random& rng, std::size_t count, Triple* out)
  {
    std::uint32_t low_bits[chunk], high_bits[chunk], rank_bits[chunk];
    std::int32_t live[chunk], kept[chunk], kept_centers[chunk];
    float x[chunk], y[chunk], z[chunk];
    const std::int32_t lives = std::int32_t(m_live.size()), threshold = m_live_threshold16;
    const Live_cell* cells = m_live.data();
    const float ball = float(m_c) * float(m_c);
    internal::Distinct_triple triple;
    std::size_t written = 0;
    // Centers since the last point drawn; after `max_failed_centers` of
    // them (only through rounding, see `draw_point()`), a point is drawn
    // uniformly instead.
    int failed = 0;
    auto add_point = [&](std::uint32_t p) {
      failed = 0;
      if(triple.add(p, m_n, rng))
        out[written++] = triple.triple();
    };
    while(written < count)
    {
      for(std::size_t j = 0; j < chunk; ++j)
      {
        const std::uint64_t word = rng();
        low_bits[j] = std::uint32_t(word);
        high_bits[j] = std::uint32_t(word >> 32);
      }
      for(std::size_t j = 0; j < chunk; ++j)
        rank_bits[j] = std::uint32_t(rng() >> 32);
      for(std::size_t j = 0; j < chunk; ++j)
      {
        // 16 bits for the live cell, 14 for each coordinate.
        std::int32_t l;
        const bool accepted = Random::draw16(low_bits[j], lives, threshold, l);
        const Live_cell& cell = cells[l];
        x[j] = cell.x + fraction(low_bits[j] >> 16);
        y[j] = cell.y + fraction(high_bits[j]);
        z[j] = cell.z + fraction(high_bits[j] >> 14);
        live[j] = l;
        kept[j] = std::int32_t(accepted) & std::int32_t(x[j] * x[j] + y[j] * y[j] + z[j] * z[j] <= ball);
      }
      std::size_t centers = 0;
      for(std::size_t j = 0; j < chunk; ++j)
      {
        kept_centers[centers] = std::int32_t(j);
        centers += std::size_t(kept[j]);
      }
      failed += int(chunk - centers); // those not kept, counted first
      if(failed >= max_failed_centers)
        add_point(rng.uniform_index(m_n));
      for(std::size_t k = 0; k < centers && written < count; ++k)
      {
        const std::int32_t j = kept_centers[k];
        const Live_cell& cell = cells[live[j]];
        const std::uint32_t m = points_in_small_ball(cell, Eigen::Vector3f(x[j], y[j], z[j]));
        if(m == 0)
        {
          if(++failed >= max_failed_centers)
            add_point(rng.uniform_index(m_n));
          continue;
        }
        std::uint32_t rank;
        if(!Random::draw32(rank_bits[j], m, rank))
          rank = rng.uniform_index(m);
        add_point(point_of_small_ball(cell, rank));
      }
    }
  }

  // The grid: cells of side s over [-r, r]^3 (2c per axis), with a margin of
  // one cell on each side so that the 27 cells around any cell exist.
  void build_grid()
  {
    const std::int32_t g = std::int32_t(2 * m_c + 2);
    m_cells_per_axis = std::uint32_t(g);
    const std::size_t cells = std::size_t(g) * g * g;
    m_meets_ball.assign(cells, 0);
    m_count.assign(cells, 0);
    m_live_index.assign(cells, no_cell);
    const double c = m_c;
    for(std::int32_t i = 1; i + 1 < g; ++i)
      for(std::int32_t j = 1; j + 1 < g; ++j)
        for(std::int32_t k = 1; k + 1 < g; ++k)
        {
          // Cell i of the grid spans [i - 1 - c, i - c] (in units of s).
          const double low[3] = { i - 1 - c, j - 1 - c, k - 1 - c };
          m_meets_ball[(std::size_t(i) * g + j) * g + k] = (internal::squared_distance_to_cube(low, 1.) <= c * c);
        }
    m_neighbor_offsets.clear();
    for(std::int32_t a = -1; a <= 1; ++a)
      for(std::int32_t b = -1; b <= 1; ++b)
        for(std::int32_t e = -1; e <= 1; ++e)
          m_neighbor_offsets.push_back((a * g + b) * g + e);
  }

  // The cell of a point of B_P (clamped to the grid, for rounding).
  std::uint32_t cell_of(const Eigen::Vector3f& p) const
  {
    std::uint32_t cell = 0;
    for(int d = 0; d < 3; ++d)
    {
      // Clamped, then truncated: the floor, without `std::floor()`.
      const float clamped = (std::min)((std::max)(p[d] + float(m_c), 0.f), float(2 * m_c - 1));
      cell = cell * m_cells_per_axis + std::uint32_t(clamped) + 1;
    }
    return cell;
  }

  // A number in [0, 1) from the 14 low bits of `bits`, at the middle of one
  // of 2^14 steps.
  static float fraction(std::uint64_t bits)
  {
    const float step = 1.f / (1u << 14);
    return float(std::int32_t(std::uint32_t(bits) & ((1u << 14) - 1))) * step + step / 2;
  }

  static Eigen::Vector3f uniform_in_unit_ball(Random& rng)
  {
    Eigen::Vector3f x;
    do
    {
      const std::uint64_t word = rng();
      x = Eigen::Vector3f(fraction(word), fraction(word >> 14), fraction(word >> 28)) * 2.f -
          Eigen::Vector3f::Ones();
    } while(x.squaredNorm() > 1);
    return x;
  }

  unsigned int m_c;
  Instruction_set m_instruction_set;
  std::uint32_t m_n = 0;
  std::uint32_t m_cells_per_axis = 0;
  bool m_from_neighbors = false;
  std::vector<std::uint8_t> m_meets_ball;        // per cell of the grid: it meets B_P
  std::vector<std::uint32_t> m_count;            // per cell: 0 between neighborhoods
  std::vector<std::uint32_t> m_live_index;       // per cell: in m_live, or no_cell
  std::vector<std::int32_t> m_neighbor_offsets;  // the 27 cells around a cell
  std::vector<Eigen::Vector3f> m_scaled;         // the neighborhood in units of s
  std::vector<std::uint32_t> m_home;             // the cell of each point
  std::vector<Live_cell> m_live;
  std::uint32_t m_live_threshold = 0;
  std::int32_t m_live_threshold16 = 0; // for the batches of `draw_triples()`
  std::vector<Block> m_blocks;
  std::vector<std::uint8_t> m_masks;             // of the blocks of one list
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_BALL_SAMPLING_H
