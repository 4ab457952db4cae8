// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Three passes over the points of a cloud, where a point's second pass reads
// the results of its neighbors' first passes and its third those of their
// second passes, streamed along the Hilbert curve: the list of a point's
// neighbors, found in its first pass, is kept until its third pass only,
// instead of for the whole cloud between passes, and found again where that
// is far along the curve.

#ifndef CGAL_RRHT_INTERNAL_NEIGHBORHOOD_PASSES_H
#define CGAL_RRHT_INTERNAL_NEIGHBORHOOD_PASSES_H

#include <CGAL/RRHT/internal/Progress.h>
#include <CGAL/RRHT/internal/for_each_block.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// A point between two of its passes, as the rounds of
/// `neighborhood_passes()` hand it on: its position, the slot of its
/// `State`, and the list that holds the positions of its neighbors (itself
/// included) while they are kept.
struct Point_in_passes
{
  static constexpr std::uint32_t no_list = std::uint32_t(-1);
  std::uint32_t position;
  std::uint32_t slot;
  std::uint32_t list; // or `no_list`
};

/// Runs three passes over the `size` points of a cloud stored along a
/// Hilbert curve (`Neighbor_search`), each point's pass once the passes it
/// reads are done:
/// - `first(position, neighbors, state, scratch)` finds the point's
///   neighbors (their positions, in `neighbors`, the point included) and
///   fills its `state`;
/// - `second(position, neighbors, state, scratch)` may read the results
///   of the first passes of its `neighbors`;
/// - `third(position, neighbors, state, scratch)` may read the results of
///   their second passes.
///
/// The curve is cut into steps of `chunk` points. Each round of the loop
/// runs, in one parallel loop, the first passes of the next step, the
/// second passes of the points whose neighbors all had their first, and
/// the third passes of those whose neighbors all had their second: only the
/// points between their first and third passes are held. Where the curve
/// folds back, a point's neighbors lie far along it and its next pass waits
/// many rounds; its list is then let go and found again by
/// `find(position, neighbors, scratch)` before that pass, so that only the
/// points of the last few rounds hold a list. Each pass at a point is a
/// function of the passes it reads alone, so the results do not depend on
/// the order, the steps or the threads. Each pass counts one unit of
/// `progress`; once it is interrupted, no further round starts.
template <typename ConcurrencyTag, typename State, typename MakeScratch, typename Find, typename First,
          typename Second, typename Third>
void neighborhood_passes(std::size_t size, Progress& progress, MakeScratch make_scratch, Find find, First first,
                         Second second, Third third)
{
  constexpr std::size_t chunk = 4096;
  // A list is kept for a next pass at most this many rounds away; the lists
  // of the points that wait longer would be most of those held, and few
  // points wait that long.
  constexpr std::size_t keep = 8;
  typedef Point_in_passes Point;
  const std::size_t steps = (size + chunk - 1) / chunk;
  // The states of the points in passes and the lists of neighbors, each in
  // slots reused once let go.
  std::vector<State> states;
  std::vector<std::uint32_t> free_states;
  std::vector<std::vector<std::uint32_t> > lists;
  std::vector<std::uint32_t> free_lists;
  auto take = [](auto& pool, std::vector<std::uint32_t>& free) {
    if(free.empty())
    {
      free.push_back(std::uint32_t(pool.size()));
      pool.emplace_back();
    }
    const std::uint32_t slot = free.back();
    free.pop_back();
    return slot;
  };
  // The step after which each point's second pass can run: the last of its
  // neighbors' (and its own).
  std::vector<std::uint32_t> second_step(size);
  // The points whose second (third) pass runs after each step.
  std::vector<std::vector<Point> > seconds(steps), thirds(steps);
  // A round's points (third passes, second ones, first ones) and the step
  // after which the next pass of each can run. The parallel loop touches
  // each point's state and list; what runs between loops reads only these
  // arrays, in order.
  std::vector<Point> round;
  std::vector<std::uint32_t> next_step;
  Block_loop<ConcurrencyTag, MakeScratch> loop(make_scratch);
  // Round r: the first passes of step r, the second ones due after step
  // r - 1, the third ones due after step r - 2.
  for(std::size_t r = 0; r < steps + 2 && !progress.interrupted(); ++r)
  {
    round.clear();
    auto take_due = [&round](std::vector<Point>& due) {
      round.insert(round.end(), due.begin(), due.end());
      std::vector<Point>().swap(due);
    };
    if(r >= 2)
      take_due(thirds[r - 2]);
    const std::size_t third_end = round.size();
    if(r >= 1 && r - 1 < steps)
      take_due(seconds[r - 1]);
    const std::size_t second_end = round.size();
    if(r < steps)
      for(std::size_t i = r * chunk; i < (std::min)(size, (r + 1) * chunk); ++i)
        round.push_back({ std::uint32_t(i), take(states, free_states), Point::no_list });
    // A point without a list gets an empty one, filled in the loop: it
    // holds at least the point.
    for(Point& p : round)
      if(p.list == Point::no_list)
        p.list = take(lists, free_lists);
    next_step.resize(round.size());
    // Whether the point at `k` in the round lets its list go: after its
    // third pass, or where its next pass is more than `keep` rounds away
    // (the round of a pass due after step s is s + 1 for a second one, s + 2
    // for a third).
    auto lets_go = [&](std::size_t k) {
      return k < third_end || std::size_t(next_step[k]) + (k < second_end ? 2 : 1) > r + keep;
    };
    loop(round.size(), progress, [&](std::size_t begin, std::size_t end, auto& scratch) {
      for(std::size_t k = begin; k < end; ++k)
      {
        const std::size_t i = round[k].position;
        State& state = states[round[k].slot];
        std::vector<std::uint32_t>& neighbors = lists[round[k].list];
        if(k < second_end && neighbors.empty())
          find(i, neighbors, scratch);
        if(k < third_end)
          third(i, neighbors, state, scratch);
        else if(k < second_end)
        {
          second(i, neighbors, state, scratch);
          std::uint32_t last = second_step[i];
          for(std::uint32_t j : neighbors)
            last = (std::max)(last, second_step[j]);
          next_step[k] = last;
        }
        else
        {
          first(i, neighbors, state, scratch);
          std::uint32_t last = std::uint32_t(i);
          for(std::uint32_t j : neighbors)
            last = (std::max)(last, j);
          second_step[i] = next_step[k] = std::uint32_t(last / chunk);
        }
        if(lets_go(k))
          neighbors.clear();
      }
    });
    if(progress.interrupted())
      break;
    for(std::size_t k = 0; k < round.size(); ++k)
    {
      Point p = round[k];
      if(lets_go(k))
      {
        free_lists.push_back(p.list);
        p.list = Point::no_list;
      }
      if(k < third_end)
        free_states.push_back(p.slot);
      else
        (k < second_end ? thirds : seconds)[next_step[k]].push_back(p);
    }
  }
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NEIGHBORHOOD_PASSES_H
