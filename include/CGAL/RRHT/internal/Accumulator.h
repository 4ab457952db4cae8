// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The votes of one run of the Hough transform: per bin of the accumulator,
// the planes that voted for it and the sum of their normals (paper,
// Sections 3 and 4).

#ifndef CGAL_RRHT_INTERNAL_ACCUMULATOR_H
#define CGAL_RRHT_INTERNAL_ACCUMULATOR_H

#include <CGAL/RRHT/internal/Bin_layout.h>
#include <CGAL/RRHT/internal/confidence_intervals.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Votes of one run of the Hough transform: per bin, the number of planes
/// that voted for it and the sum of their normals (paper, Section 4), with the
/// most voted bin kept up to date, and the second one once the confidence
/// interval test (eq. 10) can hold. One per thread; `clear()` makes it ready
/// for the next run without allocating.
///
/// Eq. 10 compares the votes of the two most voted bins, but it cannot hold
/// while the most voted bin has fewer than 2 sqrt(T) of the T votes
/// (`confidence_intervals_can_be_disjoint()`). Until then only the most
/// voted bin is followed; then the votes of the second are found once, by a
/// pass over the bins, and both are followed (which bin is second is never
/// needed, only its votes). On noisy data most runs draw all their planes,
/// and
/// where the votes spread over several bins, as on an edge, most votes come
/// before that point.
class Accumulator
{
public:
  typedef Eigen::Vector3d Vector;

  explicit Accumulator(const Bin_layout& layout) : m_layout(&layout), m_bins(layout.size())
  {
    clear();
  }

  const Bin_layout& layout() const { return *m_layout; }

  void clear()
  {
    std::fill(m_bins.begin(), m_bins.end(), Bin());
    m_top = Top_two{ 0, 0, 0, 0 };
    m_ranked = false;
  }

  /// Adds the vote of a plane of normal `n` (nonzero, any length).
  void vote(const Vector& n)
  {
    const Vector unit = n / std::sqrt(n.squaredNorm());
    double sign;
    const std::size_t b = m_layout->bin_and_sign(unit.x(), unit.y(), unit.z(), sign);
    vote(b, sign * unit);
  }

  /// Adds the vote of the unit normal `unit` of bin `b`, with the sign
  /// given by `Bin_layout::bin_and_sign()`.
  void vote(std::size_t b, const Vector& unit)
  {
    if(m_ranked)
      add_vote(b, unit, m_top);
    else if(add_vote_to_most_voted(b, unit, m_top))
      rank();
  }

  /// Adds the votes of planes 0 to `count` - 1 of `planes` (a `Plane_batch`:
  /// `bin(i)` and `normal(i)`, the bin `Planes::no_plane` for no plane) in
  /// order, and calls `stop(first, second, votes)` with the votes of the two
  /// most voted bins and the number of votes after each vote at which eq. 10
  /// can hold; stops after the vote for which it returns true. Returns the
  /// number of planes looked at. The most voted bins are kept in local
  /// variables for the batch.
  template <typename Planes, typename Stop>
  std::size_t vote(const Planes& planes, std::size_t count, Stop stop)
  {
    Top_two top = m_top;
    std::size_t i = 0;
    while(!m_ranked && i < count)
    {
      const std::uint32_t b = planes.bin(i++);
      if(b == Planes::no_plane || !add_vote_to_most_voted(b, planes.normal(i - 1), top))
        continue;
      m_top = top;
      rank();
      top = m_top;
      if(stop(top.first_votes, top.second_votes, top.votes))
        return i;
    }
    while(i < count)
    {
      const std::uint32_t b = planes.bin(i++);
      if(b == Planes::no_plane)
        continue;
      add_vote(b, planes.normal(i - 1), top);
      if(stop(top.first_votes, top.second_votes, top.votes))
        break;
    }
    m_top = top;
    return i;
  }

  std::size_t number_of_votes() const { return m_top.votes; }
  std::size_t most_voted_bin() const { return m_top.first; }
  unsigned int votes_of_most_voted_bin() const { return m_top.first_votes; }

  /// The votes of the second most voted bin (a pass over the bins until eq. 10 can hold).
  unsigned int votes_of_second_most_voted_bin() const
  {
    return m_ranked ? m_top.second_votes : votes_of_second();
  }

  /// Unit mean of the normals that voted for the most voted bin (Section 4);
  /// zero when nothing was voted.
  Vector normal_of_most_voted_bin() const
  {
    const Vector& s = m_bins[m_top.first].sum;
    const double norm = s.norm();
    return norm > 0 ? Vector(s / norm) : Vector::Zero();
  }

private:
  // The most voted bin, its votes and those of the second, and the number
  // of votes. When several bins have the most votes, the first is the one
  // that got there first.
  struct Top_two
  {
    std::size_t first;
    unsigned int first_votes, second_votes;
    std::size_t votes;
  };

  // Adds the vote to bin b; returns the bin's votes.
  unsigned int add_to_bin(std::size_t b, const Vector& unit, Top_two& top)
  {
    Bin& bin = m_bins[b];
    bin.sum += unit;
    ++top.votes;
    return ++bin.votes;
  }

  // Votes grow by one, so b, now with `votes` votes, is (or stays) the first
  // when it passes the first's votes. A mask rather than a branch: whether a
  // plane votes for the first bin is random (GCC makes branches of
  // conditional operators here).
  static void follow_first(std::size_t b, unsigned int votes, Top_two& top)
  {
    const std::size_t first_mask = 0 - std::size_t(votes > top.first_votes);
    top.first = (b & first_mask) | (top.first & ~first_mask);
    top.first_votes = (std::max)(top.first_votes, votes);
  }

  // A vote while only the most voted bin is followed; returns whether eq. 10
  // can now hold.
  bool add_vote_to_most_voted(std::size_t b, const Vector& unit, Top_two& top)
  {
    follow_first(b, add_to_bin(b, unit, top), top);
    return confidence_intervals_can_be_disjoint(top.first_votes, top.votes);
  }

  // The most votes of a bin other than the first.
  unsigned int votes_of_second() const
  {
    unsigned int second = 0;
    for(std::size_t b = 0; b < m_bins.size(); ++b)
      second = (b != m_top.first) ? (std::max)(second, m_bins[b].votes) : second;
    return second;
  }

  // From now on, both most voted bins are followed.
  void rank()
  {
    m_top.second_votes = votes_of_second();
    m_ranked = true;
  }

  // A vote while both most voted bins are followed. When b becomes the
  // first, the first's votes are then the second's; else the second's votes
  // are the most of theirs and of b's (if b is not the first). Which bin is
  // second does not matter. A minimum, a maximum and a mask rather than
  // branches, as in follow_first().
  void add_vote(std::size_t b, const Vector& unit, Top_two& top)
  {
    const unsigned int votes = add_to_bin(b, unit, top);
    const unsigned int not_first_mask = 0u - unsigned(b != top.first);
    top.second_votes = (std::max)(top.second_votes, (std::min)(votes, top.first_votes) & not_first_mask);
    follow_first(b, votes, top);
  }

  // The votes of a bin next to the sum of their normals: one cache line per vote.
  struct Bin
  {
    Vector sum = Vector::Zero();
    unsigned int votes = 0;
  };

  const Bin_layout* m_layout;
  std::vector<Bin> m_bins;
  Top_two m_top;
  bool m_ranked; // whether m_top.second_votes is followed
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ACCUMULATOR_H
