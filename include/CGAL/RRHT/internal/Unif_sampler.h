// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Unif (paper, Section 5): points drawn spatially uniformly in the
// neighborhood ball B_P through small balls of radius r/c centered in it.

#ifndef CGAL_RRHT_INTERNAL_UNIF_SAMPLER_H
#define CGAL_RRHT_INTERNAL_UNIF_SAMPLER_H

#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>
#include <CGAL/RRHT/internal/Weighted_points_sampler.h>
#include <CGAL/RRHT/internal/integer_floor.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// RRHT_Unif: pick a small ball B of radius s = r/c centered uniformly in the
/// neighborhood ball B_P, redraw it while it holds no point, then pick a
/// point of B uniformly.
///
/// That too is a fixed distribution over the neighbors. Redrawing B until
/// it is not empty makes its center x uniform over U, the part of B_P within
/// s of some neighbor, so that neighbor q is drawn with probability
///
///     p(q) = (1 / vol(U)) * integral over B_P ∩ B(q, s) of dx / m(x),
///
/// m(x) being the number of neighbors within s of x. Drawing the centers one
/// by one costs a search of the small ball around each, for 1.7 centers per
/// point drawn. So the integral is computed once per neighborhood, by
/// the midpoint rule over a lattice of step h = s / L (L =
/// `lattice_steps_per_small_radius`) shifted at random, and the points are
/// then drawn with these probabilities as those of RRHT_Cubes are
/// (`Weighted_points_sampler`):
///
///     p(q) = w(q) / (sum of w),
///     w(q) = (sum over the nodes x of B_P ∩ B(q, s) of 1 / m(x)) / (number of nodes of B(q, s)).
///
/// That is the paper's procedure with the centers drawn among the nodes
/// instead of anywhere in B_P; dividing by the number of nodes of B(q, s),
/// which varies with q's place among them, corrects the volume of the small
/// ball. L = 3 keeps the total variation distance to the integral near 2%
/// (tested against the paper's procedure) at a fraction of a larger L's cost.
///
/// In units of h, B_P has radius R = c L around the origin, and the nodes
/// are the points t + δ, t an integer vector in [-R, R]^3 and δ the random
/// shift in [0, 1)^3. They are taken in rows along x (fixed y and z); in a
/// row, the nodes within L of a neighbor q are an interval, a span of q,
/// found with a square root. Then:
/// 1. the spans of every neighbor (about pi L^2 = 28 each), clipped to B_P;
/// 2. m at each node of a row, by differences: +1 at the first node of each
///    span and -1 past its last, summed along the row;
/// 3. the prefix sums of 1 / m along the rows, in fixed point (2^32 / m):
///    the sum over a span is the difference of two of them, in exact
///    integers, so that w does not depend on the order of the operations.
/// A row stores its nodes from the first of its spans to the last.
///
/// Memory, per thread: 16 bytes per row of the lattice ((2R + 1)^2 rows:
/// 10 kB at c = 4, 600 kB at c = 32), allocated at the first neighborhood;
/// per neighborhood, 12 bytes per candidate row of each point (36 of them)
/// and 8 bytes per span, and 12 bytes per node stored.
class Unif_sampler
{
public:
  /// Lattice steps per radius of a small ball (L).
  static constexpr std::int32_t lattice_steps_per_small_radius = 3;

  /// Computes with the loops of `instruction_set` (the probabilities and the
  /// points drawn are the same with each, see `Instruction_set.h`).
  explicit Unif_sampler(unsigned int presampling_factor, Instruction_set instruction_set = best_instruction_set())
    : m_c(presampling_factor), m_instruction_set(instruction_set), m_points(instruction_set)
  {}

  /// The probabilities of the n points, from the lattice shifted by three
  /// numbers of `rng`.
  void prepare(const std::vector<Eigen::Vector3d>& points, double radius, Random& rng)
  {
    const std::int32_t R = std::int32_t(m_c) * L, D = 2 * R + 1;
    if(m_row_extents.empty())
    {
      // The (2R + 1)^2 rows, then one more per candidate row: the row that
      // `add_spans()` writes to when that candidate row has no nodes.
      m_row_extents.assign(std::size_t(D) * D + candidate_rows, Row_extent{ no_node, 0 });
      m_row_base.assign(std::size_t(D) * D, 0);
      m_touched_rows.resize(std::size_t(D) * D);
    }
    const std::uint32_t n = std::uint32_t(points.size());
    // Three draws in sequence, z first: the order in which GCC evaluated the
    // arguments of the constructor that drew them before (an order that C++
    // leaves unspecified, and clang takes the other way).
    const double shift_z = rng.uniform_real(), shift_y = rng.uniform_real(), shift_x = rng.uniform_real();
    const Eigen::Vector3d shift(shift_x, shift_y, shift_z);

    // 1. The spans, point by point; each row keeps its first and last node.
    m_spans.resize(std::size_t(n) * candidate_rows);
    m_first_span.resize(std::size_t(n) + 1);
    m_nodes_in_small_ball.resize(n);
    std::size_t spans = 0;
    const double to_lattice = R / radius;
    run_with(m_instruction_set, [&] {
      for(std::uint32_t i = 0; i < n; ++i)
      {
        m_first_span[i] = std::uint32_t(spans);
        const Eigen::Vector3d u = (points[i] * to_lattice - shift).cwiseMax(-R - 1.).cwiseMin(R + 1.);
        spans += add_spans(u.cast<float>(), shift.cast<float>(), m_spans.data() + spans, m_nodes_in_small_ball[i]);
      }
    });
    m_first_span[n] = std::uint32_t(spans);

    // 2. The places of the nodes: the stored nodes of the rows one after
    // the other, each row from its first span to its last one, and one more
    // place. Node x of row r is at place base(r) + x.
    std::int64_t stored = 0;
    for(std::uint32_t t = 0; t < m_touched; ++t)
    {
      const std::uint32_t row = m_touched_rows[t];
      const Row_extent& extent = m_row_extents[row];
      m_row_base[row] = std::int32_t(stored) - extent.first;
      stored += extent.end - extent.first + 1;
    }
    // m at each place, by differences: +1 at the first node of each span,
    // -1 past its last one (so that m is 0 at the last place of each row).
    m_changes_of_m.assign(std::size_t(stored), 0);
    m_span_places.resize(2 * spans);
    for(std::size_t s = 0; s < spans; ++s)
    {
      const Span& span = m_spans[s];
      const std::int32_t base = m_row_base[span.row];
      m_span_places[2 * s] = std::uint32_t(base + span.first);
      m_span_places[2 * s + 1] = std::uint32_t(base + span.end);
      ++m_changes_of_m[std::size_t(base + span.first)];
      --m_changes_of_m[std::size_t(base + span.end)];
    }
    for(std::uint32_t t = 0; t < m_touched; ++t)
    {
      m_row_extents[m_touched_rows[t]] = Row_extent{ no_node, 0 };
    }
    m_touched = 0;

    // 3. The prefix sums of 1 / m over the places, in fixed point (2^32 / m,
    // and 0 where m = 0), so that the sum over the nodes of a span is the
    // difference of two of them, exactly.
    while(m_inverse.size() <= n) // m is at most n
      m_inverse.push_back(m_inverse.empty() ? 0 : (std::uint64_t(1) << 32) / m_inverse.size());
    m_prefix_sums.resize(std::size_t(stored) + 1);
    std::int32_t m = 0;
    std::uint64_t sum = 0;
    m_prefix_sums[0] = 0;
    for(std::size_t place = 0; place < std::size_t(stored); ++place)
    {
      m += m_changes_of_m[place];
      sum += m_inverse[std::uint32_t(m)];
      m_prefix_sums[place + 1] = sum;
    }

    // The weights, from the spans of each point.
    m_scaled.resize(n);
    double total = 0;
    for(std::uint32_t i = 0; i < n; ++i)
    {
      std::uint64_t w = 0;
      for(std::uint32_t s = m_first_span[i]; s < m_first_span[i + 1]; ++s)
        w += m_prefix_sums[m_span_places[2 * s + 1]] - m_prefix_sums[m_span_places[2 * s]];
      m_scaled[i] = double(w) / m_nodes_in_small_ball[i];
      total += m_scaled[i];
    }
    // Every point has nodes of B_P within s (a ball of radius s / 2 >= h
    // inside B_P and B(q, s)), so total > 0 unless there are no points; the
    // small ball of a point holds at least the nodes of the lattice's cell
    // around it.
    for(double& scaled : m_scaled)
      scaled = total > 0 ? scaled / total * n : 1.;
    m_points.prepare(m_scaled);
  }

  void start_run() {}

  /// Writes `count` triples of distinct points to `out`; returns `count`.
  std::size_t draw(Random& rng, std::size_t count, Triple* out) { return m_points.draw(rng, count, out); }

  /// One point (for `draw_distinct_triple()`): the draw of `draw()`.
  std::uint32_t draw_point(Random& rng) { return m_points.draw_point(rng); }

private:
  static constexpr std::int32_t L = lattice_steps_per_small_radius;
  // The rows that may meet a small ball: y and z in [-L + 1, L] from the
  // node below its center u. (A row at -L is only within L of u when u is
  // on a node's plane, and then meets the small ball at a single node at the
  // distance L: left out, that node changes nothing to the midpoint rule.)
  static constexpr std::int32_t candidate_rows = (2 * L) * (2 * L);
  static constexpr std::int32_t no_node = 0xFFFF; // the first node of a row without spans

  // The offsets of the candidate rows from the node below a point, in y
  // and z.
  struct Candidate_offsets
  {
    float y[candidate_rows], z[candidate_rows];
    std::int32_t y_int[candidate_rows], z_int[candidate_rows];

    constexpr Candidate_offsets() : y(), z(), y_int(), z_int()
    {
      for(std::int32_t k = 0; k < candidate_rows; ++k)
      {
        y_int[k] = k / (2 * L) - L + 1;
        z_int[k] = k % (2 * L) - L + 1;
        y[k] = float(y_int[k]);
        z[k] = float(z_int[k]);
      }
    }
  };

  static const Candidate_offsets& candidate_offsets()
  {
    static constexpr Candidate_offsets table;
    return table;
  }

  // The stored nodes of a row: [first, end).
  struct Row_extent
  {
    std::int32_t first, end;
  };

  // Nodes [first, end) of a row (rows numbered (y + R) (2R + 1) + z + R,
  // nodes x + R).
  struct Span
  {
    std::uint32_t row;
    std::int32_t first, end;
  };

  // Writes the spans of the point u (in units of h, the lattice at integers,
  // u within R + 1 of the origin) to `out`, and returns their number: the
  // nodes of B_P within L of u, in the candidate rows. They are computed for
  // all the candidate rows by loops without branches (vectorized, with the
  // square roots of single precision), then kept. Also gives the number of
  // nodes within L of u, in B_P or not.
  std::size_t add_spans(const Eigen::Vector3f& u, const Eigen::Vector3f& shift, Span* out,
                        std::int32_t& nodes_in_small_ball)
  {
    const std::int32_t R = std::int32_t(m_c) * L, D = 2 * R + 1;
    const float squared_small = float(L * L), squared_ball = float(R) * float(R);
    const std::int32_t base_y = floor_to_int(u.y()), base_z = floor_to_int(u.z());
    const float ux = u.x(), fy = u.y() - float(base_y), fz = u.z() - float(base_z);
    const float by = float(base_y) + shift.y(), bz = float(base_z) + shift.z();
    const Candidate_offsets& offsets = candidate_offsets();
    float in_small[candidate_rows], in_ball[candidate_rows], half_small[candidate_rows], half_ball[candidate_rows];
    std::int32_t row[candidate_rows], first[candidate_rows], end[candidate_rows], kept[candidate_rows];
    std::int32_t nodes[candidate_rows]; // of the small ball, in B_P or not
    for(std::int32_t k = 0; k < candidate_rows; ++k)
    {
      // Within L of u: x in [ux - half_small, ux + half_small].
      const float ry = offsets.y[k] - fy, rz = offsets.z[k] - fz;
      in_small[k] = squared_small - ry * ry - rz * rz;
      // In B_P: x + shift.x in [-half_ball, half_ball].
      const float y = offsets.y[k] + by, z = offsets.z[k] + bz;
      in_ball[k] = squared_ball - y * y - z * z;
    }
    // Eigen's square roots are vectorized (std::sqrt() is not, as it may
    // set errno).
    typedef Eigen::Array<float, candidate_rows, 1> Candidates;
    Eigen::Map<Candidates> half_small_map(half_small), half_ball_map(half_ball);
    half_small_map = Eigen::Map<const Candidates>(in_small).max(0.f).sqrt();
    half_ball_map = Eigen::Map<const Candidates>(in_ball).max(0.f).sqrt();
    for(std::int32_t k = 0; k < candidate_rows; ++k)
    {
      const std::int32_t small_first = ceil_to_int(ux - half_small[k]), small_last = floor_to_int(ux + half_small[k]);
      nodes[k] = (in_small[k] >= 0) ? small_last - small_first + 1 : 0;
      // In B_P, and in [-R, R]^3 whatever the rounding.
      const std::int32_t x_first = (std::max)((std::max)(small_first, ceil_to_int(-half_ball[k] - shift.x())), -R);
      const std::int32_t x_last = (std::min)((std::min)(small_last, floor_to_int(half_ball[k] - shift.x())), R);
      const std::int32_t y = base_y + offsets.y_int[k], z = base_z + offsets.z_int[k];
      const bool is_kept = (in_small[k] >= 0) & (in_ball[k] >= 0) & (x_first <= x_last) & (y >= -R) & (y <= R) &
                           (z >= -R) & (z <= R);
      kept[k] = std::int32_t(is_kept);
      // A row without nodes is left unchanged below: a row of its own, not
      // the same one each time (no chain of stores and loads).
      row[k] = is_kept ? (y + R) * D + z + R : D * D + k;
      first[k] = is_kept ? x_first + R : no_node;
      end[k] = is_kept ? x_last + R + 1 : 0;
    }
    nodes_in_small_ball = 0;
    for(std::int32_t k = 0; k < candidate_rows; ++k)
      nodes_in_small_ball += nodes[k];
    // The spans; each row keeps its first and last node, and a row met for
    // the first time is listed (the others are written over).
    std::size_t spans = 0;
    Row_extent* extents = m_row_extents.data();
    std::uint32_t* touched_rows = m_touched_rows.data();
    std::uint32_t touched = m_touched;
    for(std::int32_t k = 0; k < candidate_rows; ++k)
    {
      const std::uint32_t r = std::uint32_t(row[k]);
      out[spans] = Span{ r, first[k], end[k] };
      spans += std::size_t(kept[k]);
      Row_extent extent = extents[r];
      touched_rows[touched] = r;
      touched += std::uint32_t(kept[k] & (extent.first == no_node));
      extent.first = extent.first < first[k] ? extent.first : first[k];
      extent.end = extent.end > end[k] ? extent.end : end[k];
      extents[r] = extent;
    }
    m_touched = touched;
    return spans;
  }

  unsigned int m_c;
  Instruction_set m_instruction_set;
  std::vector<Row_extent> m_row_extents;            // per row: its stored nodes, { no_node, 0 } between neighborhoods
  std::vector<std::int32_t> m_row_base;             // per row: the place of its node 0
  std::vector<std::uint32_t> m_touched_rows;        // the rows with spans, the first m_touched
  std::uint32_t m_touched = 0;
  std::vector<Span> m_spans;                        // of all points, point by point
  std::vector<std::uint32_t> m_first_span;          // per point, and the end
  std::vector<std::int32_t> m_nodes_in_small_ball;  // per point
  std::vector<std::uint32_t> m_span_places;         // per span: the places of its first node and past its last
  std::vector<std::int32_t> m_changes_of_m;         // per place
  std::vector<std::uint64_t> m_prefix_sums;         // per place, and one more
  std::vector<std::uint64_t> m_inverse;             // 2^32 / m, 0 for m = 0
  std::vector<double> m_scaled;                     // probabilities times n
  Weighted_points_sampler m_points;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_UNIF_SAMPLER_H
