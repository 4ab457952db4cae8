// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A unit direction in 32 bits (beyond the paper): its octahedral
// coordinates, two 16-bit integers, for the per-point normals that the
// passes over a whole cloud keep, at a quarter of three doubles' memory.

#ifndef CGAL_RRHT_INTERNAL_PACKED_DIRECTION_H
#define CGAL_RRHT_INTERNAL_PACKED_DIRECTION_H

#include <Eigen/Core>

#include <cmath>
#include <cstdint>

namespace CGAL {
namespace RRHT {
namespace internal {

/// A unit direction in octahedral coordinates: projected on the octahedron
/// |x| + |y| + |z| = 1, whose lower half is folded over the upper one, and
/// the square [-1, 1]^2 so obtained sampled by 65536 x 65536 values. The
/// direction read back is within 0.005 degrees of the one written.
class Packed_direction
{
public:
  Packed_direction() = default;

  /// Packs the direction of `d`, not null and finite.
  explicit Packed_direction(const Eigen::Vector3d& d)
  {
    const double l1 = std::abs(d.x()) + std::abs(d.y()) + std::abs(d.z());
    double u = d.x() / l1, v = d.y() / l1;
    if(d.z() < 0)
      fold(u, v);
    bits_ = (std::uint32_t(quantize(u)) << 16) | quantize(v);
  }

  /// The unit direction.
  Eigen::Vector3d direction() const
  {
    double u = unquantize(std::uint16_t(bits_ >> 16)), v = unquantize(std::uint16_t(bits_ & 0xffffu));
    const double z = 1 - std::abs(u) - std::abs(v);
    if(z < 0)
      fold(u, v);
    return Eigen::Vector3d(u, v, z).normalized();
  }

private:
  static double sign(double x) { return x < 0 ? -1. : 1.; }
  // Folds the lower half of the octahedron over the upper one, and back:
  // the map is its own inverse.
  static void fold(double& u, double& v)
  {
    const double fu = (1 - std::abs(v)) * sign(u), fv = (1 - std::abs(u)) * sign(v);
    u = fu, v = fv;
  }
  static std::uint16_t quantize(double x) { return std::uint16_t(std::lround((x + 1) * 0.5 * 65535)); }
  static double unquantize(std::uint16_t q) { return double(q) / 65535 * 2 - 1; }

  std::uint32_t bits_ = 0;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PACKED_DIRECTION_H
