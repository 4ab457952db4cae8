// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The bins of the Hough accumulator of plane directions: Borrmann et al.'s
// "ball" accumulator restricted to a half sphere (paper, Section 3,
// "Accumulator shape").

#ifndef CGAL_RRHT_INTERNAL_BIN_LAYOUT_H
#define CGAL_RRHT_INTERNAL_BIN_LAYOUT_H

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

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
/// of every other one (the ratio of the smallest to the largest area is at
/// least 0.9 for n_phi <= 60, tested).
///
/// Bin index. The slice comes from the z coordinate against the cosines of
/// the slice boundaries; the bin within the slice from the azimuth. Both are
/// found without trigonometry and without a branch, since this is done for
/// every plane drawn: a table of cells of z, fine enough that a cell holds
/// at most one slice boundary, gives the slice at the bottom of z's cell
/// and that boundary, and one comparison gives z's slice; the azimuth is
/// replaced by the "diamond angle" (a rational function of x and y that
/// grows with the azimuth), and a table of its cells, one per slice, gives
/// the bin the same way. The bins are exactly those defined by the angles
/// (up to rounding), several times faster than with `std::atan2`.
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

    const double pi = CGAL_PI;
    const double h = pi / accumulator_slices;
    m_slice_height = h;
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

    // Slice lookup: cell c covers z in [c / Z, (c + 1) / Z), with Z the
    // smallest power of 2 for which no cell holds two slice boundaries.
    for(std::size_t cells = 16;; cells *= 2)
    {
      m_z_cells.clear();
      bool fine_enough = true;
      for(std::size_t c = 0; c < cells && fine_enough; ++c)
      {
        const double bottom = double(c) / cells, top = double(c + 1) / cells;
        std::size_t slice = 0; // of the bottom of the cell
        while(slice + 1 < kept && bottom < m_slice_z_low[slice])
          ++slice;
        const bool boundary_inside = slice > 0 && m_slice_z_low[slice - 1] < top;
        fine_enough = !boundary_inside || slice == 1 || m_slice_z_low[slice - 2] >= top;
        m_z_cells.push_back(Cell{ boundary_inside ? float(m_slice_z_low[slice - 1]) : infinity, std::uint32_t(slice) });
      }
      if(fine_enough)
        break;
    }
    m_last_z_cell = float(m_z_cells.size() - 1);
    m_straddling_top = !m_straddling ? 0.f : (kept == 1 ? infinity : float(m_slice_z_low[kept - 2]));

    // Azimuth lookup, per slice: the cells of its diamond angles, 2 per bin
    // or more, so that no cell holds two bin boundaries.
    m_azimuth.resize(kept);
    std::vector<double> end_of_bin; // diamond angle at which a bin of the slice ends
    for(std::size_t s = 0; s < kept; ++s)
    {
      Azimuth_lookup& a = m_azimuth[s];
      const bool straddles = m_straddling && (s + 1 == kept);
      const double period = straddles ? pi : 2 * pi;
      const double range = straddles ? 2. : 4.;
      const unsigned int bins = m_bins_in_slice[s];
      end_of_bin.clear();
      for(unsigned int b = 0; b + 1 < bins; ++b)
      {
        const double theta = (b + 1) * period / bins;
        end_of_bin.push_back(diamond_angle(std::cos(theta), std::sin(theta)));
      }
      end_of_bin.push_back(std::numeric_limits<double>::infinity());
      end_of_bin.push_back(std::numeric_limits<double>::infinity());
      a.first_cell = static_cast<std::uint32_t>(m_azimuth_cells.size());
      for(std::size_t cells = 2 * bins;; cells *= 2)
      {
        m_azimuth_cells.resize(a.first_cell);
        bool fine_enough = true;
        std::size_t bin = 0; // of the start of the cell
        for(std::size_t c = 0; c < cells && fine_enough; ++c)
        {
          const double start = c * range / cells, end = (c + 1) * range / cells;
          while(end_of_bin[bin] <= start)
            ++bin;
          const bool boundary_inside = end_of_bin[bin] < end;
          fine_enough = !boundary_inside || end_of_bin[bin + 1] >= end;
          m_azimuth_cells.push_back(Cell{ boundary_inside ? float(end_of_bin[bin]) : infinity,
                                          std::uint32_t(m_first_bin[s] + bin) });
        }
        if(fine_enough)
        {
          a.cells_per_unit = float(cells / range);
          a.last_cell = float(cells - 1);
          break;
        }
      }
    }
  }

  /// Number of bins M.
  std::size_t size() const { return m_first_bin.back(); }

  /// Area of bin `bin` on the unit sphere (the half sphere has area 2 pi).
  double area(std::size_t bin) const
  {
    const std::size_t s = slice_of_bin(bin);
    return m_slice_area[s] / m_bins_in_slice[s];
  }

  /// The unit direction at the center of bin `bin`, in polar angle and
  /// azimuth (computed on demand: only tests need it).
  Vector center(std::size_t bin) const
  {
    const std::size_t s = slice_of_bin(bin);
    const double phi = (s + 0.5) * m_slice_height;
    const bool straddles = m_straddling && (s + 1 == m_bins_in_slice.size());
    const double period = straddles ? CGAL_PI : 2 * CGAL_PI;
    const double theta = (bin - m_first_bin[s] + 0.5) * period / m_bins_in_slice[s];
    return Vector(std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi));
  }

  /// Bin of the direction of `n` (any nonzero vector); `n` and `-n` have
  /// the same bin. (The planes of a batch get theirs from `representative()`
  /// and `bin_of_representative()`.)
  std::size_t bin(const Vector& n) const
  {
    const Vector unit = n.normalized();
    double sign;
    return bin_and_sign(unit.x(), unit.y(), unit.z(), sign);
  }

  /// Bin of the unit vector (x, y, z), in double or single precision, and
  /// the sign (1 or -1) that puts the vector in the bin: the bins of the
  /// half sphere stand for pairs of opposite directions, and the normals
  /// that vote for a bin are summed with this sign, so that the sum of a bin
  /// never cancels itself (Section 4).
  template <typename Scalar>
  std::size_t bin_and_sign(Scalar x, Scalar y, Scalar z, Scalar& sign) const
  {
    Scalar height, angle;
    representative(x, y, z, Scalar(straddling_slice_top()), height, angle, sign);
    return bin_of_representative(height, angle);
  }

  /// The representative of the directions {n, -n} of n = (x, y, z) in the
  /// bins: its z coordinate `height` in [0, 1], its "angle" in [0, 4] (the
  /// diamond angle of its projection on the xy plane, see
  /// `diamond_angle()`) and the sign (1 or -1) that makes it from n.
  ///
  /// It is the one with z >= 0, and of the two with z = 0 the one whose z is
  /// +0: `copysign` gives it, and the exact negation of n flips the sign of
  /// a zero z as well, so n and -n always get the same one. In the slice
  /// that straddles the equator (n_phi odd: z below `straddling_top`, the
  /// value of `straddling_slice_top()`), azimuths are taken modulo pi, so
  /// that its bins are whole squares across the equator: the angle is then
  /// below 2, the representative possibly below the equator.
  ///
  /// Without a branch: the sign of a plane's normal is random. A loop over
  /// this function vectorizes (see `Plane_batch`); GCC 12 does so with the
  /// `&` of the two comparisons below, not with their product.
  template <typename Scalar>
  static void representative(Scalar x, Scalar y, Scalar z, Scalar straddling_top,
                             Scalar& height, Scalar& angle, Scalar& sign)
  {
    const Scalar up = std::copysign(Scalar(1), z);
    height = std::abs(z);
    const Scalar q = diamond_angle(up * x, up * y);
    const Scalar other_half = Scalar((height < straddling_top) & (q >= 2));
    angle = q - 2 * other_half;
    sign = up * (1 - 2 * other_half);
  }

  /// The height below which directions are in the slice that straddles the
  /// equator: 0 (none) when n_phi is even.
  float straddling_slice_top() const { return m_straddling_top; }

  /// Bin of the representative of height `z` and angle `q` (see
  /// `representative()`), from two table lookups. The cell tables hold
  /// single precision boundaries: a direction within about 1e-7 of a
  /// boundary may fall on either side. A NaN gives a bin in range.
  template <typename Scalar>
  std::size_t bin_of_representative(Scalar z, Scalar q) const
  {
    // Cell indices as (std::min)(last, x), which is `last` for a NaN x.
    const Cell& slice_cell = m_z_cells[static_cast<std::uint32_t>((std::min)(Scalar(m_last_z_cell), z * Scalar(m_z_cells.size())))];
    const std::size_t s = slice_cell.index - (z >= slice_cell.boundary);
    const Azimuth_lookup& a = m_azimuth[s];
    const Cell& bin_cell = m_azimuth_cells[a.first_cell + static_cast<std::uint32_t>((std::min)(Scalar(a.last_cell), q * a.cells_per_unit))];
    return bin_cell.index + (q >= bin_cell.boundary);
  }

  /// The diamond angle of (x, y): 0 on the x axis, then growing with the
  /// azimuth to 1, 2, 3 on the y, -x, -y axes and to 4 before the x axis
  /// again; 0 at the origin.
  template <typename Scalar>
  static Scalar diamond_angle(Scalar x, Scalar y)
  {
    // Dividing by at least the smallest normal number rather than testing
    // l1 > 0 keeps the function free of branches (at the origin y = 0).
    const Scalar l1 = std::abs(x) + std::abs(y);
    const Scalar r = y / (std::max)(l1, (std::numeric_limits<Scalar>::min)());
    // x >= 0: r, or 4 + r below the x axis; x < 0: 2 - r. Written as
    // arithmetic on the comparisons: the quadrant is random from one plane
    // to the next.
    const Scalar left = Scalar(x < 0), below_right = Scalar((x >= 0) & (y < 0));
    return 2 * left + 4 * below_right + (1 - 2 * left) * r;
  }

private:
  std::size_t slice_of_bin(std::size_t bin) const
  {
    return std::upper_bound(m_first_bin.begin(), m_first_bin.end(), bin) - m_first_bin.begin() - 1;
  }

  // A cell of a lookup table: the index (slice or bin) at its start and the
  // boundary where the index changes within it, if any (else infinity): the
  // slice is index - (z >= boundary), the bin index + (q >= boundary).
  struct Cell
  {
    float boundary;
    std::uint32_t index;
  };

  // The cells of diamond angles of one slice: from 0 to 4 (2 for the
  // straddling slice), `cells_per_unit` per unit, in m_azimuth_cells from
  // `first_cell` to `first_cell + last_cell`.
  struct Azimuth_lookup
  {
    float cells_per_unit;
    float last_cell;
    std::uint32_t first_cell;
  };

  static constexpr float infinity = std::numeric_limits<float>::infinity();

  double m_slice_height; // pi / n_phi
  bool m_straddling;
  float m_straddling_top;
  std::vector<Cell> m_z_cells;
  float m_last_z_cell;
  std::vector<Azimuth_lookup> m_azimuth;
  std::vector<Cell> m_azimuth_cells;
  std::vector<double> m_slice_z_low;
  std::vector<double> m_slice_area;
  std::vector<unsigned int> m_bins_in_slice;
  std::vector<std::size_t> m_first_bin;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_BIN_LAYOUT_H
