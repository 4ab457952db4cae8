// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The parameters of `CGAL::rrht_estimate_normals()` (paper, Section 6, and
// beyond it), read from the named parameters with their defaults and
// checked, before anything is written.

#ifndef CGAL_RRHT_INTERNAL_READ_PARAMETERS_H
#define CGAL_RRHT_INTERNAL_READ_PARAMETERS_H

#include <CGAL/RRHT/Aggregation.h>
#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/Setting.h>
#include <CGAL/RRHT/hoeffding_number_of_planes.h>
#include <CGAL/RRHT/parameters.h>

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Settings.h>
#include <CGAL/RRHT/internal/check_parameters.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_type_config.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <limits>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The parameters, checked.
struct Parameters
{
  Settings settings;                // those of the Hough transform
  unsigned int accumulator_slices;  // n_phi, which gives the accumulator's layout
  bool adaptive;                    // the Hough transform's fast setting first, then again where unsure
  bool refit;                       // the least-squares refit of the Hough transform's normals
  bool least_squares_first;         // jet fitting's quadric where the neighborhood is one smooth sheet
};

/// Reads and checks the parameters of an estimation of the normals of
/// `points` with `k` neighbors; a `std::invalid_argument` names a wrong one.
/// `FT` is the number type of the kernel.
template <typename FT, typename PointRange, typename NamedParameters>
Parameters read_parameters(const PointRange& points, unsigned int k, const NamedParameters& np)
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace rrht_np = RRHT::internal_np;

  Parameters p;
  Settings& settings = p.settings;
  const double neighbor_radius = CGAL::to_double(choose_parameter(get_parameter(np, CGAL::internal_np::neighbor_radius), FT(0)));
  check(std::isfinite(neighbor_radius) && neighbor_radius >= 0, "neighbor_radius must be finite and non-negative");
  check(k > 0 || neighbor_radius > 0, "k must be at least 1 when no neighbor_radius is given");
  const Setting setting = choose_parameter(get_parameter(np, rrht_np::setting), Setting::DEFAULT);
  check(setting == Setting::DEFAULT || setting == Setting::PAPER_PRECISE || setting == Setting::PAPER_FAST,
        "unknown setting");
  const bool paper = setting != Setting::DEFAULT, fast = setting == Setting::PAPER_FAST;
  p.accumulator_slices = count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::accumulator_slices), 15u), 1, 1000, "accumulator_slices (n_phi)");

  settings.k = k;
  settings.neighbor_radius = neighbor_radius;
  settings.number_of_planes = count_in_range<std::size_t>(
    choose_parameter(get_parameter(np, rrht_np::number_of_planes),
                     fast ? paper_fast_number_of_planes : hoeffding_number_of_planes(Bin_layout(p.accumulator_slices).size())),
    1, 100000000, "number_of_planes (T_R)");
  settings.use_confidence_interval = choose_parameter(get_parameter(np, rrht_np::use_confidence_interval), true);
  settings.sampling = choose_parameter(get_parameter(np, rrht_np::sampling), Sampling::POINTS);
  check(settings.sampling == Sampling::POINTS || settings.sampling == Sampling::CUBES ||
        settings.sampling == Sampling::UNIF, "unknown sampling");
  settings.presampling_factor = count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::presampling_factor), 4u), 1, 32, "presampling_factor (c)");
  settings.number_of_rotations = count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::number_of_rotations), fast ? paper_fast_number_of_rotations : 5u), 1, 100000, "number_of_rotations (n_rot)");
  settings.aggregation = choose_parameter(get_parameter(np, rrht_np::aggregation), Aggregation::CLUSTER);
  check(settings.aggregation == Aggregation::MEAN || settings.aggregation == Aggregation::BEST ||
        settings.aggregation == Aggregation::CLUSTER, "unknown aggregation");
  const double cluster_angle = choose_parameter(get_parameter(np, rrht_np::cluster_angle), 45.);
  check(cluster_angle >= 0 && cluster_angle <= 180, "cluster_angle must be from 0 to 180 degrees");
  settings.cos_cluster_angle = std::cos(cluster_angle * CGAL_PI / 180.);
  settings.seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  // The deprecated switches, where given, win over the setting.
  p.least_squares_first = choose_parameter(get_parameter(np, rrht_np::least_squares_first), !paper);
  p.adaptive = choose_parameter(get_parameter(np, rrht_np::adaptive), !paper);
  p.refit = choose_parameter(get_parameter(np, rrht_np::refit), false);
  check(std::size_t(std::distance(points.begin(), points.end())) <= Neighbor_search::max_size(),
        "at most 2^32 - 1 points at once: process larger clouds in tiles");
  return p;
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_READ_PARAMETERS_H
