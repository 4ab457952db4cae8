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
#include <type_traits>

namespace CGAL {
namespace RRHT {
namespace internal {

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

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_FOR_EACH_BLOCK_H
