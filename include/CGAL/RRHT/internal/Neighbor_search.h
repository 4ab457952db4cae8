// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Neighborhoods N_P of the points (paper, Sections 5 and 6): the k nearest
// neighbors, or the points in a ball of radius r, from one CGAL::Kd_tree.

#ifndef CGAL_RRHT_INTERNAL_NEIGHBOR_SEARCH_H
#define CGAL_RRHT_INTERNAL_NEIGHBOR_SEARCH_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/property_map.h>
#include <CGAL/hilbert_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>

#include <Eigen/Core>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The neighborhood of one point, in coordinates relative to that point.
struct Neighborhood
{
  /// The neighbors, the point itself included, minus the point.
  std::vector<Eigen::Vector3d> points;
  /// Their positions in the search's order (`Neighbor_search::input_index()`).
  std::vector<std::size_t> positions;
  /// Radius of the ball centered on the point that holds all of `points`:
  /// the search radius, or the distance to the farthest neighbor kept when
  /// the neighborhood is a set of nearest neighbors. The small cubes and balls
  /// of RRHT_Cubes and RRHT_Unif tile this ball.
  double radius = 0;
};

/// Whether the three coordinates of `p` are finite.
template <typename Point>
bool has_finite_coordinates(const Point& p)
{
  return std::isfinite(p.x()) && std::isfinite(p.y()) && std::isfinite(p.z());
}

/// Neighborhood queries on the points of a cloud, with CGAL's kd-tree.
///
/// - k-neighborhood (`radius` = 0): the point and its k nearest neighbors
///   (k + 1 points, as `CGAL::jet_estimate_normals()`), or all the points
///   when there are fewer.
/// - ball (`radius` > 0): the points within `radius`. When `k` > 0 caps the
///   ball and it holds more than k + 1 points, only the point and its k
///   nearest neighbors are kept, which does not favor any part of the ball
///   (as the first points met by the tree traversal would). A ball of fewer
///   than 3 points falls back to the k nearest neighbors (3 when k = 0).
///
/// Balls list their points nearest first (ties by position), so a ball
/// does not depend on how the tree was traversed, and a ball whose cap is
/// not reached is the same neighborhood as the uncapped ball. A ball whose
/// cap is reached is the k-neighborhood, listed as it in the order of
/// CGAL's search queue (deterministic for a given cloud).
///
/// The points, all with finite coordinates, are stored in the order of a Hilbert curve
/// (`CGAL::hilbert_sort()`), and queries are made by position in that order:
/// points close in space are close in memory, so consecutive queries walk
/// the same branches of the tree and read the same cache lines (measured in
/// `benchmark/results/targets/README.md`).
class Neighbor_search
{
public:
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;
  /// A point with its position in the input.
  typedef std::pair<Point, std::size_t> Indexed_point;

private:
  // The tree holds positions in m_points; this map gives their points.
  struct Point_map
  {
    typedef std::size_t key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::readable_property_map_tag category;
    const Indexed_point* points = nullptr;
    friend reference get(const Point_map& map, std::size_t i) { return map.points[i].first; }
  };
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  // Without the tree's cache of coordinates: the points are already in the
  // order of the tree's leaves, and the cache would cost 24 bytes per point.
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_false> Tree;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> K_neighbor_search;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

public:
  /// Per-thread buffer of the search, reused from one query to the next.
  struct Scratch
  {
    std::vector<std::pair<double, std::size_t> > ball; // squared distance, index
  };

  /// Takes the points of `cloud`, which must have finite coordinates (the
  /// cloud is emptied), sorts them along a Hilbert curve and builds the tree.
  template <typename ConcurrencyTag>
  Neighbor_search(std::vector<Indexed_point>&& cloud, ConcurrencyTag) : m_points(std::move(cloud))
  {
    typedef CGAL::Spatial_sort_traits_adapter_3<Kernel, CGAL::First_of_pair_property_map<Indexed_point> > Sort_traits;
    CGAL::hilbert_sort<ConcurrencyTag>(m_points.begin(), m_points.end(), Sort_traits(),
                                       CGAL::Hilbert_sort_median_policy());
    m_point_map.points = m_points.data();
    m_traits = Traits(m_point_map);
    m_distance = Distance(m_point_map);
    m_tree.reset(new Tree(boost::counting_iterator<std::size_t>(0),
                          boost::counting_iterator<std::size_t>(m_points.size()), Splitter(), m_traits));
    // In parallel when TBB is there (Kd_tree's own parallel build): the
    // same tree.
#ifdef CGAL_TBB_STRUCTURE_IN_KD_TREE
    m_tree->build<ConcurrencyTag>();
#else
    m_tree->build();
#endif
  }

  /// Number of points in the tree.
  std::size_t size() const { return m_points.size(); }

  /// Position in the input of the point at position `i` in the tree's order.
  std::size_t input_index(std::size_t i) const { return m_points[i].second; }

  /// The neighborhood of the point at position `query` (from 0 to `size()`).
  void find(std::size_t query, unsigned int k, double radius, Neighborhood& out, Scratch& scratch) const
  {
    const Point& q = m_points[query].first;
    out.points.clear();
    out.positions.clear();
    if(radius > 0)
    {
      if(k == 0)
      {
        scratch.ball.clear();
        m_tree->search(boost::make_function_output_iterator(Collect_with_distance{ &scratch.ball, &m_points, &q }),
                      Sphere(q, radius, 0., m_traits));
        if(scratch.ball.size() >= 3)
        {
          // Nearest first, like the k-neighborhoods, rather than in the
          // order of the tree traversal.
          std::sort(scratch.ball.begin(), scratch.ball.end());
          for(const auto& neighbor : scratch.ball)
            add(neighbor.second, q, out);
          out.radius = radius;
          return;
        }
      }
      else
      {
        // The k + 1 nearest, cut at the radius: the ball, capped to the k
        // nearest. When all are in the ball, it is the k-neighborhood (in
        // the same order) and shrinks to the ball through the k-th
        // neighbor; else it is the uncapped ball (sorted as it).
        K_neighbor_search search(*m_tree, q, k + 1, 0, true, m_distance, false);
        const double squared_radius = radius * radius;
        scratch.ball.clear();
        std::size_t nearest = 0;
        double farthest = 0;
        for(const auto& neighbor : search)
        {
          ++nearest;
          if(neighbor.second <= squared_radius)
          {
            scratch.ball.emplace_back(CGAL::squared_distance(m_points[neighbor.first].first, q), neighbor.first);
            farthest = (std::max)(farthest, neighbor.second);
          }
        }
        if(scratch.ball.size() >= 3)
        {
          const bool capped = (scratch.ball.size() == nearest && nearest == k + 1);
          if(!capped)
            std::sort(scratch.ball.begin(), scratch.ball.end());
          for(const auto& neighbor : scratch.ball)
            add(neighbor.second, q, out);
          out.radius = capped ? std::sqrt(farthest) : radius;
          return;
        }
      }
      k = (k == 0) ? 3 : k; // fewer than 3 points in the ball: k nearest neighbors
    }

    // Unsorted: the order of the search's queue, deterministic for a given
    // cloud (sorting would only cost time).
    K_neighbor_search search(*m_tree, q, k + 1, 0, true, m_distance, false);
    double farthest = 0;
    for(const auto& neighbor : search)
    {
      add(neighbor.first, q, out);
      farthest = (std::max)(farthest, neighbor.second);
    }
    out.radius = std::sqrt(farthest);
  }

private:
  // Output of the ball search: each index with its squared distance to the
  // query (an assignable functor, as the tree copies output iterators).
  struct Collect_with_distance
  {
    std::vector<std::pair<double, std::size_t> >* ball;
    const std::vector<Indexed_point>* points;
    const Point* query;
    void operator()(std::size_t i) const { ball->emplace_back(CGAL::squared_distance((*points)[i].first, *query), i); }
  };

  // Adds the point at position `i` to `out`, relative to the query `q`.
  void add(std::size_t i, const Point& q, Neighborhood& out) const
  {
    const Point& p = m_points[i].first;
    out.points.emplace_back(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
    out.positions.push_back(i);
  }

  std::vector<Indexed_point> m_points;   // along the Hilbert curve
  Point_map m_point_map;
  Traits m_traits;
  std::unique_ptr<Tree> m_tree;           // built once the points are in place
  Distance m_distance;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NEIGHBOR_SEARCH_H
