// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bins of the accumulator computed from their definition, with
// trigonometry, to check the lookup tables of Bin_layout against.

#ifndef RRHT_TEST_REFERENCE_BINS_H
#define RRHT_TEST_REFERENCE_BINS_H

#include <CGAL/RRHT/internal/Bin_layout.h>

#include "components.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace rrht_test {
// The bins by their definition (Bin_layout's documentation): slice of the
// polar angle of the upper representative, then bin of the azimuth in the
// slice, with acos and atan2.
class Reference_bins
{
public:
  explicit Reference_bins(const Bin_layout& layout) : m_slices(0), m_h(0)
  {
    first_of_slice.push_back(0);
    for(std::size_t b = 1; b < layout.size(); ++b)
      if(std::abs(std::acos(layout.center(b).z()) - std::acos(layout.center(b - 1).z())) > 1e-9)
        first_of_slice.push_back(b);
    first_of_slice.push_back(layout.size());
    m_slices = 2 * (first_of_slice.size() - 1) - (std::abs(layout.center(layout.size() - 1).z()) < 1e-12 ? 1 : 0);
    m_h = pi / m_slices;
  }

  // The bin of the unit vector n, and its distance (radians) to the nearest
  // boundary of its slice or bin.
  std::size_t bin(Eigen::Vector3d n, double& to_boundary) const
  {
    if(n.z() < 0)
      n = -n;
    const double phi = std::acos((std::min)(1., n.z()));
    const std::size_t s = (std::min)(std::size_t(phi / m_h), first_of_slice.size() - 2);
    const bool straddles = (m_slices % 2 == 1) && s + 2 == first_of_slice.size();
    const double period = straddles ? pi : 2 * pi;
    const double theta = std::fmod(std::atan2(n.y(), n.x()) + 2 * pi, period);
    const std::size_t bins = first_of_slice[s + 1] - first_of_slice[s];
    const double position = theta / period * bins;
    to_boundary = (std::min)(std::abs(position - std::round(position)) / bins * period * std::sin(phi),
                             std::abs(phi / m_h - std::round(phi / m_h)) * m_h);
    return first_of_slice[s] + (std::min)(std::size_t(position), bins - 1);
  }

  static constexpr double pi = CGAL_PI;
  std::vector<std::size_t> first_of_slice;

private:
  std::size_t m_slices;
  double m_h;
};
} // namespace rrht_test
using rrht_test::Reference_bins;

#endif // RRHT_TEST_REFERENCE_BINS_H
