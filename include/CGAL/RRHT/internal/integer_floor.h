// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Floor and ceiling to integers in loops that the compiler vectorizes.

#ifndef CGAL_RRHT_INTERNAL_INTEGER_FLOOR_H
#define CGAL_RRHT_INTERNAL_INTEGER_FLOOR_H

#include <cstdint>

namespace CGAL {
namespace RRHT {
namespace internal {

/// floor(x) and ceil(x) as integers, for |x| < 2^31: the truncation,
/// corrected. `std::floor()` has no SSE2 instruction (it is a call), which
/// would keep the loops of the grids of RRHT_Cubes and RRHT_Unif from being
/// vectorized.
template <typename Scalar>
std::int32_t floor_to_int(Scalar x)
{
  const std::int32_t t = std::int32_t(x);
  return t - std::int32_t(Scalar(t) > x);
}

template <typename Scalar>
std::int32_t ceil_to_int(Scalar x)
{
  const std::int32_t t = std::int32_t(x);
  return t + std::int32_t(Scalar(t) < x);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_INTEGER_FLOOR_H
