// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The signed edges of a consistent orientation: the k-nearest-neighbor graph
// of the points, each edge weighted by how surely its two normals agree in
// orientation as they are (positive) or after one of them flips (negative).

#ifndef CGAL_RRHT_INTERNAL_ORIENTATION_EDGES_H
#define CGAL_RRHT_INTERNAL_ORIENTATION_EDGES_H

#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/Sheets.h>
#include <CGAL/RRHT/internal/Wedge.h>
#include <CGAL/RRHT/internal/for_each_block.h>

#include <CGAL/for_each.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numeric>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// An edge between the points at positions `a` < `b` of the search, with its
/// signed weight (0: no evidence).
struct Signed_edge
{
  std::uint32_t a, b;
  double weight;
};

/// The offsets of the `nearest` first neighbors from the tangent plane of
/// `normal` at the point at position `point`:
/// their first quartile, in absolute value, is the scale of the noise across
/// the surface that the other side of a thin part does not inflate.
inline double offset_scale(const Neighborhood& neighborhood, std::size_t nearest, std::size_t point,
                           const Eigen::Vector3d& normal, std::vector<double>& work)
{
  work.clear();
  for(std::size_t t = 0; t < nearest; ++t)
    if(neighborhood.positions[t] != point)
      work.push_back(std::abs(normal.dot(neighborhood.points[t])));
  if(work.empty())
    return 0;
  const auto quartile = work.begin() + (work.size() - 1) / 4;
  std::nth_element(work.begin(), quartile, work.end());
  return *quartile;
}

/// How surely the tangent plane of `normal` at a point is the surface's,
/// from the offsets `offsets` of the point (0) and its nearest neighbors
/// from that plane (reordered on return): the share of them within `band`
/// of their median, squared. A normal that is not the surface's, such as a
/// face's normal on the narrow rim of a plate, leaves most neighbors off
/// its plane; the median, rather than the point's own offset, keeps a
/// noisy point's support. Its square weighs the evidence of parallel
/// normals: a band of such points, each on the plane of the next, would
/// otherwise chain the two faces of the plate into one sheet.
inline double plane_support(std::vector<double>& offsets, double band)
{
  if(offsets.size() < 2)
    return 1;
  const auto middle = offsets.begin() + std::ptrdiff_t(offsets.size() / 2);
  std::nth_element(offsets.begin(), middle, offsets.end());
  const double median = *middle;
  std::size_t on_plane = 0;
  for(double o : offsets)
    on_plane += std::abs(o - median) <= band;
  const double share = double(on_plane) / double(offsets.size());
  return share * share;
}

/// Normals within 30 degrees of each other are parallel.
constexpr double cos_parallel = 0.8660254037844386;

/// The signed weight of the edge from a point with unit normal `ni` to a
/// neighbor at `d` from it with unit normal `nj`, given their offset scales
/// `si` and `sj` and, where their normals are parallel, on which face of
/// each other's neighborhood each lies: `side_i`, the neighbor's in the
/// point's, and `side_j`, the point's in the neighbor's (+1 the own face, -1
/// the next one, 0 unsure; +1 where a neighborhood holds one sheet).
///
/// - Nearly parallel normals (within 30 degrees) are on one smooth sheet when
///   each point lies within the noise of the other's tangent plane (with
///   the bend that the angle of the normals implies), and, where either
///   neighborhood holds several faces (`Sheets`, `Wedge`), on the other's
///   face: their dot product says whether they agree (Hoppe et al. 1992).
///   When each is on the face next to the other's, across the chord, they
///   are the two sides of a thin part, or of a narrow gap, whose outward
///   normals point away from each other, or towards each other: opposite.
///   Otherwise, no evidence.
/// - Across a sharp edge, the dot product is noise (perpendicular normals).
///   The normal at one end reflected through the plane that bisects the
///   chord is the normal at the other end of a circular arc between them:
///   its dot product with the other normal says whether they agree (the
///   reflection criterion of Xie et al. 2003, after König and Gumhold 2009),
///   and it is confident across a 90 degree edge.
inline double signed_weight(const Eigen::Vector3d& d, const Eigen::Vector3d& ni, const Eigen::Vector3d& nj, double si,
                            double sj, int side_i, int side_j)
{
  const double noise_factor = 7, normal_tolerance = 0.03;
  const double length = d.norm(), c = ni.dot(nj);
  if(!(length > 0))
    return c;
  if(std::abs(c) > cos_parallel)
  {
    const double oi = ni.dot(d), oj = -nj.dot(d); // each one's offset from the other's tangent plane
    const double half_angle_sine = std::sqrt((std::max)(0., (1 - std::abs(c)) / 2));
    // The band may reach across to the next face: the faces decide.
    const double band = noise_factor * (std::min)(si, sj) + length * (half_angle_sine + normal_tolerance);
    if(side_i == 1 && side_j == 1 && std::abs(oi) <= band && std::abs(oj) <= band)
      return c;
    // Across a thin part the chord runs along the normals (within 45
    // degrees); across a step or the rim of a plate, whose near points may
    // take the rim's normal, it is oblique.
    const double along = 0.7071067811865476 * length;
    return side_i == -1 && side_j == -1 && std::abs(oi) > along && std::abs(oj) > along ? -c : 0.;
  }
  const Eigen::Vector3d u = d / length;
  return c - 2 * ni.dot(u) * nj.dot(u);
}

/// The number of neighbors whose offsets tell the sheets apart, at least.
constexpr unsigned int sheet_neighbors = 48;

/// A point is off the surface, an outlier, where the offset scale of its
/// neighbors from its tangent plane is over these many times the noise over
/// the cloud, and over this share of its neighborhood's radius.
constexpr double off_surface_noises = 4, off_surface_radius = 0.05;

/// The edges of the graph whose vertices are the points of `search` and
/// whose edges join each point to its `k` nearest neighbors (once per
/// pair), with their signed weights, in a fixed order whatever the number of
/// threads. `normals` are unit vectors in the order of the search. Also
/// gives each point's share of the surface's area, the area of the disk of
/// its neighborhood shared among its points, in `areas`.
template <typename ConcurrencyTag>
std::vector<Signed_edge> orientation_edges(const Neighbor_search& search, const std::vector<Eigen::Vector3d>& normals,
                                           unsigned int k, std::vector<double>& areas)
{
  const std::size_t size = search.size();
  k = static_cast<unsigned int>((std::min<std::size_t>)(k, size - 1));
  // The sheets are told apart on more neighbors than the edges join: a
  // split of a few offsets is unsure where the sheets are only a few times
  // the noise apart.
  const unsigned int sheet_k =
    static_cast<unsigned int>((std::min<std::size_t>)((std::max)(k, sheet_neighbors), size - 1));
  // The neighbors of every point, k per point, their offset scales, and the
  // positions of those of its sheet_k nearest whose normals are parallel to
  // its own (itself included), and the splits of their offsets into sheets.
  const std::size_t row = sheet_k + 1;
  std::vector<std::uint32_t> neighbors(size * k), parallel(size * row);
  std::vector<double> scales(size), spreads(size), radii(size);
  std::vector<std::size_t> counts(size);
  std::vector<Eigen::Vector3d> axes(size);
  std::vector<Sheets::Splits> splits(size);
  areas.assign(size, 0.);
  struct Scratch
  {
    Neighborhood neighborhood;
    Neighbor_search::Scratch search;
    std::vector<double> work;
    std::vector<Eigen::Vector3d> displacements;
  };
  const std::function<bool(double)> no_callback;
  Progress no_progress(no_callback, size);
  for_each_block<ConcurrencyTag>(size, no_progress, [] { return Scratch(); },
                                 [&](std::size_t begin, std::size_t end, Scratch& scratch) {
    for(std::size_t i = begin; i < end; ++i)
    {
      search.find(i, sheet_k, 0., scratch.neighborhood, scratch.search);
      // The point itself is not always first: a duplicate with a smaller id
      // comes before it.
      const std::vector<std::size_t>& positions = scratch.neighborhood.positions;
      const std::size_t nearest = (std::min<std::size_t>)(positions.size(), std::size_t(k) + 1);
      std::size_t t = 0;
      for(std::size_t u = 0; u < nearest; ++u)
        if(positions[u] != i && t < k)
          neighbors[i * k + t++] = std::uint32_t(positions[u]);
      scales[i] = offset_scale(scratch.neighborhood, nearest, i, normals[i], scratch.work);
      // The sheets are those of the neighbors whose normals are parallel to
      // the point's: a perpendicular face (the rim of a plate, the other
      // side of a sharp edge) is no sheet.
      // The offsets are taken along the mean line of those normals, the
      // point's own included: steadier under noise than one normal, whose
      // tilt would spread each sheet's offsets over the neighborhood.
      Eigen::Vector3d axis = Eigen::Vector3d::Zero();
      counts[i] = 0;
      for(std::size_t u = 0; u < (std::min)(positions.size(), row); ++u)
      {
        const double c = normals[i].dot(normals[positions[u]]);
        if(std::abs(c) > cos_parallel)
        {
          parallel[i * row + counts[i]++] = std::uint32_t(positions[u]);
          axis += c < 0 ? Eigen::Vector3d(-normals[positions[u]]) : normals[positions[u]];
        }
      }
      axes[i] = axis.squaredNorm() > 0 ? axis.normalized() : normals[i];
      scratch.work.clear();
      for(std::size_t t = 0; t < counts[i]; ++t)
        scratch.work.push_back(axes[i].dot(search.point(parallel[i * row + t]) - search.point(i)));
      splits[i] = Sheets::Splits(scratch.work);
      spreads[i] = splits[i].spread_within_sheets();
      radii[i] = scratch.neighborhood.radius;
      const double radius = scratch.neighborhood.points[nearest - 1].norm();
      areas[i] = CGAL_PI * radius * radius / double(nearest);
    }
  });
  // The noise across a sheet, over the cloud; on clean flat sheets, at
  // least a thousandth of the neighborhoods' size, so that the rounding
  // errors of their offsets are not taken for sheets.
  auto median = [size](std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(size / 2), values.end());
    return values[size / 2];
  };
  const double noise = (std::max)(median(spreads), 1e-3 * median(radii));
  // An outlier, off the surface, has its nearest neighbors off its tangent
  // plane, far beyond the noise; in a wedge's fit, it would pull the planes
  // away from the faces.
  auto off_surface = [&](std::size_t p) {
    return scales[p] > off_surface_noises * noise && scales[p] > off_surface_radius * radii[p];
  };
  std::vector<Sheets> sheets(size);
  std::vector<Wedge> wedges(size);
  std::vector<double> support(size);
  for_each_block<ConcurrencyTag>(size, no_progress, [] { return Scratch(); },
                                 [&](std::size_t begin, std::size_t end, Scratch& scratch) {
    std::vector<double>& work = scratch.work;
    for(std::size_t i = begin; i < end; ++i)
    {
      sheets[i] = Sheets(splits[i], noise);
      scratch.displacements.clear();
      for(std::size_t t = 0; t < counts[i]; ++t)
        if(!off_surface(parallel[i * row + t]))
          scratch.displacements.push_back(search.point(parallel[i * row + t]) - search.point(i));
      wedges[i] = Wedge(scratch.displacements, axes[i]);
      // Points within the noise of one plane are on one face.
      if(!(wedges[i].deviation() > noise))
        wedges[i] = Wedge();
      // The plane's band: the noise, and the bend of a curved surface over
      // the neighborhood.
      work.assign(1, 0.);
      double radius = 0;
      for(std::size_t t = 0; t < k; ++t)
      {
        const Eigen::Vector3d d = search.point(neighbors[i * k + t]) - search.point(i);
        work.push_back(normals[i].dot(d));
        radius = (std::max)(radius, d.norm());
      }
      support[i] = plane_support(work, 3 * noise + 0.15 * radius);
    }
  });
  // On which face of the point at position `p`'s neighborhood a neighbor at
  // `d` from it lies: its wedge's, else its sheets'.
  auto side = [&](std::size_t p, const Eigen::Vector3d& d) {
    return wedges[p].found() ? wedges[p].side(d) : sheets[p].side(axes[p].dot(d));
  };
  // Each pair once: a mutual pair by its first point, else by the point
  // whose neighbor the other is. The weight does not depend on which.
  std::vector<std::vector<Signed_edge> > blocks((size + 4095) / 4096);
  std::vector<std::size_t> block_numbers(blocks.size());
  std::iota(block_numbers.begin(), block_numbers.end(), std::size_t(0));
  CGAL::for_each<ConcurrencyTag>(block_numbers, [&](std::size_t block) {
    for(std::size_t i = block * 4096; i < (std::min)(size, (block + 1) * 4096); ++i)
      for(std::size_t t = 0; t < k; ++t)
      {
        const std::uint32_t j = neighbors[i * k + t];
        const auto first = neighbors.begin() + std::ptrdiff_t(j) * k;
        if(j < i && std::find(first, first + k, std::uint32_t(i)) != first + k)
          continue;
        const Eigen::Vector3d d = search.point(j) - search.point(i);
        // Across a sharp edge, each normal is its own face's, whatever its
        // support.
        const double trust =
          std::abs(normals[i].dot(normals[j])) > cos_parallel ? (std::min)(support[i], support[j]) : 1.;
        blocks[block].push_back({ std::uint32_t((std::min<std::size_t>)(i, j)), std::uint32_t((std::max<std::size_t>)(i, j)),
                                  trust * signed_weight(d, normals[i], normals[j], scales[i], scales[j], side(i, d),
                                                        side(j, -d)) });
      }
    return true;
  });
  std::size_t count = 0;
  for(const std::vector<Signed_edge>& block : blocks)
    count += block.size();
  std::vector<Signed_edge> edges;
  edges.reserve(count);
  for(const std::vector<Signed_edge>& block : blocks)
    edges.insert(edges.end(), block.begin(), block.end());
  return edges;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ORIENTATION_EDGES_H
