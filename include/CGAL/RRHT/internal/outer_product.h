// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sums of outer products that covariance matrices are made of.

#ifndef CGAL_RRHT_INTERNAL_OUTER_PRODUCT_H
#define CGAL_RRHT_INTERNAL_OUTER_PRODUCT_H

#include <Eigen/Core>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Adds the outer product a b^T to `sum`, entry by entry, as Eigen's
/// `sum += a * b.transpose()` does, to the same bits: GCC compiles Eigen's
/// own into stores of the columns that the next additions read back as
/// wider loads, which stalls each on the stores.
inline void add_outer_product(Eigen::Matrix3d& sum, const Eigen::Vector3d& a, const Eigen::Vector3d& b)
{
  for(int c = 0; c < 3; ++c)
    for(int r = 0; r < 3; ++r)
      sum(r, c) += b[c] * a[r];
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_OUTER_PRODUCT_H
