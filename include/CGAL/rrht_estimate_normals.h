// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Normal estimation with the Robust Randomized Hough Transform of
// A. Boulch and R. Marlet, "Fast and Robust Normal Estimation for Point
// Clouds with Sharp Features", Computer Graphics Forum 31(5), 2012.

#ifndef CGAL_RRHT_ESTIMATE_NORMALS_H
#define CGAL_RRHT_ESTIMATE_NORMALS_H

#include <CGAL/RRHT/parameters.h>
#include <CGAL/RRHT/Neighbor_search.h>
#include <CGAL/RRHT/Accumulator.h>
#include <CGAL/RRHT/Instruction_set.h>
#include <CGAL/RRHT/Plane_batch.h>
#include <CGAL/RRHT/stopping_rules.h>
#include <CGAL/RRHT/Sampling.h>
#include <CGAL/RRHT/aggregation.h>
#include <CGAL/RRHT/Random.h>

#include <CGAL/assertions.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/property_map.h>
#include <CGAL/tags.h>

#include <Eigen/Core>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
template <typename Point, typename Vector> class Point_set_3;

namespace RRHT {
/// \cond SKIP_IN_MANUAL
namespace internal {

/// The parameters of the algorithm (paper, Section 6), once checked.
struct Settings
{
  unsigned int k;                 // K, or the cap on a ball
  double neighbor_radius;         // r, or 0 for k-neighborhoods
  std::size_t number_of_planes;   // T_R
  bool use_confidence_interval;   // eq. 10
  Sampling sampling;              // Points, Cubes or Unif
  unsigned int presampling_factor;// c
  unsigned int number_of_rotations; // n_rot
  Aggregation aggregation;        // m, b or c
  double cos_cluster_angle;       // cos(a_cluster)
  std::uint64_t seed;
};

/// The working memory of one thread, reused from point to point.
struct Scratch
{
  Scratch(const Bin_layout& layout, const Cube_weights& cube_weights, unsigned int presampling_factor)
    : accumulator(layout), cubes(cube_weights), unif(presampling_factor), triples(Plane_batch::capacity)
  {}

  Neighbor_search::Scratch search;
  Neighborhood neighborhood;
  std::vector<Eigen::Vector3f> rotated; // the neighborhood rotated, over its radius, in single precision
  Accumulator accumulator;
  Points_sampler points;
  Cubes_sampler cubes;
  Unif_sampler unif;
  std::vector<Triple> triples; // a batch of draws
  Plane_batch planes;          // and their planes
  std::vector<Candidate_normal> candidates;
};

/// One run of the Robust Randomized Hough Transform (Section 3): draws planes
/// through triples of `points` until T_R triples have been drawn (eq. 7) or
/// the confidence intervals of the two most voted bins separate (eq. 10), and
/// returns the mean normal of the most voted bin (Section 4). Triples of
/// (nearly) collinear or repeated points define no plane and cast no vote;
/// the paper does not check near-collinearity (Section 2), we only leave out
/// triples whose two edges make an angle below 1e-5 radians, which would
/// give no direction in single precision (see `Plane_batch`).
///
/// Triples are drawn, and their planes computed (`Plane_batch`), in
/// batches; they vote one by one, and eq. 10 is tested after each vote at
/// which it can hold (see `Accumulator`), so the run stops at the same vote
/// as when drawing one triple at a time. A batch is half the votes so far
/// plus 8 (at most `Plane_batch::capacity`, which it is without eq. 10): a run of 300 planes that does not stop early takes 9 batches
/// rather than 20, and a run that stops wastes at most that many planes,
/// drawn and not voted.
template <typename Sampler>
Candidate_normal hough_transform(const std::vector<Eigen::Vector3f>& points, Sampler& sampler, Random& rng,
                                 const Settings& settings, Scratch& scratch)
{
  Accumulator& accumulator = scratch.accumulator;
  accumulator.clear();
  sampler.start_run();
  std::size_t drawn = 0;
  bool stop = false;
  while(!stop && drawn < settings.number_of_planes)
  {
    const std::size_t batch =
      settings.use_confidence_interval ? accumulator.number_of_votes() / 2 + 8 : scratch.triples.size();
    const std::size_t wanted = (std::min)({ settings.number_of_planes - drawn, scratch.triples.size(), batch });
    const std::size_t got = sampler.draw(rng, wanted, scratch.triples.data());
    scratch.planes.compute(points, scratch.triples.data(), got, accumulator.layout());
    accumulator.vote(scratch.planes, got, [&](unsigned int first, unsigned int second, std::size_t votes) {
      return stop = settings.use_confidence_interval && confidence_intervals_are_disjoint(first, second, votes);
    });
    drawn += got;
    stop |= (got < wanted); // every triple of the neighborhood has voted
  }
  return Candidate_normal{ accumulator.normal_of_most_voted_bin(), accumulator.votes_of_most_voted_bin() };
}

/// `points` multiplied by `matrix`, in single precision, into `out` (of the
/// same size). Each coordinate is (m_i0 x + m_i1 y) + m_i2 z in double
/// precision, as Eigen's product computes it (the same floats: tested), and
/// the same bits with the loop of each instruction set (`Instruction_set.h`).
/// For AVX2 the loop is vectorized over 4 points. It runs for every
/// accumulator; as an Eigen product per point it took 3 to 4% of the
/// instructions at the fast setting.
inline void rotate(const std::vector<Eigen::Vector3d>& points, const Eigen::Matrix3d& matrix,
                   std::vector<Eigen::Vector3f>& out, Instruction_set instruction_set)
{
  CGAL_precondition(out.size() == points.size());
  // The coordinates of the points one after the other (Eigen's fixed-size
  // vectors hold their coefficients and nothing else).
  const Eigen::Map<const Eigen::Matrix3Xd> in(points.data()->data(), 3, Eigen::Index(points.size()));
  Eigen::Map<Eigen::Matrix3Xf> rotated(out.data()->data(), 3, Eigen::Index(out.size()));
  const double m00 = matrix(0, 0), m01 = matrix(0, 1), m02 = matrix(0, 2), m10 = matrix(1, 0), m11 = matrix(1, 1),
               m12 = matrix(1, 2), m20 = matrix(2, 0), m21 = matrix(2, 1), m22 = matrix(2, 2);
  run_with(instruction_set, [&] {
    for(Eigen::Index i = 0; i < in.cols(); ++i)
    {
      const double x = in(0, i), y = in(1, i), z = in(2, i);
      rotated(0, i) = float(m00 * x + m01 * y + m02 * z);
      rotated(1, i) = float(m10 * x + m11 * y + m12 * z);
      rotated(2, i) = float(m20 * x + m21 * y + m22 * z);
    }
  });
}

/// The normal of a neighborhood from n_rot randomly rotated accumulators
/// (Section 4): each run sees the points rotated, its normal is rotated back,
/// and the normals are aggregated.
template <typename Sampler>
Eigen::Vector3d rotated_hough_transforms(const Neighborhood& neighborhood, Sampler& sampler, Random& rng,
                                         const Settings& settings, Scratch& scratch)
{
  const std::vector<Eigen::Vector3d>& points = neighborhood.points;
  scratch.candidates.clear();
  scratch.rotated.resize(points.size());
  for(unsigned int r = 0; r < settings.number_of_rotations; ++r)
  {
    // Rotated and scaled to the unit ball: normals do not depend on the
    // scale, and single precision keeps its relative accuracy.
    const Eigen::Matrix3d rotation = rng.uniform_rotation();
    rotate(points, rotation / neighborhood.radius, scratch.rotated, best_instruction_set());
    Candidate_normal candidate = hough_transform(scratch.rotated, sampler, rng, settings, scratch);
    candidate.normal = rotation.transpose() * candidate.normal; // back to the frame of the cloud
    scratch.candidates.push_back(candidate);
  }
  return aggregate(scratch.candidates, settings.aggregation, settings.cos_cluster_angle);
}

/// The normal at the point at `position` in the search's order, the
/// `input_index`-th of the input (Section 2): draws plane hypotheses in its
/// neighborhood with n_rot randomly rotated accumulators and combines their
/// winners. Returns the zero vector when no plane can be formed.
inline Eigen::Vector3d estimate_normal(std::size_t position, std::size_t input_index, const Neighbor_search& search,
                                       const Settings& settings, Scratch& scratch)
{
  Neighborhood& neighborhood = scratch.neighborhood;
  search.find(position, settings.k, settings.neighbor_radius, neighborhood, scratch.search);
  const std::vector<Eigen::Vector3d>& points = neighborhood.points;
  // Fewer than 3 distinct points, or a ball so small (a `neighbor_radius`
  // below 1e-300) that the points cannot be scaled to the unit ball, nor to
  // the grids of RRHT_Cubes and RRHT_Unif, without overflow.
  if(points.size() < 3 || !(neighborhood.radius >= 1e-300))
    return Eigen::Vector3d::Zero();

  // One random stream per point: the same normals whatever the threads.
  Random rng(settings.seed, input_index);

  switch(settings.sampling)
  {
  case Sampling::CUBES:
    scratch.cubes.prepare(points, neighborhood.radius);
    return rotated_hough_transforms(neighborhood, scratch.cubes, rng, settings, scratch);
  case Sampling::UNIF:
    scratch.unif.prepare(points, neighborhood.radius, rng);
    return rotated_hough_transforms(neighborhood, scratch.unif, rng, settings, scratch);
  case Sampling::POINTS:
  default:
    scratch.points.prepare(std::uint32_t(points.size()), settings.number_of_planes);
    return rotated_hough_transforms(neighborhood, scratch.points, rng, settings, scratch);
  }
}

/// Progress report and interruption through the user's callback, called
/// after every block of points: directly in a sequential run; in a parallel
/// run by the thread that finishes a block, one thread at a time (a thread
/// that finds the callback busy does not wait for it).
class Progress
{
public:
  Progress(const std::function<bool(double)>& callback, std::size_t total)
    : m_callback(callback), m_total(total), m_done(0), m_busy(false), m_interrupted(false)
  {}

  bool interrupted() const { return m_interrupted.load(std::memory_order_relaxed); }

  void add(std::size_t done)
  {
    const std::size_t now = m_done.fetch_add(done) + done;
    if(!m_callback || m_busy.exchange(true))
      return;
    if(!m_callback(double(now) / double(m_total)))
      m_interrupted = true;
    m_busy = false;
  }

  void finish()
  {
    if(m_callback && !interrupted())
      m_callback(1.);
  }

private:
  const std::function<bool(double)>& m_callback;
  std::size_t m_total;
  std::atomic<std::size_t> m_done;
  std::atomic<bool> m_busy;
  std::atomic<bool> m_interrupted;
};

/// The iterator to the element at a position of the input range: kept in a
/// table, unless the iterators are random access.
template <typename Iterator,
          bool random_access = std::is_convertible<typename std::iterator_traits<Iterator>::iterator_category,
                                                   std::random_access_iterator_tag>::value>
class Elements
{
public:
  void add(Iterator it) { m_iterators.push_back(it); }
  Iterator at(Iterator, std::size_t position) const { return m_iterators[position]; }

private:
  std::vector<Iterator> m_iterators;
};

template <typename Iterator>
class Elements<Iterator, true>
{
public:
  void add(Iterator) {}
  Iterator at(Iterator begin, std::size_t position) const { return begin + position; }
};

/// Calls `process(begin, end, scratch)` on blocks of at most 64 consecutive
/// positions of [0, `size`), with one `scratch = make_scratch()` per thread:
/// over TBB's threads with `Parallel_tag`, in order otherwise. Reports each
/// block to `progress` and stops starting blocks once it is interrupted.
template <typename ConcurrencyTag, typename MakeScratch, typename Process>
void for_each_block(std::size_t size, Progress& progress, MakeScratch make_scratch, Process process)
{
  const std::size_t block = 64;
#ifdef CGAL_LINKED_WITH_TBB
  if(std::is_convertible<ConcurrencyTag, Parallel_tag>::value)
  {
    typedef decltype(make_scratch()) Scratch_type;
    tbb::enumerable_thread_specific<Scratch_type> scratches(make_scratch);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, size, block),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                        if(progress.interrupted())
                          return;
                        process(range.begin(), range.end(), scratches.local());
                        progress.add(range.size());
                      });
    return;
  }
#endif
  auto scratch = make_scratch();
  for(std::size_t begin = 0; begin < size && !progress.interrupted(); begin += block)
  {
    const std::size_t end = (std::min)(size, begin + block);
    process(begin, end, scratch);
    progress.add(end - begin);
  }
}

inline void check(bool condition, const std::string& message)
{
  if(!condition)
    throw std::invalid_argument("CGAL::rrht_estimate_normals(): " + message);
}

/// A count given as any arithmetic type, checked to lie in [low, high]
/// before it is converted (so that -1 is not taken for a huge unsigned).
/// The bounds are far below 2^53, so the comparison in double is exact.
template <typename Count, typename T>
Count count_in_range(const T& value, std::uint64_t low, std::uint64_t high, const std::string& what)
{
  static_assert(std::is_arithmetic<T>::value, "a count must be given as a number");
  const double as_double = static_cast<double>(value);
  check(as_double >= double(low) && as_double <= double(high), // false for NaN
        what + " must be from " + std::to_string(low) + " to " + std::to_string(high));
  return static_cast<Count>(value);
}

/// Whether normals can be written: a range needs a `normal_map` (checked at
/// compile time, as \cgal does); a `CGAL::Point_set_3` may use its own normal
/// map, if it has one (checked at run time, the same on every \cgal version).
template <typename PointRange, typename NamedParameters>
bool has_normal_map(const PointRange&, const NamedParameters&)
{
  static_assert(!CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value,
                "CGAL::rrht_estimate_normals(): no normal map");
  return true;
}

template <typename Point, typename Vector, typename NamedParameters>
bool has_normal_map(const Point_set_3<Point, Vector>& points, const NamedParameters&)
{
  return !CGAL::parameters::is_default_parameter<NamedParameters, CGAL::internal_np::normal_t>::value ||
         points.has_normal_map();
}

} // namespace internal
/// \endcond
} // namespace RRHT

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

   The output normals are unit vectors, randomly oriented (use
   `CGAL::mst_orient_normals()` to orient them). Where no plane can be formed
   (fewer than 3 distinct points in the neighborhood, all of them collinear,
   a `neighbor_radius` below 1e-300, or a point with a non-finite
   coordinate), the normal is the null vector
   `CGAL::NULL_VECTOR`. Points with a non-finite coordinate are not
   neighbors of any point.

   The result depends only on the input, the parameters and `random_seed`:
   it is the same, bit for bit, with `Sequential_tag` and `Parallel_tag` and
   any number of threads.

   \tparam ConcurrencyTag enables sequential versus parallel algorithm. Possible values are `Sequential_tag`,
                          `Parallel_tag`, and `Parallel_if_available_tag`.
   \tparam PointRange is a model of `Range`. The value type of
   its iterator is the key type of the named parameter `point_map`.

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

     \cgalParamNBegin{neighbor_radius}
       \cgalParamDescription{the spherical neighborhood radius}
       \cgalParamType{floating scalar value}
       \cgalParamDefault{`0` (no limit)}
       \cgalParamExtra{If provided, the neighborhood of a point is the set of points within this distance,
                       the point included. If `k` is not 0 and the ball holds more than `k` other points,
                       only the `k` nearest are kept, so that no part of the ball is favored. A ball with
                       fewer than 3 points is replaced by the point and its `k` nearest neighbors (3 if `k` is 0).}
     \cgalParamNEnd

     \cgalParamNBegin{callback}
       \cgalParamDescription{a mechanism to get feedback on the advancement of the algorithm
                             while it's running and to interrupt it if needed}
       \cgalParamType{an instance of `std::function<bool(double)>`.}
       \cgalParamDefault{unused}
       \cgalParamExtra{It is called after every block of 64 points with the current advancement (between 0. and
                       1.), and with 1. at the end. If it returns `true`, then the
                       algorithm continues its execution normally; if it returns
                       `false`, the algorithm is stopped and the remaining normals are left unchanged.}
       \cgalParamExtra{The callback will be copied and therefore needs to be lightweight.}
       \cgalParamExtra{When `CGAL::Parallel_tag` is used, the `callback` is called from the worker threads,
                       one at a time, and shouldn't access or modify the variables that are parameters of the algorithm.}
     \cgalParamNEnd

     \cgalParamNBegin{random_seed}
       \cgalParamDescription{the seed of the random draws}
       \cgalParamType{unsigned int}
       \cgalParamDefault{`0`}
       \cgalParamExtra{Each point draws from its own random stream, derived from the seed and its position in `points`.}
     \cgalParamNEnd

     \cgalParamNBegin{geom_traits}
       \cgalParamDescription{an instance of a geometric traits class}
       \cgalParamType{a model of `Kernel`}
       \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
     \cgalParamNEnd

     \cgalParamNBegin{number_of_planes}
       \cgalParamDescription{T_R, the largest number of triples drawn per rotated accumulator (paper, eq. 7)}
       \cgalParamType{an integer from 1 to 100 000 000}
       \cgalParamDefault{the Hoeffding bound of eq. 7 with alpha = 0.95, delta = 0.08 and the number M of bins
                         of the accumulator, `CGAL::RRHT::hoeffding_number_of_planes(M)`: 691 for 15 slices}
       \cgalParamExtra{With `CGAL::RRHT::Sampling::POINTS`, a neighborhood with fewer triples has each of them drawn once.}
     \cgalParamNEnd

     \cgalParamNBegin{accumulator_slices}
       \cgalParamDescription{n_phi, the number of slices of the sphere in the accumulator (paper, Section 3)}
       \cgalParamType{an integer from 1 to 1000}
       \cgalParamDefault{`15` (172 bins on the half sphere, see `CGAL::RRHT::Bin_layout`)}
     \cgalParamNEnd

     \cgalParamNBegin{number_of_rotations}
       \cgalParamDescription{n_rot, the number of randomly rotated accumulators (paper, Section 4)}
       \cgalParamType{an integer from 1 to 100 000}
       \cgalParamDefault{`5`}
     \cgalParamNEnd

     \cgalParamNBegin{use_confidence_interval}
       \cgalParamDescription{whether to stop drawing as soon as the 95% confidence intervals of the two most
                             voted bins are disjoint (paper, eq. 10)}
       \cgalParamType{bool}
       \cgalParamDefault{`true`}
     \cgalParamNEnd

     \cgalParamNBegin{sampling}
       \cgalParamDescription{how triples of points are drawn (paper, Section 5)}
       \cgalParamType{`CGAL::RRHT::Sampling`: `POINTS` (RRHT_Points), `CUBES` (RRHT_Cubes) or `UNIF` (RRHT_Unif)}
       \cgalParamDefault{`CGAL::RRHT::Sampling::POINTS`}
       \cgalParamExtra{`CUBES` and `UNIF` draw points spatially uniformly in the neighborhood ball: the ball of
                       `neighbor_radius`, or, for a k-neighborhood or a capped ball, the ball through the farthest
                       neighbor kept. They resist density variations (anisotropy) at some cost in time.}
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

   \throws std::invalid_argument if `k` is 0 without a positive `neighbor_radius`, or if a parameter is out
           of the range given above (a negative or non-finite radius, 0 planes, 0 rotations, 0 slices...).
   Nothing is written then. An empty range is left as it is.
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

#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!(std::is_convertible<ConcurrencyTag, Parallel_tag>::value),
                "Parallel_tag is enabled but TBB is unavailable.");
#endif
  RRHT::internal::check(RRHT::internal::has_normal_map(points, np),
                        "the point set has no normal map: call add_normal_map() first, or pass a normal_map");

  Point_map point_map = NP_helper::get_point_map(points, np);
  Normal_map normal_map = NP_helper::get_normal_map(points, np);
  const std::function<bool(double)> callback =
    choose_parameter(get_parameter(np, internal_np::callback), std::function<bool(double)>());

  // The parameters (paper, Section 6), checked before anything is written.
  using RRHT::internal::check;
  const double neighbor_radius = CGAL::to_double(choose_parameter(get_parameter(np, internal_np::neighbor_radius), FT(0)));
  check(std::isfinite(neighbor_radius) && neighbor_radius >= 0, "neighbor_radius must be finite and non-negative");
  check(k > 0 || neighbor_radius > 0, "k must be at least 1 when no neighbor_radius is given");
  const unsigned int accumulator_slices = RRHT::internal::count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::accumulator_slices), 15u), 1, 1000, "accumulator_slices (n_phi)");
  const RRHT::Bin_layout layout(accumulator_slices);

  RRHT::internal::Settings settings;
  settings.k = k;
  settings.neighbor_radius = neighbor_radius;
  settings.number_of_planes = RRHT::internal::count_in_range<std::size_t>(
    choose_parameter(get_parameter(np, rrht_np::number_of_planes), RRHT::hoeffding_number_of_planes(layout.size())),
    1, 100000000, "number_of_planes (T_R)");
  settings.use_confidence_interval = choose_parameter(get_parameter(np, rrht_np::use_confidence_interval), true);
  settings.sampling = choose_parameter(get_parameter(np, rrht_np::sampling), RRHT::Sampling::POINTS);
  check(settings.sampling == RRHT::Sampling::POINTS || settings.sampling == RRHT::Sampling::CUBES ||
        settings.sampling == RRHT::Sampling::UNIF, "unknown sampling");
  settings.presampling_factor = RRHT::internal::count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::presampling_factor), 4u), 1, 32, "presampling_factor (c)");
  settings.number_of_rotations = RRHT::internal::count_in_range<unsigned int>(
    choose_parameter(get_parameter(np, rrht_np::number_of_rotations), 5u), 1, 100000, "number_of_rotations (n_rot)");
  settings.aggregation = choose_parameter(get_parameter(np, rrht_np::aggregation), RRHT::Aggregation::CLUSTER);
  check(settings.aggregation == RRHT::Aggregation::MEAN || settings.aggregation == RRHT::Aggregation::BEST ||
        settings.aggregation == RRHT::Aggregation::CLUSTER, "unknown aggregation");
  const double cluster_angle = choose_parameter(get_parameter(np, rrht_np::cluster_angle), 45.);
  check(cluster_angle >= 0 && cluster_angle <= 180, "cluster_angle must be from 0 to 180 degrees");
  settings.cos_cluster_angle = std::cos(cluster_angle * 3.14159265358979323846 / 180.);
  settings.seed = choose_parameter(get_parameter(np, internal_np::random_seed), 0u);

  // The finite points of the cloud in double precision, in one kd-tree along
  // a Hilbert curve. The others get the null vector.
  RRHT::internal::Elements<typename PointRange::iterator> elements;
  std::vector<RRHT::Neighbor_search::Indexed_point> cloud;
  std::size_t position = 0;
  for(auto it = points.begin(); it != points.end(); ++it, ++position)
  {
    const auto& p = get(point_map, *it);
    const RRHT::Neighbor_search::Point q(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    elements.add(it);
    if(RRHT::has_finite_coordinates(q))
      cloud.emplace_back(q, position);
    else
      put(normal_map, *it, CGAL::NULL_VECTOR);
  }
  if(cloud.empty())
    return;
  const RRHT::Neighbor_search search(std::move(cloud), ConcurrencyTag());
  const std::size_t size = search.size();
  settings.k = static_cast<unsigned int>((std::min<std::size_t>)(k, size - 1));
  const RRHT::Cube_weights cube_weights(settings.sampling == RRHT::Sampling::CUBES ? settings.presampling_factor : 1);

  // Points are processed along the Hilbert curve, each with the random
  // stream of its position in the input.
  auto process = [&](std::size_t begin, std::size_t end, RRHT::internal::Scratch& scratch) {
    for(std::size_t i = begin; i < end; ++i)
    {
      const std::size_t input_index = search.input_index(i);
      const Eigen::Vector3d n = RRHT::internal::estimate_normal(i, input_index, search, settings, scratch);
      put(normal_map, *elements.at(points.begin(), input_index), Vector_3(FT(n.x()), FT(n.y()), FT(n.z())));
    }
  };

  RRHT::internal::Progress progress(callback, size);
  RRHT::internal::for_each_block<ConcurrencyTag>(
    size, progress, [&]() { return RRHT::internal::Scratch(layout, cube_weights, settings.presampling_factor); },
    process);
  progress.finish();
}

} // namespace CGAL

#endif // CGAL_RRHT_ESTIMATE_NORMALS_H
