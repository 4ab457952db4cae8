// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The number of allocations made by the test program so far, counted by a
// replacement of the global operator new (allocation_counter.cpp), except
// under AddressSanitizer, which replaces it with its own.

#ifndef RRHT_TEST_ALLOCATION_COUNTER_H
#define RRHT_TEST_ALLOCATION_COUNTER_H

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#  define RRHT_TEST_COUNTS_ALLOCATIONS 0
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer)
#    define RRHT_TEST_COUNTS_ALLOCATIONS 0
#  endif
#endif
#ifndef RRHT_TEST_COUNTS_ALLOCATIONS
#  define RRHT_TEST_COUNTS_ALLOCATIONS 1
#endif

namespace rrht_test {
/// Allocations since the start of the program (0 when they are not counted).
std::size_t number_of_allocations();
} // namespace rrht_test

#endif // RRHT_TEST_ALLOCATION_COUNTER_H
