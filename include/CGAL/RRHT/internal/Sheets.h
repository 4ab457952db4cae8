// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sheets of the surface that a neighborhood holds: one, or the sides of
// thin parts and narrow gaps stacked along the normal, told apart by the
// offsets of the points from the tangent plane.

#ifndef CGAL_RRHT_INTERNAL_SHEETS_H
#define CGAL_RRHT_INTERNAL_SHEETS_H

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// The sheets of a point's neighborhood: the groups of its points' offsets
/// from its tangent plane, the point's own group, and whether an offset is
/// on the point's sheet or on the next one.
class Sheets
{
public:
  /// One sheet: every offset is on it.
  Sheets() = default;

  class Splits;

  /// The sheets of the offsets whose splits are `splits`, given the spread
  /// of the offsets within a sheet over the whole cloud, `noise` (the median
  /// of `Splits::spread_within_sheets()`).
  ///
  /// The sorted offsets are split into three, else two, groups of least
  /// squared deviation (1D k-means, exact), each of two offsets and an
  /// eighth of them or more. The
  /// split stands when the gap between any two adjacent groups' means is
  /// over 3.5 times the spread within the groups and 2.5 times `noise`: the
  /// local test keeps one noisy sheet from being split (its two halves are
  /// about 2.7 spreads apart; two sheets 5 noise deviations apart, 5), the
  /// global one a neighborhood whose few offsets happen to bunch up.
  /// Otherwise it is one sheet.
  Sheets(const Splits& splits, double noise);

  /// Whether the neighborhood holds more than one sheet.
  bool several() const { return m_groups > 1; }

  /// +1 if a point at offset `offset` is on the point's own sheet, -1 if on
  /// an adjacent one, 0 if on a sheet farther away. A point goes to the
  /// sheet whose mean is nearer: where the noise carries a point past the
  /// middle, it is nearer the other side than its own, and nothing in the
  /// points can tell its side (the floor of the orientation).
  int side(double offset) const
  {
    int group = 0;
    for(int g = 1; g < m_groups; ++g)
      if(offset > (m_means[g - 1] + m_means[g]) / 2)
        group = g;
    const int apart = std::abs(group - m_own);
    return apart == 0 ? 1 : apart == 1 ? -1 : 0;
  }

private:
  static constexpr double local_ratio = 3.5, global_ratio = 2.5;
  // A sheet holds at least 2 offsets and an eighth of them: a few points
  // with wrong normals between two sheets are not one.
  static constexpr std::size_t min_points = 2;
  static constexpr double min_share = 0.125;

  /// Sorted offsets' prefix sums, from which the squared deviation of any
  /// run of them from its mean comes at once, and those of every first and
  /// every last run: what the splits into two and into three share.
  struct Runs
  {
    std::vector<double> sum, sum2, head, tail;

    explicit Runs(const std::vector<double>& sorted)
      : sum(sorted.size() + 1, 0.), sum2(sorted.size() + 1, 0.), head(sorted.size() + 1, 0.),
        tail(sorted.size() + 1, 0.)
    {
      const std::size_t n = sorted.size();
      for(std::size_t t = 0; t < n; ++t)
      {
        sum[t + 1] = sum[t] + sorted[t];
        sum2[t + 1] = sum2[t] + sorted[t] * sorted[t];
      }
      for(std::size_t s = 1; s < n; ++s)
      {
        head[s] = deviation(0, s);
        tail[s] = deviation(s, n);
      }
    }

    std::size_t size() const { return sum.size() - 1; }

    /// The squared deviation of the offsets [a, b) from their mean.
    double deviation(std::size_t a, std::size_t b) const
    {
      const double s = sum[b] - sum[a];
      return (std::max)(0., sum2[b] - sum2[a] - s * s / double(b - a));
    }
  };

  /// The split of sorted offsets into 2 or 3 contiguous groups of least
  /// squared deviation from their means, by trying every split (at most
  /// n^2 / 2 for about 20 offsets).
  struct Split
  {
    bool found = false;
    double means[3] = { 0, 0, 0 };
    double spread = 0; // the standard deviation within the groups

    Split() = default;

    Split(const Runs& runs, int groups)
    {
      const std::size_t n = runs.size();
      const std::size_t min_group = (std::max)(min_points, std::size_t(min_share * double(n)));
      if(n < std::size_t(groups) * min_group)
        return;
      double best = -1;
      std::size_t first = 0, second = n;
      // A group's deviation only grows with it: once the first group's, or
      // the first two groups', reach the best cost, the splits that follow
      // cost more.
      for(std::size_t s1 = min_group; s1 + min_group * std::size_t(groups - 1) <= n; ++s1)
      {
        if(best >= 0 && runs.head[s1] >= best)
          break;
        for(std::size_t s2 = (groups == 2 ? n : s1 + min_group); s2 <= n && (groups == 2 || s2 + min_group <= n); ++s2)
        {
          const double first_two = runs.head[s1] + (groups == 2 ? runs.tail[s1] : runs.deviation(s1, s2));
          if(groups == 3 && best >= 0 && first_two >= best)
            break;
          const double cost = first_two + (s2 < n ? runs.tail[s2] : 0.);
          if(best < 0 || cost < best)
          {
            best = cost;
            first = s1;
            second = s2;
          }
        }
      }
      found = true;
      const std::size_t bounds[4] = { 0, first, second, n };
      for(int g = 0; g < groups; ++g)
        means[g] = (runs.sum[bounds[g + 1]] - runs.sum[bounds[g]]) / double(bounds[g + 1] - bounds[g]);
      spread = std::sqrt(best / double(n - std::size_t(groups)));
    }
  };

  int m_groups = 1;
  double m_means[3] = { 0, 0, 0 };
  int m_own = 0;
};

/// The best splits of a neighborhood's offsets into three and into two
/// sheets. They do not depend on the noise: they are taken where the offsets
/// are at hand, the noise over the cloud is the median of their spreads, and
/// `Sheets` judges them against it.
class Sheets::Splits
{
public:
  /// No offsets: one sheet.
  Splits() = default;

  /// The splits of `offsets`, the offsets of a point's neighbors from its
  /// tangent plane (the point's own, 0, among them; sorted on return).
  explicit Splits(std::vector<double>& offsets)
  {
    std::sort(offsets.begin(), offsets.end());
    const Runs runs(offsets);
    m_two = Split(runs, 2);
    m_three = Split(runs, 3);
  }

  /// The spread within the groups of the best split into two: the noise
  /// across one sheet, or a little less, where the neighborhood holds one
  /// sheet, and across each where it holds two.
  double spread_within_sheets() const { return m_two.found ? m_two.spread : 0.; }

private:
  friend class Sheets;
  Split m_two, m_three;
};

inline Sheets::Sheets(const Splits& splits, double noise)
{
  for(int groups = 3; groups >= 2; --groups)
  {
    const Split& split = groups == 3 ? splits.m_three : splits.m_two;
    if(!split.found)
      continue;
    bool apart = true;
    for(int g = 1; g < groups; ++g)
    {
      const double gap = split.means[g] - split.means[g - 1];
      apart = apart && gap > local_ratio * split.spread && gap > global_ratio * noise;
    }
    if(!apart)
      continue;
    m_groups = groups;
    std::copy(split.means, split.means + 3, m_means);
    for(int g = 1; g < groups; ++g)
      if(std::abs(m_means[g]) < std::abs(m_means[m_own]))
        m_own = g;
    return;
  }
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_SHEETS_H
