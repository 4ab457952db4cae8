// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// RRHT_Points (paper, Section 5): triples drawn uniformly among the
// neighbors, never the same triple twice within one run.

#ifndef CGAL_RRHT_INTERNAL_POINTS_SAMPLER_H
#define CGAL_RRHT_INTERNAL_POINTS_SAMPLER_H

#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Triple.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Draws distinct triples of a neighborhood of `n` points, uniformly and
/// without repetition until `start_run()` is called again, in one of three
/// ways chosen by how many triples the neighborhood has against how many a
/// run may draw (max_draws, T_R):
///
/// - list: when C(n,3) <= `list_factor` max_draws, the triples are all
///   listed once and handed out in a random order (a Fisher-Yates shuffle
///   done lazily, one swap per draw), so that a run of C(n,3) draws sees
///   every triple exactly once. Drawing at random and again on a repeat
///   would draw up to C(n,3) ln(C(n,3) / (C(n,3) - max_draws)) triples,
///   2.2 max_draws for C(n,3) = 1.2 max_draws.
/// - bitmap and filter: otherwise a triple is drawn uniformly and drawn
///   again if this run has drawn it already, which a bit per triple of the
///   neighborhood (indexed by the triple's rank) answers when C(n,3) <
///   `bitmap_factor` max_draws, and otherwise a Bloom filter, in front of
///   the list of the run's triples for the few triples it lets through
///   (repeats and false positives). Both give the same triples.
///
/// Triples are drawn in batches (`draw()`). In the last two ways and when
/// n <= 2^12 (`Random::max_range16`), a triple costs one 64-bit random word
/// (three 16-bit numbers), computed in vectorized loops without branches
/// (`compute_candidates()`), which also have an AVX2 version
/// (`Instruction_set.h`) that draws the same triples. Larger neighborhoods
/// draw three numbers with `Random::uniform_index()`.
///
/// Memory, kept from one point to the next: the list, 12 bytes per triple
/// (up to 48 max_draws bytes); the bitmap, up to 32 max_draws bytes; the
/// filter, 4 bytes per draw rounded up to a power of 2 and 8 per key.
class Points_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the triples are the same
  /// with each, see `Instruction_set.h`).
  explicit Points_sampler(Instruction_set instruction_set = best_instruction_set())
    : m_instruction_set(instruction_set)
  {}

  /// Prepares the runs on a neighborhood of `n` points, each of at most
  /// `max_draws` triples.
  void prepare(std::uint32_t n, std::size_t max_draws)
  {
    m_n = n;
    m_triples = number_of_triples(n);
    if(n < 3 || m_triples <= list_factor * max_draws)
    {
      m_mode = Mode::list;
      m_all.clear();
      for(std::uint32_t c = 2; c < n; ++c)
        for(std::uint32_t b = 1; b < c; ++b)
          for(std::uint32_t a = 0; a < b; ++a)
            m_all.push_back(Triple{{a, b, c}});
      return;
    }
    if(n <= bitmap_limit && m_triples < bitmap_factor * max_draws)
    {
      m_mode = Mode::bitmap;
      m_bitmap.resize(std::size_t((m_triples + 31) / 32));
    }
    else
    {
      m_mode = Mode::filter;
      unsigned int filter_bits_log2 = 6; // 32 bits per draw, rounded up to a power of 2
      while((std::size_t(1) << filter_bits_log2) < 32 * max_draws && filter_bits_log2 < 32)
        ++filter_bits_log2;
      m_filter.resize((std::size_t(1) << filter_bits_log2) / 32);
      m_filter_shift = 32 - (filter_bits_log2 - 5);
      m_keys.resize(max_draws);
    }
    for(std::int32_t i = 0; i < 3; ++i)
      m_rejection_threshold[i] = (n <= Random::max_range16) ? Random::rejection_threshold16(n - i) : 0;
  }

  void start_run()
  {
    m_next = 0;
    if(m_mode == Mode::bitmap)
      std::fill(m_bitmap.begin(), m_bitmap.end(), std::uint32_t(0));
    else if(m_mode == Mode::filter)
      std::fill(m_filter.begin(), m_filter.end(), std::uint32_t(0));
    m_drawn = 0;
  }

  /// Writes the next `count` triples of this run to `out`; returns how many
  /// were written, fewer when every triple has been drawn.
  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    if(m_mode == Mode::list)
    {
      count = (std::min)(count, m_all.size() - m_next);
      for(std::size_t i = 0; i < count; ++i, ++m_next)
      {
        // The drawn triple is written out from a register: read back from
        // m_all, where three stores have just put it, it would wait for them.
        const std::size_t j = m_next + rng.uniform_index(std::uint32_t(m_all.size() - m_next));
        const Triple drawn = m_all[j];
        m_all[j] = m_all[m_next];
        m_all[m_next] = drawn;
        out[i] = drawn;
      }
      return count;
    }
    if(m_n > Random::max_range16) // never in bitmap mode (`bitmap_limit`)
    {
      for(std::size_t i = 0; i < count; ++i)
        do
          out[i] = draw_triple(rng);
        while(!insert(key(out[i])));
      return count;
    }
    run_with(m_instruction_set, [&] { draw_in_chunks(rng, count, out); });
    return count;
  }

private:
  enum class Mode
  {
    list,    // every triple listed, handed out in a random order
    bitmap,  // a bit per triple of the neighborhood, by rank
    filter   // the keys of the drawn triples, behind a Bloom filter
  };

  static std::uint64_t number_of_triples(std::uint64_t n)
  {
    if(n >= (1u << 21)) // C(n,3) beyond 2^60: more than any run draws
      return ~std::uint64_t(0);
    return n * (n - 1) * (n - 2) / 6;
  }

  // Three distinct indices, sorted, from a in [0, n), b in [0, n-1) and c in
  // [0, n-2) uniform: b and c are shifted past the indices already taken.
  // Branch-free, on 32-bit integers of either sign, so that the loop of
  // `compute_candidates()` vectorizes through it.
  template <typename Integer>
  static void distinct_and_sorted(Integer a, Integer b, Integer c, Integer& first, Integer& middle, Integer& last)
  {
    b += (b >= a);
    const Integer low = a < b ? a : b, high = a < b ? b : a;
    c += (c >= low);
    c += (c >= high);
    first = low < c ? low : c;
    last = high < c ? c : high;
    middle = low + high + c - first - last;
  }

  // The first `size` candidates of a chunk, when n <= 2^12: from one random
  // word each, three 16-bit numbers to which Lemire's method gives a in
  // [0, n), b in [0, n-1), c in [0, n-2) (rejected with probability below
  // 3 n / 2^16), made distinct and sorted, then their word and bit of the
  // bitmap or their key. In 32-bit integers (products below 2^28, ranks
  // below 2^32) and without branches, so that the loops are vectorized.
  void compute_candidates(Random& rng, std::size_t size)
  {
    rng.split_words(size, m_low_bits, m_high_bits);
    const std::int32_t n = std::int32_t(m_n);
    const std::int32_t threshold_a = m_rejection_threshold[0], threshold_b = m_rejection_threshold[1],
                       threshold_c = m_rejection_threshold[2];
    for(std::size_t i = 0; i < size; ++i)
    {
      std::int32_t a, b, c;
      m_accepted[i] = std::int32_t(Random::draw16(m_low_bits[i], n, threshold_a, a)) &
                      std::int32_t(Random::draw16(m_low_bits[i] >> 16, n - 1, threshold_b, b)) &
                      std::int32_t(Random::draw16(m_high_bits[i], n - 2, threshold_c, c));
      distinct_and_sorted(a, b, c, m_first[i], m_middle[i], m_last[i]);
    }
    if(m_mode == Mode::bitmap)
      for(std::size_t i = 0; i < size; ++i)
      {
        const std::uint32_t first = std::uint32_t(m_first[i]), middle = std::uint32_t(m_middle[i]),
                            last = std::uint32_t(m_last[i]);
        const std::uint32_t rank = last * (last - 1) * (last - 2) / 6 + middle * (middle - 1) / 2 + first;
        m_word[i] = rank / 32;
        m_bit[i] = std::uint32_t(m_accepted[i]) << (rank % 32); // none if rejected
      }
    else
      for(std::size_t i = 0; i < size; ++i)
      {
        const std::uint32_t hash = (std::uint32_t(m_first[i]) * 0x9E3779B1u) ^
                                   (std::uint32_t(m_middle[i]) * 0x85EBCA77u) ^ (std::uint32_t(m_last[i]) * 0xC2B2AE3Du);
        m_word[i] = filter_word(hash);
        m_bit[i] = filter_bits(hash);
        m_key[i] = exact_key(candidate(i));
      }
  }

  Triple candidate(std::size_t i) const
  {
    return Triple{{ std::uint32_t(m_first[i]), std::uint32_t(m_middle[i]), std::uint32_t(m_last[i]) }};
  }

  // When n <= 2^12: the candidates of the random stream, examined in order,
  // in chunks sized by how many are expected to be needed; those neither
  // rejected nor drawn already are kept. The stream then moves past the
  // candidates examined, so the triples do not depend on the chunks.
  void draw_in_chunks(Random& rng, std::size_t count, Triple* out)
  {
    Random ahead = rng;
    std::size_t examined = 0;
    for(std::size_t kept = 0; kept < count;)
    {
      // Each candidate is new with probability (triples left) / (triples):
      // the chunk is that many, rounded up to whole vectors.
      const std::uint64_t wanted = count - kept, left = m_triples - m_drawn;
      const std::size_t expected = std::size_t((wanted * m_triples + left - 1) / left);
      const std::size_t size = (std::min)(chunk, (expected + 7) & ~std::size_t(7));
      compute_candidates(ahead, size);
      std::size_t i = 0;
      if(m_mode == Mode::bitmap)
        for(; i < size && kept < count; ++i)
        {
          std::uint32_t& word = m_bitmap[m_word[i]];
          const bool is_new = (m_bit[i] & ~word) != 0;
          word |= m_bit[i];
          out[kept] = candidate(i);
          kept += is_new;
          m_drawn += is_new;
        }
      else
        for(; i < size && kept < count; ++i)
          if(m_accepted[i] != 0 && insert(m_key[i], m_word[i], m_bit[i]))
            out[kept++] = candidate(i);
      examined += i;
    }
    rng.discard(examined);
  }

  // A uniform triple for any n.
  Triple draw_triple(Random& rng) const
  {
    const std::uint32_t a = rng.uniform_index(m_n), b = rng.uniform_index(m_n - 1), c = rng.uniform_index(m_n - 2);
    Triple t;
    distinct_and_sorted(a, b, c, t[0], t[1], t[2]);
    return t;
  }

  // The triple itself, when its indices fit in 21 bits.
  static std::uint64_t exact_key(const Triple& t)
  {
    return std::uint64_t(t[0]) | (std::uint64_t(t[1]) << 21) | (std::uint64_t(t[2]) << 42);
  }

  // The exact triple when indices fit in 21 bits, else a 64-bit mix of it:
  // two draws of one triple always have the same key, so a repeat is never
  // let through (a rare collision of two different triples only costs a
  // redraw).
  static std::uint64_t key(const Triple& t)
  {
    if(t[2] < (1u << 21))
      return exact_key(t);
    Random mixer(t[0] | (std::uint64_t(t[1]) << 32), t[2]);
    return mixer();
  }

  // The filter: a 32-bit hash of a triple picks a word (its high bits) and
  // two bits of it (its 10 low bits), which answer "never drawn" for all but
  // a few in a thousand of the new triples; only those, and the repeats,
  // are looked up in the list of keys.
  std::uint32_t filter_word(std::uint32_t hash) const { return hash >> m_filter_shift; }
  static std::uint32_t filter_bits(std::uint32_t hash) { return (1u << (hash & 31u)) | (1u << ((hash >> 5) & 31u)); }

  // Adds `key`, whose hash gives `word` and `bits` of the filter; false if
  // this run has drawn it already.
  bool insert(std::uint64_t key, std::uint32_t word, std::uint32_t bits)
  {
    const auto drawn = m_keys.begin() + std::ptrdiff_t(m_drawn);
    if((m_filter[word] & bits) == bits && std::find(m_keys.begin(), drawn, key) != drawn)
      return false;
    m_filter[word] |= bits;
    *drawn = key;
    ++m_drawn;
    return true;
  }

  bool insert(std::uint64_t key)
  {
    const std::uint32_t hash = std::uint32_t((key * 0x9E3779B97F4A7C15ull) >> 32);
    return insert(key, filter_word(hash), filter_bits(hash));
  }

  // Up to this many triples per draw of a run, listing them is faster than
  // drawing at random; the `speed` benchmark's time against k checks it.
  static constexpr std::uint64_t list_factor = 4;
  // Up to this many bits per draw of a run, the bitmap, cleared at each
  // run, is faster than the filter (same check).
  static constexpr std::uint64_t bitmap_factor = 256;
  // Ranks computed in 32 bits: last * (last - 1) * (last - 2) below 2^32.
  static constexpr std::uint32_t bitmap_limit = 1024;
  static constexpr std::size_t chunk = triples_per_chunk;

  Instruction_set m_instruction_set;
  std::uint32_t m_n = 0;
  std::uint64_t m_triples = 0;
  Mode m_mode = Mode::list;
  std::vector<Triple> m_all;           // list: every triple, the first m_next handed out
  std::size_t m_next = 0;
  std::vector<std::uint32_t> m_bitmap; // bitmap: the run's triples
  std::vector<std::uint64_t> m_keys;   // filter: the run's triples, the first m_drawn
  std::vector<std::uint32_t> m_filter; // and their filter
  unsigned int m_filter_shift = 31;    // 32 - log2 of the filter's words
  std::size_t m_drawn = 0;             // bitmap and filter: the run's triples
  std::int32_t m_rejection_threshold[3] = { 0, 0, 0 };
  // A chunk of candidates: random bits, triple, accepted (0 or 1), then
  // word and bit(s) of the bitmap or the filter, and key.
  std::uint32_t m_low_bits[chunk], m_high_bits[chunk];
  std::int32_t m_first[chunk], m_middle[chunk], m_last[chunk], m_accepted[chunk];
  std::uint32_t m_word[chunk], m_bit[chunk];
  std::uint64_t m_key[chunk];
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_POINTS_SAMPLER_H
