// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A consistent orientation of unoriented normals from the points alone.

#ifndef CGAL_RRHT_INTERNAL_CONSISTENT_ORIENTATION_H
#define CGAL_RRHT_INTERNAL_CONSISTENT_ORIENTATION_H

#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Signed_agglomeration.h>
#include <CGAL/RRHT/internal/global_signs.h>
#include <CGAL/RRHT/internal/orientation_edges.h>
#include <CGAL/RRHT/internal/outward_signs.h>
#include <CGAL/RRHT/internal/relaxed_signs.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// +1 or -1: the sign that turns `normal` to the one of its two senses whose
/// largest coordinate in absolute value (the first of equal ones) is
/// positive.
inline int canonical_sign(const Eigen::Vector3d& normal)
{
  Eigen::Index largest = 0;
  normal.cwiseAbs().maxCoeff(&largest);
  return normal[largest] < 0 ? -1 : 1;
}

/// The sign, +1 or -1, by which each unit normal of `given` (in the order
/// of `search`) is to be multiplied: the signed edges of the graph of the
/// `k` nearest neighbors (`orientation_edges()`) join the points into
/// consistently oriented clusters (`signed_clusters()`), each cluster is
/// turned out of the solid (`outward_signs()`), the signs within each
/// cluster are relaxed by all its edges at once (`relaxed_signs()`), and
/// whole patches are turned back where the winding number of the whole
/// cloud says so (`global_signs()`). The
/// normals are first turned to a sense that depends on their lines only, so
/// that the result does not depend on the senses given, to the last bit.
template <typename ConcurrencyTag>
std::vector<int> consistent_orientation(const Neighbor_search& search, const std::vector<Eigen::Vector3d>& given,
                                        unsigned int k)
{
  const std::size_t size = search.size();
  if(size < 2)
    return std::vector<int>(size, 1);
  std::vector<int> canonical(size);
  std::vector<Eigen::Vector3d> normals(size);
  for(std::size_t v = 0; v < size; ++v)
  {
    canonical[v] = canonical_sign(given[v]);
    normals[v] = double(canonical[v]) * given[v];
  }
  std::vector<double> areas;
  // Blocks of 8192 points along the search's Hilbert order: large enough
  // that the clusters are nearly those of one agglomeration of the whole
  // graph, small enough that each block's heap stays in the cache.
  const std::vector<Signed_edge> edges = orientation_edges<ConcurrencyTag>(search, normals, k, areas);
  const Signed_clusters clusters = signed_clusters<ConcurrencyTag>(size, edges, 8192);
  std::vector<std::uint32_t> cluster(size);
  std::vector<int> signs(size);
  std::vector<Eigen::Vector3d> points(size);
  for(std::size_t v = 0; v < size; ++v)
  {
    cluster[v] = clusters.cluster[v];
    signs[v] = clusters.sign[v];
    points[v] = search.point(v);
  }
  const std::vector<std::vector<std::uint32_t> > members = clusters_of(cluster);
  const std::vector<int> outward = outward_signs(members, points, normals, signs, areas);
  for(std::size_t c = 0; c < members.size(); ++c)
    for(std::uint32_t v : members[c])
      signs[v] *= outward[c];
  signs = relaxed_signs<ConcurrencyTag>(size, edges, cluster, std::move(signs));
  signs = global_signs<ConcurrencyTag>(points, normals, areas, edges, std::move(signs));
  for(std::size_t v = 0; v < size; ++v)
    signs[v] *= canonical[v];
  return signs;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_CONSISTENT_ORIENTATION_H
