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
#include <CGAL/Kd_tree.h>
#include <CGAL/property_map.h>
#include <CGAL/Hilbert_policy_tags.h>
#include <CGAL/Hilbert_sort_3.h>
#include <CGAL/Spatial_sort_traits_adapter_3.h>

#include <Eigen/Core>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/sort/pdqsort/pdqsort.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <numeric>
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
  /// False when a k-neighborhood came out smaller than asked for, the
  /// cloud holding fewer points: it then depends on all of the cloud.
  bool complete = true;
};

/// Whether a neighborhood of this radius can be given a normal: below 1e-150
/// or above 1e150 (or not a number), the squared distances and products of
/// coordinates that the estimators compute before they scale the points
/// would leave the normal range of doubles (1e-308 to 1e308).
inline bool has_computable_radius(double radius) { return radius >= 1e-150 && radius <= 1e150; }

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
/// Every neighborhood lists its points nearest first, points at the same
/// distance by increasing id, and a tie at the k-th neighbor is settled by
/// the ids too. The ids are stable 64-bit numbers given with the points
/// (their positions in the input by default): a neighborhood does not depend
/// on the tree or on which other points the cloud holds beyond it, so a part
/// of a cloud that holds a point's neighborhood gives that point the same
/// neighborhood, in the same order, as the whole cloud.
///
/// The points, all with finite coordinates, are stored in the order of a
/// Hilbert curve (`CGAL::Hilbert_sort_3`, median policy), and queries are
/// made by position in that order: points close in space are close in
/// memory, so consecutive queries walk the same branches of the tree and
/// read the same cache lines. Consecutive queries also have neighborhoods of
/// about the same radius: a k-neighborhood is first looked for among the
/// points within a little more than the previous one's radius, collected
/// from the tree without a queue, and CGAL's k-neighbor search runs only
/// where that ball holds too few. Positions are 32-bit, as the indices of
/// `CGAL::Point_set_3`: at most 2^32 - 1 points (`max_size()`).
class Neighbor_search
{
public:
  typedef CGAL::Simple_cartesian<double> Kernel;
  typedef Kernel::Point_3 Point;
  /// The most points a search holds.
  static constexpr std::size_t max_size() { return (std::numeric_limits<std::uint32_t>::max)(); }

private:
  // The tree holds positions in m_points; this map gives their points.
  struct Point_map
  {
    typedef std::uint32_t key_type;
    typedef Point value_type;
    typedef const Point& reference;
    typedef boost::readable_property_map_tag category;
    const Point* points = nullptr;
    friend reference get(const Point_map& map, std::uint32_t i) { return map.points[i]; }
  };
  typedef CGAL::Search_traits_3<Kernel> Base_traits;
  typedef CGAL::Search_traits_adapter<std::uint32_t, Point_map, Base_traits> Traits;
  typedef CGAL::Sliding_midpoint<Traits> Splitter;
  // Without the tree's cache of coordinates: the points are already in the
  // order of the tree's leaves, and the cache would cost 24 bytes per point.
  typedef CGAL::Kd_tree<Traits, Splitter, CGAL::Tag_true, CGAL::Tag_false> Tree;
  typedef CGAL::Distance_adapter<std::uint32_t, Point_map, CGAL::Euclidean_distance<Base_traits> > Distance;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits, Distance, Splitter, Tree> K_neighbor_search;
  typedef std::pair<double, std::size_t> Neighbor; // squared distance, position
  static constexpr unsigned int leaf_size = 32;
  // The ball first searched for a k-neighborhood: the previous one's radius
  // times this. Nearly all queries find enough points in it, and few more.
  static constexpr double radius_growth = 1.08;
  // A ball that holds more than this many times the points asked for is
  // given up for CGAL's search, which then costs less; the balls collected
  // for a k-neighborhood thus take bounded memory.
  static constexpr std::size_t most_per_point_asked = 16;

public:
  /// Per-thread buffer of the search, reused from one query to the next.
  struct Scratch
  {
    std::vector<Neighbor> ball;
    // The last k-neighborhood found with this scratch: its query, its number
    // of points (0 if it has fewer than asked for) and its squared radius.
    // They make the next search faster, never different.
    std::size_t previous = (std::numeric_limits<std::size_t>::max)();
    std::size_t previous_count = 0;
    double previous_squared_radius = 0;
    // The bucket sort's buffers (sort_nearest_first()).
    std::vector<std::uint32_t> buckets, bucket_ends;
    std::vector<Neighbor> sorted;
  };

  /// Takes `points`, at most `max_size()`, all with finite coordinates (the
  /// vector is emptied), sorts them along a Hilbert curve and builds the
  /// tree. The id of each point is its position in `points`.
  template <typename ConcurrencyTag>
  Neighbor_search(std::vector<Point>&& points, ConcurrencyTag tag)
    : Neighbor_search(std::move(points), std::vector<std::uint32_t>(), std::vector<std::uint64_t>(), tag)
  {}

  /// As above, where the point at `i` in `points` has the position
  /// `input[i]` in the input (`input` is emptied), unless `input` is empty,
  /// and the id `ids[input[i]]`, unless `ids` is empty.
  template <typename ConcurrencyTag>
  Neighbor_search(std::vector<Point>&& points, std::vector<std::uint32_t>&& input, const std::vector<std::uint64_t>& ids,
                  ConcurrencyTag)
    : m_points(std::move(points))
  {
    const std::size_t n = m_points.size();
    CGAL_precondition(n <= max_size() && (input.empty() || input.size() == n));
    // The curve's order of the positions, sorted as 4-byte indices, then the
    // points moved to it in place: the points are never copied.
    m_input.resize(n);
    std::iota(m_input.begin(), m_input.end(), std::uint32_t(0));
    m_point_map.points = m_points.data();
    // CGAL::hilbert_sort() shuffles the points first, which a Delaunay
    // insertion needs and a median split does not: its sorter alone.
    typedef CGAL::Spatial_sort_traits_adapter_3<Kernel, Point_map> Sort_traits;
    const CGAL::Hilbert_sort_3<Sort_traits, CGAL::Hilbert_sort_median_policy, ConcurrencyTag> sort(
      (Sort_traits(m_point_map)));
    sort(m_input.begin(), m_input.end());
    std::vector<bool> placed(n, false);
    for(std::size_t start = 0; start < n; ++start)
    {
      if(placed[start])
        continue;
      const Point first = m_points[start];
      std::size_t to = start;
      for(std::size_t from = m_input[to]; from != start; to = from, from = m_input[to])
        m_points[to] = m_points[from], placed[to] = true;
      m_points[to] = first, placed[to] = true;
    }
    if(!input.empty())
    {
      for(std::uint32_t& position : m_input)
        position = input[position];
      std::vector<std::uint32_t>().swap(input);
    }
    if(!ids.empty())
    {
      m_ids.reserve(n);
      for(std::uint32_t position : m_input)
        m_ids.push_back(ids[position]);
    }
    m_traits = Traits(m_point_map);
    m_distance = Distance(m_point_map);
    // Leaves of 32 points instead of CGAL's 10: a third of the nodes, and
    // queries of 18 to 100 neighbors as fast.
    m_tree.reset(new Tree(boost::counting_iterator<std::uint32_t>(0),
                          boost::counting_iterator<std::uint32_t>(std::uint32_t(m_points.size())), Splitter(leaf_size),
                          m_traits));
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
  std::size_t input_index(std::size_t i) const { return m_input[i]; }

  /// The point at position `i` in the tree's order.
  Eigen::Vector3d point(std::size_t i) const
  {
    const Point& p = m_points[i];
    return Eigen::Vector3d(p.x(), p.y(), p.z());
  }

  /// Id of the point at position `i` in the tree's order.
  std::uint64_t id(std::size_t i) const { return m_ids.empty() ? std::uint64_t(m_input[i]) : m_ids[i]; }

  /// The neighborhood of the point at position `query` (from 0 to `size()`).
  void find(std::size_t query, unsigned int k, double radius, Neighborhood& out, Scratch& scratch) const
  {
    const Point& q = m_points[query];
    std::vector<Neighbor>& ball = scratch.ball;
    out.points.clear();
    out.positions.clear();
    out.complete = true;
    if(radius > 0)
    {
      const double squared_radius = radius * radius;
      bool capped = false;
      if(k == 0)
      {
        ball.clear();
        collect(q, squared_radius, (std::numeric_limits<std::size_t>::max)(), ball);
        sort_nearest_first(ball, scratch);
      }
      else
      {
        // The k + 1 nearest, cut at the radius: when all are in the ball, the
        // ball capped to the k nearest, which shrinks to the ball through the
        // k-th neighbor; else the whole ball.
        nearest(query, std::size_t(k) + 1, scratch);
        capped = ball.size() == std::size_t(k) + 1 && ball.back().first <= squared_radius;
        if(!capped)
          ball.erase(std::find_if(ball.begin(), ball.end(), [&](const Neighbor& n) { return n.first > squared_radius; }),
                     ball.end());
      }
      if(ball.size() >= 3)
      {
        add_all(ball, q, out);
        out.radius = capped ? std::sqrt(ball.back().first) : radius;
        return;
      }
      k = (k == 0) ? 3 : k; // fewer than 3 points in the ball: k nearest neighbors
    }
    nearest(query, std::size_t(k) + 1, scratch);
    add_all(ball, q, out);
    out.radius = ball.empty() ? 0. : std::sqrt(ball.back().first);
    out.complete = ball.size() == std::size_t(k) + 1;
  }

  /// The neighborhood that `find()` gave at the point at position `query`,
  /// rebuilt from the positions of its points and its radius without
  /// searching again (`out.complete` is left as it is).
  template <typename Positions>
  void rebuild(std::size_t query, const Positions& positions, double radius, Neighborhood& out) const
  {
    const Point& q = m_points[query];
    out.points.clear();
    out.positions.clear();
    for(auto position : positions)
    {
      const Point& p = m_points[position];
      out.points.emplace_back(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
      out.positions.push_back(position);
    }
    out.radius = radius;
  }

private:
  // The order of neighborhoods: by squared distance, then by id.
  bool nearer(const Neighbor& a, const Neighbor& b) const
  {
    return a.first < b.first || (a.first == b.first && id(a.second) < id(b.second));
  }

  // Sorts neighbors nearer first (`nearer()`): the sort is the price of
  // neighborhoods that do not depend on the tree
  // (benchmark/results/tiles/README.md). The squared distances of points on
  // a surface spread evenly from 0 to the largest: a bucket sort on them,
  // about one neighbor a bucket, leaves a few neighbors to put in order by
  // an insertion sort. Where a bucket holds many (points of a volume, or
  // many at one distance), Boost's pdqsort.
  void sort_nearest_first(std::vector<Neighbor>& neighbors, Scratch& scratch) const
  {
    if(!bucket_sort(neighbors, scratch))
      boost::sort::pdqsort(neighbors.begin(), neighbors.end(),
                           [this](const Neighbor& a, const Neighbor& b) { return nearer(a, b); });
  }

  // The bucket sort of sort_nearest_first(); false, `neighbors` untouched,
  // where a bucket holds more than `crowded` of them.
  bool bucket_sort(std::vector<Neighbor>& neighbors, Scratch& scratch) const
  {
    constexpr std::uint32_t crowded = 12;
    const std::size_t n = neighbors.size();
    if(n <= crowded)
      return false;
    double largest = 0;
    for(const Neighbor& neighbor : neighbors)
      largest = (std::max)(largest, neighbor.first);
    if(!(largest > 0 && largest < std::numeric_limits<double>::infinity()))
      return false; // all at one distance, or one too far to scale
    // Buckets 0 to n - 1, in the order of the squared distances.
    const double scale = double(n - 1) / largest;
    std::vector<std::uint32_t>& bucket = scratch.buckets;
    std::vector<std::uint32_t>& end = scratch.bucket_ends;
    bucket.resize(n);
    end.assign(n + 1, 0);
    for(std::size_t i = 0; i < n; ++i)
    {
      bucket[i] = std::uint32_t(neighbors[i].first * scale);
      ++end[bucket[i] + 1];
    }
    std::uint32_t most = 0;
    for(std::size_t b = 1; b <= n; ++b)
      most = (std::max)(most, end[b]), end[b] += end[b - 1];
    if(most > crowded)
      return false;
    std::vector<Neighbor>& sorted = scratch.sorted;
    sorted.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      sorted[end[bucket[i]]++] = neighbors[i];
    for(std::size_t i = 1; i < n; ++i)
    {
      const Neighbor moved = sorted[i];
      std::size_t j = i;
      for(; j > 0 && nearer(moved, sorted[j - 1]); --j)
        sorted[j] = sorted[j - 1];
      sorted[j] = moved;
    }
    neighbors.swap(sorted);
    return true;
  }

  // The `count` nearest points to the point at position `query`, with
  // their squared distances, nearest first (`sort_nearest_first()`), in
  // `scratch.ball`. Any ball that holds at least `count` points holds them
  // all, the points at the last distance too: first the ball a little wider
  // than the previous neighborhood, then one that surely holds as many (the
  // triangle inequality: the previous radius plus the step between the two
  // queries), then CGAL's k-neighbor search. A ball is given up once it
  // holds `most_per_point_asked` times the points asked for: after a long
  // step (a thread taking up another part of the curve), the ball that
  // surely holds enough may hold most of the cloud.
  void nearest(std::size_t query, std::size_t count, Scratch& scratch) const
  {
    std::vector<Neighbor>& ball = scratch.ball;
    const Point& q = m_points[query];
    bool found = false;
    if(scratch.previous < size() && scratch.previous_count == count)
    {
      const double previous = std::sqrt(scratch.previous_squared_radius);
      const double step = std::sqrt(squared_distance(std::uint32_t(scratch.previous), q));
      const std::size_t most = most_per_point_asked * count;
      const double first = (std::min)(radius_growth * previous, previous + step);
      const double bounds[2] = { first, previous + step > first ? previous + step : 0. };
      for(double bound : bounds)
      {
        if(!(bound > 0))
          break;
        ball.clear();
        collect(q, bound * bound, most, ball);
        if(ball.size() >= count && ball.size() <= most)
        {
          sort_nearest_first(ball, scratch);
          ball.resize(count);
          found = true;
          break;
        }
        if(ball.size() > most)
          break; // a wider ball holds more
      }
    }
    if(!found)
      nearest_by_k_neighbor_search(q, count, scratch);
    scratch.previous = query;
    scratch.previous_count = ball.size() == count ? count : 0;
    scratch.previous_squared_radius = ball.empty() ? 0. : ball.back().first;
  }

  // As nearest(), with CGAL's k-neighbor search, which breaks ties at the
  // last distance by the tree's layout: one more point is asked for, and
  // while it is at that same distance, twice as many, until all the points
  // at that distance are known and the ids choose among them.
  void nearest_by_k_neighbor_search(const Point& q, std::size_t count, Scratch& scratch) const
  {
    std::vector<Neighbor>& out = scratch.ball;
    for(std::size_t asked = count + 1;; asked *= 2)
    {
      out.clear();
      K_neighbor_search search(*m_tree, q, (unsigned int)((std::min)(asked, size())), 0, true, m_distance, false);
      for(const auto& neighbor : search)
        out.emplace_back(neighbor.second, neighbor.first);
      sort_nearest_first(out, scratch);
      if(out.size() <= count)
        return;
      if(out.size() < asked || out.back().first > out[count - 1].first)
        break;
    }
    out.resize(count);
  }

  // Appends to `ball` the points within the squared distance `bound` of `q`,
  // with their squared distances (squared_distance()), from the tree's
  // root; stops once `ball` holds more than `most`.
  void collect(const Point& q, double bound, std::size_t most, std::vector<Neighbor>& ball) const
  {
    const double c[3] = { q.x(), q.y(), q.z() };
    double to_box[3] = { 0, 0, 0 };
    // A subtree is left out only beyond the rounding of its box's distance.
    collect(m_tree->root(), q, c, 0., to_box, bound, bound * (1 + 1e-9), most, ball);
  }

  // The same in the subtree `node`, whose box is at the distance `to_box[i]`
  // from `c`, the coordinates of `q`, along the axis i, and at the squared
  // distance `box`; the subtree is searched where `box` is at most `reach`.
  // The extended nodes of the tree give the extent of each child along its
  // parent's cutting axis, as in CGAL's own search.
  void collect(typename Tree::Node_const_handle node, const Point& q, const double* c, double box, double* to_box,
               double bound, double reach, std::size_t most, std::vector<Neighbor>& ball) const
  {
    if(ball.size() > most)
      return;
    if(node->is_leaf())
    {
      // Each point written, and kept if within the bound: whether a point
      // of a leaf that the ball cuts is in it is random, a branch would be
      // mispredicted.
      typename Tree::Leaf_node_const_handle leaf = static_cast<typename Tree::Leaf_node_const_handle>(node);
      std::size_t kept = ball.size();
      ball.resize(kept + leaf->size());
      for(auto it = leaf->begin(); it != leaf->end(); ++it)
      {
        const double d = squared_distance(*it, q);
        ball[kept] = Neighbor(d, *it);
        kept += (d <= bound);
      }
      ball.resize(kept);
      return;
    }
    typename Tree::Internal_node_const_handle inner = static_cast<typename Tree::Internal_node_const_handle>(node);
    const int axis = inner->cutting_dimension();
    const double v = c[axis], before = to_box[axis];
    const double to_lower = (std::max)((std::max)(0., v - inner->lower_high_value()), inner->lower_low_value() - v);
    const double to_upper = (std::max)((std::max)(0., inner->upper_low_value() - v), v - inner->upper_high_value());
    const double lower_box = box - before * before + to_lower * to_lower;
    const double upper_box = box - before * before + to_upper * to_upper;
    // Not left out where the distances overflow (NaN).
    if(!(lower_box > reach))
    {
      to_box[axis] = to_lower;
      collect(inner->lower(), q, c, lower_box, to_box, bound, reach, most, ball);
    }
    if(!(upper_box > reach))
    {
      to_box[axis] = to_upper;
      collect(inner->upper(), q, c, upper_box, to_box, bound, reach, most, ball);
    }
    to_box[axis] = before;
  }

  // The squared distance from the point at position `i` to `q`, as CGAL's
  // k-neighbor search computes it, so that all searches agree on ties.
  double squared_distance(std::uint32_t i, const Point& q) const
  {
    return m_distance.transformed_distance(q, i);
  }

  // Adds the `neighbors` to `out`, relative to the query `q`.
  void add_all(const std::vector<Neighbor>& neighbors, const Point& q, Neighborhood& out) const
  {
    for(const auto& neighbor : neighbors)
    {
      const Point& p = m_points[neighbor.second];
      out.points.emplace_back(p.x() - q.x(), p.y() - q.y(), p.z() - q.z());
      out.positions.push_back(neighbor.second);
    }
  }

  std::vector<Point> m_points;           // along the Hilbert curve
  std::vector<std::uint32_t> m_input;    // their positions in the input
  std::vector<std::uint64_t> m_ids;      // in the same order; empty: the input positions
  Point_map m_point_map;
  Traits m_traits;
  std::unique_ptr<Tree> m_tree;           // built once the points are in place
  Distance m_distance;
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NEIGHBOR_SEARCH_H
