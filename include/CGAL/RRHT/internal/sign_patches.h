// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The patches of an oriented cloud: the pieces of smooth surface that the
// signs orient as one, which a global check of the signs flips whole.

#ifndef CGAL_RRHT_INTERNAL_SIGN_PATCHES_H
#define CGAL_RRHT_INTERNAL_SIGN_PATCHES_H

#include <CGAL/RRHT/internal/orientation_edges.h>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The patch of each vertex, numbered from 0 in the order of their first
/// vertex, and their number.
struct Sign_patches
{
  std::vector<std::uint32_t> patch;
  std::size_t count = 0;
};

/// Normals within 20 degrees of each other's line are on one face.
constexpr double cos_one_face = 0.9396926207859084;

/// An edge that joins two patches weighs at least this share of the most a
/// pair weighs: the less supported of two normals on the narrow rim of a
/// plate weighs less.
constexpr double least_joining_weight = 0.25;

/// Whether the edge `e` between `points` joins two points of one face, sure
/// of it, oriented alike by `signs`: their unit `normals` within 20 degrees
/// of each other's line, the chord between them within 15 degrees of both
/// tangent planes (the two sides of a wall thinner than a few neighbor
/// spacings, which the edge's weight may take for one face, lie along the
/// normals), an edge weight that says they agree as they are (not the two
/// sides of a thin part, nor the reflection across a sharp edge), at least
/// `least_joining_weight`, and signs that keep it.
inline bool joins_one_face(const Signed_edge& e, const std::vector<Eigen::Vector3d>& points,
                           const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& signs)
{
  const double sin_chord = 0.25;
  const double c = normals[e.a].dot(normals[e.b]);
  if(!(std::abs(c) > cos_one_face && e.weight * c > 0 && std::abs(e.weight) >= least_joining_weight &&
       e.weight * signs[e.a] * signs[e.b] > 0))
    return false;
  const Eigen::Vector3d chord = points[e.b] - points[e.a];
  const double length = chord.norm();
  return std::abs(normals[e.a].dot(chord)) <= sin_chord * length &&
         std::abs(normals[e.b].dot(chord)) <= sin_chord * length;
}

/// Whether the edge `e` says that its two points, whose unit `normals` are
/// parallel, are the two sides of a thin part or of a narrow gap.
inline bool joins_two_sides(const Signed_edge& e, const std::vector<Eigen::Vector3d>& normals)
{
  const double c = normals[e.a].dot(normals[e.b]);
  return std::abs(c) > cos_parallel && e.weight * c < 0;
}

/// The neighbors of each of `size` vertices along the `edges` that `keep`
/// keeps, in the order of the edges (compressed rows: those of `v` are
/// `next[first[v]]` to `next[first[v + 1] - 1]`).
struct Adjacency
{
  std::vector<std::size_t> first;
  std::vector<std::uint32_t> next;

  template <typename Keep>
  Adjacency(std::size_t size, const std::vector<Signed_edge>& edges, Keep keep) : first(size + 1, 0)
  {
    for(const Signed_edge& e : edges)
      if(keep(e))
      {
        ++first[e.a + 1];
        ++first[e.b + 1];
      }
    std::partial_sum(first.begin(), first.end(), first.begin());
    next.resize(first.back());
    std::vector<std::size_t> filled(first.begin(), first.end() - 1);
    for(const Signed_edge& e : edges)
      if(keep(e))
      {
        next[filled[e.a]++] = e.b;
        next[filled[e.b]++] = e.a;
      }
  }
};

/// The patches of the `points`, grown one after the other from the first
/// point that none holds yet, breadth first, along the `edges` that join
/// one face (`joins_one_face()`), to the points whose oriented normal stays
/// within 20 degrees of the first one's and none of whose edges says it is
/// on the other side of a thin part from a point of the patch
/// (`joins_two_sides()`). A patch is a piece of smooth surface that the
/// signs orient as one: it never spans the two sides of a thin part nor a
/// sharp edge, even where the normals blur across the edge or a few edges
/// take the two sides of a wall for one face, so that a face that an early
/// join turned over, with the points across a thin wall that the join went
/// through, falls into patches of its own. A curved face falls into
/// several. The result depends on the order of the edges, which is fixed.
inline Sign_patches sign_patches(const std::vector<Eigen::Vector3d>& points, const std::vector<Signed_edge>& edges,
                                 const std::vector<Eigen::Vector3d>& normals, const std::vector<int>& signs)
{
  const std::size_t size = points.size();
  const Adjacency one_face(size, edges, [&](const Signed_edge& e) { return joins_one_face(e, points, normals, signs); });
  const Adjacency two_sides(size, edges, [&](const Signed_edge& e) { return joins_two_sides(e, normals); });
  const std::uint32_t none = std::uint32_t(-1);
  Sign_patches patches;
  patches.patch.assign(size, none);
  std::vector<std::uint32_t> queue;
  auto across_from = [&](std::uint32_t v, std::uint32_t number) {
    for(std::size_t t = two_sides.first[v]; t < two_sides.first[v + 1]; ++t)
      if(patches.patch[two_sides.next[t]] == number)
        return true;
    return false;
  };
  for(std::size_t seed = 0; seed < size; ++seed)
  {
    if(patches.patch[seed] != none)
      continue;
    const std::uint32_t number = std::uint32_t(patches.count++);
    const Eigen::Vector3d axis = double(signs[seed]) * normals[seed];
    patches.patch[seed] = number;
    queue.assign(1, std::uint32_t(seed));
    for(std::size_t head = 0; head < queue.size(); ++head)
      for(std::size_t t = one_face.first[queue[head]]; t < one_face.first[queue[head] + 1]; ++t)
      {
        const std::uint32_t v = one_face.next[t];
        if(patches.patch[v] == none && double(signs[v]) * normals[v].dot(axis) > cos_one_face &&
           !across_from(v, number))
        {
          patches.patch[v] = number;
          queue.push_back(v);
        }
      }
  }
  return patches;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SIGN_PATCHES_H
