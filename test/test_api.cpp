// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The interface: ranges and kernels, named parameters, concurrency and
// reproducibility, callback, neighborhoods, and bad input.

#include "shapes.h"

#include <CGAL/rrht_estimate_normals.h>
#include <CGAL/jet_estimate_normals.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/range/counting_range.hpp>

#include <catch2/catch.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <limits>
#include <list>
#include <mutex>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace params = CGAL::RRHT::parameters;
using CGAL::RRHT::Sampling;
using CGAL::RRHT::Aggregation;
using CGAL::RRHT::Setting;

namespace {

template <typename Kernel>
using Point_with_normal = std::pair<typename Kernel::Point_3, typename Kernel::Vector_3>;

template <typename Kernel>
using Pair_cloud = std::vector<Point_with_normal<Kernel> >;

template <typename Kernel>
const auto pair_maps = CGAL::parameters::point_map(CGAL::First_of_pair_property_map<Point_with_normal<Kernel> >())
                         .normal_map(CGAL::Second_of_pair_property_map<Point_with_normal<Kernel> >());

template <typename Kernel>
Pair_cloud<Kernel> to_pairs(const rrht_test::Cloud& cloud)
{
  typedef typename Kernel::FT FT;
  Pair_cloud<Kernel> out;
  for(const auto& s : cloud)
    out.emplace_back(typename Kernel::Point_3(FT(s.point.x()), FT(s.point.y()), FT(s.point.z())),
                     typename Kernel::Vector_3(CGAL::NULL_VECTOR));
  return out;
}

// Share of normals more than 10 degrees off the truth; also checks that every
// normal is finite and of unit length.
template <typename Vector3>
double share_above_10_degrees(const std::vector<Vector3>& normals, const rrht_test::Cloud& truth)
{
  REQUIRE(normals.size() == truth.size());
  std::size_t bad = 0;
  for(std::size_t i = 0; i < normals.size(); ++i)
  {
    const double x = CGAL::to_double(normals[i].x()), y = CGAL::to_double(normals[i].y()), z = CGAL::to_double(normals[i].z());
    REQUIRE(std::isfinite(x));
    REQUIRE(std::isfinite(y));
    REQUIRE(std::isfinite(z));
    REQUIRE(std::sqrt(x * x + y * y + z * z) == Approx(1).epsilon(1e-5));
    const rrht_test::Vector& t = truth[i].truth;
    bad += std::abs(x * t.x() + y * t.y() + z * t.z()) < std::cos(10 * rrht_test::pi / 180);
  }
  return double(bad) / normals.size();
}

template <typename Kernel>
std::vector<typename Kernel::Vector_3> normals_of(const Pair_cloud<Kernel>& cloud)
{
  std::vector<typename Kernel::Vector_3> out;
  for(const auto& pn : cloud)
    out.push_back(pn.second);
  return out;
}

rrht_test::Cloud noisy_cube(std::size_t n)
{
  rrht_test::Cloud cloud = rrht_test::cube(n, 21);
  rrht_test::add_noise(cloud, 0.2, 22);
  return cloud;
}

// Runs `run(callback)` with a callback that records every advancement, and
// checks that they lie in [0, 1] and end with 1.
template <typename Run>
void check_progress(Run run)
{
  std::vector<double> seen;
  std::mutex mutex;
  const std::function<bool(double)> callback = [&](double advancement) {
    std::lock_guard<std::mutex> lock(mutex);
    seen.push_back(advancement);
    return true;
  };
  run(callback);
  REQUIRE(!seen.empty());
  CHECK(seen.back() == 1.);
  for(double a : seen)
    CHECK((a >= 0 && a <= 1));
}

bool has_nan(const std::vector<CGAL::Simple_cartesian<double>::Vector_3>& normals)
{
  for(const auto& n : normals)
    if(!(std::isfinite(n.x()) && std::isfinite(n.y()) && std::isfinite(n.z())))
      return true;
  return false;
}

typedef CGAL::Simple_cartesian<double> SC;

} // namespace

TEMPLATE_TEST_CASE("Works on a vector of pairs with pair property maps, for several kernels", "[api]",
                   CGAL::Simple_cartesian<double>, CGAL::Exact_predicates_inexact_constructions_kernel,
                   CGAL::Simple_cartesian<float>)
{
  const rrht_test::Cloud truth = noisy_cube(6000);
  Pair_cloud<TestType> cloud = to_pairs<TestType>(truth);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(cloud, 60, pair_maps<TestType>);
  CHECK(share_above_10_degrees(normals_of<TestType>(cloud), truth) < 0.06);
}

TEST_CASE("Works on a CGAL::Point_set_3 with its own maps, with the same result as on a vector", "[api]")
{
  const rrht_test::Cloud truth = noisy_cube(6000);
  CGAL::Point_set_3<SC::Point_3> point_set;
  point_set.add_normal_map();
  for(const auto& s : truth)
    point_set.insert(s.point);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(point_set, 60);

  Pair_cloud<SC> pairs = to_pairs<SC>(truth);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(pairs, 60, pair_maps<SC>);

  std::vector<SC::Vector_3> normals;
  for(auto i : point_set)
    normals.push_back(point_set.normal(i));
  CHECK(normals == normals_of<SC>(pairs));
  CHECK(share_above_10_degrees(normals, truth) < 0.06);
}

namespace {
// A user's own type, with property maps of its own.
struct Scan_point
{
  double xyz[3];
  float normal[3];
  int label;
};

struct Scan_point_map
{
  typedef Scan_point key_type;
  typedef SC::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  friend value_type get(Scan_point_map, const Scan_point& p) { return value_type(p.xyz[0], p.xyz[1], p.xyz[2]); }
};

struct Scan_normal_map
{
  typedef Scan_point key_type;
  typedef SC::Vector_3 value_type;
  typedef value_type reference;
  typedef boost::writable_property_map_tag category;
  friend void put(Scan_normal_map, Scan_point& p, const value_type& n)
  {
    p.normal[0] = float(n.x()); p.normal[1] = float(n.y()); p.normal[2] = float(n.z());
  }
};
} // namespace

TEST_CASE("Works on a user struct with custom property maps and a std::list", "[api]")
{
  const rrht_test::Cloud truth = noisy_cube(6000);
  std::list<Scan_point> scan;
  for(const auto& s : truth)
    scan.push_back(Scan_point{ { s.point.x(), s.point.y(), s.point.z() }, { 0, 0, 0 }, 7 });
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    scan, 60, params::point_map(Scan_point_map()).normal_map(Scan_normal_map()).number_of_rotations(3));
  std::vector<SC::Vector_3> normals;
  for(const auto& p : scan)
  {
    normals.emplace_back(p.normal[0], p.normal[1], p.normal[2]);
    CHECK(p.label == 7);
  }
  CHECK(share_above_10_degrees(normals, truth) < 0.06);
}

TEST_CASE("Every documented named-parameter form", "[api][parameters]")
{
  typedef Point_with_normal<SC> PN;
  const CGAL::First_of_pair_property_map<PN> point_map;
  const CGAL::Second_of_pair_property_map<PN> normal_map;
  const rrht_test::Cloud truth = noisy_cube(2000);
  const Pair_cloud<SC> input = to_pairs<SC>(truth);

  auto run = [&](const auto& np) {
    Pair_cloud<SC> cloud = input;
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(cloud, 40, np);
    return normals_of<SC>(cloud);
  };

  // 1. A plain CGAL chain, exactly as for jet fitting: RRHT defaults, which
  // are least squares first with the adaptive Hough transform.
  const auto defaults = run(CGAL::parameters::point_map(point_map).normal_map(normal_map));
  CHECK(share_above_10_degrees(defaults, truth) < 0.12);
  CHECK(run(params::point_map(point_map).normal_map(normal_map).setting(Setting::DEFAULT)) == defaults);
  {
    Pair_cloud<SC> cloud = input; // the same expression still works with jet fitting
    CGAL::jet_estimate_normals<CGAL::Sequential_tag>(cloud, 40, CGAL::parameters::point_map(point_map).normal_map(normal_map));
  }
  // 2. The paper's precise setting, and an RRHT chain repeating its values
  // explicitly, give the same normals.
  const auto precise = run(params::setting(Setting::PAPER_PRECISE).point_map(point_map).normal_map(normal_map));
  CHECK(share_above_10_degrees(precise, truth) < 0.08);
  CHECK(precise != defaults);
  const auto explicit_precise = run(params::point_map(point_map)
                                      .normal_map(normal_map)
                                      .setting(Setting::PAPER_PRECISE)
                                      .refit(false)
                                      .number_of_planes(CGAL::RRHT::hoeffding_number_of_planes(172))
                                      .accumulator_slices(15)
                                      .number_of_rotations(5)
                                      .use_confidence_interval(true)
                                      .sampling(Sampling::POINTS)
                                      .presampling_factor(4)
                                      .aggregation(Aggregation::CLUSTER)
                                      .cluster_angle(45.)
                                      .random_seed(0));
  CHECK(explicit_precise == precise);
  // 3. RRHT parameters first, then CGAL ones, in any order: the same normals.
  // The fast setting is the precise one with 300 planes and 2 rotations, and
  // a value given wins over the setting's, wherever it stands in the chain.
  const auto fast = run(params::setting(Setting::PAPER_FAST).point_map(point_map).normal_map(normal_map));
  CHECK(run(params::normal_map(normal_map).number_of_rotations(2).setting(Setting::PAPER_PRECISE)
              .point_map(point_map).number_of_planes(300)) == fast);
  CHECK(fast != precise); // the setting is read
  CHECK(run(params::number_of_planes(CGAL::RRHT::hoeffding_number_of_planes(172)).number_of_rotations(5)
              .setting(Setting::PAPER_FAST).point_map(point_map).normal_map(normal_map)) == precise);
  // The deprecated spellings, kept for one release: the presets, and the
  // switches, which win over the setting.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  CHECK(run(params::paper_precise().point_map(point_map).normal_map(normal_map)) == precise);
  CHECK(run(params::paper_fast().point_map(point_map).normal_map(normal_map)) == fast);
#pragma GCC diagnostic pop
  CHECK(run(params::least_squares_first(false).adaptive(false).point_map(point_map).normal_map(normal_map)) == precise);
  CHECK(run(params::setting(Setting::PAPER_PRECISE).least_squares_first(true).adaptive(true).point_map(point_map)
              .normal_map(normal_map)) == defaults);
  // An unknown setting is refused before anything is written.
  CHECK_THROWS_AS(run(params::setting(static_cast<Setting>(7)).point_map(point_map).normal_map(normal_map)),
                  std::invalid_argument);
  // 4. From an empty chain.
  CHECK(run(params::default_values().point_map(point_map).normal_map(normal_map)) == defaults);
  // 5. Extending a CGAL chain received from elsewhere.
  const auto cgal_chain = CGAL::parameters::point_map(point_map).normal_map(normal_map);
  CHECK(run(params::extend(cgal_chain).setting(Setting::PAPER_FAST)) == fast);
  CHECK(run(params::extend(cgal_chain)) == defaults);
  // 6. Each RRHT parameter changes the result.
  const auto base = params::setting(Setting::PAPER_PRECISE).point_map(point_map).normal_map(normal_map);
  CHECK(run(base.accumulator_slices(10)) != precise);
  CHECK(run(base.use_confidence_interval(false)) != precise);
  CHECK(run(base.sampling(Sampling::CUBES)) != precise);
  CHECK(run(base.sampling(Sampling::CUBES).presampling_factor(3)) != run(base.sampling(Sampling::CUBES)));
  CHECK(run(base.sampling(Sampling::UNIF)) != precise);
  CHECK(run(base.aggregation(Aggregation::MEAN)) != precise);
  CHECK(run(base.aggregation(Aggregation::BEST)) != precise);
  CHECK(run(base.cluster_angle(5.)) != precise);
  CHECK(run(base.random_seed(7)) != precise);
  CHECK(run(base.adaptive(true)) != precise);
  CHECK(run(base.least_squares_first(true)) != precise);
  CHECK(run(base.refit(true)) != precise);
  CHECK(run(params::extend(cgal_chain).setting(Setting::PAPER_FAST).refit(true)) != fast);
  // 7. An RRHT chain is a CGAL chain: CGAL's own functions take it.
  {
    Pair_cloud<SC> cloud = input;
    CGAL::jet_estimate_normals<CGAL::Sequential_tag>(cloud, 40, base.number_of_planes(300).degree_fitting(2));
    CHECK(share_above_10_degrees(normals_of<SC>(cloud), truth) < 0.5);
  }
}

TEST_CASE("CGAL 6's combine() keeps an RRHT chain and its RRHT parameters", "[api][parameters]")
{
#if CGAL_VERSION_NR < CGAL_VERSION_NUMBER(6, 0, 0)
  WARN("SKIPPED: CGAL " << CGAL_VERSION_STR << " has no Named_function_parameters::combine()");
#else
  typedef Point_with_normal<SC> PN;
  const CGAL::First_of_pair_property_map<PN> point_map;
  const CGAL::Second_of_pair_property_map<PN> normal_map;
  const Pair_cloud<SC> input = to_pairs<SC>(noisy_cube(2000));
  auto run = [&](const auto& np) {
    Pair_cloud<SC> cloud = input;
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(cloud, 40, np);
    return normals_of<SC>(cloud);
  };
  const auto fast = run(params::point_map(point_map).normal_map(normal_map).number_of_planes(300).number_of_rotations(2));
  // An RRHT chain combined with CGAL and RRHT links, then continued with RRHT parameters.
  const auto combined = params::number_of_planes(300)
                          .combine(CGAL::parameters::point_map(point_map), params::normal_map(normal_map))
                          .number_of_rotations(2);
  CHECK(run(combined) == fast);
  // A CGAL chain combined with RRHT links holds their values.
  CHECK(run(CGAL::parameters::point_map(point_map)
              .combine(params::normal_map(normal_map), params::number_of_planes(300), params::number_of_rotations(2))) == fast);
#endif
}

TEST_CASE("A CGAL::Point_set_3 without a normal map: a clear exception, nothing written", "[api][bad-input]")
{
  CGAL::Point_set_3<SC::Point_3> point_set;
  for(const rrht_test::Sample& s : noisy_cube(500))
    point_set.insert(s.point);
  CHECK_THROWS_WITH(CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(point_set, 20),
                    Catch::Contains("no normal map"));
  CHECK(!point_set.has_normal_map());
  // Once it has one, the same call works.
  point_set.add_normal_map();
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(point_set, 20);
  CHECK(point_set.normal(*point_set.begin()) != CGAL::NULL_VECTOR);
}

#ifdef CGAL_LINKED_WITH_TBB
TEST_CASE("Same seed, same normals, bit for bit, whatever the concurrency and the number of threads", "[api][parallel]")
{
  const rrht_test::Cloud truth = noisy_cube(2000);
  for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
  {
    const auto np = pair_maps<SC>;
    Pair_cloud<SC> sequential = to_pairs<SC>(truth);
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(sequential, 50, params::extend(np).sampling(sampling).random_seed(3));
    for(int threads : { 1, 2, 3 })
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      Pair_cloud<SC> parallel = to_pairs<SC>(truth);
      CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(parallel, 50, params::extend(np).sampling(sampling).random_seed(3));
      INFO("sampling " << int(sampling) << ", " << threads << " threads");
      CHECK(normals_of<SC>(parallel) == normals_of<SC>(sequential));
    }
  }
  // The adaptive setting and the refit too.
  auto check_setting = [&](const char* name, const auto& np) {
    Pair_cloud<SC> sequential = to_pairs<SC>(truth);
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(sequential, 50, np);
    for(int threads : { 1, 2, 3 })
    {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      Pair_cloud<SC> parallel = to_pairs<SC>(truth);
      CGAL::rrht_estimate_normals<CGAL::Parallel_tag>(parallel, 50, np);
      INFO(name << ", " << threads << " threads");
      CHECK(normals_of<SC>(parallel) == normals_of<SC>(sequential));
    }
  };
  check_setting("adaptive", params::extend(pair_maps<SC>).adaptive(true));
  check_setting("refit", params::extend(pair_maps<SC>).refit(true));
  check_setting("refit with a radius", params::extend(pair_maps<SC>).refit(true).neighbor_radius(0.3));
  check_setting("default", params::extend(pair_maps<SC>).setting(Setting::DEFAULT));
  check_setting("least squares first with refit and a radius",
                params::extend(pair_maps<SC>).least_squares_first(true).refit(true).neighbor_radius(0.3));
}
#endif

TEST_CASE("confidence_map: into a Point_set_3 property, the same whatever the threads, 0 where no normal", "[api][confidence]")
{
  const rrht_test::Cloud truth = noisy_cube(3000);
  auto run = [&](auto concurrency, int threads, const auto& np) {
    CGAL::Point_set_3<SC::Point_3> point_set;
    point_set.add_normal_map();
    auto confidence = point_set.add_property_map<double>("confidence", -1.).first;
    for(const auto& s : truth)
      point_set.insert(s.point);
    point_set.insert(SC::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0)); // no normal
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
#endif
    (void)threads;
    CGAL::rrht_estimate_normals<decltype(concurrency)>(point_set, 30, params::extend(np).confidence_map(confidence));
    std::vector<std::pair<SC::Vector_3, double> > out;
    for(auto i : point_set)
      out.emplace_back(point_set.normal(i), confidence[i]);
    return out;
  };
  // The paper's setting, where every normal is a bin's, and the default,
  // where a quadric's normal may be off every bin of the Hough transform.
  for(bool paper : { true, false })
  {
    INFO((paper ? "PAPER_PRECISE" : "DEFAULT"));
    const auto np = params::setting(paper ? Setting::PAPER_PRECISE : Setting::DEFAULT);
    const auto sequential = run(CGAL::Sequential_tag(), 1, np);
    std::size_t positive = 0;
    for(std::size_t i = 0; i < truth.size(); ++i)
    {
      CHECK(sequential[i].second >= 0);
      CHECK(sequential[i].second <= 1);
      positive += sequential[i].second > 0;
    }
    CHECK(positive >= (paper ? truth.size() : truth.size() * 99 / 100));
    for(std::size_t i = truth.size(); i < sequential.size(); ++i)
    {
      CHECK(sequential[i].first == SC::Vector_3(CGAL::NULL_VECTOR));
      CHECK(sequential[i].second == 0);
    }
#ifdef CGAL_LINKED_WITH_TBB
    for(int threads : { 1, 2, 3 })
      CHECK(run(CGAL::Parallel_tag(), threads, np) == sequential);
#endif
  }

  // Collinear points: no plane, so no normal and no confidence.
  CGAL::Point_set_3<SC::Point_3> line;
  line.add_normal_map();
  auto confidence = line.add_property_map<double>("confidence", -1.).first;
  for(int i = 0; i < 20; ++i)
    line.insert(SC::Point_3(i, 2 * i, 3 * i));
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(line, 10, params::confidence_map(confidence));
  for(auto i : line)
  {
    CHECK(line.normal(i) == SC::Vector_3(CGAL::NULL_VECTOR));
    CHECK(confidence[i] == 0);
  }
}

TEST_CASE("The callback reports progress, and returning false stops, leaving the rest unchanged", "[api][callback]")
{
  const rrht_test::Cloud truth = noisy_cube(5000), large = noisy_cube(200000);
  const SC::Vector_3 untouched(7, 7, 7);
  auto check_tag = [&](auto tag, std::size_t threads) {
    typedef decltype(tag) Tag;
    // A full run: advancement in [0, 1], ending with 1.
    {
      Pair_cloud<SC> cloud = to_pairs<SC>(truth);
      check_progress([&](const std::function<bool(double)>& callback) {
        CGAL::rrht_estimate_normals<Tag>(cloud, 30, params::extend(pair_maps<SC>).callback(callback));
      });
    }
    // Interrupted at the first report, on a cloud large enough for TBB's
    // default partitioner to hand out ranges of thousands of points. By
    // default, the normals are written in the last of three passes: stopped
    // in the first, every normal is left unchanged.
    for(bool paper : { true, false })
    {
      INFO((paper ? "PAPER_PRECISE" : "DEFAULT"));
      Pair_cloud<SC> cloud = to_pairs<SC>(large);
      for(auto& pn : cloud)
        pn.second = untouched;
      std::function<bool(double)> stop = [](double) { return false; };
      CGAL::rrht_estimate_normals<Tag>(
        cloud, 10, params::extend(pair_maps<SC>).callback(stop).number_of_planes(10).number_of_rotations(1)
                     .setting(paper ? Setting::PAPER_PRECISE : Setting::DEFAULT));
      std::size_t estimated = 0, unchanged = 0;
      for(const auto& pn : cloud)
      {
        if(pn.second == untouched)
          ++unchanged;
        else
        {
          ++estimated;
          CHECK(pn.second.squared_length() == Approx(1));
        }
      }
      CHECK((estimated > 0) == paper);
      // Each thread stops after the block of at most 64 points it was on, and
      // may have started one more before the first report.
      CHECK(estimated <= 2 * 64 * threads);
      CHECK(estimated + unchanged == cloud.size());
    }
  };
  check_tag(CGAL::Sequential_tag(), 1);
#ifdef CGAL_LINKED_WITH_TBB
  check_tag(CGAL::Parallel_tag(), std::size_t(tbb::this_task_arena::max_concurrency()));
#endif
}

TEST_CASE("Ball neighborhoods: with and without a cap on the number of points", "[api][radius]")
{
  const rrht_test::Cloud truth = noisy_cube(8000);
  // 8000 points on an area of 24: about 333 points per unit area.
  SECTION("uncapped ball")
  {
    for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
    {
      Pair_cloud<SC> cloud = to_pairs<SC>(truth);
      CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
        cloud, 0, params::extend(pair_maps<SC>).neighbor_radius(0.25).sampling(sampling));
      INFO("sampling " << int(sampling));
      CHECK(share_above_10_degrees(normals_of<SC>(cloud), truth) < 0.06);
    }
  }
  SECTION("a capped ball keeps the k nearest: the same as the k-neighborhood")
  {
    for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES })
    {
      Pair_cloud<SC> capped = to_pairs<SC>(truth), knn = to_pairs<SC>(truth);
      CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(capped, 40,
                                                        params::extend(pair_maps<SC>).neighbor_radius(10.).sampling(sampling));
      CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(knn, 40, params::extend(pair_maps<SC>).sampling(sampling));
      CHECK(normals_of<SC>(capped) == normals_of<SC>(knn));
    }
  }
  SECTION("a ball that holds fewer points than the cap is the uncapped ball")
  {
    Pair_cloud<SC> capped = to_pairs<SC>(truth), ball = to_pairs<SC>(truth);
    // A ball of radius 0.2 holds about 42 points on a face, 80 at a corner.
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(capped, 400, params::extend(pair_maps<SC>).neighbor_radius(0.2));
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(ball, 0, params::extend(pair_maps<SC>).neighbor_radius(0.2));
    CHECK(normals_of<SC>(capped) == normals_of<SC>(ball));
    CHECK(share_above_10_degrees(normals_of<SC>(ball), truth) < 0.06);
  }
  SECTION("a ball with fewer than 3 points falls back to the k nearest neighbors")
  {
    Pair_cloud<SC> tiny = to_pairs<SC>(truth), knn = to_pairs<SC>(truth);
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(tiny, 30, params::extend(pair_maps<SC>).neighbor_radius(1e-9));
    CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(knn, 30, pair_maps<SC>);
    CHECK(normals_of<SC>(tiny) == normals_of<SC>(knn));
  }
}

namespace {

// Maps on positions that count their use: what reads no point leaves 0.
struct Counted_use
{
  std::atomic<std::size_t>* uses;
};
struct Point_at : Counted_use
{
  typedef std::uint64_t key_type;
  typedef SC::Point_3 value_type;
  typedef value_type reference;
  typedef boost::readable_property_map_tag category;
  friend value_type get(const Point_at& map, std::uint64_t i) { return ++*map.uses, value_type(double(i), 0, 0); }
};
struct Normal_at : Counted_use
{
  typedef std::uint64_t key_type;
  typedef SC::Vector_3 value_type;
  typedef value_type reference;
  typedef boost::writable_property_map_tag category;
  friend void put(const Normal_at& map, std::uint64_t, const value_type&) { ++*map.uses; }
};

} // namespace

TEST_CASE("Bad input: a clear exception or a documented result, never NaN", "[api][bad-input]")
{
  typedef Point_with_normal<SC> PN;
  auto estimate = [](Pair_cloud<SC>& cloud, unsigned int k, const auto& np) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, k, np);
    return normals_of<SC>(cloud);
  };
  const auto maps = params::extend(pair_maps<SC>);
  const SC::Vector_3 null(CGAL::NULL_VECTOR);

  SECTION("empty range: nothing to do, but the parameters are checked (rrht_normals relies on it)")
  {
    Pair_cloud<SC> cloud;
    CHECK_NOTHROW(estimate(cloud, 10, maps));
    CHECK_THROWS_AS(estimate(cloud, 10, maps.number_of_planes(0)), std::invalid_argument);
    CHECK_THROWS_AS(estimate(cloud, 0, maps), std::invalid_argument);
  }
  SECTION("more than 2^32 - 1 points: refused before a point is read or a normal written")
  {
    // A range of 2^32 positions, whose point and normal maps count their use.
    auto huge = boost::counting_range(std::uint64_t(0), std::uint64_t(1) << 32);
    std::atomic<std::size_t> uses(0);
    CHECK_THROWS_WITH(CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(
                        huge, 10, params::point_map(Point_at{ { &uses } }).normal_map(Normal_at{ { &uses } })),
                      Catch::Contains("2^32 - 1 points"));
    CHECK(uses == 0);
  }

  SECTION("1 and 2 points, all points identical, collinear points: the null vector")
  {
    for(std::size_t n : { 1, 2 })
    {
      Pair_cloud<SC> cloud;
      for(std::size_t i = 0; i < n; ++i)
        cloud.emplace_back(SC::Point_3(double(i), 0, 0), SC::Vector_3(1, 1, 1));
      for(const auto& normal : estimate(cloud, 10, maps))
        CHECK(normal == null);
    }
    Pair_cloud<SC> same(50, PN(SC::Point_3(1, 2, 3), SC::Vector_3(1, 1, 1)));
    for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
      for(const auto& normal : estimate(same, 10, maps.sampling(sampling)))
        CHECK(normal == null);
    Pair_cloud<SC> line;
    for(int i = 0; i < 50; ++i)
      line.emplace_back(SC::Point_3(0.5 * i, 0, 0), SC::Vector_3(1, 1, 1));
    for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
      for(const auto& normal : estimate(line, 10, maps.sampling(sampling)))
        CHECK(normal == null);
  }
  SECTION("identical points in a ball of radius below 1e-300: the null vector")
  {
    Pair_cloud<SC> same(50, PN(SC::Point_3(1, 2, 3), SC::Vector_3(1, 1, 1)));
    for(Sampling sampling : { Sampling::POINTS, Sampling::CUBES, Sampling::UNIF })
      for(const auto& normal : estimate(same, 10, maps.sampling(sampling).neighbor_radius(1e-320)))
        CHECK(normal == null);
  }
  SECTION("k larger than the number of points: all points are neighbors")
  {
    Pair_cloud<SC> cloud = to_pairs<SC>(rrht_test::plane(20, 3));
    for(const auto& normal : estimate(cloud, 1000, maps))
      CHECK(std::abs(normal.z()) == Approx(1));
  }
  SECTION("NaN or infinite coordinates: the null vector there, the other points unaffected")
  {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    Pair_cloud<SC> cloud = to_pairs<SC>(rrht_test::plane(300, 4));
    cloud[5].first = SC::Point_3(nan, 0, 0);
    cloud[6].first = SC::Point_3(0, inf, 0);
    cloud[7].first = SC::Point_3(0, 0, -inf);
    const auto normals = estimate(cloud, 20, maps);
    CHECK(!has_nan(normals));
    for(std::size_t i = 0; i < normals.size(); ++i)
    {
      if(i >= 5 && i <= 7)
        CHECK(normals[i] == null);
      else
        CHECK(std::abs(normals[i].z()) == Approx(1));
    }
  }
  SECTION("points spanning hundreds of orders of magnitude: unit normals or the null vector, never NaN")
  {
    // A damaged binary PLY file read as doubles: coordinates from 1e-300 to
    // 1e256, neighborhoods whose points span more orders of magnitude than
    // double precision holds.
    std::ifstream in(std::string(RRHT_TEST_DATA) + "/multiscale.xyz");
    Pair_cloud<SC> cloud;
    for(double x, y, z; in >> x >> y >> z;)
      cloud.emplace_back(SC::Point_3(x, y, z), SC::Vector_3(1, 1, 1));
    REQUIRE(cloud.size() == 300);
    auto check = [&](const auto& np) {
      for(unsigned int k : { 3, 8, 30 })
        for(const auto& normal : estimate(cloud, k, np))
          CHECK((normal == null || std::abs(normal.squared_length() - 1) < 1e-12));
    };
    check(maps);
    check(maps.setting(Setting::PAPER_PRECISE));
  }
  SECTION("invalid parameters throw std::invalid_argument and write nothing")
  {
    const Pair_cloud<SC> input = to_pairs<SC>(rrht_test::plane(100, 5));
    auto throws = [&](unsigned int k, const auto& np) {
      Pair_cloud<SC> cloud = input;
      CHECK_THROWS_AS(estimate(cloud, k, np), std::invalid_argument);
      for(const auto& pn : cloud)
        CHECK(pn.second == null);
    };
    throws(0, maps);                                  // k = 0 without radius
    throws(10, maps.neighbor_radius(-1.));
    throws(10, maps.neighbor_radius(std::numeric_limits<double>::quiet_NaN()));
    throws(10, maps.number_of_planes(0));             // T = 0
    throws(10, maps.number_of_planes(-5));
    throws(10, maps.number_of_rotations(0));          // n_rot = 0
    throws(10, maps.accumulator_slices(0));           // n_phi = 0
    throws(10, maps.presampling_factor(0));
    throws(10, maps.presampling_factor(33));
    throws(10, maps.cluster_angle(-1.));
    throws(10, maps.cluster_angle(std::numeric_limits<double>::quiet_NaN()));
    throws(10, maps.sampling(static_cast<Sampling>(42)));
    throws(10, maps.aggregation(static_cast<Aggregation>(42)));
  }
  SECTION("extreme but valid parameters")
  {
    Pair_cloud<SC> cloud = to_pairs<SC>(noisy_cube(500));
    CHECK(!has_nan(estimate(cloud, 10, maps.number_of_planes(1).number_of_rotations(1).accumulator_slices(1))));
    CHECK(!has_nan(estimate(cloud, 10, maps.sampling(Sampling::UNIF).presampling_factor(32))));
    CHECK(!has_nan(estimate(cloud, 10, maps.sampling(Sampling::CUBES).presampling_factor(1).cluster_angle(0.))));
  }
}

TEST_CASE("Refit: degenerate neighborhoods keep the RRHT result, never NaN, and progress still ends at 1", "[api][refit][bad-input]")
{
  typedef Point_with_normal<SC> PN;
  auto estimate = [](Pair_cloud<SC> cloud, unsigned int k, const auto& np) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, k, np);
    return normals_of<SC>(cloud);
  };
  const auto maps = params::extend(pair_maps<SC>);
  const SC::Vector_3 null(CGAL::NULL_VECTOR);

  // Identical and collinear points: the null vector, as without the refit.
  const Pair_cloud<SC> same(50, PN(SC::Point_3(1, 2, 3), SC::Vector_3(1, 1, 1)));
  Pair_cloud<SC> line;
  for(int i = 0; i < 50; ++i)
    line.emplace_back(SC::Point_3(0.5 * i, 0, 0), SC::Vector_3(1, 1, 1));
  for(const auto& normal : estimate(same, 10, maps.refit(true)))
    CHECK(normal == null);
  for(const auto& normal : estimate(line, 10, maps.refit(true)))
    CHECK(normal == null);

  // A noise-free plane, with a NaN point among it: the exact normal, with a
  // noise deviation of 0 (the band's floor then applies), and the null vector
  // at the NaN point.
  Pair_cloud<SC> plane = to_pairs<SC>(rrht_test::plane(300, 4));
  plane[5].first = SC::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  const auto refitted = estimate(plane, 20, maps.refit(true));
  CHECK(!has_nan(refitted));
  for(std::size_t i = 0; i < refitted.size(); ++i)
  {
    if(i == 5)
      CHECK(refitted[i] == null);
    else
      CHECK(std::abs(refitted[i].z()) == Approx(1).margin(1e-12));
  }

  // Fewer neighbors than the quadric's 6 unknowns: the RRHT normals stay.
  const Pair_cloud<SC> cube = to_pairs<SC>(noisy_cube(500));
  CHECK(estimate(cube, 4, maps.refit(true)) == estimate(cube, 4, maps));

  // Two passes, one progress from 0 to 1.
  check_progress([&](const std::function<bool(double)>& callback) { estimate(cube, 30, maps.refit(true).callback(callback)); });
}

TEST_CASE("Least squares first: degenerate neighborhoods get the Hough transform's result, never NaN, and progress ends at 1",
          "[api][least-squares-first][bad-input]")
{
  typedef Point_with_normal<SC> PN;
  auto estimate = [](Pair_cloud<SC> cloud, unsigned int k, const auto& np) {
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, k, np);
    return normals_of<SC>(cloud);
  };
  const auto maps = params::extend(pair_maps<SC>);
  const auto first = maps.least_squares_first(true);
  const SC::Vector_3 null(CGAL::NULL_VECTOR);

  // Identical and collinear points: no quadric, no plane, the null vector.
  const Pair_cloud<SC> same(50, PN(SC::Point_3(1, 2, 3), SC::Vector_3(1, 1, 1)));
  Pair_cloud<SC> line;
  for(int i = 0; i < 50; ++i)
    line.emplace_back(SC::Point_3(0.5 * i, 0, 0), SC::Vector_3(1, 1, 1));
  for(const auto& normal : estimate(same, 10, first))
    CHECK(normal == null);
  for(const auto& normal : estimate(line, 10, first.refit(true)))
    CHECK(normal == null);

  // A noise-free plane, with a NaN point among it: the exact normal from the
  // quadric, and the null vector at the NaN point.
  Pair_cloud<SC> plane = to_pairs<SC>(rrht_test::plane(300, 4));
  plane[5].first = SC::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  const auto fitted = estimate(plane, 20, first);
  CHECK(!has_nan(fitted));
  for(std::size_t i = 0; i < fitted.size(); ++i)
  {
    if(i == 5)
      CHECK(fitted[i] == null);
    else
      CHECK(std::abs(fitted[i].z()) == Approx(1).margin(1e-12));
  }

  // At most 6 points, fewer than a quadric needs: the Hough transform everywhere.
  const Pair_cloud<SC> cube = to_pairs<SC>(noisy_cube(500));
  CHECK(estimate(cube, 5, first.adaptive(true)) == estimate(cube, 5, maps.adaptive(true)));
  CHECK(estimate(cube, 5, first) == estimate(cube, 5, maps));

  // Three passes, one progress from 0 to 1.
  check_progress([&](const std::function<bool(double)>& callback) { estimate(cube, 30, first.callback(callback)); });
}


namespace {

// A point with what the estimation writes, and a stable id.
typedef std::tuple<SC::Point_3, SC::Vector_3, std::uint64_t, double, double> Identified; // point, normal, id, support, confidence
const auto identified_maps = params::point_map(CGAL::Nth_of_tuple_property_map<0, Identified>())
                               .normal_map(CGAL::Nth_of_tuple_property_map<1, Identified>())
                               .point_id_map(CGAL::Nth_of_tuple_property_map<2, Identified>())
                               .support_radius_map(CGAL::Nth_of_tuple_property_map<3, Identified>())
                               .confidence_map(CGAL::Nth_of_tuple_property_map<4, Identified>());

std::vector<Identified> identified(const std::vector<SC::Point_3>& points)
{
  std::vector<Identified> out;
  for(std::size_t i = 0; i < points.size(); ++i)
    out.emplace_back(points[i], CGAL::NULL_VECTOR, std::uint64_t(i), -1., -1.);
  return out;
}

// Runs `estimate` on the whole cloud and on the points with x < `cut`, in
// another order, and checks that every point of the part whose support lies
// in it (distance to the plane x = cut above the support radius, with a
// margin for rounding) has the same normal, confidence and support, bit for
// bit. Returns the share of the part's points so checked.
template <typename Estimate>
double check_part_against_whole(const std::vector<SC::Point_3>& points, double cut, Estimate estimate)
{
  std::vector<Identified> whole = identified(points), part;
  estimate(whole);
  for(const Identified& e : identified(points))
    if(std::get<0>(e).x() < cut)
      part.push_back(e);
  std::shuffle(part.begin(), part.end(), std::mt19937(5)); // the order of the range does not matter
  estimate(part);
  std::size_t checked = 0;
  for(const Identified& e : part)
  {
    const double support = std::get<3>(e);
    REQUIRE(support >= 0);
    if(cut - std::get<0>(e).x() <= support * (1 + 1e-12))
      continue;
    const Identified& w = whole[std::get<2>(e)];
    INFO("point " << std::get<2>(e));
    REQUIRE(std::get<1>(e) == std::get<1>(w));
    REQUIRE(std::get<4>(e) == std::get<4>(w));
    REQUIRE(std::get<3>(e) == std::get<3>(w));
    ++checked;
  }
  return double(checked) / part.size();
}

std::vector<SC::Point_3> points_of(const rrht_test::Cloud& cloud)
{
  std::vector<SC::Point_3> out;
  for(const auto& s : cloud)
    out.push_back(s.point);
  return out;
}

} // namespace

TEST_CASE("point_id_map: a part of the cloud gives each point whose support it holds the normal of the whole cloud",
          "[api][point_id_map]")
{
  const std::vector<SC::Point_3> cube = points_of(noisy_cube(6000));
  auto with = [](unsigned int k, const auto& np) {
    return [=](std::vector<Identified>& cloud) { CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(cloud, k, np); };
  };
  const auto defaults = identified_maps.random_seed(9);
  CHECK(check_part_against_whole(cube, 0.2, with(50, defaults)) > 0.4);
  CHECK(check_part_against_whole(cube, 0.2, with(30, defaults.neighbor_radius(0.25))) > 0.4);
  const auto np = defaults.setting(Setting::PAPER_PRECISE);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np)) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np.sampling(Sampling::CUBES).number_of_planes(200))) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np.sampling(Sampling::UNIF).number_of_planes(200))) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np.adaptive(true))) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(0, np.neighbor_radius(0.25))) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(30, np.neighbor_radius(0.25))) > 0.6);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np.refit(true))) > 0.5);
  CHECK(check_part_against_whole(cube, 0.2, with(50, np.least_squares_first(true).adaptive(true))) > 0.4);
  CHECK(check_part_against_whole(cube, 0.2, with(30, np.least_squares_first(true).refit(true).neighbor_radius(0.25))) > 0.4);

  // A regular grid, where many neighbors are at the same distance, the k-th
  // too: the ids settle the ties, not the tree.
  std::vector<SC::Point_3> grid;
  for(int i = 0; i < 60; ++i)
    for(int j = 0; j < 60; ++j)
      grid.emplace_back(0.1 * i, 0.1 * j, (i > 30) ? 0.05 * (i - 30) : 0.);
  CHECK(check_part_against_whole(grid, 2.0, with(24, np)) > 0.6);
  CHECK(check_part_against_whole(grid, 2.0, with(24, np.refit(true))) > 0.5);
  CHECK(check_part_against_whole(grid, 2.0, with(24, np.least_squares_first(true))) > 0.4);
  CHECK(check_part_against_whole(grid, 2.0, with(0, np.neighbor_radius(0.25))) > 0.6);
}

TEST_CASE("point_id_map: by default the id is the position, and support_radius_map is the neighborhood's radius",
          "[api][point_id_map]")
{
  const std::vector<SC::Point_3> points = points_of(noisy_cube(3000));
  std::vector<Identified> with_ids = identified(points), without = identified(points);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(with_ids, 40, identified_maps);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    without, 40, params::point_map(CGAL::Nth_of_tuple_property_map<0, Identified>())
                   .normal_map(CGAL::Nth_of_tuple_property_map<1, Identified>()));
  for(std::size_t i = 0; i < points.size(); ++i)
    REQUIRE(std::get<1>(with_ids[i]) == std::get<1>(without[i]));

  // Other ids, other random streams: other normals wherever the Hough
  // transform gives them (everywhere with the paper's setting; the default's
  // quadrics do not depend on the streams).
  const auto paper = identified_maps.setting(Setting::PAPER_PRECISE);
  std::vector<Identified> plain = identified(points), shifted = identified(points);
  for(Identified& e : shifted)
    std::get<2>(e) += 1000000;
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(plain, 40, paper);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(shifted, 40, paper);
  std::size_t same = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
    same += std::get<1>(shifted[i]) == std::get<1>(plain[i]);
  CHECK(same < points.size() / 10);

  // With the paper's setting, the support is the distance to the 40th
  // nearest neighbor; with the refit, at least that, and at most three times
  // as large on this even sampling; least squares first (the default), at
  // most four times.
  std::vector<Identified> refitted = identified(points);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(refitted, 40, paper.refit(true));
  for(std::size_t i = 0; i < points.size(); i += 97)
  {
    std::vector<double> distances;
    for(const SC::Point_3& p : points)
      distances.push_back(std::sqrt(CGAL::squared_distance(p, points[i])));
    std::nth_element(distances.begin(), distances.begin() + 40, distances.end());
    CHECK(std::get<3>(plain[i]) == Approx(distances[40]).epsilon(1e-12));
    CHECK(std::get<3>(refitted[i]) >= std::get<3>(plain[i]));
    CHECK(std::get<3>(refitted[i]) < 3 * std::get<3>(plain[i]));
    CHECK(std::get<3>(with_ids[i]) >= 2 * std::get<3>(plain[i]));
    CHECK(std::get<3>(with_ids[i]) < 4 * std::get<3>(plain[i]));
  }

  // A cloud of at most k points is every point's neighborhood: an infinite
  // support.
  std::vector<Identified> few = identified(std::vector<SC::Point_3>(points.begin(), points.begin() + 30));
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(few, 40, identified_maps);
  for(const Identified& e : few)
    CHECK(std::isinf(std::get<3>(e)));
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(few, 40, paper);
  for(const Identified& e : few)
    CHECK(std::isinf(std::get<3>(e)));

  // A point with a non-finite coordinate has support 0.
  std::vector<SC::Point_3> with_nan = points;
  with_nan[7] = SC::Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  std::vector<Identified> nan_cloud = identified(with_nan);
  CGAL::rrht_estimate_normals<CGAL::Sequential_tag>(nan_cloud, 40, identified_maps);
  CHECK(std::get<3>(nan_cloud[7]) == 0.);
  CHECK(std::get<1>(nan_cloud[7]) == CGAL::NULL_VECTOR);
}

namespace {

// The points at x >= `cut` are only neighbors.
struct Beyond_cut
{
  typedef Identified key_type;
  typedef bool value_type;
  typedef bool reference;
  typedef boost::readable_property_map_tag category;
  double cut;
  friend bool get(const Beyond_cut& map, const Identified& e) { return std::get<0>(e).x() >= map.cut; }
};

} // namespace

TEST_CASE("neighbor_only_map: those points get nothing written, the others their normals", "[api][point_id_map]")
{
  std::vector<SC::Point_3> points = points_of(noisy_cube(4000));
  points[11] = SC::Point_3(0.5, std::numeric_limits<double>::infinity(), 0); // only a neighbor, not finite
  for(int setting : { 0, 1, 2 })
  {
    // The paper's precise setting, with the refit, and the defaults.
    const auto np = identified_maps.refit(setting == 1).setting(setting == 2 ? Setting::DEFAULT : Setting::PAPER_PRECISE);
    std::vector<Identified> all = identified(points), some = identified(points);
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(all, 40, np);
    CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(some, 40, np.neighbor_only_map(Beyond_cut{ 0.2 }));
    std::size_t only = 0;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      INFO("point " << i << ", setting " << setting);
      if(points[i].x() >= 0.2)
      {
        ++only;
        REQUIRE(std::get<1>(some[i]) == CGAL::NULL_VECTOR); // as given
        REQUIRE(std::get<3>(some[i]) == -1.);
        REQUIRE(std::get<4>(some[i]) == -1.);
      }
      else
      {
        REQUIRE(std::get<1>(some[i]) == std::get<1>(all[i]));
        REQUIRE(std::get<3>(some[i]) == std::get<3>(all[i]));
        REQUIRE(std::get<4>(some[i]) == std::get<4>(all[i]));
      }
    }
    CHECK(only > points.size() / 4);
  }
}

TEST_CASE("Least squares first: the confidence written is that of the normal returned, and changes no normal",
          "[api][least-squares-first][confidence]")
{
  const std::vector<SC::Point_3> points = points_of(noisy_cube(3000));
  std::vector<Identified> with = identified(points), without = identified(points);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    with, 50, identified_maps);
  CGAL::rrht_estimate_normals<CGAL::Parallel_if_available_tag>(
    without, 50, params::point_map(CGAL::Nth_of_tuple_property_map<0, Identified>())
                   .normal_map(CGAL::Nth_of_tuple_property_map<1, Identified>()));
  for(std::size_t i = 0; i < points.size(); ++i)
    REQUIRE(std::get<1>(with[i]) == std::get<1>(without[i]));
  // On the faces, where the quadric is kept, most of the triples that
  // measure its confidence lie near it; near the edges, the votes scatter.
  double faces = 0, edges = 0;
  std::size_t on_faces = 0, near_edges = 0;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const double confidence = std::get<4>(with[i]);
    REQUIRE(confidence >= 0);
    REQUIRE(confidence <= 1);
    const SC::Point_3& p = points[i];
    double a[3] = { std::abs(p.x()), std::abs(p.y()), std::abs(p.z()) };
    std::sort(a, a + 3);
    const double to_edge = 1 - a[1]; // a[2] is about 1, on the face
    if(to_edge > 0.3)
      faces += confidence, ++on_faces;
    else if(to_edge < 0.05)
      edges += confidence, ++near_edges;
  }
  REQUIRE(on_faces > 100);
  REQUIRE(near_edges > 100);
  INFO("mean confidence " << faces / on_faces << " on the faces, " << edges / near_edges << " near the edges");
  CHECK(faces / on_faces > 2 * edges / near_edges);
}
