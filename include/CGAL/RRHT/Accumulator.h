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
#include <limits>
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
/// the slice boundaries; the bin within the slice from the azimuth. Both are
/// found without trigonometry, since this is done for every plane drawn:
/// a table indexed by z gives the slice at the top of z's cell, at most a
/// few comparisons with the slice boundaries below it give z's slice; the
/// azimuth is replaced by the "diamond angle" (a rational function of x and
/// y that grows with the azimuth), and a table indexed by it, then a
/// comparison with the diamond angles of the bin boundaries, give the bin.
/// The bins are exactly those defined by the angles (up to rounding). In a
/// micro-benchmark of the lookup alone this is 3 times as fast as with
/// `std::atan2` (8.5 ns against 26 ns per direction, the same bins).
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

    // Slice lookup: cell c of [0, 1] in z gives the slice of z = (c + 1) / Z.
    m_z_cells = (std::max)(1024u, 4 * kept);
    m_slice_of_z_cell.resize(m_z_cells + 1);
    for(unsigned int c = 0; c <= m_z_cells; ++c)
    {
      const double z = (std::min)(1., double(c + 1) / m_z_cells);
      std::size_t slice = 0;
      while(slice + 1 < kept && z < m_slice_z_low[slice])
        ++slice;
      m_slice_of_z_cell[c] = static_cast<std::uint32_t>(slice);
    }

    // Azimuth lookup: the diamond angle at which each bin ends, and per slice
    // a table of the bin at the start of each cell of diamond angles.
    m_end_of_bin.resize(size());
    m_azimuth.resize(kept);
    for(std::size_t s = 0; s < kept; ++s)
    {
      Azimuth_lookup& a = m_azimuth[s];
      const bool straddles = m_straddling && (s + 1 == kept);
      const double period = straddles ? pi : 2 * pi;
      a.range = straddles ? 2. : 4.;
      const unsigned int bins = m_bins_in_slice[s];
      for(unsigned int b = 0; b + 1 < bins; ++b)
      {
        const double theta = (b + 1) * period / bins;
        m_end_of_bin[m_first_bin[s] + b] = diamond_angle(std::cos(theta), std::sin(theta));
      }
      m_end_of_bin[m_first_bin[s] + bins - 1] = std::numeric_limits<double>::infinity();
      const unsigned int cells = (std::max)(256u, 2 * bins);
      a.cells_per_unit = cells / a.range;
      a.first_cell = static_cast<std::uint32_t>(m_bin_at_cell.size());
      a.last_cell = cells - 1;
      std::size_t bin = m_first_bin[s];
      for(unsigned int c = 0; c < cells; ++c)
      {
        while(m_end_of_bin[bin] <= c / a.cells_per_unit)
          ++bin;
        m_bin_at_cell.push_back(static_cast<std::uint32_t>(bin));
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
    // Representative of {n, -n} on the upper half sphere; on the equator, the
    // one with y > 0 (or x > 0 when y = 0). The sign is random from one plane
    // to the next: it is applied without a branch.
    const bool flip = (n.z() < 0) | ((n.z() == 0) & ((n.y() < 0) | ((n.y() == 0) & (n.x() < 0))));
    const double sign = flip ? -1. : 1.;
    double x = sign * n.x(), y = sign * n.y();
    const double z = sign * n.z();
    // (The comparisons are written so that a NaN stays in range.)
    std::size_t s = m_slice_of_z_cell[z < 1 ? static_cast<std::size_t>(z * m_z_cells) : m_z_cells];
    while(s + 1 < m_slice_z_low.size() && z < m_slice_z_low[s])
      ++s;

    const Azimuth_lookup& a = m_azimuth[s];
    if(a.range == 2 && (y < 0 || (y == 0 && x < 0)))
    {
      // The straddling slice is cut over azimuths modulo pi, so that the bins
      // are whole squares across the equator.
      x = -x; y = -y;
    }
    const double q = diamond_angle(x, y);
    const double cell = q * a.cells_per_unit;
    std::size_t b = m_bin_at_cell[a.first_cell + (cell < a.last_cell ? static_cast<std::uint32_t>(cell) : a.last_cell)];
    while(q >= m_end_of_bin[b])
      ++b;
    return b;
  }

  /// The diamond angle of (x, y): 0 on the x axis, then growing with the
  /// azimuth to 1, 2, 3 on the y, -x, -y axes and to 4 before the x axis
  /// again; 0 at the origin.
  static double diamond_angle(double x, double y)
  {
    const double l1 = std::abs(x) + std::abs(y);
    const double r = l1 > 0 ? y / l1 : 0.;
    // x >= 0: r, or 4 + r below the x axis; x < 0: 2 - r. Written as
    // arithmetic on the comparisons: the quadrant is random from one plane
    // to the next.
    const double left = double(x < 0), below_right = double((x >= 0) & (y < 0));
    return 2 * left + 4 * below_right + (1 - 2 * left) * r;
  }

private:
  std::size_t slice_of_bin(std::size_t bin) const
  {
    return std::upper_bound(m_first_bin.begin(), m_first_bin.end(), bin) - m_first_bin.begin() - 1;
  }

  // The cells of diamond angles of one slice: from 0 to `range` (4, or 2 for
  // the straddling slice), `cells_per_unit` per unit, their first bins in
  // m_bin_at_cell from `first_cell` to `first_cell + last_cell`.
  struct Azimuth_lookup
  {
    double range;
    double cells_per_unit;
    std::uint32_t first_cell, last_cell;
  };

  bool m_straddling;
  unsigned int m_z_cells;
  std::vector<std::uint32_t> m_slice_of_z_cell;
  std::vector<Azimuth_lookup> m_azimuth;
  std::vector<std::uint32_t> m_bin_at_cell;
  std::vector<double> m_end_of_bin; // diamond angle, infinite for the last bin of a slice
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

  explicit Accumulator(const Bin_layout& layout) : m_layout(&layout), m_bins(layout.size())
  {
    clear();
  }

  const Bin_layout& layout() const { return *m_layout; }

  void clear()
  {
    std::fill(m_bins.begin(), m_bins.end(), Bin());
    m_first = 0;
    m_second = m_bins.size() > 1 ? 1 : 0;
    m_number_of_votes = 0;
  }

  /// Adds the vote of a plane of normal `n` (nonzero, any length). The normal
  /// is added to the bin's sum with the sign that agrees with the bin's
  /// center, so that the sum of a bin never cancels itself.
  void vote(const Vector& n)
  {
    const Vector unit = n / std::sqrt(n.squaredNorm());
    vote(m_layout->bin_of_unit(unit), unit);
  }

  /// Adds the vote of the unit normal `unit` of bin `b`.
  void vote(std::size_t b, const Vector& unit)
  {
    Bin& bin = m_bins[b];
    // The sign without a branch: it is random when the bin straddles the equator.
    bin.sum += std::copysign(1., unit.dot(m_layout->center(b))) * unit;
    ++bin.votes;
    ++m_number_of_votes;

    // Votes only grow by one, so the two most voted bins follow
    // incrementally; with selects rather than branches, since whether a plane
    // votes for the first bin is random.
    const bool new_first = bin.votes > m_bins[m_first].votes; // never when b is the first
    const bool new_second = !new_first && b != m_first && b != m_second && bin.votes > m_bins[m_second].votes;
    m_second = new_first ? m_first : (new_second ? b : m_second);
    m_first = new_first ? b : m_first;
  }

  std::size_t number_of_votes() const { return m_number_of_votes; }
  std::size_t most_voted_bin() const { return m_first; }
  unsigned int votes_of_most_voted_bin() const { return m_bins[m_first].votes; }
  unsigned int votes_of_second_most_voted_bin() const { return m_first == m_second ? 0u : m_bins[m_second].votes; }

  /// Unit mean of the normals that voted for the most voted bin (Section 4);
  /// zero when nothing was voted.
  Vector normal_of_most_voted_bin() const
  {
    const Vector& s = m_bins[m_first].sum;
    const double norm = s.norm();
    return norm > 0 ? Vector(s / norm) : Vector::Zero();
  }

private:
  // The votes of a bin next to the sum of their normals: one cache line per vote.
  struct Bin
  {
    Vector sum = Vector::Zero();
    unsigned int votes = 0;
  };

  const Bin_layout* m_layout;
  std::vector<Bin> m_bins;
  std::size_t m_first, m_second;
  std::size_t m_number_of_votes;
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_ACCUMULATOR_H
