// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How RRHT combines the normals of its randomly rotated accumulators
// (paper, Section 4).

#ifndef CGAL_RRHT_AGGREGATION_H
#define CGAL_RRHT_AGGREGATION_H

#include <array>
#include <utility>

namespace CGAL {
namespace RRHT {

/// \ingroup PkgRRHTRef
/// How the normals of the rotated accumulators are combined.
enum class Aggregation
{
  MEAN,   ///< RRHT_m: mean of the normals weighted by their votes.
  BEST,   ///< RRHT_b: the most voted normal.
  CLUSTER ///< RRHT_c: vote-weighted mean of the most voted cluster of normals within `cluster_angle`.
};

/// \ingroup PkgRRHTRef
/// The name of each aggregation, as `rrht_normals --aggregation` and the
/// Python package's `aggregation=` take it: "mean", "best", "cluster".
inline constexpr std::array<std::pair<const char*, Aggregation>, 3> aggregation_names = {
  { { "mean", Aggregation::MEAN }, { "best", Aggregation::BEST }, { "cluster", Aggregation::CLUSTER } }
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_AGGREGATION_H
