// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triples of distinct points drawn with given probabilities (Walker's alias
// method): the draws of RRHT_Cubes and RRHT_Unif (paper, Section 5), whose
// spatially uniform procedures give each neighbor a fixed probability.

#ifndef CGAL_RRHT_INTERNAL_WEIGHTED_POINTS_SAMPLER_H
#define CGAL_RRHT_INTERNAL_WEIGHTED_POINTS_SAMPLER_H

#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>
#include <CGAL/RRHT/internal/draw_distinct_triple.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Draws the points of a neighborhood of n points, point i with a given
/// probability p_i, and triples of distinct points from these draws
/// (`draw_distinct_triple()`).
///
/// A point is drawn in constant time with Walker's alias method: one random
/// word gives a point and whether to keep it or take its alias, with one
/// table read. A draw costs one random word, for neighborhoods of at most
/// 2^12 points (`Random::max_range16`): 16 bits for the point (Lemire's method,
/// rejected with probability below n / 2^16) and 30 bits for the choice of
/// its alias. `draw()` computes the three draws of 64 triples at a time
/// with loops without branches, which the compiler vectorizes (and compiles
/// for AVX2, see `Instruction_set.h`), and goes on drawing only for the few
/// triples whose three draws are not distinct (see `draw_triples()`).
/// `prepare()` makes the alias table without branches on the
/// probabilities, which would be mispredicted at random.
class Weighted_points_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the triples are the same
  /// with each, see `Instruction_set.h`).
  explicit Weighted_points_sampler(Instruction_set instruction_set = best_instruction_set())
    : m_instruction_set(instruction_set)
  {}

  /// Makes the table for the n points whose probabilities times n (a mean
  /// of 1) are `scaled`; uses `scaled` up.
  void prepare(std::vector<double>& scaled)
  {
    m_n = std::uint32_t(scaled.size());
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
      const bool small = scaled[i] < 1;
      m_small[smalls] = i;
      m_large[larges] = i;
      smalls += small;
      larges += !small;
    }
    while(smalls != 0 && larges != 0)
    {
      const std::uint32_t small = m_small[--smalls], large = m_large[larges - 1];
      m_keep[small] = static_cast<std::int32_t>(scaled[small] * always_keep);
      m_alias[small] = std::int32_t(large);
      scaled[large] -= 1 - scaled[small];
      // If the large one is now small, it moves to the other list.
      const bool now_small = scaled[large] < 1;
      m_small[smalls] = large;
      smalls += now_small;
      larges -= now_small;
    }
    for(std::uint32_t s = 0; s < smalls; ++s) // 1 up to rounding
      set_always_kept(m_small[s]);
    for(std::uint32_t l = 0; l < larges; ++l)
      set_always_kept(m_large[l]);
    m_rejection_threshold = (m_n != 0 && m_n <= Random::max_range16) ? Random::rejection_threshold16(m_n) : 0;
  }

  /// Writes `count` triples of distinct points to `out`; returns `count`.
  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    if(m_n > Random::max_range16)
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
    if(m_n > Random::max_range16)
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

  // The triples of `draw()` when n <= Random::max_range16, a chunk of T triples at
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
    std::uint32_t low_bits[3 * triples_per_chunk], high_bits[3 * triples_per_chunk];
    std::int32_t point[3 * triples_per_chunk], accepted[3 * triples_per_chunk];
    std::int32_t is_triple[triples_per_chunk]; // its three draws are the triple
    const std::int32_t n = std::int32_t(m_n), threshold = m_rejection_threshold;
    const std::int32_t *keep = m_keep.data(), *alias = m_alias.data();
    for(std::size_t written = 0; written < count;)
    {
      const std::size_t triples = (std::min)(triples_per_chunk, count - written), draws = 3 * triples;
      rng.split_words(draws, low_bits, high_bits);
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
    Distinct_triple triple;
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

  Instruction_set m_instruction_set;
  std::uint32_t m_n = 0;
  std::vector<std::int32_t> m_keep, m_alias; // the alias table
  std::int32_t m_rejection_threshold = 0;
  std::vector<std::uint32_t> m_small, m_large; // Vose's work lists
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_WEIGHTED_POINTS_SAMPLER_H
