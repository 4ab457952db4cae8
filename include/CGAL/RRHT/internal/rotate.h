// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A neighborhood seen by a randomly rotated accumulator (paper, Section 4).

#ifndef CGAL_RRHT_INTERNAL_ROTATE_H
#define CGAL_RRHT_INTERNAL_ROTATE_H

#include <CGAL/RRHT/internal/Instruction_set.h>

#include <CGAL/assertions.h>

#include <Eigen/Core>

#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// `points` multiplied by `matrix`, in single precision, into `out` (of the
/// same size). Each coordinate is (m_i0 x + m_i1 y) + m_i2 z in double
/// precision, as Eigen's product computes it (the same floats: tested), and
/// the same bits with the loop of each instruction set (`Instruction_set.h`).
/// For AVX2 the loop is vectorized over 4 points. It runs for every
/// accumulator.
inline void rotate(const std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& matrix,
                   std::vector<Eigen::Vector3f>& out, Instruction_set instruction_set)
{
  CGAL_precondition(out.size() == points.size());
  // The coordinates of the points one after the other (Eigen's fixed-size
  // vectors hold their coefficients and nothing else).
  const Eigen::Map<const Eigen::Matrix3Xd> in(points.data()->data(), 3, Eigen::Index(points.size()));
  Eigen::Map<Eigen::Matrix3Xf> rotated(out.data()->data(), 3, Eigen::Index(out.size()));
  const double m00 = matrix(0, 0), m01 = matrix(0, 1), m02 = matrix(0, 2), m10 = matrix(1, 0), m11 = matrix(1, 1),
               m12 = matrix(1, 2), m20 = matrix(2, 0), m21 = matrix(2, 1), m22 = matrix(2, 2);
  run_with(instruction_set, [&] {
    for(Eigen::Index i = 0; i < in.cols(); ++i)
    {
      const double x = in(0, i), y = in(1, i), z = in(2, i);
      rotated(0, i) = float(m00 * x + m01 * y + m02 * z);
      rotated(1, i) = float(m10 * x + m11 * y + m12 * z);
      rotated(2, i) = float(m20 * x + m21 * y + m22 * z);
    }
  });
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ROTATE_H
