// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triples of three distinct points from draws of single points, as the
// spatially uniform samplings (RRHT_Cubes, RRHT_Unif; paper, Section 5) make them.

#ifndef CGAL_RRHT_INTERNAL_DRAW_DISTINCT_TRIPLE_H
#define CGAL_RRHT_INTERNAL_DRAW_DISTINCT_TRIPLE_H

#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>

#include <cstdint>

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
/// Draws three distinct points of a neighborhood of `n` points with
/// `sampler.draw_point(rng)`, drawing again a point equal to one already
/// drawn; after `max_repeated_draws` such draws of one point, that
/// point is drawn uniformly among the others instead.
template <typename Sampler>
void draw_distinct_triple(Sampler& sampler, std::uint32_t n, Random& rng, Triple& t)
{
  Distinct_triple triple;
  while(!triple.add(sampler.draw_point(rng), n, rng))
    ;
  t = triple.triple();
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_DRAW_DISTINCT_TRIPLE_H
