// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The generalized winding number of oriented points (Barill et al. 2018),
// each group of points' share apart, at query points away from the surface.

#ifndef CGAL_RRHT_INTERNAL_PATCH_WINDING_NUMBERS_H
#define CGAL_RRHT_INTERNAL_PATCH_WINDING_NUMBERS_H

#include <CGAL/for_each.h>
#include <CGAL/number_type_config.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The winding number at query points of a cloud of oriented points, each
/// point `v` a dipole of moment `areas[v] * normals[v]` (the discrete form of
/// the winding number's integral, Barill et al. 2018, Eq. 4), summed apart
/// for each of `groups` groups of points (`group[v]`, `groups` for a point
/// of none), and for the points of no group.
///
/// The cloud's bounding cube is cut into an octree of `2^depth` cells a
/// side; each cell holds, for each group with points in it, the sum of their
/// moments at their area-weighted centroid. A cell seen from a query within
/// `opening` of its side over its distance is taken whole (Barnes and Hut
/// 1986, the far-field expansion of Barill et al. to its first term),
/// otherwise its children are; the finest cells are always taken whole,
/// which is accurate where the query is a few cells from every point. The
/// queries are the centers of the cells of half the finest resolution
/// whose nearest point lies at least `clearance` finest cells away: the
/// winding number is evaluated away from the surface, where a patch that is
/// turned over changes it by its whole share, while a step either side of a
/// point would see the patch's own share turn with it. Where the surface
/// bounds a space narrower than that (a small bore, a slot, a wall), no
/// cell is that clear: the queries are then also the centers of the
/// largest empty balls that touch the points `seeds` on either side
/// (`medial_center()`), their sums taken point by point near them. Each
/// query's sums are taken in the same order whatever the number of
/// threads. It keeps references to `points`, `normals` and `areas`, which
/// must outlive it.
class Patch_winding_numbers
{
public:
  template <typename ConcurrencyTag>
  Patch_winding_numbers(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                        const std::vector<double>& areas, const std::vector<std::uint32_t>& group, std::size_t groups,
                        ConcurrencyTag, const std::vector<std::uint32_t>& seeds = std::vector<std::uint32_t>())
    : m_groups(groups), m_points(&points), m_normals(&normals), m_areas(&areas)
  {
    if(!bound(points))
      return;
    build_levels(points, normals, areas, group);
    place_queries(points);
    const std::size_t grid_queries = m_queries.size();
    place_medial_queries<ConcurrencyTag>(seeds);
    m_shares.assign(m_queries.size() * (m_groups + 1), 0.f);
    std::vector<std::size_t> queries(m_queries.size());
    std::iota(queries.begin(), queries.end(), std::size_t(0));
    CGAL::for_each<ConcurrencyTag>(queries, [&](std::size_t q) {
      std::vector<double> sums(m_groups + 1, 0.);
      add_shares(m_queries[q], 0, 0, sums, q >= grid_queries);
      for(std::size_t g = 0; g <= m_groups; ++g)
        m_shares[g * m_queries.size() + q] = float(sums[g]);
      return true;
    });
  }

  /// The number of query points: the grid's (`grid_size()`), then the
  /// medial ones.
  std::size_t size() const { return m_queries.size(); }
  std::size_t grid_size() const { return m_queries.size() - m_medial_touched.size(); }

  /// For each medial query, in their order after the grid's, the point
  /// across the space from its seed that its empty ball touches too.
  const std::vector<std::uint32_t>& medial_touched() const { return m_medial_touched; }

  /// The query points.
  const std::vector<Eigen::Vector3d>& queries() const { return m_queries; }

  /// The share of each group (then of the points of none) in the winding
  /// number at any point `q`: as at the queries, but the finest cells near
  /// `q` are summed point by point, so that it may lie between two sides of
  /// a part thinner than a cell.
  std::vector<double> shares_at(const Eigen::Vector3d& q) const
  {
    std::vector<double> sums(m_groups + 1, 0.);
    if(!m_levels.empty())
      add_shares(q, 0, 0, sums, true);
    return sums;
  }

  /// The share of group `g` (`groups` for the points of no group) in the
  /// winding number at each query, in the order of `queries()`.
  const float* shares(std::size_t g) const { return m_shares.data() + g * m_queries.size(); }
  float* shares(std::size_t g) { return m_shares.data() + g * m_queries.size(); }

private:
  static constexpr unsigned int depth = 6;
  static constexpr double opening = 0.5;
  static constexpr int clearance = 3;
  // Nearer the points than this many spacings (the square root of a
  // point's area), the sum over the points strays from the integral.
  static constexpr double medial_spacings = 2;

  // The moments of one group's points in one cell; at the finest level,
  // also where its points are in `m_order`.
  struct Cell_group
  {
    std::uint32_t code; // Morton code of the cell at its level
    std::uint32_t group;
    Eigen::Vector3d moment, centroid;
    double area;
    std::uint32_t first = 0, count = 0;
  };

  bool bound(const std::vector<Eigen::Vector3d>& points)
  {
    if(points.empty())
      return false;
    Eigen::Vector3d lo = points[0], hi = points[0];
    for(const Eigen::Vector3d& p : points)
    {
      lo = lo.cwiseMin(p);
      hi = hi.cwiseMax(p);
    }
    m_side = (hi - lo).maxCoeff();
    if(!(m_side > 0))
      return false;
    // A margin, so that the points of the largest coordinates fall inside.
    m_side *= 1 + 1e-9;
    m_corner = lo;
    return true;
  }

  std::uint32_t cell_coordinate(double x, double lo) const
  {
    const double cells = double(1u << depth);
    const double c = (x - lo) / m_side * cells;
    return std::uint32_t((std::min)(cells - 1, (std::max)(0., std::floor(c))));
  }

  static std::uint32_t morton(std::uint32_t x, std::uint32_t y, std::uint32_t z)
  {
    std::uint32_t code = 0;
    for(unsigned int bit = 0; bit < depth; ++bit)
      code |= (((x >> bit) & 1u) << (3 * bit)) | (((y >> bit) & 1u) << (3 * bit + 1)) |
              (((z >> bit) & 1u) << (3 * bit + 2));
    return code;
  }

  // The finest cells' moments, from the points in a fixed order, then each
  // coarser level from the one below.
  void build_levels(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
                    const std::vector<double>& areas, const std::vector<std::uint32_t>& group)
  {
    std::vector<std::pair<std::uint64_t, std::uint32_t> > keys(points.size());
    for(std::size_t v = 0; v < points.size(); ++v)
    {
      const Eigen::Vector3d& p = points[v];
      const std::uint32_t code = morton(cell_coordinate(p.x(), m_corner.x()), cell_coordinate(p.y(), m_corner.y()),
                                        cell_coordinate(p.z(), m_corner.z()));
      keys[v] = { (std::uint64_t(code) << 32) | (std::min<std::size_t>)(group[v], m_groups), std::uint32_t(v) };
    }
    std::sort(keys.begin(), keys.end());
    m_levels.assign(depth + 1, std::vector<Cell_group>());
    std::vector<Cell_group>& finest = m_levels[depth];
    m_order.resize(keys.size());
    for(std::size_t t = 0; t < keys.size(); ++t)
    {
      const auto& key = keys[t];
      const std::uint32_t code = std::uint32_t(key.first >> 32), g = std::uint32_t(key.first & 0xffffffffu);
      if(finest.empty() || finest.back().code != code || finest.back().group != g)
        finest.push_back({ code, g, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0., std::uint32_t(t), 0 });
      const std::uint32_t v = key.second;
      m_order[t] = v;
      finest.back().moment += areas[v] * normals[v];
      finest.back().centroid += areas[v] * points[v];
      finest.back().area += areas[v];
      ++finest.back().count;
    }
    for(Cell_group& c : finest)
      c.centroid = c.area > 0 ? Eigen::Vector3d(c.centroid / c.area) : Eigen::Vector3d::Zero();
    for(unsigned int level = depth; level > 0; --level)
    {
      std::vector<Cell_group> parents;
      for(const Cell_group& c : m_levels[level])
        parents.push_back({ c.code >> 3, c.group, c.moment, c.area * c.centroid, c.area, 0, 0 });
      std::stable_sort(parents.begin(), parents.end(), [](const Cell_group& x, const Cell_group& y) {
        return x.code != y.code ? x.code < y.code : x.group < y.group;
      });
      std::vector<Cell_group>& merged = m_levels[level - 1];
      for(const Cell_group& c : parents)
        if(!merged.empty() && merged.back().code == c.code && merged.back().group == c.group)
        {
          merged.back().moment += c.moment;
          merged.back().centroid += c.centroid;
          merged.back().area += c.area;
        }
        else
          merged.push_back(c);
      for(Cell_group& c : merged)
        c.centroid = c.area > 0 ? Eigen::Vector3d(c.centroid / c.area) : Eigen::Vector3d::Zero();
    }
  }

  // The centers of the cells of half the finest resolution that no point
  // comes within `clearance` finest cells of.
  void place_queries(const std::vector<Eigen::Vector3d>& points)
  {
    const int cells = 1 << depth;
    std::vector<char> occupied(std::size_t(cells) * cells * cells, 0);
    for(const Eigen::Vector3d& p : points)
      occupied[(std::size_t(cell_coordinate(p.z(), m_corner.z())) * cells + cell_coordinate(p.y(), m_corner.y())) *
                 cells + cell_coordinate(p.x(), m_corner.x())] = 1;
    const double finest_side = m_side / cells;
    for(int z = 1; z < cells; z += 2)
      for(int y = 1; y < cells; y += 2)
        for(int x = 1; x < cells; x += 2)
        {
          // The query is the corner shared by the finest cells x - 1 and x
          // along each axis.
          bool clear = true;
          for(int dz = -clearance; clear && dz < clearance; ++dz)
            for(int dy = -clearance; clear && dy < clearance; ++dy)
              for(int dx = -clearance; clear && dx < clearance; ++dx)
              {
                const int cx = x + dx, cy = y + dy, cz = z + dz;
                if(cx >= 0 && cy >= 0 && cz >= 0 && cx < cells && cy < cells && cz < cells &&
                   occupied[(std::size_t(cz) * cells + cy) * cells + cx])
                  clear = false;
              }
          if(clear)
            m_queries.push_back(m_corner + finest_side * Eigen::Vector3d(x, y, z));
        }
  }

  // The center of the largest ball empty of points that touches the point
  // `v` on the side of `sense` times its normal, shrunk from the grid's
  // clearance (the shrinking ball of Ma, Bae and Choi 2012): while
  // a point lies inside, the ball becomes the one tangent at `v` through
  // the nearest such point, which it then `touched`. The points within
  // `least` of `v` are its own surface, whose noise would shrink the ball
  // to nothing. False where the ball keeps the clearance (the grid's
  // queries see there) or shrinks below `least`.
  bool medial_center(std::uint32_t v, double sense, double least, Eigen::Vector3d& center, std::uint32_t& touched) const
  {
    const Eigen::Vector3d& p = (*m_points)[v];
    const Eigen::Vector3d m = sense * (*m_normals)[v];
    const double most = clearance * m_side / double(1u << depth);
    double radius = most;
    for(int step = 0; step < 32; ++step)
    {
      center = p + radius * m;
      std::uint32_t inside = 0;
      if(!nearest_inside(center, radius, p, least, inside))
        return radius < most;
      const Eigen::Vector3d d = (*m_points)[inside] - p;
      const double along = m.dot(d);
      if(!(along > 0))
        return false;
      radius = d.squaredNorm() / (2 * along);
      touched = inside;
      if(radius < least)
        return false;
    }
    return false;
  }

  // The point nearest to `c` strictly within `radius` of it, of those at
  // least `least` from `p`, from the finest cells that the ball meets; the
  // first of equal ones in the cells' order. False if none.
  bool nearest_inside(const Eigen::Vector3d& c, double radius, const Eigen::Vector3d& p, double least,
                      std::uint32_t& nearest) const
  {
    const std::vector<Cell_group>& finest = m_levels[depth];
    std::uint32_t lo[3], hi[3];
    for(int a = 0; a < 3; ++a)
    {
      lo[a] = cell_coordinate(c[a] - radius, m_corner[a]);
      hi[a] = cell_coordinate(c[a] + radius, m_corner[a]);
    }
    double best = radius * radius;
    bool found = false;
    for(std::uint32_t z = lo[2]; z <= hi[2]; ++z)
      for(std::uint32_t y = lo[1]; y <= hi[1]; ++y)
        for(std::uint32_t x = lo[0]; x <= hi[0]; ++x)
        {
          const std::uint32_t code = morton(x, y, z);
          for(auto it = std::lower_bound(finest.begin(), finest.end(), code,
                                         [](const Cell_group& cell, std::uint32_t value) { return cell.code < value; });
              it != finest.end() && it->code == code; ++it)
            for(std::uint32_t t = it->first; t < it->first + it->count; ++t)
            {
              const std::uint32_t u = m_order[t];
              const Eigen::Vector3d& q = (*m_points)[u];
              const double d = (q - c).squaredNorm();
              if(d < best && (q - p).squaredNorm() >= least * least)
              {
                best = d;
                nearest = u;
                found = true;
              }
            }
        }
    return found;
  }

  // Appends the medial centers (`medial_center()`) of the points `seeds`,
  // both sides of each in turn, where they lie `medial_spacings` from
  // every point or more.
  template <typename ConcurrencyTag>
  void place_medial_queries(const std::vector<std::uint32_t>& seeds)
  {
    std::vector<Eigen::Vector3d> centers(2 * seeds.size());
    std::vector<std::uint32_t> touched(2 * seeds.size(), 0);
    std::vector<char> found(2 * seeds.size(), 0);
    std::vector<std::size_t> numbers(centers.size());
    std::iota(numbers.begin(), numbers.end(), std::size_t(0));
    CGAL::for_each<ConcurrencyTag>(numbers, [&](std::size_t i) {
      const std::uint32_t v = seeds[i / 2];
      found[i] = medial_center(v, i % 2 ? -1. : 1., medial_spacings * std::sqrt((*m_areas)[v]), centers[i],
                                touched[i]);
      return true;
    });
    for(std::size_t i = 0; i < centers.size(); ++i)
      if(found[i])
      {
        m_queries.push_back(centers[i]);
        m_medial_touched.push_back(touched[i]);
      }
  }

  // Adds the shares of the cell of `code` at `level` at query `q` to `sums`;
  // with `point_by_point`, the finest cells near `q` point by point.
  void add_shares(const Eigen::Vector3d& q, unsigned int level, std::uint32_t code, std::vector<double>& sums,
                  bool point_by_point = false) const
  {
    const std::vector<Cell_group>& cells = m_levels[level];
    auto first = std::lower_bound(cells.begin(), cells.end(), code,
                                  [](const Cell_group& c, std::uint32_t value) { return c.code < value; });
    if(first == cells.end() || first->code != code)
      return;
    const double side = m_side / double(1u << level);
    Eigen::Vector3d center = m_corner;
    for(unsigned int bit = 0; bit < level; ++bit)
      center += side * Eigen::Vector3d(double((code >> (3 * bit)) & 1u), double((code >> (3 * bit + 1)) & 1u),
                                       double((code >> (3 * bit + 2)) & 1u)) * double(1u << bit);
    center += Eigen::Vector3d::Constant(side / 2);
    const bool near = side > opening * (center - q).norm();
    if(level < depth && near)
    {
      for(std::uint32_t child = 0; child < 8; ++child)
        add_shares(q, level + 1, (code << 3) | child, sums, point_by_point);
      return;
    }
    for(auto it = first; it != cells.end() && it->code == code; ++it)
      if(near && point_by_point)
        for(std::uint32_t t = it->first; t < it->first + it->count; ++t)
        {
          const std::uint32_t v = m_order[t];
          sums[it->group] += dipole((*m_areas)[v] * (*m_normals)[v], (*m_points)[v] - q);
        }
      else
        sums[it->group] += dipole(it->moment, it->centroid - q);
  }

  // The winding number at a query `d` from a dipole of moment `moment`.
  static double dipole(const Eigen::Vector3d& moment, const Eigen::Vector3d& d)
  {
    const double r = d.norm();
    return r > 0 ? moment.dot(d) / (4 * CGAL_PI * r * r * r) : 0.;
  }

  std::size_t m_groups;
  double m_side = 0;
  Eigen::Vector3d m_corner = Eigen::Vector3d::Zero();
  std::vector<std::vector<Cell_group> > m_levels; // by level, each sorted by code then group
  std::vector<Eigen::Vector3d> m_queries;
  std::vector<std::uint32_t> m_medial_touched;
  const std::vector<Eigen::Vector3d>* m_points = nullptr; // the arrays given, for the point-by-point sums
  const std::vector<Eigen::Vector3d>* m_normals = nullptr;
  const std::vector<double>* m_areas = nullptr;
  std::vector<std::uint32_t> m_order; // the points by finest cell, then group
  std::vector<float> m_shares; // group-major: m_shares[g * size() + q]
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_PATCH_WINDING_NUMBERS_H
