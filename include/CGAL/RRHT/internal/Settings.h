// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of `CGAL::rrht_estimate_normals()`, once checked.

#ifndef CGAL_RRHT_INTERNAL_SETTINGS_H
#define CGAL_RRHT_INTERNAL_SETTINGS_H

#include <CGAL/RRHT/Aggregation.h>
#include <CGAL/RRHT/Sampling.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace RRHT {
namespace internal {

/// T_R and n_rot of the paper's fast setting (Section 6), which the
/// adaptive setting runs first.
constexpr std::size_t paper_fast_number_of_planes = 300;
constexpr unsigned int paper_fast_number_of_rotations = 2;

/// The parameters of the algorithm (paper, Section 6), once checked.
struct Settings
{
  unsigned int k;                 // K, or the cap on a ball
  double neighbor_radius;         // r, or 0 for k-neighborhoods
  std::size_t number_of_planes;   // T_R
  bool use_confidence_interval;   // eq. 10
  Sampling sampling;              // Points, Cubes or Unif
  unsigned int presampling_factor;// c
  unsigned int number_of_rotations; // n_rot
  Aggregation aggregation;        // m, b or c
  double cos_cluster_angle;       // cos(a_cluster)
  std::uint64_t seed;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SETTINGS_H
