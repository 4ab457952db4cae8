// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The three points of a plane hypothesis (paper, Section 2).

#ifndef CGAL_RRHT_INTERNAL_TRIPLE_H
#define CGAL_RRHT_INTERNAL_TRIPLE_H

#include <array>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Three distinct indices into a neighborhood: the points through which a
/// plane is drawn.
typedef std::array<std::uint32_t, 3> Triple;

/// The triples that the vectorized loops of the samplers compute at a time.
constexpr std::size_t triples_per_chunk = 64;

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_TRIPLE_H
