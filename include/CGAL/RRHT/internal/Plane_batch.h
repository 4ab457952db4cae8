// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The plane hypotheses of a batch of triples (paper, Section 2: "each
// triple of points defines a plane"), their unit normals and their bins in
// the accumulator (Section 3), computed together.

#ifndef CGAL_RRHT_INTERNAL_PLANE_BATCH_H
#define CGAL_RRHT_INTERNAL_PLANE_BATCH_H

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Instruction_set.h>
#include <CGAL/RRHT/internal/Triple.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The planes through a batch of at most `capacity` triples of points.
///
/// This is the inner loop of the RRHT, run for every plane hypothesis, and
/// it is written for SIMD: the batch is held as arrays of coordinates
/// (structure of arrays), in single precision, and each step is one loop
/// over the batch whose iterations are independent:
///   1. the two edges of each triple (gathered from the points);
///   2. the normal and its squared norm, in a loop that the compiler
///      vectorizes, then the reciprocal of the norm with Eigen's array
///      expressions (they use SSE/AVX/NEON, square root included, which a
///      plain loop only gets with -fno-math-errno);
///   3. the unit normal and the representative of its direction in the bins
///      (`Bin_layout::representative()`), in a loop without branches that
///      the compiler vectorizes;
///   4. the bin, from the tables of `Bin_layout` (scalar).
/// The loops also have an AVX2 version, taken when the processor has it
/// (`Instruction_set.h`), with the same results.
///
/// Single precision is enough: the points are relative to the neighborhood's
/// center and scaled by its radius (coordinates in [-1, 1]), so a normal is
/// off by about 1e-7 / sin(angle of its triple) radians, far below the size
/// of a bin and the spread of the normals of a noisy triple. Triples whose
/// two edges make an angle below 1e-5 radians (sin^2 < 1e-10, where single
/// precision gives no direction) define no plane and are left out, as in
/// `confidence_of_kept_normal()`.
class Plane_batch
{
public:
  static constexpr std::size_t capacity = 64;

  /// Batches computed with the loops of `instruction_set` (the results are
  /// the same with each, see `Instruction_set.h`).
  explicit Plane_batch(Instruction_set instruction_set = best_instruction_set())
    : m_instruction_set(instruction_set)
  {}

  /// Computes the planes through `triples[0, count)` of `points`
  /// (count <= capacity) and their bins in `layout`: triple i has bin
  /// `bin(i)`, `no_plane` when it is degenerate, and unit normal
  /// `normal(i)`, oriented by `Bin_layout::bin_and_sign()`.
  void compute(const std::vector<Eigen::Vector3f>& points, const Triple* triples, std::size_t count,
               const Bin_layout& layout)
  {
    run_with(m_instruction_set, [&] { compute_planes(points, triples, count, layout); });
  }

  /// The bin of triple i, `no_plane` if its points define no plane.
  static constexpr std::uint32_t no_plane = ~std::uint32_t(0);

  std::uint32_t bin(std::size_t i) const { return m_bin[i]; }
  Eigen::Vector3d normal(std::size_t i) const { return Eigen::Vector3d(m_nx[i], m_ny[i], m_nz[i]); }

private:
  typedef Eigen::Index Index;

  // The four steps.
  void compute_planes(const std::vector<Eigen::Vector3f>& points, const Triple* triples, std::size_t count,
                      const Bin_layout& layout)
  {
    typedef Eigen::Map<Eigen::ArrayXf, Eigen::Aligned16> Array;
    // 1. Edges.
    for(std::size_t i = 0; i < count; ++i)
    {
      const Eigen::Vector3f& a = points[triples[i][0]];
      const Eigen::Vector3f& b = points[triples[i][1]];
      const Eigen::Vector3f& c = points[triples[i][2]];
      m_ux[i] = b.x() - a.x(); m_uy[i] = b.y() - a.y(); m_uz[i] = b.z() - a.z();
      m_vx[i] = c.x() - a.x(); m_vy[i] = c.y() - a.y(); m_vz[i] = c.z() - a.z();
    }

    // 2. Normals, their squared norms and |u|^2 |v|^2, in one loop that the
    //    compiler vectorizes; the reciprocal square roots through Eigen.
    for(std::size_t i = 0; i < count; ++i)
    {
      const float ux = m_ux[i], uy = m_uy[i], uz = m_uz[i], vx = m_vx[i], vy = m_vy[i], vz = m_vz[i];
      const float nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
      m_nx[i] = nx;
      m_ny[i] = ny;
      m_nz[i] = nz;
      m_squared_norm[i] = nx * nx + ny * ny + nz * nz;
      m_edges[i] = (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
    }
    const Index n = static_cast<Index>(count);
    Array(m_inverse_norm, n) = Array(m_squared_norm, n).rsqrt();

    // 3. Unit normals, their representatives (Bin_layout::representative()),
    //    oriented normals.
    const float straddling_top = layout.straddling_slice_top();
    for(std::size_t i = 0; i < count; ++i)
    {
      const float inverse_norm = m_inverse_norm[i];
      const float nx = m_nx[i] * inverse_norm, ny = m_ny[i] * inverse_norm, nz = m_nz[i] * inverse_norm;
      float sign;
      Bin_layout::representative(nx, ny, nz, straddling_top, m_height[i], m_angle[i], sign);
      m_nx[i] = nx * sign;
      m_ny[i] = ny * sign;
      m_nz[i] = nz * sign;
    }

    // 4. Bins, and `no_plane` for degenerate triples.
    for(std::size_t i = 0; i < count; ++i)
    {
      const std::uint32_t bin = static_cast<std::uint32_t>(layout.bin_of_representative(m_height[i], m_angle[i]));
      m_bin[i] = (m_squared_norm[i] > 1e-10f * m_edges[i]) ? bin : no_plane; // sin^2 of the angle above 1e-10
    }
  }

  Instruction_set m_instruction_set;
  alignas(16) float m_ux[capacity], m_uy[capacity], m_uz[capacity];
  alignas(16) float m_vx[capacity], m_vy[capacity], m_vz[capacity];
  alignas(16) float m_nx[capacity], m_ny[capacity], m_nz[capacity];
  alignas(16) float m_squared_norm[capacity], m_inverse_norm[capacity], m_edges[capacity];
  alignas(16) float m_height[capacity], m_angle[capacity];
  std::uint32_t m_bin[capacity];
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PLANE_BATCH_H
