// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reproducible randomness: one independent stream per point, so that the
// normals do not depend on how points are spread over threads.

#ifndef CGAL_RRHT_INTERNAL_RANDOM_H
#define CGAL_RRHT_INTERNAL_RANDOM_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <CGAL/number_type_config.h>

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace RRHT {
namespace internal {

/// A counter-based generator (SplitMix64, Steele, Lea and Flood 2014): the
/// k-th number of a stream is a bijective mix of `key + k * gamma`. The key of
/// a point's stream mixes the user's seed with the point's index, so each
/// point has its own stream whatever thread handles it. Neither the standard
/// library nor Boost 1.74 offers a counter-based generator; seeding a
/// std::mt19937 per point would cost 2.5 kB of state and 624 words of set-up.
/// Models the standard UniformRandomBitGenerator.
class Random
{
public:
  typedef std::uint64_t result_type;

  Random(std::uint64_t seed, std::uint64_t stream)
    : m_state(mix(mix(seed + golden_gamma) ^ (stream * 0xD1B54A32D192ED03ull)))
  {}

  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return ~result_type(0); }

  result_type operator()()
  {
    m_state += golden_gamma;
    return mix(m_state);
  }

  /// Moves the stream past its next `count` numbers, as if drawn (as the
  /// standard engines' `discard()`).
  void discard(std::uint64_t count) { m_state += count * golden_gamma; }

  /// Uniform integer in [0, n), n > 0, without bias (Lemire 2019, "Fast
  /// random integer generation in an interval": one multiplication instead
  /// of a division in the common case).
  std::uint32_t uniform_index(std::uint32_t n)
  {
    std::uint32_t x;
    while(!draw32(std::uint32_t((*this)() >> 32), n, x))
      ;
    return x;
  }

  /// The next `count` numbers of the stream, split into their low and high
  /// 32 bits: the random bits of the vectorized loops of the samplers.
  void split_words(std::size_t count, std::uint32_t* low, std::uint32_t* high)
  {
    for(std::size_t i = 0; i < count; ++i)
    {
      const std::uint64_t word = (*this)();
      low[i] = std::uint32_t(word);
      high[i] = std::uint32_t(word >> 32);
    }
  }

  /// Uniform double in [0, 1), from the 53 high bits.
  double uniform_real() { return double((*this)() >> 11) * 0x1.0p-53; }

  /// Uniform rotation of SO(3), from a uniform unit quaternion (Shoemake,
  /// "Uniform random rotations", Graphics Gems III, 1992).
  Eigen::Matrix3d uniform_rotation()
  {
    const double two_pi = 2 * CGAL_PI;
    const double u1 = uniform_real(), u2 = uniform_real(), u3 = uniform_real();
    const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
    const Eigen::Quaterniond q(a * std::sin(two_pi * u2), a * std::cos(two_pi * u2),
                               b * std::sin(two_pi * u3), b * std::cos(two_pi * u3));
    return q.normalized().toRotationMatrix();
  }

  /// Uniform integer in [0, range), range > 0, from 32 random bits
  /// (Lemire's method): sets x to (bits * range) >> 32 and returns false,
  /// with probability below range / 2^32, when the draw must be made again
  /// to stay unbiased. The division that finds the threshold is only made
  /// when the low bits of the product fall below range.
  static bool draw32(std::uint32_t bits, std::uint32_t range, std::uint32_t& x)
  {
    const std::uint64_t product = std::uint64_t(bits) * range;
    x = std::uint32_t(product >> 32);
    const std::uint32_t low = std::uint32_t(product);
    return low >= range || low >= std::uint32_t(-range) % range;
  }

  /// Uniform integers in [0, range) for range <= `max_range16` (2^12) from the 16 low bits
  /// of `bits` (Lemire's method on 16 bits), in 32-bit signed arithmetic
  /// (the product stays below 2^28) so that loops over them vectorize:
  /// `draw16(bits, range, rejection_threshold16(range), x)` sets x to
  /// ((bits mod 2^16) * range) >> 16 and returns false, with probability
  /// below range / 2^16, when the draw must be made again.
  static constexpr std::uint32_t max_range16 = 1u << 12;
  static std::int32_t rejection_threshold16(std::uint32_t range) { return std::int32_t((1u << 16) % range); }
  static bool draw16(std::uint32_t bits, std::int32_t range, std::int32_t threshold, std::int32_t& x)
  {
    const std::int32_t product = std::int32_t(bits & 0xFFFF) * range;
    x = product >> 16;
    return (product & 0xFFFF) >= threshold;
  }

private:
  static constexpr std::uint64_t golden_gamma = 0x9E3779B97F4A7C15ull;

  static std::uint64_t mix(std::uint64_t z)
  {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::uint64_t m_state;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_RANDOM_H
