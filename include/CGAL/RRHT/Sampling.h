// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The three ways of drawing the triples of points that define plane
// hypotheses (paper, Section 5).

#ifndef CGAL_RRHT_SAMPLING_H
#define CGAL_RRHT_SAMPLING_H

#include <array>
#include <utility>

namespace CGAL {
namespace RRHT {

/// \ingroup PkgRRHTRef
/// How the three points of a plane hypothesis are drawn in a neighborhood.
enum class Sampling
{
  POINTS, ///< RRHT_Points: uniformly among the neighbors, never the same triple twice.
  CUBES,  ///< RRHT_Cubes: a small cube of the ball, weighted by its volume in the ball, then a point in it.
  UNIF    ///< RRHT_Unif: a small ball of radius r/c in the neighborhood ball, redrawn while empty, then a point in it.
};

/// \ingroup PkgRRHTRef
/// The name of each sampling, as `rrht_normals --sampling` and the Python
/// package's `sampling=` take it: "points", "cubes", "unif".
inline constexpr std::array<std::pair<const char*, Sampling>, 3> sampling_names = {
  { { "points", Sampling::POINTS }, { "cubes", Sampling::CUBES }, { "unif", Sampling::UNIF } }
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_SAMPLING_H
