// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks of the parameters of `CGAL::rrht_estimate_normals()`, made before
// anything is written.

#ifndef CGAL_RRHT_INTERNAL_CHECK_PARAMETERS_H
#define CGAL_RRHT_INTERNAL_CHECK_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace CGAL {
template <typename Point, typename Vector> class Point_set_3;

namespace RRHT {
namespace internal {

/// Throws `std::invalid_argument` with `message` unless `condition` holds.
inline void check(bool condition, const std::string& message)
{
  if(!condition)
    throw std::invalid_argument("CGAL::rrht_estimate_normals(): " + message);
}

/// A count given as any arithmetic type, checked to lie in [low, high]
/// before it is converted (so that -1 is not taken for a huge unsigned).
/// The bounds are far below 2^53, so the comparison in double is exact.
template <typename Count, typename T>
Count count_in_range(const T& value, std::uint64_t low, std::uint64_t high, const std::string& what)
{
  static_assert(std::is_arithmetic<T>::value, "a count must be given as a number");
  const double as_double = static_cast<double>(value);
  check(as_double >= double(low) && as_double <= double(high), // false for NaN
        what + " must be from " + std::to_string(low) + " to " + std::to_string(high));
  return static_cast<Count>(value);
}

/// Whether normals can be written: a range needs a `normal_map` (checked at
/// compile time, as \cgal does); a `CGAL::Point_set_3` may use its own normal
/// map, if it has one (checked at run time, the same on every \cgal version).
template <typename PointRange, typename NamedParameters>
bool has_normal_map(const PointRange&, const NamedParameters&)
{
  static_assert(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value,
                "CGAL::rrht_estimate_normals(): no normal map");
  return true;
}

template <typename Point, typename Vector, typename NamedParameters>
bool has_normal_map(const Point_set_3<Point, Vector>& points, const NamedParameters&)
{
  return !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value ||
         points.has_normal_map();
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CHECK_PARAMETERS_H
