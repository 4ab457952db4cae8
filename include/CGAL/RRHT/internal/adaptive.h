// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The adaptive setting (beyond the paper; its Section 7 proposes, as future
// work, to draw cheaply by default and switch to the uniform drawing where
// the estimation is known to be inaccurate). Measured in
// benchmark/results/adaptive/adaptive.md.

#ifndef CGAL_RRHT_INTERNAL_ADAPTIVE_H
#define CGAL_RRHT_INTERNAL_ADAPTIVE_H

#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/internal/Settings.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The estimations the adaptive setting makes at a point, each the
/// estimation of a plain setting with the point's own random stream:
/// - `cheap`, the paper's fast setting (at most 300 planes, 2 rotations,
///   RRHT_Points), everywhere;
/// - where the cheap normal's confidence is below `recheck_below`, that
///   normal is replaced by `precise`'s, the parameters given (T_R and
///   n_rot) with RRHT_Points, which happens where noise scattered the few
///   cheap votes; where the confidence is below `spatial_below` too, which
///   happens along sharp features, by `spatial`'s instead, the parameters
///   given with RRHT_Cubes (RRHT_Unif if that was the sampling asked for),
///   unless its confidence is below the cheap one's and `precise`'s is
///   higher: spatial sampling resists the uneven density of the two sides
///   of a feature, but draws mostly outliers where they fill the ball.
/// So a normal of the adaptive setting is, bit for bit, the normal that one
/// of these plain settings gives at that point.
struct Adaptive_stages
{
  Settings cheap, precise, spatial;

  /// Confidences are shares of votes (`confidence()`); with the cheap
  /// setting on the benchmark's noisy shapes (100k points, 0.2% noise,
  /// K = 100) their median is 0.08 to 0.16 on the faces, 0.04 to 0.05
  /// within 1% of an edge.
  static constexpr double recheck_below = 0.09;
  static constexpr double spatial_below = 0.045;

  explicit Adaptive_stages(const Settings& settings) : cheap(settings), precise(settings), spatial(settings)
  {
    cheap.number_of_planes = (std::min)(settings.number_of_planes, paper_fast_number_of_planes);
    cheap.number_of_rotations = (std::min)(settings.number_of_rotations, paper_fast_number_of_rotations);
    cheap.sampling = Sampling::POINTS;
    precise.sampling = Sampling::POINTS;
    spatial.sampling = (settings.sampling == Sampling::UNIF) ? Sampling::UNIF : Sampling::CUBES;
  }
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ADAPTIVE_H
