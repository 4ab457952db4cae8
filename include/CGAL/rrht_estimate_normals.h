// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Normal estimation with the Robust Randomized Hough Transform of
// A. Boulch and R. Marlet, "Fast and Robust Normal Estimation for Point
// Clouds with Sharp Features", Computer Graphics Forum 31(5), 2012.

#ifndef CGAL_RRHT_ESTIMATE_NORMALS_H
#define CGAL_RRHT_ESTIMATE_NORMALS_H

#include <CGAL/RRHT/Aggregation.h>
#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/Setting.h>
#include <CGAL/RRHT/hoeffding_number_of_planes.h>
#include <CGAL/RRHT/parameters.h>

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Cube_weights.h>
#include <CGAL/RRHT/internal/Elements.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Pass_context.h>
#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/adaptive.h>
#include <CGAL/RRHT/internal/check_parameters.h>
#include <CGAL/RRHT/internal/hough_transform_passes.h>
#include <CGAL/RRHT/internal/least_squares_first.h>
#include <CGAL/RRHT/internal/points_in_double.h>
#include <CGAL/RRHT/internal/read_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <numeric>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/**
   \ingroup PkgRRHTRef

   Estimates normal directions of the range of `points` with the Robust
   Randomized Hough Transform (RRHT) of Boulch and Marlet (2012), which keeps
   sharp features: the normal at a point is the most probable normal of the
   planes through random triples of its neighbors, found with a Hough
   accumulator.

   For each point, planes through triples of its neighbors vote in an
   accumulator of directions (`accumulator_slices`) until `number_of_planes`
   triples were drawn or, with `use_confidence_interval`, until the most voted
   bin is confidently ahead of the second one. The normal is the mean of the
   normals of the most voted bin. This is done with `number_of_rotations`
   randomly rotated accumulators, whose normals are combined by
   `aggregation`. Triples are drawn according to `sampling`: uniformly among
   the neighbors, or spatially uniformly in the neighborhood ball to resist
   density variations.

   By default, the Hough transform runs only where it is needed (beyond the
   paper): where the neighborhood of a point is one smooth sheet within the
   noise, or one side of a thin part, the normal is that of a quadric fitted
   to it by least squares, as `CGAL::jet_estimate_normals()` does;
   elsewhere, as along sharp features, it is that of the Hough transform,
   run with the paper's fast setting and again with its precise setting
   where the confidence of the first is low. The named parameter `setting`
   chooses the paper's settings instead. The user manual compares them.

   The output normals are unit vectors, randomly oriented (use
   `CGAL::mst_orient_normals()` to orient them). Where no plane can be formed
   (fewer than 3 distinct points in the neighborhood, all of them collinear,
   a neighborhood of radius below 1e-150 or above 1e150, whose squared
   distances leave the range of doubles, a neighborhood whose points span more orders of
   magnitude than double precision holds, or a point with a non-finite
   coordinate), the normal is the null vector
   `CGAL::NULL_VECTOR`. Points with a non-finite coordinate are not
   neighbors of any point.

   The result depends only on the input, the parameters and `random_seed`:
   it is the same, bit for bit, with `Sequential_tag` and `Parallel_tag` and
   any number of threads. With `point_id_map`, it is also the same on any part
   of the cloud: a point whose support (see `support_radius_map`) lies in the
   part gets the same normal, bit for bit, as with the whole cloud, which is how
   a cloud too large for memory is processed tile by tile.

   \tparam ConcurrencyTag enables sequential versus parallel algorithm. Possible values are `Sequential_tag`,
                          `Parallel_tag`, and `Parallel_if_available_tag`.
   \tparam PointRange is a model of `Range`. The value type of
   its iterator is the key type of the named parameter `point_map`.
   \tparam NamedParameters a sequence of \ref bgl_namedparameters "Named Parameters"

   \param points input point range
   \param k number of neighbors (the neighborhood of a point is the point and its `k` nearest neighbors),
            or, with `neighbor_radius`, the cap on the number of neighbors taken from a ball (0: no cap)
   \param np an optional sequence of \ref bgl_namedparameters "Named Parameters" among the ones listed below;
             a chain of `CGAL::parameters` works as with `CGAL::jet_estimate_normals()`, and a chain started
             from `CGAL::RRHT::parameters` also takes the RRHT parameters, in any order

   \cgalNamedParamsBegin
     \cgalParamNBegin{point_map}
       \cgalParamDescription{a property map associating points to the elements of the point set `points`}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Point_3`}
       \cgalParamDefault{`CGAL::Identity_property_map<geom_traits::Point_3>`}
     \cgalParamNEnd

     \cgalParamNBegin{normal_map}
       \cgalParamDescription{a property map associating normals to the elements of the point set `points`}
       \cgalParamType{a model of `WritablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `geom_traits::Vector_3`}
     \cgalParamNEnd

     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd

     \cgalParamNBegin{neighbor_radius}
       \cgalParamDescription{r, the radius of a spherical neighborhood: the points within it, the point included}
       \cgalParamType{floating scalar value, positive and finite, or 0}
       \cgalParamDefault{`0` (the `k` nearest neighbors)}
       \cgalParamExtra{A ball with more than `k` other points keeps the `k` nearest (`k` = 0: no cap); a ball of
                       fewer than 3 points is replaced by the point and its `k` (at least 3) nearest neighbors.}
     \cgalParamNEnd

     \cgalParamNBegin{random_seed}
       \cgalParamDescription{the seed of the random draws; each point draws from its own stream, keyed by the seed
                             and its id (`point_id_map`)}
       \cgalParamType{unsigned int}
       \cgalParamDefault{`0`}
     \cgalParamNEnd

     \cgalParamNBegin{callback}
       \cgalParamDescription{a mechanism to get feedback on the advancement of the algorithm
                             while it's running and to interrupt it if needed}
       \cgalParamType{an instance of `std::function<bool(double)>`.}
       \cgalParamDefault{unused}
       \cgalParamExtra{It is called after every block of 64 points with the advancement (from 0. to 1.), and
                       with 1. at the end; returning `false` stops the algorithm and leaves the remaining
                       normals unchanged (under `CGAL::RRHT::Setting::DEFAULT`, every normal if stopped before the last
                       third; with `refit` under a paper setting, the points its second pass did not reach keep their RRHT normal).
                       It is copied, and with `CGAL::Parallel_tag` called from the worker threads, one at a time.}
     \cgalParamNEnd

     \cgalParamNBegin{confidence_map}
       \cgalParamDescription{a property map receiving the confidence of each normal, from 0 to 1 (beyond the paper):
                             the share of the planes drawn at the point that voted for the returned normal}
       \cgalParamType{a model of `WritablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is a floating-point type}
       \cgalParamDefault{unused}
       \cgalParamExtra{High where one plane holds the neighborhood, low near sharp features and where the normal
                       is wrong; noise lowers it evenly, so compare values within a cloud and a setting. 0 for a null
                       normal. Under `DEFAULT`, where a normal is kept without a vote, 50 triples are
                       drawn to measure it, which takes time: pass a map only where the confidences are read.}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \cgalNamedParamsBegin{The setting: what runs where}
     \cgalParamNBegin{setting}
       \cgalParamDescription{the estimation: least squares where the neighborhood is one smooth sheet and the adaptive
                             Hough transform elsewhere, or the Hough transform everywhere with one of the paper's
                             settings}
       \cgalParamType{`CGAL::RRHT::Setting`: `DEFAULT`, `PAPER_PRECISE` or `PAPER_FAST`}
       \cgalParamDefault{`CGAL::RRHT::Setting::DEFAULT`}
       \cgalParamExtra{It gives the defaults of `number_of_planes` and `number_of_rotations`. Under `DEFAULT`, they
                       set the Hough transform's second stage, where the first one's confidence is low, and
                       `sampling` changes something only as `UNIF`: that stage draws spatially where it is lowest.}
     \cgalParamNEnd

     \cgalParamNBegin{refit}
       \cgalParamDescription{refit each normal of the Hough transform by least squares where its neighborhood is one
                             sheet within the noise (a quadric) or the two sides of a thin part (two parallel planes);
                             elsewhere, as near sharp features, it stays}
       \cgalParamType{bool}
       \cgalParamDefault{`false`}
       \cgalParamExtra{With any setting. A second pass, about twice the time; the confidence written is still that
                       of the Hough transform's normal.}
     \cgalParamNEnd

     \cgalParamNBegin{least_squares_first}
       \cgalParamDescription{deprecated, replaced by `setting`: the least squares of `DEFAULT`, on or off, whatever
                             the setting}
       \cgalParamType{bool}
       \cgalParamDefault{`true` under `DEFAULT`, else `false`}
     \cgalParamNEnd

     \cgalParamNBegin{adaptive}
       \cgalParamDescription{deprecated, replaced by `setting`: the adaptive Hough transform of `DEFAULT`, on or off,
                             whatever the setting}
       \cgalParamType{bool}
       \cgalParamDefault{`true` under `DEFAULT`, else `false`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \cgalNamedParamsBegin{The paper's tuning knobs (see `setting` for what the default reads of them)}
     \cgalParamNBegin{number_of_planes}
       \cgalParamDescription{T_R, the largest number of triples drawn per rotated accumulator (paper, eq. 7)}
       \cgalParamType{an integer from 1 to 100 000 000}
       \cgalParamDefault{the Hoeffding bound of eq. 7 with alpha = 0.95, delta = 0.08 and the number M of bins
                         of the accumulator, `CGAL::RRHT::hoeffding_number_of_planes(M)`: 691 for 15 slices;
                         300 with `CGAL::RRHT::Setting::PAPER_FAST`}
     \cgalParamNEnd

     \cgalParamNBegin{number_of_rotations}
       \cgalParamDescription{n_rot, the number of randomly rotated accumulators (paper, Section 4)}
       \cgalParamType{an integer from 1 to 100 000}
       \cgalParamDefault{`5`; `2` with `CGAL::RRHT::Setting::PAPER_FAST`}
     \cgalParamNEnd

     \cgalParamNBegin{accumulator_slices}
       \cgalParamDescription{n_phi, the number of slices of the sphere in the accumulator (paper, Section 3)}
       \cgalParamType{an integer from 1 to 1000}
       \cgalParamDefault{`15` (M = 172 bins on the half sphere)}
     \cgalParamNEnd

     \cgalParamNBegin{use_confidence_interval}
       \cgalParamDescription{stop drawing as soon as the 95% confidence intervals of the two most voted bins are
                             disjoint (paper, eq. 10)}
       \cgalParamType{bool}
       \cgalParamDefault{`true`}
     \cgalParamNEnd

     \cgalParamNBegin{sampling}
       \cgalParamDescription{how triples are drawn (paper, Section 5): uniformly among the neighbors, or spatially
                             uniformly in the neighborhood ball, which resists density variations at some cost in time}
       \cgalParamType{`CGAL::RRHT::Sampling`: `POINTS` (RRHT_Points), `CUBES` (RRHT_Cubes) or `UNIF` (RRHT_Unif)}
       \cgalParamDefault{`CGAL::RRHT::Sampling::POINTS`; under `CGAL::RRHT::Setting::DEFAULT`, `CUBES` where it
                         draws spatially, `UNIF` if `sampling` is `UNIF`}
     \cgalParamNEnd

     \cgalParamNBegin{presampling_factor}
       \cgalParamDescription{c, the discretization of the ball by `CUBES` (c^3 cubes) and `UNIF` (balls of radius r/c)}
       \cgalParamType{an integer from 1 to 32}
       \cgalParamDefault{`4`}
     \cgalParamNEnd

     \cgalParamNBegin{aggregation}
       \cgalParamDescription{how the normals of the rotated accumulators are combined (paper, Section 4)}
       \cgalParamType{`CGAL::RRHT::Aggregation`: `MEAN` (RRHT_m), `BEST` (RRHT_b) or `CLUSTER` (RRHT_c)}
       \cgalParamDefault{`CGAL::RRHT::Aggregation::CLUSTER`}
     \cgalParamNEnd

     \cgalParamNBegin{cluster_angle}
       \cgalParamDescription{a_cluster, the angle within which normals form a cluster, in degrees}
       \cgalParamType{floating scalar value, from 0 to 180}
       \cgalParamDefault{`45`}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \cgalNamedParamsBegin{For parts of a cloud (beyond the paper; `cgal_rrht.tiles` processes a cloud tile by tile
                         with them)}
     \cgalParamNBegin{point_id_map}
       \cgalParamDescription{a property map associating a stable id to each point: it keys the point's random stream
                             and orders its neighbors at the same distance}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is convertible to `std::uint64_t`}
       \cgalParamDefault{the position of the point in `points`}
       \cgalParamExtra{With the ids of the whole cloud, a part of it gives each point whose support
                       (`support_radius_map`) it holds the same normal, bit for bit. Ids should be distinct.}
     \cgalParamNEnd

     \cgalParamNBegin{support_radius_map}
       \cgalParamDescription{a property map receiving the radius of each point's support: the ball around the point
                             that holds every point its normal depends on}
       \cgalParamType{a model of `WritablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `double`}
       \cgalParamDefault{unused}
       \cgalParamExtra{0 for a point with a non-finite coordinate; infinite where the neighborhood is the whole
                       cloud, which has fewer points than it asks for. Computed in double precision: allow a few
                       units in the last place when comparing it to a distance.}
     \cgalParamNEnd

     \cgalParamNBegin{neighbor_only_map}
       \cgalParamDescription{a property map telling which points are only neighbors of the others, as the halo of a
                             tile: nothing is written for them and their estimation is saved}
       \cgalParamType{a model of `ReadablePropertyMap` whose key type is the value type
                      of the iterator of `PointRange` and whose value type is `bool`}
       \cgalParamDefault{no point is only a neighbor}
     \cgalParamNEnd
   \cgalNamedParamsEnd

   \throws std::invalid_argument if `k` is 0 without a positive `neighbor_radius`, or if a parameter is out
           of the range given above (a negative or non-finite radius, 0 planes, 0 rotations, 0 slices, a value
           outside its enumeration...), or if
           `points` holds more than 2^32 - 1 points (as `CGAL::Point_set_3`'s 32-bit indices; larger clouds are
           processed in tiles). Nothing is written then. An empty range is left as it is.
*/
template <typename ConcurrencyTag,
          typename PointRange,
          typename NamedParameters = parameters::Default_named_parameters>
void rrht_estimate_normals(PointRange& points,
                           unsigned int k,
                           const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  namespace rrht_np = RRHT::internal_np;

  typedef Point_set_processing_3_np_helper<PointRange, NamedParameters> NP_helper;
  typedef typename NP_helper::Point_map Point_map;
  typedef typename NP_helper::Normal_map Normal_map;
  typedef typename NP_helper::Geom_traits Kernel;
  typedef typename Kernel::FT FT;
  typedef typename Kernel::Vector_3 Vector_3;
  typedef typename std::iterator_traits<typename PointRange::iterator>::value_type Element;

#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!(std::is_convertible<ConcurrencyTag, Parallel_tag>::value),
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  RRHT::internal::check(RRHT::internal::has_normal_map(points, np),
                        "the point set has no normal map: call add_normal_map() first, or pass a normal_map");

  Point_map point_map = NP_helper::get_point_map(points, np);
  Normal_map normal_map = NP_helper::get_normal_map(points, np);
  // Without a confidence_map, the confidences go to a map that drops them.
  const auto confidence_map = choose_parameter(get_parameter(np, rrht_np::confidence_map),
                                               Constant_property_map<Element, double>(0.));
  // Without a support_radius_map, the radii go to a map that drops them.
  const auto support_radius_map = choose_parameter(get_parameter(np, rrht_np::support_radius_map),
                                                   Constant_property_map<Element, double>(0.));
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  // The parameters (paper, Section 6), checked before anything is written.
  const RRHT::internal::Parameters checked = RRHT::internal::read_parameters<FT>(points, k, np);
  RRHT::internal::Settings settings = checked.settings;
  const RRHT::internal::Bin_layout layout(checked.accumulator_slices);

  // The finite points of the cloud in double precision, in one kd-tree along
  // a Hilbert curve, with their ids if a point_id_map is given. The others
  // get the null vector.
  const auto point_id_map = get_parameter(np, rrht_np::point_id_map);
  constexpr bool with_ids = !std::is_same<typename std::decay<decltype(point_id_map)>::type,
                                          internal_np::Param_not_found>::value;
  // The points that are only neighbors, by position in the input.
  const auto neighbor_only_map = get_parameter(np, rrht_np::neighbor_only_map);
  constexpr bool with_neighbor_only = !std::is_same<typename std::decay<decltype(neighbor_only_map)>::type,
                                                    internal_np::Param_not_found>::value;
  std::vector<bool> neighbor_only;
  RRHT::internal::Elements<typename PointRange::iterator> elements;
  std::vector<RRHT::internal::Neighbor_search::Point> cloud =
    RRHT::internal::points_in_double<ConcurrencyTag>(points, point_map);
  // The finite points are moved to the front of the cloud, in order; their
  // positions in the input are listed once one is moved.
  std::vector<std::uint32_t> input;
  std::vector<std::uint64_t> ids;
  std::size_t position = 0, kept = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++position)
  {
    elements.add(it);
    if constexpr(with_ids)
      ids.push_back(static_cast<std::uint64_t>(get(point_id_map, *it)));
    if constexpr(with_neighbor_only)
      neighbor_only.push_back(static_cast<bool>(get(neighbor_only_map, *it)));
    if(RRHT::internal::has_finite_coordinates(cloud[position]))
    {
      if(kept != position)
      {
        if(input.empty())
        {
          input.resize(kept);
          std::iota(input.begin(), input.end(), std::uint32_t(0));
        }
        cloud[kept] = cloud[position];
        input.push_back(std::uint32_t(position));
      }
      ++kept;
    }
    else if(neighbor_only.empty() || !neighbor_only.back())
    {
      put(normal_map, *it, CGAL::NULL_VECTOR);
      put(confidence_map, *it, 0.);
      put(support_radius_map, *it, 0.);
    }
  }
  cloud.resize(kept);
  if(cloud.empty())
    return;
  const RRHT::internal::Neighbor_search search(std::move(cloud), std::move(input), ids, ConcurrencyTag());
  std::vector<std::uint64_t>().swap(ids);
  const std::size_t size = search.size();
  settings.k = static_cast<unsigned int>((std::min<std::size_t>)(k, size - 1));
  const RRHT::internal::Adaptive_stages stages(settings);
  const bool cubes = checked.adaptive ? stages.spatial.sampling == RRHT::Sampling::CUBES
                                         : settings.sampling == RRHT::Sampling::CUBES;
  const RRHT::internal::Cube_weights cube_weights(cubes ? settings.presampling_factor : 1);

  // Where the passes write the results of a point, by its position in the search.
  auto element = [&](std::size_t i) { return elements.at(points.begin(), search.input_index(i)); };
  RRHT::internal::Pass_output output;
  // A neighborhood whose points span more orders of magnitude than double
  // precision holds (1e-300 beside 1e-130) can give a normal that is not a
  // number: such a point gets the null vector and no confidence.
  output.normal = [&](std::size_t i, const Eigen::Vector3d& n) {
    put(normal_map, *element(i), n.allFinite() ? Vector_3(FT(n.x()), FT(n.y()), FT(n.z())) : CGAL::NULL_VECTOR);
  };
  output.confidence = [&](std::size_t i, double confidence) {
    put(confidence_map, *element(i), std::isfinite(confidence) ? confidence : 0.);
  };
  output.support = [&](std::size_t i, double radius) { put(support_radius_map, *element(i), radius); };
  // A cloud of at most k points is every point's neighborhood: each normal
  // depends on all of it, and has an infinite support.
  const RRHT::internal::Pass_context context{ search,        settings,      layout, cube_weights,
                                              neighbor_only, settings.k < k, output };

  constexpr bool with_supports =
    !std::is_same<typename std::decay<decltype(get_parameter(np, rrht_np::support_radius_map))>::type,
                  internal_np::Param_not_found>::value;
  const RRHT::internal::Adaptive_stages* adaptive = checked.adaptive ? &stages : nullptr;
  if(checked.least_squares_first)
  {
    // Jet fitting's quadric where the neighborhood is one smooth sheet, the
    // Hough transform elsewhere.
    constexpr bool with_confidences =
      !std::is_same<typename std::decay<decltype(get_parameter(np, rrht_np::confidence_map))>::type,
                    internal_np::Param_not_found>::value;
    RRHT::internal::Progress progress(callback, 3 * size);
    RRHT::internal::least_squares_first<ConcurrencyTag>(
      context, { adaptive, checked.refit, with_confidences, with_supports }, progress);
    progress.finish();
    return;
  }
  // Section 2 at every point, and the least-squares refit if asked.
  RRHT::internal::Progress progress(callback, checked.refit ? 2 * size : size);
  RRHT::internal::hough_transform_passes<ConcurrencyTag>(context, adaptive, checked.refit, with_supports, progress);
  progress.finish();
}

} // namespace CGAL

#endif // CGAL_RRHT_ESTIMATE_NORMALS_H
