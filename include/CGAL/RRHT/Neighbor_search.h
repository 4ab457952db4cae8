// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Neighborhoods N_P of the points (paper, Sections 5 and 6): the k nearest
// neighbors, or the points in a ball of radius r, from one CGAL::Kd_tree.

#ifndef CGAL_RRHT_NEIGHBOR_SEARCH_H
#define CGAL_RRHT_NEIGHBOR_SEARCH_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Fuzzy_sphere.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/property_map.h>

#include <Eigen/Core>

#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {

/// The neighborhood of one point, in coordinates relative to that point.
struct Neighborhood
{
  /// The neighbors, the point itself included, minus the point.
  std::vector<Eigen::Vector3d> points;
  /// Radius of the ball centered on the point that holds all of `points`:
  /// the search radius, or the distance to the farthest neighbor kept when
  /// the neighborhood is a set of nearest neighbors. The small cubes and balls
  /// of RRHT_Cubes and RRHT_Unif tile this ball.
  double radius = 0;
};

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
/// Neighbors are listed nearest first (ties by index for balls), so a
/// neighborhood does not depend on how the tree was traversed, and a ball
/// whose cap is not reached is the same neighborhood as the uncapped ball.
///
/// The tree holds indices into the cloud; points whose index is not given to
/// the constructor (e.g. those with non-finite coordinates) are never
/// neighbors.
class Neighbor_search
{
public:
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;

private:
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Pointer_property_map<Point>::const_type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, Base_traits> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_true> Tree;
  typedef CGAL::Distance_adapter<std::size_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> K_neighbor_search;
  typedef CGAL::Fuzzy_sphere<Traits> Sphere;

public:
  /// Per-thread buffer of the search, reused from one query to the next.
  struct Scratch
  {
    std::vector<std::pair<double, std::size_t> > ball; // squared distance, index
  };

  /// `points`: the whole cloud (kept by reference); `indexed`: the indices of
  /// the points to put in the tree.
  Neighbor_search(const std::vector<Point>& points, const std::vector<std::size_t>& indexed)
    : m_points(points),
      m_point_map(CGAL::make_property_map(points)),
      m_traits(m_point_map),
      m_tree(indexed.begin(), indexed.end(), Splitter(), m_traits),
      m_distance(m_point_map)
  {
    m_tree.build();
  }

  /// The neighborhood of point `query` (an index given to the constructor).
  void find(std::size_t query, unsigned int k, double radius, Neighborhood& out, Scratch& scratch) const
  {
    const Point& q = m_points[query];
    out.points.clear();
    if(radius > 0)
    {
      if(k == 0)
      {
        scratch.ball.clear();
        m_tree.search(boost::make_function_output_iterator(Collect_with_distance{ &scratch.ball, &m_points, &q }),
                      Sphere(q, radius, 0., m_traits));
        if(scratch.ball.size() >= 3)
        {
          // Nearest first, like the k-neighborhoods, rather than in the
          // order of the tree traversal.
          std::sort(scratch.ball.begin(), scratch.ball.end());
          for(const auto& neighbor : scratch.ball)
            out.points.push_back(relative(neighbor.second, q));
          out.radius = radius;
          return;
        }
      }
      else
      {
        // The k + 1 nearest, cut at the radius: the ball, capped to the k nearest.
        K_neighbor_search search(m_tree, q, k + 1, 0, true, m_distance);
        const double squared_radius = radius * radius;
        double farthest = 0;
        for(const auto& neighbor : search)
        {
          if(neighbor.second > squared_radius)
            break;
          out.points.push_back(relative(neighbor.first, q));
          farthest = neighbor.second;
        }
        if(out.points.size() >= 3)
        {
          // A capped ball shrinks to the ball through the k-th neighbor.
          out.radius = (out.points.size() == k + 1) ? std::sqrt(farthest) : radius;
          return;
        }
        out.points.clear();
      }
      k = (k == 0) ? 3 : k; // fewer than 3 points in the ball: k nearest neighbors
    }

    K_neighbor_search search(m_tree, q, k + 1, 0, true, m_distance);
    double farthest = 0;
    for(const auto& neighbor : search)
    {
      out.points.push_back(relative(neighbor.first, q));
      farthest = neighbor.second;
    }
    out.radius = std::sqrt(farthest);
  }

private:
  // Output of the ball search: each index with its squared distance to the
  // query (an assignable functor, as the tree copies output iterators).
  struct Collect_with_distance
  {
    std::vector<std::pair<double, std::size_t> >* ball;
    const std::vector<Point>* points;
    const Point* query;
    void operator()(std::size_t i) const { ball->emplace_back(CGAL::squared_distance((*points)[i], *query), i); }
  };

  Eigen::Vector3d relative(std::size_t i, const Point& q) const
  {
    const Point& p = m_points[i];
    return Eigen::Vector3d(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
  }

  const std::vector<Point>& m_points;
  Point_map m_point_map;
  Traits m_traits;
  Tree m_tree;
  Distance m_distance;
};

} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_NEIGHBOR_SEARCH_H
