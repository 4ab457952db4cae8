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
/// without repetition until `start_run()` is called again.
///
/// - When the neighborhood has no more triples than the run may draw
///   (C(n,3) <= max_draws), they are all listed once and handed out in a
///   random order (a Fisher-Yates shuffle done lazily, one swap per draw), so
///   that a run ends having seen every triple exactly once.
/// - Otherwise a triple is drawn uniformly and redrawn if this run has
///   already drawn it. The run's triples are kept in a list, and a bit
///   array of 32 bits per triple the run may draw (a blocked Bloom filter:
///   two bits in one 32-bit word per triple) answers "never drawn" for all
///   but a few in a thousand of the new triples; only those are looked up in
///   the list: one word read and a store per triple, cheaper than a hash set
///   (measured in `benchmark/results/targets/README.md`).
///
/// Triples are drawn in batches (`draw()`), with no call per triple through
/// the sampling mode. When n <= 2^12 (`small_limit`), a triple costs one
/// 64-bit random word (three 16-bit numbers), and is computed in a
/// vectorized loop without branches (see `draw_candidates()`): this loop
/// runs for every plane of the RRHT, and also has an AVX2 version, taken
/// when the processor has it (`Instruction_set.h`), which draws the same
/// triples. Larger neighborhoods draw three
/// numbers with `Random::uniform_index()`.
///
/// Memory, kept from one point to the next: 12 bytes per triple in the first
/// case, 8 bytes per triple and 4 bytes per triple of the filter (32
/// max_draws bits rounded up to a power of 2) in the second.
class Points_sampler
{
public:
  /// Draws with the loops of `instruction_set` (the triples are the same
  /// with each, see `Instruction_set.h`).
  explicit Points_sampler(Instruction_set instruction_set = best_instruction_set())
    : m_instruction_set(instruction_set)
  {}

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
      return;
    }
    unsigned int filter_bits_log2 = 6;
    while((std::size_t(1) << filter_bits_log2) < 32 * max_draws && filter_bits_log2 < 32)
      ++filter_bits_log2;
    m_filter.resize((std::size_t(1) << filter_bits_log2) / 32);
    m_filter_shift = 32 - (filter_bits_log2 - 5);
    m_keys.resize(max_draws);
    for(std::int32_t i = 0; i < 3; ++i)
      m_rejection_threshold[i] = (n <= small_limit) ? Random::rejection_threshold16(n - i) : 0;
  }

  void start_run()
  {
    m_next = 0;
    if(!m_enumerate)
    {
      std::fill(m_filter.begin(), m_filter.end(), std::uint32_t(0));
      m_drawn = 0;
    }
  }

  /// Writes the next `count` triples of this run to `out`; returns how many
  /// were written, fewer when every triple has been drawn.
  std::size_t draw(Random& rng, std::size_t count, Triple* out)
  {
    if(m_enumerate)
    {
      count = (std::min)(count, m_all.size() - m_next);
      for(std::size_t i = 0; i < count; ++i, ++m_next)
      {
        std::swap(m_all[m_next], m_all[m_next + rng.uniform_index(std::uint32_t(m_all.size() - m_next))]);
        out[i] = m_all[m_next];
      }
      return count;
    }
    Drawn_set drawn{ m_keys.data(), m_filter.data(), m_filter_shift, m_drawn };
    if(m_n > small_limit)
    {
      for(std::size_t i = 0; i < count; ++i)
        do
          out[i] = draw_triple(rng);
        while(!drawn.insert(key(out[i])));
      m_drawn = drawn.size;
      return count;
    }
    // Two passes over chunks of the batch: the candidate triples, in a
    // loop without branches on 32-bit integers that the compiler
    // vectorizes; then those that were neither rejected nor drawn already
    // are kept, in order, and the others are drawn again.
    for(std::size_t first = 0; first < count; first += chunk)
    {
      Triple* chunk_out = out + first;
      const std::size_t size = (std::min)(chunk, count - first);
      for(std::size_t kept = 0; kept < size;)
      {
        draw_candidates(rng, kept, size);
        for(std::size_t i = kept, end = size; i < end; ++i)
        {
          const Triple t = {{ std::uint32_t(m_first[i]), std::uint32_t(m_middle[i]), std::uint32_t(m_last[i]) }};
          if(m_accepted[i] != 0 && drawn.insert(m_key[i], m_filter_word[i], m_filter_bits[i]))
            chunk_out[kept++] = t;
        }
      }
    }
    m_drawn = drawn.size;
    return count;
  }

private:
  static std::uint64_t number_of_triples(std::uint64_t n)
  {
    if(n >= (1u << 21)) // C(n,3) beyond 2^60: more than any run draws
      return ~std::uint64_t(0);
    return n * (n - 1) * (n - 2) / 6;
  }

  // Three distinct indices, sorted, from a in [0, n), b in [0, n-1) and c in
  // [0, n-2) uniform: b and c are shifted past the indices already taken.
  // Branch-free, on 32-bit integers of either sign, so that the loop of
  // `draw_candidates()` vectorizes through it.
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

  // Candidates [begin, end) of a chunk, when n <= small_limit: from one
  // random word each, three 16-bit numbers to which Lemire's method gives
  // a in [0, n), b in [0, n-1), c in [0, n-2) (rejected with probability
  // below 3 n / 2^16), made distinct and sorted by `distinct_and_sorted()`,
  // with a 32-bit hash for the filter. All in 32-bit integers (products
  // below 2^28), without branches, so that the loops are vectorized.
  void draw_candidates(Random& rng, std::size_t begin, std::size_t end)
  {
    run_with(m_instruction_set, [&] { compute_candidates(rng, begin, end); });
  }

  void compute_candidates(Random& rng, std::size_t begin, std::size_t end)
  {
    for(std::size_t i = begin; i < end; ++i)
    {
      const std::uint64_t word = rng();
      m_low_bits[i] = std::uint32_t(word);
      m_high_bits[i] = std::uint32_t(word >> 32);
    }
    const std::int32_t n = std::int32_t(m_n);
    const std::int32_t threshold_a = m_rejection_threshold[0], threshold_b = m_rejection_threshold[1],
                       threshold_c = m_rejection_threshold[2];
    for(std::size_t i = begin; i < end; ++i)
    {
      std::int32_t a, b, c;
      m_accepted[i] = std::int32_t(Random::draw16(m_low_bits[i], n, threshold_a, a)) &
                      std::int32_t(Random::draw16(m_low_bits[i] >> 16, n - 1, threshold_b, b)) &
                      std::int32_t(Random::draw16(m_high_bits[i], n - 2, threshold_c, c));
      std::int32_t first, middle, last;
      distinct_and_sorted(a, b, c, first, middle, last);
      m_first[i] = first;
      m_middle[i] = middle;
      m_last[i] = last;
      m_hash[i] = (std::uint32_t(first) * 0x9E3779B1u) ^ (std::uint32_t(middle) * 0x85EBCA77u) ^
                  (std::uint32_t(last) * 0xC2B2AE3Du);
    }
    // The filter's word and bits of each candidate, in a loop of their own:
    // SSE2 has no shift by a different amount per lane, and the loop above
    // stays vectorized without them.
    const unsigned int shift = m_filter_shift;
    for(std::size_t i = begin; i < end; ++i)
    {
      m_filter_word[i] = Drawn_set::word_of(m_hash[i], shift);
      m_filter_bits[i] = Drawn_set::bits_of(m_hash[i]);
    }
    for(std::size_t i = begin; i < end; ++i)
      m_key[i] = exact_key(Triple{{ std::uint32_t(m_first[i]), std::uint32_t(m_middle[i]), std::uint32_t(m_last[i]) }});
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

  // The exact triple when indices fit in 21 bits, else a 64-bit mix of it: two
  // draws of one triple always have the same key, so a repeat is never let
  // through (a rare collision of two different triples only costs a redraw).
  static std::uint64_t key(const Triple& t)
  {
    if(t[2] < (1u << 21))
      return exact_key(t);
    Random mixer(t[0] | (std::uint64_t(t[1]) << 32), t[2]);
    return mixer();
  }

  // This run's triples (their keys) and their filter, for one batch, in
  // local variables: the stores to the triples and to the filter could
  // otherwise alias the members, which the compiler would reload after each.
  struct Drawn_set
  {
    std::uint64_t* keys;
    std::uint32_t* filter;
    unsigned int shift; // 32 - log2 of the filter's words
    std::size_t size;

    // A 32-bit hash of a triple picks a word of the filter (its high bits)
    // and two bits of it (its 10 low bits): a blocked Bloom filter, which
    // sends fewer new triples to the list than one bit per triple, for the
    // same memory and one read. With 32-bit words, the word and the bits are
    // computed in the vectorized loop for AVX2 (`vpsllvd`).
    static std::uint32_t word_of(std::uint32_t hash, unsigned int shift) { return hash >> shift; }
    static std::uint32_t bits_of(std::uint32_t hash) { return (1u << (hash & 31u)) | (1u << ((hash >> 5) & 31u)); }

    // Inserts `k`, whose hash gives `word` and `bits`; false if it was there
    // already.
    bool insert(std::uint64_t k, std::uint32_t word, std::uint32_t bits)
    {
      std::uint32_t& filter_word = filter[word];
      if((filter_word & bits) == bits && contains(keys, size, k))
        return false;
      filter_word |= bits;
      keys[size++] = k;
      return true;
    }

    // Whether `k` is among the first `size` keys: the rare case, when the
    // filter has the bits of `k` already, in a function of its own so that
    // the loop that calls `insert()` keeps its registers.
#if defined(__GNUC__)
    __attribute__((noinline))
#endif
    static bool contains(const std::uint64_t* keys, std::size_t size, std::uint64_t k)
    {
      return std::find(keys, keys + size, k) != keys + size;
    }

    bool insert(std::uint64_t k)
    {
      const std::uint32_t hash = std::uint32_t((k * 0x9E3779B97F4A7C15ull) >> 32);
      return insert(k, word_of(hash, shift), bits_of(hash));
    }
  };

  Instruction_set m_instruction_set;
  std::uint32_t m_n = 0;
  bool m_enumerate = true;
  std::vector<Triple> m_all;
  std::size_t m_next = 0;
  // Neighborhoods of at most 2^12 points take the vectorized draw (the
  // rejection rate of 16-bit numbers stays below 3 / 16 per triple).
  static constexpr std::uint32_t small_limit = 1u << 12;
  static constexpr std::size_t chunk = 64;
  // A chunk of candidates: random bits, triple, accepted (0 or 1), hash,
  // word and bits of the filter.
  std::uint32_t m_low_bits[chunk], m_high_bits[chunk];
  std::int32_t m_first[chunk], m_middle[chunk], m_last[chunk], m_accepted[chunk];
  std::uint32_t m_hash[chunk], m_filter_word[chunk], m_filter_bits[chunk];
  std::uint64_t m_key[chunk];
  std::vector<std::uint64_t> m_keys;   // this run's triples: the first m_drawn
  std::size_t m_drawn = 0;
  std::vector<std::uint32_t> m_filter; // and their bits
  unsigned int m_filter_shift = 31;
  std::int32_t m_rejection_threshold[3] = { 0, 0, 0 };
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_POINTS_SAMPLER_H
