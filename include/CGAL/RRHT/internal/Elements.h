// Copyright (c) 2026 The CGAL RRHT authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The elements of the input range by their position in it.

#ifndef CGAL_RRHT_INTERNAL_ELEMENTS_H
#define CGAL_RRHT_INTERNAL_ELEMENTS_H

#include <cstddef>
#include <iterator>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace RRHT {
namespace internal {

/// Whether `Iterator` is a random-access iterator.
template <typename Iterator>
constexpr bool is_random_access =
  std::is_convertible<typename std::iterator_traits<Iterator>::iterator_category,
                      std::random_access_iterator_tag>::value;

/// The iterator to the element at a position of the input range: kept in a
/// table, unless the iterators are random access.
template <typename Iterator, bool random_access = is_random_access<Iterator>>
class Elements
{
public:
  void add(Iterator it) { m_iterators.push_back(it); }
  Iterator at(Iterator, std::size_t position) const { return m_iterators[position]; }

private:
  std::vector<Iterator> m_iterators;
};

template <typename Iterator>
class Elements<Iterator, true>
{
public:
  void add(Iterator) {}
  Iterator at(Iterator begin, std::size_t position) const { return begin + position; }
};

} // namespace internal
} // namespace RRHT
} // namespace CGAL

#endif // CGAL_RRHT_INTERNAL_ELEMENTS_H
