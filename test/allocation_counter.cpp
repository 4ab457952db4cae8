// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The replacement of the global operator new that counts allocations: it
// applies to the whole test program, so it lives here on its own, and only
// the memory test reads the count.

#include "allocation_counter.h"

#include <atomic>
#include <cstdlib>
#include <new>

#if RRHT_TEST_COUNTS_ALLOCATIONS
namespace {
std::atomic<std::size_t> allocations(0);
}

void* operator new(std::size_t size)
{
  ++allocations;
  if(void* p = std::malloc(size == 0 ? 1 : size))
    return p;
  throw std::bad_alloc();
}
// GCC cannot see that this free() matches the malloc() of the replacement above.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

std::size_t rrht_test::number_of_allocations() { return allocations; }
#else
std::size_t rrht_test::number_of_allocations() { return 0; }
#endif
