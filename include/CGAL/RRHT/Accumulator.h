// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Hough accumulator of plane directions: Borrmann et al.'s "ball"
// accumulator restricted to a half sphere (paper, Section 3, "Accumulator
// shape", and Section 4 for the per-bin sum of normals).

#ifndef CGAL_RRHT_ACCUMULATOR_H
#define CGAL_RRHT_ACCUMULATOR_H

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace RRHT {

/// The bins of the accumulator: a partition of the unit half sphere (the
/// directions modulo their sign) into slices of equal polar angle, each cut
/// into bins of equal area (Borrmann, Elseberg, Lingemann and Nüchter 2011).
///
/// Layout. The full sphere is cut into `accumulator_slices` = n_phi slices
/// of height h = pi / n_phi in polar angle phi. A direction and its opposite
/// are one bin, so only the slices with phi < pi/2 are kept; when n_phi is
/// odd the middle slice straddles the equator and its two halves are
/// identified through the antipodal map. Slice i gets
///   ceil(area_i / (0.85 h^2))
/// bins, area_i being its area on the half sphere. The paper gives the number
/// M of bins (Fig. 4) but not its rounding: this rule reproduces Fig. 4
/// within 14% (n_phi = 5, 10, 15, 20, 25 give M = 20, 77, 172, 303, 475
/// against 23, 82, 171, 290, 441) while every bin keeps an area within 10%
/// of every other one (the ratio of the smallest to the largest area is
/// `area_ratio()`, at least 0.9 for n_phi <= 60).
///
/// Bin index. The slice comes from the z coordinate against the cosines of
/// the slice boundaries; the bin within the slice from the azimuth.
class Bin_layout
{
public:
  typedef Eigen::Vector3d Vector;

  explicit Bin_layout(unsigned int accumulator_slices)
  {
    if(accumulator_slices == 0)
      throw std::invalid_argument("CGAL::rrht_estimate_normals(): accumulator_slices (n_phi) must be at least 1");
    if(accumulator_slices > 1000)
      throw std::invalid_argument("CGAL::rrht_estimate_normals(): accumulator_slices (n_phi) must be at most 1000");

    const double pi = 3.14159265358979323846;
    const double h = pi / accumulator_slices;
    const double bin_area = 0.85 * h * h;
    m_straddling = (accumulator_slices % 2 == 1);
    const unsigned int kept = (accumulator_slices + 1) / 2;

    m_first_bin.push_back(0);
    for(unsigned int i = 0; i < kept; ++i)
    {
      const double phi_low = i * h;
      const bool straddles = m_straddling && (i + 1 == kept);
      // Area of the slice on the half sphere; the straddling slice counts for
      // its part above the equator (the part below is its antipodal copy).
      const double area = 2 * pi * (std::cos(phi_low) - (straddles ? 0. : std::cos(phi_low + h)));
      const unsigned int bins = (std::max)(1u, static_cast<unsigned int>(std::ceil(area / bin_area - 1e-9)));
      m_slice_area.push_back(area);
      m_bins_in_slice.push_back(bins);
      m_first_bin.push_back(m_first_bin.back() + bins);
      // Lower z bound of the slice (z decreases with phi).
      m_slice_z_low.push_back(straddles ? 0. : std::cos(phi_low + h));
    }
    if(!m_straddling)
      m_slice_z_low.back() = 0.; // exactly the equator

    // Centers of the bins, used to orient the normals that vote (see Accumulator::vote).
    m_center.resize(size());
    for(std::size_t s = 0; s < m_bins_in_slice.size(); ++s)
    {
      const double phi = (s + 0.5) * h;
      const bool straddles = m_straddling && (s + 1 == m_bins_in_slice.size());
      const double period = straddles ? pi : 2 * pi;
      for(unsigned int b = 0; b < m_bins_in_slice[s]; ++b)
      {
        const double theta = (b + 0.5) * period / m_bins_in_slice[s];
        m_center[m_first_bin[s] + b] = Vector(std::cos(theta) * std::sin(phi),
                                              std::sin(theta) * std::sin(phi),
                                              std::cos(phi));
      }
    }
  }

  /// Number of bins M.
  std::size_t size() const { return m_first_bin.back(); }

  /// Number of slices of the half sphere.
  std::size_t number_of_slices() const { return m_bins_in_slice.size(); }

  /// Area of bin `bin` on the unit sphere (the half sphere has area 2 pi).
  double area(std::size_t bin) const
  {
    const std::size_t s = slice_of_bin(bin);
    return m_slice_area[s] / m_bins_in_slice[s];
  }

  /// Smallest bin area over largest bin area.
  double area_ratio() const
  {
    double lo = area(0), hi = area(0);
    for(std::size_t b = 1; b < size(); ++b)
    {
      lo = (std::min)(lo, area(b));
      hi = (std::max)(hi, area(b));
    }
    return lo / hi;
  }

  /// A unit direction at the center of bin `bin`.
  const Vector& center(std::size_t bin) const { return m_center[bin]; }

  /// Bin of the direction of `n` (any nonzero vector); `n` and `-n` have the same bin.
  std::size_t bin(const Vector& n) const { return bin_of_unit(n.normalized()); }

  /// Bin of the unit vector `n`.
  std::size_t bin_of_unit(const Vector& n) const
  {
    const double pi = 3.14159265358979323846;
    double x = n.x(), y = n.y(), z = n.z();
    // Representative of {n, -n} on the upper half sphere; on the equator, the
    // one with y > 0 (or x > 0 when y = 0).
    if(z < 0 || (z == 0 && (y < 0 || (y == 0 && x < 0))))
    {
      x = -x; y = -y; z = -z;
    }
    std::size_t s = 0;
    const std::size_t last = m_slice_z_low.size() - 1;
    while(s < last && z < m_slice_z_low[s])
      ++s;

    const bool straddles = m_straddling && s == last;
    double theta = std::atan2(y, x); // in [-pi, pi]
    double period = 2 * pi;
    if(straddles)
    {
      // The straddling slice is cut over azimuths modulo pi, so that the bins
      // are whole squares across the equator.
      period = pi;
      if(theta < 0) theta += pi;
      if(theta >= pi) theta -= pi;
    }
    else if(theta < 0)
      theta += 2 * pi;
    const unsigned int bins = m_bins_in_slice[s];
    unsigned int b = static_cast<unsigned int>(theta / period * bins);
    if(b >= bins) b = bins - 1; // theta == period after rounding
    return m_first_bin[s] + b;
  }

private:
  std::size_t slice_of_bin(std::size_t bin) const
  {
    return std::upper_bound(m_first_bin.begin(), m_first_bin.end(), bin) - m_first_bin.begin() - 1;
  }

  bool m_straddling;
  std::vector<double> m_slice_z_low;
  std::vector<double> m_slice_area;
  std::vector<unsigned int> m_bins_in_slice;
  std::vector<std::size_t> m_first_bin;
  std::vector<Vector> m_center;
};

/// Votes of one run of the Hough transform: per bin, the number of planes
/// that voted for it and the sum of their normals (paper, Section 4), with the
/// two most voted bins kept up to date for the confidence interval test
/// (eq. 10). One per thread; `clear()` makes it ready for the next run
/// without allocating.
class Accumulator
{
public:
  typedef Eigen::Vector3d Vector;

  explicit Accumulator(const Bin_layout& layout)
    : m_layout(&layout), m_votes(layout.size(), 0), m_sums(layout.size(), Vector::Zero())
  {
    clear();
  }

  const Bin_layout& layout() const { return *m_layout; }

  void clear()
  {
    std::fill(m_votes.begin(), m_votes.end(), 0u);
    std::fill(m_sums.begin(), m_sums.end(), Vector::Zero());
    m_first = 0;
    m_second = m_votes.size() > 1 ? 1 : 0;
    m_number_of_votes = 0;
  }

  /// Adds the vote of a plane of normal `n` (nonzero, any length). The normal
  /// is added to the bin's sum with the sign that agrees with the bin's
  /// center, so that the sum of a bin never cancels itself.
  void vote(const Vector& n)
  {
    const Vector unit = n.normalized();
    const std::size_t b = m_layout->bin_of_unit(unit);
    m_sums[b] += (unit.dot(m_layout->center(b)) >= 0) ? unit : Vector(-unit);
    ++m_votes[b];
    ++m_number_of_votes;

    // Votes only grow by one, so the two most voted bins follow incrementally.
    if(b == m_first)
      return;
    if(m_votes[b] > m_votes[m_first])
    {
      m_second = m_first;
      m_first = b;
    }
    else if(b != m_second && m_votes[b] > m_votes[m_second])
      m_second = b;
  }

  std::size_t number_of_votes() const { return m_number_of_votes; }
  std::size_t most_voted_bin() const { return m_first; }
  unsigned int votes_of_most_voted_bin() const { return m_votes[m_first]; }
  unsigned int votes_of_second_most_voted_bin() const { return m_first == m_second ? 0u : m_votes[m_second]; }

  /// Unit mean of the normals that voted for the most voted bin (Section 4);
  /// zero when nothing was voted.
  Vector normal_of_most_voted_bin() const
  {
    const Vector& s = m_sums[m_first];
    const double norm = s.norm();
    return norm > 0 ? Vector(s / norm) : Vector::Zero();
  }

private:
  const Bin_layout* m_layout;
  std::vector<unsigned int> m_votes;
  std::vector<Vector> m_sums;
  std::size_t m_first, m_second;
  std::size_t m_number_of_votes;
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_ACCUMULATOR_H
