// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Orientation of unoriented normals (such as those of
// `CGAL::rrht_estimate_normals()`): towards a direction or a viewpoint, or
// consistently, out of the solid, from the points alone.

#ifndef CGAL_RRHT_ORIENT_NORMALS_H
#define CGAL_RRHT_ORIENT_NORMALS_H

#include <CGAL/RRHT/parameters.h>

#include <CGAL/RRHT/internal/Elements.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/check_parameters.h>
#include <CGAL/RRHT/internal/consistent_orientation.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/**
   \ingroup PkgRRHTRef

   Orients the normals of the range of `points`, in place:

   - with `direction`, each normal is flipped where it points against that
     direction (aerial surveys: "up");
   - with `viewpoint` or `viewpoint_map`, each normal is flipped where it
     points away from the viewpoint, or the point's own sensor position
     (terrestrial scans);
   - else, the normals are oriented consistently from the points alone, and
     out of the solid where the surface is closed.

   The consistent orientation joins the points into consistently oriented
   clusters on the graph of their `k` nearest neighbors, whose edges say
   whether their two normals agree. Nearly parallel normals agree by the
   sign of their dot product where each point lies on the other's tangent
   plane (as in `CGAL::mst_orient_normals()`). Where a neighborhood holds
   the two or three faces of a thin part or of a narrow gap, a pair agrees
   only when each point is on the other's face, and is opposite when each
   is on the face next to the other's, across the chord; other pairs give
   no evidence. Parallel faces are told apart by the offsets of the points
   along the normal; faces that meet at a small angle, such as the sides of
   a blade near its edge, which lie within the noise of each other's
   tangent planes there, by two planes fitted to the points (a wedge),
   outliers left out: a point is one where its nearest neighbors lie off its
   tangent plane, far beyond the noise over the cloud. Such a pair weighs as
   much as the less supported of its two normals, a normal's support being
   the square of the share of the point's `k` nearest neighbors that lie on
   its tangent plane: normals that are not
   the surface's, such as the faces' normals on the narrow rim of a plate,
   each on the plane of the next, would otherwise chain the two faces into
   one sheet and turn one of them over. Across a sharp edge, where that dot
   product is noise, they agree by the sign of the dot product of one normal
   with the other reflected through the plane that bisects them (the
   reflection criterion of Xie et al. 2003). Clusters are joined by the sum
   of the evidence between them, strongest first, so that a few wrong edges
   are outvoted. Each cluster is then turned so that the flux of the position through it
   is positive (outward on a closed surface), and flipped where it lies
   within an odd number of others (the walls of a cavity, whose outside is
   the cavity), by the winding number of their oriented points. An open
   surface ends up oriented to one side. Last, within each cluster, the
   signs are relaxed by all its edges at once, as the signs of the
   least-squares values that make each pair agree as its edge says, lightly
   held to the joins' signs: a part that an early join on little evidence
   turned over is turned back where its edges say so. Then the signs are
   checked as a whole: the cloud falls into patches of smooth surface that
   the signs orient as one (never across a sharp edge or the two sides of a
   thin part), and a patch is turned back where the generalized winding
   number of all the oriented points (Barill et al. 2018), away from the
   surface, comes nearer those of a solid (0 outside, 1 inside) for it: a
   whole face that the local evidence turned inward, which no local
   evidence can see, is turned back; so are both sides of a thin wall
   turned together, where the winding number between them says so. Clusters with no evidence between
   them, such as separate objects, are each oriented so. Only the lines of
   the given normals count: flipping any of them before the call changes
   nothing in the result. The user manual says why, and the benchmark
   measures it.

   Points with a non-finite coordinate and points whose normal is null or has
   a non-finite coordinate are not oriented; neither are points whose
   sensor position in `viewpoint_map` has a non-finite coordinate. Their
   normals are left as they are. The points are reordered, as by
   `CGAL::mst_orient_normals()`: the oriented points first, then those, each
   group in its order. A normal perpendicular to the direction, or a point
   at its viewpoint, is oriented as it is.

   The result depends only on the points, their normals and the parameters:
   it is the same, bit for bit, with `Sequential_tag` and `Parallel_tag` and
   any number of threads.

   \tparam ConcurrencyTag enables sequential versus parallel algorithm. Possible values are `Sequential_tag`,
                          `Parallel_tag`, and `Parallel_if_available_tag`.
   \tparam PointRange is a model of `Range`. The value type of
   its iterator is the key type of the named parameter `point_map`.
   \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

   \param points input point range
   \param k number of neighbors of the consistent orientation (at least 2; 18 is a good start); not used
            with `direction`, `viewpoint` or `viewpoint_map`
   \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below;
             a chain started from `CGAL::RRHT::parameters`

   \cgalNamedParamsBegin
     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the point set `points`}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
     \cgalParamNEnd

     \cgalParamNBegin{normal_map}
       \cgalParamDescription{a property map associating normals to the elements of the point set `points`}
       \cgalParamType{a model of `ReadWritePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Vector_3`}
     \cgalParamNEnd

     \cgalParamNBegin{direction}
       \cgalParamDescription{the direction the normals should point to (beyond the paper)}
       \cgalParamType{`geom_traits::Vector_3`, finite and not null}
       \cgalParamDefault{unused}
       \cgalParamExtra{Each normal whose dot product with it is negative is flipped: `Vector_3(0, 0, 1)`
                       orients the normals of an aerial survey up, as PDAL's `always_up`.}
     \cgalParamNEnd

     \cgalParamNBegin{viewpoint}
       \cgalParamDescription{the position the normals should point to, such as a scanner's (beyond the paper)}
       \cgalParamType{`geom_traits::Point_3`, finite}
       \cgalParamDefault{unused}
       \cgalParamExtra{Each normal `n` at a point `p` with `n * (viewpoint - p) < 0` is flipped, as by PCL's
                       `flipNormalTowardsViewpoint()` and Open3D's `orient_normals_towards_camera_location()`.}
     \cgalParamNEnd

     \cgalParamNBegin{viewpoint_map}
       \cgalParamDescription{a property map associating to each point the position of the sensor that saw it
                             (beyond the paper)}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{unused}
       \cgalParamExtra{As `viewpoint`, with each point's own viewpoint.}
     \cgalParamNEnd

     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \return an iterator to the first point whose normal was not oriented.

   \throws std::invalid_argument if more than one of `direction`, `viewpoint` and `viewpoint_map` is given, if
           `direction` is null or not finite, if `viewpoint` is not finite, if `k` is below 2 for the
           consistent orientation, or if `points` holds more than 2^32 - 1 points (as `CGAL::Point_set_3`'s
           32-bit indices). Nothing is changed then.
*/
template <typename ConcurrencyTag,
          typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
typename PointRange::iterator rrht_orient_normals(PointRange& points,
                                                  unsigned int k,
                                                  const NamedParameters& np = parameters::default_values())
{
  using parameters::get_parameter;
  namespace rrht_np = RRHT::internal_np;

  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Point_map Point_map;
  typedef typename NP_helper::Normal_map Normal_map;
  typedef typename NP_helper::Geom_traits Kernel;
  typedef typename Kernel::Vector_3 Vector_3;
  typedef typename std::iterator_traits<typename PointRange::iterator>::value_type Element;

#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!(std::is_convertible<ConcurrencyTag, Parallel_tag>::value),
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  auto check = [](bool condition, const std::string& message) {
    if(!condition)
      throw std::invalid_argument("CGAL::rrht_orient_normals(): " + message);
  };
  check(RRHT::internal::has_normal_map(points, np),
        "the point set has no normal map: call add_normal_map() first, or pass a normal_map");
  Point_map point_map = NP_helper::get_point_map(points, np);
  Normal_map normal_map = NP_helper::get_normal_map(points, np);

  const auto direction = get_parameter(np, rrht_np::direction);
  const auto viewpoint = get_parameter(np, rrht_np::viewpoint);
  const auto viewpoint_map = get_parameter(np, rrht_np::viewpoint_map);
  using parameters::is_default_parameter;
  constexpr bool with_direction = !is_default_parameter<NamedParameters, rrht_np::direction_t>::value;
  constexpr bool with_viewpoint = !is_default_parameter<NamedParameters, rrht_np::viewpoint_t>::value;
  constexpr bool with_viewpoint_map = !is_default_parameter<NamedParameters, rrht_np::viewpoint_map_t>::value;
  check(int(with_direction) + int(with_viewpoint) + int(with_viewpoint_map) <= 1,
        "give at most one of direction, viewpoint and viewpoint_map");
  auto to_eigen = [](const auto& v) {
    return Eigen::Vector3d(CGAL::to_double(v.x()), CGAL::to_double(v.y()), CGAL::to_double(v.z()));
  };
  auto finite = [](const Eigen::Vector3d& v) { return v.allFinite(); };
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  if constexpr(with_direction)
  {
    target = to_eigen(direction);
    check(finite(target) && target != Eigen::Vector3d::Zero(), "direction must be finite and not null");
  }
  if constexpr(with_viewpoint)
  {
    target = to_eigen(viewpoint);
    check(finite(target), "viewpoint must be finite");
  }
  constexpr bool consistent = !with_direction && !with_viewpoint && !with_viewpoint_map;
  check(!consistent || k >= 2, "k must be at least 2");
  check(std::size_t(std::distance(points.begin(), points.end())) <= RRHT::internal::Neighbor_search::max_size(),
        "at most 2^32 - 1 points at once");

  // The points that can be oriented: finite, with a finite, non-null normal
  // (and a finite viewpoint).
  auto orientable = [&](const Element& e) {
    const Eigen::Vector3d n = to_eigen(get(normal_map, e));
    bool ok = finite(to_eigen(get(point_map, e))) && finite(n) && n != Eigen::Vector3d::Zero();
    if constexpr(with_viewpoint_map)
      ok = ok && finite(to_eigen(get(viewpoint_map, e)));
    return ok;
  };
  auto flip = [&](Element& e) {
    const Vector_3 n = get(normal_map, e);
    put(normal_map, e, Vector_3(-n.x(), -n.y(), -n.z()));
  };
  const typename PointRange::iterator first_unoriented = std::stable_partition(points.begin(), points.end(), orientable);

  if constexpr(!consistent)
  {
    // Towards the direction or the viewpoint, point by point.
    for(auto it = points.begin(); it != first_unoriented; ++it)
    {
      const Eigen::Vector3d n = to_eigen(get(normal_map, *it));
      Eigen::Vector3d towards = target;
      if constexpr(with_viewpoint)
        towards = target - to_eigen(get(point_map, *it));
      if constexpr(with_viewpoint_map)
        towards = to_eigen(get(viewpoint_map, *it)) - to_eigen(get(point_map, *it));
      if(n.dot(towards) < 0)
        flip(*it);
    }
    return first_unoriented;
  }
  else
  {
    // The oriented points by their position from the beginning of the range.
    std::vector<RRHT::internal::Neighbor_search::Point> cloud;
    RRHT::internal::Elements<typename PointRange::iterator> elements;
    for(auto it = points.begin(); it != first_unoriented; ++it)
    {
      const auto& p = get(point_map, *it);
      cloud.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
      elements.add(it);
    }
    if(cloud.empty())
      return first_unoriented;
    const RRHT::internal::Neighbor_search search(std::move(cloud), ConcurrencyTag());
    std::vector<Eigen::Vector3d> normals(search.size());
    for(std::size_t v = 0; v < search.size(); ++v)
      normals[v] = to_eigen(get(normal_map, *elements.at(points.begin(), search.input_index(v)))).normalized();
    const std::vector<int> signs = RRHT::internal::consistent_orientation<ConcurrencyTag>(search, normals, k);
    for(std::size_t v = 0; v < search.size(); ++v)
      if(signs[v] < 0)
        flip(*elements.at(points.begin(), search.input_index(v)));
    return first_unoriented;
  }
}

} // namespace CGAL

#endif // CGAL_RRHT_ORIENT_NORMALS_H
