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

/// A point between its first pass and its third: its position, the list
/// that holds the positions of its neighbors (itself included) while they
/// are kept, and what its own passes hand to each other (`State`).
template <typename State>
struct Point_in_passes
{
  static constexpr std::uint32_t no_list = std::uint32_t(-1);
  std::uint32_t position;
  std::uint32_t third_step; // the step of the curve after which its third pass can run
  std::uint32_t list;       // or `no_list`
  State state;
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
  typedef Point_in_passes<State> Point;
  const std::size_t steps = (size + chunk - 1) / chunk;
  // The points in passes and the lists of neighbors, each in slots reused
  // once let go.
  std::vector<Point> slots;
  std::vector<std::uint32_t> free_slots;
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
  auto let_go = [&](Point& p) {
    lists[p.list].clear();
    free_lists.push_back(p.list);
    p.list = Point::no_list;
  };
  // The step after which each point's second pass can run: the last of its
  // neighbors' (and its own).
  std::vector<std::uint32_t> second_step(size);
  // The slots whose second (third) pass runs after each step.
  std::vector<std::vector<std::uint32_t> > seconds(steps), thirds(steps);
  std::vector<std::uint32_t> round; // the slots of a round: third passes, second ones, first ones
  Block_loop<ConcurrencyTag, MakeScratch> loop(make_scratch);
  // Round r: the first passes of step r, the second ones due after step
  // r - 1, the third ones due after step r - 2.
  for(std::size_t r = 0; r < steps + 2 && !progress.interrupted(); ++r)
  {
    round.clear();
    auto take_due = [&round](std::vector<std::uint32_t>& due) {
      round.insert(round.end(), due.begin(), due.end());
      std::vector<std::uint32_t>().swap(due);
    };
    if(r >= 2)
      take_due(thirds[r - 2]);
    const std::size_t third_end = round.size();
    if(r >= 1 && r - 1 < steps)
      take_due(seconds[r - 1]);
    const std::size_t second_end = round.size();
    if(r < steps)
      for(std::size_t i = r * chunk; i < (std::min)(size, (r + 1) * chunk); ++i)
      {
        const std::uint32_t slot = take(slots, free_slots);
        slots[slot].position = std::uint32_t(i);
        slots[slot].list = Point::no_list;
        round.push_back(slot);
      }
    // An empty list is found in the loop: it holds at least the point.
    for(std::uint32_t slot : round)
      if(slots[slot].list == Point::no_list)
        slots[slot].list = take(lists, free_lists);
    loop(round.size(), progress, [&](std::size_t begin, std::size_t end, auto& scratch) {
      for(std::size_t k = begin; k < end; ++k)
      {
        Point& p = slots[round[k]];
        std::vector<std::uint32_t>& neighbors = lists[p.list];
        if(k < second_end && neighbors.empty())
          find(std::size_t(p.position), neighbors, scratch);
        if(k < third_end)
          third(std::size_t(p.position), neighbors, p.state, scratch);
        else if(k < second_end)
        {
          second(std::size_t(p.position), neighbors, p.state, scratch);
          std::uint32_t last = second_step[p.position];
          for(std::uint32_t j : neighbors)
            last = (std::max)(last, second_step[j]);
          p.third_step = last;
        }
        else
        {
          first(std::size_t(p.position), neighbors, p.state, scratch);
          std::uint32_t last = p.position;
          for(std::uint32_t j : neighbors)
            last = (std::max)(last, j);
          second_step[p.position] = std::uint32_t(last / chunk);
        }
      }
    });
    if(progress.interrupted())
      break;
    // The round of a pass due after step s is s + 1 for a second one, s + 2
    // for a third.
    auto schedule = [&](std::vector<std::uint32_t>& due, std::uint32_t slot, std::size_t pass_round) {
      due.push_back(slot);
      if(pass_round > r + keep)
        let_go(slots[slot]);
    };
    for(std::size_t k = 0; k < round.size(); ++k)
    {
      Point& p = slots[round[k]];
      if(k < third_end)
      {
        let_go(p);
        free_slots.push_back(round[k]);
      }
      else if(k < second_end)
        schedule(thirds[p.third_step], round[k], std::size_t(p.third_step) + 2);
      else
        schedule(seconds[second_step[p.position]], round[k], std::size_t(second_step[p.position]) + 1);
    }
  }
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_NEIGHBORHOOD_PASSES_H
