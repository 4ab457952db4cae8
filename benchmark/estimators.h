// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The normal estimators the benchmark compares, each behind the same
// `Estimate` signature: RRHT (this package), CGAL's jet fitting, PCA and
// VCM, and PCL's NormalEstimationOMP and Open3D's EstimateNormals when they
// were found at configure time; and the orientations of the normals, each
// an `Orient`: RRHT's, CGAL's mst_orient_normals and Open3D's.

#ifndef CGAL_RRHT_BENCHMARK_ESTIMATORS_H
#define CGAL_RRHT_BENCHMARK_ESTIMATORS_H

#include "measure.h"

#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/rrht_orient_normals.h>
// The components measured on their own by `rrht_neighborhoods()`.
#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/for_each_block.h>
#include <CGAL/Point_set_processing_3/internal/Neighbor_query.h>
#include <CGAL/for_each.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/compute_average_spacing.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/mst_orient_normals.h>
#include <CGAL/pca_estimate_normals.h>
#include <CGAL/vcm_estimate_normals.h>

#include <string>

namespace rrht_benchmark {

/// A named estimator; `parallel` is false for those that use one thread
/// whatever TBB allows (VCM), which are then measured with 1 thread only.
struct Estimator
{
  std::string name;
  Estimate estimate;
  bool parallel = true;
  int planes = 0, rotations = 0; // RRHT's T and n_rot, 0 for the others
};

/// The neighborhood of every estimator: the `k` nearest points, or the ball
/// of radius `radius` if `radius > 0` (CGAL's `neighbor_radius` semantics).
struct Neighborhood
{
  unsigned int k = 100;
  double radius = 0;
  std::string suffix() const { return radius > 0 ? "_r" : "_K" + std::to_string(k); }
};

inline auto sample_maps() { return CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample()); }

/// `sample_maps()` with the paper's precise setting, on which the paper's
/// variants and the options below are built.
inline auto paper_sample_maps()
{
  return CGAL::RRHT::parameters::setting(CGAL::RRHT::Setting::PAPER_PRECISE).point_map(Point_of_sample()).normal_map(Normal_of_sample());
}

/// RRHT settings of the paper's Section 6.
struct Rrht_setting
{
  CGAL::RRHT::Sampling sampling = CGAL::RRHT::Sampling::POINTS;
  CGAL::RRHT::Aggregation aggregation = CGAL::RRHT::Aggregation::CLUSTER;
  int planes = 700;     // T_R
  int rotations = 5;    // n_rot
  bool confidence_interval = true;
  std::string label;    // appended to the name, e.g. "_fast"

  /// T_R = 700, n_rot = 5: the paper's precise setting (Fig. 10, Table 1).
  static Rrht_setting precise(CGAL::RRHT::Sampling s = CGAL::RRHT::Sampling::POINTS,
                              CGAL::RRHT::Aggregation a = CGAL::RRHT::Aggregation::CLUSTER)
  {
    Rrht_setting r;
    r.sampling = s;
    r.aggregation = a;
    return r;
  }
  /// T_R = 300, n_rot = 2: the paper's fast setting (Fig. 10, Table 1).
  static Rrht_setting fast(CGAL::RRHT::Sampling s = CGAL::RRHT::Sampling::POINTS)
  {
    Rrht_setting r = precise(s);
    r.planes = 300;
    r.rotations = 2;
    r.label = "_fast";
    return r;
  }
  Rrht_setting without_confidence_interval() const
  {
    Rrht_setting r = *this;
    r.confidence_interval = false;
    r.label += "_noCI";
    return r;
  }
};

/// "RRHT_Cubes_c_fast": sampling, aggregation (m, b, c as in the paper), setting.
inline std::string rrht_name(const Rrht_setting& s)
{
  static const char* samplings[] = { "Points", "Cubes", "Unif" };
  static const char* aggregations[] = { "m", "b", "c" };
  return std::string("RRHT_") + samplings[int(s.sampling)] + "_" + aggregations[int(s.aggregation)] + s.label;
}

inline Estimator rrht(const Rrht_setting& s, const Neighborhood& n)
{
  Estimator e;
  e.name = rrht_name(s);
  e.planes = s.planes;
  e.rotations = s.rotations;
  e.estimate = [s, n](Cloud& cloud, unsigned int) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
      cloud, n.k,
      paper_sample_maps()
        .neighbor_radius(n.radius)
        .sampling(s.sampling)
        .aggregation(s.aggregation)
        .number_of_planes(s.planes)
        .number_of_rotations(s.rotations)
        .use_confidence_interval(s.confidence_interval));
  };
  return e;
}

/// RRHT with the paper's precise setting (T_R from eq. 7: 691, n_rot = 5) and
/// the options `adaptive`, `refit` and `least_squares_first`, named `name`.
inline Estimator rrht_with_options(const std::string& name, const Neighborhood& n, bool adaptive, bool refit,
                                   bool least_squares_first = false)
{
  Estimator e;
  e.name = name;
  e.rotations = 5;
  e.estimate = [n, adaptive, refit, least_squares_first](Cloud& cloud, unsigned int) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
      cloud, n.k,
      sample_maps().neighbor_radius(n.radius).adaptive(adaptive).refit(refit).least_squares_first(least_squares_first));
  };
  return e;
}

/// The defaults of `CGAL::rrht_estimate_normals()`, no RRHT parameter given
/// (least squares first with the adaptive Hough transform): "RRHT_default".
inline Estimator rrht_default(const Neighborhood& n)
{
  Estimator e;
  e.name = "RRHT_default";
  e.rotations = 5;
  e.estimate = [n](Cloud& cloud, unsigned int) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, n.k, sample_maps().neighbor_radius(n.radius));
  };
  return e;
}

/// Least squares first with one of the paper's settings where the quadric is
/// rejected, instead of the adaptive one: the precise setting
/// ("RRHT_least_squares_first_precise") or, if `fast`, the fast one (300
/// planes, 2 rotations: "RRHT_least_squares_first_fast").
inline Estimator rrht_least_squares_first_with(const Neighborhood& n, bool fast)
{
  const Rrht_setting setting = fast ? Rrht_setting::fast() : Rrht_setting::precise();
  Estimator e;
  e.name = fast ? "RRHT_least_squares_first_fast" : "RRHT_least_squares_first_precise";
  e.planes = fast ? setting.planes : 0; // 0: the precise setting's T_R of eq. 7
  e.rotations = setting.rotations;
  e.estimate = [n, fast, setting](Cloud& cloud, unsigned int) {
    auto np = sample_maps().neighbor_radius(n.radius).adaptive(false).least_squares_first(true);
    if(fast)
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
        cloud, n.k, np.number_of_planes(std::size_t(setting.planes)).number_of_rotations(unsigned(setting.rotations)));
    else
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, n.k, np);
  };
  return e;
}

/// The paper's precise setting, named with its neighborhood: "RRHT_defaults_K18".
inline Estimator rrht_defaults(const Neighborhood& n)
{
  return rrht_with_options("RRHT_defaults" + n.suffix(), n, false, false);
}

/// The defaults with the least-squares refit (`refit(true)`):
/// "RRHT_refit_K100".
inline Estimator rrht_refit(const Neighborhood& n) { return rrht_with_options("RRHT_refit" + n.suffix(), n, false, true); }

/// The adaptive setting (`adaptive(true)`, T_R = 691 and n_rot = 5 for the
/// points estimated again): "RRHT_adaptive".
inline Estimator rrht_adaptive(const Neighborhood& n) { return rrht_with_options("RRHT_adaptive", n, true, false); }

/// The adaptive setting with the least-squares refit
/// (`adaptive(true).refit(true)`): "RRHT_adaptive_refit".
inline Estimator rrht_adaptive_refit(const Neighborhood& n)
{
  return rrht_with_options("RRHT_adaptive_refit", n, true, true);
}

/// Least squares first, the adaptive setting where the quadric is rejected
/// (`least_squares_first(true).adaptive(true)`): "RRHT_least_squares_first_K100".
inline Estimator rrht_least_squares_first(const Neighborhood& n)
{
  return rrht_with_options("RRHT_least_squares_first" + n.suffix(), n, true, false, true);
}

/// `rrht_defaults()` that also writes each point's confidence
/// (`confidence_map`): "RRHT_defaults_K100_confidence".
inline Estimator rrht_defaults_with_confidence(const Neighborhood& n)
{
  Estimator e = rrht_defaults(n);
  e.name += "_confidence";
  e.estimate = [n](Cloud& cloud, unsigned int) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
      cloud, n.k, paper_sample_maps().neighbor_radius(n.radius).confidence_map(Confidence_of_sample()));
  };
  return e;
}

/// CGAL's bare k-nearest-neighbor queries, as `CGAL::jet_estimate_normals()`
/// makes them (`Point_set_processing_3::internal::Neighbor_query`): a
/// kd-tree of the points, then `Orthogonal_k_neighbor_search` for the k + 1
/// nearest of every point, in parallel, and nothing done with them. The
/// yardstick of the default's time. Writes no normals.
inline Estimator neighbor_queries(const Neighborhood& n)
{
  Estimator e;
  e.name = "queries" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int) {
    typedef CGAL::Point_set_processing_3::internal::Neighbor_query<Kernel, Cloud&, Point_of_sample> Query;
    const Query query(cloud, Point_of_sample());
    CGAL::for_each<CGAL::Parallel_if_available_tag>(cloud, [&](const Sample& s) {
      query.get_iterators(s.point, n.k, n.radius, boost::make_function_output_iterator([](const auto&) {}));
      return true;
    });
  };
  return e;
}

/// What RRHT's neighborhoods cost on their own: the copy of the cloud, the
/// Hilbert sort and the kd-tree of `CGAL::RRHT::internal::Neighbor_search`,
/// then the neighborhood of every point, over the same blocks and threads
/// as `rrht_estimate_normals()` (`CGAL::RRHT::internal::for_each_block`), and
/// nothing done with them. Writes no normals.
inline Estimator rrht_neighborhoods(const Neighborhood& n)
{
  Estimator e;
  e.name = "neighborhoods" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int) {
    typedef CGAL::RRHT::internal::Neighbor_search Search;
    std::vector<Search::Point> points;
    for(const Sample& s : cloud)
      points.emplace_back(s.point.x(), s.point.y(), s.point.z());
    const Search search(std::move(points), CGAL::Parallel_if_available_tag());
    struct Scratch
    {
      Search::Scratch search;
      CGAL::RRHT::internal::Neighborhood neighborhood;
    };
    const std::function<bool(double)> no_callback;
    CGAL::RRHT::internal::Progress progress(no_callback, search.size());
    CGAL::RRHT::internal::for_each_block<CGAL::Parallel_if_available_tag>(
      search.size(), progress, []() { return Scratch(); },
      [&](std::size_t begin, std::size_t end, Scratch& scratch) {
        for(std::size_t i = begin; i < end; ++i)
          search.find(i, n.k, n.radius, scratch.neighborhood, scratch.search);
      });
  };
  return e;
}

/// CGAL::jet_estimate_normals, default degrees (fitting 2, monge 2).
inline Estimator jet(const Neighborhood& n)
{
  Estimator e;
  e.name = "jet" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int) {
    CGAL::jet_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, n.k, sample_maps().neighbor_radius(n.radius));
  };
  return e;
}

inline Estimator pca(const Neighborhood& n)
{
  Estimator e;
  e.name = "pca" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int) {
    CGAL::pca_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, n.k, sample_maps().neighbor_radius(n.radius));
  };
  return e;
}

namespace internal {
// VCM intersects convex polyhedra, which needs robust predicates: it runs on
// EPICK points (with Simple_cartesian<double> CGAL's quickhull crashes).
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;

struct Epick_point_of_sample
{
  typedef Sample key_type;
  typedef Epick::Point_3 value_type;
  typedef Epick::Point_3 reference;
  typedef boost::readable_property_map_tag category;
  friend Epick::Point_3 get(Epick_point_of_sample, const Sample& s)
  {
    return Epick::Point_3(s.point.x(), s.point.y(), s.point.z());
  }
};

struct Epick_normal_of_sample
{
  typedef Sample key_type;
  typedef Epick::Vector_3 value_type;
  typedef Epick::Vector_3 reference;
  typedef boost::writable_property_map_tag category;
  friend void put(Epick_normal_of_sample, Sample& s, const Epick::Vector_3& n) { s.normal = Vector(n.x(), n.y(), n.z()); }
};
} // namespace internal

/// CGAL::vcm_estimate_normals (sequential: a Delaunay triangulation of the
/// whole cloud, with EPICK). The offset radius R is the average distance to
/// the `k` nearest neighbors (80: the scale of the others' neighborhoods), the
/// convolution radius the average distance to the 18 nearest, both computed
/// inside the timed call. (CGAL 5.5.1's variant that convolves over k
/// neighbors instead gives errors near 90 degrees everywhere; not used.)
inline Estimator vcm(const Neighborhood& n)
{
  Estimator e;
  e.name = "vcm";
  e.parallel = false;
  e.estimate = [n](Cloud& cloud, unsigned int) {
    const auto maps = CGAL::parameters::point_map(internal::Epick_point_of_sample())
                        .normal_map(internal::Epick_normal_of_sample());
    const double offset_radius = CGAL::compute_average_spacing<CGAL::Sequential_tag>(cloud, n.k, maps);
    const double convolution_radius = CGAL::compute_average_spacing<CGAL::Sequential_tag>(cloud, 18, maps);
    CGAL::vcm_estimate_normals(cloud, offset_radius, convolution_radius, maps);
  };
  return e;
}

/// An orientation of the normals a cloud already has, in place: returns how
/// many samples it oriented, which it moved to the front (the others follow,
/// as `CGAL::mst_orient_normals()` and `CGAL::rrht_orient_normals()` leave
/// them).
typedef std::function<std::size_t(Cloud&, unsigned int threads)> Orient;

struct Orientation
{
  std::string name;
  Orient orient;
  bool parallel = true;

  /// As an `Estimator`, to be timed by `measure()` on a cloud with normals.
  Estimator timed() const
  {
    Estimator e;
    e.name = name;
    e.parallel = parallel;
    const Orient o = orient;
    e.estimate = [o](Cloud& cloud, unsigned int threads) { o(cloud, threads); };
    return e;
  }
};

/// CGAL::rrht_orient_normals(), consistently (no direction nor viewpoint):
/// "rrht_orient_K18".
inline Orientation rrht_orient(unsigned int k)
{
  Orientation o;
  o.name = "rrht_orient_K" + std::to_string(k);
  o.orient = [k](Cloud& cloud, unsigned int) {
    const auto end = CGAL::rrht_orient_normals<CGAL::Parallel_if_available_tag>(
      cloud, k, CGAL::RRHT::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
    return std::size_t(end - cloud.begin());
  };
  return o;
}

/// CGAL::mst_orient_normals() (Hoppe et al. 1992; sequential): "mst_orient_K18".
inline Orientation mst_orient(unsigned int k)
{
  Orientation o;
  o.name = "mst_orient_K" + std::to_string(k);
  o.parallel = false;
  o.orient = [k](Cloud& cloud, unsigned int) {
    const auto end = CGAL::mst_orient_normals(
      cloud, k, CGAL::parameters::point_map(Point_of_sample()).normal_map(Normal_of_sample()));
    return std::size_t(end - cloud.begin());
  };
  return o;
}

#ifdef RRHT_BENCHMARK_WITH_PCL
/// pcl::NormalEstimationOMP with the k nearest neighbors (pcl_peer.cpp).
void pcl_estimate_normals(Cloud& cloud, unsigned int k, double radius, unsigned int threads);

inline Estimator pcl(const Neighborhood& n)
{
  Estimator e;
  e.name = "pcl" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int threads) { pcl_estimate_normals(cloud, n.k, n.radius, threads); };
  return e;
}
#endif

#ifdef RRHT_BENCHMARK_WITH_OPEN3D
/// open3d::geometry::PointCloud::EstimateNormals with the `k` nearest points,
/// or at most `k` points within `radius` if `radius > 0` (open3d_peer.cpp).
void open3d_estimate_normals(Cloud& cloud, unsigned int k, double radius, unsigned int threads);

/// Open3D with KDTreeSearchParamKNN(k): "open3d_K30" at its documented default.
inline Estimator open3d(const Neighborhood& n)
{
  Estimator e;
  e.name = "open3d" + n.suffix();
  e.estimate = [n](Cloud& cloud, unsigned int threads) { open3d_estimate_normals(cloud, n.k, 0, threads); };
  return e;
}

/// Open3D with KDTreeSearchParamHybrid(radius, max_nn = k): "open3d_hybrid".
/// The radius is 3 times CGAL's average spacing (6 neighbors), computed
/// inside the timed call.
inline Estimator open3d_hybrid(const Neighborhood& n)
{
  Estimator e;
  e.name = "open3d_hybrid";
  e.estimate = [n](Cloud& cloud, unsigned int threads) {
    // On a uniformly sampled surface this ball holds about 30 points (= max_nn): the
    // radius only bounds the neighborhood where the cloud is sparser than on average.
    const double radius = 3 * CGAL::compute_average_spacing<CGAL::Parallel_if_available_tag>(
                                cloud, 6, CGAL::parameters::point_map(Point_of_sample()));
    open3d_estimate_normals(cloud, n.k, radius, threads);
  };
  return e;
}

/// open3d::geometry::PointCloud::OrientNormalsConsistentTangentPlane(k) on the
/// normals of the cloud (open3d_peer.cpp).
void open3d_orient_normals(Cloud& cloud, unsigned int k, unsigned int threads);

/// Open3D's orientation (Hoppe et al. 1992 on its own graph): "open3d_orient_K10".
/// It orients every point.
inline Orientation open3d_orient(unsigned int k)
{
  Orientation o;
  o.name = "open3d_orient_K" + std::to_string(k);
  o.orient = [k](Cloud& cloud, unsigned int threads) {
    open3d_orient_normals(cloud, k, threads);
    return cloud.size();
  };
  return o;
}
#endif

} // namespace rrht_benchmark

#endif // CGAL_RRHT_BENCHMARK_ESTIMATORS_H
