// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Least squares first (beyond the paper): the normal of jet fitting's
// quadric where the neighborhood, or on a thin part the point's own side of
// it, is one smooth sheet within the noise, the Hough transform only
// elsewhere. On a smooth sheet, a least-squares fit on
// all the neighbors is more accurate than votes of triples in a quantized
// accumulator, and much cheaper; near a sharp feature it smooths the normal,
// and the residuals of the quadric exceed the noise of the scan.

#ifndef CGAL_RRHT_INTERNAL_LEAST_SQUARES_FIRST_H
#define CGAL_RRHT_INTERNAL_LEAST_SQUARES_FIRST_H

#include <CGAL/RRHT/internal/Neighbor_search.h>
#include <CGAL/RRHT/internal/Packed_direction.h>
#include <CGAL/RRHT/internal/Pass_context.h>
#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/Random.h>
#include <CGAL/RRHT/internal/Scratch.h>
#include <CGAL/RRHT/internal/Settings.h>
#include <CGAL/RRHT/internal/adaptive.h>
#include <CGAL/RRHT/internal/confidence.h>
#include <CGAL/RRHT/internal/estimate_normal.h>
#include <CGAL/RRHT/internal/neighbor_planes.h>
#include <CGAL/RRHT/internal/neighborhood_passes.h>
#include <CGAL/RRHT/internal/refit_normal.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <boost/sort/pdqsort/pdqsort.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The tests of the least-squares-first estimation, chosen on the
/// benchmark's clouds (the design notes, "Beyond the paper, in detail").
struct Least_squares_first_thresholds
{
  /// The first quartile of the noise deviations estimated at the n
  /// neighbors, squared, times 1 + `scatter` / (n - 6), bounds the noise
  /// variance of one smooth sheet: the quartile of a few noisy estimates
  /// lies below their mean, and the mean square of the residuals, with
  /// n - 6 degrees of freedom, scatters about the variance, both as
  /// 1 / (n - 6). Tuned at k = 100 on the sharp shapes, and at k = 12 and 18
  /// on smooth ones.
  static constexpr double scatter = 65.5;
  /// A quadric is kept where the mean square of its residuals exceeds the
  /// noise variance by at most the square of this share of the radius.
  static constexpr double excess = 0.03;
  /// ... and where at most `most_rejected` of the nearest `dilation` share
  /// of its neighbors are rejected: next to a sharp feature, the quadric of
  /// a neighborhood that only grazes it is accepted, but turned.
  static constexpr double dilation = 0.6;
  static constexpr double most_rejected = 0.15;
  /// Where a kept quadric's neighborhood holds a rejected point and its
  /// normal is more than 5 degrees (this cosine) from the Hough transform's
  /// first stage, the quadric of the nearest `referee` share of the
  /// neighbors tells which of the two to take, if that share holds at least
  /// `referee_min` points: with fewer, with noise, the referee and the
  /// Hough transform are both too scattered to overrule the quadric.
  static constexpr double cos_turn = 0.99619469809174553;
  /// Where the referee is within 2.45 degrees (this cosine) of the quadric,
  /// just under half of those 5, no normal more than 5 degrees from the
  /// quadric can be nearer to the referee: the quadric stays.
  static constexpr double cos_contest = 0.99908590626404760;
  static constexpr double referee = 0.3;
  static constexpr std::size_t referee_min = 24;
  /// A neighborhood holds a second sheet (the other side of a thin part)
  /// where its offsets from the tangent plane split in two groups whose
  /// means are more than `sheets_apart` times the spread within the groups
  /// apart: the two halves of one noisy sheet are about 2.7 apart.
  static constexpr double sheets_apart = 3.5;
  /// ... in a neighborhood of at least `least_for_sheets` points: in fewer,
  /// the few points of another face across an edge pass for a sheet.
  static constexpr std::size_t least_for_sheets = 40;
  /// Where the noise deviation of a quadric's residuals exceeds their root
  /// mean square `bimodal` times, they are bimodal: the two sides of a thin
  /// part, about the quadric between them. For one noisy sheet the two are
  /// equal, within 1.5 at 100 neighbors; near an edge, the noise is less.
  static constexpr double bimodal = 1.5;
  /// Where a quadric's normal is more than `near_turn` degrees from the
  /// principal normal of the nearest `near_share` of the neighbors, which
  /// lie on the point's side, the other side may have tilted the principal
  /// axes: a ball about as deep as wide, whose residuals about the tilted
  /// quadric are not bimodal.
  static constexpr double near_share = 0.25;
  static constexpr double near_turn = 10;
  /// Where those nearest neighbors already reach the next sheet of a stack
  /// (fins as far apart as half the radius), the `stack_nearest` nearest
  /// do not: along their normal, the point's own sheet is the run of
  /// offsets unbroken by a gap of `stack_gap` times the radius, if it
  /// leaves out at least `stacked_others` of the neighbors
  /// (`own_stacked_sheet()`). Where fewer points sample the fins, the
  /// `stack_fewest` nearest are tried next: the fewest that still span a
  /// plane with some room for noise.
  static constexpr std::size_t stack_nearest = 10;
  static constexpr std::size_t stack_fewest = 6;
  static constexpr double stack_gap = 0.1;
  static constexpr double stacked_others = 0.1;
  /// The confidence of a normal kept without a vote (a quadric that no
  /// rejected neighbor contests, a neighbor plane that holds most of the
  /// neighborhood) is measured on `confidence_planes` triples
  /// (`confidence_of_kept_normal()`): it only has to rank the normal among
  /// the others, and these are most of the points. Their share within a cap
  /// of `confidence_cap` bins' solid angle about the normal ranks the errors
  /// as well as the most voted bin's share of a vote of as many triples
  /// (one bin: less well on the noisy corner and gear).
  static constexpr std::size_t confidence_planes = 50;
  static constexpr double confidence_cap = 2;
};

/// Jet fitting's quadric at a point: its normal, and its residuals' root
/// mean square and noise deviation (lengths), or infinite ones and the null
/// vector where it cannot be fitted.
struct Quadric_fit
{
  Eigen::Vector3d normal;
  double rms;
  double noise;
};

/// Fits the quadric height field of all the neighbors `points` (relative to
/// the point, within `radius`) in the frame of their principal axes, as
/// jet fitting does. The residuals' root mean square and noise deviation
/// (`noise_of_residuals()`) are both scaled by n / (n - 6), the degrees of
/// freedom that the 6 coefficients take, so that they keep their meaning
/// with few neighbors. A neighborhood of at most 6 points, or whose points
/// are collinear, has no quadric.
inline Quadric_fit fit_quadric(const std::vector<Eigen::Vector3d>& points, double radius, Refit_scratch& scratch)
{
  const double infinity = std::numeric_limits<double>::infinity();
  const Quadric_fit none{ Eigen::Vector3d::Zero(), infinity, infinity };
  const std::size_t size = points.size();
  if(size <= 6 || !has_computable_radius(radius))
    return none;
  const Principal_axes principal = principal_axes(points, [](std::size_t) { return true; });
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>& axes = principal.axes;
  // Eigenvalues are sorted increasingly: a line has a single large one.
  if(!(axes.eigenvalues()[1] > 1e-12 * axes.eigenvalues()[2]))
    return none;
  const Eigen::Vector3d axis = axes.eigenvectors().col(0);
  const Eigen::Vector3d u = axis.unitOrthogonal(), v = axis.cross(u);
  to_frame(points, radius, axis, u, v, scratch.local);
  const std::vector<Eigen::Vector3d>& local = scratch.local;
  Eigen::Matrix<double, 6, 1> quadric;
  if(!fit_quadric_height_field(local, [](std::size_t) { return true; }, quadric))
    return none;
  std::vector<double>& residuals = scratch.residuals;
  residuals.resize(size);
  double squares = 0;
  for(std::size_t i = 0; i < size; ++i)
  {
    residuals[i] = local[i].z() - quadric_height(quadric, local[i]);
    squares += residuals[i] * residuals[i];
  }
  const double freedom = double(size - 6);
  const Eigen::Vector3d normal = (axis - quadric[1] * u - quadric[2] * v).normalized();
  if(!normal.allFinite())
    return none;
  return Quadric_fit{ normal, radius * std::sqrt(squares / freedom),
                      radius * noise_of_residuals(residuals, scratch.work) * std::sqrt(double(size) / freedom) };
}

/// The offsets of the neighbors `points` (relative to the point) along
/// `normal`, sorted, in `offsets`. Boost's branchless pdqsort: most points
/// sort their offsets along a few directions, and the sorted values do not
/// depend on the algorithm.
inline void sorted_offsets(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                           std::vector<double>& offsets)
{
  offsets.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i)
    offsets[i] = normal.dot(points[i]);
  boost::sort::pdqsort_branchless(offsets.begin(), offsets.end());
}

/// The mean of `offsets` [first, last) and their standard deviation (0 for
/// a single one).
inline std::pair<double, double> mean_and_spread(const std::vector<double>& offsets, std::size_t first, std::size_t last)
{
  double s = 0, q = 0;
  for(std::size_t i = first; i < last; ++i)
    s += offsets[i], q += offsets[i] * offsets[i];
  const double n = double(last - first), mean = s / n;
  return std::make_pair(mean, n > 1 ? std::sqrt((std::max)(0., q - s * mean) / (n - 1)) : 0.);
}

/// The neighbors `points` (relative to the point) on the point's own sheet,
/// in `own`, where they hold a second sheet along `normal`
/// (`Least_squares_first_thresholds::sheets_apart`), found by the split of
/// their offsets in two groups of least squared deviation from their means
/// (`split_in_two()`); false where they hold one sheet. A group may be a
/// single point: the other side of a thin part may just touch the ball.
inline bool own_sheet(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                      std::vector<Eigen::Vector3d>& own, std::vector<double>& offsets)
{
  const std::size_t size = points.size();
  if(size < Least_squares_first_thresholds::least_for_sheets)
    return false;
  sorted_offsets(points, normal, offsets);
  const std::size_t at = split_in_two(offsets);
  // Each group is a sheet: both spreads, not only their pool, are small
  // beside the gap, unlike the strip of another face across an edge.
  const std::pair<double, double> low = mean_and_spread(offsets, 0, at), high = mean_and_spread(offsets, at, size);
  if(!(high.first - low.first > Least_squares_first_thresholds::sheets_apart * (std::max)(low.second, high.second)))
    return false;
  const double split = 0.5 * (offsets[at - 1] + offsets[at]);
  own.clear();
  for(const Eigen::Vector3d& p : points)
    if((normal.dot(p) > split) == (0 > split))
      own.push_back(p);
  return true;
}

/// The run [first, last) of the sorted, nonempty `offsets` about the
/// point's, 0 (from the least nonnegative offset, or the greatest if none
/// is), unbroken by a gap wider than `gap`.
inline std::pair<std::size_t, std::size_t> run_about_point(const std::vector<double>& offsets, double gap)
{
  const std::size_t size = offsets.size();
  std::size_t first =
    (std::min)(std::size_t(std::lower_bound(offsets.begin(), offsets.end(), 0.) - offsets.begin()), size - 1);
  std::size_t last = first + 1;
  while(first > 0 && offsets[first] - offsets[first - 1] <= gap)
    --first;
  while(last < size && offsets[last] - offsets[last - 1] <= gap)
    ++last;
  return std::make_pair(first, last);
}

/// Whether the run of the offsets of the neighbors `points` (relative to the
/// point, within `radius`) along `normal` about the point's, unbroken by a
/// gap of `Least_squares_first_thresholds::stack_gap` times the radius
/// (`own_stacked_sheet()`), surely leaves out fewer than `stacked_others` of
/// them, found without sorting: offsets in bins next to each other, a
/// little narrower than half the gap, are within the gap of each other, so
/// the run holds at least the chain of nonempty bins about the point's. On
/// one noisy sheet, that chain is nearly all the neighbors.
inline bool run_holds_nearly_all(const std::vector<Eigen::Vector3d>& points, double radius,
                                 const Eigen::Vector3d& normal)
{
  typedef Least_squares_first_thresholds T;
  const double width = 0.49 * T::stack_gap * radius;
  if(!(width > 0))
    return false;
  // Bins [b, b + 1) of offsets over the width, from -half to half; the run
  // starts at the least nonnegative offset, or the greatest if none is.
  constexpr int half = 32;
  std::array<std::uint32_t, 2 * half> count{};
  double start = std::numeric_limits<double>::infinity(), greatest = -start;
  for(const Eigen::Vector3d& p : points)
  {
    const double o = normal.dot(p) / width, bin = std::floor(o);
    if(bin >= -half && bin < half)
      ++count[std::size_t(int(bin) + half)];
    if(o >= 0 && o < start)
      start = o;
    greatest = (std::max)(greatest, o);
  }
  const double first = std::floor(std::isfinite(start) ? start : greatest);
  if(!(first >= -half && first < half))
    return false;
  const int from = int(first) + half;
  std::size_t chain = 0;
  for(int b = from; b < 2 * half && count[std::size_t(b)] != 0; ++b)
    chain += count[std::size_t(b)];
  for(int b = from - 1; b >= 0 && count[std::size_t(b)] != 0; --b)
    chain += count[std::size_t(b)];
  return double(points.size() - chain) < T::stacked_others * double(points.size());
}

/// The neighbors `points` (relative to the point, within `radius`) on the
/// point's own sheet, in `own`, where they hold a stack of parallel sheets
/// normal to `normal` (fins, or the walls of narrow slots) that two groups
/// cannot describe: the run of their offsets about the point's, 0,
/// unbroken by a gap of `stack_gap` times the radius, and set apart from
/// the rest by more than `sheets_apart` times its spread. False where no
/// such run leaves out another sheet.
inline bool own_stacked_sheet(const std::vector<Eigen::Vector3d>& points, double radius, const Eigen::Vector3d& normal,
                              std::vector<Eigen::Vector3d>& own, std::vector<double>& offsets)
{
  typedef Least_squares_first_thresholds T;
  const std::size_t size = points.size();
  if(size < T::least_for_sheets || run_holds_nearly_all(points, radius, normal))
    return false;
  sorted_offsets(points, normal, offsets);
  const std::pair<std::size_t, std::size_t> about = run_about_point(offsets, T::stack_gap * radius);
  const std::size_t first = about.first, last = about.second, run = last - first;
  if(run < T::least_for_sheets / 2 || double(size - run) < T::stacked_others * double(size))
    return false;
  const double spread = mean_and_spread(offsets, first, last).second;
  // The nearer of the gaps on either side; the run may reach one end.
  const double apart = (std::min)(first > 0 ? offsets[first] - offsets[first - 1] : radius,
                                  last < size ? offsets[last] - offsets[last - 1] : radius);
  if(!(apart > T::sheets_apart * spread))
    return false;
  const double low = offsets[first], high = offsets[last - 1];
  own.clear();
  for(const Eigen::Vector3d& p : points)
  {
    const double o = normal.dot(p);
    if(o >= low && o <= high)
      own.push_back(p);
  }
  return true;
}

/// The quadric of the point's own sheet (`fit_quadric()`), where its
/// neighbors `points` (relative to it, within `radius`) hold two along
/// `normal` (`own_sheet()`), the sheet's points in `scratch.own`; a fit
/// without a normal where they hold one.
inline Quadric_fit fit_own_sheet(const std::vector<Eigen::Vector3d>& points, double radius,
                                 const Eigen::Vector3d& normal, Refit_scratch& scratch)
{
  const double infinity = std::numeric_limits<double>::infinity();
  if(!own_sheet(points, normal, scratch.own, scratch.work))
    return Quadric_fit{ Eigen::Vector3d::Zero(), infinity, infinity };
  return fit_quadric(scratch.own, radius, scratch);
}

/// The quadric `fit` of the neighbors `points` (relative to the point,
/// nearest first, within `radius`), or, where they hold the two sides of a
/// thin part or a stack of sheets, that of the point's own sheet
/// (`fit_own_sheet()`, `own_stacked_sheet()`), so that its noise, which its
/// neighbors' tests read, is not the gap between the sheets. The sides are
/// split along the quadric's normal where its residuals are bimodal (the
/// quadric lies between them), else along the principal normal of the
/// nearest neighbors where the quadric turned away from it, and a stack
/// along that of the few nearest.
inline Quadric_fit fit_point_side(const std::vector<Eigen::Vector3d>& points, double radius, const Quadric_fit& fit,
                                  Refit_scratch& scratch)
{
  typedef Least_squares_first_thresholds T;
  Quadric_fit own{ Eigen::Vector3d::Zero(), 0, 0 };
  if(fit.noise > T::bimodal * fit.rms)
    own = fit_own_sheet(points, radius, fit.normal, scratch);
  else if(points.size() >= T::least_for_sheets && fit.normal != Eigen::Vector3d::Zero())
  {
    const std::size_t nearest = std::size_t(T::near_share * double(points.size()));
    const Eigen::Vector3d near = principal_normal(points, [&](std::size_t j) { return j < nearest; });
    if(!within_angle(near, fit.normal, T::near_turn))
    {
      own = fit_own_sheet(points, radius, near, scratch);
      if(own.normal == Eigen::Vector3d::Zero())
      {
        for(std::size_t few : { T::stack_nearest, T::stack_fewest })
        {
          const Eigen::Vector3d nearer = principal_normal(points, [&](std::size_t j) { return j < few; });
          if(own_stacked_sheet(points, radius, nearer, scratch.own, scratch.work))
          {
            own = fit_quadric(scratch.own, radius, scratch);
            break;
          }
        }
      }
    }
  }
  return own.normal != Eigen::Vector3d::Zero() ? own : fit;
}

/// Whether a quadric whose residuals have the root mean square `rms` is one
/// smooth sheet within the noise of the scan in a ball of `radius`, where
/// the first quartile of the noise deviations of its `count` neighbors is
/// `noise_near` (`noise_of_neighbors()`).
inline bool is_one_sheet(double rms, double noise_near, std::size_t count, double radius)
{
  typedef Least_squares_first_thresholds T;
  if(count <= 6 || !std::isfinite(rms) || !std::isfinite(noise_near))
    return false;
  const double variance = noise_near * noise_near * (1 + T::scatter / double(count - 6));
  const double excess = T::excess * radius;
  return rms * rms - variance <= excess * excess;
}

/// The nearest neighbors of the point at `position` whose rejection
/// vetoes its quadric: the nearest `dilation` share of `neighbors`, the
/// point itself left out. Calls `visit(neighbor)` on each.
template <typename Visit>
void for_each_near_neighbor(std::size_t position, const std::vector<std::uint32_t>& neighbors, Visit visit)
{
  const std::size_t count =
    neighbors.empty() ? 0 : std::size_t(std::ceil(Least_squares_first_thresholds::dilation * double(neighbors.size() - 1)));
  std::size_t seen = 0;
  for(std::size_t j = 0; j < neighbors.size() && seen < count; ++j)
    if(neighbors[j] != position)
      visit(neighbors[j]), ++seen;
}

/// Whether the quadric of the point at `position` is kept: its own test
/// passed (`one_sheet`) and few of its near neighbors failed theirs.
inline bool keeps_quadric(std::size_t position, const std::vector<std::uint32_t>& neighbors,
                          const std::vector<unsigned char>& one_sheet)
{
  if(!one_sheet[position])
    return false;
  std::size_t near = 0, rejected = 0;
  for_each_near_neighbor(position, neighbors, [&](std::uint32_t j) { ++near, rejected += !one_sheet[j]; });
  return double(rejected) <= Least_squares_first_thresholds::most_rejected * double(near);
}

/// The referee between the Hough transform and a kept quadric at a point
/// next to rejected ones: the normal of the quadric of the nearest
/// `Least_squares_first_thresholds::referee` share of its neighborhood
/// `points` (relative to it, nearest first), or the null vector where that
/// share holds too few points to overrule the quadric.
inline Eigen::Vector3d referee_normal(const std::vector<Eigen::Vector3d>& points, Refit_scratch& scratch)
{
  typedef Least_squares_first_thresholds T;
  const std::size_t count = std::size_t(T::referee * double(points.size()));
  if(count < T::referee_min)
    return Eigen::Vector3d::Zero();
  scratch.nearest.assign(points.begin(), points.begin() + std::ptrdiff_t(count));
  return fit_quadric(scratch.nearest, scratch.nearest.back().norm(), scratch).normal;
}

/// Whether the referee (`referee_normal()`) may prefer the Hough transform's
/// normal to the kept quadric's `quadric`: only where it is turned from the
/// quadric by more than half the turn that `prefers_hough()` asks of the
/// Hough transform (the triangle inequality, with a margin for rounding),
/// so that the Hough transform runs only where it may change the answer.
inline bool contests_quadric(const Eigen::Vector3d& referee, const Eigen::Vector3d& quadric)
{
  return referee != Eigen::Vector3d::Zero() &&
         std::abs(referee.dot(quadric)) < Least_squares_first_thresholds::cos_contest;
}

/// Whether the Hough transform's normal `hough` is taken instead of the
/// kept quadric's normal `quadric` at a point next to rejected ones, as the
/// `referee` (`referee_normal()`) decides. Next to a sharp feature, the
/// quadric of a neighborhood that grazes it turns towards the other side
/// while the Hough transform and the quadric of the nearer neighbors stay
/// on the point's side; on a fillet narrower than the neighborhood, the
/// Hough transform takes a flat side while the nearer quadric follows the
/// fillet.
inline bool prefers_hough(const Eigen::Vector3d& hough, const Eigen::Vector3d& quadric, const Eigen::Vector3d& referee)
{
  if(referee == Eigen::Vector3d::Zero() || std::abs(hough.dot(quadric)) >= Least_squares_first_thresholds::cos_turn)
    return false;
  return std::abs(referee.dot(hough)) > std::abs(referee.dot(quadric));
}

/// What `least_squares_first()` needs to know of the call.
struct Least_squares_first_options
{
  const Adaptive_stages* stages; // the adaptive setting, or null for `settings` alone
  bool refit;                    // refit the normals of the Hough transform (`refit_normal()`)
  bool confidences;              // compute the confidences
  bool supports;                 // compute the support radii
};

/// Estimates the normals of the points of the context's search that it
/// estimates, least squares first, in three passes over the cloud
/// (`neighborhood_passes()`, each point's neighbors kept between its passes
/// or found again), and writes each normal, confidence and support to
/// the context's output:
/// 1. at every point, the quadric of its neighborhood (`fit_quadric()`),
///    or of its side of a thin part (`fit_point_side()`), whose neighbors
///    are kept;
/// 2. at every point, whether it is one sheet within the noise around it
///    (`noise_of_neighbors()` over the deviations relative to each
///    neighbor's radius, `is_one_sheet()`); where it is not but the
///    neighborhood holds two sheets (`own_sheet()`), the quadric of the
///    point's own sheet replaces it if that one is;
/// 3. where the quadric is kept (`keeps_quadric()`), its normal, unless a
///    neighbor was rejected, the referee contests the quadric
///    (`contests_quadric()`) and prefers the Hough transform's first stage
///    (`prefers_hough()`); elsewhere, the Hough transform's, with
///    `settings` or the adaptive `stages`, then refitted if asked. With
///    the adaptive stages, the best of the planes of the point's one-sheet
///    neighbors, refitted (`best_neighbor_plane()`), is taken instead where
///    it holds most of the neighborhood, or where it agrees with the cheap
///    stage (`Neighbor_planes_thresholds`).
/// The confidence of a quadric's or a neighbor plane's normal is measured on
/// the votes of the Hough transform's first stage at the point where it
/// ran, and elsewhere on a few triples of its neighbors
/// (`confidence_of_kept_normal()`,
/// `Least_squares_first_thresholds::confidence_planes`). The support
/// is the ball that holds the neighborhoods of the point's neighbors'
/// neighbors, whose tests decide.
template <typename ConcurrencyTag>
void least_squares_first(const Pass_context& context, const Least_squares_first_options& options, Progress& progress)
{
  const Neighbor_search& search = context.search;
  const Settings& settings = context.settings;
  auto make_scratch = [&context]() { return context.make_scratch(); };
  auto write = [&context](std::size_t i, const Eigen::Vector3d& normal, double confidence, double support) {
    context.output.normal(i, normal);
    context.output.confidence(i, confidence);
    context.output.support(i, support);
  };
  const std::size_t size = search.size();
  // What the neighbors of a point read of its passes, for the whole cloud:
  // its noise deviation (relative to its radius), its test, with the
  // adaptive setting the normal of its quadric where it passed, and, for
  // the supports, the balls that hold its neighborhood and its neighbors'.
  // The noise is a relative deviation, which single precision keeps.
  std::vector<float> noise(size);
  std::vector<double> extents(options.supports ? size : 0), reach(options.supports ? size : 0);
  std::vector<unsigned char> one_sheet(size);
  std::vector<Packed_direction> sheet_normals(options.stages ? size : 0);
  // What a point's own passes hand to each other.
  struct State
  {
    Eigen::Vector3d normal;
    double rms, radius, noise_near;
  };

  auto find = [&](std::size_t i, std::vector<std::uint32_t>& neighbors, Scratch& scratch) {
    search.find(i, settings.k, settings.neighbor_radius, scratch.neighborhood, scratch.search);
    neighbors.assign(scratch.neighborhood.positions.begin(), scratch.neighborhood.positions.end());
  };

  auto fit = [&](std::size_t i, std::vector<std::uint32_t>& neighbors, State& state, Scratch& scratch) {
    find(i, neighbors, scratch);
    const Neighborhood& neighborhood = scratch.neighborhood;
    state.radius = neighborhood.radius;
    if(options.supports)
      extents[i] = context.support_of(neighborhood);
    const Quadric_fit fit = fit_point_side(
      neighborhood.points, neighborhood.radius, fit_quadric(neighborhood.points, neighborhood.radius, scratch.refit),
      scratch.refit);
    // The noise relative to the neighborhood's radius: where the density
    // varies, so does the scale of the neighborhoods a deviation is from.
    state.normal = fit.normal, state.rms = fit.rms, noise[i] = float(fit.noise / neighborhood.radius);
  };

  // The noise around the point, its test and, for the supports, the ball
  // that holds its neighbors' neighborhoods.
  auto test = [&](std::size_t i, const std::vector<std::uint32_t>& neighbors, State& state, Scratch& scratch) {
    // A neighborhood too small or too large to compute on has no noise
    // estimate.
    state.noise_near = has_computable_radius(state.radius)
                         ? state.radius * noise_of_neighbors(neighbors, noise, scratch.refit.work)
                         : std::numeric_limits<double>::infinity();
    one_sheet[i] = is_one_sheet(state.rms, state.noise_near, neighbors.size(), state.radius);
    if(!one_sheet[i] && state.normal != Eigen::Vector3d::Zero() &&
       neighbors.size() >= Least_squares_first_thresholds::least_for_sheets)
    {
      // Two sheets: the quadric of the point's own, if it is one sheet.
      search.rebuild(i, neighbors, state.radius, scratch.neighborhood);
      const Quadric_fit own = fit_own_sheet(scratch.neighborhood.points, state.radius, state.normal, scratch.refit);
      if(is_one_sheet(own.rms, state.noise_near, scratch.refit.own.size(), state.radius))
        one_sheet[i] = 1, state.normal = own.normal;
    }
    if(options.stages && one_sheet[i])
      sheet_normals[i] = Packed_direction(state.normal);
    if(options.supports)
    {
      double farthest = 0;
      for(std::uint32_t j : neighbors)
        farthest = (std::max)(farthest, (search.point(j) - search.point(i)).norm() + extents[j]);
      reach[i] = farthest;
    }
  };

  const Settings& first_stage = options.stages ? options.stages->cheap : settings;
  // The confidence of `normal`, kept without a vote at the point whose id is
  // `id`, where the confidences are asked: a few of the point's triples
  // measure it, with its own random stream.
  const std::size_t confidence_planes =
    (std::min)(first_stage.number_of_planes, Least_squares_first_thresholds::confidence_planes);
  const double cos_cap =
    (std::max)(0., 1 - Least_squares_first_thresholds::confidence_cap / double(context.layout.size()));
  auto confidence_of_kept = [&](std::uint64_t id, const Eigen::Vector3d& normal, Scratch& scratch) {
    if(!options.confidences)
      return 0.;
    Random rng(settings.seed, id);
    return confidence_of_kept_normal(scratch.neighborhood.points, normal, cos_cap, confidence_planes, scratch.points,
                                     rng, scratch.triples);
  };
  // The best of the planes of the point's one-sheet neighbors, refitted
  // (`best_neighbor_plane()`, `refit_neighbor_plane()`), in its
  // neighborhood found again; no plane where the noise around it is unknown.
  auto neighbor_plane = [&](const std::vector<std::uint32_t>& neighbors, const State& state, Scratch& scratch) {
    const Scored_plane none{ Eigen::Vector3d::Zero(), 0. };
    const double band = plane_band(state.noise_near, state.radius);
    if(!std::isfinite(band) || !(band * band >= 1e-300))
      return none;
    const std::vector<Eigen::Vector3d>& points = scratch.neighborhood.points;
    const Scored_plane best = best_neighbor_plane(
      points, neighbors, [&](std::uint32_t j) { return one_sheet[j] != 0; },
      [&](std::uint32_t j) { return sheet_normals[j].direction(); }, band, scratch.neighbor_planes);
    if(best.normal == Eigen::Vector3d::Zero())
      return none;
    return Scored_plane{ refit_neighbor_plane(points, best.normal, band, scratch.neighbor_planes), best.share };
  };
  auto estimate = [&](std::size_t i, const std::vector<std::uint32_t>& neighbors, const State& state,
                      Scratch& scratch) {
    if(!context.estimated(i))
      return;
    Neighborhood& neighborhood = scratch.neighborhood;
    double support = 0;
    if(options.supports)
    {
      support = reach[i];
      for(std::uint32_t j : neighbors)
        support = (std::max)(support, (search.point(j) - search.point(i)).norm() + reach[j]);
    }
    const bool quadric = keeps_quadric(i, neighbors, one_sheet);
    const bool border =
      quadric && std::any_of(neighbors.begin(), neighbors.end(), [&](std::uint32_t j) { return !one_sheet[j]; });
    if(quadric && !border && !options.confidences)
    {
      write(i, state.normal, 0., support);
      return;
    }
    search.rebuild(i, neighbors, state.radius, neighborhood);
    const Eigen::Vector3d referee = border ? referee_normal(neighborhood.points, scratch.refit) : Eigen::Vector3d::Zero();
    const bool contested = border && contests_quadric(referee, state.normal);
    const std::uint64_t id = search.id(i);
    if(quadric && !contested)
    {
      write(i, state.normal, confidence_of_kept(id, state.normal, scratch), support);
      return;
    }
    Estimated_normal e;
    if(quadric)
    {
      const Estimated_normal cheap = estimate_normal_of_neighborhood(id, first_stage, scratch);
      if(!prefers_hough(cheap.normal, state.normal, referee))
      {
        write(i, state.normal, confidence(scratch.candidates, state.normal, first_stage.cos_cluster_angle), support);
        return;
      }
      e = options.stages ? recheck(id, cheap, *options.stages, scratch) : cheap;
    }
    else if(options.stages && neighborhood.points.size() >= 3 && has_computable_radius(neighborhood.radius))
    {
      // The neighbors' plane where it holds most of the neighborhood, or
      // where the cheap stage agrees with it across a crease; the adaptive
      // stages elsewhere.
      typedef Neighbor_planes_thresholds T;
      const Scored_plane plane = neighbor_plane(neighbors, state, scratch);
      if(plane.normal != Eigen::Vector3d::Zero() && plane.share >= T::strong)
      {
        write(i, plane.normal, confidence_of_kept(id, plane.normal, scratch), support);
        return;
      }
      const Estimated_normal cheap = estimate_normal_of_neighborhood(id, first_stage, scratch);
      if(plane.normal != Eigen::Vector3d::Zero() && std::abs(plane.normal.dot(cheap.normal)) >= T::cos_agree &&
         state.rms >= T::crease * state.radius)
      {
        write(i, plane.normal, confidence(scratch.candidates, plane.normal, first_stage.cos_cluster_angle), support);
        return;
      }
      e = recheck(id, cheap, *options.stages, scratch);
    }
    else
      e = estimate_normal_of_found(id, settings, scratch, options.stages);
    if(options.refit && e.normal != Eigen::Vector3d::Zero() && std::isfinite(state.noise_near))
    {
      const Eigen::Vector3d refitted =
        refit_normal(neighborhood.points, neighborhood.radius, e.normal, state.noise_near, scratch.refit);
      if(refitted != Eigen::Vector3d::Zero())
        e.normal = refitted;
    }
    write(i, e.normal, e.confidence, support);
  };

  neighborhood_passes<ConcurrencyTag, State>(size, progress, make_scratch, find, fit, test, estimate);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_LEAST_SQUARES_FIRST_H
