// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Which estimation runs where: the package's default, or one of the
// paper's two settings (Section 6).

#ifndef CGAL_RRHT_SETTING_H
#define CGAL_RRHT_SETTING_H

#include <array>
#include <utility>

namespace CGAL {
namespace RRHT {

/// \ingroup PkgRRHTRef
/// The estimation that `CGAL::rrht_estimate_normals()` runs, chosen by its
/// named parameter `setting`. A setting gives the defaults of
/// `number_of_planes` and `number_of_rotations`; a value given for either wins.
enum class Setting
{
  /// Least squares where the neighborhood is one smooth sheet, the adaptive
  /// Hough transform elsewhere (beyond the paper): the paper's fast setting,
  /// then `number_of_planes` and `number_of_rotations` where its confidence is low.
  DEFAULT,
  /// The paper's precise setting: the Hough transform at every point, T_R from
  /// eq. 7 (691 for 15 slices) and n_rot = 5.
  PAPER_PRECISE,
  /// The paper's fast setting: the Hough transform at every point, T_R = 300
  /// and n_rot = 2.
  PAPER_FAST
};

/// \ingroup PkgRRHTRef
/// The name of each setting, as `rrht_normals --setting` and the Python
/// package's `setting=` take it: "default", "paper_precise", "paper_fast".
inline constexpr std::array<std::pair<const char*, Setting>, 3> setting_names = {
  { { "default", Setting::DEFAULT }, { "paper_precise", Setting::PAPER_PRECISE }, { "paper_fast", Setting::PAPER_FAST } }
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_SETTING_H
