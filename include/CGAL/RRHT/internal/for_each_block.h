// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The points processed in blocks, sequentially or over TBB's threads.

#ifndef CGAL_RRHT_INTERNAL_FOR_EACH_BLOCK_H
#define CGAL_RRHT_INTERNAL_FOR_EACH_BLOCK_H

#include <CGAL/RRHT/internal/Progress.h>

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#endif

#include <algorithm>
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Loops over blocks of at most 64 consecutive positions, sequentially or
/// over TBB's threads, each thread with its own working memory, made by
/// `make_scratch()` where the thread first needs one and kept from one loop
/// to the next.
template <typename ConcurrencyTag, typename MakeScratch>
class Block_loop
{
  typedef decltype(std::declval<MakeScratch&>()()) Scratch_type;
  static constexpr bool parallel =
#ifdef CGAL_LINKED_WITH_TBB
    std::is_convertible<ConcurrencyTag, Parallel_tag>::value;
#else
    false;
#endif

public:
  explicit Block_loop(MakeScratch make_scratch)
    : m_make_scratch(make_scratch)
#ifdef CGAL_LINKED_WITH_TBB
      , m_scratches(make_scratch)
#endif
  {}

  /// Calls `process(begin, end, scratch)` on blocks of at most 64
  /// consecutive positions of [0, `size`): over TBB's threads with
  /// `Parallel_tag`, in order otherwise. Reports each block to `progress`
  /// and stops starting blocks once it is interrupted.
  template <typename Process>
  void operator()(std::size_t size, Progress& progress, Process process)
  {
    // Progress is reported, and an interruption seen, after every block of
    // 64 points, however large the ranges that TBB hands to a thread.
    const std::size_t block = 64;
    auto blocks = [&](std::size_t begin, std::size_t end, Scratch_type& scratch) {
      for(; begin < end && !progress.interrupted(); begin += block)
      {
        const std::size_t block_end = (std::min)(end, begin + block);
        process(begin, block_end, scratch);
        progress.add(block_end - begin);
      }
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(parallel)
    {
      // TBB may hand ranges of as few as this many points, so that the
      // threads finish a loop together where some points cost far more than
      // others.
      const std::size_t grain = 8;
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, size, grain),
                        [&](const tbb::blocked_range<std::size_t>& range) {
                          blocks(range.begin(), range.end(), m_scratches.local());
                        });
      return;
    }
#endif
    if(!m_scratch)
      m_scratch.emplace(m_make_scratch());
    blocks(0, size, *m_scratch);
  }

private:
  MakeScratch m_make_scratch;
  std::optional<Scratch_type> m_scratch; // the sequential loop's
#ifdef CGAL_LINKED_WITH_TBB
  tbb::enumerable_thread_specific<Scratch_type> m_scratches;
#endif
};

/// Calls `process(begin, end, scratch)` on blocks of at most 64 consecutive
/// positions of [0, `size`), with one `scratch = make_scratch()` per thread
/// (`Block_loop`).
template <typename ConcurrencyTag, typename MakeScratch, typename Process>
void for_each_block(std::size_t size, Progress& progress, MakeScratch make_scratch, Process process)
{
  Block_loop<ConcurrencyTag, MakeScratch> loop(make_scratch);
  loop(size, progress, process);
}

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_FOR_EACH_BLOCK_H
