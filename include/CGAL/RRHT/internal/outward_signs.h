// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sign of each consistently oriented cluster of points that makes its
// normals point out of the solid that the surfaces bound.

#ifndef CGAL_RRHT_INTERNAL_OUTWARD_SIGNS_H
#define CGAL_RRHT_INTERNAL_OUTWARD_SIGNS_H

#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The points of each cluster, the clusters in the order of their first
/// point.
inline std::vector<std::vector<std::uint32_t> > clusters_of(const std::vector<std::uint32_t>& cluster)
{
  std::unordered_map<std::uint32_t, std::size_t> index;
  std::vector<std::vector<std::uint32_t> > members;
  for(std::size_t v = 0; v < cluster.size(); ++v)
  {
    const auto found = index.emplace(cluster[v], members.size());
    if(found.second)
      members.emplace_back();
    members[found.first->second].push_back(std::uint32_t(v));
  }
  return members;
}

/// For each cluster of `members`, +1 or -1: the sign by which the normals
/// `normals[v] * signs[v]` of its points `points[v]` should be multiplied so
/// that they point out of the solid, each point standing for an area
/// `areas[v]` of the surface.
///
/// - A closed surface oriented outward has a positive flux of the position
///   through it: 3 times the volume it bounds (divergence theorem). The sign
///   of that flux orients each cluster. An open surface has no outside: its
///   side is then the one the flux prefers.
/// - A closed surface within another one bounds a cavity (the inside of a
///   hollow part), whose outward normals, out of the material, point into
///   it: a cluster that lies within an odd number of others, by the winding
///   number of their oriented points (Barill et al. 2018) at its own points,
///   is flipped. This is checked among the `max_nested` largest clusters of
///   at least 100 points and a thousandth of the cloud.
inline std::vector<int> outward_signs(const std::vector<std::vector<std::uint32_t> >& members,
                                      const std::vector<Eigen::Vector3d>& points,
                                      const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& signs,
                                      const std::vector<double>& areas, std::size_t max_nested = 64)
{
  std::vector<int> outward(members.size(), 1);
  for(std::size_t c = 0; c < members.size(); ++c)
  {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    for(std::uint32_t v : members[c])
      center += points[v];
    center /= double(members[c].size());
    double flux = 0;
    for(std::uint32_t v : members[c])
      flux += areas[v] * signs[v] * normals[v].dot(points[v] - center);
    outward[c] = flux < 0 ? -1 : 1;
  }

  std::vector<std::size_t> large;
  for(std::size_t c = 0; c < members.size(); ++c)
    if(members[c].size() >= (std::max<std::size_t>)(100, points.size() / 1000))
      large.push_back(c);
  std::stable_sort(large.begin(), large.end(),
                   [&](std::size_t x, std::size_t y) { return members[x].size() > members[y].size(); });
  if(large.size() > max_nested)
    large.resize(max_nested);
  // The winding number of cluster `a`, oriented outward, at point `q`.
  auto winding_number = [&](std::size_t a, const Eigen::Vector3d& q) {
    double w = 0;
    for(std::uint32_t v : members[a])
    {
      const Eigen::Vector3d d = points[v] - q;
      const double r = d.norm();
      if(r > 0)
        w += areas[v] * signs[v] * normals[v].dot(d) / (r * r * r);
    }
    return outward[a] * w / (4 * CGAL_PI);
  };
  std::vector<int> depth(members.size(), 0);
  const std::size_t queries = 9;
  for(std::size_t b : large)
    for(std::size_t a : large)
    {
      if(a == b)
        continue;
      // The median over points spread along the cluster, so that a few of
      // them near the other surface, where the sum is least accurate, do not
      // decide.
      std::vector<double> w;
      for(std::size_t q = 0; q < queries; ++q)
        w.push_back(winding_number(a, points[members[b][q * members[b].size() / queries]]));
      std::nth_element(w.begin(), w.begin() + queries / 2, w.end());
      depth[b] += w[queries / 2] > 0.5;
    }
  for(std::size_t c = 0; c < members.size(); ++c)
    if(depth[c] % 2 == 1)
      outward[c] = -outward[c];
  return outward;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_OUTWARD_SIGNS_H
