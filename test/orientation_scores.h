// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How oriented normals compare with the exact outward normals, for the tests
// and the benchmark: which point inward, and the largest patch of them.

#ifndef RRHT_TEST_ORIENTATION_SCORES_H
#define RRHT_TEST_ORIENTATION_SCORES_H

#include "shapes.h"

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>
#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace rrht_test {

/// The nearest samples of a cloud to a point, by their index in the cloud
/// (CGAL's kd-tree). Sequential: the benchmark's parent process never starts
/// TBB (it forks the measurements).
class Nearest_samples
{
  typedef CGAL::Pointer_property_map<Point>::type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Kernel> > Traits;

public:
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Knn;

  explicit Nearest_samples(const Cloud& cloud)
    : m_points(points_of(cloud)), m_map(CGAL::make_property_map(m_points)),
      m_tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(m_points.size()),
             Knn::Tree::Splitter(), Traits(m_map)),
      m_distance(m_map)
  {}

  /// The `k` samples nearest to `q`, nearest first (`first`: the index).
  Knn nearest(const Point& q, unsigned int k) const { return Knn(m_tree, q, k, 0, true, m_distance); }

private:
  static std::vector<Point> points_of(const Cloud& cloud)
  {
    std::vector<Point> points;
    for(const Sample& s : cloud)
      points.push_back(s.point);
    return points;
  }

  std::vector<Point> m_points;
  Point_map m_map;
  Knn::Tree m_tree;
  Knn::Distance m_distance;
};

/// The cosine of the angle between the normal of `s` and its exact normal;
/// 0 where either is null.
inline double cosine_to_truth(const Sample& s)
{
  const double norm = std::sqrt(s.normal.squared_length() * s.truth.squared_length());
  return norm > 0 ? (s.normal * s.truth) / norm : 0.;
}

/// Whether the normal of `s` points into the solid: within 60 degrees of its
/// exact, outward normal's line and against it. A normal farther off is not
/// the surface's (at an edge, a wrong plane): which way it points says
/// nothing of the orientation.
inline bool inward(const Sample& s) { return s.truth != CGAL::NULL_VECTOR && cosine_to_truth(s) <= -0.5; }

/// The largest connected set of inward normals (`inward()`), in points: two
/// inward points are joined where one is among the `k` nearest neighbors of
/// the other in the cloud (every point of it, outliers included, is a
/// neighbor). A few scattered wrong normals make patches of a point or two;
/// a region the orientation turned in as a whole makes one large patch.
inline std::size_t largest_inward_patch(const Cloud& cloud, unsigned int k)
{
  std::vector<std::size_t> parent(cloud.size());
  std::vector<char> is_inward(cloud.size(), 0);
  std::size_t inward_count = 0;
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    parent[i] = i;
    is_inward[i] = inward(cloud[i]);
    inward_count += is_inward[i];
  }
  if(inward_count == 0)
    return 0;
  auto find = [&](std::size_t i) {
    while(parent[i] != i)
      i = parent[i] = parent[parent[i]]; // path halving
    return i;
  };
  const Nearest_samples nearest_samples(cloud);
  for(std::size_t i = 0; i < cloud.size(); ++i)
  {
    if(!is_inward[i])
      continue;
    // The union over every inward point of its k nearest joins two points
    // where either is among the other's.
    const Nearest_samples::Knn search = nearest_samples.nearest(cloud[i].point, k + 1);
    for(const auto& neighbor : search)
      if(neighbor.first != i && is_inward[neighbor.first])
      {
        const std::size_t a = find(i), b = find(neighbor.first);
        if(a != b)
          parent[(std::max)(a, b)] = (std::min)(a, b);
      }
  }
  std::vector<std::size_t> size(cloud.size(), 0);
  std::size_t largest = 0;
  for(std::size_t i = 0; i < cloud.size(); ++i)
    if(is_inward[i])
      largest = (std::max)(largest, ++size[find(i)]);
  return largest;
}

} // namespace rrht_test

#endif // RRHT_TEST_ORIENTATION_SCORES_H
