// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Points (paper, Section 5): triples drawn uniformly among the
// neighbors, never the same triple twice within one run.

#ifndef CGAL_RRHT_POINTS_SAMPLING_H
#define CGAL_RRHT_POINTS_SAMPLING_H

#include <CGAL/RRHT/Random.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {

/// Three distinct indices into a neighborhood.
typedef std::array<std::uint32_t, 3> Triple;

/// Draws distinct triples of a neighborhood of `n` points, uniformly and
/// without repetition until `start_run()` is called again.
///
/// - When the neighborhood has no more triples than the run may draw
///   (C(n,3) <= max_draws), they are all listed once and handed out in a
///   random order (a Fisher-Yates shuffle done lazily, one swap per draw), so
///   that a run ends having seen every triple exactly once.
/// - Otherwise a triple is drawn uniformly and redrawn if this run has
///   already drawn it, as recorded in a small open-addressing hash set whose
///   slots are stamped with the run number, so that starting a run clears
///   nothing.
///
/// Memory, kept from one point to the next: 12 bytes per triple in the first
/// case, 12 bytes per slot of the hash set (2 max_draws rounded up to a power
/// of 2) in the second.
class Points_sampler
{
public:
  void prepare(std::uint32_t n, std::size_t max_draws)
  {
    m_n = n;
    m_enumerate = (n < 3) || number_of_triples(n) <= max_draws;
    if(m_enumerate)
    {
      m_all.clear();
      for(std::uint32_t c = 2; c < n; ++c)
        for(std::uint32_t b = 1; b < c; ++b)
          for(std::uint32_t a = 0; a < b; ++a)
            m_all.push_back(Triple{{a, b, c}});
    }
    else
    {
      std::size_t size = 16;
      while(size < 2 * max_draws)
        size *= 2;
      if(m_keys.size() < size)
      {
        m_keys.assign(size, 0);
        m_stamps.assign(size, 0);
        m_run = 0;
      }
      m_mask = m_keys.size() - 1;
    }
  }

  void start_run()
  {
    m_next = 0;
    if(!m_enumerate && ++m_run == 0) // stamps wrapped around: really clear
    {
      std::fill(m_stamps.begin(), m_stamps.end(), 0u);
      m_run = 1;
    }
  }

  /// Writes the next triple in `t`; false when every triple has been drawn.
  bool draw(Random& rng, Triple& t)
  {
    if(m_enumerate)
    {
      if(m_next == m_all.size())
        return false;
      std::swap(m_all[m_next], m_all[m_next + rng.uniform_index(std::uint32_t(m_all.size() - m_next))]);
      t = m_all[m_next++];
      return true;
    }
    for(;;)
    {
      std::uint32_t a = rng.uniform_index(m_n);
      std::uint32_t b = rng.uniform_index(m_n - 1);
      std::uint32_t c = rng.uniform_index(m_n - 2);
      // Three distinct indices, uniformly: shift past the ones already taken.
      if(b >= a) ++b;
      const std::uint32_t lo = (std::min)(a, b), hi = (std::max)(a, b);
      if(c >= lo) ++c;
      if(c >= hi) ++c;
      t = Triple{{a, b, c}};
      std::sort(t.begin(), t.end());
      if(insert(key(t)))
        return true;
    }
  }

private:
  static std::uint64_t number_of_triples(std::uint64_t n)
  {
    if(n >= (1u << 21)) // C(n,3) beyond 2^60: more than any run draws
      return ~std::uint64_t(0);
    return n * (n - 1) * (n - 2) / 6;
  }

  // The exact triple when indices fit in 21 bits, else a 64-bit mix of it: two
  // draws of one triple always have the same key, so a repeat is never let
  // through (a rare collision of two different triples only costs a redraw).
  static std::uint64_t key(const Triple& t)
  {
    if(t[2] < (1u << 21))
      return std::uint64_t(t[0]) | (std::uint64_t(t[1]) << 21) | (std::uint64_t(t[2]) << 42);
    Random mixer(t[0] | (std::uint64_t(t[1]) << 32), t[2]);
    return mixer();
  }

  // Inserts `k` in this run's set; false if it was there already.
  bool insert(std::uint64_t k)
  {
    std::size_t slot = std::size_t((k * 0x9E3779B97F4A7C15ull) >> 17) & m_mask;
    while(m_stamps[slot] == m_run)
    {
      if(m_keys[slot] == k)
        return false;
      slot = (slot + 1) & m_mask;
    }
    m_stamps[slot] = m_run;
    m_keys[slot] = k;
    return true;
  }

  std::uint32_t m_n = 0;
  bool m_enumerate = true;
  std::vector<Triple> m_all;
  std::size_t m_next = 0;
  std::vector<std::uint64_t> m_keys;
  std::vector<std::uint32_t> m_stamps;
  std::uint32_t m_run = 0;
  std::size_t m_mask = 0;
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_POINTS_SAMPLING_H
