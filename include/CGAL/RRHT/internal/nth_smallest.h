// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The n-th smallest of a neighborhood's values (the first quartile of its
// noise deviations and residuals), found without branches on their order.

#ifndef CGAL_RRHT_INTERNAL_NTH_SMALLEST_H
#define CGAL_RRHT_INTERNAL_NTH_SMALLEST_H

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The value at position `n` (below the size) of `values` once sorted,
/// which `std::nth_element()` would put there; reorders `values`.
///
/// Quickselect whose partitions have no branch on the values: a
/// neighborhood's values come in random order, so each comparison in the
/// partitions of `std::nth_element()` is a branch mispredicted half the
/// time, while here it only moves an index. Each round splits the range
/// about the median of three of its values into the values below, equal to
/// and above it. After 2 log2(size) rounds, as in introselect,
/// `std::nth_element()` finishes, so that no order of the values takes
/// quadratic time.
inline double nth_smallest(std::vector<double>& values, std::size_t n)
{
  double* const v = values.data();
  std::size_t first = 0, last = values.size();
  int rounds = 0;
  for(std::size_t size = last; size > 1; size /= 2)
    rounds += 2;
  while(last - first > 16)
  {
    if(rounds-- == 0)
    {
      std::nth_element(v + first, v + n, v + last);
      return v[n];
    }
    const double a = v[first], b = v[first + (last - first) / 2], c = v[last - 1];
    const double pivot = (std::max)((std::min)(a, b), (std::min)((std::max)(a, b), c));
    // [first, below) holds the values below the pivot, [below, i) the others.
    std::size_t below = first;
    for(std::size_t i = first; i < last; ++i)
    {
      const double x = v[i];
      v[i] = v[below];
      v[below] = x;
      below += (x < pivot);
    }
    if(n < below)
    {
      last = below;
      continue;
    }
    // [below, equal) holds the values equal to the pivot, one at least.
    std::size_t equal = below;
    for(std::size_t i = below; i < last; ++i)
    {
      const double x = v[i];
      v[i] = v[equal];
      v[equal] = x;
      equal += !(pivot < x);
    }
    if(n < equal)
      return v[n];
    first = equal;
  }
  std::sort(v + first, v + last);
  return v[n];
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NTH_SMALLEST_H
